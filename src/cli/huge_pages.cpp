#include "src/cli/huge_pages.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
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
// glibc gives each block of 32 MB or more a mapping of its own and unmaps it when freed, so a
// vector that grows by doubling, or a workspace allocated per phase, is zeroed by the kernel
// again each time: at 10⁶ connectors that was 9 s of kernel time in a 17 s run
// (docs/performance.md). Every block from the heap, and a heap that is never trimmed, reuse the
// freed memory; the peak stays the same.
constexpr const char* kHeapOnly = "glibc.malloc.mmap_max=0";
constexpr const char* kNoTrim = "glibc.malloc.trim_threshold=1099511627776";

bool transparent_huge_pages_on_request() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.find("[madvise]") != std::string::npos;
}

// Re-executing costs a second start-up (about 5 ms); it pays off only when some input is large:
// for `clinch check` a deck of 4 MiB, for `clinch run`, which builds and factorizes far more
// than the deck, one of 128 KiB (the AXIAL lattice of 10³ nodes, 178 kB: 0.21–0.23 s →
// 0.13–0.19 s, docs/performance.md).
constexpr off_t kLargeInput = 4 << 20;
constexpr off_t kLargeInputToRun = 128 << 10;
// Below this the heap grows by less than one huge page, which would only round its size up.
constexpr off_t kMediumInput = 256 << 10;
constexpr std::size_t kHugePage = 2 << 20;

// The size of the largest regular file among the arguments (0 if none).
off_t largest_input(char** argv) {
  off_t largest = 0;
  for (char** arg = argv + 1; *arg; ++arg) {
    struct stat info {};
    if (stat(*arg, &info) == 0 && S_ISREG(info.st_mode)) largest = std::max(largest, info.st_size);
  }
  return largest;
}

// The subcommand: the first argument that is not an option.
bool runs_an_analysis(char** argv) {
  for (char** arg = argv + 1; *arg; ++arg) {
    if (**arg != '-') return std::strcmp(*arg, "run") == 0;
  }
  return false;
}

bool allowed() {
  const char* setting = std::getenv("CLINCH_HUGE_PAGES");
  if (setting && std::strcmp(setting, "0") == 0) return false;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return false;  // set, or done
  const char* preload = std::getenv("LD_PRELOAD");
  if (preload && std::strstr(preload, "vgpreload")) return false;  // valgrind
  return transparent_huge_pages_on_request();
}

// For a medium input, in this process: one brk step of the heap large enough for what the input
// becomes (a `clinch check` needs about twice the deck, docs/performance.md), advised for huge
// pages, with arrays up to 32 MB allocated from it rather than mapped on their own, and kept
// rather than trimmed. The heap below the first 2 MB boundary cannot hold a huge page: a block
// that is never freed (and never touched beyond its header) moves the allocations up to it. It
// ends a page short of the boundary, so that malloc's header of the free rest lies below it too:
// a 4 kB page touched in a 2 MB range before the advice keeps the whole range in 4 kB pages.
void reserve_huge_page_heap(std::size_t input_size) {
  static void* below_boundary = nullptr;
  if (below_boundary) return;
  const std::size_t reserve = (4 * input_size + 2 * kHugePage) & ~(kHugePage - 1);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(reserve));
  mallopt(M_TOP_PAD, static_cast<int>(reserve));
  // The free top of the heap, where the next large block is cut: from the break down by its size.
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0)) - mallinfo2().keepcost;
  const auto boundary = (top + 2 * 4096 + kHugePage - 1) & ~(kHugePage - 1);
  // Extends the heap by the pad (the request is larger than the top chunk after start-up).
  below_boundary = std::malloc(boundary - top - 4096);
  mallopt(M_TOP_PAD, 128 << 10);  // later steps as glibc makes them
  if (!below_boundary) return;
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
  if (end > boundary) madvise(reinterpret_cast<void*>(boundary), end - boundary, MADV_HUGEPAGE);
}

}  // namespace

void use_huge_pages(char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  if (!allowed()) return;
  const off_t input = largest_input(argv);
  const bool run = runs_an_analysis(argv);
  if (run && input < kLargeInputToRun) return;
  if (!run && input < kMediumInput) return;
  if (!run && input < kLargeInput) {
    reserve_huge_page_heap(static_cast<std::size_t>(input));
    return;
  }
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string value = tunables && *tunables ? std::string(tunables) + ":" + kTunable : kTunable;
  // The user's own settings of these win.
  for (const char* tunable : {kTopPad, kHeapOnly, kNoTrim}) {
    const std::string name(tunable, std::strchr(tunable, '='));
    if (!tunables || !std::strstr(tunables, name.c_str())) value += std::string(":") + tunable;
  }
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
