// Automatic stabilization of a *STATIC step (docs/stabilization.md): viscous forces
//   F_v = c M* (u − u₀)/Δt
// on the free nodal DOFs Newton solves, u₀ the converged state at the increment's start. M* is an
// artificial unit mass per translation and L̄² per rotation: connectors have no volume to give
// the unit-density mass Abaqus uses (docs/decisions.md "Automatic stabilization"). The damping
// factor c is given (FACTOR) or chosen after the step's first increment so that an increment
// like it dissipates the dissipated energy fraction of the strain energy extrapolated to the
// step's end. The adaptive form (ALLSDTOL > 0) doubles c for the retry of an attempt that failed,
// halves it back towards that base value after an increment that converged, and halves it below
// the base value after an increment that leaves ALLSD above ALLSDTOL·ALLIE.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/assembly/dependent_dofs.hpp"
#include "src/assembly/dof_map.hpp"
#include "src/assembly/energy_balance.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/linalg/sparse_matrix.hpp"
#include "src/model/history_model.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

// Where the viscous forces go: the residual over every equation, the tangent (null: residual
// only) with the position of each solved equation's diagonal entry, and the force per equation.
struct StabilizationTarget {
  Eigen::VectorXd& residual;
  SparseMatrix* tangent;
  const std::vector<int>& diagonal;
  Eigen::VectorXd& force;
};

class StabilizationDamping {
 public:
  StabilizationDamping(const DofMap& dofs, const DependentDofs& dependents, double length_scale);

  // Starts a step of `period` with `settings` (null: a step without stabilization). With
  // CONTINUE=YES the factor the last stabilized step ended with carries on. Returns the log's
  // line on how c is chosen (empty without stabilization).
  std::string begin_step(const StaticStabilization* settings, double period);
  bool active() const { return settings_ != nullptr && factor_ > 0.0; }
  // Vectors by rows (docs/parallel.md): this rank damps its own rows, the first `owned`
  // equations, and the ranks' motions are summed where c is chosen.
  void share_rows(Communicator& ranks, int owned);
  double factor() const { return factor_; }

  // Adds F_v to the free, solved nodal rows of `target.residual`, c M*/Δt to their diagonal.
  void add(const Eigen::VectorXd& x, const Eigen::VectorXd& x_n, double dt,
           const IncrementConditions& conditions, StabilizationTarget target) const;

  // After a converged increment of length `dt` that moved the nodes by `dx` and in which the
  // elements took `element_work`, with the model's energies after it: the factor once it can be
  // chosen, and the adaptive reduction. Log lines go to `notes`, a warning (once a step) when
  // ALLSD exceeds the fraction ALLSDTOL (0.05 when 0) of ALLIE to `warnings`.
  void converged(const Eigen::VectorXd& dx, double dt, double element_work,
                 const ModelEnergies& energies, std::vector<std::string>& notes,
                 std::vector<std::string>& warnings);
  // An attempt failed to converge: the adaptive form retries with 2 c.
  void attempt_failed(std::vector<std::string>& notes);

 private:
  double artificial_mass_norm(const Eigen::VectorXd& dx) const;  // dxᵀ M* dx

  std::vector<double> mass_;  // M* per equation (0: a multiplier or a dependent DOF)
  const DependentDofs& dependents_;
  const StaticStabilization* settings_ = nullptr;
  double period_ = 1.0;
  double factor_ = 0.0;
  double base_factor_ = 0.0;  // c of the energy fraction, FACTOR or CONTINUE=YES
  double last_factor_ = 0.0;  // of the last stabilized step (CONTINUE=YES)
  bool warned_ = false;
  Communicator* ranks_ = nullptr;
};

}  // namespace clinch
