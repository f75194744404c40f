#pragma once
// interp/control_flow: the decoder's control flow, $IF/$ELSEIF/$ELSE, $SWITCH/$CASE/$DEFAULT,
// $FOR/$WHILE/$DO/$REPEAT with $BREAK/$CONTINUE, and $GOTO (PROG-206915851 ff.).
//
// Input: a control block at the decoder's pc (the block after it is pc). Output: the decoder's
// pc moved to the block that runs next, and the stack of open loops / $SWITCH blocks. Partners
// ($ELSE, $ENDIF, loop ends, $GOTO labels) are found lazily by scanning forward or backward in
// the same program level and remembered per site in memos of at most kMaxMemoEntries entries.
// Invariant: the stack never holds frames of a caller's level above that level's depth
// (CallFrame::control_depth); a jump never enters a loop (21480).
// The decoder (Interpreter::Impl) gives it the block stream, expression evaluation,
// variables and diagnostics; it owns nothing else of the decoder's state.

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar/ast.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter.hpp"
#include "interp/variables.hpp"

namespace ncsim::interp {

namespace ast = grammar::ast;

enum class FrameKind : std::uint8_t { for_, while_, do_, repeat, switch_ };

/// One open loop or $SWITCH.
struct ControlFrame {
  FrameKind kind = FrameKind::for_;
  std::uint16_t file = 0;
  std::uint32_t open = 0;              // ordinal of the opening block
  std::uint32_t end = 0xFFFFFFFFu;     // ordinal of the closing block, once known
  VarRef counter;                      // $FOR
  double end_value = 0.0, step = 0.0;  // $FOR
  std::uint32_t line = 0;
};

/// A $GOTO target copied out of its block (the block may leave the cache during the search).
struct GotoLabel {
  ast::GotoKind kind = ast::GotoKind::none;
  std::uint32_t number = 0;  // block number for GotoKind::block_number
  std::string name;          // label name, or the block number's digits
  bool matches(const ast::Block& b) const {
    if (kind == ast::GotoKind::block_number) {
      return b.number && b.number->is_label && b.number->number == number;
    }
    return b.label && grammar::iequals(b.label->name, name);
  }
};

/// Where a $GOTO site lands and what the jump leaves or enters, remembered per site.
struct GotoResult {
  std::uint32_t label = 0;          // ordinal of the labelled block
  bool backward = false;            // found before the $GOTO
  int closed = 0;                   // forward: loop/$SWITCH ends passed (frames left)
  std::vector<std::uint32_t> open;  // backward: openers enclosing the label
};

/// Entries each memo of jump destinations holds at most; a full memo is cleared and refilled
/// on demand, so memory does not grow with the program length.
inline constexpr std::size_t kMaxMemoEntries = 1u << 16;

/// The block is a program header (`%name`): the end of a program level.
inline bool is_header(const ast::Block* b) {
  return b != nullptr && std::holds_alternative<ast::ProgramHeader>(b->body);
}

class ControlFlow {
 public:
  explicit ControlFlow(Interpreter::Impl& decoder) : ip_(decoder) {}

  /// Runs control block `c` of block `b` (the decoder's pc is the block after it).
  bool run(const ast::Block& b, const ast::Control& c);
  /// `$GOTO target` of block `b` (also `$IF cond $GOTO` and a block's trailing $GOTO).
  bool jump_to_label(const ast::Block& b, const ast::GotoTarget& target);

  const std::vector<ControlFrame>& frames() const { return frames_; }
  /// Leaves the frames above `depth` (a subroutine returns).
  void leave_to(std::size_t depth) { frames_.resize(std::min(frames_.size(), depth)); }
  /// The line of the innermost open loop, else `otherwise` (where NC4901/NC4903 point).
  std::uint32_t loop_line(std::uint32_t otherwise) const {
    return frames_.empty() ? otherwise : frames_.back().line;
  }
  std::size_t memo_entries() const { return jump_memo_.size() + goto_memo_.size(); }

 private:
  /// Where the control block stands; read before any fetch (a search may evict the block).
  struct Site {
    std::uint32_t here = 0;  // its ordinal
    std::uint16_t file = 0;
    core::SourceLoc at;
    std::uint32_t line = 0;
  };
  bool run_if(const ast::Block& b, const ast::Control& c, const Site& s);
  bool run_switch(const ast::Block& b, const ast::Control& c, const Site& s);
  bool run_for(const ast::Block& b, const ast::Control& c, const Site& s);
  bool run_while(const ast::Block& b, const ast::Control& c, const Site& s);
  bool run_loop_end(const ast::Block& b, const ast::Control& c, const Site& s);
  bool run_break(const ast::Control& c, const Site& s);  // $BREAK / $CONTINUE
  std::size_t level_base() const;  // frames below belong to the calling levels
  std::optional<GotoResult> find_label(const GotoLabel& target, core::SourceLoc at);
  std::optional<std::uint32_t> matching_end(std::uint16_t file, std::uint32_t from,
                                            core::SourceLoc at);
  std::optional<std::uint32_t> next_if_branch(std::uint16_t file, std::uint32_t from,
                                              bool endif_only, core::SourceLoc at);
  void remember(std::uint64_t key, std::uint32_t value);

  Interpreter::Impl& ip_;
  std::vector<ControlFrame> frames_;
  std::unordered_map<std::uint64_t, std::uint32_t> jump_memo_;  // $IF/loop partners
  std::unordered_map<std::uint64_t, GotoResult> goto_memo_;     // by $GOTO site
};

}  // namespace ncsim::interp
