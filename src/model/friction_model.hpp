// Plain data for *CONNECTOR FRICTION and the *FRICTION law that belongs to it (friction.md §2–§3).
// One FrictionDefinition per *CONNECTOR FRICTION keyword; validation fills the friction components
// J (default_stick_stiffness.hpp gives the stick stiffness when STICK STIFFNESS is omitted).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/name.hpp"

namespace clinch {

// *FRICTION in a connector behaviour (friction.md §3).
struct FrictionLaw {
  SourceLoc loc;  // the *FRICTION keyword line
  bool exponential_decay = false;
  // Default form: rows (μ, slip rate, contact force F_N). v1: μ depends on at most one of the two
  // columns, which then increases strictly (§3.2).
  enum class Variable : std::uint8_t { None, SlipRate, ContactForce };
  Variable variable = Variable::None;
  std::vector<double> mu;
  std::vector<double> slip_rate;
  std::vector<double> contact_force;
  // EXPONENTIAL DECAY: μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇).
  double mu_static = 0.0;
  double mu_kinetic = 0.0;
  double decay = 0.0;
  std::optional<double> taumax;  // TAUMAX = F_max (no cap when absent)
  bool complete = false;         // the data were read without error
};

struct FrictionDefinition {
  SourceLoc loc;  // the *CONNECTOR FRICTION keyword line
  bool predefined = false;
  SourceLoc predefined_loc;
  int component = 0;        // COMPONENT= (0: none)
  SourceLoc component_loc;  // the COMPONENT parameter name
  // CONTACT FORCE= (friction.md §2.2): none, a component number, or a derived component name.
  enum class Contact : std::uint8_t { None, Component, Derived };
  Contact contact = Contact::None;
  int contact_component = 0;
  Name contact_name;                      // loc: the value
  SourceLoc contact_loc;                  // the CONTACT FORCE parameter name
  std::optional<double> stick_stiffness;  // STICK STIFFNESS= (> 0)
  SourceLoc stick_stiffness_loc;          // its value
  std::string extrapolation = "CONSTANT";
  // Internal contact force table F_int(γ) (§2.4): one row = constant, none = 0.
  std::vector<double> internal_force;
  std::vector<double> slip;
  std::int32_t owner = -1;  // index into ConnectorBehavior::potential_owners
  bool has_law = false;
  FrictionLaw law;
  // Set by validation: friction components J as a bit mask (bit i−1 = component i).
  std::uint8_t friction_components = 0;
};

}  // namespace clinch
