#include "src/assembly/stabilization_damping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace clinch {

StabilizationDamping::StabilizationDamping(const DofMap& dofs, const DependentDofs& dependents,
                                           double length_scale)
    : mass_(static_cast<std::size_t>(dofs.equations()), 0.0), dependents_(dependents) {
  for (int eq = 0; eq < dofs.equations(); ++eq) {
    if (dependents.is_dependent(eq)) continue;  // it follows its independent DOFs
    const EquationField field = dofs.field(eq);
    mass_[static_cast<std::size_t>(eq)] = field == EquationField::Translation ? 1.0
                                          : field == EquationField::Rotation
                                              ? length_scale * length_scale
                                              : 0.0;
  }
}

std::string StabilizationDamping::begin_step(const StaticStabilization* settings, double period) {
  settings_ = settings;
  period_ = period;
  warned_ = false;
  if (settings == nullptr) {
    factor_ = 0.0;
    return {};
  }
  if (settings->factor) {
    factor_ = base_factor_ = *settings->factor;
    return fmt::format("automatic stabilization: damping factor c = {:.6g} (FACTOR){}", factor_,
                       settings->allsdtol > 0 ? ", adaptive" : "");
  }
  if (settings->continue_previous && last_factor_ > 0.0) {
    factor_ = base_factor_ = last_factor_;
    return fmt::format(
        "automatic stabilization: damping factor c = {:.6g} from the previous "
        "step (CONTINUE=YES){}",
        factor_, settings->allsdtol > 0 ? ", adaptive" : "");
  }
  factor_ = base_factor_ = 0.0;
  return fmt::format(
      "automatic stabilization: the first increment runs without damping; c "
      "then follows from the dissipated energy fraction {:.3g}{}",
      settings->energy_fraction, settings->allsdtol > 0 ? ", adaptive" : "");
}

void StabilizationDamping::add(const Eigen::VectorXd& x, const Eigen::VectorXd& x_n, double dt,
                               const IncrementConditions& conditions,
                               StabilizationTarget target) const {
  if (!active() || dt <= 0.0) return;
  const double per_time = factor_ / dt;
  for (std::size_t eq = 0; eq < mass_.size(); ++eq) {
    const int e = static_cast<int>(eq);
    if (mass_[eq] == 0.0 || conditions.is_prescribed(e)) continue;
    const double force = per_time * mass_[eq] * (x[e] - x_n[e]);
    target.force[e] = force;
    target.residual[e] += force;
    // Under assembly by rows the rank that owns the row adds its diagonal.
    if (target.tangent && target.tangent->owns_row(dependents_.solved(e))) {
      target.tangent->values[static_cast<std::size_t>(
          target.diagonal[static_cast<std::size_t>(dependents_.solved(e))])] +=
          per_time * mass_[eq];
    }
  }
}

void StabilizationDamping::share_rows(Communicator& ranks, int owned) {
  ranks_ = &ranks;
  std::fill(mass_.begin() + owned, mass_.end(), 0.0);
}

double StabilizationDamping::artificial_mass_norm(const Eigen::VectorXd& dx) const {
  double sum = 0.0;
  for (std::size_t eq = 0; eq < mass_.size(); ++eq) {
    sum += mass_[eq] * dx[static_cast<Eigen::Index>(eq)] * dx[static_cast<Eigen::Index>(eq)];
  }
  if (ranks_) ranks_->sum({&sum, 1});
  return sum;
}

void StabilizationDamping::converged(const Eigen::VectorXd& dx, double dt, double element_work,
                                     const ModelEnergies& energies, std::vector<std::string>& notes,
                                     std::vector<std::string>& warnings) {
  if (settings_ == nullptr) return;
  const StaticStabilization& s = *settings_;
  if (factor_ == 0.0) {
    // The first increment that moves and stores energy (docs/decisions.md): an increment like it
    // dissipates c dxᵀM*dx/Δt, the strain energy grows as the load squared to ΔE (T/Δt)².
    const double motion = artificial_mass_norm(dx);
    if (motion <= 0.0 || element_work <= 0.0 || dt <= 0.0) return;
    const double extrapolated = element_work * (period_ / dt) * (period_ / dt);
    factor_ = s.energy_fraction * extrapolated * dt / motion;
    base_factor_ = factor_;
    notes.push_back(
        fmt::format("automatic stabilization: damping factor c = {:.6g} (the "
                    "increment's strain energy {:.6g} extrapolated to {:.6g})",
                    factor_, element_work, extrapolated));
  } else {
    const double strain = energies.internal;
    const double tolerance = s.allsdtol > 0.0 ? s.allsdtol : 0.05;
    const bool above = strain > 0.0 && energies.stabilization > tolerance * strain;
    if (s.allsdtol > 0.0 && !above && factor_ > base_factor_) {
      factor_ = std::max(base_factor_, 0.5 * factor_);  // back once the trouble has passed
    }
    if (above && s.allsdtol > 0.0) {
      factor_ *= 0.5;
      notes.push_back(
          fmt::format("automatic stabilization: ALLSD/ALLIE = {:.3g} > ALLSDTOL = "
                      "{:.3g}: damping factor halved to {:.6g}",
                      energies.stabilization / strain, s.allsdtol, factor_));
    }
    if (above && !warned_) {
      warned_ = true;
      warnings.push_back(fmt::format(
          "the stabilization energy ALLSD = {:.6g} is {:.3g} of the strain energy ALLIE = {:.6g}, "
          "more than {:.3g}: the viscous forces of STABILIZE may change the answer (check the "
          "reactions against a run with a smaller factor, or use *STATIC, RIKS)",
          energies.stabilization, energies.stabilization / strain, strain, tolerance));
    }
  }
  last_factor_ = factor_;
}

void StabilizationDamping::attempt_failed(std::vector<std::string>& notes) {
  if (settings_ == nullptr || settings_->allsdtol <= 0.0 || factor_ == 0.0) return;
  factor_ *= 2.0;
  notes.push_back(fmt::format(
      "automatic stabilization: an attempt failed; damping factor raised to {:.6g}", factor_));
}

}  // namespace clinch
