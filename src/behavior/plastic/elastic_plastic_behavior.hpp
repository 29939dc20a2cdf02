// Connector plasticity as a Behavior (behaviors.md §6): linear elasticity (uncoupled or coupled)
// with uncoupled plasticity per component (isotropic and kinematic hardening, §6.3) and at most
// one coupled plasticity through a connector potential (SUM: closest-point projection §6.4; MAX:
// multi-surface return §6.6), each with its closed-form consistent tangent. Components that no
// plasticity involves keep their elastic law (linear or nonlinear tables).
#pragma once

#include <memory>

#include "src/behavior/behavior.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

// The constitutive law of `behavior` on the components in `available`: the elastic law of
// make_elastic_behavior when the behaviour has no plasticity, the elastic-plastic law otherwise;
// nullptr when nothing acts on an available component. The model must have passed validation.
std::unique_ptr<Behavior> make_connector_behavior(const ConnectorBehavior& behavior,
                                                  ComponentMask available);

}  // namespace clinch
