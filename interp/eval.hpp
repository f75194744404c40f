#pragma once
// interp/eval: evaluation of one block's expression nodes (isg-language.md §3.1-3.3).
//
// Inputs: a parsed block (its compact node array), the variable store. Outputs: a number, or
// an EvalError with the node's position and an id.
// Decisions (docs/interp.md "Expressions"): trigonometric functions take and give degrees; a
// value is TRUE when |x| >= 0.5 (PROG-206901003); comparisons give 1 or 0, `==` and `!=`
// compare with a relative tolerance of kRelTol (core/tolerance.hpp); division by zero (also MOD 0)
// is error 20396 (DIAG-20396); domain errors (SQRT of a negative number, LN/LOG of x <= 0,
// ASIN/ACOS outside
// [-1, 1], TAN/COT at a pole) are NC4101; bit operations work on the values truncated to
// 32-bit integers.
// Invariants: evaluation never allocates for P parameters and numbers; nothing is thrown.

#include <cmath>
#include <optional>
#include <string>

#include "core/source_file.hpp"
#include "grammar/ast.hpp"
#include "interp/variables.hpp"

namespace ncsim::interp {

struct EvalError {
  core::SourceLoc loc;
  std::string id;
  std::string message;
};

/// TRUE when |x| >= 0.5 (PROG-206901003, PROG-206940939).
inline bool is_true(double x) {
  return x >= 0.5 || x <= -0.5;
}

class Evaluator {
 public:
  explicit Evaluator(Variables& variables) : vars_(variables) {}

  /// Value of node `n` of `block`; on failure returns nullopt and error() describes it. A
  /// result that is not a finite number (EXP[1000], DEXP[400], 1e300 * 1e300) is error NC4101
  /// at the operation that produced it: no infinity or NaN ever leaves the evaluator.
  std::optional<double> eval(const grammar::ast::Block& block, grammar::ast::NodeIndex n) {
    // Most values are a literal: read here, without the call of the whole evaluator.
    if (n < block.exprs.size()) {
      const grammar::ast::ExprNode& node = block.exprs[n];
      if (node.op == grammar::ast::Op::number || node.op == grammar::ast::Op::constant) {
        return node.value;
      }
    }
    return eval_node(block, n);
  }
  /// Resolves a variable node (evaluating its indices) into `out`.
  bool resolve(const grammar::ast::Block& block, grammar::ast::NodeIndex n, VarRef& out);
  /// Writes `value` to the variable node `n` (assignment).
  bool assign(const grammar::ast::Block& block, grammar::ast::NodeIndex n, double value);

  const EvalError& error() const { return error_; }

 private:
  bool fail(core::SourceLoc loc, std::string id, std::string message);
  std::optional<double> eval_node(const grammar::ast::Block& block, grammar::ast::NodeIndex n);
  /// `value` when finite, else error NC4101 at `node`. Applied where a result can leave the
  /// range of a double (+ - * /, functions): leaves are finite already, as literals are
  /// range-checked (NC1005) and every stored value passed through such a check.
  std::optional<double> finite(const grammar::ast::ExprNode& node, double value) {
    if (std::isfinite(value)) [[likely]]
      return value;
    return not_finite(node, value);
  }
  [[gnu::cold, gnu::noinline]] std::optional<double> not_finite(const grammar::ast::ExprNode& node,
                                                                double value);
  std::optional<double> call(const grammar::ast::Block& block, const grammar::ast::ExprNode& n);
  std::optional<double> read_variable(const grammar::ast::Block& block, grammar::ast::NodeIndex n,
                                      const grammar::ast::ExprNode& node);
  /// The binary operator of `node` on its evaluated operands.
  std::optional<double> binary(const grammar::ast::ExprNode& node, double x, double y);

  Variables& vars_;
  EvalError error_;
  VarRef scratch_;
  int depth_ = 0;
};

}  // namespace ncsim::interp
