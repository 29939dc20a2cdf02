#include "parser/reader/parameter_substitution.hpp"

#include <fmt/format.h>

#include <string>

namespace clinch {

void ParameterSubstitution::substitute(Field& field) {
  if (field.quoted) return;
  const std::string& t = field.text;
  std::size_t lt = t.find('<');
  if (lt == std::string::npos) return;
  if (t.size() >= 3 && t.front() == '<' && t.back() == '>' && t.find('<', 1) == std::string::npos &&
      t.find('>') == t.size() - 1) {
    std::string name = t.substr(1, t.size() - 2);
    const ParameterTable::Entry* entry = parameters_.use(name);
    if (!entry) {
      parameters_.report_undefined(sink_, name, field.loc);
      field.text.clear();
      field.parameter = nullptr;
      failed_ = true;
      return;
    }
    if (!entry->ok) {
      field.text.clear();
      failed_ = true;
      return;
    }
    field.parameter = &entry->value;
    field.parameter_loc = entry->loc;
    field.parameter_name = name;
    field.text =
        entry->value.kind == ParamValue::Kind::String ? entry->value.s : entry->value.to_display();
    return;
  }
  if (t.find('>') != std::string::npos) {
    sink_.report(DiagCode::partial_parameter_reference, field.loc,
                 fmt::format("'{}' mixes a parameter reference with other text; define a new "
                             "parameter",
                             t));
    field.text.clear();
    failed_ = true;
  }
}

void ParameterSubstitution::mark_references_used(std::string_view text) {
  for (std::size_t lt = text.find('<'); lt != std::string_view::npos; lt = text.find('<', lt + 1)) {
    const std::size_t gt = text.find('>', lt + 1);
    if (gt == std::string_view::npos) return;
    parameters_.use(text.substr(lt + 1, gt - lt - 1));
  }
}

}  // namespace clinch
