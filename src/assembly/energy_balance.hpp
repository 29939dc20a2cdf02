// Whole-model energies (docs/dynamics.md "Energies"): the work of the loads and reactions
// (ALLWK), the energy the elements took (ALLIE, without friction and viscosity), the energy
// friction (ALLFD), viscosity (ALLVD) and automatic stabilization (ALLSD) dissipated, the kinetic
// energy (ALLKE), and their balance ETOTAL = ALLKE + ALLIE + ALLFD + ALLVD + ALLSD − ALLWK. Each
// increment adds the trapezoidal work of the forces at its start and end over its motion; with the
// trapezoidal rule of time integration (HHT with α = 0) a linear model then keeps ETOTAL constant
// to round-off.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/assembly/analysis_state.hpp"
#include "src/assembly/spring_element.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

struct ModelEnergies {
  double kinetic = 0;        // ALLKE
  double internal = 0;       // ALLIE: elastic, plastic and damage work of connectors and springs
  double frictional = 0;     // ALLFD: connector friction (CSF) over its relative motion
  double viscous = 0;        // ALLVD: connector damping (CVF) and dashpots
  double stabilization = 0;  // ALLSD: the viscous forces of *STATIC, STABILIZE
  double work = 0;           // ALLWK: loads, and reactions at prescribed DOFs
  double total() const {     // ETOTAL
    return kinetic + internal + frictional + viscous + stabilization - work;
  }
};

// The forces of one state: over the nodal equations, the elements' forces on the nodes and the
// external forces on them (the loads, and at prescribed DOFs what holds them there); per
// connector and dashpot what splits the elements' work.
struct EnergyForces {
  const Eigen::VectorXd& internal;
  const Eigen::VectorXd& external;
  const std::vector<ConnectorResult>& connectors;
  const std::vector<SpringResult>& springs;
  const Eigen::VectorXd* stabilization = nullptr;  // over the equations; null: none
};

class EnergyBalance {
 public:
  // Starts from the unloaded initial state of `node_equations` nodal equations, `connectors`
  // connectors and the springs of which `dashpots` says which are dashpots (their work is viscous).
  EnergyBalance(int node_equations, std::size_t connectors, std::vector<bool> dashpots);
  // The connectors and springs are this rank's share of a distributed model's (docs/parallel.md):
  // the friction and viscous work of each increment is summed over `ranks`. The nodal terms are
  // every rank's alike, or with `own_rows` ≥ 0 (vectors by rows) those of the rank's own nodes,
  // its first `own_rows` nodal equations, summed over the ranks too. Before the first increment.
  void share_elements(Communicator& ranks, int own_rows);

  // Adds the work over the nodal motion `dx` (the nodal equations) from the last kept forces to
  // `now`, and keeps them.
  void add_increment(const Eigen::VectorXd& dx, const EnergyForces& now);
  // Keeps `now` as the forces the next increment starts from, without adding work: at the start
  // of a dynamic step, where a load of AMPLITUDE=STEP acts from step time 0 on.
  void restart(const EnergyForces& now);
  // ALLKE of the converged velocities, which the system computes from its masses.
  void set_kinetic(double kinetic) { energies_.kinetic = kinetic; }
  const ModelEnergies& energies() const { return energies_; }
  // The largest |ALLIE|, |ALLFD|, |ALLVD|, |ALLSD| or |ALLWK| the run has had: the scale of ETOTAL.
  double largest() const { return largest_; }

 private:
  void keep(const EnergyForces& now);

  std::vector<bool> dashpots_;
  ModelEnergies energies_;
  double largest_ = 0.0;
  Eigen::VectorXd internal_n_, external_n_, stabilization_n_;
  std::vector<Vector6> friction_n_, viscous_n_, change_n_;
  std::vector<SpringResult> springs_n_;
  Communicator* ranks_ = nullptr;
  bool nodal_by_rows_ = false;
};

}  // namespace clinch
