#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "grammar/test_support.hpp"

namespace ncsim::grammar::test {

TEST_CASE("DIN words need no separators and addresses are case-insensitive") {
  const Parsed p("g01x10Y20f100");
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.words.size() == 4);
  CHECK(p.block.words[0].kind == ast::WordKind::g);
  CHECK(p.block.words[0].code == 1);
  CHECK(p.block.words[1].name == "x");
  CHECK(p.block.words[1].loc.column == 4);
  CHECK(p.block.words[2].loc.column == 7);
  CHECK(p.block.words[3].kind == ast::WordKind::f);
}

TEST_CASE("block numbers, labels and expressions as block numbers") {
  const Parsed a("N00860 G01 X1");
  REQUIRE(a.block.number);
  CHECK(a.block.number->number == 860);
  CHECK_FALSE(a.block.number->is_label);
  const Parsed b("N10: X1");
  REQUIRE(b.block.number);
  CHECK(b.block.number->is_label);
  const Parsed c("N[P1*100] X1");
  REQUIRE(c.block.number);
  CHECK(c.block.number->expr != ast::kNoNode);
  const Parsed d("[END]");
  REQUIRE(d.block.label);
  CHECK(d.block.label->name == "END");
  CHECK(d.diags.items().empty());
}

TEST_CASE("skip levels / and /1 to /10") {
  CHECK(Parsed("/ X1").block.skip == 1);
  CHECK(Parsed("/7 N10 X1").block.skip == 7);
  CHECK(Parsed("/10 X1").block.skip == 10);
  const Parsed bad("/11 X1");
  REQUIRE(bad.diags.items().size() == 1);
  CHECK(bad.diags.items()[0].loc.column == 2);
}

TEST_CASE("comments: nested parentheses, semicolon, unclosed parenthesis") {
  const Parsed a("G01 (outer (inner) still) X1 ; tail");
  CHECK(a.diags.items().empty());
  CHECK(a.block.words.size() == 2);
  const Parsed b("G01 X1 (unclosed runs to the end Y2");
  CHECK(b.diags.items().empty());
  CHECK(b.block.words.size() == 2);
  const Parsed c("(only a comment)\nG01");
  CHECK(c.block.loc.line == 2);
}

TEST_CASE("a backslash at the line end continues the block") {
  const Parsed p("S1[MC_MoveVelocity Velocity=300000 \\\n  Direction=1]\nX1");
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.axis_commands.size() == 1);
  CHECK(p.block.axis_commands[0].item_count == 3);
  CHECK(p.block.items[2].loc.line == 2);
  CHECK(p.block.items[2].loc.column == 3);
}

TEST_CASE("errors point at the offending character on continued lines") {
  const Parsed p("X[1 + \\\n  * 2]");
  REQUIRE(p.diags.items().size() == 1);
  CHECK(p.diags.items()[0].loc.line == 2);
  CHECK(p.diags.items()[0].loc.column == 3);
}

TEST_CASE("program headers: %name, bare %, % name, %L name") {
  struct Header {
    bool local;
    std::string name;
  };
  const auto header = [](const std::string& t) {
    const Parsed p(t);  // the AST points into p.file: copy what the test needs
    REQUIRE(p.diags.items().empty());
    const auto& h = std::get<ast::ProgramHeader>(p.block.body);
    return Header{h.local, std::string(h.name)};
  };
  CHECK(header("%main").name == "main");
  CHECK(header("%").name.empty());
  CHECK(header("% Laser").name == "Laser");
  CHECK(header("%L SUB1").local);
  CHECK(header("%L SUB1").name == "SUB1");
  CHECK_FALSE(header("%Laser").local);
}

TEST_CASE("a %name header after a block with an H word is not a local subroutine") {
  // The header action read a word kind only `%L` sets: an H word's kind left from an earlier
  // block marked the next plain header local.
  const core::SourceFile file("t.nc", "%main\nH5\n%next\nH6\n%L sub\n");
  BlockParser parser(file);
  core::DiagnosticList diags;
  ast::Block b;
  std::vector<bool> local;
  while (parser.next(b, diags))
    if (const auto* h = std::get_if<ast::ProgramHeader>(&b.body)) local.push_back(h->local);
  CHECK(diags.items().empty());
  CHECK(local == std::vector<bool>{false, false, true});
}

TEST_CASE("axis values: number, bracket, variable with or without blank, sign") {
  const Parsed p("X P5 Y-0 ZV.S.VAR[4] A[2*3] AB=90 U+.5");
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.words.size() == 6);
  CHECK(p.value(0).op == ast::Op::variable);
  CHECK(p.value(2).var_class == ast::VarClass::v_s);
  CHECK(p.block.words[4].name == "AB");
  CHECK(p.value(5).value == 0.5);
}

TEST_CASE("a syntax error names what was expected and what was found") {
  const Parsed p("N10 G01 X10 Q5");
  REQUIRE(p.diags.items().size() == 1);
  const auto& d = p.diags.items()[0];
  CHECK(d.loc.column == 13);
  CHECK(d.message.find("expected a word") != std::string::npos);
  CHECK(d.message.find("found 'Q5'") != std::string::npos);
  CHECK(p.block.has_error);
}

TEST_CASE("blocks longer than 4000 characters are an error at character 4001") {
  const std::string text = "G01 X1 (" + std::string(4100, 'c') + ")";
  const auto diags = check(text);
  REQUIRE(diags.size() == 1);
  CHECK(diags[0] == "1:4001 NC1003");
  CHECK(check("G01 X1 (" + std::string(3900, 'c') + ")").empty());
}

TEST_CASE("a number beyond the range of a double is an error, not a silent value") {
  // 1 followed by 400 zeros: std::from_chars reports out of range and leaves 0.
  CHECK(check("G01 X1" + std::string(400, '0') + " F100\n") ==
        std::vector<std::string>{"1:6 NC1005"});
  CHECK(check("G01 X[2*1" + std::string(400, '9') + "] F100\n") ==
        std::vector<std::string>{"1:9 NC1005"});
  // Leading zeros and tiny values are no overflow: the latter round to 0.
  CHECK(check("G01 X" + std::string(400, '0') + "1 F100\n").empty());
  const Parsed tiny("X0." + std::string(400, '0') + "1");
  CHECK(tiny.diags.items().empty());
  CHECK(tiny.value(0).value == 0.0);
}

TEST_CASE("a block number beyond 4294967295 is an error, not a saturated number") {
  CHECK(check("N4294967295 X1\n").empty());
  CHECK(check("N4294967296 X1\n") == std::vector<std::string>{"1:1 NC1005"});
  CHECK(check("N" + std::string(50, '9') + ": X1\n") == std::vector<std::string>{"1:1 NC1005"});
  CHECK(check("N000000000000000010 X1\n").empty());
}

TEST_CASE("every syntax error of a file is reported, one per block") {
  const auto diags = check("G01 X1 Q\nG01 X[1+]\nG01 X1\nM\n");
  REQUIRE(diags.size() == 3);
  CHECK(diags[0] == "1:8 NC1001");
  CHECK(diags[1] == "2:9 NC1001");
  CHECK(diags[2] == "4:2 NC1001");
}

TEST_CASE("subroutine calls: LL name, L file, L \"macro\", L V.E.x, L CYCLE [...]") {
  const Parsed a("LL SUB1");
  REQUIRE(a.block.call);
  CHECK(a.block.call->kind == ast::CallKind::local);
  CHECK(a.block.call->name == "SUB1");
  const Parsed b("L sub/prog.nc");
  CHECK(b.block.call->kind == ast::CallKind::global);
  CHECK(b.block.call->name == "sub/prog.nc");
  CHECK(Parsed("LL \"macro\"").block.call->target == ast::CallTarget::macro);
  CHECK(Parsed("L V.E.x").block.call->target == ast::CallTarget::variable);
  const Parsed c("L CYCLE [NAME=drill.ecy @P1=10 @P2=5]");
  REQUIRE(c.diags.items().empty());
  CHECK(c.block.call->kind == ast::CallKind::cycle);
  CHECK(c.block.call->item_count == 3);
  CHECK(c.block.items[0].text == "drill.ecy");
}

TEST_CASE("declarations between #VAR and #ENDVAR, array initialisers across lines") {
  const core::SourceFile file(
      "t.nc", "#VAR\n V.P.A[3] : REAL = [1.5, 2.5, \\\n 3.5]\n V.L.S : STRING[10]\n#ENDVAR\n");
  BlockParser parser(file);
  core::DiagnosticList diags;
  ast::Block b;
  REQUIRE(parser.next(b, diags));
  REQUIRE(parser.next(b, diags));
  const auto& d = std::get<ast::Declaration>(b.body);
  CHECK(d.array_init);
  CHECK(d.init_count == 3);
  CHECK(d.type == ast::VarType::real64);
  REQUIRE(parser.next(b, diags));
  CHECK(std::get<ast::Declaration>(b.body).type == ast::VarType::string);
  REQUIRE(parser.next(b, diags));
  CHECK(std::get<ast::HashCommand>(b.body).kind == ast::HashKind::endvar);
  CHECK_FALSE(parser.next(b, diags));
  CHECK(diags.items().empty());
}

// The number rule converts short literals itself (custom_rules_hot.hpp) and long ones with
// std::from_chars; both must give the correctly rounded double.
TEST_CASE("decimal literals have exactly the value of correctly rounded parsing") {
  std::vector<std::string> literals = {"0",
                                       "5.",
                                       ".5",
                                       "0.1",
                                       "4.35",
                                       "123.456",
                                       "007.250",
                                       "9007199254740992",
                                       "9007199254740993",
                                       "900719925474099.3",
                                       "9999999999999999999",
                                       "18446744073709551617",
                                       "1.0000000000000000000001",
                                       "0.0000000000000000000001",
                                       "0.00000000000000000000001",
                                       "0.3000000000000000444089209850062616169452667236328125",
                                       "179769313486231570000000000000000000000000.5"};
  std::mt19937_64 random(20251121);  // seeded: the same literals every run
  for (int n = 0; n < 3000; ++n) {
    std::string text;
    const auto whole = random() % 21;
    const auto decimals = random() % 26;
    for (std::uint64_t k = 0; k < whole; ++k)
      text += static_cast<char>('0' + random() % 10);
    if (decimals > 0 || whole == 0) text += '.';
    for (std::uint64_t k = 0; k < (whole == 0 && decimals == 0 ? 1 : decimals); ++k)
      text += static_cast<char>('0' + random() % 10);
    literals.push_back(text);
  }
  for (const std::string& literal : literals) {
    CAPTURE(literal);
    const Parsed p("X" + literal);
    REQUIRE(p.diags.items().empty());
    REQUIRE(p.block.words.size() == 1);
    const ast::ExprNode& node = p.value(0);
    CHECK(node.op == ast::Op::number);
    CHECK(node.text == literal);
    double expected = 0.0;
    std::from_chars(literal.data(), literal.data() + literal.size(), expected);
    CHECK(std::bit_cast<std::uint64_t>(node.value) == std::bit_cast<std::uint64_t>(expected));
  }
}

TEST_CASE("a name followed by '[' or '=' still reaches every kind of word") {
  const Parsed named("XA = 5 PX=5 P2=3 P3 X [1+2]");
  REQUIRE(named.diags.items().empty());
  REQUIRE(named.block.words.size() == 5);
  CHECK(named.block.words[0].kind == ast::WordKind::axis);
  CHECK(named.block.words[0].name == "XA");
  CHECK(named.block.words[1].kind == ast::WordKind::axis);
  CHECK(named.block.words[1].name == "PX");
  CHECK(named.block.words[2].kind == ast::WordKind::assignment);
  CHECK(named.block.words[3].kind == ast::WordKind::bare_value);
  CHECK(named.block.words[4].kind == ast::WordKind::axis);
  CHECK(named.block.words[4].name == "X");
  CHECK(named.node(named.block.words[4].value).op == ast::Op::add);
  const Parsed dense("G01X.5Y5.Z007");
  REQUIRE(dense.block.words.size() == 4);
  CHECK(dense.value(1).value == 0.5);
  CHECK(dense.block.words[3].loc.column == 10);
}

TEST_CASE("a backslash separates only when a line end follows it (blanks and CR between)") {
  const Parsed joined("X1 \\  \r\nY2");
  REQUIRE(joined.diags.items().empty());
  REQUIRE(joined.block.words.size() == 2);
  CHECK(joined.block.words[1].loc.line == 2);
  CHECK(joined.block.words[1].loc.column == 1);
  CHECK(check("X1 \\ Y2\n") == std::vector<std::string>{"1:4 NC1001"});
}

TEST_CASE("lines between #COMMENT BEGIN and END are not parsed") {
  CHECK(check("#COMMENT BEGIN\n$$$ not NC at all (\n#COMMENT END\nG01 X1\n").empty());
  CHECK(check("#COMMENT BEGIN\nX1\n") == std::vector<std::string>{"1:1 NC2016"});
}

void same_as_whole_grammar(const std::string& text) {
  CAPTURE(text);
  const Parsed fast(text);
  const Parsed full(text, false);
  REQUIRE(fast.found == full.found);
  CHECK(fast.block.has_error == full.block.has_error);
  CHECK(fast.block.body.index() == full.block.body.index());
  REQUIRE(fast.block.words.size() == full.block.words.size());
  for (std::size_t w = 0; w < fast.block.words.size(); ++w) {
    const ast::Word& a = fast.block.words[w];
    const ast::Word& b = full.block.words[w];
    CHECK(a.kind == b.kind);
    CHECK(a.name == b.name);
    CHECK(a.loc.line == b.loc.line);
    CHECK(a.loc.column == b.loc.column);
    CHECK(a.value == b.value);
    CHECK(a.extra == b.extra);
    CHECK(a.code == b.code);
    CHECK(a.has_params == b.has_params);
  }
  CHECK(fast.block.number.has_value() == full.block.number.has_value());
  if (fast.block.number && full.block.number) {
    CHECK(fast.block.number->number == full.block.number->number);
    CHECK(fast.block.number->digits == full.block.number->digits);
    CHECK(fast.block.number->is_label == full.block.number->is_label);
    CHECK(fast.block.number->loc.column == full.block.number->loc.column);
  }
  REQUIRE(fast.block.exprs.size() == full.block.exprs.size());
  for (std::size_t i = 0; i < fast.block.exprs.size(); ++i) {
    const ast::ExprNode& a = fast.block.exprs[i];
    const ast::ExprNode& b = full.block.exprs[i];
    CHECK(a.op == b.op);
    CHECK(a.function == b.function);
    CHECK(a.var_class == b.var_class);
    CHECK(a.loc.line == b.loc.line);
    CHECK(a.loc.column == b.loc.column);
    CHECK(std::bit_cast<std::uint64_t>(a.value) == std::bit_cast<std::uint64_t>(b.value));
    CHECK(a.text == b.text);
    if (!a.text.empty()) {  // the same characters of the block, not a copy
      CHECK(a.text.data() - fast.block.text.data() == b.text.data() - full.block.text.data());
    }
    CHECK(a.a == b.a);
    CHECK(a.b == b.b);
    CHECK(a.next == b.next);
  }
  REQUIRE(fast.diags.items().size() == full.diags.items().size());
  for (std::size_t d = 0; d < fast.diags.items().size(); ++d) {
    CHECK(fast.diags.items()[d].id == full.diags.items()[d].id);
    CHECK(fast.diags.items()[d].loc.line == full.diags.items()[d].loc.line);
    CHECK(fast.diags.items()[d].loc.column == full.diags.items()[d].loc.column);
    CHECK(fast.diags.items()[d].message == full.diags.items()[d].message);
  }
}

TEST_CASE("plain address-word blocks parse as through the whole grammar") {
  const std::string too_long = "X" + std::string(400, '9');  // beyond a double: NC1005
  const std::vector<std::string> blocks = {"X20.1234 Y3.4567",
                                           "  x-1.5\tY+.25 f6000 ",
                                           "X1Y2Z3",
                                           "M30",
                                           "X5. Y-0 E3",
                                           "A1 B2 C3 U4 W5",
                                           "X0.000000000000000000001 Y12345678901234567890",
                                           "X1.5.3",
                                           "X. Y1",
                                           "V5 X1",
                                           "G01 X1",
                                           "N10 X1",
                                           "n10: g1x2 (c) ; rest",
                                           "N10 G01 G90 X1 (first (nested)) Y-2 F1000 (end",
                                           "N10",
                                           "(only a comment)",
                                           "N4294967296 X1",
                                           "N10 G01 G80 X1",
                                           "G01 = 5",
                                           "G1.5 X1",
                                           "G X1",
                                           "N X1",
                                           "X1 N10",
                                           "G01 X1 ;",
                                           "N10 G04 X1 (a=b [c]) Y2",
                                           "G" + std::string(30, '9') + " X1",
                                           too_long,
                                           too_long + " Y1"};
  for (const std::string& text : blocks)
    same_as_whole_grammar(text);
}

// Seeded random blocks of the shortcut's shape (an optional block number, G words, the
// letters it takes in either case, signs, numbers of up to 25 digits with or without a point on
// either side, words with or without blanks or comments between, a `;` comment at the end), and
// some with one character the shape does not allow: each parses to the same block and
// diagnostics as through the whole grammar.
TEST_CASE("random plain blocks parse as through the whole grammar") {
  const std::string letters = "MHFESTDIJKRXYZABCUWmhfestdijkrxyzabcuw";
  const std::string strays = "=[].VvLlNnPp$#%/\\\"@:G";
  std::mt19937 rng(20261124);
  const auto below = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const auto digits = [&](std::size_t n) {
    std::string d;
    for (std::size_t k = 0; k < n; ++k)
      d += static_cast<char>('0' + below(10));
    return d;
  };
  const std::array<const char*, 6> separators = {"", " ", "\t", " (c) ", "(a (b) c)", "\r"};
  for (int n = 0; n < 8000; ++n) {
    std::string text(below(3), ' ');
    if (below(2) == 0)
      text += std::string(below(2) == 0 ? "N" : "n") + digits(1 + below(10)) +
              (below(4) == 0 ? ":" : "") + separators[below(separators.size())];
    const std::size_t words = below(6);
    for (std::size_t w = 0; w < words; ++w) {
      if (below(4) == 0) {
        text += (below(2) == 0 ? "G" : "g") + digits(1 + below(3));
      } else {
        text += letters[below(letters.size())];
        if (const std::size_t sign = below(3); sign < 2) text += "+-"[sign];
        switch (below(4)) {
          case 0:
            text += digits(1 + below(25));
            break;
          case 1:
            text += digits(1 + below(6)) + ".";
            break;
          case 2:
            text += "." + digits(1 + below(12));
            break;
          default:
            text += digits(1 + below(6)) + "." + digits(1 + below(12));
            break;
        }
      }
      text += separators[below(separators.size())];
    }
    if (below(5) == 0) text += "; rest [=]";
    if (below(4) == 0) text.insert(below(text.size() + 1), 1, strays[below(strays.size())]);
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;  // no block
    same_as_whole_grammar(text);
  }
}

}  // namespace ncsim::grammar::test
