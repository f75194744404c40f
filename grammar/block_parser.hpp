#pragma once
// grammar/block_parser: streams an NC program file block by block into a reused ast::Block.
//
// Purpose: the front end of `ncsim check` and of the interpreter. Inputs: a SourceFile (which
// must outlive the parser and every Block it fills). Outputs: one ast::Block per call of
// next(), plus syntax diagnostics (NC1xxx and the manual ids the parser itself detects:
// 20219, 20839, 21542).
// Invariants: memory is the reused block (the file's pages behind the parser are released,
// SourceFile::release_before); a syntax error is reported once,
// at the offending character, and parsing resumes at the next block (`Block::has_error`).
// Blank and comment-only lines yield no block. Lines between #COMMENT BEGIN/END are skipped;
// lines between #VAR and #ENDVAR are parsed as declarations.

#include <cstddef>
#include <memory>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/ast.hpp"

namespace ncsim::grammar {

/// Longest block the kernel accepts (isg-language.md §1.3, PROG-205952267) [characters].
inline constexpr std::size_t kMaxBlockLength = 4000;
/// Deepest `[` nesting of expressions and `(` nesting of comments ncsim accepts.
inline constexpr int kMaxNesting = 200;

class BlockParser {
 public:
  explicit BlockParser(const core::SourceFile& file);
  ~BlockParser();
  BlockParser(const BlockParser&) = delete;
  BlockParser& operator=(const BlockParser&) = delete;

  /// Fills `out` with the next block; false when the file is exhausted. Syntax errors are
  /// added to `diags`, and the block comes back with `has_error` set and what was recognised.
  bool next(ast::Block& out, core::DiagnosticList& diags);

  const core::SourceFile& file() const { return file_; }

  /// Off: every block through the whole grammar (rules::block), for the tests that compare the
  /// shortcut for blocks of the plain shape against it. On by default; both give the same
  /// block and diagnostics.
  void use_shortcut(bool on);

  /// Where the parser stands between two blocks: enough to resume there (a checkpoint).
  struct Position {
    std::size_t offset = 0;    ///< byte offset of the next line to read
    std::uint32_t line = 1;    ///< its 1-based line number
    std::uint8_t mode = 0;     ///< normal, in #VAR ... #ENDVAR, in #COMMENT BEGIN ... END
    core::SourceLoc mode_loc;  ///< the #VAR / #COMMENT BEGIN that opened the mode
  };
  Position position() const;
  /// Continues from a position this parser (or one of the same file) returned.
  void seek(const Position& at);

 private:
  struct Impl;
  const core::SourceFile& file_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncsim::grammar
