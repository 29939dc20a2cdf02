// What Newton and the step driver see (ARCHITECTURE.md "Key interfaces"). Newton: a residual and
// a tangent with a fixed sparsity pattern, a way to apply a correction, and the norms the
// convergence criteria of *CONTROLS need. The step driver, between solves: commit or revert the
// trial state, settle the active set, the end-of-increment events, and what the laws asked for.
// The state (displacements, rotations, multipliers, trial history) lives inside the problem
// because rotations are updated multiplicatively under NLGEOM.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

struct EvalStatus {
  bool ok = true;
  std::string message;  // why an element could not be evaluated (names the element)
};

// The force entries whose mean is q̃, the spatial average force of keywords.md §16 field 1 (per
// field: 0 = forces, 1 = moments). As Abaqus's spatial average flux, q̃ averages the magnitudes
// of the entries, not of their sums at the nodes: each element's contribution at each of its
// nodal DOFs, each nonzero component force of a connector (CEF, CVF, CSF, CRF: the multipliers
// of its constraints and motions, CCF: its connector load) and each applied nodal load. Forces
// that cancel at a node (a bolt preloaded against its clamped plates, a connector motion against
// a spring in parallel, a self-equilibrated frame whose reactions cancel) still count, so that
// q̃ has the size of the forces the model carries rather than of the round-off of their sum.
// Reactions are not entries of their own: they are the elements' entries at the held DOFs.
struct ForceEntries {
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  void add(int field, double magnitude) {
    if (!(magnitude > 0)) return;
    sum[field] += magnitude;
    ++count[field];
  }
  double mean(int field) const { return count[field] ? sum[field] / count[field] : 0.0; }
};

// Per-field measures of one iteration (keywords.md §16): index 0 = translations and forces,
// 1 = rotations and moments.
struct IterationNorms {
  double largest_residual[2] = {0, 0};    // r_max over free DOFs of the field
  double flux[2] = {0, 0};                // q̃: the mean of the field's ForceEntries
  double largest_correction[2] = {0, 0};  // c_max of the last correction
  double largest_increment[2] = {0, 0};   // largest change of the solution in the increment
  // Corrections up to this size are round-off (1e-12·L̄ for translations, 1e-12 rad for
  // rotations) and pass the correction tests, so that a field that does not move in the
  // increment is not held by corrections of 1e-16 against an increment of 0.
  double resolution[2] = {0, 0};
  // Forces up to this size are round-off: 1e-12 of the larger of the force flux and the moment
  // flux over L̄ (times L̄ for moments). A field whose flux is no more than this carries no force
  // (a moment of 3e-14 beside forces of 90 is not a moment field to converge on).
  double force_resolution[2] = {0, 0};
  double residual_norm = 0;  // Euclidean norm over all free equations (log)
  double correction_norm = 0;
  double constraint_violation = 0;  // max |g| / its tolerance (≤ 1 passes)
};

// What the laws asked of the time step: the smallest ratio any law suggested (infinity when none
// did), whether some result was unreliable, and the message of the law that set the ratio.
struct StepRequest {
  double dt_ratio = std::numeric_limits<double>::infinity();
  bool unreliable = false;
  std::string message;
  // Conditions of the converged state that the log reports once per element and step.
  struct Warning {
    std::size_t element = 0;
    std::string message;
  };
  std::vector<Warning> warnings;
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  virtual int size() const = 0;
  virtual const SparseMatrix& pattern() const = 0;
  // Residual F_int − F_ext (and constraint residuals) at the current state; the tangent's values
  // into `tangent` (pattern of pattern()) when non-null.
  virtual EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) = 0;
  // Adds a Newton correction (rotations: R ← exp(Δθ̂) R under NLGEOM).
  virtual void apply_correction(const Eigen::VectorXd& correction) = 0;
  // True while prescribed values are short of their targets: the next correction is the linear
  // predictor that takes them there, so the state cannot have converged and a line search does
  // not apply to that correction.
  virtual bool moving_prescribed() const { return false; }
  // Fills the residual and constraint parts of `norms`; the correction parts when `correction`
  // is non-null.
  virtual void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
                       IterationNorms& norms) const = 0;
  // A problem shared by rows between processes (docs/parallel.md "Vectors by rows"): its
  // vectors hold the entries of this process's rows, the first owned_size() of them, then ghost
  // entries that copy other processes' rows. What Newton and the line search sum or compare over
  // the entries is taken over the owned entries of every process through these, and an equation
  // Newton names is given by its global number. One process: as given.
  virtual int owned_size() const { return size(); }
  virtual double sum_over_ranks(double mine) const { return mine; }
  virtual double max_over_ranks(double mine) const { return mine; }
  virtual int global_equation(int equation) const { return equation; }
  // How much a change of each equation counts as motion in the arc length of a Riks step
  // (docs/riks.md): 1 for every equation unless the problem knows its fields.
  virtual void path_weights(Eigen::VectorXd& weights) const { weights.setOnes(size()); }
  // The damage of the laws at the current state against the converged one: whether any law is
  // damaged, and whether any damage grows (a Riks step tells the softening branch from the
  // elastic unloading one by it: docs/riks.md).
  struct DamageChange {
    bool damaged = false, growing = false;
  };
  virtual DamageChange damage_change() const { return {}; }
};

}  // namespace clinch
