#include "src/behavior/damage/damage_evolution_law.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {
namespace {

// §7.2 ENERGY: d = 1 − e^(−W/G_f) only tends to 1; clinch completes the failure at 0.99.
constexpr double kEnergyFailure = 0.99;

}  // namespace

DamageEvolutionLaw::DamageEvolutionLaw(const DamageEvolution& evolution, bool plastic)
    : type_(evolution.type),
      softening_(evolution.softening),
      plastic_(plastic),
      failure_motion_(evolution.failure_motion),
      exponent_(evolution.exponent),
      fracture_energy_(evolution.fracture_energy) {
  if (type_ == DamageEvolution::Type::Motion && softening_ == DamageEvolution::Softening::Tabular) {
    table_ = PiecewiseLinearTable::from_points(evolution.table, evolution.extrapolation);
  }
}

TrialSensitive DamageEvolutionLaw::remaining_fraction(const TrialSensitive& kappa) const {
  if (kappa.value >= failure_motion_) return 0.0;
  const TrialSensitive x = kappa / TrialSensitive(failure_motion_);
  if (softening_ == DamageEvolution::Softening::Linear) return TrialSensitive(1.0) - x;
  // EXPONENTIAL: g = 1 − (1 − e^(−a x))/(1 − e^(−a)).
  const double scale = 1.0 / (1.0 - std::exp(-exponent_));
  return TrialSensitive(1.0) -
         (TrialSensitive(1.0) - exp(TrialSensitive(-exponent_) * x)) * TrialSensitive(scale);
}

TrialSensitive DamageEvolutionLaw::damage(const TrialSensitive& kappa,
                                          const TrialSensitive& initiation_measure,
                                          const TrialSensitive& work) const {
  if (type_ == DamageEvolution::Type::Energy) {
    const TrialSensitive d = TrialSensitive(1.0) - exp(-work / TrialSensitive(fracture_energy_));
    return d.value >= kEnergyFailure ? TrialSensitive(1.0) : d;
  }
  if (softening_ == DamageEvolution::Softening::Tabular) {
    // TABULAR gives d itself (§7.2), clamped to [0, 1].
    const TableSample s = table_->evaluate(kappa.value);
    if (s.value <= 0) return 0.0;
    if (s.value >= 1) return 1.0;
    return {s.value, s.slope * kappa.gradient};
  }
  const TrialSensitive g = remaining_fraction(kappa);
  if (g.value <= 0) return 1.0;
  // PLASTIC MOTION: (1 − d) F_y follows g; FORCE/MOTION: the envelope force k u_0 g(κ), so
  // d = 1 − m_0 g/(m_0 + κ).
  if (plastic_) return TrialSensitive(1.0) - g;
  return TrialSensitive(1.0) - initiation_measure * g / (initiation_measure + kappa);
}

}  // namespace clinch
