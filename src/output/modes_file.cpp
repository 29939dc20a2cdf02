#include "src/output/modes_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace clinch {

double circular_frequency(double eigenvalue) { return eigenvalue > 0 ? std::sqrt(eigenvalue) : 0.0; }

bool ModesFile::write_step(int step, const std::vector<ModeRecord>& modes,
                           const std::vector<std::string>& dof_names) {
  std::string text;
  if (!opened_) {
    opened_ = true;
    if (!file_.open(path_, &open_error_)) return false;
    text = "step,mode,eigenvalue,frequency_rad,frequency_cycles,generalized_mass";
    for (const std::string& name : dof_names) {
      if (!name.empty()) text += "," + name;
    }
    text += "\n";
  }
  if (!file_.is_open()) return false;
  for (const ModeRecord& m : modes) {
    const double omega = circular_frequency(m.eigenvalue);
    // fmt's shortest form that reads back to the same double, as in the history table.
    text += fmt::format("{},{},{},{},{},{}", step, m.mode, m.eigenvalue, omega,
                        omega / (2.0 * std::numbers::pi), m.generalized_mass);
    for (std::size_t i = 0; i < dof_names.size(); ++i) {
      if (!dof_names[i].empty()) text += fmt::format(",{}", m.shape[static_cast<Eigen::Index>(i)]);
    }
    text += "\n";
  }
  return file_.write(text);
}

}  // namespace clinch
