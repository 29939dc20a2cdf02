#include "src/assembly/dependent_dofs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "src/model/model.hpp"

namespace clinch {
namespace {

Vector3 position(const Model& model, std::int32_t node) {
  const Vec3& x = model.nodes[static_cast<std::size_t>(node)].x;
  return {x[0], x[1], x[2]};
}

std::string describe_dof(const Model& model, std::int32_t node, int dof) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return fmt::format("DOF {} of node {}", dof, qualified_label(model, n.instance, n.label));
}

class Builder {
 public:
  Builder(const Model& model, const DofMap& dofs, DependentDofs& out)
      : model_(model), map_(dofs), out_(out) {
    out_.of_equation.assign(static_cast<std::size_t>(dofs.equations()), -1);
  }

  bool collect(std::string* error) {
    const ConstraintModel& c = model_.constraints;
    for (const NodeFollower& f : c.followers) {
      for (int dof = 1; dof <= 6; ++dof) {
        if (!(f.dofs & (1u << (dof - 1)))) continue;
        const int eq = map_.equation(f.node, dof);
        if (eq < 0) continue;
        DependentDof d = make(eq, f.node, dof, f.source);
        d.reference = f.reference;
        if (dof <= 3) {
          d.map = DependentDof::Map::RigidTranslation;
          const std::int32_t source = f.translation_source();
          if (f.rigid_arm) d.arm = position(model_, f.node) - position(model_, source);
          add_term(map_.equation(source, dof), 0.0);
          if (d.arm != Vector3::Zero()) {
            for (int i = 0; i < 3; ++i) {
              add_term(i == d.axis ? -1 : map_.equation(f.reference, 4 + i), 0.0);
            }
          }
        } else {
          d.map = DependentDof::Map::Rotation;
          add_term(map_.equation(f.reference, dof), 0.0);
        }
        if (!add(d, error)) return false;
      }
    }
    for (const LinearConstraint& equation : c.equations) {
      const LinearTerm& first = equation.terms.front();
      const int eq = map_.equation(first.node, first.dof);
      if (eq < 0) continue;
      DependentDof d = make(eq, first.node, first.dof, equation.source);
      d.map = DependentDof::Map::Linear;
      for (std::size_t t = 1; t < equation.terms.size(); ++t) {
        const LinearTerm& term = equation.terms[t];
        add_term(map_.equation(term.node, term.dof), -term.coefficient / first.coefficient);
      }
      if (!add(d, error)) return false;
    }
    for (const DistanceLink& link : c.links) {
      const Vector3 arm = position(model_, link.node) - position(model_, link.other);
      // The translation along which the link lies most: its derivative stays away from zero.
      int axis = 0;
      for (int k = 1; k < 3; ++k) {
        if (std::abs(arm[k]) > std::abs(arm[axis])) axis = k;
      }
      const int eq = map_.equation(link.node, axis + 1);
      if (eq < 0) continue;
      DependentDof d = make(eq, link.node, axis + 1, link.source);
      d.map = DependentDof::Map::LinkTranslation;
      d.reference = link.other;
      d.arm = arm;
      add_term(map_.equation(link.other, axis + 1), 0.0);
      for (std::int32_t node : {link.node, link.other}) {
        for (int j = 0; j < 3; ++j) add_term(j == axis ? -1 : map_.equation(node, j + 1), 0.0);
      }
      if (!add(d, error)) return false;
    }
    return true;
  }

  // Orders the DOFs so that each comes after the dependent DOFs its terms name (depth first),
  // then substitutes the chains.
  bool order(std::string* error) {
    std::vector<DependentDof> ordered;
    ordered.reserve(out_.dofs.size());
    std::vector<std::uint8_t> mark(out_.dofs.size(), 0);  // 1: on the path, 2: placed
    for (std::size_t start = 0; start < out_.dofs.size(); ++start) {
      if (!visit(start, mark, ordered, error)) return false;
    }
    out_.dofs = std::move(ordered);
    for (std::size_t i = 0; i < out_.dofs.size(); ++i) {
      out_.of_equation[static_cast<std::size_t>(out_.dofs[i].equation)] =
          static_cast<std::int32_t>(i);
    }
    resolve();
    return true;
  }

 private:
  DependentDof make(int eq, std::int32_t node, int dof, std::int32_t source) {
    DependentDof d;
    d.equation = eq;
    d.node = node;
    d.axis = (dof - 1) % 3;
    d.source = source;
    d.first_term = static_cast<std::uint32_t>(out_.term_equation.size());
    return d;
  }

  void add_term(int equation, double coefficient) {
    out_.term_equation.push_back(equation);
    out_.term_coefficient.push_back(coefficient);
  }

  bool add(DependentDof& d, std::string* error) {
    d.term_count = static_cast<std::uint32_t>(out_.term_equation.size()) - d.first_term;
    auto& slot = out_.of_equation[static_cast<std::size_t>(d.equation)];
    if (slot >= 0) {
      // The checks report a DOF tied twice at both sources; this guards the plan.
      *error = fmt::format("{} is eliminated by two constraints",
                           describe_dof(model_, d.node, map_.dof_of(d.equation)));
      return false;
    }
    slot = static_cast<std::int32_t>(out_.dofs.size());
    out_.dofs.push_back(d);
    return true;
  }

  bool visit(std::size_t i, std::vector<std::uint8_t>& mark, std::vector<DependentDof>& ordered,
             std::string* error) {
    if (mark[i] == 2) return true;
    const DependentDof& d = out_.dofs[i];
    if (mark[i] == 1) {
      *error = fmt::format("{} depends on itself through a cycle of constraints",
                           describe_dof(model_, d.node, map_.dof_of(d.equation)));
      return false;
    }
    mark[i] = 1;
    for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
      const int eq = out_.term_equation[t];
      if (eq < 0) continue;
      const std::int32_t m = out_.of_equation[static_cast<std::size_t>(eq)];
      if (m >= 0 && !visit(static_cast<std::size_t>(m), mark, ordered, error)) {
        return false;
      }
    }
    mark[i] = 2;
    ordered.push_back(d);
    return true;
  }

  void resolve() {
    std::vector<std::uint8_t> turns_with_another(map_.nodes(), 0);
    for (DependentDof& d : out_.dofs) {
      d.first_resolved = static_cast<std::uint32_t>(out_.resolved_equation.size());
      for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
        const int eq = out_.term_equation[t];
        if (eq < 0) continue;
        const std::int32_t m = out_.of_equation[static_cast<std::size_t>(eq)];
        if (m < 0) {
          push_resolved(eq, t, -1);
          continue;
        }
        const DependentDof& master = out_.dofs[static_cast<std::size_t>(m)];
        for (std::uint32_t e = master.first_resolved;
             e < master.first_resolved + master.resolved_count; ++e) {
          push_resolved(out_.resolved_equation[e], t, static_cast<std::int32_t>(e));
        }
      }
      d.resolved_count =
          static_cast<std::uint32_t>(out_.resolved_equation.size()) - d.first_resolved;
      if (d.map == DependentDof::Map::Rotation && d.reference >= 0 &&
          !turns_with_another[static_cast<std::size_t>(d.node)]) {
        turns_with_another[static_cast<std::size_t>(d.node)] = 1;
        out_.rotation_followers.emplace_back(d.node, d.reference);
      }
    }
  }

  void push_resolved(int equation, std::uint32_t via_term, std::int32_t via_entry) {
    out_.resolved_equation.push_back(equation);
    out_.resolved_via_term.push_back(via_term);
    out_.resolved_via_entry.push_back(via_entry);
  }

  const Model& model_;
  const DofMap& map_;
  DependentDofs& out_;
};

// The solved numbering: every equation but the dependent ones, in their order.
void number_solved(DependentDofs& out) {
  out.solved_of_equation.assign(out.of_equation.size(), -1);
  for (std::size_t eq = 0; eq < out.of_equation.size(); ++eq) {
    if (out.of_equation[eq] >= 0) continue;
    out.solved_of_equation[eq] = static_cast<int>(out.equation_of_solved.size());
    out.equation_of_solved.push_back(static_cast<int>(eq));
  }
}

}  // namespace

int DependentDofs::solved_node_block(const DofMap& map) const {
  if (dofs.empty()) return map.uniform_node_block();
  if (map.equations() != map.node_equations()) return 1;  // multipliers
  int common = 0;
  for (std::size_t node = 0; node < map.nodes(); ++node) {
    int solved = 0;
    for (int dof = 1; dof <= 6; ++dof) {
      const int eq = map.equation(static_cast<std::int32_t>(node), dof);
      if (eq >= 0 && !is_dependent(eq)) ++solved;
    }
    if (solved == 0) continue;
    if (common != 0 && solved != common) return 1;
    common = solved;
  }
  return common == 0 ? 1 : common;
}

bool build_dependent_dofs(const Model& model, const DofMap& dofs, DependentDofs& out,
                          std::string* error) {
  out = {};
  Builder builder(model, dofs, out);
  if (!builder.collect(error)) return false;
  if (out.dofs.empty()) {
    out.of_equation.clear();
    return true;
  }
  if (!builder.order(error)) return false;
  number_solved(out);
  return true;
}

DependentDofs local_dependents(const DependentDofs& whole, std::span<const int> local_of,
                               const DofMap& local) {
  DependentDofs out;
  if (whole.empty()) return out;
  const auto local_equation = [&](int eq) {
    if (eq < 0) return -1;
    const int mine = local_of[static_cast<std::size_t>(eq)];
    if (mine < 0) throw std::logic_error("local_dependents: a map reads an equation not held");
    return mine;
  };
  out.of_equation.assign(static_cast<std::size_t>(local.equations()), -1);
  // Where each resolved entry of the whole list went: a chain's entries point at its master's.
  std::vector<std::int32_t> entry_of(whole.resolved_equation.size(), -1);
  for (const DependentDof& w : whole.dofs) {
    if (local_of[static_cast<std::size_t>(w.equation)] < 0) continue;
    DependentDof d = w;
    d.equation = local_equation(w.equation);
    d.first_term = static_cast<std::uint32_t>(out.term_equation.size());
    for (std::uint32_t t = w.first_term; t < w.first_term + w.term_count; ++t) {
      out.term_equation.push_back(local_equation(whole.term_equation[t]));
      out.term_coefficient.push_back(whole.term_coefficient[t]);
    }
    d.first_resolved = static_cast<std::uint32_t>(out.resolved_equation.size());
    for (std::uint32_t e = w.first_resolved; e < w.first_resolved + w.resolved_count; ++e) {
      entry_of[e] = static_cast<std::int32_t>(out.resolved_equation.size());
      out.resolved_equation.push_back(local_equation(whole.resolved_equation[e]));
      out.resolved_via_term.push_back(whole.resolved_via_term[e] - w.first_term + d.first_term);
      const std::int32_t via = whole.resolved_via_entry[e];
      out.resolved_via_entry.push_back(via < 0 ? -1 : entry_of[static_cast<std::size_t>(via)]);
    }
    out.of_equation[static_cast<std::size_t>(d.equation)] =
        static_cast<std::int32_t>(out.dofs.size());
    out.dofs.push_back(d);
  }
  for (const auto& [node, reference] : whole.rotation_followers) {
    if (local.active(node) != 0) out.rotation_followers.emplace_back(node, reference);
  }
  if (out.dofs.empty()) {
    out.of_equation.clear();
    return out;
  }
  number_solved(out);
  return out;
}

}  // namespace clinch
