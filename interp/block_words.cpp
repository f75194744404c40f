// interp/block_words.cpp: a block's G codes (read_flag_g: those that only set a modal state or
// a flag) and addresses, and the dynamics weightings they carry.
#include "interp/block_words.hpp"

#include <array>
#include <cmath>

#include "core/number_text.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"
#include "interp/weights.hpp"

namespace ncsim::interp {
namespace {

constexpr double kInch = 25.4;  // [mm/inch] (G70, PROG-206272267)

/// The G codes that set a modal state or a flag of the block and nothing else; false: `code`
/// is not one of them.
bool read_flag_g(std::uint32_t code, ModalSnapshot& modal, bool& centre_absolute, BlockWords& bw) {
  constexpr std::array<MotionKind, 4> kMotion{MotionKind::rapid, MotionKind::linear,
                                              MotionKind::arc_cw, MotionKind::arc_ccw};
  switch (code) {
    case 0:
    case 1:
    case 2:
    case 3:
      bw.motion_word = kMotion[code];
      return true;
    case 4:
      bw.g04 = true;
      return true;
    case 8:
      modal.transition = Transition::accelerate_at_start;
      return true;
    case 9:
      bw.g09 = true;
      return true;
    case 900:
      modal.transition = Transition::decel_at_end;
      return true;
    case 901:
      modal.transition = Transition::decel_after_end;
      return true;
    case 60:
      bw.g60 = true;
      return true;
    case 61:
      bw.g61 = true;
      return true;
    case 359:
    case 360:
      modal.exact_stop = code == 360;
      return true;
    case 260:
    case 261:
      modal.contouring = code == 261;
      return true;
    case 70:
    case 71:
      modal.inch = code == 70;
      return true;
    case 74:
      bw.g74 = true;
      return true;
    case 90:
    case 91:
      modal.incremental = code == 91;
      return true;
    case 92:
      bw.g92 = true;
      return true;
    case 93:
    case 94:
      modal.feed_mode = code == 93 ? FeedMode::inverse_time : FeedMode::per_minute;
      return true;
    case 161:
    case 162:
      centre_absolute = code == 161;
      return true;
    case 163:
    case 164:
    case 165:
    case 115:
    case 116:
    case 117:
      return true;  // accepted, no effect
    default:
      return false;
  }
}

/// Dynamics weightings: velocity per axis / group / rapid G127..G129 (PROG-206578955 ...),
/// acceleration G130/G131/G230/G231/G333/G334 (PROG-206590731), ramp time G132..G134, G233,
/// G338/G339.
bool is_weighting_g(std::uint32_t code) {
  return (code >= 127 && code <= 134) || code == 230 || code == 231 || code == 233 || code == 333 ||
         code == 334 || code == 338 || code == 339;
}

}  // namespace

bool WordReader::read(const ast::Block& b, BlockWords& bw) {
  bw.clear();
  return read_g_codes(b, bw) && read_addresses(b, bw);
}

void WordReader::apply_weightings(const BlockWords& bw) {
  DynamicsWeights w = ip_.modal.weights ? *ip_.modal.weights : DynamicsWeights{};
  for (const BlockWords::Weighting& g : bw.weightings) {
    for (std::string& note : apply_weighting(w, g.code, g.group, bw.axis_words, ip_.machine.axes))
      ip_.warn(g.loc, "NC4314", std::move(note));
  }
  if (w == DynamicsWeights{})
    ip_.modal.weights.reset();
  else
    ip_.modal.weights = std::make_shared<const DynamicsWeights>(w);
}

bool WordReader::read_g_codes(const ast::Block& b, BlockWords& bw) {
  for (const ast::Word& w : b.words) {
    if (w.kind != ast::WordKind::g) continue;
    if (read_flag_g(w.code, ip_.modal, ip_.centre_absolute, bw)) continue;
    if (is_weighting_g(w.code)) {
      if (!read_weighting(b, w, bw)) return false;
      continue;
    }
    switch (w.code) {
      case 17:
      case 18:
      case 19: {
        const Plane plane = w.code == 17 ? Plane::xy : (w.code == 18 ? Plane::zx : Plane::yz);
        if (!ip_.trc_words.plane_change_allowed(w.loc, plane)) return false;
        ip_.modal.plane = plane;
        break;
      }
      case 150:  // = #SPLINE OFF (PROG-207216267): a point in this block is not a vertex
        if (!ip_.spline_off(w.loc)) return false;
        break;
      case 151:  // = #SPLINE ON (PROG-207209611)
        if (!ip_.spline_on(w.loc)) return false;
        break;
      case 53:
      case 54:
      case 55:
      case 56:
      case 57:
      case 58:
      case 59:
      case 159:
        if (!ip_.offsets.select_zero_offset(b, w)) return false;
        break;
      case 25:
      case 26:
      case 40:
      case 41:
      case 42:
      case 138:
      case 139:
      case 237:
      case 239:
      case 10:
      case 11:
        if (!ip_.trc_words.g_code(w, bw)) return false;  // trc_words.cpp
        break;
      default:
        if (grammar::is_implicit_call_g(w.code)) {
          if (!ip_.subs.read_implicit_call(b, w)) return false;
          break;
        }
        return ip_.fail(w.loc, "NC4102",
                        "G" + std::to_string(w.code) + " is not supported by ncsim");
    }
  }
  return true;
}

bool WordReader::read_weighting(const ast::Block& b, const ast::Word& w, BlockWords& bw) {
  // Axis-specific forms (G130 X70) give weights, not positions; the group forms
  // (G131=50) leave the block's axis words positions. Applied after the addresses are
  // read (run_words, interp/weights.hpp).
  std::optional<double> group;
  if (is_axis_weighting(w.code)) {
    bw.weights_axes = true;
  } else if (w.value != ast::kNoNode) {
    group = ip_.eval(b, w.value);
    if (!group) return false;
  }
  if (is_applied_weighting(w.code)) {
    bw.weightings.push_back({w.code, group, w.loc});
    return true;
  }
  if (!said_g_.insert(w.code).second) return true;  // said once per code
  const std::string g = "G" + std::to_string(w.code);
  if (is_feedhold_weighting(w.code)) {
    // PROG-206590731 / PROG-206596619: the feed-hold weightings scale the feed-hold ramps
    // P-AXIS-00053 / P-AXIS-00081, which a feed hold uses only with P-CHAN-00097 = 1. ncsim's
    // channel is P-CHAN-00097 = 0 (the default; 1 is NC3013 at load): a feed hold decelerates
    // at the currently valid deceleration, so the weighting changes nothing, as on the kernel.
    ip_.warn(w.loc, "NC4315",
             g + " (feed-hold " + (w.code <= 334 ? "acceleration" : "ramp time") +
                 " weighting) acts on the feed-hold ramps P-AXIS-00053 / P-AXIS-00081, which "
                 "a feed hold uses only with P-CHAN-00097 = 1; this channel decelerates a feed "
                 "hold at the currently valid deceleration (P-CHAN-00097 = 0), so " +
                 g + " changes nothing",
             core::Severity::note);
  } else {
    // G134: P-AXIS-00199 (the contour's jerk bound) is not a limit ncsim's planner applies.
    ip_.warn(w.loc, "NC4313",
             g + " (geometric ramp time weighting, P-AXIS-00199) is not modelled by ncsim: its "
                 "planner does not bound the contour jerk by the geometric ramp time, so there "
                 "is nothing to weight (G132 / G133 weight the feed ramps)");
  }
  return true;
}

bool WordReader::additional_value(const ast::Block& b, const ast::Word& w,
                                  std::optional<double>& out) {
  out.reset();
  if (w.extra == ast::kNoNode) return true;
  // TF5200 "M/H functions with optional additional information": a negative or positive
  // integer (ncsim: within SGN32), not for the spindle functions M03/M04/M05/M19 and the gear
  // stages M40-M45.
  const std::string name = (w.kind == ast::WordKind::h ? "H" : "M");
  auto code = ip_.eval(b, w.value);
  if (!code) return false;
  const long m = std::lround(*code);
  if (w.kind == ast::WordKind::m &&
      (m == 3 || m == 4 || m == 5 || m == 19 || (m >= 40 && m <= 45))) {
    return ip_.fail(
        w.loc, "NC4033",
        "M" + std::to_string(m) + " takes no additional value (spindle and gear functions)");
  }
  auto v = ip_.eval(b, w.extra);
  if (!v) return false;
  if (!(std::abs(*v) <= 2147483647.0) || *v != std::trunc(*v)) {
    return ip_.fail(b.exprs[w.extra].loc, "NC4033",
                    "the additional value of " + name + core::number_text(*code) +
                        " must be a whole number in -2147483648..2147483647, not " +
                        core::number_text(*v));
  }
  out = *v;
  return true;
}

bool WordReader::has_d_word(const ast::Block& b) {
  for (const ast::Word& w : b.words)
    if (w.kind == ast::WordKind::d) return true;
  return false;
}

bool WordReader::read_d(double d, const core::SourceLoc& loc, BlockWords& bw) {
  bool called = false;  // P-CHAN-00429: a D word may also call a subroutine
  if (!ip_.subs.read_word_call(WordCall::d, loc, called)) return false;
  bw.tech.push_back(Tech{TechKind::d, d, {}});
  bw.d_word = d;  // the tool for TRC (trc_words.cpp)
  bw.d_loc = loc;
  return true;
}

bool WordReader::read_addresses(const ast::Block& b, BlockWords& bw) {
  bw.unit = ip_.modal.inch ? kInch : 1.0;
  const double unit = bw.unit;
  for (const ast::Word& w : b.words) {
    if (w.kind == ast::WordKind::g || w.kind == ast::WordKind::assignment ||
        w.kind == ast::WordKind::macro_def) {
      continue;
    }
    auto v = ip_.eval(b, w.value);
    if (!v) return false;
    if (!std::isfinite(*v * unit)) {  // G70: a finite inch value beyond the mm range
      return ip_.fail(w.loc, "NC4101",
                      "value " + core::number_text(*v) + " is out of range in millimetres (G70)");
    }
    switch (w.kind) {
      case ast::WordKind::f:
        // A feed or block time of 0 would never end the block (decision, docs/interp.md).
        if (*v <= 0.0) {
          return ip_.fail(
              w.loc, "NC4030",
              std::string(ip_.modal.feed_mode == FeedMode::inverse_time ? "block time" : "feed") +
                  " F" + core::number_text(*v) + " must be greater than 0");
        }
        if (ip_.modal.feed_mode == FeedMode::inverse_time) {
          if (!(*v <= core::kLongestTime)) {
            return ip_.fail(w.loc, "NC4032", longest_time_text("G93 block time", *v));
          }
          bw.block_time = *v;  // G93: seconds (PROG-206602507)
        } else {
          // F in mm/min by default; P-CHAN-00108 sets another unit (F x 100 / factor mm/min)
          ip_.feed = *v * unit * (100.0 / ip_.machine.channel.feedrate_factor) / 60.0;
        }
        break;
      case ast::WordKind::e:
        if (*v < 0.0) {  // E0 is a stop at the block end; a negative feed is none
          return ip_.fail(w.loc, "NC4030", "end feed E" + core::number_text(*v) + " is negative");
        }
        bw.end_feed = *v * unit / 60.0;
        break;
      case ast::WordKind::s:
        if (*v < 0.0) {  // the direction is M03/M04's, the speed a magnitude
          return ip_.fail(w.loc, "NC4030",
                          "spindle speed S" + core::number_text(*v) + " is negative");
        }
        bw.tech.push_back(Tech{TechKind::s, *v, {}});
        break;
      case ast::WordKind::t:
        bw.tech.push_back(Tech{TechKind::t, *v, {}});
        // P-CHAN-00014 einrechnen_mit_t: "T80" is "T80 D80". Decision: a D programmed in the
        // same block is the one executed (docs/interp.md "Cycles").
        if (ip_.machine.channel.d_with_t && !has_d_word(b) && !read_d(*v, w.loc, bw)) return false;
        break;
      case ast::WordKind::d:
        if (!read_d(*v, w.loc, bw)) return false;
        break;
      case ast::WordKind::h:
      case ast::WordKind::m: {
        std::optional<double> extra;
        if (!additional_value(b, w, extra)) return false;
        const int code = static_cast<int>(std::lround(*v));
        bool called = false;
        if (w.kind == ast::WordKind::m && *v == 6.0 && !extra &&
            !ip_.subs.read_word_call(WordCall::m6, w.loc, called)) {
          return false;
        }
        if (w.kind == ast::WordKind::h) {
          bw.tech.push_back(Tech{TechKind::h, *v, extra});
        } else if (called) {
          // P-CHAN-00118: M6 calls its subroutine and is no M function (no technology process)
        } else if (code == 0 || code == 1 || code == 2 || code == 30 || code == 17 || code == 29) {
          bw.program_m = code;  // an additional value goes to the PLC with it (not modelled)
        } else {
          bw.tech.push_back(Tech{TechKind::m, *v, extra});
        }
        break;
      }
      case ast::WordKind::i:
        bw.ijk[0] = *v * unit;
        break;
      case ast::WordKind::j:
        bw.ijk[1] = *v * unit;
        break;
      case ast::WordKind::k:
        bw.ijk[2] = *v * unit;
        break;
      case ast::WordKind::r:
        bw.radius = *v * unit;
        break;
      case ast::WordKind::bare_value:
        bw.bare = *v;
        break;
      case ast::WordKind::axis: {
        auto index = ip_.axis_index(w.name);
        if (!index) {
          return ip_.fail(
              w.loc, "NC4103",
              "axis " + std::string(w.name) + " does not exist on machine " + ip_.machine.name);
        }
        bw.axis_words.emplace_back(*index, *v);
        break;
      }
      default:
        break;
    }
  }
  return true;
}

}  // namespace ncsim::interp
