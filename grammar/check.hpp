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

namespace ncsim::grammar {

/// Syntax and structure check of a whole program file.
core::DiagnosticList check_program(const core::SourceFile& file);

}  // namespace ncsim::grammar
