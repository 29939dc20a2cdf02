// `clinch check DECK.inp [--format text|json]` (cli-contract.md): parse and validate, solve
// nothing. Exit 0 without errors, 1 with errors, 3 on a usage or I/O error.
#pragma once

#include <string>

namespace clinch {

enum class DiagnosticFormat { Text, Json };

int run_check(const std::string& deck_path, DiagnosticFormat format);

}  // namespace clinch
