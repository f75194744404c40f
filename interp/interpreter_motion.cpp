// interp/interpreter_motion.cpp: a block's motion: the target from the axis words, the Motion
// command in the current frame with its start (the re-based current position, see
// interp/frames.cpp), arc centres from I/J/K or R, spline points.
#include <cmath>
#include <numbers>

#include "core/tolerance.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

// A spline vertex the planner drops as a repeat of the one before: every axis within
// kSamePoint (planner/spline.cpp).
bool same_spline_point(const AxisValues& a, const AxisValues& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > kSamePoint) return false;
  return true;
}

}  // namespace

bool Interpreter::Impl::run_block_motion(const ast::Block& b, const BlockWords& bw) {
  if (bw.axis_words.empty() && !bw.motion_word && !bw.g60) return true;  // no motion here
  if (bw.weights_axes) return true;  // G130 X70: the axis words were weights
  offsets.follow_cs_base();
  AxisValues target = position;
  AxisMask programmed = 0;
  if (bw.motion_word) motion = *bw.motion_word;
  for (const auto& [axis, value] : bw.axis_words) {
    const bool rotary = machine.axes[axis].kind == machines::AxisKind::rotary;
    // #SCALE scales the programmed value about the active zero point; the zero offset then
    // takes effect at the next absolute value (PROG-206487307: G91 values do not move by it).
    const double v = value * (rotary ? 1.0 : bw.unit) * offsets.scale_of(axis);
    target[axis] = modal.incremental ? position[axis] + v : v + offsets.axis_offset(axis);
    if (!std::isfinite(target[axis])) {  // G91: the sum left the range of a double
      return fail(b.loc, "NC4101",
                  "target of axis " + machine.axes[axis].name + " is not a finite number");
    }
    programmed |= AxisMask{1} << axis;
  }
  const bool arc = motion == MotionKind::arc_cw || motion == MotionKind::arc_ccw;
  AxisMask absolute = modal.incremental ? 0 : programmed;  // values the zero offset shifts
  for (std::size_t k = 0; k < 3; ++k) {  // G161: absolute centres shift too (make_arc)
    if (arc && centre_absolute && bw.ijk[k] && xyz[k]) absolute |= AxisMask{1} << *xyz[k];
  }
  if (!offsets.check_offsets_frame(b, absolute)) return false;
  if (programmed != 0 || (arc && bw.motion_word && (bw.ijk[0] || bw.ijk[1] || bw.ijk[2]))) {
    const BlockMotionWords words{bw.g09, bw.g60, bw.g61, bw.block_time, bw.end_feed};
    std::array<std::optional<double>, 3> ijk = bw.ijk;
    std::optional<double> radius = bw.radius;
    if (offsets.scale_on && arc && !offsets.scale_arc(b, ijk, radius)) return false;
    if (!run_motion(b, motion, target, programmed, ijk, radius, words)) return false;
  } else if (bw.g60) {
    return fail(b.loc, "20003", "G60 without a motion in the block");
  }
  return true;
}

bool Interpreter::Impl::run_motion(const ast::Block& b, MotionKind kind, const AxisValues& target,
                                   AxisMask programmed,
                                   const std::array<std::optional<double>, 3>& ijk,
                                   std::optional<double> radius, const BlockMotionWords& words) {
  const bool arc = kind == MotionKind::arc_cw || kind == MotionKind::arc_ccw;
  if (modal.synchronised && !motion_since_sync) {
    // seed 004 §2.1.1: the first motion after #SYNC IN must be G00 or G01.
    if (arc) return fail(b.loc, "NC4502", "the first motion after #SYNC IN must be G00 or G01");
    motion_since_sync = true;
  }
  departure_pending = false;
  if (spline && !arc) {
    if (!feed) return fail(b.loc, "20008", "the spline needs a feed F");
    emit(line, SplinePoint{spline->points, frames.frame(), target, programmed, *feed});
    ++spline->points;
    if (!same_spline_point(position, target)) ++spline->distinct;
    position = target;
    blocks_without_motion = 0;
    return true;
  }
  if (spline) return fail(b.loc, "NC4402", "G02/G03 inside #SPLINE ON ... OFF is not supported");
  if (kind != MotionKind::rapid && modal.feed_mode == FeedMode::per_minute && !feed) {
    return fail(b.loc, "20008", "the first G01/G02/G03 needs a feed F (DIAG-20008)");
  }
  // G93: F is this block's machining time; a block without one has none (an earlier feed is
  // no time; decision, docs/interp.md).
  if (kind != MotionKind::rapid && modal.feed_mode == FeedMode::inverse_time && !words.block_time) {
    return fail(b.loc, "20008",
                "under G93 every G01/G02/G03 block needs its machining time F [s] (DIAG-20008)");
  }
  // Built where it is queued; taken back on an error below.
  Motion& m = pending.emplace_default<Motion>(line, current_file);
  m.kind = kind;
  m.frame = frames.frame();
  m.start = position;
  m.end = target;
  m.programmed = programmed;
  m.feed = kind == MotionKind::rapid ? 0.0 : feed.value_or(0.0);
  if (offsets.vector_vel && kind != MotionKind::rapid)
    m.feed = std::min(m.feed, *offsets.vector_vel);
  m.modal = snapshot();
  if (words.stop_at_end) m.modal.transition = Transition::stop_at_end;
  m.modal.exact_stop = m.modal.exact_stop || words.exact_stop;
  m.modal.contouring = m.modal.contouring || words.contour;
  m.block_time = words.block_time;
  m.end_feed = words.end_feed;
  if (arc) {
    m.arc = make_arc(b, kind, target, ijk, radius);
    if (!m.arc) {
      pending.pop_back();
      return false;
    }
  }
  if (kind != MotionKind::rapid && modal.feed_mode == FeedMode::per_minute && m.feed > 0.0) {
    // The block's time at its feed, from a lower bound of its length (the X/Y/Z chord; a full
    // circle's circumference): beyond ncsim's longest time it is an error here, as for a
    // dwell, instead of a run of days (issue 34 item 19; docs/interp.md "The longest time").
    // The sum of |dX|, |dY|, |dZ| is no shorter than the chord: when even that is well within
    // the longest time, so is the chord, and its three hypot() calls are not needed.
    double bound = 0.0;  // [mm]
    for (const auto& a : xyz) {
      if (a) bound += std::fabs(target[*a] - position[*a]);
    }
    const bool full_circle = m.arc && m.arc->full_circle;
    if (full_circle || !(bound / m.feed <= 0.5 * core::kLongestTime)) {
      double length = 0.0;  // [mm]
      for (const auto& a : xyz) {
        if (a) length = std::hypot(length, target[*a] - position[*a]);
      }
      if (full_circle) length = 2.0 * std::numbers::pi * m.arc->radius;
      const double t_feed = length / m.feed;  // [s]
      if (!(t_feed <= core::kLongestTime)) {
        std::string message =
            longest_time_text("the motion time at F" + core::number_text(m.feed * 60.0) + " (" +
                                  core::number_text(length) + " mm)",
                              t_feed);
        pending.pop_back();  // m with it
        return fail(b.loc, "NC4032", std::move(message));
      }
    }
  }
  // A zero-length G00/G01 moves nothing (the planner drops it), so it is no progress for
  // NC4901 / NC4903: a loop of them would otherwise decode forever while the run stands
  // (issue 34 item 2; docs/interp.md "Endless loops").
  if (arc || target != position) blocks_without_motion = 0;
  position = target;
  return true;
}

std::optional<Arc> Interpreter::Impl::make_arc(const ast::Block& b, MotionKind kind,
                                               const AxisValues& target,
                                               const std::array<std::optional<double>, 3>& ijk,
                                               std::optional<double> radius) {
  const auto fail_arc = [&](core::SourceLoc at, const char* id, std::string message) {
    fail(at, id, std::move(message));
    return std::nullopt;
  };
  // Plane axes (PROG-206253067): G17 X/Y, G18 Z/X, G19 Y/Z; I/J/K belong to X/Y/Z.
  const int p1 = modal.plane == Plane::xy ? 0 : (modal.plane == Plane::zx ? 2 : 1);
  const int p2 = modal.plane == Plane::xy ? 1 : (modal.plane == Plane::zx ? 0 : 2);
  if (!xyz[p1] || !xyz[p2]) {
    return fail_arc(b.loc, "NC4103", "the machine lacks an axis of the circle plane");
  }
  const std::uint8_t a1 = *xyz[p1], a2 = *xyz[p2];
  const double s1 = position[a1], s2 = position[a2];
  const double e1 = target[a1], e2 = target[a2];
  const double d1 = e1 - s1, d2 = e2 - s2;
  const double chord = std::hypot(d1, d2);
  if (!std::isfinite(chord)) {
    return fail_arc(b.loc, "NC4101", "circle end point too far from its start for a double");
  }
  double c1 = 0.0, c2 = 0.0;
  const bool full = chord < kSamePoint;
  if (radius) {
    // TC2 R programming (isg-language.md §2.2): R > 0 short arc, R < 0 long arc.
    if (full) return fail_arc(b.loc, "20034", "a full circle cannot be programmed with R");
    const double r = std::fabs(*radius);
    if (chord > 2.0 * r + options.centre_diff_max) {
      return fail_arc(b.loc, "NC4202",
                      "radius R" + core::number_text(*radius) + " is smaller than half the chord");
    }
    const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4.0));
    const double n1 = -d2 / chord, n2 = d1 / chord;  // left normal of the chord
    const bool ccw = kind == MotionKind::arc_ccw;
    const double side = (ccw == (*radius > 0.0)) ? 1.0 : -1.0;
    c1 = (s1 + e1) / 2.0 + side * h * n1;
    c2 = (s2 + e2) / 2.0 + side * h * n2;
  } else {
    const auto& o1 = ijk[static_cast<std::size_t>(p1)];
    const auto& o2 = ijk[static_cast<std::size_t>(p2)];
    // G161: absolute centre coordinates, shifted by the zero offset as axis values are.
    const auto shift = [&](int p) {
      const auto& a = xyz[static_cast<std::size_t>(p)];
      return a ? offsets.axis_offset(*a) : 0.0;
    };
    c1 = centre_absolute ? (o1 ? *o1 + shift(p1) : s1) : s1 + o1.value_or(0.0);
    c2 = centre_absolute ? (o2 ? *o2 + shift(p2) : s2) : s2 + o2.value_or(0.0);
    const double r_start = std::hypot(s1 - c1, s2 - c2);
    const double r_end = std::hypot(e1 - c1, e2 - c2);
    const double diff = std::fabs(r_end - r_start);
    // P-CHAN-00059 / P-CHAN-00060 (PROG-206551563): beyond both limits is an error.
    if (diff > options.centre_diff_max && diff > options.centre_factor * r_start) {
      return fail_arc(b.loc, "NC4201",
                      "circle end point radius " + core::number_text(r_end) +
                          " differs from the start radius " + core::number_text(r_start) +
                          " by more than P-CHAN-00059/00060 allow");
    }
    if (r_start < kSamePoint) return fail_arc(b.loc, "NC4201", "circle with radius 0");
    if (!full && diff > 0.0) {  // centre correction onto the perpendicular bisector
      const double n1 = -d2 / chord, n2 = d1 / chord;
      const double m1 = (s1 + e1) / 2.0, m2 = (s2 + e2) / 2.0;
      const double t = (c1 - m1) * n1 + (c2 - m2) * n2;
      c1 = m1 + t * n1;
      c2 = m2 + t * n2;
    }
  }
  const double r = std::hypot(s1 - c1, s2 - c2);
  if (!std::isfinite(c1) || !std::isfinite(c2) || !std::isfinite(r)) {
    return fail_arc(b.loc, "NC4101", "circle centre or radius is not a finite number");
  }
  // Beyond 1e9 mm the centre's coordinates keep less than 0.2 um (a double's ulp), and the
  // arc is a straight line to far below that: refused, not run as a NaN or a full circle
  // (issue 34 items 3, 4; docs/interp.md "Arcs of a huge radius").
  if (r > kArcRadiusMax) {
    return fail_arc(b.loc, "NC4203",
                    "circle radius " + core::number_text(r) + " mm is above ncsim's largest, " +
                        core::number_text(kArcRadiusMax) +
                        " mm: the centre cannot be represented to the micrometre; program a "
                        "straight line (G01)");
  }
  return Arc{c1, c2, a1, a2, r, full};
}

}  // namespace ncsim::interp
