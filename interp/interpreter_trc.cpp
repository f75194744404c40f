// interp/interpreter_trc.cpp: the decoder's side of tool radius compensation (docs/trc.md):
// G40/G41/G42, G25/G26, G138/G139 and D set the TRC state every motion carries in
// ModalSnapshot::trc; the geometry is interp/trc's filter behind Interpreter::next().
#include <cmath>

#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

bool Interpreter::Impl::trc_g_code(const ast::Word& w, BlockWords& bw) {
  switch (w.code) {
    case 25:  // linear transition at outer corners (modal, initial state)
      modal.trc.corner = TrcCorner::linear;
      return true;
    case 26:  // circular transition
      modal.trc.corner = TrcCorner::circle;
      return true;
    case 138:  // direct selection / deselection
      modal.trc.approach = TrcApproach::direct;
      return true;
    case 139:  // indirect selection / deselection (modal, initial state)
      modal.trc.approach = TrcApproach::indirect;
      return true;
    default:
      break;
  }
  if (bw.trc_side) {  // DIAG 20114: more than one of G40/G41/G42 in a block
    return fail(w.loc, "20114",
                "double programmed selection of tool radius compensation: G" +
                    std::to_string(w.code) + " in a block that already has G40, G41 or G42");
  }
  bw.trc_side = w.code == 40 ? TrcSide::off : (w.code == 41 ? TrcSide::left : TrcSide::right);
  bw.trc_loc = w.loc;
  return true;
}

bool Interpreter::Impl::plane_change_allowed(core::SourceLoc at, Plane to) {
  if (modal.trc.side == TrcSide::off || to == modal.plane) return true;
  return fail(at, "20133",
              "plane selection not allowed during active tool radius compensation: deselect it "
              "with G40 (and a deselection block) first");
}

std::optional<double> Interpreter::Impl::tool_radius(core::SourceLoc at) {
  if (!d_number || *d_number == 0.0) return 0.0;  // D0: the tool without dimensions
  const double n = *d_number;
  const std::string d = "D" + core::number_text(n);
  if (n < 0.0 || n != std::floor(n) || n > machines::kMaxToolNumber) {
    fail(at, "NC4706",
         d + ": a tool number is a whole number 0.." + std::to_string(machines::kMaxToolNumber));
    return std::nullopt;
  }
  if (machine.tools.file.empty()) {
    fail(at, "NC4706",
         d + " for tool radius compensation, but machine " + machine.name +
             " has no tool list (a 'tools <file>' line in machine.lis, docs/trc.md)");
    return std::nullopt;
  }
  const int number = static_cast<int>(n);
  const machines::Tool* tool = machine.tools.find(number);
  if (tool == nullptr) {
    fail(at, "NC4706",
         d + ": tool " + std::to_string(number) + " is not in the tool list " + machine.tools.file);
    return std::nullopt;
  }
  if (!tool->valid) {
    fail(at, "NC4706",
         d + ": tool " + std::to_string(number) + " is not valid (wz[" + std::to_string(number) +
             "].gueltig, P-TOOL-00005, is 0 in " + machine.tools.file + ")");
    return std::nullopt;
  }
  return tool->radius;
}

bool Interpreter::Impl::update_trc(const BlockWords& bw) {
  if (bw.d_word) {
    d_number = *bw.d_word;
    d_loc = bw.d_loc;
  }
  // The D's position when it is in this block, else the G41/G42 that needs its radius.
  const core::SourceLoc at = bw.d_word ? bw.d_loc : bw.trc_loc;
  if (bw.trc_side && *bw.trc_side == TrcSide::off) {
    modal.trc.side = TrcSide::off;
    return true;
  }
  if (bw.trc_side) {
    if (modal.trc.side != TrcSide::off && modal.trc.side != *bw.trc_side) {
      return fail(bw.trc_loc, "NC4704",
                  "not supported: changing the side of tool radius compensation (G41 <-> G42) "
                  "without G40 and a deselection block between");
    }
    if (!xyz[0] || !xyz[1] || !xyz[2]) {
      const int p1 = modal.plane == Plane::xy ? 0 : (modal.plane == Plane::zx ? 2 : 1);
      const int p2 = modal.plane == Plane::xy ? 1 : (modal.plane == Plane::zx ? 0 : 2);
      if (!xyz[static_cast<std::size_t>(p1)] || !xyz[static_cast<std::size_t>(p2)]) {
        return fail(bw.trc_loc, "NC4103",
                    "the machine lacks an axis of the plane of tool radius compensation");
      }
    }
    const std::optional<double> r = tool_radius(at);
    if (!r) return false;
    modal.trc.side = *bw.trc_side;
    modal.trc.radius = *r;
    return true;
  }
  if (bw.d_word && modal.trc.side != TrcSide::off) {
    const std::optional<double> r = tool_radius(at);
    if (!r) return false;
    if (*r != modal.trc.radius) {
      return fail(bw.d_loc, "NC4704",
                  "not supported: changing the tool radius (" +
                      core::number_text(modal.trc.radius) + " -> " + core::number_text(*r) +
                      " mm) while tool radius compensation is active");
    }
  }
  return true;
}

}  // namespace ncsim::interp
