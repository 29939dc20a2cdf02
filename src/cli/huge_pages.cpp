#include "src/cli/huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace clinch {
namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb=1";

bool transparent_huge_pages_on_request() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.find("[madvise]") != std::string::npos;
}

bool wanted() {
  const char* setting = std::getenv("CLINCH_HUGE_PAGES");
  if (setting && std::strcmp(setting, "0") == 0) return false;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return false;  // set, or done
  const char* preload = std::getenv("LD_PRELOAD");
  if (preload && std::strstr(preload, "vgpreload")) return false;  // valgrind
  return transparent_huge_pages_on_request();
}

}  // namespace

void reexec_with_huge_pages(char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  if (!wanted()) return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string value =
      tunables && *tunables ? std::string(tunables) + ":" + kTunable : std::string(kTunable);
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Only reached when execv failed: carry on in this process.
#else
  (void)argv;
#endif
}

}  // namespace clinch
