// *BOUNDARY on a node of a rigid body other than its reference node acts on the body
// (docs/constraints.md "Conditions on a body's nodes"). A body's node follows the reference node,
// so its DOFs are not its own; two rewrites make the prescribed ones independent again, exactly
// in both small and large displacements:
//   - a translation k prescribed at one node A of the body: A keeps u_k as its own and the
//     body's nodes, the reference node among them, follow A in it,
//     u_k = u_A,k + ((R_ref − I)(X − X_A))_k, the reference node still giving the rotation;
//   - a rotation prescribed at a tie node: a tie node turns exactly as the reference node does
//     (R = R_ref), so the condition is the reference node's and moves there.
// A translation prescribed at two nodes of a body, or at the reference node and another, would
// fix the body's rotation through its arms; that is left to the checks (E0523), which name it.
#include <algorithm>
#include <map>
#include <unordered_map>

#include "src/model/model.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

constexpr DofMask kTranslations3 = 0x07, kRotations3 = 0x38;
constexpr DofMask kTranslations2 = 0x03, kRotations2 = 0x20;  // 2-D: DOFs 1, 2 and 6

DofMask bit(int dof) { return static_cast<DofMask>(1u << (dof - 1)); }

// The DOFs a *BOUNDARY line prescribes (in 2-D only 1, 2 and 6 of a named type: keywords.md §9).
DofMask prescribed_by(const Model& model, const BoundaryCondition& bc) {
  if (!bc.named_type.empty() && model.dimension == 2) return bc.dofs & 0b100011;
  return bc.dofs;
}

template <typename F>
void for_each_boundary_list(Model& model, F&& f) {
  f(model.history.model_boundaries);
  for (Step& step : model.history.steps) f(step.boundaries);
}

class BodyAnchoring {
 public:
  explicit BodyAnchoring(Model& model)
      : model_(model),
        c_(model.constraints),
        translations_(model.dimension == 2 ? kTranslations2 : kTranslations3),
        rotations_(model.dimension == 2 ? kRotations2 : kRotations3) {}

  void run() {
    collect_prescribed();
    if (prescribed_.empty()) return;
    collect_eliminated();
    std::map<std::int32_t, std::vector<std::size_t>> bodies;  // source → its followers
    for (std::size_t i = 0; i < c_.followers.size(); ++i) {
      const NodeFollower& f = c_.followers[i];
      if (c_.sources[static_cast<std::size_t>(f.source)].keyword == "*RIGID BODY") {
        bodies[f.source].push_back(i);
      }
    }
    for (const auto& [source, members] : bodies) {
      anchor_translations(members);
      find_rotation_moves(members);
    }
    std::erase_if(c_.followers, [](const NodeFollower& f) { return f.dofs == 0; });
    c_.followers.insert(c_.followers.end(), added_.begin(), added_.end());
    if (!moved_rotations_.empty()) {
      for_each_boundary_list(model_, [this](std::vector<BoundaryCondition>& list) {
        move_rotations(list);
      });
    }
  }

 private:
  DofMask prescribed(std::int32_t node) const {
    auto it = prescribed_.find(node);
    return it == prescribed_.end() ? 0 : it->second;
  }
  DofMask eliminated(std::int32_t node) const {
    auto it = eliminated_.find(node);
    return it == eliminated_.end() ? 0 : it->second;
  }

  void collect_prescribed() {
    for_each_boundary_list(model_, [this](std::vector<BoundaryCondition>& list) {
      for (const BoundaryCondition& bc : list) {
        const DofMask dofs = prescribed_by(model_, bc);
        for (std::int32_t node : bc.resolved) prescribed_[node] |= dofs;
      }
    });
  }

  // The DOFs some constraint eliminates at each node (a link: any of its node's translations).
  void collect_eliminated() {
    for (const NodeFollower& f : c_.followers) eliminated_[f.node] |= f.dofs;
    for (const LinearConstraint& e : c_.equations) {
      eliminated_[e.terms.front().node] |= bit(e.terms.front().dof);
    }
    for (const DistanceLink& link : c_.links) eliminated_[link.node] |= translations_;
  }

  // A translation prescribed at exactly one node of the body, and neither prescribed nor
  // eliminated at its reference node, anchors the body there.
  void anchor_translations(const std::vector<std::size_t>& members) {
    const std::int32_t reference = c_.followers[members.front()].reference;
    std::map<std::pair<std::int32_t, std::int32_t>, DofMask> follows;  // (node, anchor) → DOFs
    for (int k = 1; k <= 3; ++k) {
      if (!(translations_ & bit(k))) continue;
      const std::int32_t anchor = the_prescribed_member(members, k);
      if (anchor < 0) continue;
      for (std::size_t i : members) {
        NodeFollower& f = c_.followers[i];
        if (!(f.dofs & bit(k))) continue;
        f.dofs = static_cast<DofMask>(f.dofs & ~bit(k));
        if (f.node != anchor) follows[{f.node, anchor}] |= bit(k);
      }
      follows[{reference, anchor}] |= bit(k);
    }
    const NodeFollower& first = c_.followers[members.front()];
    for (const auto& [key, dofs] : follows) {
      added_.push_back({key.first, reference, dofs, true, first.source, key.second});
    }
  }

  // Rotations prescribed at one tie node of the body, and neither prescribed nor eliminated at
  // the reference node, move there.
  void find_rotation_moves(const std::vector<std::size_t>& members) {
    const std::int32_t reference = c_.followers[members.front()].reference;
    for (int k = 4; k <= 6; ++k) {
      if (!(rotations_ & bit(k))) continue;
      const std::int32_t tie = the_prescribed_member(members, k);
      if (tie >= 0) moved_rotations_[tie].push_back({reference, bit(k)});
    }
  }

  // The one node of the body (`members`: its followers) prescribed in DOF k, when the reference
  // node is neither prescribed nor eliminated in it; −1 otherwise.
  std::int32_t the_prescribed_member(const std::vector<std::size_t>& members, int k) const {
    const std::int32_t reference = c_.followers[members.front()].reference;
    if ((prescribed(reference) | eliminated(reference)) & bit(k)) return -1;
    std::int32_t found = -1;
    for (std::size_t i : members) {
      const NodeFollower& f = c_.followers[i];
      if (!(f.dofs & bit(k)) || !(prescribed(f.node) & bit(k))) continue;
      if (found >= 0) return -1;
      found = f.node;
    }
    return found;
  }

  // Splits the *BOUNDARY lines that prescribe a moved rotation: the tie node keeps the rest of
  // the line, the reference node gets the rotation, both at the line's own location.
  void move_rotations(std::vector<BoundaryCondition>& list) {
    const std::size_t written = list.size();
    for (std::size_t i = 0; i < written; ++i) {
      std::vector<std::int32_t> kept;
      std::vector<BoundaryCondition> split;
      for (std::int32_t node : list[i].resolved) {
        auto it = moved_rotations_.find(node);
        const DofMask dofs = prescribed_by(model_, list[i]);
        DofMask moved = 0;
        if (it != moved_rotations_.end()) {
          for (const auto& [reference, rotation] : it->second) {
            if (!(dofs & rotation)) continue;
            moved |= rotation;
            split.push_back(part_of(list[i], reference, rotation));
          }
        }
        if (!moved) {
          kept.push_back(node);
        } else if (list[i].dofs & ~moved) {
          split.push_back(part_of(list[i], node, static_cast<DofMask>(list[i].dofs & ~moved)));
        }
      }
      if (split.empty()) continue;
      list[i].resolved = std::move(kept);
      list.insert(list.end(), split.begin(), split.end());
    }
  }

  static BoundaryCondition part_of(const BoundaryCondition& bc, std::int32_t node,
                                   DofMask dofs) {
    BoundaryCondition part = bc;
    part.resolved = {node};
    part.dofs = dofs;
    return part;
  }

  Model& model_;
  ConstraintModel& c_;
  DofMask translations_, rotations_;
  std::unordered_map<std::int32_t, DofMask> prescribed_;
  std::unordered_map<std::int32_t, DofMask> eliminated_;
  std::vector<NodeFollower> added_;
  std::map<std::int32_t, std::vector<std::pair<std::int32_t, DofMask>>> moved_rotations_;
};

}  // namespace

void anchor_rigid_bodies(Model& model) { BodyAnchoring(model).run(); }

}  // namespace clinch
