// The deck reader: drives the lexer over the deck and its *INCLUDE / INPUT= files, evaluates the
// *PARAMETER pre-pass (input-syntax.md §6.4), checks where each keyword may stand (§7–§8),
// validates keyword parameters against their specs (§2), substitutes <name> fields (§3.3) and
// hands each block to its keyword handler. The result is a Model plus diagnostics.
#pragma once

#include <string>

#include "base/diagnostic.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

enum class ReadStatus { Ok, IoError };

// Reads a deck file into `model` (a path, or "-" for standard input: SourceManager::load_deck).
// IoError means the deck itself could not be opened or read, or a read of it or of a file it
// includes failed part-way (exit 3; `io_error` names the file); every other problem is a
// diagnostic in `sink`. Runs whole-model validation too.
ReadStatus read_deck_file(const std::string& path, SourceManager& sources, Model& model,
                          DiagnosticSink& sink, std::string* io_error);
// The same for in-memory text (tests, fuzzers). `display_name` is used in diagnostics and to
// resolve relative includes.
void read_deck_text(const std::string& display_name, std::string text, SourceManager& sources,
                    Model& model, DiagnosticSink& sink);

}  // namespace clinch
