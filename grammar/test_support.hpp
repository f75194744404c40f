#pragma once
// grammar/test_support: helpers shared by the grammar unit tests (test code only).

#include <string>
#include <vector>

#include "grammar/block_parser.hpp"
#include "grammar/check.hpp"

namespace ncsim::grammar::test {

/// Parses `text` and keeps the first block (and the file it points into).
struct Parsed {
  core::SourceFile file;
  ast::Block block;
  core::DiagnosticList diags;
  bool found = false;

  /// `shortcut` false: through the whole grammar (BlockParser::use_shortcut).
  explicit Parsed(std::string text, bool shortcut = true) : file("t.nc", std::move(text)) {
    BlockParser parser(file);
    parser.use_shortcut(shortcut);
    found = parser.next(block, diags);
  }
  const ast::ExprNode& node(ast::NodeIndex i) const { return block.exprs.at(i); }
  const ast::ExprNode& value(std::size_t word) const { return node(block.words.at(word).value); }
};

/// "line:col id" of every diagnostic of check_program, except warning NC2019 (no M02/M30),
/// which the snippets here have by design; structure_test.cpp tests NC2019 itself.
inline std::vector<std::string> check(const std::string& text) {
  const core::SourceFile file("t.nc", text);
  std::vector<std::string> out;
  const core::DiagnosticList diags = check_program(file);
  for (const auto& d : diags.items()) {
    if (d.id == "NC2019") continue;
    out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.id);
  }
  return out;
}

/// Blocks of the plain shape (N10 G01 Y[ABS[2]-1] (comment)) are read by a shortcut past
/// rules::block (block_parser.cpp, read_plain_block); BlockParser::use_shortcut(false) sends them
/// through the whole grammar. Checks that both give the same block, to the bit, and the same
/// diagnostics (defined in lexical_test.cpp).
void same_as_whole_grammar(const std::string& text);

/// Evaluates the constant part of an expression tree (numbers and operators), for
/// precedence tests.
double eval(const ast::Block& b, ast::NodeIndex i);

}  // namespace ncsim::grammar::test
