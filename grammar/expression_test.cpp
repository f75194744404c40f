#include <doctest/doctest.h>

#include <cmath>

#include "grammar/test_support.hpp"

namespace ncsim::grammar::test {

double eval(const ast::Block& b, ast::NodeIndex i) {
  const ast::ExprNode& n = b.exprs.at(i);
  using O = ast::Op;
  const auto A = [&] { return eval(b, n.a); };
  const auto B = [&] { return eval(b, n.b); };
  switch (n.op) {
    case O::number:
    case O::constant:
      return n.value;
    case O::negate:
      return -A();
    case O::plus:
      return A();
    case O::logical_not:
      return std::fabs(A()) >= 0.5 ? 0.0 : 1.0;
    case O::power:
      return std::pow(A(), B());
    case O::multiply:
      return A() * B();
    case O::divide:
      return A() / B();
    case O::modulo:
      return std::fmod(A(), B());
    case O::add:
      return A() + B();
    case O::subtract:
      return A() - B();
    case O::equal:
      return A() == B();
    case O::less:
      return A() < B();
    case O::greater:
      return A() > B();
    case O::bit_and:
      return static_cast<double>(static_cast<long>(A()) & static_cast<long>(B()));
    case O::bit_or:
      return static_cast<double>(static_cast<long>(A()) | static_cast<long>(B()));
    case O::logical_and:
      return (std::fabs(A()) >= 0.5 && std::fabs(B()) >= 0.5) ? 1.0 : 0.0;
    case O::logical_or:
      return (std::fabs(A()) >= 0.5 || std::fabs(B()) >= 0.5) ? 1.0 : 0.0;
    default:
      FAIL("operator not evaluated in tests");
      return 0.0;
  }
}

namespace {
double value_of(const std::string& expr) {
  const Parsed p("P1 = " + expr);
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.words.size() == 1);
  return eval(p.block, p.block.words[0].value);
}
}  // namespace

TEST_CASE("multiplication binds tighter than addition and brackets group") {
  CHECK(value_of("1 + 2 * 3") == 7);
  CHECK(value_of("[1 + 2] * 3") == 9);
  CHECK(value_of("11 MOD 3") == 2);
  CHECK(value_of("2 * 3 MOD 4") == 2);
  CHECK(value_of("10 - 4 - 3") == 3);  // left-associative
}

TEST_CASE("power is right-associative and binds tighter than unary minus") {
  CHECK(value_of("2 ** 3 ** 2") == 512);
  CHECK(value_of("-2 ** 2") == -4);
  CHECK(value_of("2 ** -1") == 0.5);
}

TEST_CASE("comparisons bind looser than arithmetic, logical operators loosest") {
  CHECK(value_of("1 + 1 == 2") == 1);
  CHECK(value_of("1 < 2 && 3 > 4") == 0);
  CHECK(value_of("1 < 2 || 3 > 4") == 1);
  CHECK(value_of("6 & 3 == 3") == 0);  // & below comparisons: 6 & [3 == 3] = 6 & 1 = 0
  CHECK(value_of("4 | 1 && 0") == 0);  // | above &&
}

// Each precedence level tries its operator only when the character after the separators can
// start it (rules::when_next): an operator after blanks, comments or a line continuation, in
// either case, is still found at every level.
TEST_CASE("operators after blanks, comments and continuations at every precedence level") {
  CHECK(value_of("2 (c) ** (d) 3") == 8);
  CHECK(value_of("7 (c) mod 4 * 2") == 6);
  CHECK(value_of("1 (a (nested)) + 2 \\\n - 4") == -1);
  CHECK(value_of("1 (c) == 1 (c) & 3 (c) | 4") == 5);
  // the operators the helper does not evaluate: the tree they build
  const Parsed p("P1 = 1 (c) ^ 2 (c) xor 1 (c) || 0 (c) != 2 (c) <= 1 (c) >= 1");
  REQUIRE(p.diags.items().empty());
  const ast::ExprNode& top = p.node(p.block.words.at(0).value);
  CHECK(top.op == ast::Op::logical_or);
  CHECK(p.node(top.a).op == ast::Op::logical_xor);
  CHECK(p.node(p.node(top.a).a).op == ast::Op::bit_xor);
  CHECK(p.node(top.b).op == ast::Op::greater_equal);
  CHECK(p.node(p.node(top.b).a).op == ast::Op::less_equal);
  CHECK(p.node(p.node(p.node(top.b).a).a).op == ast::Op::not_equal);
  CHECK(value_of("[3] MOD 2") == 1);
}

TEST_CASE("unary minus on a literal is folded into the number") {
  const Parsed p("X-0");
  REQUIRE(p.block.words.size() == 1);
  CHECK(p.value(0).op == ast::Op::number);
  CHECK(std::signbit(p.value(0).value));
}

TEST_CASE("functions take bracketed arguments, ATAN2 takes two") {
  const Parsed p("P1 = SIN[30] + ATAN2[1, 2] + sqrt[4]");
  REQUIRE(p.diags.items().empty());
  int calls = 0;
  for (const auto& n : p.block.exprs) {
    if (n.op == ast::Op::call) ++calls;
    if (n.function == ast::Function::atan2) {
      REQUIRE(n.a != ast::kNoNode);
      CHECK(p.node(n.a).next != ast::kNoNode);
    }
  }
  CHECK(calls == 3);
}

TEST_CASE("variables keep their class, number and subscripts") {
  const Parsed p("P100[5][2] = PP10 + V.G.KIN[90].PARAM[0] + @P3");
  REQUIRE(p.diags.items().empty());
  const ast::Word& w = p.block.words.at(0);
  const ast::ExprNode& target = p.node(w.target);
  CHECK(target.var_class == ast::VarClass::p);
  CHECK(target.value == 100);
  REQUIRE(target.a != ast::kNoNode);
  CHECK(p.node(target.a).next != ast::kNoNode);  // two subscripts
  bool kin = false;
  for (const auto& n : p.block.exprs) {
    if (n.op == ast::Op::variable && n.var_class == ast::VarClass::v_g) {
      kin = true;
      CHECK(n.text == "V.G.KIN[90].PARAM[0]");
      CHECK(p.node(n.a).text == "KIN");
      CHECK(p.node(p.node(n.a).next).text == "PARAM");
    }
  }
  CHECK(kin);
}

TEST_CASE("hexadecimal and binary literals in quotes") {
  CHECK(value_of("'16#FA1B'") == 0xFA1B);
  CHECK(value_of("'0x0ED2'") == 0x0ED2);
  CHECK(value_of("'H1869f'") == 0x1869F);
  CHECK(value_of("'2#1010'") == 10);
  const Parsed bad("P1 = '16#XYZ'");
  REQUIRE(bad.diags.items().size() == 1);
  CHECK(bad.diags.items()[0].loc.column == 6);
}

TEST_CASE("constants TRUE FALSE PI and the keyword operators are case-insensitive") {
  CHECK(value_of("true + False") == 1);
  CHECK(value_of("pi") == doctest::Approx(3.14159265));
  CHECK(value_of("11 mod 3") == 2);
  CHECK(value_of("not 0") == 1);
}

TEST_CASE("string macros: definition with escapes and use in expressions") {
  const Parsed def("N10 \"STRING1\" = \"COS[\\\"STRING2\\\"]\"");
  REQUIRE(def.diags.items().empty());
  REQUIRE(def.block.words.size() == 1);
  CHECK(def.block.words[0].kind == ast::WordKind::macro_def);
  CHECK(def.block.words[0].name == "STRING1");
  CHECK(def.block.words[0].text == "COS[\\\"STRING2\\\"]");
  const Parsed use("N40 X[-2*\"STRING1\"+\"STRING2\"]");
  REQUIRE(use.diags.items().empty());
  int strings = 0;
  for (const auto& n : use.block.exprs)
    strings += n.op == ast::Op::string;
  CHECK(strings == 2);
}

TEST_CASE("compound assignments") {
  for (const auto& [text, op] :
       {std::pair{"P1 += 2", ast::AssignOp::add}, std::pair{"P1 -= 2", ast::AssignOp::subtract},
        std::pair{"P1 *= 2", ast::AssignOp::multiply},
        std::pair{"V.L.X /= 2", ast::AssignOp::divide}}) {
    const Parsed p(text);
    REQUIRE(p.block.words.size() == 1);
    CHECK(p.block.words[0].assign == op);
  }
}

TEST_CASE("deep bracket and sign nesting ends in a nesting diagnostic, not a crash") {
  const Parsed p("P1 = " + std::string(1900, '[') + "1" + std::string(1900, ']'));
  REQUIRE(p.diags.items().size() == 1);
  CHECK(p.diags.items()[0].id == "NC1004");
  CHECK(p.diags.items()[0].loc.column == 5 + kMaxNesting + 1);
  const Parsed q("P1 = " + std::string(3000, '-') + "1");
  REQUIRE(q.diags.items().size() == 1);
  CHECK(q.diags.items()[0].id == "NC1004");
  const Parsed ok("P1 = " + std::string(150, '[') + "1" + std::string(150, ']'));
  CHECK(ok.diags.items().empty());
}

TEST_CASE("10,000 nested brackets or parentheses hit the block length limit first") {
  const Parsed p("P1 = " + std::string(10000, '[') + "1" + std::string(10000, ']'));
  REQUIRE(p.diags.items().size() == 1);
  CHECK(p.diags.items()[0].id == "NC1003");
  const Parsed q("X1 " + std::string(10000, '(') + std::string(10000, ')'));
  REQUIRE(q.diags.items().size() == 1);
  CHECK(q.diags.items()[0].id == "NC1003");
}

TEST_CASE("1,900 nested parentheses are one comment") {
  const Parsed p("G01 X1 " + std::string(1900, '(') + "c" + std::string(1900, ')') + " Y2");
  CHECK(p.diags.items().empty());
  CHECK(p.block.words.size() == 3);
}

}  // namespace ncsim::grammar::test
