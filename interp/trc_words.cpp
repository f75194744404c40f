// interp/trc_words.cpp: G40/G41/G42, G25/G26, G138/G139 and D into the TRC state a motion
// carries (docs/trc.md).
#include "interp/trc_words.hpp"

#include <cmath>

#include "core/number_text.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

bool TrcWords::g_code(const ast::Word& w, BlockWords& bw) {
  switch (w.code) {
    case 25:  // linear transition at outer corners (modal, initial state)
      ip_.modal.trc.corner = TrcCorner::linear;
      return true;
    case 26:  // circular transition
      ip_.modal.trc.corner = TrcCorner::circle;
      return true;
    case 138:  // direct selection / deselection
      ip_.modal.trc.approach = TrcApproach::direct;
      return true;
    case 139:  // indirect selection / deselection (modal, initial state)
      ip_.modal.trc.approach = TrcApproach::indirect;
      return true;
    default:
      break;
  }
  if (bw.trc_side) {  // DIAG 20114: more than one of G40/G41/G42 in a block
    return ip_.fail(w.loc, "20114",
                    "double programmed selection of tool radius compensation: G" +
                        std::to_string(w.code) + " in a block that already has G40, G41 or G42");
  }
  bw.trc_side = w.code == 40 ? TrcSide::off : (w.code == 41 ? TrcSide::left : TrcSide::right);
  bw.trc_loc = w.loc;
  return true;
}

bool TrcWords::plane_change_allowed(core::SourceLoc at, Plane to) {
  if (ip_.modal.trc.side == TrcSide::off || to == ip_.modal.plane) return true;
  return ip_.fail(at, "20133",
                  "plane selection not allowed during active tool radius compensation: deselect it "
                  "with G40 (and a deselection block) first");
}

std::optional<double> TrcWords::tool_radius(core::SourceLoc at) {
  if (!d_number || *d_number == 0.0) return 0.0;  // D0: the tool without dimensions
  const double n = *d_number;
  const std::string d = "D" + core::number_text(n);
  const auto refuse = [&](const std::string& why) {  // NC4706, the D named first
    ip_.fail(at, "NC4706", d + why);
    return std::nullopt;
  };
  if (n < 0.0 || n != std::floor(n) || n > machines::kMaxToolNumber) {
    return refuse(": a tool number is a whole number 0.." +
                  std::to_string(machines::kMaxToolNumber));
  }
  if (ip_.machine.tools.file.empty()) {
    return refuse(" for tool radius compensation, but machine " + ip_.machine.name +
                  " has no tool list (a 'tools <file>' line in machine.lis, docs/trc.md)");
  }
  const int number = static_cast<int>(n);
  const machines::Tool* tool = ip_.machine.tools.find(number);
  if (tool == nullptr) {
    return refuse(": tool " + std::to_string(number) + " is not in the tool list " +
                  ip_.machine.tools.file);
  }
  if (!tool->valid) {
    return refuse(": tool " + std::to_string(number) + " is not valid (wz[" +
                  std::to_string(number) + "].gueltig, P-TOOL-00005, is 0 in " +
                  ip_.machine.tools.file + ")");
  }
  return tool->radius;
}

bool TrcWords::update(const BlockWords& bw) {
  if (bw.d_word) d_number = *bw.d_word;
  // The D's position when it is in this block, else the G41/G42 that needs its radius.
  const core::SourceLoc at = bw.d_word ? bw.d_loc : bw.trc_loc;
  if (bw.trc_side && *bw.trc_side == TrcSide::off) {
    ip_.modal.trc.side = TrcSide::off;
    return true;
  }
  if (bw.trc_side) {
    if (ip_.modal.trc.side != TrcSide::off && ip_.modal.trc.side != *bw.trc_side) {
      return ip_.fail(bw.trc_loc, "NC4704",
                      "not supported: changing the side of tool radius compensation (G41 <-> G42) "
                      "without G40 and a deselection block between");
    }
    if (!ip_.xyz[0] || !ip_.xyz[1] || !ip_.xyz[2]) {
      const int p1 = ip_.modal.plane == Plane::xy ? 0 : (ip_.modal.plane == Plane::zx ? 2 : 1);
      const int p2 = ip_.modal.plane == Plane::xy ? 1 : (ip_.modal.plane == Plane::zx ? 0 : 2);
      if (!ip_.xyz[static_cast<std::size_t>(p1)] || !ip_.xyz[static_cast<std::size_t>(p2)]) {
        return ip_.fail(bw.trc_loc, "NC4103",
                        "the machine lacks an axis of the plane of tool radius compensation");
      }
    }
    const std::optional<double> r = tool_radius(at);
    if (!r) return false;
    ip_.modal.trc.side = *bw.trc_side;
    ip_.modal.trc.radius = *r;
    return true;
  }
  if (bw.d_word && ip_.modal.trc.side != TrcSide::off) {
    const std::optional<double> r = tool_radius(at);
    if (!r) return false;
    if (*r != ip_.modal.trc.radius) {
      return ip_.fail(bw.d_loc, "NC4704",
                      "not supported: changing the tool radius (" +
                          core::number_text(ip_.modal.trc.radius) + " -> " + core::number_text(*r) +
                          " mm) while tool radius compensation is active");
    }
  }
  return true;
}

}  // namespace ncsim::interp
