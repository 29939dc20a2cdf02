// A reduced closest-point projection for coupled plasticity whose potential is a sum of groups
// (ConnectorPotential::group_structure: NORM and Macaulay terms on disjoint components, every
// α_i = β) and whose elasticity is diagonal. Then the flow rule K⁻¹(F − F^tr) + Δλ n = 0 acts on
// each group alone: with κ_c = k_c C_c² and y_i = Δλ n_i, F_c = t_c T_g/(T_g + κ_c y_i), where
// the group's resultant T_g solves Σ_c C_c² t_c²/(T_g + κ_c y_i)² = 1, clipped at zero where the
// exact return stops on the kink (behaviors.md §6.4 with the potential of
// derived-components-and-potentials.md §2.4). Where κ_c is the same over the group (always for
// a Macaulay or one-component term) this is a radial shrink, T_g = ⟨r_g^tr − κ_g y_i⟩. The spot
// weld of §3 is such a potential.
//
// At the solution P = F_y, so the slope of contribution i is n_i = z_i^(β−1)/R_i with the share
// z_i = E_i/(R_i F_y) (§2.4), and Σ z_i^β = 1. For β = 1.5 (and β = 2 with a non-uniform group)
// Δλ and v_i = z_i^(β−1) are found together by a semismooth Newton on R_i F_y z_i =
// E_i(Δλ v_i/R_i) and Σ z_i^β = 1 (solve_jointly), with a non-uniform group's T_g from its own
// scalar Newton inside. Otherwise, and where that does not settle, every group being uniform,
// each share solves its own scalar equation for a given Δλ (a quadratic in √z for β = 1.5,
// linear for β = 1 and 2) and one scalar equation Σ z_i(Δλ)^β = 1 is left (solve_multiplier).
// The consistent tangent follows in closed form from the same relations: no root of the
// potential, no 6×6 factorisation. Same answer as closest_point_return, an order of magnitude
// cheaper. A non-uniform group with another β is left to closest_point_return.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>

#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/plastic/isotropic_hardening.hpp"
#include "src/behavior/plastic/plastic_return_types.hpp"

namespace clinch {

class GroupedReturn {
 public:
  // nullopt unless `potential` has a group structure and `space` is diagonal with a uniform
  // k·C² over every NORM group.
  static std::optional<GroupedReturn> create(const ConnectorPotential& potential,
                                             const ElasticSpace& space);

  // As closest_point_return (coupled_return_mapping.hpp); `converged` is false when the scalar
  // Newton fails, and the caller then uses the general return.
  CoupledReturn solve(const IsotropicHardeningLaw& yield, const Vector6& trial,
                      double equivalent_old, bool want_tangent) const;

  static constexpr int kMaxGroups = 6;  // the groups are disjoint sets of the six components

 private:
  struct Group {
    ComponentMask components = 0;
    bool macauley = false;
    bool single = false;  // one component: its resultant is |C x|, no root
    int contribution = 0;
    Vector6 coefficient = Vector6::Zero();  // C (sign included)
    double kappa = 0;                       // k·C² (of its first component where not uniform)
    double inverse_kappa = 0;
    Vector6 component_kappa = Vector6::Zero();  // κ_c = k_c C_c²
    bool uniform = true;                        // κ_c the same over the group: radial flow
  };
  struct Contribution {
    double scale = 1;          // R_i
    double inverse_scale = 1;  // 1/R_i
    unsigned groups = 0;       // bits of its groups in groups_
  };
  // How z^(β−1) is formed from the share equation (§5 exponents get closed forms).
  enum class Exponent : std::uint8_t { One, ThreeHalves, Two, General };
  struct GroupSet;
  struct Trial;
  struct Share;
  struct Iterate;
  struct Response;
  struct Distance {
    double value, slope, curvature;  // g, dg/dΔλ, d²g/dΔλ² (NaN where S″ is not formed)
  };

  // The group resultants r_g of the trial force; then the rest of Trial, for a plastic update.
  void resolve_resultants(const Vector6& trial, Trial& t) const;
  void resolve_groups(Trial& t) const;
  // S = Σ z_i^β at Δλ = 0 (z_i = E_i^tr/(R_i F_y)), from the resultants alone: the yield check.
  double trial_share_sum(const Trial& t, double yield_size) const;
  // The groups among `candidates` that a y_i of `y` leaves positive (r_g/κ_g > y).
  GroupSet reaching_beyond(unsigned candidates, const Trial& t, double y) const;
  // The group among `candidates` that clips last (largest r_g/κ_g), alone.
  GroupSet last_to_clip(unsigned candidates, const Trial& t) const;
  // T_g and −dT_g/dy of a non-uniform NORM group at y below its clip, from a guess of T_g.
  std::pair<double, double> norm_group_response(int group, const Trial& t, double y,
                                                double guess) const;
  // E_i(y) and −dE_i/dy of a contribution, with T_g and −dT_g/dy of its groups into `it`.
  template <bool kAllUniform>
  Response respond(int contribution, const Trial& t, double y, Iterate& it) const;
  Share solve_share(int contribution, const Trial& t, double multiplier,
                    const YieldSample& y) const;
  void evaluate(const Trial& t, double multiplier, const YieldSample& y, Iterate& it) const;
  double root_of_share_sum(double s) const;
  Distance distance(const Iterate& it) const;
  // From S = Σ z_i^β at Δλ = 0 and root = S^γ.
  double radial_guess(const Trial& t, double share_sum, const YieldSample& y, double root) const;
  // β = 1.5 or 2: Δλ and the shares at it in `it` (left as it is on failure), from S at Δλ = 0.
  template <bool kAllUniform>
  bool solve_jointly(const Trial& t, const IsotropicHardeningLaw& yield, double equivalent_old,
                     double share_sum, Iterate& it, double& multiplier) const;
  // Any β, the same by Newton–Halley on Δλ alone with every share solved at each iterate.
  bool solve_multiplier(const Trial& t, const IsotropicHardeningLaw& yield, double equivalent_old,
                        Iterate& it, double& multiplier) const;
  void tangent(const Vector6& trial, const Trial& t, const Iterate& it, double multiplier,
               Matrix6& out) const;

  std::array<Group, kMaxGroups> groups_{};
  int group_count_ = 0;
  std::array<Contribution, kMaxGroups> contributions_{};
  int contribution_count_ = 0;
  Vector6 stiffness_ = Vector6::Ones();                          // the diagonal of K
  std::array<std::int8_t, 6> group_of_{-1, -1, -1, -1, -1, -1};  // per component
  // The contribution of each component's group (0 for a component outside the potential, whose
  // rows of the tangent vanish), and 1 where components c and e are in the same group
  // (contribution), else 0: the masks of the tangent's outer products.
  std::array<int, 6> contribution_of_{};
  Matrix6 same_group_ = Matrix6::Zero(), same_contribution_ = Matrix6::Zero();
  double beta_ = 2.0;
  double gamma_ = 0.5;  // 1 − 1/β
  Exponent exponent_ = Exponent::Two;
  bool nonuniform_ = false;  // some NORM group has unequal κ_c (solve_jointly only)
};

}  // namespace clinch
