// Running clinch's plotting scripts (matplotlib, Debian's python3-matplotlib): the work-precision
// plot of `clinch study` and the page of `clinch report`. The scripts are installed with the
// binary, in share/clinch next to it (the build tree) or in ../share/clinch (an installed tree).
// The interpreter is $CLINCH_PYTHON when set, else the system's /usr/bin/python3 (where Debian
// installs matplotlib), else python3 on the PATH.
#pragma once

#include <string>
#include <vector>

namespace clinch {

// Runs `python SCRIPT ARGS...` with the script's messages passed through to stderr. Returns
// true when it succeeded; otherwise false with a message in `error` that says what is missing
// (the script, python3, matplotlib) or how the script failed.
bool run_plot_script(const std::string& script, const std::vector<std::string>& args,
                     std::string* error);

}  // namespace clinch
