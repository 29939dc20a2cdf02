// A reduced closest-point projection for coupled plasticity whose potential is a sum of groups
// (ConnectorPotential::group_structure: NORM and Macaulay terms on disjoint components, every
// α_i = β) and whose elasticity is diagonal with k·C² the same over each NORM group. Then the
// flow rule K⁻¹(F − F^tr) + Δλ n = 0 shrinks every group radially: a NORM group's resultant to
// T_g = ⟨r_g^tr − κ_g Δλ n_i⟩ (κ_g = k C²), a Macaulay term likewise, clipped at zero where the
// exact return stops on the kink. What is left is m + 1 scalar equations for Δλ and the
// contribution values E_i (behaviors.md §6.4 with the potential of
// derived-components-and-potentials.md §2.4), solved by Newton. The spot weld of §3 is such a
// potential. Same answer as closest_point_return, a few times cheaper.
#pragma once

#include <optional>
#include <vector>

#include "src/behavior/connector_potential.hpp"
#include "src/behavior/fixed_power.hpp"
#include "src/behavior/isotropic_hardening.hpp"
#include "src/behavior/plastic_return_types.hpp"

namespace clinch {

class GroupedReturn {
 public:
  // nullopt unless `potential` has a group structure and `space` is diagonal with a uniform
  // k·C² over every NORM group.
  static std::optional<GroupedReturn> create(const ConnectorPotential& potential,
                                             const ElasticSpace& space);

  // As closest_point_return (coupled_return_mapping.hpp); `converged` is false when the scalar
  // Newton fails, and the caller then uses the general return.
  CoupledReturn solve(const ElasticSpace& space, const ConnectorPotential& potential,
                      const IsotropicHardeningLaw& yield, const Vector6& trial,
                      double equivalent_old, bool want_tangent) const;

 private:
  struct Group {
    std::vector<KinkGroup>::size_type index = 0;
    ComponentMask components = 0;
    bool macauley = false;
    int contribution = 0;
    Vector6 coefficient = Vector6::Zero();
    double kappa = 0;  // k·C², uniform over the group
  };
  std::vector<Group> groups_;
  std::vector<double> scales_;  // R_i
  FixedPower beta_;  // β
};

}  // namespace clinch
