// Transparent huge pages for clinch's large arrays (docs/performance.md). A large deck touches
// hundreds of megabytes once, page by page: the deck's text, the model, the analysis plan and
// CHOLMOD's factor. Where the kernel gives huge pages only on request (THP mode "madvise",
// Debian's default), glibc's malloc requests them when the tunable glibc.malloc.hugetlb=1 is set,
// which cuts the page faults of such a run by two orders of magnitude. glibc reads its tunables
// at start-up, so clinch executes itself once more with the tunable added to GLIBC_TUNABLES; for a
// medium deck, where that second start-up would cost more than it saves, clinch reserves a heap in
// huge pages itself.
#pragma once

namespace clinch {

// On Linux with THP in "madvise" mode, the tunable not already set, CLINCH_HUGE_PAGES not "0" and
// not under valgrind (whose tools would lose the process), by the largest file among the
// arguments (the deck):
// - 4 MiB or more (128 KiB or more for `clinch run`): re-executes the program with
//   glibc.malloc.hugetlb=1 (a second start-up costs more than a smaller deck gains); returns only
//   if that fails;
// - other subcommands, 256 KiB to 4 MiB: reserves a heap in huge pages in this process (malloc
//   options and madvise);
// - smaller: nothing (its heap grows by less than one huge page).
void use_huge_pages(char** argv);

}  // namespace clinch
