#include "parser/deck_reader.hpp"

#include <deque>
#include <filesystem>
#include <memory>
#include <unordered_set>

#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/expression.hpp"
#include "parser/file_scan.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keyword_registry.hpp"
#include "parser/lexer.hpp"
#include "parser/parameters.hpp"
#include "base/suggest.hpp"
#include "src/check/validate.hpp"

namespace clinch {
namespace {

constexpr std::size_t kMaxIncludeDepth = 32;

// Physical lines of the deck with *INCLUDE splicing: a stack of files being read. The stream
// that first reads a file records where its keyword lines are (SourceManager::begin_layout).
class LineStream {
 public:
  LineStream(SourceManager& sources, DiagnosticSink& sink, bool checks = true)
      : sources_(sources), sink_(sink), checks_(checks) {}

  void push(std::uint32_t file) {
    frames_.push_back(std::make_unique<Frame>(
        Frame{file, scan_file(sources_, file, sink_, checks_), sources_.begin_layout(file)}));
  }
  bool empty() const { return frames_.empty(); }
  std::size_t depth() const { return frames_.size(); }
  std::uint32_t file_at(std::size_t level) const { return frames_[level]->file; }

  // Next line of the innermost open file; pops finished files. End only when all are done.
  LineScanner::Kind next() {
    while (!frames_.empty()) {
      LineScanner::Kind kind = advance(*frames_.back());
      if (kind != LineScanner::Kind::End) return kind;
      frames_.pop_back();
    }
    return LineScanner::Kind::End;
  }
  // Next line of the current file only (continuations must end in the same file, §5.1).
  LineScanner::Kind next_in_file() {
    if (frames_.empty()) return LineScanner::Kind::End;
    return advance(*frames_.back());
  }
  const LineScanner& scanner() const { return frames_.back()->scanner; }

 private:
  struct Frame {
    std::uint32_t file;
    LineScanner scanner;
    bool records_layout;
    bool finished = false;
  };
  LineScanner::Kind advance(Frame& frame) {
    const LineScanner::Kind kind = frame.scanner.next();
    if (kind == LineScanner::Kind::Keyword && frame.records_layout) {
      sources_.record_keyword_line(frame.file, frame.scanner.line_number());
    }
    if (kind == LineScanner::Kind::End && !frame.finished) {
      frame.finished = true;
      if (frame.records_layout) sources_.end_layout(frame.file, frame.scanner.line_number());
      check_read_whole(sources_, frame.scanner, frame.file, sink_);
    }
    return kind;
  }
  SourceManager& sources_;
  DiagnosticSink& sink_;
  bool checks_;
  std::vector<std::unique_ptr<Frame>> frames_;
};

std::string resolve_path(const SourceManager& sources, std::uint32_t from_file,
                         const std::string& name) {
  std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  std::string dir = sources.directory_of(from_file);
  return dir.empty() ? name : (std::filesystem::path(dir) / p).string();
}

std::string canonical(const std::string& path) {
  std::error_code ec;
  auto c = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : c.string();
}

std::string display_of_file_param(const Field& f) { return f.text; }

class Reader {
 public:
  Reader(SourceManager& sources, Model& model, DiagnosticSink& sink)
      : sources_(sources), model_(model), sink_(sink),
        registry_(KeywordRegistry::instance()) {}

  void run(std::uint32_t main_file) {
    main_file_ = main_file;
    loaded_.emplace(canonical(sources_.file(main_file).path), main_file);
    prepass(main_file);
    parameters_.evaluate(sink_);
    LineStream stream(sources_, sink_);
    open_files_.push_back(canonical(sources_.file(main_file).path));
    stream.push(main_file);
    read_lines(stream, /*data_file=*/false);
    close_block();
    finish_structure();
    parameters_.report_unused(sink_);
  }

 private:
  // ---- Pass 1: which parameters exist, and is this a part–assembly deck ----------------------
  void prepass(std::uint32_t main_file) {
    DiagnosticSink quiet;
    LineStream stream(sources_, quiet, /*checks=*/false);
    std::vector<std::string> open;
    stream.push(main_file);
    bool in_parameter = false;
    std::vector<KeywordSegment> segments;
    while (true) {
      LineScanner::Kind kind = stream.next();
      if (kind == LineScanner::Kind::End) break;
      if (kind == LineScanner::Kind::Comment) continue;
      if (kind == LineScanner::Kind::Keyword) {
        KeywordLine line;
        segments.assign(1, {stream.scanner().text(), stream.scanner().loc()});
        if (!parse_keyword_line(segments, line, quiet)) {
          in_parameter = false;
          continue;
        }
        if (line.name == "INCLUDE") {
          in_parameter = false;
          for (const KeywordParam& p : line.params) {
            if (p.name != "INPUT" || !p.has_value || stream.depth() > kMaxIncludeDepth) continue;
            std::string path = resolve_path(sources_, stream.scanner().loc().file, p.value.text);
            auto idx = prepass_load(path, p.value.loc);
            if (idx) stream.push(*idx);
          }
          continue;
        }
        if (line.name == "PART" || line.name == "ASSEMBLY") model_.part_assembly = true;
        in_parameter = line.name == "PARAMETER";
        if (in_parameter) {
          for (const KeywordParam& p : line.params) {
            if (p.name != "INPUT" || !p.has_value) continue;
            std::string path = resolve_path(sources_, stream.scanner().loc().file, p.value.text);
            auto idx = prepass_load(path, p.value.loc);
            if (!idx) continue;
            LineScanner scanner = scan_file(sources_, *idx, quiet);
            for (auto k = scanner.next(); k != LineScanner::Kind::End; k = scanner.next()) {
              if (k == LineScanner::Kind::Data) {
                parameters_.add_line({std::string(scanner.text()), scanner.loc()});
              }
            }
            check_read_whole(sources_, scanner, *idx, sink_);
          }
        }
        continue;
      }
      if (in_parameter && kind == LineScanner::Kind::Data) {
        parameters_.add_line({std::string(stream.scanner().text()), stream.scanner().loc()});
      }
    }
  }

  std::optional<std::uint32_t> prepass_load(const std::string& path, SourceLoc at) {
    std::string error;
    return load_once(path, at, &error);
  }

  // Each file is registered once; both passes (and repeated includes) share its entry.
  std::optional<std::uint32_t> load_once(const std::string& path, SourceLoc at,
                                         std::string* error) {
    std::string key = canonical(path);
    auto it = loaded_.find(key);
    if (it != loaded_.end()) return it->second;
    auto idx = sources_.load(path, at, error);
    if (idx) loaded_.emplace(key, *idx);
    return idx;
  }

  // ---- Pass 2 ---------------------------------------------------------------------------------
  void read_lines(LineStream& stream, bool data_file) {
    (void)data_file;
    while (true) {
      LineScanner::Kind kind = stream.next();
      if (kind == LineScanner::Kind::End) break;
      if (stream.scanner().line_rejected() && kind != LineScanner::Kind::Comment) continue;
      switch (kind) {
        case LineScanner::Kind::Comment:
          break;
        case LineScanner::Kind::Keyword:
          keyword_line(stream);
          break;
        case LineScanner::Kind::Blank:
        case LineScanner::Kind::Data:
          data_line(stream.scanner().text(), stream.scanner().loc(),
                    kind == LineScanner::Kind::Blank);
          break;
        case LineScanner::Kind::End:
          break;
      }
    }
  }

  void keyword_line(LineStream& stream) {
    std::vector<KeywordSegment> segments;
    segments.push_back({stream.scanner().text(), stream.scanner().loc()});
    auto ends_with_comma = [](std::string_view t) {
      std::size_t e = t.size();
      while (e > 0 && (t[e - 1] == ' ' || t[e - 1] == '\t')) --e;
      return e > 0 && t[e - 1] == ',';
    };
    // A line's text lasts only until the scanner moves on: a continued keyword line keeps copies.
    std::deque<std::string> held;
    while (ends_with_comma(segments.back().text)) {
      if (held.size() < segments.size()) {
        segments.back().text = held.emplace_back(segments.back().text);
      }
      SourceLoc last = segments.back().loc.shifted(
          static_cast<std::uint32_t>(segments.back().text.size()));
      LineScanner::Kind k;
      do {
        k = stream.next_in_file();
      } while (k == LineScanner::Kind::Comment);
      if (k == LineScanner::Kind::End) {
        sink_.report(DiagCode::dangling_continuation, last.shifted(static_cast<std::uint32_t>(-1)),
                     "keyword line ends with ',' but no continuation line follows");
        break;
      }
      if (k == LineScanner::Kind::Keyword) {
        sink_.report(DiagCode::dangling_continuation, last.shifted(static_cast<std::uint32_t>(-1)),
                     "keyword line ends with ',' but the next line is a keyword line");
        // That next line is a keyword line of its own: process the current one, then it.
        process_keyword(segments);
        keyword_line(stream);
        return;
      }
      if (k == LineScanner::Kind::Blank) continue;
      segments.push_back({stream.scanner().text(), stream.scanner().loc()});
    }
    process_keyword(segments, &stream);
  }

  void process_keyword(const std::vector<KeywordSegment>& segments, LineStream* stream = nullptr) {
    KeywordLine line;
    if (!parse_keyword_line(segments, line, sink_)) {
      close_block();
      skip_block_ = true;
      return;
    }
    if (line.name == "INCLUDE") {
      if (stream) include(line, *stream);
      return;
    }
    close_block();
    open_block(std::move(line));
  }

  void include(const KeywordLine& line, LineStream& stream) {
    const KeywordParam* input = nullptr;
    for (const KeywordParam& p : line.params) {
      if (p.name == "INPUT") {
        input = &p;
      } else if (p.name == "PASSWORD") {
        sink_.report(DiagCode::unsupported_option, p.loc,
                     "encrypted include files (PASSWORD) are not supported by clinch");
        return;
      } else {
        sink_.report(DiagCode::unknown_parameter, p.loc,
                     fmt::format("unknown parameter '{}' for *INCLUDE", p.spelled))
            .notes.push_back({{}, "valid parameters: INPUT"});
      }
    }
    if (!input) {
      sink_.report(DiagCode::missing_parameter, line.loc, "*INCLUDE requires parameter 'INPUT'");
      return;
    }
    if (!input->has_value || input->value.text.empty()) {
      sink_.report(DiagCode::parameter_needs_value, input->loc,
                   "parameter 'INPUT' needs a value (INPUT=file)");
      return;
    }
    std::uint32_t from = stream.scanner().loc().file;
    std::string path = resolve_path(sources_, from, input->value.text);
    std::string key = canonical(path);
    // Cycle: the file is already open on the stack.
    for (std::size_t level = 0; level < stream.depth(); ++level) {
      if (canonical(sources_.file(stream.file_at(level)).path) == key) {
        std::string chain;
        for (std::size_t k = level; k < stream.depth(); ++k) {
          chain += sources_.file(stream.file_at(k)).display_name + " → ";
        }
        chain += input->value.text;
        sink_.report(DiagCode::include_cycle, input->value.loc,
                     fmt::format("'{}' includes itself ({})", input->value.text, chain));
        return;
      }
    }
    if (stream.depth() >= kMaxIncludeDepth) {
      sink_.report(DiagCode::include_cycle, input->value.loc,
                   fmt::format("*INCLUDE nesting deeper than {} levels", kMaxIncludeDepth));
      return;
    }
    std::string error;
    auto idx = load_once(path, input->value.loc, &error);
    if (!idx) {
      sink_.report(DiagCode::file_not_found, input->value.loc,
                   fmt::format("cannot open '{}': {}", display_of_file_param(input->value),
                               error));
      return;
    }
    stream.push(*idx);
  }

  void report_unknown_keyword(const KeywordLine& line) {
    Diagnostic& d = sink_.report(DiagCode::unknown_keyword, line.loc,
                                 fmt::format("unknown keyword '*{}'", line.spelled));
    // The abbreviation note only when the name is a prefix of exactly one keyword: a prefix of
    // several is no abbreviation Abaqus would have expanded either (input-syntax.md §2).
    const std::string* expansion = nullptr;
    int prefix_of = 0;
    for (const std::string& candidate : registry_.display_names()) {
      std::string folded = fold_name(candidate.substr(1));
      if (folded.size() > line.name.size() && folded.rfind(line.name, 0) == 0) {
        ++prefix_of;
        expansion = &candidate;
      }
    }
    if (prefix_of == 1 && line.name.size() >= 3) {
      d.notes.push_back(
          {line.loc, fmt::format("keywords cannot be abbreviated; the full name is '{}'",
                                 *expansion)});
      return;
    }
    if (auto guess = closest_match(fmt::format("*{}", line.spelled), registry_.display_names())) {
      d.notes.push_back({line.loc, fmt::format("did you mean '{}'?", *guess)});
    }
  }

  // Checks where a keyword stands (input-syntax.md §7.1, §8); false when the block is skipped.
  bool check_level(const KeywordSpec& spec, const KeywordLine& line) {
    const std::string kw = fmt::format("*{}", spec.name);
    const ReaderPosition& p = position_;
    auto wrong_level = [&](std::string message) {
      sink_.report(DiagCode::wrong_level, line.loc, std::move(message));
      return false;
    };
    if (spec.behavior_suboption && !p.in_behavior) {
      if (spec.unsupported_outside_behavior) {
        sink_.report(DiagCode::unsupported_keyword, line.loc,
                     fmt::format("keyword '{}' outside a *CONNECTOR BEHAVIOR belongs to surface "
                                 "contact, which is not supported by clinch", kw));
        return false;
      }
      return wrong_level(fmt::format("'{}' must follow *CONNECTOR BEHAVIOR (it is one of its "
                                     "sub-options)", kw));
    }
    if (p.in_instance && spec.name != "END INSTANCE" && spec.level != KeywordLevel::Anywhere) {
      sink_.report(DiagCode::unsupported_keyword, line.loc,
                   fmt::format("'{}' inside *INSTANCE: definitions inside an instance are not "
                               "supported", kw));
      return false;
    }
    switch (spec.level) {
      case KeywordLevel::Anywhere:
      case KeywordLevel::Block:
        return true;
      case KeywordLevel::History:
        if (!p.in_step) {
          sink_.report(DiagCode::history_data_outside_step, line.loc,
                       fmt::format("'{}' is history data and must be inside a *STEP", kw));
          return false;
        }
        return true;
      case KeywordLevel::Model:
      case KeywordLevel::ModelGeometry:
      case KeywordLevel::ModelOrHistory:
        break;
    }
    if (p.after_first_step && spec.level != KeywordLevel::ModelOrHistory) {
      sink_.report(DiagCode::model_data_in_step, line.loc,
                   fmt::format("'{}' is model data and cannot appear after the first *STEP", kw));
      return false;
    }
    if (p.after_first_step && !p.in_step) {
      sink_.report(DiagCode::history_data_outside_step, line.loc,
                   fmt::format("'{}' after the first *STEP must be inside a *STEP", kw));
      return false;
    }
    if (p.in_step) return true;
    if (spec.level == KeywordLevel::ModelGeometry) {
      if (model_.part_assembly && p.part == 0 && !p.in_assembly) {
        return wrong_level(fmt::format("'{}' must be inside a *PART or the *ASSEMBLY in a deck "
                                       "that uses parts", kw));
      }
      return true;
    }
    if (p.part != 0) {
      return wrong_level(fmt::format("'{}' cannot appear inside *PART '{}'", kw,
                                     model_.parts[p.part].name.display));
    }
    if (p.in_assembly) {
      return wrong_level(fmt::format("'{}' cannot appear inside *ASSEMBLY", kw));
    }
    return true;
  }

  // The parameter an abbreviation stands for among those it begins: the only one, or the one whose
  // name begins all the others (FREQ is FREQUENCY, not the CalculiX FREQUENCYF, which no prefix
  // of FREQUENCY could ever single out; docs/decisions.md, "Abbreviations"). Null if ambiguous.
  static const ParamSpec* shortest_covering(const std::vector<const ParamSpec*>& candidates) {
    if (candidates.empty()) return nullptr;
    const ParamSpec* shortest = *std::min_element(
        candidates.begin(), candidates.end(),
        [](const ParamSpec* a, const ParamSpec* b) { return a->name.size() < b->name.size(); });
    const std::string folded = fold_name(shortest->name);
    for (const ParamSpec* c : candidates) {
      if (fold_name(c->name).rfind(folded, 0) != 0) return nullptr;
    }
    return shortest;
  }

  // Generic parameter checks of input-syntax.md §2 against the spec.
  bool validate_params(const KeywordSpec& spec, const KeywordLine& line, ParamSet& out) {
    const std::size_t errors_before = sink_.error_count();
    const std::string kw = fmt::format("*{}", spec.name);
    std::vector<const ParamSpec*> seen_specs;
    for (const KeywordParam& param : line.params) {
      const ParamSpec* match = nullptr;
      std::vector<const ParamSpec*> prefix_matches;
      for (const ParamSpec& ps : spec.params) {
        std::string folded = fold_name(ps.name);
        if (folded == param.name) {
          match = &ps;
          break;
        }
        if (folded.rfind(param.name, 0) == 0) prefix_matches.push_back(&ps);
      }
      const ParamSpec* shortest = shortest_covering(prefix_matches);
      if (!match && shortest) {
        match = shortest;
        sink_.report(DiagCode::abbreviation_expanded, param.loc,
                     fmt::format("'{}' taken as '{}'", param.spelled, match->name));
      } else if (!match && prefix_matches.size() > 1) {
        std::string list;
        for (const ParamSpec* ps : prefix_matches) {
          list += (list.empty() ? "" : ", ") + std::string(ps->name);
        }
        sink_.report(DiagCode::ambiguous_abbreviation, param.loc,
                     fmt::format("'{}' is ambiguous for {}: {}", param.spelled, kw, list));
        continue;
      }
      if (!match) {
        if (spec.loose_params) continue;
        Diagnostic& d = sink_.report(
            DiagCode::unknown_parameter, param.loc,
            fmt::format("unknown parameter '{}' for {}", param.spelled, kw));
        std::vector<std::string> names;
        for (const ParamSpec& ps : spec.params) names.emplace_back(ps.name);
        if (auto guess = closest_match(param.spelled, names)) {
          d.notes.push_back({param.loc, fmt::format("did you mean '{}'?", *guess)});
        }
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        d.notes.push_back({{}, list.empty() ? kw + " takes no parameters"
                                            : "valid parameters: " + list});
        continue;
      }
      bool duplicate = false;
      for (const ParamSet::Entry& e : out.entries()) {
        if (e.spec == match) {
          sink_.report(DiagCode::duplicate_parameter, param.loc,
                       fmt::format("parameter '{}' given twice", match->name))
              .notes.push_back({e.param->loc, "first given here"});
          duplicate = true;
          break;
        }
      }
      if (duplicate) continue;
      ParamSet::Entry entry{match, &param, {}};
      switch (match->kind) {
        case ParamKind::Flag:
          if (param.has_value) {
            sink_.report(DiagCode::parameter_takes_no_value, param.value.loc,
                         fmt::format("parameter '{}' takes no value", match->name));
            continue;
          }
          break;
        case ParamKind::OptionalValue:
          break;
        case ParamKind::Value:
          if (!param.has_value || param.value.empty()) {
            sink_.report(DiagCode::parameter_needs_value,
                         param.has_value ? param.value.loc : param.loc,
                         fmt::format("parameter '{}' needs a value ({}=...)", match->name,
                                     fold_name(match->name)));
            continue;
          }
          break;
        case ParamKind::FlagOrYesNo:
        case ParamKind::Enum: {
          if (!param.has_value) {
            if (match->kind == ParamKind::FlagOrYesNo) {
              entry.enum_value = "YES";
              break;
            }
            sink_.report(DiagCode::parameter_needs_value, param.loc,
                         fmt::format("parameter '{}' needs a value", match->name));
            continue;
          }
          static const std::vector<std::string_view> kYesNo = {"YES", "NO"};
          const auto& values = match->kind == ParamKind::FlagOrYesNo ? kYesNo : match->values;
          BlockContext ctx(line, spec, out, model_, position_, sink_, sources_);
          auto word = ctx.word(param.value, values, match->name);
          if (!word) continue;
          entry.enum_value = *word;
          break;
        }
      }
      out.add(std::move(entry));
    }
    for (const ParamSpec& ps : spec.params) {
      if (ps.required && !out.has(ps.name)) {
        std::string required;
        for (const ParamSpec& r : spec.params) {
          if (r.required) required += (required.empty() ? "" : ", ") + std::string(r.name);
        }
        sink_.report(DiagCode::missing_parameter, line.loc,
                     fmt::format("{} requires parameter '{}'", kw, ps.name))
            .notes.push_back({{}, "required parameters: " + required});
      }
    }
    return sink_.error_count() == errors_before;
  }

  // A behaviour or amplitude block refused for its parameters still names what it defines:
  // references to that name are not reported again (input-syntax.md §10). -1 marks the name.
  void remember_refused_name(const KeywordSpec& spec, const KeywordLine& line) {
    for (const KeywordParam& p : line.params) {
      if (p.name != "NAME" || !p.has_value || p.value.text.empty()) continue;
      const std::string key = name_key(p.value.text, p.value.quoted);
      if (spec.name == "CONNECTOR BEHAVIOR") model_.behaviors.by_key.emplace(key, -1);
      if (spec.name == "AMPLITUDE") model_.history.amplitude_by_key.emplace(key, -1);
    }
  }

  // Marks every `<name>` in the text of a line that is not read as used, without reporting.
  void mark_references_used(std::string_view text) {
    for (std::size_t lt = text.find('<'); lt != std::string_view::npos;
         lt = text.find('<', lt + 1)) {
      const std::size_t gt = text.find('>', lt + 1);
      if (gt == std::string_view::npos) return;
      parameters_.use(text.substr(lt + 1, gt - lt - 1));
    }
  }

  void substitute(Field& field) {
    if (field.quoted) return;
    const std::string& t = field.text;
    std::size_t lt = t.find('<');
    if (lt == std::string::npos) return;
    if (t.size() >= 3 && t.front() == '<' && t.back() == '>' &&
        t.find('<', 1) == std::string::npos && t.find('>') == t.size() - 1) {
      std::string name = t.substr(1, t.size() - 2);
      const ParameterTable::Entry* entry = parameters_.use(name);
      if (!entry) {
        parameters_.report_undefined(sink_, name, field.loc);
        field.text.clear();
        field.parameter = nullptr;
        substitution_failed_ = true;
        return;
      }
      if (!entry->ok) {
        field.text.clear();
        substitution_failed_ = true;
        return;
      }
      field.parameter = &entry->value;
      field.parameter_loc = entry->loc;
      field.parameter_name = name;
      field.text = entry->value.kind == ParamValue::Kind::String ? entry->value.s
                                                                  : entry->value.to_display();
      return;
    }
    if (t.find('>') != std::string::npos) {
      sink_.report(DiagCode::partial_parameter_reference, field.loc,
                   fmt::format("'{}' mixes a parameter reference with other text; define a new "
                               "parameter", t));
      field.text.clear();
      substitution_failed_ = true;
    }
  }

  void open_block(KeywordLine line) {
    block_line_ = std::move(line);
    const KeywordLine& kl = block_line_;
    skip_block_ = true;
    block_spec_ = nullptr;
    const KeywordSpec* spec = registry_.find(kl.name);
    // Any keyword that is not a behaviour sub-option closes the behaviour block.
    if (!spec || (!spec->behavior_suboption && spec->level != KeywordLevel::Anywhere)) {
      position_.in_behavior = false;
    }
    // A block that is refused as a whole still uses the parameters it names: they are not
    // reported unused (input-syntax.md §6.4 item 6, §10 "follows only from an earlier error").
    for (const KeywordParam& p : kl.params) {
      if (p.has_value) mark_references_used(p.value.text);
    }
    if (!spec) {
      report_unknown_keyword(kl);
      return;
    }
    if (spec->keyword_class == KeywordClass::NotSupported) {
      sink_.report(DiagCode::unsupported_keyword, kl.loc,
                   fmt::format("keyword '*{}' is not supported by clinch", spec->name));
      return;
    }
    if (!check_level(*spec, kl)) return;
    if (spec->keyword_class == KeywordClass::NoEffect) {
      // A parameter that would change the analysis makes the keyword an error (*RESTART, READ:
      // input-syntax.md §9).
      for (const KeywordParam& p : kl.params) {
        for (std::string_view refused : spec->refused_params) {
          if (p.name == fold_name(refused)) {
            sink_.report(DiagCode::unsupported_option, p.loc,
                         fmt::format("*{}, {} is not supported by clinch: {}", spec->name,
                                     refused, spec->refused_reason));
            return;
          }
        }
      }
      if (warned_no_effect_.insert(kl.name).second) {
        sink_.report(DiagCode::keyword_ignored, kl.loc,
                     fmt::format("'*{}' has no effect in clinch and is ignored", spec->name));
      }
      return;
    }
    // Keyword parameter values may be <name> references (input-syntax.md §3.3).
    substitution_failed_ = false;
    for (KeywordParam& p : block_line_.params) {
      if (p.has_value) substitute(p.value);
    }
    block_params_ = ParamSet();
    const bool params_ok = validate_params_with_input(*spec, block_line_, block_params_);
    if (!update_structure_before(*spec, block_line_)) return;
    if (!params_ok || substitution_failed_) {
      remember_refused_name(*spec, block_line_);
      return;
    }
    block_spec_ = spec;
    skip_block_ = false;
    block_data_lines_ = 0;
    data_line_reported_ = false;
    block_ctx_ = std::make_unique<BlockContext>(block_line_, *spec, block_params_, model_,
                                                position_, sink_, sources_);
    handler_ = spec->make_handler ? spec->make_handler() : nullptr;
    if (handler_) handler_->begin(*block_ctx_);
    read_input_file();
  }

  // Every keyword with data lines accepts INPUT=file (input-syntax.md §5.2); it is not listed
  // in each spec.
  bool validate_params_with_input(const KeywordSpec& spec, KeywordLine& line, ParamSet& out) {
    input_param_ = nullptr;
    if (spec.data == DataMode::Fields || spec.data == DataMode::Raw) {
      for (auto it = line.params.begin(); it != line.params.end(); ++it) {
        if (it->name == "INPUT") {
          input_line_param_ = *it;
          input_param_ = &input_line_param_;
          line.params.erase(it);
          break;
        }
      }
    }
    bool ok = validate_params(spec, line, out);
    if (input_param_ && (!input_param_->has_value || input_param_->value.text.empty())) {
      sink_.report(DiagCode::parameter_needs_value, input_param_->loc,
                   "parameter 'INPUT' needs a value (INPUT=file)");
      input_param_ = nullptr;
      ok = false;
    }
    return ok;
  }

  void read_input_file() {
    if (!input_param_) return;
    const Field& value = input_param_->value;
    std::string path = resolve_path(sources_, value.loc.file, value.text);
    std::string error;
    auto idx = load_once(path, value.loc, &error);
    if (!idx) {
      sink_.report(DiagCode::file_not_found, value.loc,
                   fmt::format("cannot open '{}': {}", value.text, error));
      skip_block_ = true;
      return;
    }
    if (block_spec_->name == "PARAMETER") {
      // Already evaluated in the pre-pass.
      input_used_ = true;
      return;
    }
    LineScanner scanner = scan_file(sources_, *idx, sink_);
    for (auto k = scanner.next(); k != LineScanner::Kind::End; k = scanner.next()) {
      if (k == LineScanner::Kind::Comment) continue;
      if (k == LineScanner::Kind::Keyword) {
        sink_.report(DiagCode::keyword_in_data_file, scanner.loc(),
                     "keyword line in a data file read through INPUT=");
        continue;
      }
      deliver_data(scanner.text(), scanner.loc(), k == LineScanner::Kind::Blank);
    }
    check_read_whole(sources_, scanner, *idx, sink_);
    input_used_ = true;
  }

  void data_line(std::string_view text, SourceLoc loc, bool blank) {
    if (!block_open_) {
      if (!blank && !data_before_keyword_reported_) {
        data_before_keyword_reported_ = true;
        sink_.report(DiagCode::data_before_keyword, loc,
                     "data line before the first keyword line");
      }
      return;
    }
    if (skip_block_ || !block_spec_ || block_spec_->data == DataMode::Skip) {
      mark_references_used(text);
      return;
    }
    if (input_used_) {
      if (!blank && !data_line_reported_) {
        data_line_reported_ = true;
        sink_.report(DiagCode::unexpected_data_line, loc,
                     fmt::format("*{} reads its data lines from INPUT=; data lines may not also "
                                 "follow it in the deck", block_spec_->name));
      }
      return;
    }
    deliver_data(text, loc, blank);
  }

  void deliver_data(std::string_view text, SourceLoc loc, bool blank) {
    const KeywordSpec& spec = *block_spec_;
    if (spec.data == DataMode::Skip || (spec.name == "PARAMETER")) return;
    if (spec.data == DataMode::None) {
      if (!blank && !data_line_reported_) {
        data_line_reported_ = true;
        sink_.report(DiagCode::unexpected_data_line, loc,
                     fmt::format("*{} takes no data lines", spec.name));
      }
      return;
    }
    DataLine line{text, loc, blank};
    ++block_data_lines_;
    block_ctx_->set_line_index(block_data_lines_);
    if (blank || spec.data == DataMode::Raw) fields_.clear();
    if (spec.data == DataMode::Fields && !blank) {
      if (!split_fields(text, loc, fields_, sink_)) return;
      if (text.find('<') != std::string_view::npos) {
        substitution_failed_ = false;
        for (Field& f : fields_) substitute(f);
        if (substitution_failed_) return;  // the line's diagnostics would only repeat it
      }
    } else if (spec.data == DataMode::Raw) {
      for (char c : text) {
        if (static_cast<unsigned char>(c) >= 0x80) {
          sink_.report(DiagCode::non_ascii_text, loc,
                       "non-ASCII character in text (Abaqus accepts ASCII only)");
          break;
        }
      }
    }
    if (handler_) handler_->data_line(*block_ctx_, line, fields_);
  }

  void close_block() {
    if (handler_ && block_ctx_) handler_->end(*block_ctx_);
    handler_.reset();
    block_ctx_.reset();
    block_spec_ = nullptr;
    skip_block_ = false;
    input_used_ = false;
    block_open_ = true;
    if (!first_keyword_seen_) first_keyword_seen_ = true;
  }

  // Structure bookkeeping that must happen even when the block's parameters are bad, so that
  // later keywords are judged at the right level (input-syntax.md §7.2, §8).
  bool update_structure_before(const KeywordSpec& spec, const KeywordLine& line) {
    ReaderPosition& p = position_;
    const std::string_view n = spec.name;
    if (n == "CONNECTOR BEHAVIOR") {
      p.in_behavior = true;
      p.behavior_loc = line.loc;
    } else if (n == "STEP") {
      if (p.in_step) {
        sink_.report(DiagCode::missing_end_step, open_step_loc_,
                     "step has no *END STEP before the next *STEP");
      }
      p.in_step = true;
      p.after_first_step = true;
      ++p.step;
      open_step_loc_ = line.loc;
      if (p.part != 0 || p.in_assembly) {
        sink_.report(DiagCode::unbalanced_block, line.loc,
                     p.part != 0 ? "*STEP inside a *PART (missing *END PART)"
                                 : "*STEP inside the *ASSEMBLY (missing *END ASSEMBLY)");
        p.part = 0;
        p.in_assembly = false;
        p.in_instance = false;
      }
    } else if (n == "PART") {
      if (p.part != 0) {
        sink_.report(DiagCode::unbalanced_block, line.loc,
                     "*PART inside another *PART (parts cannot nest; missing *END PART?)");
      } else if (p.in_assembly || assembly_seen_) {
        sink_.report(DiagCode::part_after_assembly, line.loc,
                     "*PART appears after *ASSEMBLY; parts must be defined before the assembly");
      }
      p.part = 0;
      const Field* name_field = block_params_.value("NAME");
      BlockContext ctx(line, spec, block_params_, model_, position_, sink_, sources_);
      std::optional<Name> name = name_field ? ctx.name(*name_field, "NAME") : std::nullopt;
      if (!name) name = Name{"__UNNAMED" + std::to_string(model_.parts.size()), "(unnamed)",
                             line.loc};
      auto [it, inserted] = model_.part_by_key.try_emplace(
          name->key, static_cast<std::int32_t>(model_.parts.size()));
      if (!inserted) {
        sink_.report(DiagCode::duplicate_name, name->loc,
                     fmt::format("part '{}' is already defined", name->display))
            .notes.push_back({model_.parts[it->second].loc, "previous definition is here"});
      }
      Part part;
      part.name = *name;
      part.loc = line.loc;
      model_.parts.push_back(std::move(part));
      p.part = static_cast<std::int32_t>(model_.parts.size() - 1);
    } else if (n == "END PART") {
      if (p.part == 0) {
        sink_.report(DiagCode::unbalanced_block, line.loc, "*END PART without *PART");
      }
      p.part = 0;
    } else if (n == "ASSEMBLY") {
      if (assembly_seen_) {
        sink_.report(DiagCode::unbalanced_block, line.loc, "a deck has at most one *ASSEMBLY");
      } else if (p.part != 0) {
        sink_.report(DiagCode::unbalanced_block, line.loc, "*ASSEMBLY inside *PART");
        p.part = 0;
      }
      assembly_seen_ = true;
      p.in_assembly = true;
      assembly_loc_ = line.loc;
    } else if (n == "END ASSEMBLY") {
      if (!p.in_assembly) {
        sink_.report(DiagCode::unbalanced_block, line.loc, "*END ASSEMBLY without *ASSEMBLY");
      }
      p.in_assembly = false;
      p.in_instance = false;
    } else if (n == "INSTANCE") {
      if (!p.in_assembly) {
        sink_.report(DiagCode::wrong_level, line.loc,
                     "*INSTANCE must be inside the *ASSEMBLY");
        return false;
      }
      p.in_instance = true;
    } else if (n == "END INSTANCE") {
      if (!p.in_instance) {
        sink_.report(DiagCode::unbalanced_block, line.loc, "*END INSTANCE without *INSTANCE");
      }
      p.in_instance = false;
    } else if (n == "END STEP") {
      if (!p.in_step) {
        sink_.report(DiagCode::end_step_without_step, line.loc,
                     "*END STEP without a matching *STEP");
      }
      p.in_step = false;
    }
    return true;
  }

  void finish_structure() {
    if (position_.in_step) {
      sink_.report(DiagCode::missing_end_step, open_step_loc_, "step has no *END STEP");
    }
    if (position_.part != 0) {
      sink_.report(DiagCode::unbalanced_block, part_loc(), "*PART has no *END PART");
    }
    if (position_.in_assembly) {
      sink_.report(DiagCode::unbalanced_block, assembly_loc(), "*ASSEMBLY has no *END ASSEMBLY");
    }
    if (!position_.after_first_step) {
      sink_.report(DiagCode::no_step, {main_file_, 1, 1},
                   "the deck defines no *STEP; nothing to analyse");
    }
  }

  SourceLoc part_loc() const { return model_.parts[position_.part].name.loc; }
  SourceLoc assembly_loc() const { return assembly_loc_; }

  SourceManager& sources_;
  Model& model_;
  DiagnosticSink& sink_;
  const KeywordRegistry& registry_;
  ParameterTable parameters_;
  std::uint32_t main_file_ = 0;
  std::unordered_map<std::string, std::uint32_t> loaded_;
  std::vector<std::string> open_files_;

  ReaderPosition position_;
  SourceLoc open_step_loc_;
  SourceLoc assembly_loc_;
  bool assembly_seen_ = false;
  std::unordered_set<std::string> warned_no_effect_;

  KeywordLine block_line_;
  ParamSet block_params_;
  const KeywordSpec* block_spec_ = nullptr;
  std::unique_ptr<BlockContext> block_ctx_;
  std::unique_ptr<KeywordHandler> handler_;
  KeywordParam input_line_param_;
  const KeywordParam* input_param_ = nullptr;
  bool input_used_ = false;
  bool skip_block_ = false;
  bool block_open_ = false;
  bool first_keyword_seen_ = false;
  bool data_before_keyword_reported_ = false;
  bool data_line_reported_ = false;
  bool substitution_failed_ = false;
  std::uint32_t block_data_lines_ = 0;
  std::vector<Field> fields_;
};

}  // namespace

ReadStatus read_deck_file(const std::string& path, SourceManager& sources, Model& model,
                          DiagnosticSink& sink, std::string* io_error) {
  std::string error;
  auto idx = sources.load_deck(path, &error);
  if (!idx) {
    if (io_error) *io_error = fmt::format("cannot read '{}': {}", path, error);
    return ReadStatus::IoError;
  }
  Reader(sources, model, sink).run(*idx);
  if (!sources.read_error().empty()) {
    // The deck read is not the deck on disk: its diagnostics would describe a truncated deck.
    if (io_error) *io_error = sources.read_error();
    return ReadStatus::IoError;
  }
  validate_model(model, sink);
  return ReadStatus::Ok;
}

void read_deck_text(const std::string& display_name, std::string text, SourceManager& sources,
                    Model& model, DiagnosticSink& sink) {
  std::uint32_t idx = sources.add_buffer(display_name, std::move(text));
  Reader(sources, model, sink).run(idx);
  validate_model(model, sink);
}

}  // namespace clinch
