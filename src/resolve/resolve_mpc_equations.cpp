// *MPC and *EQUATION into the flat lists the analysis eliminates (src/model/constraint_model.hpp;
// docs/constraints.md "MPCs", "Equations"). Runs before the history is resolved, because
// active_dofs() reads the followers, equations and links.
#include <fmt/format.h>

#include <algorithm>
#include <string_view>
#include <utility>

#include "base/diagnostic.hpp"
#include "src/model/model.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

constexpr DofMask kAll3D = 0x3F, kTranslations3D = 0x07;
constexpr DofMask kAll2D = 0x23, kTranslations2D = 0x03;  // 2-D: DOFs 1, 2 and 6

std::string node_display(const Model& model, std::int32_t n) {
  const Node& node = model.nodes[static_cast<std::size_t>(n)];
  return qualified_label(model, node.instance, node.label);
}

const char* mpc_keyword(MpcDefinition::Type type) {
  switch (type) {
    case MpcDefinition::Type::Beam:
      return "*MPC BEAM";
    case MpcDefinition::Type::Link:
      return "*MPC LINK";
    case MpcDefinition::Type::Pin:
      return "*MPC PIN";
    case MpcDefinition::Type::Tie:
      return "*MPC TIE";
  }
  return "*MPC";
}

class MpcEquationResolver {
 public:
  MpcEquationResolver(Model& model, DiagnosticSink& sink)
      : model_(model), constraints_(model.constraints), sink_(sink) {
    for (const Step& step : model.history.steps) nlgeom_ = nlgeom_ || step.nlgeom;
  }

  void run() {
    for (const MpcDefinition& mpc : constraints_.mpcs) resolve_mpc(mpc);
    for (const EquationDefinition& equation : constraints_.equation_definitions) {
      resolve_equation(equation);
    }
  }

 private:
  std::int32_t add_source(std::string keyword, SourceLoc loc) {
    constraints_.sources.push_back({std::move(keyword), loc});
    return static_cast<std::int32_t>(constraints_.sources.size()) - 1;
  }

  // The nodes a reference names, in the order the manual matches sets in: ascending labels
  // (instance by instance). Empty after a report.
  std::vector<std::int32_t> nodes_of(const TargetRef& ref) {
    std::vector<std::int32_t> nodes;
    if (!resolve_nodes(model_, ref, nodes, sink_)) return {};
    if (nodes.empty()) {
      sink_.report(DiagCode::empty_set, ref.loc, fmt::format("{} is empty", describe(ref, false)));
      return {};
    }
    std::sort(nodes.begin(), nodes.end(), [&](std::int32_t a, std::int32_t b) {
      const Node& na = model_.nodes[static_cast<std::size_t>(a)];
      const Node& nb = model_.nodes[static_cast<std::size_t>(b)];
      return std::pair(na.instance, na.label) < std::pair(nb.instance, nb.label);
    });
    return nodes;
  }

  // Sets matched entry by entry are matched in ascending label order; an UNSORTED set's written
  // order is not kept (Set::unsorted_loc), so matching it with another set is refused.
  bool order_kept(const TargetRef& ref) {
    if (ref.is_label) return true;
    std::int32_t part = ref.part;
    if (!ref.instance_key.empty()) {
      auto it = model_.instance_by_key.find(ref.instance_key);
      if (it == model_.instance_by_key.end()) return true;  // reported when resolved
      part = model_.instances[static_cast<std::size_t>(it->second)].part;
    }
    const auto& sets = model_.parts[static_cast<std::size_t>(part)].node_sets;
    auto it = sets.find(ref.set_key);
    if (it == sets.end() || !it->second.unsorted_loc.valid()) return true;
    sink_
        .report(DiagCode::unsupported_option, ref.loc,
                fmt::format("{} is UNSORTED, and clinch keeps node sets in ascending label order "
                            "only: matched entry by entry with another set here, its written "
                            "order would be lost; define it so that its labels ascend together "
                            "with the other set's",
                            describe(ref, false)))
        .notes.push_back({it->second.unsorted_loc, "UNSORTED is given here"});
    return false;
  }

  // ---------------------------------------------------------------------------------------
  // *MPC

  void resolve_mpc(const MpcDefinition& mpc) {
    const std::vector<std::int32_t> a = nodes_of(mpc.first);
    const std::vector<std::int32_t> b = nodes_of(mpc.second);
    if (a.empty() || b.empty()) return;
    // The manual's "General multi-point constraints": node sets are matched entry by entry; a
    // single node second is the one every node of the first set depends on.
    if (b.size() != 1 && b.size() != a.size()) {
      sink_.report(
          DiagCode::invalid_value, mpc.second.loc,
          fmt::format("{} holds {} nodes and {} {}: an MPC matches the entries of its "
                      "node sets one by one, so they must have the same size (or the "
                      "second entry must be a single node)",
                      describe(mpc.second, false), b.size(), describe(mpc.first, false), a.size()));
      return;
    }
    if (a.size() > 1 && b.size() > 1 && !(order_kept(mpc.first) & order_kept(mpc.second))) return;
    const bool two_d = model_.dimension == 2;
    const double tolerance = geometry_tolerance(model_.nodes);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::int32_t node = a[i];
      const std::int32_t other = b.size() == 1 ? b[0] : b[i];
      if (node == other) {
        sink_.report(DiagCode::degenerate_mpc, mpc.loc,
                     fmt::format("{} joins node {} to itself", mpc_keyword(mpc.type),
                                 node_display(model_, node)));
        return;
      }
      if (mpc.type == MpcDefinition::Type::Link && distance(node, other) <= tolerance) {
        sink_.report(DiagCode::degenerate_mpc, mpc.loc,
                     fmt::format("the nodes {} and {} of this MPC LINK coincide: a link of zero "
                                 "length has no direction to keep (use MPC PIN to join them)",
                                 node_display(model_, node), node_display(model_, other)));
        return;
      }
    }
    const std::int32_t source = add_source(mpc_keyword(mpc.type), mpc.loc);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::int32_t node = a[i];
      const std::int32_t other = b.size() == 1 ? b[0] : b[i];
      switch (mpc.type) {
        // BEAM: a rigid beam, the first node's displacement and rotation follow the second's.
        case MpcDefinition::Type::Beam:
          constraints_.followers.push_back({node, other, two_d ? kAll2D : kAll3D, true, source});
          break;
        // TIE: every DOF of the first node equal to the second's.
        case MpcDefinition::Type::Tie:
          constraints_.followers.push_back({node, other, two_d ? kAll2D : kAll3D, false, source});
          break;
        // PIN: equal displacements, rotations left independent.
        case MpcDefinition::Type::Pin:
          constraints_.followers.push_back(
              {node, other, two_d ? kTranslations2D : kTranslations3D, false, source});
          break;
        // LINK: the distance stays constant; the first node's displacement is modified.
        case MpcDefinition::Type::Link:
          constraints_.links.push_back({node, other, source});
          break;
      }
    }
  }

  double distance(std::int32_t a, std::int32_t b) const {
    const Vec3& xa = model_.nodes[static_cast<std::size_t>(a)].x;
    const Vec3& xb = model_.nodes[static_cast<std::size_t>(b)].x;
    return length_of({xa[0] - xb[0], xa[1] - xb[1], xa[2] - xb[2]});
  }

  // ---------------------------------------------------------------------------------------
  // *EQUATION

  void resolve_equation(const EquationDefinition& definition) {
    // Each term's nodes; terms with node sets expand the equation set by set, entry by entry
    // (the manual's "Linear constraint equations"); a single node repeats in every copy.
    std::vector<std::vector<std::int32_t>> nodes;
    std::size_t copies = 1;
    const TargetRef* widest = nullptr;
    for (const EquationTermDefinition& term : definition.terms) {
      nodes.push_back(nodes_of(term.target));
      if (nodes.back().empty()) return;
      if (nodes.back().size() > 1 && copies == 1) {
        copies = nodes.back().size();
        widest = &term.target;
      }
    }
    bool ok = true;
    bool rotation_refused = false;
    for (std::size_t t = 0; t < definition.terms.size(); ++t) {
      const EquationTermDefinition& term = definition.terms[t];
      if (nodes[t].size() != 1 && nodes[t].size() != copies) {
        sink_.report(DiagCode::invalid_value, term.target.loc,
                     fmt::format("{} holds {} nodes and {} {}: an equation matches the entries "
                                 "of its node sets one by one, so they must have the same size "
                                 "(or name a single node)",
                                 describe(term.target, false), nodes[t].size(),
                                 describe(*widest, false), copies));
        ok = false;
      }
      ok = check_dof(term, rotation_refused) && ok;
    }
    if (!ok) return;
    std::size_t matched_sets = 0;
    for (const auto& n : nodes) matched_sets += n.size() > 1 ? 1 : 0;
    if (matched_sets > 1) {
      for (std::size_t t = 0; t < definition.terms.size(); ++t) {
        if (nodes[t].size() > 1) ok = order_kept(definition.terms[t].target) && ok;
      }
      if (!ok) return;
    }
    if (copies > 1 && nodes[0].size() == 1) {
      sink_.report(DiagCode::constraint_conflict, definition.terms[0].target.loc,
                   fmt::format("the first term names one node, and {} repeats the equation for "
                               "each of its {} nodes: DOF {} of node {} would be eliminated {} "
                               "times; make the first term a node set of the same size",
                               describe(*widest, false), copies, definition.terms[0].dof,
                               node_display(model_, nodes[0][0]), copies));
      return;
    }
    std::vector<LinearConstraint> expanded(copies);
    for (std::size_t k = 0; k < copies; ++k) {
      for (std::size_t t = 0; t < definition.terms.size(); ++t) {
        const EquationTermDefinition& term = definition.terms[t];
        const std::int32_t node = nodes[t].size() == 1 ? nodes[t][0] : nodes[t][k];
        for (const LinearTerm& earlier : expanded[k].terms) {
          if (earlier.node != node || earlier.dof != term.dof) continue;
          sink_.report(DiagCode::invalid_value, term.dof_loc,
                       fmt::format("DOF {} of node {} appears twice in this equation; write it "
                                   "once with the sum of its coefficients",
                                   term.dof, node_display(model_, node)));
          return;
        }
        expanded[k].terms.push_back({node, term.dof, term.coefficient});
      }
    }
    const std::int32_t source = add_source("*EQUATION", definition.terms[0].target.loc);
    for (LinearConstraint& equation : expanded) {
      equation.exact_under_nlgeom = true;
      equation.source = source;
      constraints_.equations.push_back(std::move(equation));
    }
  }

  // DOFs 1, 2 and 6 in a 2-D model; no rotation when a step has NLGEOM=YES (refused once per
  // equation: `rotation_refused`).
  bool check_dof(const EquationTermDefinition& term, bool& rotation_refused) {
    if (model_.dimension == 2 && term.dof != 1 && term.dof != 2 && term.dof != 6) {
      sink_.report(
          DiagCode::invalid_dof, term.dof_loc,
          fmt::format("DOF {} does not exist in a 2-D model (its DOFs are 1, 2 and 6)", term.dof));
      return false;
    }
    // Under NLGEOM, DOFs 4-6 of Abaqus are the components of the total rotation vector (the
    // manual's "Rotation variables"), and an equation on them constrains those components;
    // clinch composes finite rotations as rotation matrices, where such an equation is not the
    // same constraint. Refused rather than approximated.
    if (nlgeom_ && term.dof >= 4) {
      if (std::exchange(rotation_refused, true)) return false;
      sink_.report(DiagCode::unsupported_option, term.dof_loc,
                   fmt::format("an *EQUATION on rotational DOF {} is not supported in a model "
                               "with an NLGEOM=YES step: finite rotations do not add up like the "
                               "components of a vector; join the rotations with MPC BEAM or TIE, "
                               "a kinematic coupling or a connector instead",
                               term.dof));
      return false;
    }
    return true;
  }

  Model& model_;
  ConstraintModel& constraints_;
  DiagnosticSink& sink_;
  bool nlgeom_ = false;  // some step has NLGEOM=YES
};

}  // namespace

void resolve_mpc_equations(Model& model, DiagnosticSink& sink) {
  MpcEquationResolver(model, sink).run();
}

}  // namespace clinch
