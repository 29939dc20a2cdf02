#include "src/cli/standard_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace clinch {

bool standard_output_written() {
  // A stream that failed earlier has lost errno since; one that fails on this flush still has it.
  const bool failed_before = !std::cout.good();
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int code = errno;
  if (!failed_before && std::cout.good() && flushed && !std::ferror(stdout)) return true;
  std::string reason;
  if (!failed_before && code != 0) reason = std::string(": ") + std::strerror(code);
  std::cerr << "clinch: error: cannot write to standard output" << reason << "\n";
  return false;
}

}  // namespace clinch
