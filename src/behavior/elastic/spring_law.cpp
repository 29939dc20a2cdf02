#include "src/behavior/elastic/spring_law.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace clinch {

SpringLaw::SpringLaw(const SpringProperty& spring) : stiffness_(spring.stiffness) {
  if (!spring.valid) throw std::invalid_argument("spring law built from an invalid *SPRING");
  if (!spring.nonlinear) return;
  std::vector<double> delta, force;
  delta.reserve(spring.table.size());
  force.reserve(spring.table.size());
  for (const SpringProperty::Point& p : spring.table) {
    delta.push_back(p.delta);
    force.push_back(p.force);
  }
  // §7: outside the table F stays at the end value with zero tangent, whatever the
  // *CONNECTOR BEHAVIOR rules say for connectors.
  table_.emplace(std::move(delta), std::move(force), Extrapolation::Constant);
}

}  // namespace clinch
