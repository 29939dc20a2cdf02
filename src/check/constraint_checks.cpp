// Overconstraints across every kind of kinematic constraint (docs/constraints.md
// "Overconstraints"): a DOF eliminated by two definitions, a dependent DOF that *BOUNDARY also
// prescribes, cycles of constraints, chains through a nonlinear map under NLGEOM, linearised
// constraints under NLGEOM, and connectors whose constrained components join two nodes that
// already move as one. Each is an error at the later source naming the earlier, so that the
// analysis never meets a singular matrix or a DOF it cannot order (src/assembly/dependent_dofs.cpp
// guards the same conditions without lines to name).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

using DofKey = std::int64_t;  // node × 8 + DOF

DofKey key_of(std::int32_t node, int dof) { return static_cast<DofKey>(node) * 8 + dof; }
std::int32_t node_of(DofKey key) { return static_cast<std::int32_t>(key / 8); }
int dof_of(DofKey key) { return static_cast<int>(key % 8); }
DofMask bit(int dof) { return static_cast<DofMask>(1u << (dof - 1)); }

std::string node_display(const Model& model, std::int32_t n) {
  const Node& node = model.nodes[static_cast<std::size_t>(n)];
  return qualified_label(model, node.instance, node.label);
}

bool later(SourceLoc a, SourceLoc b) {
  return std::tie(a.file, a.line, a.column) > std::tie(b.file, b.line, b.column);
}

// The DOF of a link's first node that the analysis eliminates: the translation along which the
// link lies most (ties: the lower axis), as src/assembly/dependent_dofs.cpp chooses it.
int link_dof(const Model& model, const DistanceLink& link) {
  const Vec3& x = model.nodes[static_cast<std::size_t>(link.node)].x;
  const Vec3& y = model.nodes[static_cast<std::size_t>(link.other)].x;
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(x[k] - y[k]) > std::abs(x[axis] - y[axis])) axis = k;
  }
  return axis + 1;
}

// One eliminated DOF: what eliminates it and the DOFs its value is computed from.
struct Dependent {
  std::int32_t source = -1;
  bool curved = false;        // a rigid arm's translation or a link: nonlinear under NLGEOM
  std::vector<DofKey> reads;  // the DOFs the map reads
};

class ConstraintChecker {
 public:
  ConstraintChecker(const Model& model, DiagnosticSink& sink)
      : model_(model), c_(model.constraints), sink_(sink) {
    const bool two_d = model.dimension == 2;
    translations_ = two_d ? 0x03 : 0x07;
    rotations_ = two_d ? 0x20 : 0x38;
    for (const Step& step : model.history.steps) {
      if (step.nlgeom) {
        nlgeom_step_ = &step;
        break;
      }
    }
  }

  void run() {
    if (c_.sources.empty()) return;
    collect();
    check_boundaries();
    check_cycles();
    if (nlgeom_step_) {
      check_nonlinear_chains();
      check_linearised();
    }
    check_connectors();
  }

 private:
  const ConstraintSource& source(std::int32_t s) const {
    return c_.sources[static_cast<std::size_t>(s)];
  }
  std::string at_line(std::int32_t s) const {
    return fmt::format("the {} at line {}", source(s).keyword, source(s).loc.line);
  }

  // ---- (a) every dependent DOF once -------------------------------------------------------

  void collect() {
    for (const NodeFollower& f : c_.followers) {
      const Vec3& x = model_.nodes[static_cast<std::size_t>(f.node)].x;
      const Vec3& x_source = model_.nodes[static_cast<std::size_t>(f.translation_source())].x;
      const bool arm = f.rigid_arm && x != x_source;
      for (int dof = 1; dof <= 6; ++dof) {
        if (!(f.dofs & bit(dof))) continue;
        Dependent d;
        d.source = f.source;
        d.reads.push_back(key_of(dof <= 3 ? f.translation_source() : f.reference, dof));
        if (dof <= 3 && arm) {
          d.curved = true;
          for (int r = 4; r <= 6; ++r) {
            if (rotations_ & bit(r)) d.reads.push_back(key_of(f.reference, r));
          }
        }
        add(key_of(f.node, dof), std::move(d));
      }
    }
    for (const LinearConstraint& equation : c_.equations) {
      Dependent d;
      d.source = equation.source;
      for (std::size_t t = 1; t < equation.terms.size(); ++t) {
        d.reads.push_back(key_of(equation.terms[t].node, equation.terms[t].dof));
      }
      add(key_of(equation.terms.front().node, equation.terms.front().dof), std::move(d));
    }
    for (const DistanceLink& link : c_.links) {
      const int eliminated = link_dof(model_, link);
      Dependent d;
      d.source = link.source;
      d.curved = true;
      for (int k = 1; k <= 3; ++k) {
        if (!(translations_ & bit(k))) continue;
        d.reads.push_back(key_of(link.other, k));
        if (k != eliminated) d.reads.push_back(key_of(link.node, k));
      }
      add(key_of(link.node, eliminated), std::move(d));
    }
  }

  // A DOF eliminated by a second definition: reported once per pair of definitions, at the
  // later one. Within one definition a DOF is never claimed twice (its resolve drops repeats).
  void add(DofKey key, Dependent d) {
    auto [it, inserted] = dependents_.try_emplace(key, std::move(d));
    if (inserted) return;
    std::int32_t first = it->second.source, second = d.source;
    if (first == second) return;
    if (later(source(first).loc, source(second).loc)) std::swap(first, second);
    if (!reported_pairs_.insert({first, second}).second) return;
    sink_
        .report(DiagCode::constraint_conflict, source(second).loc,
                fmt::format("DOF {} of node {} is tied twice: {} already eliminates it; a DOF "
                            "can follow one definition only",
                            dof_of(key), node_display(model_, node_of(key)), at_line(first)))
        .notes.push_back({source(first).loc, fmt::format("the {} is here", source(first).keyword)});
  }

  const Dependent* dependent(DofKey key) const {
    auto it = dependents_.find(key);
    return it == dependents_.end() ? nullptr : &it->second;
  }

  // ---- (b) a dependent DOF prescribed -----------------------------------------------------

  void check_boundaries() {
    check_boundaries(model_.history.model_boundaries);
    for (const Step& step : model_.history.steps) check_boundaries(step.boundaries);
  }

  void check_boundaries(const std::vector<BoundaryCondition>& boundaries) {
    for (const BoundaryCondition& bc : boundaries) {
      for (std::int32_t node : bc.resolved) {
        const Dependent* found = nullptr;
        int found_dof = 0;
        for (int dof = 1; dof <= 6 && !found; ++dof) {
          if (!(bc.dofs & bit(dof))) continue;
          found = dependent(key_of(node, dof));
          found_dof = dof;
        }
        if (!found) continue;
        sink_
            .report(DiagCode::dependent_dof_prescribed, bc.loc,
                    fmt::format("DOF {} of node {} is prescribed here, but {} makes it depend "
                                "on {}; {}",
                                found_dof, node_display(model_, node), at_line(found->source),
                                reads_display(*found), remedy(*found, found_dof)))
            .notes.push_back({source(found->source).loc,
                              fmt::format("the {} is here", source(found->source).keyword)});
        break;  // one report per *BOUNDARY line
      }
    }
  }

  // A rigid body takes each of its DOFs at one node (anchor_rigid_bodies.cpp): a second
  // prescribed translation would fix its rotation through the arms.
  std::string remedy(const Dependent& d, int dof) const {
    if (source(d.source).keyword != "*RIGID BODY") {
      return "prescribe the independent DOFs (the reference node) instead";
    }
    return fmt::format("a rigid body takes a condition on DOF {} at one of its nodes only "
                       "(the reference node or one other), and only while no other constraint "
                       "eliminates that DOF of its reference node; prescribe the body's rotation "
                       "at its reference node instead of a second translation",
                       dof);
  }

  // "node 7" or "nodes 7 and 9": the nodes a dependent DOF reads.
  std::string reads_display(const Dependent& d) const {
    std::vector<std::int32_t> nodes;
    for (DofKey k : d.reads) nodes.push_back(node_of(k));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::string out = nodes.size() == 1 ? "node " : "nodes ";
    for (std::size_t i = 0; i < nodes.size() && i < 4; ++i) {
      if (i) out += i + 1 == nodes.size() ? " and " : ", ";
      out += node_display(model_, nodes[i]);
    }
    if (nodes.size() > 4) out += ", ...";
    return out;
  }

  // ---- (c) cycles and nonlinear chains ----------------------------------------------------

  // Depth first over the dependent DOFs, iteratively (chains of thousands of bodies).
  void check_cycles() {
    enum : std::uint8_t { kNew, kOnPath, kDone };
    std::unordered_map<DofKey, std::uint8_t> mark;
    std::set<std::vector<std::int32_t>> reported;
    struct Frame {
      DofKey key;
      std::size_t next;
    };
    for (const auto& [start, unused] : dependents_) {
      if (mark[start] != kNew) continue;
      std::vector<Frame> path{{start, 0}};
      mark[start] = kOnPath;
      while (!path.empty()) {
        Frame& top = path.back();
        const Dependent& d = dependents_.at(top.key);
        if (top.next == d.reads.size()) {
          mark[top.key] = kDone;
          path.pop_back();
          continue;
        }
        const DofKey to = d.reads[top.next++];
        if (!dependents_.contains(to)) continue;
        std::uint8_t& state = mark[to];
        if (state == kNew) {
          state = kOnPath;
          path.push_back({to, 0});
        } else if (state == kOnPath) {
          report_cycle(path, to, reported);
        }
      }
    }
  }

  template <typename Frames>
  void report_cycle(const Frames& path, DofKey back_to,
                    std::set<std::vector<std::int32_t>>& reported) {
    std::vector<std::int32_t> sources;
    std::size_t from = path.size();
    while (from > 0 && path[from - 1].key != back_to) --from;
    if (from > 0) --from;
    for (std::size_t i = from; i < path.size(); ++i) {
      sources.push_back(dependents_.at(path[i].key).source);
    }
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
    if (!reported.insert(sources).second) return;
    std::int32_t last = sources.front();
    for (std::int32_t s : sources) {
      if (later(source(s).loc, source(last).loc)) last = s;
    }
    std::string others;
    for (std::int32_t s : sources) {
      if (s == last) continue;
      others += (others.empty() ? "" : ", ") + at_line(s);
    }
    Diagnostic& d = sink_.report(
        DiagCode::constraint_cycle, source(last).loc,
        fmt::format("DOF {} of node {} depends on itself through a cycle of constraints{}{}; "
                    "make one of them independent",
                    dof_of(back_to), node_display(model_, node_of(back_to)),
                    others.empty() ? "" : ": this one and ", others));
    for (std::int32_t s : sources) {
      if (s != last)
        d.notes.push_back({source(s).loc, fmt::format("the {} is here", source(s).keyword)});
    }
  }

  // Under NLGEOM a chain of constraints is substituted exactly only through linear maps: a
  // rigid arm or a link reading a DOF that another definition eliminates (or read by one) is
  // refused, naming both.
  void check_nonlinear_chains() {
    std::set<std::pair<std::int32_t, std::int32_t>> reported;
    for (const auto& [key, d] : dependents_) {
      for (DofKey r : d.reads) {
        const Dependent* next = dependent(r);
        if (!next || next->source == d.source || !(d.curved || next->curved)) continue;
        std::int32_t first = next->source, second = d.source;
        if (later(source(first).loc, source(second).loc)) std::swap(first, second);
        if (!reported.insert({first, second}).second) continue;
        sink_
            .report(DiagCode::constraint_not_under_nlgeom, source(second).loc,
                    fmt::format("{} and {} form a chain (DOF {} of node {} is eliminated by one "
                                "and read by the other) through a rigid arm or a link, which is "
                                "not supported under NLGEOM; attach both to the same independent "
                                "node",
                                at_line(first), at_line(second), dof_of(r),
                                node_display(model_, node_of(r))))
            .notes.push_back({nlgeom_step_->loc, "NLGEOM=YES in this step"});
      }
    }
  }

  // ---- (e) maps that hold in small displacements only --------------------------------------

  void check_linearised() {
    std::set<std::int32_t> reported;
    for (const LinearConstraint& equation : c_.equations) {
      if (equation.exact_under_nlgeom || !reported.insert(equation.source).second) continue;
      sink_
          .report(DiagCode::constraint_not_under_nlgeom, source(equation.source).loc,
                  fmt::format("the {} is linearised (its map holds in small displacements "
                              "only): NLGEOM=YES is not supported for it",
                              source(equation.source).keyword))
          .notes.push_back({nlgeom_step_->loc, "NLGEOM=YES in this step"});
    }
    // Some but not all rotations of a node following a reference: under finite rotations the
    // components left free are not independent of those that follow.
    for (const NodeFollower& f : c_.followers) {
      const DofMask r = static_cast<DofMask>(f.dofs & rotations_);
      if (!r || r == rotations_ || !reported.insert(f.source).second) continue;
      sink_
          .report(DiagCode::constraint_not_under_nlgeom, source(f.source).loc,
                  fmt::format("the {} couples some but not all rotations of node {}: under "
                              "NLGEOM the free rotation components are not independent of the "
                              "coupled ones, which is not supported; couple all rotations or "
                              "none",
                              source(f.source).keyword, node_display(model_, f.node)))
          .notes.push_back({nlgeom_step_->loc, "NLGEOM=YES in this step"});
    }
  }

  // ---- (d) connectors between nodes that move as one ---------------------------------------

  // The node `n` follows rigidly (through rigid-arm followers) and the DOFs it follows it in;
  // a node that follows none is its own root with every DOF.
  std::pair<std::int32_t, DofMask> root(std::int32_t n) const {
    DofMask mask = static_cast<DofMask>(translations_ | rotations_);
    for (std::size_t steps = 0; steps <= c_.followers.size(); ++steps) {
      auto it = rigid_follower_.find(n);
      if (it == rigid_follower_.end()) break;
      mask &= it->second.dofs;
      n = it->second.reference;
    }
    return {n, mask};
  }

  // Each node's rigid-arm followers as one: the node it moves with and in which DOFs. A body's
  // anchor (anchor_rigid_bodies.cpp) moves with it in the DOFs it anchors.
  void collect_rigid_followers() {
    for (const NodeFollower& f : c_.followers) {
      if (!f.rigid_arm) continue;
      for (std::int32_t n : {f.node, f.anchor}) {
        if (n < 0 || n == f.reference) continue;
        Moves& m =
            rigid_follower_.try_emplace(n, Moves{f.reference, 0, f.source}).first->second;
        if (m.reference == f.reference) m.dofs |= f.dofs;
      }
    }
  }

  ComponentMask rigid_components(const ConnectorSection& section) const {
    if (section.behavior_index < 0) return 0;
    ComponentMask mask = 0;
    const ConnectorBehavior& behavior =
        model_.behaviors.behaviors[static_cast<std::size_t>(section.behavior_index)];
    for (const ConnectorElasticity& e : behavior.elasticities) {
      if (e.kind != ConnectorElasticity::Kind::Rigid || !e.valid) continue;
      mask |= e.rigid_all ? section.available : e.rigid_components;
    }
    return mask;
  }

  void check_connectors() {
    collect_rigid_followers();
    if (rigid_follower_.empty()) return;
    const auto& section_of = model_.sections.section_of_element;
    const DofMask all = static_cast<DofMask>(translations_ | rotations_);
    for (std::size_t e = 0; e < model_.elements.size() && e < section_of.size(); ++e) {
      const Element& element = model_.elements[e];
      if (!is_connector(element.type) || section_of[e] < 0) continue;
      const auto [a, b] = element.nodes;
      if (a < 0 || b < 0) continue;
      const auto [root_a, mask_a] = root(a);
      const auto [root_b, mask_b] = root(b);
      if (root_a != root_b) continue;
      const DofMask common = static_cast<DofMask>(mask_a & mask_b);
      // Both nodes follow the same node in every DOF: every component of their relative
      // motion is fixed; in the translations only (pin nodes): the translational components.
      ComponentMask fixed = 0;
      if ((common & all) == all) {
        fixed = 0x3F;
      } else if ((common & translations_) == translations_) {
        fixed = 0x07;
      }
      const ConnectorSection& section =
          model_.sections.connector_sections[static_cast<std::size_t>(section_of[e])];
      const ComponentMask over =
          static_cast<ComponentMask>((section.constrained | rigid_components(section)) & fixed);
      if (!over) continue;
      const std::int32_t via = rigid_follower_.at(a != root_a ? a : b).source;
      std::string components;
      for (int k = 1; k <= 6; ++k) {
        if (over & (1u << (k - 1)))
          components += (components.empty() ? "" : ", ") + std::to_string(k);
      }
      sink_
          .report(DiagCode::connector_overconstraint, element.loc(),
                  fmt::format("connector element {} joins nodes {} and {}, which already move "
                              "as one with node {} ({}): its constrained or RIGID "
                              "component{} {} would constrain them twice; join the body to a "
                              "node outside it, or remove the connector",
                              element.label, node_display(model_, a), node_display(model_, b),
                              node_display(model_, root_a), at_line(via),
                              components.size() > 1 ? "s" : "", components))
          .notes.push_back({source(via).loc, fmt::format("the {} is here", source(via).keyword)});
    }
  }

  const Model& model_;
  const ConstraintModel& c_;
  DiagnosticSink& sink_;
  DofMask translations_ = 0, rotations_ = 0;
  const Step* nlgeom_step_ = nullptr;       // the first step with NLGEOM=YES
  std::map<DofKey, Dependent> dependents_;  // ordered: reports come in the same order every run
  std::set<std::pair<std::int32_t, std::int32_t>> reported_pairs_;
  struct Moves {
    std::int32_t reference = -1;
    DofMask dofs = 0;
    std::int32_t source = -1;
  };
  std::unordered_map<std::int32_t, Moves> rigid_follower_;  // node → how it moves rigidly
};

}  // namespace

void check_constraints(const Model& model, DiagnosticSink& sink) {
  ConstraintChecker(model, sink).run();
}

}  // namespace clinch
