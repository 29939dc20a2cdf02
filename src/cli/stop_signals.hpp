// SIGINT and SIGTERM during `clinch run`: instead of dying mid-write, the run stops cleanly after
// reading the deck, after planning, or before the next factorization or increment attempt, so
// that the history keeps every converged increment and the status file says where the run was
// interrupted (exit 2, cli-contract.md). A second signal of the same kind kills at once, for a run
// that does not get there. `clinch study` forwards them to its runs in the same way
// (docs/study-and-report.md).
#pragma once

namespace clinch {

// Installs the handlers for SIGINT and SIGTERM.
void catch_stop_signals();

// The name of the signal that asked the run to stop ("SIGINT" or "SIGTERM"), or nullptr.
const char* stop_signal_name();

// Its number, or 0.
int stop_signal_number();

// Gives SIGINT and SIGTERM their default effect again, for what follows the part of a command
// that stops cleanly.
void release_stop_signals();

}  // namespace clinch
