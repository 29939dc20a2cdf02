#include "src/study/ladder_runner.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <thread>

namespace clinch {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  std::size_t index;
  pid_t pid;
  Clock::time_point start;
};

// Starts `clinch run --quiet` on one setting with stdout and stderr in <out_dir>/run.out. The
// child stops (SIGTERM, which `clinch run` handles cleanly) when the study ends in any way, even
// by SIGKILL, and runs in a process group of its own, so that a Ctrl-C on the terminal reaches it
// once, forwarded by the study, rather than twice.
std::optional<pid_t> spawn_run(const std::string& clinch, const LadderSetting& s,
                               std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(s.out_dir, ec);
  if (ec) {
    *error = fmt::format("cannot create '{}': {}", s.out_dir, ec.message());
    return std::nullopt;
  }
  const std::string out = (std::filesystem::path(s.out_dir) / "run.out").string();
  std::vector<std::string> args = {clinch,    "run",   "--quiet", "--out",
                                   s.out_dir, "--job", s.job,     s.deck};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    *error = fmt::format("cannot write '{}': {}", out, std::strerror(errno));
    return std::nullopt;
  }
  // The stop signals are blocked across fork: a signal forwarded to a child that has not yet
  // reached exec must not run the study's handler in it (and be lost), but kill it.
  sigset_t stop_signals, previous;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  sigprocmask(SIG_BLOCK, &stop_signals, &previous);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    // Only async-signal-safe calls between fork and exec.
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    sigaction(SIGINT, &default_action, nullptr);
    sigaction(SIGTERM, &default_action, nullptr);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the study died before prctl took effect
    setpgid(0, 0);
    if (dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) _exit(127);
    // dup2 onto itself (a study started with stdout closed) keeps close-on-exec: cleared here.
    fcntl(STDOUT_FILENO, F_SETFD, 0);
    fcntl(STDERR_FILENO, F_SETFD, 0);
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const int fork_error = errno;
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  close(fd);
  if (pid < 0) {
    *error = fmt::format("cannot start '{}': {}", clinch, std::strerror(fork_error));
    return std::nullopt;
  }
  return pid;
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return fmt::format("signal {}", signal);
  }
}

}  // namespace

std::string current_executable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("clinch") : self.string();
}

std::vector<SettingOutcome> run_ladder(const std::vector<LadderSetting>& settings,
                                       const LadderOptions& options) {
  std::vector<SettingOutcome> outcomes(settings.size());
  std::vector<Running> running;
  const Clock::time_point study_start = Clock::now();
  std::size_t next = 0;
  bool budget_spent = false;
  auto last_progress = Clock::now() - std::chrono::seconds(1);

  // Whether setting `k` may start now: always without a budget; with one, only once some earlier
  // setting has finished and its cost, grown by cost_ratio per level, fits in what is left.
  const auto may_start = [&](std::size_t k) -> std::optional<bool> {
    if (!options.budget_seconds || k == 0) return true;
    for (std::size_t j = k; j-- > 0;) {
      const SettingOutcome& o = outcomes[j];
      if (o.state == SettingState::Completed || o.state == SettingState::Failed) {
        const double predicted =
            o.wall_seconds * std::pow(options.cost_ratio, static_cast<double>(k - j));
        const double elapsed = std::chrono::duration<double>(Clock::now() - study_start).count();
        return elapsed + predicted <= *options.budget_seconds;
      }
    }
    return std::nullopt;  // nothing measured yet: wait
  };

  int stop_signal = 0;  // the signal that stopped the study, once forwarded
  while (next < settings.size() || !running.empty()) {
    if (stop_signal == 0 && options.stop_signal && (stop_signal = options.stop_signal()) != 0) {
      // Each running child gets the signal once and stops as `clinch run` does; the settings not
      // started are not run.
      for (const Running& r : running) kill(r.pid, stop_signal);
      for (std::size_t k = next; k < settings.size(); ++k) {
        outcomes[k].note = fmt::format("not run: the study was interrupted by {}",
                                       signal_name(stop_signal));
      }
      next = settings.size();
    }
    while (!budget_spent && next < settings.size() &&
           static_cast<int>(running.size()) < std::max(1, options.jobs)) {
      const std::optional<bool> start = may_start(next);
      if (!start) break;
      if (!*start) {
        budget_spent = true;
        break;
      }
      std::string error;
      const std::optional<pid_t> pid = spawn_run(options.clinch, settings[next], &error);
      if (!pid) {
        outcomes[next].state = SettingState::Failed;
        outcomes[next].note = error;
      } else {
        outcomes[next].state = SettingState::Running;
        running.push_back({next, *pid, Clock::now()});
      }
      ++next;
    }
    if (budget_spent) {
      for (std::size_t k = next; k < settings.size(); ++k) {
        outcomes[k].note = fmt::format("not run: the time budget of {} s would be exceeded",
                                       *options.budget_seconds);
      }
      next = settings.size();
    }
    bool changed = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      const pid_t done = waitpid(it->pid, &status, WNOHANG);
      if (done != it->pid) {
        ++it;
        continue;
      }
      SettingOutcome& o = outcomes[it->index];
      o.wall_seconds = std::chrono::duration<double>(Clock::now() - it->start).count();
      if (WIFEXITED(status)) {
        o.exit_code = WEXITSTATUS(status);
        o.state = o.exit_code == 0 ? SettingState::Completed : SettingState::Failed;
      } else {
        o.state = SettingState::Failed;
        o.note = fmt::format("killed by signal {}", WTERMSIG(status));
      }
      it = running.erase(it);
      changed = true;
    }
    if (options.on_progress &&
        (changed || Clock::now() - last_progress > std::chrono::milliseconds(200))) {
      options.on_progress(outcomes);
      last_progress = Clock::now();
    }
    if (!changed && !running.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return outcomes;
}

}  // namespace clinch
