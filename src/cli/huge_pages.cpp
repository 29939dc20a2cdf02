#include "src/cli/huge_pages.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace clinch {
namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb=1";
// glibc's heap grows with brk in steps of top_pad (128 kB by default) and madvises each step for
// huge pages, but a step smaller than 2 MB never holds an aligned huge page, so the heap's
// allocations stayed in 4 kB pages (docs/performance.md). Steps of 128 MB of address space (only
// touched pages count) let the kernel back the heap with huge pages.
constexpr const char* kTopPad = "glibc.malloc.top_pad=134217728";

bool transparent_huge_pages_on_request() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.find("[madvise]") != std::string::npos;
}

// Re-executing costs a second start-up (about 10 ms); it pays off only when some input is large.
constexpr off_t kLargeInput = 4 << 20;

bool has_large_input(char** argv) {
  for (char** arg = argv + 1; *arg; ++arg) {
    struct stat info {};
    if (stat(*arg, &info) == 0 && S_ISREG(info.st_mode) && info.st_size >= kLargeInput) {
      return true;
    }
  }
  return false;
}

bool wanted(char** argv) {
  const char* setting = std::getenv("CLINCH_HUGE_PAGES");
  if (setting && std::strcmp(setting, "0") == 0) return false;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return false;  // set, or done
  const char* preload = std::getenv("LD_PRELOAD");
  if (preload && std::strstr(preload, "vgpreload")) return false;  // valgrind
  return has_large_input(argv) && transparent_huge_pages_on_request();
}

}  // namespace

void reexec_with_huge_pages(char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  if (!wanted(argv)) return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string value = tunables && *tunables ? std::string(tunables) + ":" + kTunable : kTunable;
  if (!tunables || !std::strstr(tunables, "glibc.malloc.top_pad"))
    value += std::string(":") + kTopPad;
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  // The program's own path rather than /proc/self/exe, so that the new image keeps its name
  // ("clinch", not "exe") in ps, top and /proc/<pid>/comm.
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
  if (length > 0) {
    path[length] = '\0';
    execv(path, argv);
  }
  execv("/proc/self/exe", argv);
  // Only reached when execv failed: carry on in this process.
#else
  (void)argv;
#endif
}

}  // namespace clinch
