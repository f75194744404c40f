// ipo/interpolator: the cycle loop (see the header and docs/ipo.md).

#include "ipo/interpolator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/limits.hpp"
#include "planner/joint_limits.hpp"

namespace ncsim::ipo {

namespace {

/// Moves shorter than this carry no path (planner/prepare.cpp drops them with the same rule).
constexpr double kMinLength = 1e-9;  // [mm]

/// --- conveyor-tail: a PCS1 block planned with the belt's share taken off its limits: the
/// velocity split of the axes (Move::belt, S-5) or the joints' shares under #TRAFO ON
/// (Move::belt_joints). Raised above 100 % with the axes' own limits, the belt would come on top
/// (docs/conveyor.md "Machining in PCS1", "An override above 100 %").
bool belt_capped(const planner::Move& m) noexcept {
  return m.belt_joints != nullptr ||
         std::any_of(m.belt.begin(), m.belt.end(), [](double v) { return v > 0.0; });
}
/// Items pulled in one fill() at most: a source of endless zero-length blocks cannot hang a
/// cycle (the cycle is reported as Activity::starved).
constexpr std::size_t kMaxPulls = 4096;
/// Dwells of zero cycles handled in one step() at most (then a starved cycle).
constexpr int kMaxZeroWaits = 1024;
/// Tolerance of the rounding of a wait to whole cycles [cycles]: 0.1 s at 1 ms is 100 cycles.
constexpr double kCycleRounding = 1e-9;

std::size_t ring_size(std::size_t window) {
  return std::bit_ceil((window + 2) * planner::Chain::kMaxParts + 16);
}

/// The length planner::Segment::line gives a line Move (Segment::from_move), without building
/// the Segment: the same effective metric and the same sum of squares in the same order
/// (Segment::metric_norm), so the same bits.
double line_length(const planner::Move& m) {
  planner::AxisVec delta{};
  for (std::size_t i = 0; i < m.axis_count; ++i)
    delta[i] = m.end[i] - m.start[i];
  const planner::AxisMask metric = planner::effective_metric(m.axis_count, m.path_axes, delta);
  double sum = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i)
    if (((metric >> i) & 1U) != 0) sum += delta[i] * delta[i];
  return std::sqrt(sum);
}

/// The length of a Move's path: lines without building their Segment.
double move_length(const planner::Move& m) {
  if (!m.arc && !m.spline) return line_length(m);
  return planner::Segment::from_move(m).length();
}

}  // namespace

PathInterpolator::PathInterpolator(Config config, Source& source, Sink* sink)
    : axes_(std::move(config.axes)),
      exact_stop_(std::move(config.exact_stop)),
      t_(config.channel.t_cycle),
      c1_limited_(config.channel.limit_c1_by_jerk),
      detail_(config.detail),
      source_(source),
      sink_(sink),
      prep_(axes_, config.channel),
      window_(config.window, config.channel.t_cycle),
      item_(planner::Move{}),
      override_type_(config.override_type) {
  if (axes_.empty() || axes_.size() > planner::kMaxAxes)
    throw std::invalid_argument("ipo: " + std::to_string(axes_.size()) + " axes (1.." +
                                std::to_string(planner::kMaxAxes) + ")");
  if (config.joints) {
    joints_ = config.joints;  // --- trafo-conveyor: the raised cap above 100 % (override_trafo)
    prep_.set_joints(std::move(*config.joints));
  }
  if (exact_stop_.empty()) exact_stop_.resize(axes_.size());
  if (exact_stop_.size() != axes_.size())
    throw std::invalid_argument("ipo: " + std::to_string(exact_stop_.size()) +
                                " exact-stop settings for " + std::to_string(axes_.size()) +
                                " axes");
  for (std::size_t i = 0; i < exact_stop_.size(); ++i) {
    const ExactStop& e = exact_stop_[i];
    if (!(e.window > 0.0) || !std::isfinite(e.window))
      throw std::invalid_argument("ipo: axis " + std::to_string(i) +
                                  ": exact-stop window P-AXIS-00236 must be > 0, got " +
                                  std::to_string(e.window));
    if (!(e.settle_time >= 0.0) || !std::isfinite(e.settle_time))
      throw std::invalid_argument("ipo: axis " + std::to_string(i) +
                                  ": settling time P-AXIS-00532 must be >= 0, got " +
                                  std::to_string(e.settle_time));
  }
  hold_exact_stop_ = config.hold_exact_stop;
  ring_.resize(ring_size(config.window));
  ring_mask_ = ring_.size() - 1;
  ready_.reserve(16);
  cycle_.x = config.start;
}

Status PathInterpolator::fail(const char* what) noexcept {
  failed_ = true;
  if (message_.empty()) message_ = what;
  return Status::error;
}

std::uint64_t PathInterpolator::cycles_for(double seconds) const noexcept {
  if (!(seconds > 0.0)) return 0;
  // Dwells are at most core::kLongestTime (fill() refuses longer ones), far inside uint64_t.
  return static_cast<std::uint64_t>(
      std::ceil(std::min(seconds, core::kLongestTime) / t_ - kCycleRounding));
}

bool PathInterpolator::fill() noexcept {
  try {
    std::size_t pulls = 0;
    while (!window_.full()) {
      if (ready_next_ < ready_.size()) {
        window_.push(std::move(ready_[ready_next_++]));
        continue;
      }
      ready_.clear();
      ready_next_ = 0;
      if (source_done_ || dwell_ || wait_) break;
      if (next_token_ - oldest_ >= ring_.size()) break;  // every ring slot still referenced
      if (pulls++ >= kMaxPulls) break;
      if (!source_.next(item_)) {
        source_done_ = true;
        prep_.finish(ready_);
        continue;
      }
      if (const Dwell* d = std::get_if<Dwell>(&item_)) {
        if (!(d->seconds >= 0.0) || !(d->seconds <= core::kLongestTime)) {
          message_ = "G04 dwell time must be 0 .. 86400 s (core::kLongestTime), got " +
                     std::to_string(d->seconds) + " s (line " + std::to_string(d->line) + ")";
          return false;
        }
        dwell_ = PendingDwell{d->seconds, d->line, d->event_tag, d->file, d->tech, d->since_output};
        prep_.finish(ready_);  // the path stops before the dwell
        continue;
      }
      if (const ChannelWait* w = std::get_if<ChannelWait>(&item_)) {
        wait_ = *w;
        prep_.finish(ready_);  // the path stops before the wait
        continue;
      }
      planner::Move& m = std::get<planner::Move>(item_);
      // A zero-length line takes no ring slot: the planner drops it (passing on its stop).
      if (!m.arc && move_length(m) < kMinLength) {
        m.line = static_cast<std::uint32_t>(next_token_);
        prep_.push(m, ready_);
        continue;
      }
      ring_[next_token_ & ring_mask_] = m;
      m.line = static_cast<std::uint32_t>(next_token_);  // the planner carries the token
      ++next_token_;
      prep_.push(m, ready_);
    }
    return true;
  } catch (const planner::KinematicError& e) {  // the planner carries the ring token
    message_ = "line " + std::to_string(programmed(e.line()).line) + ": " + e.what();
    return false;
  } catch (const std::exception& e) {
    message_ = e.what();
    return false;
  } catch (...) {
    message_ = "ipo: the program source failed";
    return false;
  }
}

bool PathInterpolator::start_next() noexcept {
  if (window_.empty()) return false;
  begin(window_.pop());
  return true;
}

void PathInterpolator::begin(planner::PlannedSegment&& next) noexcept {
  cur_ = std::move(next);
  prof_ = planner::profile(cur_);
  t_in_ = 0.0;
  s_prev_ = 0.0;
  t100_prev_ = 0.0;
  active_ = true;
  raised_ready_ = false;
  has_ball_ = false;
  for (std::size_t p = 0; p < cur_.segment.path.parts(); ++p)
    has_ball_ = has_ball_ || cur_.segment.path.part(p).kind() == planner::SegmentKind::blend;
  if (!plan_entry()) {
    failed_ = true;
    if (message_.empty())
      message_ = "NC6300 ipo: no velocity plan fits the entry under the override (internal)";
  }
  interval_jerk_limited_ = interval_jerk_limited_ && std::isfinite(cur_.segment.limits.j_max);
  // The oldest Move still referenced (tokens are the low 32 bits of next_token_'s count).
  const std::uint32_t token = cur_.segment.path.line_at(0.0);
  oldest_ =
      next_token_ - static_cast<std::uint32_t>(static_cast<std::uint32_t>(next_token_) - token);
  if (observer_ != nullptr) report_starts_to(token);  // --- operator
}

void PathInterpolator::sample(double distance) noexcept {
  Cycle& c = cycle_;
  const planner::Chain& path = cur_.segment.path;
  const double length = path.length();
  planner::PathState ps = on_plan_ ? planner::profile_at(prof_, t_in_) : plan_at(plan_, t_in_);
  ps.s = t_in_ >= dur_ && !plan_.hold ? length : std::clamp(ps.s, 0.0, length);
  distance += ps.s - s_prev_;
  const double s_from = s_prev_;
  s_prev_ = ps.s;
  const planner::Move& prog = programmed(path.line_at(ps.s));
  c.activity = Activity::motion;
  c.line = prog.line;
  c.file = prog.file;
  c.rapid = prog.rapid;
  c.jerk_limited = planner::jerk_limited(prog.slope);
  c.feed = cur_.segment.limits.v_programmed;
  c.feed_cap = cur_.segment.limits.feed_capped() ? cur_.segment.limits.v_max : 0.0;
  c.path = ps;
  c.distance = distance;
  c.interval_jerk_limited = interval_jerk_limited_;
  c.programmed = &prog;
  if (observer_ != nullptr && path.parts() > 1) report_part_starts(s_from, ps.s);  // --- operator
  if (prog.event_tag > c.event_tag) {
    tag_rise_ = prog.event_tag;
    tag_rise_index_ = c.index + 1;  // sample() runs before the cycle is counted
  }
  c.event_tag = std::max(c.event_tag, prog.event_tag);
  if (detail_ != Detail::axes) return;
  if (sink_ && path.parts() > 1) report_inner_joints(s_from, ps.s);
  const planner::PathPoint p = path.at(ps.s);
  const double v = ps.v;
  const double a = ps.a;
  const double j = ps.j;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    c.x[i] = p.x[i];
    c.v[i] = p.d1[i] * v;
    c.a[i] = p.d2[i] * v * v + p.d1[i] * a;
    c.j[i] = p.d3[i] * v * v * v + 3.0 * p.d2[i] * v * a + p.d1[i] * j;
  }
}

void PathInterpolator::stop_at_end(double distance) noexcept {
  active_ = false;
  t_in_ = dur_;
  sample(distance);
  Cycle& c = cycle_;
  c.path.v = 0.0;
  c.path.a = 0.0;
  c.path.j = 0.0;
  c.v = {};
  c.a = {};
  c.j = {};
  // A programmed stop ends exactly on the block's end point (no trimming at a stop).
  if (cur_.segment.stop != planner::StopReason::none && detail_ == Detail::axes)
    for (std::size_t i = 0; i < axes_.size(); ++i)
      c.x[i] = c.programmed->end[i];
}

void PathInterpolator::report_joint(const planner::PlannedSegment& next, double t_joint) noexcept {
  const planner::Chain& in = cur_.segment.path;
  const planner::PathPoint p_in = in.at(in.length());
  const planner::PathPoint p_out = next.segment.path.at(0.0);
  const planner::Move& prog_in = programmed(in.line_at(in.length()));
  const planner::Move& prog_out = programmed(next.segment.path.line_at(0.0));
  Joint jt;
  jt.t = t_joint;
  jt.line = prog_in.line;
  jt.file = prog_in.file;
  jt.cls = cur_.segment.joint;
  jt.stop = cur_.segment.stop;
  jt.jerk_limited = planner::jerk_limited(prog_in.slope) && planner::jerk_limited(prog_out.slope);
  jt.c1_limited = c1_limited_;  // P-CHAN-00009
  // The velocity and acceleration are the ones the path arrives with (below the plan's under
  // an override); a != 0 only where a ramp is carried through a soft joint (a knee steps the
  // axis acceleration by a dx' too).
  const double v = v_arrive_;
  const double a = a_arrive_;
  jt.v = v;
  jt.rule = cur_.segment.rule;
  jt.transvelmin = prog_in.transvelmin.value_or(0.0);
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    jt.dv[i] = v * (p_out.d1[i] - p_in.d1[i]);
    jt.da[i] = v * v * (p_out.d2[i] - p_in.d2[i]) + a * (p_out.d1[i] - p_in.d1[i]);
  }
  // --- trafo: the joints' own steps, for the audit's formulas on the joints. Not in PCS1
  // (belt_joints set): the path point is the programmed one, the joints follow it where the
  // belt has carried it (channel/channel_kinematics.cpp), a few per cent apart on the delta
  // picker; those joints stay unlisted and their stencils velocity-only.
  if (joints_ && prog_in.transformed && prog_out.transformed && !prog_in.belt_joints &&
      !prog_out.belt_joints && jt.stop == planner::StopReason::none) {
    const std::size_t nj = joints_->joints.size();
    const auto n =
        static_cast<std::size_t>(std::max(in.axis_count(), next.segment.path.axis_count()));
    AxisVec q1_in{}, q2_in{}, q1_out{}, q2_out{};
    if (planner::joint_derivatives(p_in, n, joints_->inverse, nj, q1_in, q2_in) &&
        planner::joint_derivatives(p_out, n, joints_->inverse, nj, q1_out, q2_out)) {
      jt.joint_steps = true;
      for (std::size_t i = 0; i < nj; ++i) {
        jt.dq[i] = v * (q1_out[i] - q1_in[i]);
        jt.dw[i] = v * v * (q2_out[i] - q2_in[i]) + a * (q1_out[i] - q1_in[i]);
      }
    }
  }
  sink_->on_joint(jt);
}

void PathInterpolator::report_inner_joints(double s_from, double s_to) noexcept {
  // Knees inside a chain (planner/corner.hpp knee_carries_acceleration) step the axis velocity
  // by v dx' and the acceleration by v^2 dx'' + a dx' with the path acceleration carried; the
  // audit needs both for its finite-difference allowances. The joint's own instant is not
  // resolved: v is bounded by the chain's velocity cap and a by its path limits, which only
  // widens the allowances by what a knee can cause; the VELOJUMP check of v dx' at the cap is
  // the planner's own chaining condition (docs/ipo.md "The audit").
  const planner::Chain& path = cur_.segment.path;
  const double v = cur_.segment.limits.v_max;
  const double a = std::max(cur_.segment.limits.a_max, cur_.segment.limits.d_max);
  for (std::size_t k = 0; k + 1 < path.parts(); ++k) {
    const double e = path.part_end(k);
    if (!(e > s_from && e <= s_to)) continue;
    const planner::Segment& in = path.part(k);
    const planner::PathPoint p_in = in.at(in.length());
    const planner::PathPoint p_out = path.part(k + 1).at(0.0);
    const planner::Move& prog_in = programmed(path.part_line(k));
    const planner::Move& prog_out = programmed(path.part_line(k + 1));
    Joint jt;
    jt.t = static_cast<double>(cycle_.index + 1) * t_;
    jt.line = prog_in.line;
    jt.file = prog_in.file;
    jt.cls = planner::TransitionClass::c2;
    jt.stop = planner::StopReason::none;
    jt.jerk_limited = planner::jerk_limited(prog_in.slope) && planner::jerk_limited(prog_out.slope);
    jt.c1_limited = c1_limited_;  // P-CHAN-00009
    jt.v = v;
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      const double dt = p_out.d1[i] - p_in.d1[i];
      jt.dv[i] = v * dt;
      jt.da[i] = v * v * std::abs(p_out.d2[i] - p_in.d2[i]) + a * std::abs(dt);
      if (dt != 0.0) jt.cls = planner::TransitionClass::c0;
    }
    sink_->on_joint(jt);
  }
}

Status PathInterpolator::step() noexcept {
  if (failed_) return Status::error;
  if (finished_) return Status::finished;
  Cycle& c = cycle_;
  const double t_start = static_cast<double>(c.index) * t_;
  for (int zero_waits = 0;; ++zero_waits) {
    if (wait_left_ > 0 || held_ || channel_held_ || zero_waits >= kMaxZeroWaits) {
      const bool waiting = wait_left_ > 0 || held_ || channel_held_;
      if (wait_left_ > 0) --wait_left_;
      ++c.index;
      c.t = static_cast<double>(c.index) * t_;
      c.activity = waiting ? wait_kind_ : Activity::starved;
      c.line = waiting ? wait_line_ : c.line;
      c.file = waiting ? wait_file_ : c.file;
      c.path.v = c.path.a = c.path.j = 0.0;
      c.interval_jerk_limited = true;
      c.distance = 0.0;
      c.held = false;
      c.lost = 0.0;
      c.v = {};
      c.a = {};
      c.j = {};
      c.programmed = nullptr;
      if (sink_) sink_->on_cycle(c);
      return Status::running;
    }
    if (active_) break;
    if (!fill()) return fail("ipo: the program source failed");
    if (start_next()) {
      if (failed_) return Status::error;
      break;
    }
    if (dwell_) {
      wait_left_ = cycles_for(dwell_->seconds);
      if (dwell_->since_output && dwell_->event_tag == tag_rise_) {
        const std::uint64_t since = c.index >= tag_rise_index_ ? c.index - tag_rise_index_ : 0;
        wait_left_ = wait_left_ > since ? wait_left_ - since : 0;
      }
      wait_kind_ = dwell_->tech ? Activity::tech : Activity::dwell;
      wait_line_ = dwell_->line;
      wait_file_ = dwell_->file;
      // --- operator: a G04 starts (a 0 s dwell is the source's flush before a barrier, or
      // takes no cycle: not reported).
      if (observer_ != nullptr && wait_left_ > 0)
        observer_->on_block_started(wait_line_, wait_file_);
      c.event_tag = std::max(c.event_tag, dwell_->event_tag);
      dwell_.reset();
      continue;
    }
    if (wait_) {
      // The path stands at the end of the block before: the channel decides.
      const ChannelWait w = *wait_;
      wait_.reset();
      c.event_tag = std::max(c.event_tag, w.tag);
      c.line = w.line;
      c.file = w.file;
      channel_held_ = wait_handler_ != nullptr && !wait_handler_->on_wait(w);
      wait_kind_ = Activity::channel;
      wait_line_ = w.line;
      wait_file_ = w.file;
      continue;
    }
    if (source_done_) {
      finished_ = true;
      return Status::finished;
    }
    zero_waits = kMaxZeroWaits - 1;  // nothing moves yet: a starved cycle
  }

  // Motion: advance the path by exactly T, carrying the rest of T across segment ends.
  interval_jerk_limited_ = std::isfinite(cur_.segment.limits.j_max);
  lost_ = 0.0;
  if (const double f = effective_factor(); f != plan_factor_ || cap_ != plan_cap_) {
    // A change of the override waits until the tolerance ball is left (000 l.366); a stop
    // (override 0, feed hold) has priority (002 l.391) and acts at once, and so does the
    // release of a stop (a path standing in a ball would never leave it).
    const planner::PathState st = plan_at(plan_, t_in_);
    if (f == 0.0 || plan_factor_ == 0.0 || !has_ball_ || !in_ball(st.s) ||
        cap_ != plan_cap_)  // --- workspace: a cap acts at once, as a stop does
      replan(f, st.s, st.v, st.a);
  }
  double rest = t_ - start_lag_;  // --- sync-feed: a start after a moving hand-over
  start_lag_ = 0.0;
  double distance = 0.0;
  bool held = false;
  for (;;) {
    if (t_in_ + rest < dur_) {
      advance_to(t_in_ + rest);
      break;
    }
    rest = std::max(0.0, rest - (dur_ - t_in_));
    advance_to(dur_);
    if (plan_.hold) {
      // Feed hold / override 0: the path stands on the contour for the rest of the cycle.
      held = true;
      lost_ += rest;
      break;
    }
    const double length = cur_.segment.path.length();
    distance += length - s_prev_;
    // Knees between the last sample and the end of a chain are passed in this cycle too.
    if (sink_ && detail_ == Detail::axes && cur_.segment.path.parts() > 1)
      report_inner_joints(s_prev_, length);
    if (observer_ != nullptr && cur_.segment.path.parts() > 1)  // --- operator
      report_part_starts(s_prev_, length);
    s_prev_ = length;
    v_arrive_ = on_plan_ ? cur_.v_exit : plan_.v_exit();
    a_arrive_ = on_plan_ ? cur_.a_exit : 0.0;
    if (cur_.segment.stop == planner::StopReason::exact_stop) {
      // G60 / G360: the rest of the cycle is not carried; window and settling time follow.
      stop_at_end(distance);
      v_arrive_ = 0.0;
      a_arrive_ = 0.0;
      c.held = false;
      c.factor = plan_factor_;
      c.lost = lost_;
      const planner::Move& prog = *c.programmed;
      double settle = 0.0;
      for (std::size_t i = 0; i < axes_.size(); ++i) {
        bool on_arc = prog.arc && (prog.arc->axis_1 == i || prog.arc->axis_2 == i);
        if (prog.arc && prog.arc_plane)  // a plane under a rotated #CS: X, Y and Z move
          on_arc = prog.arc_plane->axes[0] == i || prog.arc_plane->axes[1] == i ||
                   prog.arc_plane->axes[2] == i;
        const bool moved = prog.end[i] != prog.start[i] || on_arc;
        // The window P-AXIS-00236 is reached when the command is on the target (no following
        // error model yet; docs/ipo.md): only the settling time P-AXIS-00532 is waited for.
        if (moved) settle = std::max(settle, exact_stop_[i].settle_time);
      }
      wait_left_ = hold_exact_stop_ ? 0 : cycles_for(settle);
      held_ = hold_exact_stop_;  // the channel releases it (window on actual positions)
      wait_kind_ = Activity::exact_stop;
      wait_line_ = c.line;
      wait_file_ = c.file;
      ++c.index;
      c.t = static_cast<double>(c.index) * t_;
      if (sink_) sink_->on_cycle(c);
      return Status::running;
    }
    if (!fill()) return fail("ipo: the program source failed");
    if (window_.empty()) {
      // Program end, a dwell, or nothing known beyond: the path stands; the cycle is whole.
      stop_at_end(distance);
      v_arrive_ = 0.0;
      a_arrive_ = 0.0;
      c.held = false;
      c.factor = plan_factor_;
      c.lost = lost_;
      ++c.index;
      c.t = static_cast<double>(c.index) * t_;
      if (sink_) sink_->on_cycle(c);
      return Status::running;
    }
    planner::PlannedSegment next = window_.pop();
    if (sink_ && detail_ == Detail::axes) report_joint(next, t_start + (t_ - rest));
    begin(std::move(next));
    if (failed_) return Status::error;
  }
  sample(distance);
  // No NaN reaches a sink: a setpoint that is not a finite number ends the run here (issue 34
  // item 3: an arc beyond double precision ran with NaN and `time --json` wrote -nan).
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (!std::isfinite(c.x[i]) || !std::isfinite(c.distance)) {
      return fail(
          "NC6302 ipo: a position setpoint is not a finite number (a curve beyond double "
          "precision)");
    }
  }
  c.held = held;
  c.factor = held ? 0.0 : plan_factor_;
  c.lost = lost_;
  ++c.index;
  c.t = static_cast<double>(c.index) * t_;
  if (sink_) sink_->on_cycle(c);
  return Status::running;
}

// --- sync-feed: a path that starts moving (docs/conveyor.md S-1)

bool PathInterpolator::prefill() noexcept {
  if (failed_ || active_) return !failed_;
  if (!fill()) {
    failed_ = true;
    if (message_.empty()) message_ = "ipo: the program source failed";
    return false;
  }
  return true;
}

double PathInterpolator::start_moving(double v, double lag) noexcept {
  v_arrive_ = window_.start_at(v);
  a_arrive_ = 0.0;
  start_lag_ = std::clamp(lag, 0.0, t_);
  return v_arrive_;
}

// --- operator: block starts (docs/ipo.md "Block starts")

void PathInterpolator::report_starts_to(std::uint32_t token) noexcept {
  // Tokens count the ring's Moves in order; the ring still holds every token from the last
  // reported one on (fill() reuses only slots below oldest_, which is at most the active one).
  const std::uint64_t full =
      next_token_ - static_cast<std::uint32_t>(static_cast<std::uint32_t>(next_token_) - token);
  for (; reported_ <= full; ++reported_)
    observer_->on_block_started(ring_[reported_ & ring_mask_].line,
                                ring_[reported_ & ring_mask_].file);
}

void PathInterpolator::report_part_starts(double s_from, double s_to) noexcept {
  // Part k + 1 starts at the end of part k (Chain::at: an inner joint belongs to the later
  // part); parts of one block (a blend carries its incoming block's token) are reported once.
  const planner::Chain& path = cur_.segment.path;
  for (std::size_t k = 0; k + 1 < path.parts(); ++k) {
    const double e = path.part_end(k);
    if (e > s_from && e <= s_to) report_starts_to(path.part_line(k + 1));
  }
}

// --- override additions (docs/ipo.md "Override and feed hold")

void PathInterpolator::set_override(double factor) {
  const double hi = max_override(override_type_);
  if (!(factor >= 0.0) || !(factor <= hi))
    throw std::invalid_argument("ipo: override " + std::to_string(factor) + " outside [0, " +
                                std::to_string(hi) + "] for override type " +
                                override_type_name(override_type_) + " (NCSIM-CHAN-630)");
  override_ = factor;
}

bool PathInterpolator::plan_entry() noexcept {
  const double f = effective_factor();
  const bool as_planned = v_arrive_ == cur_.v_entry && a_arrive_ == cur_.a_entry;
  // At 100 % every type asks for the look-ahead's own profile: follow it unchanged.
  const auto follow = [&] {
    plan_ = PathPlan{prof_, 0.0, false, cur_.segment.path.length()};
    on_plan_ = true;
    plan_factor_ = 1.0;
    plan_cap_ = cap_;  // --- workspace
    dur_ = prof_.time();
    return true;
  };
  if (f == 1.0 && as_planned && !(cap_ < prof_.v_level)) return follow();  // --- workspace
  if (replan(f, 0.0, v_arrive_, a_arrive_)) return true;
  // Above 100 % the raised limits can be tighter than the planned ones: fall back to 100 %
  // (the change is retried every cycle).
  if (f > 1.0 && replan(1.0, 0.0, v_arrive_, a_arrive_)) return true;
  // A ramp carried through the joint that no plan ending at a = 0 can take over within this
  // entry goes on as planned; the change is retried every cycle (docs/ipo.md "Override and
  // feed hold").
  return a_arrive_ != 0.0 && as_planned && follow();
}

bool PathInterpolator::replan(double f, double s, double v, double a) noexcept {
  const planner::PathLimits& lim = cur_.segment.limits;
  PlanRequest r;
  r.v0 = v;
  r.a0 = a;
  r.length = cur_.segment.path.length() - s;
  r.a = cur_.a_max;
  r.d = cur_.d_max;
  r.j = cur_.j_max;
  double cap = lim.v_max;
  if (f > 1.0 && override_type_ == OverrideType::reduced_above_100) {
    if (!raised_ready_) {
      // --- trafo-conveyor: under #TRAFO ON the joints' G00 rule (ipo/override_trafo.cpp)
      const planner::Move& prog = programmed(cur_.segment.path.line_at(0.0));
      // --- trafo-pcs1: a PCS1 block under #TRAFO ON keeps its 100 % plan: the belt's shares
      // of its joints were taken at its capped F (docs/conveyor.md "Machining in PCS1");
      // --- conveyor-tail: so does one whose axes' velocity the belt shares (the split).
      if (belt_capped(prog))
        raised_ = RaisedLimits{lim.v_max, cur_.a_max, cur_.d_max, cur_.j_max};
      else
        raised_ = joints_ && prog.transformed ? raised_limits_joints(cur_, *joints_)
                                              : raised_limits(cur_, axes_);
      raised_ready_ = true;
    }
    cap = raised_.v_max;
    r.a = raised_.a;
    r.d = raised_.d;
    r.j = raised_.j;
  }
  r.level = override_level(override_type_, f, prof_.v_level, lim.v_programmed, cap);
  // Below a carried brake a plan ending at a = 0 takes the exit the plan with a = 0 at the
  // joint had (the next entry brakes on from there: docs/ipo.md).
  const bool brake_on = cur_.shape == planner::ProfileShape::carry_down ||
                        cur_.shape == planner::ProfileShape::brake_through;
  const double exit_100 = brake_on ? cur_.v_exit_zero : cur_.v_exit;
  r.exit_wanted = override_exit(override_type_, f, exit_100, lim.v_programmed);
  r.exit_cap = exit_100;
  // --- workspace: the cap lowers the level and the exit (never below 0)
  r.level = std::min(r.level, cap_);
  r.exit_wanted = std::min(r.exit_wanted, cap_);
  PathPlan np;
  if (!make_plan(r, np)) return false;
  plan_cap_ = cap_;
  np.s0 = s;
  plan_ = np;
  t_in_ = 0.0;
  dur_ = plan_.time();
  on_plan_ = false;
  plan_factor_ = f;
  return true;
}

bool PathInterpolator::in_ball(double s) const noexcept {
  const planner::Chain& path = cur_.segment.path;
  double end = 0.0;
  for (std::size_t p = 0; p < path.parts(); ++p) {
    const planner::Segment& part = path.part(p);
    const double start = end;
    end += part.length();
    if (s < start) return false;
    if (s <= end && part.kind() == planner::SegmentKind::blend) return true;
  }
  return false;
}

double PathInterpolator::t100(double s) const noexcept {
  return profile_time_at(prof_, s);
}

void PathInterpolator::advance_to(double t_new) noexcept {
  if (on_plan_) {
    t100_prev_ = t_new;
  } else {
    const double length = cur_.segment.path.length();
    const double s = t_new >= dur_ && !plan_.hold ? length : plan_at(plan_, t_new).s;
    const double t_ref = t100(s);
    lost_ += (t_new - t_in_) - (t_ref - t100_prev_);
    t100_prev_ = t_ref;
  }
  t_in_ = t_new;
}

}  // namespace ncsim::ipo
