// Plain data for *CONNECTOR BEHAVIOR and its sub-options (behaviors.md), including the derived
// components, potentials and friction definitions of each behaviour block. The reader fills it in
// deck order; check_behaviors checks the rules that need the whole block or the sections that
// use it; the analysis plan reads it. Every option keeps the locations its diagnostics need.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "src/model/derived_component_model.hpp"
#include "src/model/friction_model.hpp"
#include "src/model/name.hpp"
#include "src/model/potential_model.hpp"

namespace clinch {

// A keyword that a following *CONNECTOR POTENTIAL belongs to
// (derived-components-and-potentials.md §2.7).
struct PotentialOwner {
  enum class Kind { Plasticity, Friction, DamageInitiation, DamageEvolution };
  Kind kind = Kind::Plasticity;
  std::int32_t index = -1;  // into the behaviour's list of that kind
  SourceLoc loc;            // the owner's keyword line
  bool requires_potential = false;
  bool allows_potential = true;  // false with COMPONENT= or PREDEFINED
  std::string why_not_allowed;   // e.g. "COMPONENT=1"
  std::int32_t potential = -1;   // index into ConnectorBehavior::potentials, set when attached
};

enum class Extrapolation : std::uint8_t { Constant, Linear };

// One point of a piecewise-linear table (behaviors.md §1.2): `value` at abscissa `at`, with the
// location of the row (its first field) for diagnostics.
struct TablePoint {
  double value = 0;
  double at = 0;
  SourceLoc loc;
};

using Stiffness6 = std::array<std::array<double, 6>, 6>;

// The 21 coupled terms of *CONNECTOR ELASTICITY or *CONNECTOR DAMPING (the upper triangle
// column by column, behaviors.md §4.3) as the symmetric 6 × 6 matrix.
inline Stiffness6 expand_coupled_terms(const std::array<double, 21>& terms) {
  Stiffness6 m{};
  std::size_t t = 0;
  for (std::size_t j = 0; j < 6; ++j) {
    for (std::size_t i = 0; i <= j; ++i) m[i][j] = m[j][i] = terms[t++];
  }
  return m;
}

// *CONNECTOR ELASTICITY (behaviors.md §4).
struct ConnectorElasticity {
  enum class Kind : std::uint8_t { Linear, Nonlinear, Coupled, Rigid };
  Kind kind = Kind::Linear;
  int component = 0;        // 1…6; 0 for coupled and for all-component RIGID
  SourceLoc loc;            // keyword line
  SourceLoc component_loc;  // the COMPONENT= value
  bool valid = true;        // false after an error in the option (later checks stay silent)
  Extrapolation extrapolation = Extrapolation::Constant;  // NONLINEAR (§1.2 precedence)
  double stiffness = 0;                                   // Linear: k
  SourceLoc stiffness_loc;
  std::vector<TablePoint> table;  // Nonlinear: force (value) at constitutive motion (at)
  // Coupled: the 21 terms in input order (§4.3) and the full symmetric matrix, D[i][j] for
  // components i+1, j+1.
  std::array<double, 21> coupled_terms{};
  Stiffness6 coupled{};
  SourceLoc data_loc;  // first data line
  // Rigid: bit (i−1) for component i; `rigid_all` when no line/COMPONENT (all available ones).
  std::uint8_t rigid_components = 0;
  bool rigid_all = false;
};

// *CONNECTOR CONSTITUTIVE REFERENCE (behaviors.md §3). Angles (fields 4–6) are stored in radians.
struct ConstitutiveReference {
  SourceLoc loc;
  std::array<std::optional<double>, 6> value;  // blank: the initial measure p_i(0)
  std::array<SourceLoc, 6> value_loc;
};

// *CONNECTOR STOP (behaviors.md §5.1): limits on the position p_i.
struct ConnectorStop {
  int component = 0;
  SourceLoc loc, component_loc, data_loc;
  bool valid = true;
  std::optional<double> lower, upper;
  SourceLoc lower_loc, upper_loc;
};

// *CONNECTOR LOCK (§5.2) and *CONNECTOR FAILURE (§5.3): a criterion on the position and total
// force of `component`, acting on `target` (LOCK= / RELEASE=; 0 = ALL).
struct ConnectorCriterionBounds {
  std::optional<double> position_lower, position_upper, force_lower, force_upper;
  std::array<SourceLoc, 4> loc;  // field locations in data-line order
};
struct ConnectorLock {
  int component = 0;
  int locked = 0;  // LOCK=; 0 = ALL
  SourceLoc loc, component_loc, target_loc;
  bool valid = true;
  ConnectorCriterionBounds bounds;
};
struct ConnectorFailure {
  int component = 0;
  int released = 0;  // RELEASE=; 0 = ALL
  SourceLoc loc, component_loc, target_loc;
  bool valid = true;
  ConnectorCriterionBounds bounds;
};

// *CONNECTOR HARDENING, TYPE=ISOTROPIC (behaviors.md §6.1).
struct IsotropicHardening {
  enum class Definition : std::uint8_t { Tabular, ExponentialLaw };
  Definition definition = Definition::Tabular;
  SourceLoc loc;
  bool valid = true;
  Extrapolation extrapolation = Extrapolation::Constant;
  std::vector<TablePoint> table;  // Tabular: yield force (value) at equivalent plastic motion (at)
  double f0 = 0, q_inf = 0, b = 0;  // Exponential law: F_y = F_0 + Q_inf (1 − e^(−b ū))
  SourceLoc data_loc;
};

// *CONNECTOR HARDENING, TYPE=KINEMATIC (behaviors.md §6.1). HALF CYCLE (two rows) is stored as
// the PARAMETERS it maps to: F_0 = F_1, C = (F_2 − F_1)/u^pl_2, γ = 0.
struct KinematicHardening {
  enum class Definition : std::uint8_t { Parameters, HalfCycle };
  Definition definition = Definition::Parameters;
  SourceLoc loc;
  bool valid = true;
  double f0 = 0, c = 0, gamma = 0;
  SourceLoc f0_loc;
  std::vector<TablePoint> half_cycle;  // HALF CYCLE rows as read: F (value) at u^pl (at)
};

// *CONNECTOR PLASTICITY (behaviors.md §6): uncoupled with COMPONENT, coupled (potential) without.
struct ConnectorPlasticity {
  int component = 0;  // 0: coupled
  SourceLoc loc, component_loc;
  bool valid = true;
  std::optional<IsotropicHardening> isotropic;
  std::optional<KinematicHardening> kinematic;
  bool coupled() const { return component == 0; }
};

// *CONNECTOR DAMAGE INITIATION (behaviors.md §7.1).
struct DamageInitiation {
  enum class Criterion : std::uint8_t { Force, Motion, PlasticMotion };
  Criterion criterion = Criterion::Force;
  int component = 0;  // 0: coupled (a potential follows)
  SourceLoc loc, component_loc, criterion_loc, data_loc;
  bool valid = true;
  std::optional<double> lower, upper;  // FORCE / MOTION limits (blank: none)
  double plastic_motion = 0;           // PLASTIC MOTION: ū^pl_0
  Extrapolation extrapolation = Extrapolation::Constant;
  std::int32_t evolution = -1;  // index into ConnectorBehavior::damage_evolutions
  bool coupled() const { return component == 0; }
};

// *CONNECTOR DAMAGE EVOLUTION (behaviors.md §7.2).
struct DamageEvolution {
  enum class Type : std::uint8_t { Motion, Energy };
  enum class Softening : std::uint8_t { Linear, Exponential, Tabular };
  enum class Degradation : std::uint8_t { Maximum, Multiplicative };
  Type type = Type::Motion;
  Softening softening = Softening::Linear;
  Degradation degradation = Degradation::Maximum;
  SourceLoc loc, data_loc;
  bool valid = true;
  std::int32_t initiation = -1;  // index into ConnectorBehavior::damage_initiations
  // AFFECTED COMPONENTS: bit (i−1) for component i; 0 without the parameter (the initiation's
  // COMPONENT, or the components its potential involves).
  std::uint8_t affected = 0;
  SourceLoc affected_loc;
  double failure_motion = 0;      // MOTION LINEAR/EXPONENTIAL: Δu_f
  double exponent = 0;            // MOTION EXPONENTIAL: a
  double fracture_energy = 0;     // ENERGY: G_f
  std::vector<TablePoint> table;  // MOTION TABULAR: d (value) at δ (at)
  Extrapolation extrapolation = Extrapolation::Constant;
};

// *CONNECTOR DAMPING (behaviors.md §8): viscous, with velocities Δu/Δt in *STATIC.
struct ConnectorDamping {
  enum class Kind : std::uint8_t { Linear, Nonlinear, Coupled, Rayleigh };
  Kind kind = Kind::Linear;
  bool structural = false;  // TYPE=STRUCTURAL: steady-state dynamics only, no effect here
  Extrapolation extrapolation = Extrapolation::Constant;  // NONLINEAR table (§1.2)
  int component = 0;
  SourceLoc loc, component_loc;
  double coefficient = 0;         // Linear: c
  std::vector<TablePoint> table;  // Nonlinear: force (value) at velocity (at)
  std::array<double, 21> coupled_terms{};
  double alpha = 0, beta = 0;  // Rayleigh
};

struct ConnectorBehavior {
  Name name;
  SourceLoc loc;  // keyword line
  std::string extrapolation = "CONSTANT";
  bool used = false;  // referenced by a section (W0501 otherwise)
  // False for a behaviour whose NAME was a duplicate or invalid: it holds the sub-options of its
  // block so that they are still checked, but no section can refer to it.
  bool referable = true;
  // A misspelt keyword stood among its sub-options: what that option would have defined is
  // missing, so outputs that only it could produce are not reported "always 0" (a follow-up).
  bool misspelt_option = false;

  // Owners in deck order; the last one receives the next potential.
  std::vector<PotentialOwner> potential_owners;

  std::vector<DerivedComponentTerm> derived_terms;
  std::vector<Potential> potentials;
  std::vector<FrictionDefinition> frictions;

  std::vector<ConnectorElasticity> elasticities;
  std::optional<ConstitutiveReference> reference;
  std::vector<ConnectorStop> stops;
  std::vector<ConnectorLock> locks;
  std::vector<ConnectorFailure> failures;
  std::vector<ConnectorPlasticity> plasticities;
  std::vector<DamageInitiation> damage_initiations;
  std::vector<DamageEvolution> damage_evolutions;
  std::vector<ConnectorDamping> dampings;
};

// What a behaviour produces, for default output and output checks (output-variables.md §4).
struct BehaviorFeatures {
  bool elasticity = false;
  bool plasticity = false;
  bool kinematic_hardening = false;
  bool damage = false;
  bool force_criterion = false;
  bool motion_criterion = false;
  bool plastic_motion_criterion = false;
  bool stops_or_locks = false;
  bool friction = false;
};
BehaviorFeatures behavior_features(const ConnectorBehavior& behavior);

struct BehaviorModel {
  std::vector<ConnectorBehavior> behaviors;
  std::unordered_map<std::string, std::int32_t> by_key;
};

}  // namespace clinch
