#include "grammar/check.hpp"

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

  // End-of-level findings come last; hand everything out in file order. The list keeps the
  // first DiagnosticList::kDefaultLimit diagnostics found and counts the rest.
  found.sort_by_position();
  return found;
}

}  // namespace ncsim::grammar
