#include "src/assembly/increment_conditions.hpp"

namespace clinch {

const ConnectorConditions IncrementConditions::kNone{};

IncrementConditions::IncrementConditions(const AnalysisPlan& plan)
    : prescribed_(static_cast<std::size_t>(plan.dofs.equations()), 0),
      target_(Eigen::VectorXd::Zero(plan.dofs.equations())),
      external_(target_),
      slot_of_connector_(plan.connector_total, -1) {}

void IncrementConditions::clear() {
  for (int eq : prescribed_list_) prescribed_[static_cast<std::size_t>(eq)] = 0;
  prescribed_list_.clear();
  external_.setZero();
  for (ConnectorConditions& s : slots_) s = ConnectorConditions{};
}

void IncrementConditions::prescribe(int equation, double value) {
  if (!prescribed_[static_cast<std::size_t>(equation)]) {
    prescribed_[static_cast<std::size_t>(equation)] = 1;
    prescribed_list_.push_back(equation);
  }
  target_[equation] = value;
}

void IncrementConditions::add_load(int equation, double value) { external_[equation] += value; }

ConnectorConditions& IncrementConditions::connector_slot(int connector) {
  std::int32_t& s = slot_of_connector_[static_cast<std::size_t>(connector)];
  if (s < 0) {
    s = static_cast<std::int32_t>(slots_.size());
    slots_.emplace_back();
  }
  return slots_[static_cast<std::size_t>(s)];
}

void IncrementConditions::prescribe_motion(int connector, int component, double value) {
  ConnectorConditions& c = connector_slot(connector);
  c.motion |= component_bit(component);
  c.motion_target[component - 1] = value;
}

void IncrementConditions::add_connector_load(int connector, int component, double value) {
  connector_slot(connector).load[component - 1] += value;
}

}  // namespace clinch
