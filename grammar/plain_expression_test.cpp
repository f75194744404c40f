#include "grammar/plain_expression.hpp"

#include <doctest/doctest.h>

#include <array>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "grammar/test_support.hpp"

namespace ncsim::grammar::test {
namespace {

/// read_plain_group on `text` (a `[` first), a block of its own: where the group ends (an
/// offset into `text`), or -1 when the reader left it to the PEG rules; `nodes` the nodes it
/// left in the block.
long plain_group_end(const std::string& text, std::size_t* nodes = nullptr) {
  ast::Block block;
  State st;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  st.reset(block, begin, end, {1, 1}, text.find('\n') != std::string::npos);
  const char* const close = read_plain_group(begin, end, st);
  if (nodes != nullptr) *nodes = block.exprs.size();
  if (close == nullptr) {
    CHECK(st.stack.empty());
    return -1;
  }
  CHECK(st.stack.size() == 1);
  return close - begin;
}

}  // namespace

TEST_CASE("the plain reader takes arithmetic on numbers, groups and functions") {
  for (const std::string text :
       {"[1]", "[[63.607+33.715]/2]", "[-3.308+46.194*COS[60]]", "[ABS[144.732]-10]", "[ -2 ** 2 ]",
        "[2**-1]", "[2**3**2]", "[1--2]", "[+.5 (c) * \\\n 3.]", "[ATAN2[1, 2] / sqrt [4]]",
        "[[[[7]]]]", "[1 (a (b) c) + 2]"}) {
    CAPTURE(text);
    CHECK(plain_group_end(text) == static_cast<long>(text.size()));
  }
  CHECK(plain_group_end("[1+2] Y3") == 5);
}

TEST_CASE("the plain reader leaves every other expression to the PEG rules, unchanged") {
  const std::string deep = std::string(40, '[') + "1" + std::string(40, ']');
  const std::string huge = "[1" + std::string(400, '0') + "]";  // NC1005 through rules::number
  for (const std::string& text : std::vector<std::string>{
           "[P1+1]",  "[1 MOD 2]", "[1==2]",    "[1 < 2]",    "[1 & 3]", "[1 && 1]",
           "[1 | 2]", "[1 ^ 2]",   "[1 XOR 0]", "[NOT 1]",    "[INV 1]", "[PI]",
           "[TRUE]",  "[\"a\"]",   "['16#FF']", "[V.L.X]",    "[]",      "[1+]",
           "[1 2]",   "[SIN 30]",  "[SIN[30]",  "[SINX[30]]", "[1e5]",   "[.]",
           "[1,2]",   "[2* *3]",   "[1",        "[1 (open]",  deep,      huge}) {
    CAPTURE(text);
    std::size_t nodes = 99;
    CHECK(plain_group_end(text, &nodes) == -1);
    CHECK(nodes == 0);
  }
}

// Seeded random expressions of the plain shape (numbers in every form, groups, calls with one
// or two arguments, unary and binary operators, separators and continuations between tokens),
// as address values with or without a sign, some with one token or character the shape does not
// allow: each block parses to the same block and diagnostics as through the whole grammar, and
// each unmutated expression is taken by the plain reader.
TEST_CASE("random plain expressions parse as through the whole grammar") {
  std::mt19937 rng(20261208);
  const auto below = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const auto digits = [&](std::size_t n) {
    std::string d;
    for (std::size_t k = 0; k < n; ++k)
      d += static_cast<char>('0' + below(10));
    return d;
  };
  const std::array<const char*, 7> separators = {"", "", "", " ", "\t", "(c)", " \\\n "};
  const std::array<const char*, 6> functions = {"SIN", "cos", "Abs", "SQRT", "ROUND", "ATAN2"};
  const std::array<const char*, 5> operators = {"+", "-", "*", "/", "**"};
  const auto sep = [&] { return std::string(separators[below(separators.size())]); };
  std::function<std::string(int)> expression;
  const auto operand = [&](int depth) -> std::string {
    switch (depth > 3 ? 0 : below(6)) {
      case 0:
      case 1:
        switch (below(4)) {
          case 0:
            return digits(1 + below(8));
          case 1:
            return digits(1 + below(4)) + ".";
          case 2:
            return "." + digits(1 + below(6));
          default:
            return digits(1 + below(4)) + "." + digits(1 + below(6));
        }
      case 2:
        return "[" + sep() + expression(depth + 1) + sep() + "]";
      case 3: {
        const std::size_t f = below(functions.size());
        std::string call = std::string(functions[f]) + sep() + "[" + expression(depth + 1);
        if (f + 1 == functions.size()) call += sep() + "," + sep() + expression(depth + 1);
        return call + sep() + "]";
      }
      default:
        return std::string(below(2) == 0 ? "-" : "+") + sep() + expression(depth + 1);
    }
  };
  expression = [&](int depth) {
    std::string text = operand(depth);
    for (std::size_t n = below(4); n > 0; --n)
      text += sep() + operators[below(operators.size())] + sep() + operand(depth);
    return text;
  };
  const std::vector<std::string> strays = {
      "MOD", "P1", "==", "<",   "&&", "|", "^", "]", "[", ",", "NOT ",  "e",
      ".",   "'",  "\"", "PI ", "X",  "*", "(", ")", " ", "=", "V.L.A", std::string(400, '9')};
  int taken = 0;
  for (int n = 0; n < 6000; ++n) {
    const std::string group = "[" + sep() + expression(0) + sep() + "]";
    if (plain_group_end(group) == static_cast<long>(group.size())) ++taken;
    std::string value = group;
    if (below(3) == 0) {
      const std::size_t at = below(value.size() + 1);
      if (below(4) == 0 && at < value.size()) {
        value.erase(at, 1);
      } else {
        value.insert(at, strays[below(strays.size())]);
      }
    }
    const std::string sign = std::array<const char*, 4>{"", "", "-", "+"}[below(4)];
    const std::string text = (below(2) == 0 ? "N10 G01 " : "") +
                             std::string(1, "XYZFIJ"[below(6)]) + sign + value +
                             (below(2) == 0 ? " Y-1.5 (end)" : "");
    same_as_whole_grammar(text);
  }
  CHECK(taken == 6000);  // every unmutated expression of the plain shape is the reader's
}

}  // namespace ncsim::grammar::test
