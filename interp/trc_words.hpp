#pragma once
// interp/trc_words: the decoder's side of tool radius compensation (docs/trc.md); the geometry
// is interp/trc's filter behind Interpreter::next(). Input: a block's G40/G41/G42, G25/G26,
// G138/G139 and D (BlockWords), the tool list. Output: modal.trc, which every motion carries.
// Invariant: a change of side or radius while active takes effect with the next plane motion.

#include <optional>

#include "grammar/ast.hpp"
#include "interp/block_words.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

class TrcWords {
 public:
  explicit TrcWords(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool g_code(const grammar::ast::Word& w, BlockWords& bw);  // G10/G11/G25/G26/G40..G42/G13x/G23x
  /// #TANGFEED [RMIN=..] / #SET TANGFEED RMIN [..] (PROG-207065483): G11's minimum arc radius.
  bool hash_tangfeed(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);
  bool plane_change_allowed(core::SourceLoc at, Plane to);  // 20133 while TRC is active
  bool update(const BlockWords& bw);                        // D and G40/G41/G42 of the block

  std::optional<double> d_number;  // the D in force (none: D0)

 private:
  std::optional<double> tool_radius(core::SourceLoc at);  // of the D in force

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
