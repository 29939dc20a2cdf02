// Multi-surface return of a coupled connector plasticity with a MAX potential (behaviors.md
// §6.6): each contribution is a surface φ_i = s_i P_i(F) − F_y(ū) with its own multiplier and a
// shared ū (dū = Σ Δλ_i). Newton on (F, Δλ_J) over an active set J that is updated (at most 10
// changes), with the consistent tangent D = A − A N (Nᵀ A N + h 1 1ᵀ)⁻¹ Nᵀ A.
#pragma once

#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/yield_function.hpp"
#include "src/behavior/plastic/plastic_return_types.hpp"

namespace clinch {

// `trial` = K (u − u^pl_n) (zero in padded slots), `equivalent_old` = ū_n; the result's
// multiplier is Σ_j Δλ_j. The potential must be a MAX potential.
CoupledReturn multi_surface_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent);

}  // namespace clinch
