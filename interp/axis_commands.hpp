#pragma once
// interp/axis_commands: the axis-bracket commands of a block, one function per kind:
// X[INDP_SYN ...] / X[INDP_ASYN ...] (isg-language.md §6.1), S1[MC_MoveVelocity ...]
// (PROG-208363915), S1[MC_TouchProbe ...] (PROG-306968203).
//
// Input: a block's axis commands. Output: AxisCommand, MoveVelocity and ProbeArm commands
// emitted through the decoder, the decoder's position and unknown axes after an INDP move.

#include <cstdint>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

class AxisCommands {
 public:
  explicit AxisCommands(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool run(const grammar::ast::Block& b);  // every axis command of `b`, in order

 private:
  using Block = grammar::ast::Block;
  bool axis_indp(const Block& b, const grammar::ast::AxisCommand& ac, std::uint8_t axis);
  bool axis_move_velocity(const Block& b, const grammar::ast::AxisCommand& ac, std::uint8_t axis);
  bool axis_touch_probe(const Block& b, const grammar::ast::AxisCommand& ac, std::uint8_t axis);

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
