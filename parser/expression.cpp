// The pipeline of one *PARAMETER expression: lexer (parser/expression/lexer.*), parser
// (parser/expression/parser.*), evaluator (parser/expression/evaluator.*). Evaluation starts only
// once the whole text has parsed, so a syntax error is always reported before any evaluation
// error, as Python compiles before it runs.
#include "parser/expression.hpp"

#include <vector>

#include "parser/expression/evaluator.hpp"
#include "parser/expression/lexer.hpp"
#include "parser/expression/parser.hpp"
#include "parser/expression/tree.hpp"

namespace clinch {

using expression_detail::evaluate_tree;
using expression_detail::lex_expression;
using expression_detail::Node;
using expression_detail::parse_expression;
using expression_detail::Token;

std::optional<ParamValue> evaluate_expression(std::string_view text, SourceLoc text_loc,
                                              const ParamLookup& lookup, DiagnosticSink& sink,
                                              const ParamDefinedCheck& is_parameter) {
  // Offsets are stored as 32-bit columns; a longer text is cut there (its tail is reported as
  // a syntax error rather than mis-located).
  constexpr std::size_t kMaxText = 0x7fffffffu;
  if (text.size() > kMaxText) {
    sink.report(DiagCode::expression_syntax, text_loc.shifted(0), "expression is too long");
    return std::nullopt;
  }
  try {
    const std::vector<Token> tokens = lex_expression(text);
    std::vector<Node> nodes;
    const int root = parse_expression(text, text_loc, tokens, sink, nodes);
    if (root < 0) return std::nullopt;
    ParamValue value;
    if (!evaluate_tree(text, text_loc, nodes, root, lookup, is_parameter, sink, value)) {
      return std::nullopt;
    }
    return value;
  } catch (...) {
    // Only allocation failure can get here (a lookup callback that throws is the caller's bug,
    // but it must not escape either). Report it as an error on the expression.
    sink.report(DiagCode::expression_syntax, text_loc, "expression could not be evaluated");
    return std::nullopt;
  }
}

}  // namespace clinch
