#include "parser/reader/keyword_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/suggest.hpp"

namespace clinch {
namespace {

// The parameter an abbreviation stands for among those it begins: the only one, or the one whose
// name begins all the others (FREQ is FREQUENCY, not the CalculiX FREQUENCYF, which no prefix
// of FREQUENCY could ever single out; docs/decisions.md, "Abbreviations"). Null if ambiguous.
const ParamSpec* shortest_covering(const std::vector<const ParamSpec*>& candidates) {
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

}  // namespace

const KeywordSpec* report_unknown_keyword(const KeywordLine& line,
                                          const KeywordRegistry& registry, DiagnosticSink& sink) {
  Diagnostic& d = sink.report(DiagCode::unknown_keyword, line.loc,
                              fmt::format("unknown keyword '*{}'", line.spelled));
  // The abbreviation note only when the name is a prefix of exactly one keyword: a prefix of
  // several is no abbreviation Abaqus would have expanded either (input-syntax.md §2).
  const std::string* expansion = nullptr;
  int prefix_of = 0;
  for (const std::string& candidate : registry.display_names()) {
    std::string folded = fold_name(candidate.substr(1));
    if (folded.size() > line.name.size() && folded.rfind(line.name, 0) == 0) {
      ++prefix_of;
      expansion = &candidate;
    }
  }
  if (prefix_of == 1 && line.name.size() >= 3) {
    d.notes.push_back(
        {line.loc,
         fmt::format("keywords cannot be abbreviated; the full name is '{}'", *expansion)});
    return registry.find(fold_name(expansion->substr(1)));
  }
  if (auto guess = closest_match(fmt::format("*{}", line.spelled), registry.display_names())) {
    d.notes.push_back({line.loc, fmt::format("did you mean '{}'?", *guess)});
    return registry.find(fold_name(guess->substr(1)));
  }
  return nullptr;
}

bool validate_params(const KeywordSpec& spec, const KeywordLine& line, ParamSet& out, Model& model,
                     const ReaderPosition& position, DiagnosticSink& sink,
                     const SourceManager& sources) {
  const std::size_t errors_before = sink.error_count();
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
      sink.report(DiagCode::abbreviation_expanded, param.loc,
                  fmt::format("'{}' taken as '{}'", param.spelled, match->name));
    } else if (!match && prefix_matches.size() > 1) {
      std::string list;
      for (const ParamSpec* ps : prefix_matches) {
        list += (list.empty() ? "" : ", ") + std::string(ps->name);
      }
      sink.report(DiagCode::ambiguous_abbreviation, param.loc,
                  fmt::format("'{}' is ambiguous for {}: {}", param.spelled, kw, list));
      continue;
    }
    if (!match) {
      if (spec.loose_params) continue;
      Diagnostic& d = sink.report(DiagCode::unknown_parameter, param.loc,
                                  fmt::format("unknown parameter '{}' for {}", param.spelled, kw));
      std::vector<std::string> names;
      for (const ParamSpec& ps : spec.params) names.emplace_back(ps.name);
      if (auto guess = closest_match(param.spelled, names)) {
        d.notes.push_back({param.loc, fmt::format("did you mean '{}'?", *guess)});
      }
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      d.notes.push_back(
          {{}, list.empty() ? kw + " takes no parameters" : "valid parameters: " + list});
      continue;
    }
    bool duplicate = false;
    for (const ParamSet::Entry& e : out.entries()) {
      if (e.spec == match) {
        sink.report(DiagCode::duplicate_parameter, param.loc,
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
          sink.report(DiagCode::parameter_takes_no_value, param.value.loc,
                      fmt::format("parameter '{}' takes no value", match->name));
          continue;
        }
        break;
      case ParamKind::OptionalValue:
        break;
      case ParamKind::Value:
        if (!param.has_value || param.value.empty()) {
          sink.report(DiagCode::parameter_needs_value,
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
          sink.report(DiagCode::parameter_needs_value, param.loc,
                      fmt::format("parameter '{}' needs a value", match->name));
          continue;
        }
        static const std::vector<std::string_view> kYesNo = {"YES", "NO"};
        const auto& values = match->kind == ParamKind::FlagOrYesNo ? kYesNo : match->values;
        BlockContext ctx(line, spec, out, model, position, sink, sources);
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
      sink.report(DiagCode::missing_parameter, line.loc,
                  fmt::format("{} requires parameter '{}'", kw, ps.name))
          .notes.push_back({{}, "required parameters: " + required});
    }
  }
  return sink.error_count() == errors_before;
}

}  // namespace clinch
