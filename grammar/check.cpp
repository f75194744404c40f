#include "grammar/check.hpp"

#include <utility>

#include "grammar/block_parser.hpp"

namespace ncsim::grammar {

core::DiagnosticList ProgramCheck::finish() {
  structure_.finish(found_);
  // End-of-level findings come last; hand everything out in file order. The list keeps the
  // first DiagnosticList::kDefaultLimit diagnostics found and counts the rest.
  found_.sort_by_position();
  return std::move(found_);
}

core::DiagnosticList check_program(const core::SourceFile& file) {
  ProgramCheck check(file);
  BlockParser parser(file);
  ast::Block block;
  while (parser.next(block, check.found())) {
    check.feed(block);
  }
  return check.finish();
}

}  // namespace ncsim::grammar
