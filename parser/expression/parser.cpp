#include "parser/expression/parser.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <utility>

namespace clinch::expression_detail {

namespace {

// Python itself stops at 200 nested parentheses; the same cap keeps recursion (parse and
// evaluation) far from any stack limit whatever the input.
constexpr int kMaxDepth = 200;

class Parser {
 public:
  Parser(std::string_view text, SourceLoc loc, const std::vector<Token>& tokens,
         DiagnosticSink& sink)
      : text_(text), loc_(loc), toks_(tokens), sink_(sink) {}

  // Returns the root node, or -1 after reporting an error.
  int parse() {
    const int root = parse_expr();
    if (root < 0) return -1;
    if (cur().kind == Tok::End) return root;
    return unexpected_after_operand("an operator or the end of the expression");
  }

  std::vector<Node>& nodes() { return nodes_; }

 private:
  const Token& cur() const { return toks_[k_]; }
  void advance() {
    if (toks_[k_].kind != Tok::End) ++k_;
  }
  bool is_op(std::string_view op) const { return cur().kind == Tok::Op && tok_text(cur()) == op; }
  bool is_name(std::string_view name) const {
    return cur().kind == Tok::Name && tok_text(cur()) == name;
  }
  std::string_view tok_text(const Token& t) const { return text_.substr(t.pos, t.len); }
  // The token as quoted in a message (long tokens are shortened).
  std::string shown(const Token& t) const {
    std::string_view s = tok_text(t);
    if (s.size() > 24) return std::string(s.substr(0, 21)) + "...";
    return std::string(s);
  }

  int fail(DiagCode code, std::uint32_t pos, std::string message) {
    sink_.report(code, loc_.shifted(pos), std::move(message));
    return -1;
  }

  int add(Node node) {
    nodes_.push_back(std::move(node));
    return static_cast<int>(nodes_.size() - 1);
  }

  int parse_expr() { return parse_chain(/*additive=*/true); }

  int parse_chain(bool additive) {
    const int first = additive ? parse_chain(false) : parse_unary();
    if (first < 0) return -1;
    Node chain;
    chain.kind = NodeKind::Chain;
    chain.kids.push_back(first);
    for (;;) {
      std::optional<BinOp> op;
      if (cur().kind == Tok::Op) {
        const std::string_view t = tok_text(cur());
        if (additive) {
          if (t == "+") op = BinOp::Add;
          if (t == "-") op = BinOp::Sub;
        } else {
          if (t == "*") op = BinOp::Mul;
          if (t == "/") op = BinOp::Div;
          if (t == "//") op = BinOp::FloorDiv;
          if (t == "%") op = BinOp::Mod;
        }
      }
      if (!op) break;
      chain.ops.push_back({*op, cur().pos});
      advance();
      const int next = additive ? parse_chain(false) : parse_unary();
      if (next < 0) return -1;
      chain.kids.push_back(next);
    }
    if (chain.kids.size() == 1) return first;
    chain.begin = nodes_[static_cast<std::size_t>(chain.kids.front())].begin;
    chain.end = nodes_[static_cast<std::size_t>(chain.kids.back())].end;
    chain.pos = chain.ops.front().pos;
    return add(std::move(chain));
  }

  int parse_unary() {
    // Every recursive path (parentheses, arguments, prefix operators, '**') passes through here.
    struct DepthGuard {
      int& depth;
      explicit DepthGuard(int& d) : depth(d) { ++depth; }
      ~DepthGuard() { --depth; }
    } guard(depth_);
    if (depth_ > kMaxDepth) {
      return fail(DiagCode::expression_syntax, cur().pos,
                  fmt::format("expression is nested too deeply (more than {} levels)", kMaxDepth));
    }
    if (is_op("-") || is_op("+")) {
      Node node;
      node.kind = is_op("-") ? NodeKind::Negate : NodeKind::Plus;
      node.pos = node.begin = cur().pos;
      advance();
      const int operand = parse_unary();
      if (operand < 0) return -1;
      node.kids.push_back(operand);
      node.end = nodes_[static_cast<std::size_t>(operand)].end;
      return add(std::move(node));
    }
    if (is_op("~")) {
      return fail(DiagCode::unsupported_expression, cur().pos,
                  "bitwise operators are not supported in parameter expressions");
    }
    if (is_name("not")) {
      return fail(DiagCode::unsupported_expression, cur().pos,
                  "boolean operators ('and', 'or', 'not') are not supported in parameter "
                  "expressions");
    }
    return parse_power();
  }

  // power := primary ('**' unary)?  (right-associative; binds tighter than a unary minus on its
  // left: -2**2 == -4, 2**-1 == 0.5, 2**3**2 == 512)
  int parse_power() {
    const int base = parse_primary();
    if (base < 0) return -1;
    if (!is_op("**")) return base;
    Node node;
    node.kind = NodeKind::Power;
    node.pos = cur().pos;
    advance();
    const int exponent = parse_unary();
    if (exponent < 0) return -1;
    node.kids = {base, exponent};
    node.begin = nodes_[static_cast<std::size_t>(base)].begin;
    node.end = nodes_[static_cast<std::size_t>(exponent)].end;
    return add(std::move(node));
  }

  int parse_primary() {
    const Token& t = cur();
    int result = -1;
    switch (t.kind) {
      case Tok::Number: {
        Node node;
        node.kind = NodeKind::Literal;
        node.pos = node.begin = t.pos;
        node.end = t.pos + t.len;
        node.value = t.value;
        node.overflow = t.overflow;
        node.digits_only = t.digits_only;
        advance();
        result = add(std::move(node));
        break;
      }
      case Tok::String: {
        // Adjacent string literals are one string, as in Python ('a' "b" == 'ab').
        Node node;
        node.kind = NodeKind::Literal;
        node.pos = node.begin = t.pos;
        node.value = ParamValue::make_string({});
        while (cur().kind == Tok::String) {
          node.value.s += cur().value.s;
          node.end = cur().pos + cur().len;
          advance();
        }
        result = add(std::move(node));
        break;
      }
      case Tok::Name: {
        const std::string_view name = tok_text(t);
        if (is_python_keyword(name)) return keyword_as_operand(t);
        Node node;
        node.pos = node.begin = t.pos;
        node.end = t.pos + t.len;
        node.name = name;
        advance();
        if (is_op("(")) {
          node.kind = NodeKind::Call;
          if (!parse_arguments(node)) return -1;
        } else {
          node.kind = NodeKind::Name;
        }
        result = add(std::move(node));
        break;
      }
      case Tok::Op: {
        const std::string_view op = tok_text(t);
        if (op == "(") {
          const std::uint32_t open = t.pos;
          open_parens_.push_back(open);
          advance();
          if (is_op(")")) {
            return fail(DiagCode::unsupported_expression, open,
                        "tuples are not supported in parameter expressions");
          }
          const int inner = parse_expr();
          if (inner < 0) return -1;
          if (!is_op(")")) return unexpected_after_operand("')'");
          open_parens_.pop_back();
          // The span includes the parentheses (used to quote operands in W0403).
          nodes_[static_cast<std::size_t>(inner)].begin = open;
          nodes_[static_cast<std::size_t>(inner)].end = cur().pos + 1;
          advance();
          result = inner;
          break;
        }
        if (op == "[") {
          return fail(DiagCode::unsupported_expression, t.pos,
                      "lists are not supported in parameter expressions");
        }
        if (op == "{") {
          return fail(DiagCode::unsupported_expression, t.pos,
                      "dictionaries and sets are not supported in parameter expressions");
        }
        return missing_operand();
      }
      case Tok::Error:
        return fail(t.code, t.pos, t.message);
      case Tok::End:
        return missing_operand();
    }
    // Trailers: a call of anything but a function name, attribute access and indexing.
    for (;;) {
      if (is_op("(")) {
        return fail(DiagCode::unsupported_expression, cur().pos,
                    "only built-in functions can be called in parameter expressions");
      }
      if (is_op(".")) return attribute_access(result);
      if (is_op("[")) {
        return fail(DiagCode::unsupported_expression, cur().pos,
                    "indexing is not supported in parameter expressions");
      }
      break;
    }
    return result;
  }

  // '(' [expr (',' expr)* [',']] ')' after a function name.
  bool parse_arguments(Node& call) {
    open_parens_.push_back(cur().pos);
    advance();
    for (;;) {
      if (is_op(")")) break;
      if (cur().kind == Tok::Name && k_ + 1 < toks_.size() && toks_[k_ + 1].kind == Tok::Op &&
          tok_text(toks_[k_ + 1]) == "=") {
        fail(DiagCode::unsupported_expression, cur().pos,
             "keyword arguments are not supported in parameter expressions");
        return false;
      }
      if (is_op("*") || is_op("**")) {
        fail(DiagCode::unsupported_expression, cur().pos,
             "argument unpacking is not supported in parameter expressions");
        return false;
      }
      const int arg = parse_expr();
      if (arg < 0) return false;
      call.kids.push_back(arg);
      if (is_op(",")) {
        advance();
        continue;
      }
      if (is_op(")")) break;
      unexpected_after_operand(fmt::format("',' or ')' in the arguments of '{}'", call.name));
      return false;
    }
    open_parens_.pop_back();
    call.end = cur().pos + 1;
    advance();
    return true;
  }

  int attribute_access(int object) {
    const std::uint32_t dot = cur().pos;
    const Node& obj = nodes_[static_cast<std::size_t>(object)];
    if (obj.kind == NodeKind::Name && k_ + 1 < toks_.size() && toks_[k_ + 1].kind == Tok::Name) {
      const std::string_view attr = tok_text(toks_[k_ + 1]);
      if (obj.name == "math" && (is_builtin_function(attr) || is_builtin_constant(attr))) {
        return fail(DiagCode::unsupported_expression, dot,
                    fmt::format("attribute access ('math.{0}') is not supported in parameter "
                                "expressions; write {0}",
                                attr));
      }
    }
    return fail(DiagCode::unsupported_expression, dot,
                "attribute access is not supported in parameter expressions");
  }

  int keyword_as_operand(const Token& t) {
    const std::string_view word = tok_text(t);
    if (word == "lambda") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "lambda expressions are not supported in parameter expressions");
    }
    if (word == "True" || word == "False") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  fmt::format("booleans ('{}') are not supported in parameter expressions", word));
    }
    if (word == "None") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "'None' is not supported in parameter expressions");
    }
    if (word == "import" || word == "from") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "'import' is not supported in parameter expressions");
    }
    if (word == "yield" || word == "await") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  fmt::format("'{}' is not supported in parameter expressions", word));
    }
    if (word == "not") {
      return fail(DiagCode::unsupported_expression, t.pos,
                  "boolean operators ('and', 'or', 'not') are not supported in parameter "
                  "expressions");
    }
    return fail(DiagCode::expression_syntax, t.pos,
                fmt::format("expected an expression, got the reserved word '{}'", word));
  }

  // An operand was expected at cur().
  int missing_operand() {
    const Token& t = cur();
    if (t.kind == Tok::Error) return fail(t.code, t.pos, t.message);
    if (t.kind == Tok::End && !open_parens_.empty()) return unclosed_paren();
    if (k_ == 0) {
      if (t.kind == Tok::End)
        return fail(DiagCode::expression_syntax, t.pos, "expected an expression");
      return fail(DiagCode::expression_syntax, t.pos,
                  fmt::format("expected an expression, got '{}'", shown(t)));
    }
    return fail(DiagCode::expression_syntax, t.pos,
                fmt::format("expected an expression after '{}'", shown(toks_[k_ - 1])));
  }

  int unclosed_paren() {
    // input-syntax.md §6.2: an open parenthesis would continue the definition on the next line
    // in Python; continuation is not supported.
    return fail(DiagCode::unsupported_expression, open_parens_.back(),
                "'(' is never closed: a definition cannot continue on the next line");
  }

  // A complete operand was parsed and cur() is neither an operator of the grammar nor what the
  // context expects. Names the unsupported construct when there is one (E0407), else E0401.
  int unexpected_after_operand(const std::string& expected) {
    const Token& t = cur();
    const std::uint32_t pos = t.pos;
    auto unsupported = [&](std::string message) {
      return fail(DiagCode::unsupported_expression, pos, std::move(message));
    };
    switch (t.kind) {
      case Tok::Error:
        return fail(t.code, t.pos, t.message);
      case Tok::End:
        if (!open_parens_.empty()) return unclosed_paren();
        return fail(DiagCode::expression_syntax, pos, fmt::format("expected {}", expected));
      case Tok::Op: {
        const std::string_view op = tok_text(t);
        if (op == "==" || op == "!=" || op == "<" || op == ">" || op == "<=" || op == ">=" ||
            op == "<>") {
          return unsupported("comparisons are not supported in parameter expressions");
        }
        if (op == ",") return unsupported("tuples are not supported in parameter expressions");
        if (op == "=") {
          return unsupported(
              "'=' is not allowed inside an expression: one assignment per definition");
        }
        if (op == ":=") {
          return unsupported(
              "assignment expressions (':=') are not supported in parameter "
              "expressions");
        }
        if (op == "&" || op == "|" || op == "^" || op == "<<" || op == ">>" || op == "~") {
          return unsupported("bitwise operators are not supported in parameter expressions");
        }
        if (op == "@") {
          return unsupported("the '@' operator is not supported in parameter expressions");
        }
        if (op.size() >= 2 && op.back() == '=' && op != "!=") {
          return unsupported(fmt::format(
              "augmented assignment ('{}') is not supported: write 'name = name {} ...'", op,
              op.substr(0, op.size() - 1)));
        }
        if (op == "[") return unsupported("indexing is not supported in parameter expressions");
        if (op == ".")
          return unsupported("attribute access is not supported in parameter expressions");
        if (op == ")" && open_parens_.empty()) {
          return fail(DiagCode::expression_syntax, pos, "unmatched ')'");
        }
        break;
      }
      case Tok::Name: {
        const std::string_view word = tok_text(t);
        if (word == "and" || word == "or") {
          return unsupported(
              "boolean operators ('and', 'or', 'not') are not supported in "
              "parameter expressions");
        }
        if (word == "not" || word == "in" || word == "is") {
          return unsupported("comparisons are not supported in parameter expressions");
        }
        if (word == "if" || word == "else") {
          return unsupported(
              "conditional expressions ('... if ... else ...') are not supported "
              "in parameter expressions");
        }
        if (word == "for" || word == "async") {
          return unsupported("comprehensions are not supported in parameter expressions");
        }
        break;
      }
      default:
        break;
    }
    return fail(DiagCode::expression_syntax, pos,
                fmt::format("expected {}, got '{}'", expected, shown(t)));
  }

  std::string_view text_;
  SourceLoc loc_;
  const std::vector<Token>& toks_;
  DiagnosticSink& sink_;
  std::vector<Node> nodes_;
  std::size_t k_ = 0;
  int depth_ = 0;
  std::vector<std::uint32_t> open_parens_;
};

}  // namespace

int parse_expression(std::string_view text, SourceLoc loc, const std::vector<Token>& tokens,
                     DiagnosticSink& sink, std::vector<Node>& nodes) {
  Parser parser(text, loc, tokens, sink);
  const int root = parser.parse();
  nodes = std::move(parser.nodes());
  return root;
}

}  // namespace clinch::expression_detail
