// interp/trc_words.cpp: G40/G41/G42, G25/G26, G138/G139/G237/G239, G10/G11, #TANGFEED and D
// into the TRC state a motion carries (docs/trc.md).
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
    case 237:  // perpendicular selection / deselection
      ip_.modal.trc.approach = TrcApproach::perpendicular;
      return true;
    case 239:  // direct selection, deselection without a block
      ip_.modal.trc.approach = TrcApproach::no_block;
      return true;
    case 10:  // constant feed (modal, initial state)
    case 11:  // feed adapted: F on the contour of compensated arcs
      ip_.modal.trc.adapt_feed = w.code == 11;
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

bool TrcWords::hash_tangfeed(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const ast::Item* it = items.find("RMIN");
  if (it == nullptr && h.item_count > 0 && b.items[0].keyword.empty()) it = &b.items[0];
  if (it == nullptr) {  // "#TANGFEED" alone: no minimum radius (G11 on every arc)
    ip_.modal.trc.tangfeed_rmin = 0.0;
    return true;
  }
  const std::optional<double> v = ip_.hash.item_value(b, it);
  if (!v) return false;
  if (!(*v >= 0.0) || !std::isfinite(*v)) {
    return ip_.fail(it->loc, "NC4030",
                    "#TANGFEED RMIN must be a radius >= 0, got " + core::number_text(*v));
  }
  ip_.modal.trc.tangfeed_rmin = *v * (ip_.modal.inch ? 25.4 : 1.0);
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

double TrcWords::length_offset(std::uint8_t axis) const {
  if (d_length == 0.0) return 0.0;
  const Plane p = ip_.modal.plane;
  const std::size_t third = p == Plane::xy ? 2 : (p == Plane::zx ? 1 : 0);
  return ip_.xyz[third] == axis ? d_length : 0.0;
}

bool TrcWords::update(const BlockWords& bw) {
  // The D's position when it is in this block, else the G41/G42 that needs its radius.
  const core::SourceLoc at = bw.d_word ? bw.d_loc : bw.trc_loc;
  if (bw.d_word) {
    d_number = *bw.d_word;
    // Tool length compensation (TF5200 "Tool geometry compensation"): the D's length acts in
    // the tool axis from that axis's next absolute value (P-CHAN-00100 = 0, the default; the
    // zero offsets carry it, interp/offsets.cpp). Without a tool list D is a plain function.
    d_length = 0.0;
    if (!ip_.machine.tools.file.empty()) {
      if (!tool_radius(at)) return false;  // NC4706: a D the list does not release
      if (*d_number != 0.0) d_length = ip_.machine.tools.find(static_cast<int>(*d_number))->length;
    }
  }
  if (bw.trc_side && *bw.trc_side == TrcSide::off) {
    ip_.modal.trc.side = TrcSide::off;
    return true;
  }
  if (bw.trc_side) {
    // G41 <-> G42 without G40: a deselection and a selection in the next plane motion
    // (TF5200 "Reaction on contour change"; interp/trc).
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
    // A new radius while active: taken with the next plane motion, which must be linear
    // (TF5200 "Reaction to change in tool radius"; interp/trc).
    const std::optional<double> r = tool_radius(at);
    if (!r) return false;
    ip_.modal.trc.radius = *r;
  }
  return true;
}

}  // namespace ncsim::interp
