#include "parser/keyword_registry.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "parser/keywords/keyword_families.hpp"

namespace clinch {

const KeywordRegistry& KeywordRegistry::instance() {
  static const KeywordRegistry registry = [] {
    KeywordRegistry r;
    for (auto* family : {&general_keyword_specs, &geometry_keyword_specs, &section_keyword_specs,
                         &structure_keyword_specs, &rigid_body_keyword_specs,
                         &coupling_keyword_specs, &mpc_equation_keyword_specs,
                         &behavior_keyword_specs, &potential_friction_keyword_specs,
                         &history_keyword_specs}) {
      for (KeywordSpec& spec : family()) r.add(std::move(spec));
    }
    return r;
  }();
  return registry;
}

void KeywordRegistry::add(KeywordSpec spec) {
  auto owned = std::make_unique<KeywordSpec>(std::move(spec));
  if (!by_name_.emplace(fold_name(owned->name), owned.get()).second) {
    throw std::logic_error(fmt::format("keyword *{} registered twice", owned->name));
  }
  display_names_.push_back(fmt::format("*{}", owned->name));
  specs_.push_back(std::move(owned));
}

const KeywordSpec* KeywordRegistry::find(std::string_view folded_name) const {
  auto it = by_name_.find(std::string(folded_name));
  return it == by_name_.end() ? nullptr : it->second;
}

std::vector<const KeywordSpec*> KeywordRegistry::specs() const {
  std::vector<const KeywordSpec*> all;
  all.reserve(specs_.size());
  for (const auto& spec : specs_) all.push_back(spec.get());
  return all;
}

}  // namespace clinch
