#include "src/assembly/energy_balance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace clinch {

EnergyBalance::EnergyBalance(int node_equations, std::size_t connectors, std::vector<bool> dashpots)
    : dashpots_(std::move(dashpots)),
      internal_n_(Eigen::VectorXd::Zero(node_equations)),
      external_n_(internal_n_),
      stabilization_n_(internal_n_),
      friction_n_(connectors, Vector6::Zero()),
      viscous_n_(friction_n_),
      change_n_(friction_n_),
      springs_n_(dashpots_.size()) {}

void EnergyBalance::share_elements(Communicator& ranks, int own_rows) {
  ranks_ = &ranks;
  nodal_by_rows_ = own_rows >= 0;
  if (!nodal_by_rows_) return;
  internal_n_.setZero(own_rows);
  external_n_ = stabilization_n_ = internal_n_;
}

void EnergyBalance::add_increment(const Eigen::VectorXd& dx, const EnergyForces& now) {
  const auto n = internal_n_.size();
  double element_work = 0.5 * (internal_n_ + now.internal.head(n)).dot(dx.head(n));
  double work = 0.5 * (external_n_ + now.external.head(n)).dot(dx.head(n));
  double stabilization = now.stabilization
                             ? 0.5 * (stabilization_n_ + now.stabilization->head(n)).dot(dx.head(n))
                             : 0.0;
  double frictional = 0.0, viscous = 0.0;
  for (std::size_t c = 0; c < now.connectors.size(); ++c) {
    const ConnectorResult& r = now.connectors[c];
    const Vector6 motion = r.change - change_n_[c];
    frictional += 0.5 * (friction_n_[c] + r.friction).dot(motion);
    viscous += 0.5 * (viscous_n_[c] + r.viscous).dot(motion);
  }
  for (std::size_t s = 0; s < now.springs.size(); ++s) {
    if (!dashpots_[s]) continue;
    viscous += 0.5 * (springs_n_[s].force + now.springs[s].force) *
               (now.springs[s].delta - springs_n_[s].delta);
  }
  if (ranks_) {
    // The elements' parts are each rank's own; the nodal ones too under vectors by rows.
    std::array<double, 5> parts{frictional, viscous, element_work, work, stabilization};
    ranks_->sum(std::span<double>(parts).first(nodal_by_rows_ ? 5 : 2));
    frictional = parts[0];
    viscous = parts[1];
    element_work = parts[2];
    work = parts[3];
    stabilization = parts[4];
  }
  energies_.work += work;
  energies_.stabilization += stabilization;
  energies_.frictional += frictional;
  energies_.viscous += viscous;
  energies_.internal += element_work - frictional - viscous;
  largest_ = std::max({largest_, std::abs(energies_.internal), std::abs(energies_.frictional),
                       std::abs(energies_.viscous), std::abs(energies_.stabilization),
                       std::abs(energies_.work)});
  keep(now);
}

void EnergyBalance::restart(const EnergyForces& now) { keep(now); }

void EnergyBalance::keep(const EnergyForces& now) {
  const auto n = internal_n_.size();
  internal_n_ = now.internal.head(n);
  external_n_ = now.external.head(n);
  if (now.stabilization) stabilization_n_ = now.stabilization->head(n);
  for (std::size_t c = 0; c < now.connectors.size(); ++c) {
    friction_n_[c] = now.connectors[c].friction;
    viscous_n_[c] = now.connectors[c].viscous;
    change_n_[c] = now.connectors[c].change;
  }
  springs_n_ = now.springs;
}

}  // namespace clinch
