// The syntax tree of a *PARAMETER expression, as the parser builds it and the evaluator walks it.
// Nodes live in one vector and refer to each other by index; additive and multiplicative runs are
// kept as one n-ary Chain node each, so that a long `1+1+...+1` does not make a deep tree.
// Names are views into the expression text, which outlives the tree.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parser/expression.hpp"

namespace clinch::expression_detail {

enum class NodeKind { Literal, Name, Call, Negate, Plus, Chain, Power };
enum class BinOp { Add, Sub, Mul, Div, FloorDiv, Mod };

struct OpAt {
  BinOp op;
  std::uint32_t pos;
};

struct Node {
  NodeKind kind = NodeKind::Literal;
  std::uint32_t begin = 0;  // source span [begin, end)
  std::uint32_t end = 0;
  std::uint32_t pos = 0;  // operator, name or literal position (where diagnostics point)
  ParamValue value;       // Literal
  std::string overflow;   // Literal that does not fit (E0406 when evaluated)
  bool digits_only = false;
  std::string_view name;  // Name, Call
  std::vector<int> kids;  // Call: arguments; Chain: operands; Negate/Plus: 1; Power: 2
  std::vector<OpAt> ops;  // Chain: ops[i] joins the result so far with kids[i + 1]
};

}  // namespace clinch::expression_detail
