// Transparent huge pages for clinch's large arrays (docs/performance.md). A large deck touches
// hundreds of megabytes once, page by page: the deck's text, the model, the analysis plan and
// CHOLMOD's factor. Where the kernel gives huge pages only on request (THP mode "madvise",
// Debian's default), glibc's malloc requests them when the tunable glibc.malloc.hugetlb=1 is set,
// which cuts the page faults of such a run by two orders of magnitude. glibc reads its tunables
// at start-up, so clinch executes itself once more with the tunable added to GLIBC_TUNABLES.
#pragma once

namespace clinch {

// Re-executes the program with glibc.malloc.hugetlb=1 when that helps: Linux with THP in
// "madvise" mode, an argument that names a file of 4 MiB or more (the deck; a second start-up
// costs more than a small deck gains), the tunable not already set, CLINCH_HUGE_PAGES not "0",
// and not under valgrind (whose tools would lose the process). Returns (and the run goes on unchanged) when any
// of that does not hold or the re-execution fails.
void reexec_with_huge_pages(char** argv);

}  // namespace clinch
