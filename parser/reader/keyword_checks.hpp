// Checks of a keyword line against the keyword specs (input-syntax.md §2): an unknown keyword with
// what it may have meant, and the generic checks of its parameters (names, abbreviations,
// duplicates, values).
#pragma once

#include "base/diagnostic.hpp"
#include "parser/block_context.hpp"
#include "parser/keyword_registry.hpp"
#include "parser/keyword_spec.hpp"
#include "parser/lexer.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

// Reports an unknown keyword with what it may have meant; returns the spec of that keyword (the
// one it abbreviates or the closest name), null when there is none.
const KeywordSpec* report_unknown_keyword(const KeywordLine& line,
                                          const KeywordRegistry& registry, DiagnosticSink& sink);

// Fills `out` with the parameters of `line` that pass; true when none was refused. The model,
// position and sources are those an enumerated value is read with (BlockContext::word).
bool validate_params(const KeywordSpec& spec, const KeywordLine& line, ParamSet& out, Model& model,
                     const ReaderPosition& position, DiagnosticSink& sink,
                     const SourceManager& sources);

}  // namespace clinch
