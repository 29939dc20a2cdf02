#include "parser/block_context.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "parser/expression.hpp"
#include "parser/source_manager.hpp"
#include "base/suggest.hpp"

namespace clinch {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Field text as quoted in a message: long texts are cut (a 10 MB field must not become a
// 10 MB message).
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 60;
  if (text.size() <= kMax) return std::string(text);
  return std::string(text.substr(0, kMax)) + "...";
}

// A valid unquoted name (input-syntax.md §4): a letter or '_' first, then letters, digits, '_',
// '-', and '/', which Abaqus/CAE writes unquoted in the sets it names (Springs/Dashpots-1-spring;
// docs/decisions.md, "Names").
bool is_unquoted_name(std::string_view text) {
  if (text.empty()) return false;
  char c0 = text[0];
  if (!(std::isalpha(static_cast<unsigned char>(c0)) || c0 == '_')) return false;
  for (char c : text) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '/')) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool parse_integer_text(std::string_view text, std::int64_t& value) {
  if (text.empty()) return false;
  std::size_t i = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  if (i == text.size() || text.size() - i > 19) return false;  // 19 digits fit an int64
  std::uint64_t magnitude = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (!is_digit(c)) return false;
    magnitude = magnitude * 10 + static_cast<std::uint64_t>(c - '0');
  }
  const std::uint64_t limit = text[0] == '-' ? 9223372036854775808ull : 9223372036854775807ull;
  if (magnitude > limit) return false;
  value = text[0] == '-' ? static_cast<std::int64_t>(0 - magnitude)
                         : static_cast<std::int64_t>(magnitude);
  return true;
}

bool parse_real_text(std::string_view text, double& value, bool* overflow) {
  if (overflow) *overflow = false;
  // Fast path: plain C syntax (no D exponent, no '+' sign) goes straight to from_chars, which
  // accepts the same grammar once the first character is a digit or a '.'. inf, nan and hex
  // start with a letter or stop early and fall through to the checks below.
  if (!text.empty() && text.size() < 64) {
    std::size_t s = text[0] == '-' ? 1 : 0;
    bool plain = s < text.size() && (is_digit(text[s]) || text[s] == '.');
    for (char c : text) plain &= (c != 'd') & (c != 'D') & (c != 'x') & (c != 'X');
    if (plain) {
      auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (ec == std::errc() && ptr == text.data() + text.size()) return true;
    }
  }
  // Grammar: [sign] (digits [. digits*] | . digits) [(e|E|d|D) [sign] digits]
  std::size_t i = 0, n = text.size();
  char buffer[128];
  if (n == 0 || n >= sizeof buffer) return false;
  if (text[i] == '+' || text[i] == '-') ++i;
  std::size_t digits = 0;
  while (i < n && is_digit(text[i])) ++i, ++digits;
  if (i < n && text[i] == '.') {
    ++i;
    while (i < n && is_digit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  std::size_t exponent_at = n;
  if (i < n && (text[i] == 'e' || text[i] == 'E' || text[i] == 'd' || text[i] == 'D')) {
    exponent_at = i;
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < n && is_digit(text[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  if (i != n) return false;
  std::size_t skip = text[0] == '+' ? 1 : 0;
  std::size_t length = 0;
  for (std::size_t k = skip; k < n; ++k) {
    buffer[length++] = (k == exponent_at) ? 'e' : text[k];
  }
  auto [ptr, ec] = std::from_chars(buffer, buffer + length, value);
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports underflow as out of range too; only a huge magnitude is an overflow.
    errno = 0;
    buffer[length] = '\0';
    double v = std::strtod(buffer, nullptr);
    if (std::isinf(v)) {
      if (overflow) *overflow = true;
      return true;
    }
    value = v;
    return true;
  }
  return ec == std::errc() && ptr == buffer + length;
}

std::string BlockContext::keyword_display() const { return fmt::format("*{}", spec_.name); }

Diagnostic& BlockContext::report(DiagCode code, SourceLoc loc, std::string message) {
  return sink_.report(code, loc, std::move(message));
}

Diagnostic& BlockContext::report(DiagCode code, const Field& field, std::string message) {
  Diagnostic& d = sink_.report(code, field.loc, std::move(message));
  if (field.parameter) {
    d.notes.push_back({field.parameter_loc,
                       fmt::format("value comes from parameter '{}' defined at {}",
                                   field.parameter_name, sources_.format(field.parameter_loc))});
  }
  return d;
}

std::optional<std::int64_t> BlockContext::integer(const Field& field, std::string_view what) {
  if (field.parameter) {
    const ParamValue& v = *field.parameter;
    if (v.kind == ParamValue::Kind::Int) return v.i;
    if (v.kind == ParamValue::Kind::Float && std::isfinite(v.f) && v.f == std::floor(v.f) &&
        std::fabs(v.f) < 9.0e18) {
      return static_cast<std::int64_t>(v.f);
    }
    if (v.kind == ParamValue::Kind::String) {
      report(DiagCode::parameter_type_error, field,
             fmt::format("parameter '{}' is a string; a number is expected here for {}",
                         field.parameter_name, what));
    } else {
      report(DiagCode::expected_integer, field,
             fmt::format("expected an integer for {}, got {}", what, v.to_display()));
    }
    return std::nullopt;
  }
  if (field.empty()) return std::nullopt;
  std::int64_t value = 0;
  if (!field.quoted && parse_integer_text(field.text, value)) {
    if (field.had_inner_blank) {
      report(DiagCode::blank_in_field, field,
             fmt::format("blank in '{}' ignored; the value is {}", shown(field.text), value));
    }
    return value;
  }
  double real = 0;
  bool overflow = false;
  if (!field.quoted && parse_real_text(field.text, real, &overflow) && !overflow &&
      real == std::floor(real) && std::fabs(real) < 9.0e18) {
    report(DiagCode::real_as_integer, field,
           fmt::format("real value '{}' used where an integer is expected", shown(field.text)));
    return static_cast<std::int64_t>(real);
  }
  report(DiagCode::expected_integer, field,
         fmt::format("expected an integer for {}, got '{}'", what, shown(field.text)));
  return std::nullopt;
}

std::optional<double> BlockContext::real(const Field& field, std::string_view what) {
  if (field.parameter) {
    const ParamValue& v = *field.parameter;
    if (v.is_number()) return v.as_double();
    report(DiagCode::parameter_type_error, field,
           fmt::format("parameter '{}' is a string; a number is expected here for {}",
                       field.parameter_name, what));
    return std::nullopt;
  }
  if (field.empty()) return std::nullopt;
  double value = 0;
  bool overflow = false;
  if (field.quoted || !parse_real_text(field.text, value, &overflow)) {
    report(DiagCode::expected_number, field,
           fmt::format("expected a number for {}, got '{}'", what, shown(field.text)));
    return std::nullopt;
  }
  if (overflow) {
    report(DiagCode::value_out_of_range, field,
           fmt::format("{} '{}' does not fit a double-precision number", what, shown(field.text)));
    return std::nullopt;
  }
  if (field.had_inner_blank) {
    report(DiagCode::blank_in_field, field,
           fmt::format("blank in '{}' ignored; the value is {}", shown(field.text), shown(field.text)));
  }
  return value;
}

std::optional<Name> BlockContext::name(const Field& field, std::string_view what) {
  if (field.parameter) {
    const ParamValue& v = *field.parameter;
    if (v.kind != ParamValue::Kind::String || !is_unquoted_name(v.s)) {
      report(DiagCode::parameter_type_error, field,
             fmt::format("parameter '{}' is {}; a name is expected here for {}",
                         field.parameter_name, v.to_display(), what));
      return std::nullopt;
    }
    return Name{name_key(v.s, false), v.s, field.loc};
  }
  if (field.empty()) return std::nullopt;
  if (field.text.size() > 80) {
    report(DiagCode::invalid_name, field,
           fmt::format("name is {} characters long (at most 80)", field.text.size()));
    return std::nullopt;
  }
  if (field.text.rfind("__", 0) == 0) {
    report(DiagCode::invalid_name, field,
           fmt::format("names starting with '__' are reserved ('{}')", shown(field.text)));
    return std::nullopt;
  }
  if (field.quoted) {
    if (field.text.empty()) {
      report(DiagCode::invalid_name, field, "empty quoted name");
      return std::nullopt;
    }
    return Name{name_key(field.text, true), field.text, field.loc};
  }
  if (!is_unquoted_name(field.text)) {
    report(DiagCode::expected_name, field,
           fmt::format("expected a name for {}, got '{}' (quote names that contain other "
                       "characters)", what, shown(field.text)));
    return std::nullopt;
  }
  if (field.had_inner_blank) {
    report(DiagCode::blank_in_field, field,
           fmt::format("blank in the name ignored; the name is '{}' (quote it to keep the "
                       "blank)", field.text));
  }
  return Name{name_key(field.text, false), field.text, field.loc};
}

std::optional<TargetRef> BlockContext::label_ref(const Field& field, std::string_view what) {
  std::optional<TargetRef> ref = target(field, what);
  if (ref && !ref->is_label) {
    report(DiagCode::expected_integer, field,
           fmt::format("expected a {} label, got '{}'", what, shown(field.text)));
    return std::nullopt;
  }
  return ref;
}

std::optional<TargetRef> BlockContext::target(const Field& field, std::string_view what) {
  TargetRef ref;
  ref.loc = field.loc;
  ref.part = position_.part;
  // Fast path for the common plain label (element connectivity, set lists).
  std::int64_t plain = 0;
  if (!field.parameter && !field.quoted && !field.text.empty() && is_digit(field.text[0]) &&
      parse_integer_text(field.text, plain) && plain >= 1 && plain <= 2147483647) {
    ref.is_label = true;
    ref.label = static_cast<std::int32_t>(plain);
    return ref;
  }
  if (field.parameter) {
    const ParamValue& v = *field.parameter;
    if (v.kind == ParamValue::Kind::String) {
      std::optional<Name> n = name(field, what);
      if (!n) return std::nullopt;
      ref.set_key = n->key;
      ref.set_display = n->display;
      return ref;
    }
    std::optional<std::int64_t> label = integer(field, what);
    if (!label) return std::nullopt;
    if (*label < 1 || *label > 2147483647) {
      report(DiagCode::value_out_of_range, field,
             fmt::format("{} label {} is out of range (1-2147483647)", what, *label));
      return std::nullopt;
    }
    ref.is_label = true;
    ref.label = static_cast<std::int32_t>(*label);
    return ref;
  }
  if (field.empty()) return std::nullopt;
  // Split at the last period outside quotes (input-syntax.md §7.3). Quoted parts were unquoted by
  // the lexer, so a quoted field with a period is a plain quoted name unless it is "inst".label.
  std::string_view text = field.text;
  std::string_view item = text;
  if (!field.quoted || text.find('.') != std::string_view::npos) {
    std::size_t dot = text.rfind('.');
    // A real number such as "3." is not a qualified label.
    double dummy = 0;
    bool numeric = !field.quoted && parse_real_text(text, dummy, nullptr);
    if (dot != std::string_view::npos && !numeric && !(field.quoted && dot == 0)) {
      std::string_view instance = text.substr(0, dot);
      item = text.substr(dot + 1);
      if (field.quoted) {
        // "bolt 1".477 arrives as `bolt 1.477`: the instance part was quoted.
        ref.instance_key = name_key(std::string(instance), true);
      } else {
        ref.instance_key = name_key(std::string(instance), false);
      }
      ref.instance_display = std::string(instance);
      if (instance.empty() || item.empty()) {
        report(DiagCode::expected_name, field,
               fmt::format("expected a {} label or set name, got '{}'", what, shown(field.text)));
        return std::nullopt;
      }
    }
  }
  std::int64_t label = 0;
  if (!item.empty() && (std::isdigit(static_cast<unsigned char>(item[0])) || item[0] == '-' ||
                        item[0] == '+')) {
    if (!parse_integer_text(item, label)) {
      double real_value = 0;
      if (parse_real_text(item, real_value, nullptr) && real_value == std::floor(real_value) &&
          std::fabs(real_value) < 3e9) {
        report(DiagCode::real_as_integer, field,
               fmt::format("real value '{}' used where an integer is expected", item));
        label = static_cast<std::int64_t>(real_value);
      } else {
        report(DiagCode::expected_name, field,
               fmt::format("expected a {} label or set name, got '{}'", what, shown(field.text)));
        return std::nullopt;
      }
    }
    if (label < 1 || label > 2147483647) {
      report(DiagCode::value_out_of_range, field,
             fmt::format("{} label {} is out of range (1-2147483647)", what, label));
      return std::nullopt;
    }
    ref.is_label = true;
    ref.label = static_cast<std::int32_t>(label);
    return ref;
  }
  if (!ref.instance_key.empty() || !field.quoted) {
    if (!is_unquoted_name(item) && !field.quoted) {
      report(DiagCode::expected_name, field,
             fmt::format("expected a {} label or set name, got '{}'", what, shown(field.text)));
      return std::nullopt;
    }
  }
  if (item.size() > 80) {
    report(DiagCode::invalid_name, field,
           fmt::format("name is {} characters long (at most 80)", item.size()));
    return std::nullopt;
  }
  ref.set_key = name_key(std::string(item), field.quoted && ref.instance_key.empty());
  ref.set_display = std::string(item);
  return ref;
}

std::optional<std::string> BlockContext::word(const Field& field,
                                              std::span<const std::string_view> allowed,
                                              std::string_view what) {
  std::string text;
  if (field.parameter) {
    if (field.parameter->kind != ParamValue::Kind::String) {
      report(DiagCode::parameter_type_error, field,
             fmt::format("parameter '{}' is a number; a word is expected here for {}",
                         field.parameter_name, what));
      return std::nullopt;
    }
    text = field.parameter->s;
  } else {
    if (field.empty()) return std::nullopt;
    text = field.text;
  }
  std::string folded = fold_name(text);
  std::string prefix_match;
  int prefix_count = 0;
  std::string candidates;
  for (std::string_view value : allowed) {
    std::string folded_value = fold_name(value);
    if (folded_value == folded) return std::string(value);
    if (!folded.empty() && folded_value.rfind(folded, 0) == 0) {
      ++prefix_count;
      prefix_match = std::string(value);
      candidates += candidates.empty() ? "" : ", ";
      candidates += value;
    }
  }
  if (prefix_count == 1) {
    report(DiagCode::abbreviation_expanded, field,
           fmt::format("'{}' taken as '{}'", text, prefix_match));
    return prefix_match;
  }
  if (prefix_count > 1) {
    report(DiagCode::ambiguous_abbreviation, field,
           fmt::format("'{}' is ambiguous for {}: {}", text, what, candidates));
    return std::nullopt;
  }
  std::string expected;
  for (std::size_t i = 0; i < allowed.size(); ++i) {
    if (i) expected += i + 1 == allowed.size() ? " or " : ", ";
    expected += allowed[i];
  }
  Diagnostic& d = report(DiagCode::invalid_value, field,
                         fmt::format("invalid value '{}' for {} (expected {})", text, what,
                                     expected));
  if (auto guess = closest_match(text, allowed)) {
    d.notes.push_back({field.loc, fmt::format("did you mean '{}'?", *guess)});
  }
  return std::nullopt;
}

void BlockContext::missing(SourceLoc where, std::string_view what) {
  report(DiagCode::missing_field, where,
         fmt::format("missing value for '{}' of {}", what, keyword_display()));
}

bool BlockContext::check_field_count(const DataLine& line, const std::vector<Field>& fields,
                                     std::size_t max_fields, std::string_view layout) {
  (void)line;
  if (fields.size() <= max_fields) return true;
  report(DiagCode::too_many_fields, fields[max_fields],
         fmt::format("too many fields: {} data lines take at most {} ({})", keyword_display(),
                     max_fields, layout));
  return false;
}

SourceLoc BlockContext::end_of_line(const DataLine& line) {
  return line.loc.shifted(static_cast<std::uint32_t>(line.text.size()));
}

std::optional<double> BlockContext::real_param(std::string_view param_name) {
  const Field* f = params_.value(param_name);
  return f ? real(*f, param_name) : std::nullopt;
}

std::optional<std::int64_t> BlockContext::integer_param(std::string_view param_name) {
  const Field* f = params_.value(param_name);
  return f ? integer(*f, param_name) : std::nullopt;
}

std::optional<Name> BlockContext::name_param(std::string_view param_name) {
  const Field* f = params_.value(param_name);
  return f ? name(*f, param_name) : std::nullopt;
}


}  // namespace clinch
