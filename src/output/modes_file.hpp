// The mode shapes of the *FREQUENCY steps, `<job>.modes.csv` beside the history
// (docs/cli-contract.md "The modes file"): one row per mode, with its step, number, eigenvalue,
// frequencies and generalized mass, then one column per active nodal DOF ("U1@5", "UR3@7") with
// the mode's component there (0 at a held DOF). Created at the first frequency step, so that a
// run without one writes no such file; rows reach the kernel as they are written.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/output/output_file.hpp"

namespace clinch {

// One extracted mode (frequency_step.hpp): λ = ω², the generalized mass φᵀMφ and φ over the
// solved equations, normalized as the step asks.
struct ModeRecord {
  int mode = 0;
  double eigenvalue = 0;
  double generalized_mass = 0;
  Eigen::VectorXd shape;
};

class ModesFile {
 public:
  explicit ModesFile(std::string path) : path_(std::move(path)) {}

  // The rows of step `step`; `dof_names` names each solved equation (empty: a multiplier, which
  // has no column). False when the file could not be created or written (file().error()).
  bool write_step(int step, const std::vector<ModeRecord>& modes,
                  const std::vector<std::string>& dof_names);
  // "cannot write 'PATH': REASON" of the first failure; empty while none.
  const std::string& error() const { return open_error_.empty() ? file_.error() : open_error_; }

 private:
  std::string path_;
  OutputFile file_;
  bool opened_ = false;
  std::string open_error_;
};

// ω = √λ in rad/time (0 for a negative λ: an unstable base state has no frequency there).
double circular_frequency(double eigenvalue);

}  // namespace clinch
