// Queries on the elasticity and plasticity of one behaviour block that validation and the run
// share (behaviors.md §2, §4.4, §6): which components are plastic, which are RIGID, and the stiff
// spring of a rigid-plastic component. Valid after validation.
#pragma once

#include <cstddef>

#include "src/model/behavior_model.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

// The components a potential attached to owner (kind, index) involves
// (derived-components-and-potentials.md §2.8): its intrinsic components and the components of
// every term of the derived components it names. 0 when there is no attached potential.
ComponentMask potential_components(const ConnectorBehavior& behavior, PotentialOwner::Kind kind,
                                   std::size_t index);

// Components of `available` with a plasticity: uncoupled ones and those of the coupled
// plasticity's potential (§6).
ComponentMask plastic_components(const ConnectorBehavior& behavior, ComponentMask available);

// Components of `available` that some RIGID elasticity names (§4.4).
ComponentMask rigid_elasticity_components(const ConnectorBehavior& behavior,
                                          ComponentMask available);

// §4.4 rigid-plastic: RIGID components of `available` that are also plastic.
ComponentMask rigid_plastic_components(const ConnectorBehavior& behavior, ComponentMask available);

// §4.4: the stiff spring of rigid-plastic `component`: 1000 × the largest linear elastic
// stiffness (diagonal, every definition added) of the same kind (translational 1–3, rotational
// 4–6) among `available`, or 1.0e8 when there is none.
double rigid_plastic_stiffness(const ConnectorBehavior& behavior, ComponentMask available,
                               int component);

}  // namespace clinch
