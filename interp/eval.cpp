#include "interp/eval.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "grammar/keywords.hpp"

namespace ncsim::interp {
namespace {

namespace ast = grammar::ast;
using ast::Op;

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kMaxDepth = 400;          // deeper than the grammar's kMaxNesting allows
constexpr double kZeroDivisor = kTiny;  // |divisor| below this is zero (COS[90] = 6e-17)

std::int64_t to_int(double x) {
  if (!(std::fabs(x) < 9.0e18)) return 0;
  return static_cast<std::int64_t>(std::trunc(x));
}

bool nearly_equal(double a, double b) {
  const double scale = std::max({1.0, std::fabs(a), std::fabs(b)});
  return std::fabs(a - b) <= kRelTol * scale;
}

/// "V.P.TABLE[2]" -> "TABLE"; "V.G.KIN[90].PARAM[0]" -> "KIN.PARAM" (indices kept apart).
void base_name(std::string_view text, std::string& out) {
  out.clear();
  std::size_t k = 0;
  int dots = 0;
  while (k < text.size() && dots < 2) {
    if (text[k] == '.') ++dots;
    ++k;
  }
  int depth = 0;
  for (; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '[') {
      ++depth;
    } else if (c == ']') {
      --depth;
    } else if (depth == 0) {
      out.push_back(grammar::ascii_upper(c));
    }
  }
}

}  // namespace

bool Evaluator::fail(core::SourceLoc loc, std::string id, std::string message) {
  error_ = {loc, std::move(id), std::move(message)};
  return false;
}

bool Evaluator::resolve(const ast::Block& block, ast::NodeIndex n, VarRef& out) {
  const ast::ExprNode& node = block.exprs[n];
  if (node.op != Op::variable) {
    return fail(node.loc, "NC4003", "a variable is expected here");
  }
  // The indices first: an index expression may read a variable through the same `out`
  // (the evaluator's scratch reference), so `out` is filled only after them.
  std::array<double, 4> index{};
  std::uint32_t index_count = 0;
  for (ast::NodeIndex s = node.a; s != ast::kNoNode; s = block.exprs[s].next) {
    if (index_count == index.size()) {
      return fail(node.loc, "NC4015", "more than 4 indices: " + std::string(node.text));
    }
    auto v = eval(block, block.exprs[s].a);
    if (!v) return false;
    // An index within the `==` tolerance below a whole number is that number.
    index[index_count++] = std::trunc(*v + (*v >= 0 ? kRelTol : -kRelTol));
  }
  out.cls = node.var_class;
  out.index = index;
  out.index_count = index_count;
  if (node.var_class == ast::VarClass::p) {
    out.number = static_cast<std::uint32_t>(node.value);
    if (node.value < 0.0 || node.value != std::trunc(node.value)) out.number = 0;
  } else if (node.var_class == ast::VarClass::at_p) {
    out.number = static_cast<std::uint32_t>(std::min(node.value, 1e9));
    if (node.value < 0.0 || node.value != std::trunc(node.value)) out.number = 0;
  } else if (node.var_class == ast::VarClass::pp || node.var_class == ast::VarClass::v_other ||
             node.var_class == ast::VarClass::none) {
    return fail(node.loc, "NC4004",
                "variable " + std::string(node.text) + " is not supported by ncsim");
  } else {
    base_name(node.text, out.name);
  }
  return true;
}

bool Evaluator::assign(const ast::Block& block, ast::NodeIndex n, double value) {
  VarRef ref;
  if (!resolve(block, n, ref)) return false;
  VarError err;
  if (!vars_.write(ref, value, err)) return fail(block.exprs[n].loc, err.id, err.message);
  vars_.note_ve_write(ref);  // the run time's V.E. store sees it
  return true;
}

std::optional<double> Evaluator::not_finite(const ast::ExprNode& node, double value) {
  fail(node.loc, "NC4101", "the result is not a finite number (" + core::number_text(value) + ")");
  return std::nullopt;
}

std::optional<double> Evaluator::eval_node(const ast::Block& block, ast::NodeIndex n) {
  if (n == ast::kNoNode || n >= block.exprs.size()) {
    fail(block.loc, "NC4002", "missing value");
    return std::nullopt;
  }
  const ast::ExprNode& node = block.exprs[n];
  switch (node.op) {
    case Op::number:
    case Op::constant:
      return node.value;
    case Op::variable:
      return read_variable(block, n, node);
    case Op::string:
      fail(node.loc, "NC4005",
           "string \"" + std::string(node.text) +
               "\" is no macro defined before; a number is expected");
      return std::nullopt;
    case Op::subscript:
      fail(node.loc, "NC4002", "unexpected subscript");
      return std::nullopt;
    case Op::call:
      if (++depth_ > kMaxDepth) {
        --depth_;
        fail(node.loc, "NC4002", "expression too deeply nested");
        return std::nullopt;
      }
      {
        auto v = call(block, node);
        --depth_;
        return v ? finite(node, *v) : v;
      }
    default:
      break;
  }
  if (++depth_ > kMaxDepth) {
    --depth_;
    fail(node.loc, "NC4002", "expression too deeply nested");
    return std::nullopt;
  }
  auto a = eval(block, node.a);
  if (!a) {
    --depth_;
    return std::nullopt;
  }
  double x = *a;
  switch (node.op) {
    case Op::negate:
      --depth_;
      return -x;
    case Op::plus:
      --depth_;
      return x;
    case Op::logical_not:
      --depth_;
      return is_true(x) ? 0.0 : 1.0;
    case Op::bit_inv:
      --depth_;
      return static_cast<double>(~static_cast<std::uint32_t>(to_int(x)));
    default:
      break;
  }
  auto b = eval(block, node.b);
  --depth_;
  if (!b) return std::nullopt;
  return binary(node, x, *b);
}

std::optional<double> Evaluator::read_variable(const ast::Block& block, ast::NodeIndex n,
                                               const ast::ExprNode& node) {
  if (node.var_class == ast::VarClass::p && node.a == ast::kNoNode) {
    // fast path: scalar P parameter
    scratch_.cls = ast::VarClass::p;
    scratch_.index_count = 0;
    scratch_.number = (node.value >= 1.0 && node.value == std::trunc(node.value))
                          ? static_cast<std::uint32_t>(node.value)
                          : 0;
  } else if (!resolve(block, n, scratch_)) {
    return std::nullopt;
  }
  VarError err;
  auto v = vars_.read(scratch_, err);
  if (!v && err.id == "NC4011" && !node.text.empty()) {
    // The variable as the program wrote it (V.G.KIN[9].PROGRAMMING_MODE), not the store's
    // name with its indices at the end.
    err.message = "unknown variable " + std::string(node.text);
  }
  if (!v) fail(node.loc, err.id, err.message);
  return v;
}

std::optional<double> Evaluator::binary(const ast::ExprNode& node, double x, double y) {
  switch (node.op) {
    case Op::power: {
      const double r = std::pow(x, y);
      if (!std::isfinite(r)) {
        fail(node.loc, "NC4101",
             "power " + core::number_text(x) + " ** " + core::number_text(y) + " is not defined");
        return std::nullopt;
      }
      return r;
    }
    case Op::multiply:
      return finite(node, x * y);
    case Op::divide:
      if (std::fabs(y) < kZeroDivisor) {  // DIAG-20396: 10/COS[90] is a division by zero
        fail(node.loc, "20396", "division by zero");
        return std::nullopt;
      }
      return finite(node, x / y);
    case Op::modulo:
      if (std::fabs(y) < kZeroDivisor) {
        fail(node.loc, "20396", "division by zero (MOD 0)");
        return std::nullopt;
      }
      return std::fmod(x, y);
    case Op::add:
      return finite(node, x + y);
    case Op::subtract:
      return finite(node, x - y);
    case Op::equal:
      return nearly_equal(x, y) ? 1.0 : 0.0;
    case Op::not_equal:
      return nearly_equal(x, y) ? 0.0 : 1.0;
    case Op::less:
      return x < y ? 1.0 : 0.0;
    case Op::greater:
      return x > y ? 1.0 : 0.0;
    case Op::less_equal:
      return x <= y ? 1.0 : 0.0;
    case Op::greater_equal:
      return x >= y ? 1.0 : 0.0;
    case Op::bit_and:
      return static_cast<double>(to_int(x) & to_int(y));
    case Op::bit_xor:
      return static_cast<double>(to_int(x) ^ to_int(y));
    case Op::bit_or:
      return static_cast<double>(to_int(x) | to_int(y));
    case Op::logical_and:
      return (is_true(x) && is_true(y)) ? 1.0 : 0.0;
    case Op::logical_xor:
      return (is_true(x) != is_true(y)) ? 1.0 : 0.0;
    case Op::logical_or:
      return (is_true(x) || is_true(y)) ? 1.0 : 0.0;
    default:
      break;
  }
  fail(node.loc, "NC4002", "unknown operator");
  return std::nullopt;
}

std::optional<double> Evaluator::call(const ast::Block& block, const ast::ExprNode& node) {
  using F = ast::Function;
  if (node.function == F::sizeof_ || node.function == F::exist) {
    VarRef ref;
    const ast::NodeIndex arg = node.a;
    if (arg == ast::kNoNode || block.exprs[arg].op != Op::variable) {
      fail(node.loc, "NC4003", "SIZEOF and EXIST take a variable");
      return std::nullopt;
    }
    ref.cls = block.exprs[arg].var_class;
    ref.number = static_cast<std::uint32_t>(block.exprs[arg].value);
    base_name(block.exprs[arg].text, ref.name);
    if (node.function == F::exist) return vars_.exists(ref) ? 1.0 : 0.0;
    auto size = vars_.size_of(ref);
    if (!size) {
      fail(node.loc, "NC4011",
           "SIZEOF of an unknown variable " + std::string(block.exprs[arg].text));
      return std::nullopt;
    }
    return static_cast<double>(*size);
  }
  auto a = eval(block, node.a);
  if (!a) return std::nullopt;
  const double x = *a;
  if (node.function != F::atan2 && block.exprs[node.a].next != ast::kNoNode) {
    fail(node.loc, "NC4002", "the function takes one argument");
    return std::nullopt;
  }
  const auto domain = [&](const char* what) -> std::optional<double> {
    fail(node.loc, "NC4101", std::string(what) + " is not defined for " + core::number_text(x));
    return std::nullopt;
  };
  switch (node.function) {
    case F::sin:
      return std::sin(x * kDeg);
    case F::cos:
      return std::cos(x * kDeg);
    case F::tan: {
      const double c = std::cos(x * kDeg);
      if (std::fabs(c) < kTiny) return domain("TAN");
      return std::sin(x * kDeg) / c;
    }
    case F::cot: {
      const double s = std::sin(x * kDeg);
      if (std::fabs(s) < kTiny) return domain("COT");
      return std::cos(x * kDeg) / s;
    }
    case F::asin:
      if (x < -1.0 || x > 1.0) return domain("ASIN");
      return std::asin(x) / kDeg;
    case F::acos:
      if (x < -1.0 || x > 1.0) return domain("ACOS");
      return std::acos(x) / kDeg;
    case F::atan:
      return std::atan(x) / kDeg;
    case F::acot:
      return (std::numbers::pi / 2.0 - std::atan(x)) / kDeg;
    case F::atan2: {
      const ast::NodeIndex second = block.exprs[node.a].next;
      if (second == ast::kNoNode) {
        fail(node.loc, "NC4002", "ATAN2 takes two arguments [y, x]");
        return std::nullopt;
      }
      auto b = eval(block, second);
      if (!b) return std::nullopt;
      if (x == 0.0 && *b == 0.0) return domain("ATAN2");
      return std::atan2(x, *b) / kDeg;
    }
    case F::sqrt:
      if (x < 0.0) return domain("SQRT");
      return std::sqrt(x);
    case F::sqr:
      return x * x;
    case F::abs:
      return std::fabs(x);
    case F::int_:
      return std::trunc(x);
    case F::fract:
      return x - std::trunc(x);
    case F::round:
      return std::round(x);
    case F::ceil:
      return std::ceil(x);
    case F::floor:
      return std::floor(x);
    case F::exp:
      return std::exp(x);
    case F::ln:
      if (x <= 0.0) return domain("LN");
      return std::log(x);
    case F::dexp:
      return std::pow(10.0, x);
    case F::log:
      if (x <= 0.0) return domain("LOG");
      return std::log10(x);
    default:
      break;
  }
  fail(node.loc, "NC4002", "unknown function");
  return std::nullopt;
}

}  // namespace ncsim::interp
