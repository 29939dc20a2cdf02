// The conditions of the current increment, as the step conditions set them (keywords.md §9–§12):
// prescribed nodal values and their targets, nodal loads, prescribed connector motions and
// connector loads. Plain data that the elements and the assembly read.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "src/assembly/analysis_plan.hpp"

namespace clinch {

// *CONNECTOR MOTION and *CONNECTOR LOAD on one connector.
struct ConnectorConditions {
  ComponentMask motion = 0;
  Vector6 motion_target = Vector6::Zero();
  Vector6 load = Vector6::Zero();
};

class IncrementConditions {
 public:
  explicit IncrementConditions(const AnalysisPlan& plan);

  void clear();
  void prescribe(int equation, double value);  // *BOUNDARY target of this increment
  void add_load(int equation, double value);   // *CLOAD (and released reactions)
  void prescribe_motion(int connector, int component, double value);
  void add_connector_load(int connector, int component, double value);

  bool is_prescribed(int equation) const { return prescribed_[static_cast<std::size_t>(equation)]; }
  const std::vector<int>& prescribed() const { return prescribed_list_; }
  double target(int equation) const { return target_[equation]; }
  const Eigen::VectorXd& external() const { return external_; }
  bool has_connector_loads() const {
    return std::any_of(slots_.begin(), slots_.end(),
                       [](const ConnectorConditions& c) { return c.load != Vector6::Zero(); });
  }
  // The motion and load conditions of connector `c` (global index; none for most connectors).
  const ConnectorConditions& connector(std::size_t c) const {
    const std::int32_t s = slot_of_connector_[c];
    return s < 0 ? kNone : slots_[static_cast<std::size_t>(s)];
  }

 private:
  ConnectorConditions& connector_slot(int connector);
  static const ConnectorConditions kNone;
  std::vector<std::uint8_t> prescribed_;
  std::vector<int> prescribed_list_;
  Eigen::VectorXd target_, external_;
  std::vector<std::int32_t> slot_of_connector_;
  std::vector<ConnectorConditions> slots_;
};

}  // namespace clinch
