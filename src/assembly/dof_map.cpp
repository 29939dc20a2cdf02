#include "src/assembly/dof_map.hpp"

namespace clinch {

DofMap::DofMap(std::vector<DofMask> active) : active_(std::move(active)) {
  first_.resize(active_.size(), -1);
  for (std::size_t n = 0; n < active_.size(); ++n) number(static_cast<std::int32_t>(n));
}

DofMap::DofMap(std::vector<DofMask> active, const std::vector<std::int32_t>& order)
    : active_(std::move(active)) {
  first_.resize(active_.size(), -1);
  for (const std::int32_t n : order) number(n);
}

void DofMap::add_nodes(const std::vector<std::int32_t>& order) {
  for (const std::int32_t n : order) number(n);
}

void DofMap::number(std::int32_t node) {
  const auto n = static_cast<std::size_t>(node);
  first_[n] = equations();
  for (int dof = 1; dof <= 6; ++dof) {
    if (!(active_[n] & (1u << (dof - 1)))) continue;
    node_of_.push_back(node);
    field_.push_back(dof <= 3 ? EquationField::Translation : EquationField::Rotation);
    ++node_equations_;
  }
}

int DofMap::add_multiplier(bool rotational) {
  field_.push_back(rotational ? EquationField::RotationalMultiplier
                              : EquationField::TranslationalMultiplier);
  node_of_.push_back(-1);
  return static_cast<int>(field_.size()) - 1;
}

int DofMap::uniform_node_block() const {
  if (equations() != node_equations_ || node_equations_ == 0) return 1;
  DofMask common = 0;
  for (const DofMask mask : active_) {
    if (mask == 0) continue;
    if (common != 0 && mask != common) return 1;
    common = mask;
  }
  return std::popcount(static_cast<unsigned>(common));
}

int DofMap::dof_of(int equation) const {
  const std::int32_t node = node_of(equation);
  if (node < 0) return 0;
  for (int dof = 1; dof <= 6; ++dof) {
    if (this->equation(node, dof) == equation) return dof;
  }
  return 0;
}

}  // namespace clinch
