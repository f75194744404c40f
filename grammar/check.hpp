#pragma once
// grammar/check: the syntax and structure check behind `ncsim check`.
//
// Input: one NC program file. Output: every diagnostic in file order (syntax errors recovered
// at the block end, then structural errors: unbalanced control keywords, labels, calls,
// unknown G/M codes, ...). Streams block by block: memory is a small amount per open control
// block and label, never per block (the file's pages are released behind the parser), and
// at most DiagnosticList::kDefaultLimit diagnostics (the rest are counted).

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/ast.hpp"
#include "grammar/structure.hpp"

namespace ncsim::grammar {

/// Syntax and structure check of a whole program file.
core::DiagnosticList check_program(const core::SourceFile& file);

/// check_program() fed by a parser that someone else drives, so that a program is parsed
/// once (`ncsim check`: the interpreter's first parse, interp::BlockSource). The parser adds
/// its syntax diagnostics to found() and hands every block to feed(), in file order, each
/// once; finish() after the last block gives exactly what check_program() gives.
class ProgramCheck {
 public:
  explicit ProgramCheck(const core::SourceFile& file) : structure_(file) {}

  /// Where the parser adds its syntax diagnostics.
  core::DiagnosticList& found() { return found_; }
  /// The next block of the file.
  void feed(const ast::Block& block) { structure_.feed(block, found_); }
  /// Errors found so far (syntax and structure up to the last block fed).
  bool has_errors() const { return found_.has_errors(); }
  /// After the last block: the end-of-file findings, then everything in file order.
  core::DiagnosticList finish();

 private:
  core::DiagnosticList found_;
  StructureChecker structure_;
};

}  // namespace ncsim::grammar
