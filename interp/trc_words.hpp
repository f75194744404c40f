#pragma once
// interp/trc_words: the decoder's side of tool radius compensation (docs/trc.md); the geometry
// is interp/trc's filter behind Interpreter::next(). Input: a block's G40/G41/G42, G25/G26,
// G138/G139 and D (BlockWords), the tool list. Output: modal.trc, which every motion carries.
// Invariant: a change of side or radius while active takes effect with the next plane motion.

#include <cstdint>
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
  double d_length = 0.0;  // [mm] its tool length (P-TOOL-00003); 0 without a tool list or D0

  /// The tool length offset of machine axis `axis` [mm]: d_length in the third main axis of the
  /// plane in force (G17 Z, G18 Y, G19 X, direction +; TF5200 "#TLAX"), else 0.
  double length_offset(std::uint8_t axis) const;

 private:
  std::optional<double> tool_radius(core::SourceLoc at);  // of the D in force

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
