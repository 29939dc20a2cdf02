// What a command prints on standard output (the JSON of `check`, the verdicts of `compare`, the
// table of `study`, the summary of `run`) is its result: when it cannot be written (a full disk,
// /dev/full), the command must not exit as if it had been.
#pragma once

namespace clinch {

// Flushes standard output. When something printed on it was not written, says so on stderr and
// returns false: the command then exits with the I/O error status 3 (cli-contract.md).
bool standard_output_written();

}  // namespace clinch
