// The parser of *PARAMETER expressions: tokens → tree, by the grammar of input-syntax.md §6.3.
// Names the unsupported Python construct when it meets one (E0407), else reports a syntax error
// (E0401); at most one error per expression.
#pragma once

#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"
#include "parser/expression/lexer.hpp"
#include "parser/expression/tree.hpp"

namespace clinch::expression_detail {

// Parses tokens (of text, located at loc) into nodes; returns the index of the root node, or -1
// after reporting an error into sink.
int parse_expression(std::string_view text, SourceLoc loc, const std::vector<Token>& tokens,
                     DiagnosticSink& sink, std::vector<Node>& nodes);

}  // namespace clinch::expression_detail
