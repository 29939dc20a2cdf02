// Rendering of diagnostics for people and tools: the gcc-style text with the source line and a
// caret, and the JSON array of cli-contract.md. Rendering needs the deck's text, so it lives with
// the source manager; the diagnostics themselves are in base/.
#pragma once

#include <string>
#include <vector>

#include "base/diagnostic.hpp"

namespace clinch {

class SourceManager;

// gcc-style text: FILE:LINE:COL: error: MESSAGE [name], the source line and a caret under the
// start of the location, '~' under the rest of its span (^~~~), then notes, then one
// "included from" note per include level (input-syntax.md §5.1).
std::string render_text(const Diagnostic& diagnostic, const SourceManager& sources);
// The JSON array of cli-contract.md: file, line, column, severity, code, name, message, notes;
// clinch adds end_column, the last column of the span (= column for a point), as gcc's JSON does.
std::string render_json(const std::vector<Diagnostic>& diagnostics, const SourceManager& sources);

}  // namespace clinch
