#include "src/report/plot_script.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include "src/study/ladder_runner.hpp"

extern char** environ;

namespace clinch {
namespace {

namespace fs = std::filesystem;

// The scripts exit with this status when matplotlib cannot be imported, so that another
// interpreter can be tried.
constexpr int kNoMatplotlib = 4;

std::optional<fs::path> find_script(const std::string& script) {
  const fs::path dir = fs::path(current_executable()).parent_path();
  for (const fs::path& candidate :
       {dir / "share" / "clinch" / script, dir / ".." / "share" / "clinch" / script}) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal();
  }
  return std::nullopt;
}

std::vector<std::string> interpreters() {
  if (const char* chosen = std::getenv("CLINCH_PYTHON"); chosen != nullptr && *chosen != '\0') {
    return {chosen};
  }
  std::vector<std::string> list;
  std::error_code ec;
  if (fs::exists("/usr/bin/python3", ec)) list.push_back("/usr/bin/python3");
  list.push_back("python3");
  return list;
}

// Runs the interpreter; returns its exit status, -1 when it could not be started (errno-style
// reason in `why`), or 128 + signal.
int spawn_python(const std::string& python, const std::vector<std::string>& args,
                 std::string* why) {
  std::vector<std::string> all = args;
  all.insert(all.begin(), python);
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
  if (rc != 0) {
    *why = std::strerror(rc);
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + WTERMSIG(status);
}

}  // namespace

bool run_plot_script(const std::string& script, const std::vector<std::string>& args,
                     std::string* error) {
  const std::optional<fs::path> path = find_script(script);
  if (!path) {
    *error = fmt::format(
        "the plotting script '{}' is not installed next to clinch (looked in "
        "share/clinch and ../share/clinch beside {})",
        script, current_executable());
    return false;
  }
  std::vector<std::string> full = args;
  full.insert(full.begin(), path->string());
  std::vector<std::string> tried;
  for (const std::string& python : interpreters()) {
    std::string why;
    const int status = spawn_python(python, full, &why);
    if (status == 0) return true;
    if (status == -1) {
      tried.push_back(fmt::format("{} ({})", python, why));
      continue;
    }
    if (status == kNoMatplotlib) {
      tried.push_back(fmt::format("{} (no matplotlib)", python));
      continue;
    }
    *error = fmt::format("{} {} failed with status {}", python, path->string(), status);
    return false;
  }
  *error = fmt::format(
      "cannot plot: python3 with matplotlib is needed (Debian: apt-get install "
      "python3-matplotlib; or set CLINCH_PYTHON); tried {}",
      fmt::join(tried, ", "));
  return false;
}

}  // namespace clinch
