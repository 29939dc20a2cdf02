// The reader's first pass over a deck (input-syntax.md §6.4): it collects the *PARAMETER definition
// lines, including those read through INPUT=, so that they can be evaluated before any field is
// substituted, and notes whether the deck uses parts and an assembly (§7.1). It follows *INCLUDE
// but reports nothing of the deck's own faults: the second pass does.
#pragma once

#include <cstdint>

#include "base/diagnostic.hpp"
#include "parser/parameters.hpp"
#include "parser/reader/deck_files.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

void run_prepass(std::uint32_t main_file, SourceManager& sources, DeckFiles& files,
                 ParameterTable& parameters, Model& model, DiagnosticSink& sink);

}  // namespace clinch
