#include "grammar/check.hpp"

#include <algorithm>

#include "grammar/block_parser.hpp"
#include "grammar/structure.hpp"

namespace ncsim::grammar {

core::DiagnosticList check_program(const core::SourceFile& file) {
  core::DiagnosticList found;
  BlockParser parser(file);
  StructureChecker checker(file);
  ast::Block block;
  while (parser.next(block, found)) {
    checker.feed(block, found);
  }
  checker.finish(found);

  // End-of-level findings come last; hand everything out in file order.
  std::vector<core::Diagnostic> items = found.items();
  std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
    return a.loc.line != b.loc.line ? a.loc.line < b.loc.line : a.loc.column < b.loc.column;
  });
  core::DiagnosticList sorted;
  for (auto& d : items)
    sorted.add(std::move(d));
  return sorted;
}

}  // namespace ncsim::grammar
