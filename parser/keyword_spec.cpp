#include "parser/keyword_spec.hpp"

namespace clinch {

const ParamSet::Entry* ParamSet::find(std::string_view canonical_name) const {
  for (const Entry& e : entries_) {
    if (e.spec && e.spec->name == canonical_name) return &e;
  }
  return nullptr;
}

const Field* ParamSet::value(std::string_view canonical_name) const {
  const Entry* e = find(canonical_name);
  return (e && e->param->has_value) ? &e->param->value : nullptr;
}

std::string_view ParamSet::enum_value(std::string_view canonical_name) const {
  const Entry* e = find(canonical_name);
  return e ? std::string_view(e->enum_value) : std::string_view();
}

SourceLoc ParamSet::loc(std::string_view canonical_name, bool at_value) const {
  const Entry* e = find(canonical_name);
  if (!e) return {};
  return (at_value && e->param->has_value) ? e->param->value.loc : e->param->loc;
}

bool ParamSet::flag(std::string_view canonical_name, bool fallback) const {
  const Entry* e = find(canonical_name);
  if (!e) return fallback;
  if (!e->param->has_value) return true;
  return e->enum_value == "YES";
}

}  // namespace clinch
