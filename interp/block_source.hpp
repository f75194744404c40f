#pragma once
// interp/block_source: random access to the parsed blocks of one program file in bounded
// memory.
//
// Purpose: the interpreter jumps (loops, $GOTO, subroutine calls) but must not hold the whole
// parsed program. Inputs: a SourceFile. Outputs: the block with a given ordinal (0 = first
// block of the file), parsed on demand.
// Memory, independent of the program length in practice: a direct-mapped cache of
// kCacheSlots parsed blocks (a loop body of up to kCacheSlots blocks is decoded from the
// cache), and one checkpoint (16 bytes: parser position) per kCheckpointStride blocks seen.
// A block that is not cached is re-parsed from the nearest checkpoint before it by a second
// parser, which then goes on forward, so re-reading a stretch of program after a backward jump
// costs one parse per block. The text stays in the (mapped) file; blocks point into it.
// Invariants: ordinals are dense and in file order; the first parser only moves forward; a
// cached or re-parsed block has the same content, lines and columns as the first parse.

#include <cstdint>
#include <memory>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/ast.hpp"
#include "grammar/block_parser.hpp"
#include "grammar/check.hpp"

namespace ncsim::interp {

class BlockSource {
 public:
  static constexpr std::size_t kCacheSlots = 2048;         ///< power of two
  static constexpr std::uint32_t kCheckpointStride = 256;  ///< blocks between checkpoints

  explicit BlockSource(const core::SourceFile& file);
  BlockSource(const BlockSource&) = delete;
  BlockSource& operator=(const BlockSource&) = delete;

  /// The block with this ordinal, or nullptr past the end of the file. Syntax errors of a
  /// first parse are added to `diags` (the block then has `has_error`). The pointer stays
  /// valid until the next fetch (another fetch may reuse its cache slot).
  const grammar::ast::Block* fetch(std::uint32_t ordinal, core::DiagnosticList& diags);

  /// Parses `text` (one block, e.g. after macro expansion) as if it stood at `line`.
  /// The result stays valid until the next call.
  const grammar::ast::Block* parse_text(std::string text, std::uint32_t line,
                                        core::DiagnosticList& diags);

  /// Feeds every block of the first parse to `check` (syntax diagnostics to check.found(),
  /// copied into fetch()'s `diags` too), so that `ncsim check` parses the program once. Call
  /// before the first fetch(); `check` must outlive this source.
  void share_first_parse(grammar::ProgramCheck& check) { check_ = &check; }
  /// Runs the first parse to the end of the file (the blocks the program did not reach).
  void parse_rest();

  const core::SourceFile& file() const { return file_; }
  /// Checkpoints held (one per kCheckpointStride blocks parsed so far).
  std::size_t indexed_blocks() const { return checkpoints_.size(); }

 private:
  struct Slot {
    std::uint32_t ordinal = 0xFFFFFFFFu;
    grammar::ast::Block block;
  };

  bool parse_next(Slot& slot, core::DiagnosticList& diags);
  void reparse(std::uint32_t ordinal, Slot& slot);

  const core::SourceFile& file_;
  grammar::BlockParser parser_;  // first parse, forward only
  bool parser_done_ = false;
  std::uint32_t parsed_ = 0;  // blocks the first parser has delivered
  std::vector<grammar::BlockParser::Position> checkpoints_;  // before block k * stride
  grammar::BlockParser reparser_;                            // re-reads blocks that left the cache
  std::uint32_t reparser_next_ = 0xFFFFFFFFu;                // ordinal reparser_ delivers next
  std::vector<Slot> slots_;
  grammar::ast::Block skipped_;  // blocks the re-parser passes on its way
  Slot scratch_;                 // parse_text result
  std::unique_ptr<core::SourceFile> scratch_file_;
  grammar::ProgramCheck* check_ = nullptr;  // share_first_parse(), else none
};

/// Moves every line number of `block` by `delta` lines (a block parsed from its own text).
void shift_lines(grammar::ast::Block& block, std::uint32_t delta);

}  // namespace ncsim::interp
