#pragma once
// interp/trc_words: the decoder's side of tool radius compensation (docs/trc.md); the geometry
// is interp/trc's filter behind Interpreter::next(). Input: a block's G40/G41/G42, G25/G26,
// G138/G139 and D (BlockWords), the tool list. Output: modal.trc, which every motion carries.
// Invariant: the side changes only through G40, the radius not while TRC is active (NC4704).

#include <optional>

#include "grammar/ast.hpp"
#include "interp/block_words.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

class TrcWords {
 public:
  explicit TrcWords(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool g_code(const grammar::ast::Word& w, BlockWords& bw);  // G25/G26/G40/G41/G42/G138/G139
  bool plane_change_allowed(core::SourceLoc at, Plane to);   // 20133 while TRC is active
  bool update(const BlockWords& bw);                         // D and G40/G41/G42 of the block

  std::optional<double> d_number;  // the D in force (none: D0)

 private:
  std::optional<double> tool_radius(core::SourceLoc at);  // of the D in force

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
