#include "src/assembly/failure_description.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace clinch {
namespace {

constexpr const char* kDofNames[] = {"", "u1", "u2", "u3", "ur1", "ur2", "ur3"};

// The DOF or the multiplier behind an equation (connection-types.md §1.1, §3.8); empty when the
// equation is not one of the plan's.
std::string name_equation(const Model& model, const AnalysisPlan& plan, int equation,
                          const LinesOfEveryRank& every_rank) {
  if (equation < 0 || equation >= plan.dofs.equations()) return {};
  const std::int32_t node = plan.dofs.node_of(equation);
  if (node >= 0) {
    const Node& n = model.nodes[static_cast<std::size_t>(node)];
    return fmt::format("DOF {} of node {}", kDofNames[plan.dofs.dof_of(equation)],
                       qualified_label(model, n.instance, n.label));
  }
  const auto multiplier_of = [&]() -> std::string {
    for (const ConnectorRecord& r : plan.connectors) {
      for (int j = 0; j < r.multiplier_count; ++j) {
        if (r.local.equation[static_cast<std::size_t>(r.column_count + j)] != equation) continue;
        const Element& e = model.elements[static_cast<std::size_t>(r.element)];
        return fmt::format("connector {} component {}", qualified_label(model, e.instance, e.label),
                           r.multiplier_components[static_cast<std::size_t>(j)]);
      }
    }
    return {};
  };
  if (!plan.shared || !every_rank) return multiplier_of();
  // The rank whose share holds the multiplier's connector names it.
  for (std::string& name : every_rank({multiplier_of()})) {
    if (!name.empty()) return std::move(name);
  }
  return {};
}

// Whether connector `r` gives its local column `column` stiffness in the initial pose: a nonzero
// entry of B there, in a component that a law acts on or a multiplier holds.
bool connector_holds(const AnalysisPlan& plan, const ConnectorRecord& r, int column) {
  ComponentMask held = r.constrained | r.rigid;
  for (const LawSlot& slot : r.laws) held |= slot.law->components();
  for (int j = 0; j < r.multiplier_count; ++j) {
    held |= component_bit(r.multiplier_components[static_cast<std::size_t>(j)]);
  }
  const ConnectorKinematics& kinematics = plan.kinematics[r.kinematics];
  KinematicsResult initial;
  kinematics.evaluate(NodePose{}, NodePose{}, true, kinematics.initial_position(), false, initial);
  for (int i = 0; i < 6; ++i) {
    if (!has_component(held, i + 1)) continue;
    const double scale = initial.b.row(i).cwiseAbs().maxCoeff();
    if (std::abs(initial.b(i, column)) > 1e-12 * scale) return true;
  }
  return false;
}

// Whether spring `s` gives its local column `column` stiffness: its direction has a component
// along that DOF (keywords.md §7).
bool spring_holds(const SpringRecord& s, int column) {
  const Vector3 direction = s.type == ElementType::SpringA
                                ? Vector3(s.d0)
                                : s.direction[static_cast<std::size_t>(column / 3)];
  const double scale = direction.cwiseAbs().maxCoeff();
  return std::abs(direction[column % 3]) > 1e-12 * scale;
}

// The elements that give the DOF of `equation` stiffness in their initial pose, named: "connector
// element 1", "connector elements 1 and 2", "SPRINGA element 4 and 2 more elements".
struct Holding {
  std::size_t count = 0;
  std::string names;
};
Holding elements_holding(const Model& model, const AnalysisPlan& plan, int equation,
                         const LinesOfEveryRank& every_rank) {
  std::vector<std::pair<std::string, std::string>> found;  // kind, label
  const auto add = [&](std::string kind, std::int32_t element) {
    const Element& e = model.elements[static_cast<std::size_t>(element)];
    found.emplace_back(std::move(kind), qualified_label(model, e.instance, e.label));
  };
  for (const ConnectorRecord& r : plan.connectors) {
    for (int k = 0; k < r.column_count; ++k) {
      if (r.local.equation[static_cast<std::size_t>(k)] == equation &&
          connector_holds(plan, r, r.columns[static_cast<std::size_t>(k)])) {
        add("connector", r.element);
      }
    }
  }
  if (plan.shared && every_rank) {
    // The connectors of every rank's share, in element order.
    std::vector<std::string> labels;
    for (auto& [kind, label] : found) labels.push_back(std::move(label));
    found.clear();
    for (std::string& label : every_rank(std::move(labels))) {
      found.emplace_back("connector", std::move(label));
    }
  }
  const auto add_spring = [&](const SpringRecord& s) {
    for (int k = 0; k < s.column_count; ++k) {
      if (s.local.equation[static_cast<std::size_t>(k)] == equation &&
          spring_holds(s, s.columns[static_cast<std::size_t>(k)])) {
        add(element_type_name(model.elements[static_cast<std::size_t>(s.element)].type), s.element);
      }
    }
  };
  if (plan.shared) {
    // A rank's plan holds only its share of the springs: every rank names them all, from the
    // model, so that the ranks agree on the message.
    for (std::size_t e = 0; e < plan.spring_of_element.size(); ++e) {
      if (plan.spring_of_element[e] >= 0) {
        add_spring(spring_record(model, plan.dofs, static_cast<std::int32_t>(e)));
      }
    }
  } else {
    for (const SpringRecord& s : plan.springs) add_spring(s);
  }
  Holding holding{found.size(), {}};
  if (found.empty()) return holding;
  const auto& [kind, label] = found[0];
  if (found.size() == 1) {
    holding.names = fmt::format("{} element {}", kind, label);
  } else if (found.size() > 2) {
    holding.names =
        fmt::format("{} element {} and {} more elements", kind, label, found.size() - 1);
  } else if (found[1].first == kind) {
    holding.names = fmt::format("{} elements {} and {}", kind, label, found[1].second);
  } else {
    holding.names = fmt::format("{} element {} and {} element {}", kind, label, found[1].first,
                                found[1].second);
  }
  return holding;
}

// Whether some *BOUNDARY of the deck (model data or any step) names DOF `dof` of `node`.
bool has_boundary(const Model& model, std::int32_t node, int dof) {
  const auto names = [&](const std::vector<BoundaryCondition>& conditions) {
    return std::any_of(conditions.begin(), conditions.end(), [&](const BoundaryCondition& bc) {
      return ((bc.dofs >> (dof - 1)) & 1u) != 0 &&
             std::find(bc.resolved.begin(), bc.resolved.end(), node) != bc.resolved.end();
    });
  };
  if (names(model.history.model_boundaries)) return true;
  return std::any_of(model.history.steps.begin(), model.history.steps.end(),
                     [&](const Step& step) { return names(step.boundaries); });
}

}  // namespace

std::string describe_failure(const Model& model, const AnalysisPlan& plan,
                             const NewtonReport& report, const LinesOfEveryRank& every_rank) {
  const std::string name = name_equation(model, plan, report.failed_equation, every_rank);
  if (report.outcome == NewtonOutcome::NonFinite) {
    return name.empty() ? report.message : fmt::format("{} at {}", report.message, name);
  }
  if (name.empty()) return "the system is singular";
  const std::int32_t node = plan.dofs.node_of(report.failed_equation);
  if (node < 0) return "overconstrained " + name;
  if (const Holding holding = elements_holding(model, plan, report.failed_equation, every_rank);
      holding.count > 0) {
    return fmt::format(
        "singular system: {} has no stiffness, although {} gave it stiffness at "
        "the start: {} stiffness vanished in this state, or the DOF moves with "
        "others in a mechanism",
        name, holding.names, holding.count == 1 ? "its" : "their");
  }
  if (has_boundary(model, node, plan.dofs.dof_of(report.failed_equation))) {
    return fmt::format(
        "singular system: {} has no stiffness: no element restrains it, and its "
        "*BOUNDARY does not hold it in this step",
        name);
  }
  return fmt::format(
      "singular system: {} has no stiffness (add a *BOUNDARY or an element that "
      "restrains it)",
      name);
}

}  // namespace clinch
