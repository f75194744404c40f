#pragma once
// interp/block_source: random access to the parsed blocks of one program file in bounded
// memory.
//
// Purpose: the interpreter jumps (loops, $GOTO, subroutine calls) but must not hold the whole
// parsed program. Inputs: a SourceFile. Outputs: the block with a given ordinal (0 = first
// block of the file), parsed on demand.
// Memory: the file text (owned by the caller), an index of 12 bytes per block seen so far, and
// a direct-mapped cache of kCacheSlots parsed blocks (a loop body of up to kCacheSlots blocks
// is decoded from the cache). A block evicted from the cache is re-parsed from its own text.
// Invariants: ordinals are dense and in file order; the parser only moves forward; a cached
// or re-parsed block has the same content, lines and columns as the first parse.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/ast.hpp"
#include "grammar/block_parser.hpp"

namespace ncsim::interp {

class BlockSource {
 public:
  static constexpr std::size_t kCacheSlots = 2048;  ///< power of two

  explicit BlockSource(const core::SourceFile& file);
  BlockSource(const BlockSource&) = delete;
  BlockSource& operator=(const BlockSource&) = delete;

  /// The block with this ordinal, or nullptr past the end of the file. Syntax errors of a
  /// first parse are added to `diags` (the block then has `has_error`).
  const grammar::ast::Block* fetch(std::uint32_t ordinal, core::DiagnosticList& diags);

  /// Parses `text` (one block, e.g. after macro expansion) as if it stood at `line`.
  /// The result stays valid until the next call.
  const grammar::ast::Block* parse_text(std::string text, std::uint32_t line,
                                        core::DiagnosticList& diags);

  const core::SourceFile& file() const { return file_; }
  std::size_t indexed_blocks() const { return index_.size(); }

 private:
  struct IndexEntry {
    std::uint32_t offset;  // byte offset of the block
    std::uint32_t length;  // bytes of its text; top bit: parsed in #VAR declaration mode
    std::uint32_t line;    // first line
  };
  struct Slot {
    std::uint32_t ordinal = 0xFFFFFFFFu;
    grammar::ast::Block block;
    std::unique_ptr<core::SourceFile> own;  // text of a re-parsed block
  };

  bool parse_next(Slot& slot, core::DiagnosticList& diags);
  void reparse(std::uint32_t ordinal, Slot& slot);

  const core::SourceFile& file_;
  grammar::BlockParser parser_;
  bool parser_done_ = false;
  std::vector<IndexEntry> index_;
  std::vector<Slot> slots_;
  Slot scratch_;  // parse_text result
};

/// Moves every line number of `block` by `delta` lines (a block parsed from its own text).
void shift_lines(grammar::ast::Block& block, std::uint32_t delta);

}  // namespace ncsim::interp
