#include "grammar/plain_expression.hpp"

#include "grammar/custom_rules_hot.hpp"

namespace ncsim::grammar {
namespace {

using ast::kNoNode;
using ast::NodeIndex;
using ast::Op;

/// One read of the plain shape, a method per PEG rule it stands for. Each method reads its
/// rule at the current position and returns the node of what it read, or kNoNode where the
/// text leaves the plain shape (read_plain_group then discards everything). Nodes are added
/// when the PEG actions would add them: a leaf when read, an operator after its operands.
/// Separators are skipped before each token; rules.hpp allows rules::ws between any two
/// tokens of the shape, and only inside `**` and a number none, which the reader takes whole.
class PlainReader {
 public:
  PlainReader(const char* begin, const char* end, State& st) : p_(begin), e_(end), st_(st) {}

  const char* position() const { return p_; }

  // group: '[' ws expression ws ']' (rules::group); at a '['.
  NodeIndex group() {
    ++p_;
    const NodeIndex value = expression();
    if (value == kNoNode || peek() != ']') return kNoNode;
    ++p_;
    return value;
  }

 private:
  /// Skips separators (rules::ws) and returns the next character, '\0' at the end.
  char peek() {
    if (p_ < e_ && !lex::starts_separator(*p_)) return *p_;
    p_ = lex::separators_end(p_, e_);
    return p_ < e_ ? *p_ : '\0';
  }

  // expression: the sum. The levels above it (comparisons, bit and logical operators) leave
  // the shape: their operator is then the next character, where the caller wants ']' or ','.
  NodeIndex expression() { return sum(); }

  // sum: product (ws ('+' | '-') ws product)* (rules::sum, rules::add_tail).
  NodeIndex sum() {
    NodeIndex lhs = product();
    while (lhs != kNoNode) {
      const char c = peek();
      if (c != '+' && c != '-') break;
      const char* const at = p_++;
      const NodeIndex rhs = product();
      if (rhs == kNoNode) return kNoNode;
      lhs = binary(*at == '+' ? Op::add : Op::subtract, at, lhs, rhs);
    }
    return lhs;
  }

  // product: operand (ws ('*' | '/') ws operand)* (rules::product, rules::mul_tail). MOD
  // leaves the shape.
  NodeIndex product() {
    NodeIndex lhs = operand();
    while (lhs != kNoNode) {
      const char c = peek();
      if ((c != '*' && c != '/') || (c == '*' && p_ + 1 < e_ && p_[1] == '*')) break;  // not `**`
      const char* const at = p_++;
      const NodeIndex rhs = operand();
      if (rhs == kNoNode) return kNoNode;
      lhs = binary(*at == '*' ? Op::multiply : Op::divide, at, lhs, rhs);
    }
    return lhs;
  }

  // operand: unary | power; unary: ('-' | '+') ws operand (rules::operand, rules::unary).
  // NOT and INV leave the shape.
  NodeIndex operand() {
    if (++depth_ + st_.depth > kMaxPlainNesting) return kNoNode;
    NodeIndex value = kNoNode;
    if (const char c = peek(); c == '-' || c == '+') {
      const char* const at = p_++;
      const NodeIndex a = operand();
      if (a != kNoNode) value = unary(at, a);
    } else {
      value = power();
    }
    --depth_;
    return value;
  }

  // power: primary [ws '**' ws operand] (rules::power, rules::power_tail); at a token.
  NodeIndex power() {
    const NodeIndex base = primary();
    if (base == kNoNode || peek() != '*' || p_ + 1 == e_ || p_[1] != '*') return base;
    const char* const at = p_;
    p_ += 2;
    const NodeIndex exponent = operand();
    return exponent == kNoNode ? kNoNode : binary(Op::power, at, base, exponent);
  }

  // primary: number | group | call (rules::primary, in its order: a function name is a call
  // before it could be a constant or a variable). The other alternatives leave the shape.
  NodeIndex primary() {
    if (p_ == e_) return kNoNode;
    if (*p_ == '[') return group();
    if (lex::is_alpha(*p_)) return call();
    const lex::Decimal number = lex::read_decimal(p_, e_);
    if (number.end == nullptr) return kNoNode;
    const NodeIndex value = detail::add_number(st_, p_, number);  // kNoNode: NC1005
    p_ = number.end;
    return value;
  }

  // call: function_name ws '[' ws argument (ws ',' ws argument)* ws ']' (rules::call); the
  // arguments linked by `next`, the first in `a` (Action<rules::call>).
  NodeIndex call() {
    const char* const name = p_;
    while (p_ < e_ && lex::is_ident(*p_))
      ++p_;
    const std::string_view text(name, static_cast<std::size_t>(p_ - name));
    const ast::Function function = function_by_name(text);
    if (function == ast::Function::none || peek() != '[') return kNoNode;
    ++p_;
    NodeIndex first = kNoNode;
    NodeIndex last = kNoNode;
    for (;;) {
      const NodeIndex argument = expression();
      if (argument == kNoNode) return kNoNode;
      if (last == kNoNode) {
        first = argument;
      } else {
        st_.block->exprs[last].next = argument;
      }
      last = argument;
      const char next = peek();
      if (next == ']') break;
      if (next != ',') return kNoNode;
      ++p_;
    }
    ++p_;
    ast::ExprNode node = detail::leaf(Op::call, st_.loc(name), text);
    node.function = function;
    node.a = first;
    return st_.add(node);
  }

  /// Action<rules::unary>: `-` folds into a literal just read (State::negate_top), `+` and
  /// any other `-` make a node.
  NodeIndex unary(const char* at, NodeIndex a) {
    ast::ExprNode& value = st_.block->exprs[a];
    if (*at == '-' && value.op == Op::number && a + 1 == st_.block->exprs.size()) {
      value.value = -value.value;
      value.loc = st_.loc(at);
      return a;
    }
    ast::ExprNode node;
    node.op = *at == '-' ? Op::negate : Op::plus;
    node.loc = st_.loc(at);
    node.a = a;
    return st_.add(node);
  }

  /// BuildBinary (State::binary): the node of the operator at `at`.
  NodeIndex binary(Op op, const char* at, NodeIndex a, NodeIndex b) {
    ast::ExprNode node;
    node.op = op;
    node.loc = st_.loc(at);
    node.a = a;
    node.b = b;
    return st_.add(node);
  }

  const char* p_;
  const char* const e_;
  State& st_;
  int depth_ = 0;  // operands open, as Control<rules::operand> counts them
};

}  // namespace

const char* read_plain_group(const char* open, const char* end, State& st) {
  const std::size_t nodes = st.block->exprs.size();
  PlainReader reader(open, end, st);
  const NodeIndex value = reader.group();
  if (value == kNoNode) {
    st.block->exprs.resize(nodes);
    return nullptr;
  }
  st.stack.push_back(value);
  return reader.position();
}

}  // namespace ncsim::grammar
