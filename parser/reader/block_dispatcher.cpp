#include "parser/reader/block_dispatcher.hpp"

#include <fmt/format.h>

#include <utility>

#include "parser/file_scan.hpp"
#include "parser/reader/keyword_checks.hpp"

namespace clinch {

void BlockDispatcher::open(KeywordLine line) {
  block_line_ = std::move(line);
  const KeywordLine& kl = block_line_;
  skip_block_ = true;
  block_spec_ = nullptr;
  const KeywordSpec* spec = registry_.find(kl.name);
  const std::size_t error_index = sink_.diagnostics().size();
  // An unknown keyword stands where the keyword it was meant to be stands.
  const KeywordSpec* meant = spec ? nullptr : report_unknown_keyword(kl, registry_, sink_);
  const KeywordSpec* stands_as = spec ? spec : meant;
  // Any keyword that is not a behaviour sub-option closes the behaviour block.
  if (!stands_as ||
      (!stands_as->behavior_suboption && stands_as->level != KeywordLevel::Anywhere)) {
    structure_.leave_behavior();
  }
  if (!stands_as ||
      (!stands_as->material_suboption && stands_as->level != KeywordLevel::Anywhere)) {
    structure_.leave_material();
  }
  if (!stands_as ||
      (!stands_as->coupling_suboption && stands_as->level != KeywordLevel::Anywhere)) {
    structure_.leave_coupling();
  }
  const ReaderPosition& at = structure_.position();
  const std::string_view as = stands_as ? std::string_view(stands_as->name) : kl.name;
  misspelt_.keyword(
      kl, misspelt_.opened_behavior() ? at.in_behavior : at.in_step && as != "END STEP" && as != "STEP",
      sink_);
  // A block that is refused as a whole still uses the parameters it names: they are not
  // reported unused (input-syntax.md §6.4 item 6, §10 "follows only from an earlier error").
  for (const KeywordParam& p : kl.params) {
    if (p.has_value) substitution_.mark_references_used(p.value.text);
  }
  if (!spec) {
    auto& behaviors = model_.behaviors.behaviors;
    if (meant && meant->behavior_suboption && at.in_behavior && !behaviors.empty() &&
        behaviors.back().loc == at.behavior_loc) {
      behaviors.back().misspelt_option = true;
    }
    if (meant && MisspeltBlock::changes_structure(*meant)) {
      structure_.enter(*meant, kl, ParamSet());
      remember_refused_name(*meant, kl);
      misspelt_.begin(error_index, *meant, kl);
    }
    return;
  }
  if (spec->keyword_class == KeywordClass::NotSupported) {
    sink_.report(DiagCode::unsupported_keyword, kl.loc,
                 fmt::format("keyword '*{}' is not supported by clinch", spec->name));
    if (spec->refused_procedure && at.in_step && !model_.history.steps.empty()) {
      model_.history.steps.back().procedure_refused = true;
    }
    return;
  }
  if (!structure_.check_level(*spec, kl)) return;
  if (spec->keyword_class == KeywordClass::NoEffect) {
    // A parameter that would change the analysis makes the keyword an error (*RESTART, READ:
    // input-syntax.md §9).
    for (const KeywordParam& p : kl.params) {
      for (std::string_view refused : spec->refused_params) {
        if (p.name == fold_name(refused)) {
          sink_.report(DiagCode::unsupported_option, p.loc,
                       fmt::format("*{}, {} is not supported by clinch: {}", spec->name, refused,
                                   spec->refused_reason));
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
  substitution_.clear_failure();
  for (KeywordParam& p : block_line_.params) {
    if (p.has_value) substitution_.substitute(p.value);
  }
  block_params_ = ParamSet();
  const bool params_ok = validate_params_with_input(*spec, block_line_, block_params_);
  if (!structure_.enter(*spec, block_line_, block_params_)) return;
  if (!params_ok || substitution_.failed()) {
    remember_refused_name(*spec, block_line_);
    return;
  }
  block_spec_ = spec;
  skip_block_ = false;
  block_data_lines_ = 0;
  data_line_reported_ = false;
  block_ctx_ = std::make_unique<BlockContext>(block_line_, *spec, block_params_, model_,
                                              structure_.position(), sink_, sources_);
  handler_ = spec->make_handler ? spec->make_handler() : nullptr;
  if (handler_) handler_->begin(*block_ctx_);
  read_input_file();
}

void BlockDispatcher::close() {
  if (handler_ && block_ctx_) handler_->end(*block_ctx_);
  handler_.reset();
  block_ctx_.reset();
  block_spec_ = nullptr;
  skip_block_ = false;
  input_used_ = false;
  block_open_ = true;
}

void BlockDispatcher::finish() {
  close();
  misspelt_.finish(sink_);
}

void BlockDispatcher::close_unreadable() {
  close();
  skip_block_ = true;
}

// Every keyword with data lines accepts INPUT=file (input-syntax.md §5.2); it is not listed
// in each spec.
bool BlockDispatcher::validate_params_with_input(const KeywordSpec& spec, KeywordLine& line,
                                                 ParamSet& out) {
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
  bool ok = validate_params(spec, line, out, model_, structure_.position(), sink_, sources_);
  if (input_param_ && (!input_param_->has_value || input_param_->value.text.empty())) {
    sink_.report(DiagCode::parameter_needs_value, input_param_->loc,
                 "parameter 'INPUT' needs a value (INPUT=file)");
    input_param_ = nullptr;
    ok = false;
  }
  return ok;
}

void BlockDispatcher::read_input_file() {
  if (!input_param_) return;
  const Field& value = input_param_->value;
  std::string path = files_.resolve(value.loc.file, value.text);
  std::string error;
  auto idx = files_.load_once(path, value.loc, &error);
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

void BlockDispatcher::data_line(std::string_view text, SourceLoc loc, bool blank) {
  if (!block_open_) {
    if (!blank && !data_before_keyword_reported_) {
      data_before_keyword_reported_ = true;
      sink_.report(DiagCode::data_before_keyword, loc, "data line before the first keyword line");
    }
    return;
  }
  if (skip_block_ || !block_spec_ || block_spec_->data == DataMode::Skip) {
    substitution_.mark_references_used(text);
    return;
  }
  if (input_used_) {
    if (!blank && !data_line_reported_) {
      data_line_reported_ = true;
      sink_.report(DiagCode::unexpected_data_line, loc,
                   fmt::format("*{} reads its data lines from INPUT=; data lines may not also "
                               "follow it in the deck",
                               block_spec_->name));
    }
    return;
  }
  deliver_data(text, loc, blank);
}

void BlockDispatcher::deliver_data(std::string_view text, SourceLoc loc, bool blank) {
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
      substitution_.clear_failure();
      for (Field& f : fields_) substitution_.substitute(f);
      if (substitution_.failed()) return;  // the line's diagnostics would only repeat it
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

// A behaviour or amplitude block refused for its parameters still names what it defines:
// references to that name are not reported again (input-syntax.md §10). -1 marks the name.
void BlockDispatcher::remember_refused_name(const KeywordSpec& spec, const KeywordLine& line) {
  for (const KeywordParam& p : line.params) {
    if (p.name != "NAME" || !p.has_value || p.value.text.empty()) continue;
    const std::string key = name_key(p.value.text, p.value.quoted);
    if (spec.name == "CONNECTOR BEHAVIOR") model_.behaviors.by_key.emplace(key, -1);
    if (spec.name == "AMPLITUDE") model_.history.amplitude_by_key.emplace(key, -1);
  }
}

}  // namespace clinch
