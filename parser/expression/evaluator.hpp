// The evaluator of *PARAMETER expression trees: Python 3 semantics on int, float and str values
// (input-syntax.md §6.3), with 64-bit ints whose overflow is an error (E0406), and the W0403
// warning where Python 2 would have truncated an int division.
#pragma once

#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"
#include "parser/expression.hpp"
#include "parser/expression/tree.hpp"

namespace clinch::expression_detail {

// Evaluates the tree rooted at nodes[root] (parsed from text, located at loc) into out; false
// after reporting an error into sink.
bool evaluate_tree(std::string_view text, SourceLoc loc, const std::vector<Node>& nodes, int root,
                   const ParamLookup& lookup, const ParamDefinedCheck& is_parameter,
                   DiagnosticSink& sink, ParamValue& out);

}  // namespace clinch::expression_detail
