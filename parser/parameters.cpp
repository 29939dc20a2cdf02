#include "parser/parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <span>
#include <utility>

#include "base/suggest.hpp"

namespace clinch {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r' || c == '\n';
}
bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }

bool is_identifier(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return false;
  return std::all_of(s.begin(), s.end(), is_ident_char);
}

SourceLoc at(SourceLoc line_loc, std::size_t offset) {
  return line_loc.shifted(static_cast<std::uint32_t>(offset));
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::tolower(static_cast<unsigned char>(a[k])) !=
        std::tolower(static_cast<unsigned char>(b[k]))) {
      return false;
    }
  }
  return true;
}

}  // namespace

void ParameterTable::add_line(ParameterLine line) {
  const std::string_view text = line.text;
  const std::string_view body = text.substr(0, std::min(find_comment(text), text.size()));
  if (std::any_of(body.begin(), body.end(), [](char c) { return !is_blank(c); })) {
    has_content_ = true;
  }
  lines_.push_back(std::move(line));
}

// Splits one line into `name = expression` (input-syntax.md §6.2). Reports lines that are not a
// simple assignment. Returns nothing for blank and comment lines and for lines whose target is
// not a usable name; returns a Definition with statement_ok=false when the name is known but the
// statement is rejected, so that later uses of the name stay silent (no cascade).
std::optional<ParameterTable::Definition> ParameterTable::parse_definition(
    std::size_t line_index, DiagnosticSink& sink) const {
  const ParameterLine& line = lines_[line_index];
  const std::string_view text = line.text;
  const std::size_t body_end = std::min(find_comment(text), text.size());
  const std::string_view body = text.substr(0, body_end);
  std::size_t b = 0;
  while (b < body.size() && is_blank(body[b])) ++b;
  if (b == body.size()) return std::nullopt;  // blank or comment-only line

  auto report = [&](DiagCode code, std::size_t offset, std::string message) {
    sink.report(code, at(line.loc, offset), std::move(message));
  };
  auto failed_definition = [&](std::size_t target_begin,
                               std::size_t target_end) -> std::optional<Definition> {
    const std::string_view target = body.substr(target_begin, target_end - target_begin);
    if (!is_identifier(target) || is_python_keyword(target)) return std::nullopt;
    Definition d;
    d.name = std::string(target);
    d.name_loc = at(line.loc, target_begin);
    d.line = line_index;
    d.statement_ok = false;
    return d;
  };
  auto trimmed_end = [&](std::size_t end) {
    while (end > b && is_blank(body[end - 1])) --end;
    return end;
  };

  // The first '=' outside strings and brackets that is a plain assignment.
  std::size_t assign = std::string_view::npos;
  std::size_t comparison = std::string_view::npos;
  int depth = 0;
  for (std::size_t k = b; k < body.size();) {
    const char c = body[k];
    if (c == '\'' || c == '"') {
      k = skip_string_literal(body, k);
      continue;
    }
    if (c == '(' || c == '[' || c == '{') ++depth;
    if ((c == ')' || c == ']' || c == '}') && depth > 0) --depth;
    if (c != '=' || depth != 0) {
      ++k;
      continue;
    }
    const char next = k + 1 < body.size() ? body[k + 1] : '\0';
    const char prev = k > b ? body[k - 1] : '\0';
    const char prev2 = k > b + 1 ? body[k - 2] : '\0';
    if (next == '=') {  // '=='
      if (comparison == std::string_view::npos) comparison = k;
      k += 2;
      continue;
    }
    std::size_t op_begin = std::string_view::npos;  // augmented assignment operator
    if ((prev == '<' || prev == '>') && prev2 == prev) {
      op_begin = k - 2;  // <<= >>=
    } else if (prev == '<' || prev == '>' || prev == '!' || prev == ':') {
      if (comparison == std::string_view::npos && prev != ':') comparison = k - 1;
      ++k;  // <= >= != :=
      continue;
    } else if (prev != '\0' && std::string_view("+-*/%&|^@").find(prev) != std::string_view::npos) {
      op_begin = k - 1;
      if ((prev == '*' || prev == '/') && prev2 == prev) op_begin = k - 2;  // **= //=
    }
    if (op_begin != std::string_view::npos) {
      const std::string_view op = body.substr(op_begin, k + 1 - op_begin);
      report(DiagCode::unsupported_expression, op_begin,
             fmt::format("augmented assignment ('{}') is not supported: write 'name = name {} ...'",
                         op, op.substr(0, op.size() - 1)));
      return failed_definition(b, trimmed_end(op_begin));
    }
    assign = k;
    break;
  }

  if (assign == std::string_view::npos) {
    std::size_t word_end = b;
    while (word_end < body.size() && is_ident_char(body[word_end])) ++word_end;
    const std::string_view word = body.substr(b, word_end - b);
    if (is_python_keyword(word)) {
      report(DiagCode::unsupported_expression, b,
             fmt::format("'{}' statements are not supported in *PARAMETER blocks; only "
                         "definitions 'name = expression' are",
                         word));
    } else if (comparison != std::string_view::npos) {
      report(DiagCode::unsupported_expression, comparison,
             "this line is a comparison, not a definition 'name = expression'");
    } else {
      report(DiagCode::unsupported_expression, b,
             "expected a definition 'name = expression' (any other statement is not supported "
             "in *PARAMETER blocks)");
    }
    return std::nullopt;
  }

  const std::size_t target_end = trimmed_end(assign);
  const std::string_view target = body.substr(b, target_end - b);
  if (target.empty()) {
    report(DiagCode::expression_syntax, assign, "expected a parameter name before '='");
    return std::nullopt;
  }
  if (!is_identifier(target)) {
    std::size_t p = 0;
    if (is_ident_start(target[0])) {
      while (p < target.size() && is_ident_char(target[p])) ++p;
    }
    std::size_t q = p;
    while (q < target.size() && is_blank(target[q])) ++q;
    const char after = p > 0 && q < target.size() ? target[q] : '\0';
    if (after == ',') {
      report(DiagCode::unsupported_expression, b + q,
             "tuple assignment is not supported: write one definition per line");
    } else if (after == '.' || after == '[') {
      report(DiagCode::unsupported_expression, b + q,
             "only a plain name can be assigned in a *PARAMETER definition");
    } else if (after == ':') {
      report(DiagCode::unsupported_expression, b + q,
             "annotations are not supported in *PARAMETER definitions");
    } else {
      report(DiagCode::invalid_parameter_name, b,
             fmt::format("'{}' is not a valid parameter name (letters, digits and '_', not "
                         "starting with a digit)",
                         target.size() > 40 ? std::string(target.substr(0, 37)) + "..."
                                            : std::string(target)));
    }
    return std::nullopt;
  }
  if (is_python_keyword(target)) {
    report(DiagCode::invalid_parameter_name, b,
           fmt::format("'{}' is a reserved word and cannot be a parameter name", target));
    return std::nullopt;
  }

  Definition d;
  d.name = std::string(target);
  d.name_loc = at(line.loc, b);
  d.line = line_index;
  d.expr_begin = assign + 1;
  d.expr_end = body_end;
  const std::string_view expr = body.substr(d.expr_begin);
  if (std::all_of(expr.begin(), expr.end(), is_blank)) {
    report(DiagCode::expression_syntax, assign + 1, "expected an expression after '='");
    d.statement_ok = false;
  }
  return d;
}

const ParamValue* ParameterTable::lookup_during(std::size_t def_index, std::string_view name,
                                                SourceLoc use_loc, DiagnosticSink& sink) {
  if (auto it = slots_.find(name); it != slots_.end()) {
    it->second.used = true;
    // A parameter whose definition failed: its error is reported; stay silent.
    return it->second.entry.ok ? &it->second.entry.value : nullptr;
  }
  // Not defined yet: defined later in the deck (E0403), or nowhere (E0402). §6.4 item 2.
  if (auto it = definitions_by_name_.find(name); it != definitions_by_name_.end()) {
    referenced_early_.emplace(name);
    Diagnostic& d = sink.report(DiagCode::parameter_used_before_definition, use_loc,
                                fmt::format("parameter '{}' is used before it is defined", name));
    const auto later = std::find_if(it->second.begin(), it->second.end(),
                                    [def_index](std::size_t j) { return j > def_index; });
    if (later != it->second.end()) {
      d.notes.push_back({definitions_[*later].name_loc, "defined later here"});
    }
    return nullptr;
  }
  report_undefined(sink, name, use_loc);
  return nullptr;
}

void ParameterTable::evaluate(DiagnosticSink& sink) {
  if (evaluated_) return;
  evaluated_ = true;

  for (std::size_t k = 0; k < lines_.size(); ++k) {
    std::optional<Definition> d = parse_definition(k, sink);
    if (!d) continue;
    auto [it, inserted] = definitions_by_name_.try_emplace(d->name);
    if (inserted) names_in_order_.push_back(d->name);
    it->second.push_back(definitions_.size());
    definitions_.push_back(std::move(*d));
  }

  // In file order, like one Python script (§6.4 item 1).
  for (std::size_t i = 0; i < definitions_.size(); ++i) {
    const Definition& def = definitions_[i];
    auto previous = slots_.find(def.name);
    std::optional<ParamValue> value;
    if (def.statement_ok) {
      if (previous != slots_.end()) {
        Diagnostic& d = sink.report(DiagCode::parameter_redefined, def.name_loc,
                                    fmt::format("parameter '{}' redefined", def.name));
        d.notes.push_back({previous->second.entry.loc, "previous definition is here"});
      } else if (is_builtin_constant(def.name)) {
        sink.report(DiagCode::parameter_shadows_builtin, def.name_loc,
                    fmt::format("parameter '{0}' hides the constant {0}", def.name));
      } else if (is_builtin_function(def.name)) {
        sink.report(DiagCode::parameter_shadows_builtin, def.name_loc,
                    fmt::format("parameter '{0}' hides the built-in function {0}", def.name));
      }
      const std::string_view line = lines_[def.line].text;
      const std::string_view expr = line.substr(def.expr_begin, def.expr_end - def.expr_begin);
      const ParamLookup lookup = [this, i, &sink](std::string_view name, SourceLoc use_loc) {
        return lookup_during(i, name, use_loc, sink);
      };
      // A parameter defined earlier hides a built-in of the same name (§6.2, W0404).
      const ParamDefinedCheck is_parameter = [this](std::string_view name) {
        return slots_.find(name) != slots_.end();
      };
      value = evaluate_expression(expr, at(lines_[def.line].loc, def.expr_begin), lookup, sink,
                                  is_parameter);
    }
    Slot& slot = slots_[def.name];
    if (previous == slots_.end()) {
      slot.first_loc = def.name_loc;
      slot.used = referenced_early_.count(def.name) > 0;
    }
    slot.entry.name = def.name;
    slot.entry.loc = def.name_loc;
    slot.entry.ok = value.has_value();
    slot.entry.value = value ? std::move(*value) : ParamValue{};
    if (!value) slot.any_failed = true;
  }
}

const ParameterTable::Entry* ParameterTable::use(std::string_view name) {
  const auto it = slots_.find(name);
  if (it == slots_.end()) return nullptr;
  it->second.used = true;
  return &it->second.entry;
}

std::optional<std::string> ParameterTable::suggest(std::string_view name) const {
  // A case-only mismatch first: parameter names are case-sensitive (§6.2), a wrong case is the
  // likeliest slip.
  for (const std::string& candidate : names_in_order_) {
    if (candidate != name && equal_ignoring_case(candidate, name)) return candidate;
  }
  std::vector<std::string> others;
  for (const std::string& candidate : names_in_order_) {
    if (candidate != name) others.push_back(candidate);
  }
  return closest_match(name, std::span<const std::string>(others));
}

void ParameterTable::report_undefined(DiagnosticSink& sink, std::string_view name,
                                      SourceLoc loc) const {
  Diagnostic& d = sink.report(DiagCode::undefined_parameter, loc,
                              fmt::format("undefined parameter '{}'", name));
  if (const auto match = suggest(name)) {
    const bool case_only = equal_ignoring_case(*match, name);
    d.notes.push_back(
        {SourceLoc{}, fmt::format("did you mean '{}'?{}", *match,
                                  case_only ? " (parameter names are case-sensitive)" : "")});
  }
}

void ParameterTable::report_unused(DiagnosticSink& sink) const {
  for (const std::string& name : names_in_order_) {
    const auto it = slots_.find(name);
    if (it == slots_.end() || it->second.used || it->second.any_failed) continue;
    sink.report(DiagCode::parameter_unused, it->second.first_loc,
                fmt::format("parameter '{}' is defined but never used", name));
  }
}

}  // namespace clinch
