// ipo/interpolator: the cycle loop (see the header and docs/ipo.md).

#include "ipo/interpolator.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ncsim::ipo {

namespace {

/// Dwells of zero cycles handled in one step() at most (then a starved cycle).
constexpr int kMaxZeroWaits = 1024;

/// The point on the curve and each axis's v, a, j by the chain rule from the path state (v, a,
/// j of the path; x', x'', x''' of the curve at s).
void set_axis_values(const planner::PathPoint& p, const planner::PathState& ps, std::size_t n,
                     Cycle& c) noexcept {
  const double v = ps.v;
  const double a = ps.a;
  const double j = ps.j;
  for (std::size_t i = 0; i < n; ++i) {
    c.x[i] = p.x[i];
    c.v[i] = p.d1[i] * v;
    c.a[i] = p.d2[i] * v * v + p.d1[i] * a;
    c.j[i] = p.d3[i] * v * v * v + 3.0 * p.d2[i] * v * a + p.d1[i] * j;
  }
}

}  // namespace

PathInterpolator::PathInterpolator(Config config, Source& source, Sink* sink)
    : axes_(std::move(config.axes)),
      joints_(config.joints),
      t_(config.channel.t_cycle),
      detail_(config.detail),
      sink_(sink),
      queue_(source, axes_, config.channel, config.window, std::move(config.joints)),
      stand_(std::move(config.exact_stop), axes_.size(), config.channel.t_cycle,
             config.hold_exact_stop),
      override_(config.override_type),
      entry_(axes_, joints_, config.override_type, queue_),
      joint_report_(sink, config.detail, queue_, axes_.size(), config.channel.limit_c1_by_jerk,
                    joints_) {
  cycle_.x = config.start;
}

Status PathInterpolator::step() noexcept {
  if (failed_) return Status::error;
  if (finished_) return Status::finished;
  // 1. The path stands (a dwell, an exact stop, a channel wait, nothing to move) or has ended.
  if (const std::optional<Status> standing = stand_or_start()) return *standing;
  // 2. A changed override, feed hold or velocity cap: a replan from the path state.
  entry_.start_cycle(override_.effective_factor(), override_.velocity_cap());
  // 3. The path advances by T, the rest of T carried across segment ends; a stop ends it.
  double distance = 0.0;  // [mm]
  bool held = false;
  if (const std::optional<Status> stopped = traverse(distance, held)) return *stopped;
  // 4. The cycle record at the new path state. No NaN reaches a sink: a setpoint that is not a
  // finite number ends the run here (issue 34 item 3: an arc beyond double precision ran with
  // NaN and `time --json` wrote -nan).
  sample(distance);
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (!std::isfinite(cycle_.x[i]) || !std::isfinite(cycle_.distance)) {
      return fail(
          "NC6302 ipo: a position setpoint is not a finite number (a curve beyond double "
          "precision)");
    }
  }
  return close_cycle(held);
}

std::optional<Status> PathInterpolator::stand_or_start() noexcept {
  Cycle& c = cycle_;
  for (int zero_waits = 0;; ++zero_waits) {
    if (stand_.standing() || zero_waits >= kMaxZeroWaits) {
      stand_.stand(c);
      return emit();
    }
    if (entry_.active()) return std::nullopt;
    if (!queue_.fill(message_)) return fail("ipo: the program source failed");
    if (!queue_.empty()) {
      if (!begin(queue_.pop())) return Status::error;
      return std::nullopt;
    }
    if (const std::optional<Dwell> dwell = queue_.take_dwell()) {
      // A G04 starts (a 0 s dwell is the source's flush before a barrier, or takes no cycle:
      // not reported as a block start).
      if (stand_.start_dwell(*dwell, c.index) && observer_ != nullptr)
        observer_->on_block_started(dwell->line, dwell->file);
      c.event_tag = std::max(c.event_tag, dwell->event_tag);
      continue;
    }
    if (const std::optional<ChannelWait> wait = queue_.take_wait()) {
      stand_.reach_wait(*wait, c);
      continue;
    }
    if (queue_.source_done()) {
      finished_ = true;
      return Status::finished;
    }
    zero_waits = kMaxZeroWaits - 1;  // nothing moves yet: a starved cycle
  }
}

std::optional<Status> PathInterpolator::traverse(double& distance, bool& held) noexcept {
  const double t_start = static_cast<double>(cycle_.index) * t_;
  double rest = t_ - start_lag_;  // a start after a moving hand-over begins `lag` late
  start_lag_ = 0.0;
  for (;;) {
    if (entry_.t_in() + rest < entry_.duration()) {
      entry_.advance_to(entry_.t_in() + rest);
      return std::nullopt;
    }
    rest = std::max(0.0, rest - (entry_.duration() - entry_.t_in()));
    entry_.advance_to(entry_.duration());
    if (entry_.holding()) {
      // Feed hold / override 0: the path stands on the contour for the rest of the cycle.
      held = true;
      entry_.hold_for(rest);
      return std::nullopt;
    }
    const planner::PlannedSegment& cur = entry_.segment();
    const double length = cur.segment.path.length();
    distance += length - entry_.s_sampled();
    // Knees between the last sample and the end of a chain are passed in this cycle too.
    joint_report_.inner(cur, entry_.s_sampled(), length, static_cast<double>(cycle_.index + 1) * t_,
                        entry_.v_ceiling(), entry_.a_ceiling());
    if (observer_ != nullptr && cur.segment.path.parts() > 1)
      queue_.report_part_starts(cur.segment.path, entry_.s_sampled(), length, *observer_);
    entry_.set_sampled(length);
    entry_.arrive();
    // G60 / G360: the rest of the cycle is not carried; window and settling time follow.
    if (cur.segment.stop == planner::StopReason::exact_stop) return stop_cycle(distance);
    if (!queue_.fill(message_)) return fail("ipo: the program source failed");
    // Program end, a dwell, or nothing known beyond: the path stands; the cycle is whole.
    if (queue_.empty()) return stop_cycle(distance);
    planner::PlannedSegment next = queue_.pop();
    joint_report_.between(cur, next, t_start + (t_ - rest), entry_.v_arrive(), entry_.a_arrive());
    if (!begin(std::move(next))) return Status::error;
  }
}

bool PathInterpolator::begin(planner::PlannedSegment&& next) noexcept {
  if (!entry_.begin(std::move(next), override_.effective_factor(), override_.velocity_cap())) {
    failed_ = true;
    if (message_.empty())
      message_ = "NC6300 ipo: no velocity plan fits the entry under the override (internal)";
  }
  // The oldest Move still referenced.
  const std::uint32_t token = entry_.segment().segment.path.line_at(0.0);
  queue_.activate(token);
  if (observer_ != nullptr) queue_.report_starts_to(token, *observer_);
  return !failed_;
}

void PathInterpolator::sample(double distance) noexcept {
  Cycle& c = cycle_;
  const planner::PlannedSegment& cur = entry_.segment();
  const planner::Chain& path = cur.segment.path;
  const planner::PathState ps = entry_.state();
  distance += ps.s - entry_.s_sampled();
  const double s_from = entry_.s_sampled();
  entry_.set_sampled(ps.s);
  const planner::Move& prog = queue_.programmed(path.line_at(ps.s));
  c.activity = Activity::motion;
  c.line = prog.line;
  c.file = prog.file;
  c.rapid = prog.rapid;
  c.jerk_limited = planner::jerk_limited(prog.slope);
  c.feed = cur.segment.limits.v_programmed;
  c.feed_cap = cur.segment.limits.feed_capped() ? cur.segment.limits.v_max : 0.0;
  c.path = ps;
  c.distance = distance;
  c.interval_jerk_limited = entry_.interval_jerk_limited();
  c.programmed = &prog;
  if (observer_ != nullptr && path.parts() > 1)
    queue_.report_part_starts(path, s_from, ps.s, *observer_);
  stand_.note_tag(prog.event_tag, c);
  if (detail_ != Detail::axes) return;
  joint_report_.inner(cur, s_from, ps.s, static_cast<double>(c.index + 1) * t_, entry_.v_ceiling(),
                      entry_.a_ceiling());
  set_axis_values(path.at(ps.s), ps, axes_.size(), c);
}

Status PathInterpolator::stop_cycle(double distance) noexcept {
  entry_.stop();
  sample(distance);
  Cycle& c = cycle_;
  c.path.v = 0.0;
  c.path.a = 0.0;
  c.path.j = 0.0;
  c.v = {};
  c.a = {};
  c.j = {};
  const planner::StopReason stop = entry_.segment().segment.stop;
  // A programmed stop ends exactly on the block's end point (no trimming at a stop).
  if (stop != planner::StopReason::none && detail_ == Detail::axes)
    for (std::size_t i = 0; i < axes_.size(); ++i)
      c.x[i] = c.programmed->end[i];
  c.held = false;
  c.factor = entry_.factor();
  c.lost = entry_.lost();
  if (stop == planner::StopReason::exact_stop) stand_.start_exact_stop(c);
  return emit();
}

Status PathInterpolator::close_cycle(bool held) noexcept {
  Cycle& c = cycle_;
  c.held = held;
  c.factor = held ? 0.0 : entry_.factor();
  c.lost = entry_.lost();
  return emit();
}

Status PathInterpolator::emit() noexcept {
  Cycle& c = cycle_;
  ++c.index;
  c.t = static_cast<double>(c.index) * t_;
  if (sink_) sink_->on_cycle(c);
  return Status::running;
}

Status PathInterpolator::fail(const char* what) noexcept {
  failed_ = true;
  if (message_.empty()) message_ = what;
  return Status::error;
}

bool PathInterpolator::prefill() noexcept {
  if (failed_ || entry_.active()) return !failed_;
  if (!queue_.fill(message_)) {
    fail("ipo: the program source failed");
    return false;
  }
  return true;
}

double PathInterpolator::start_moving(double v, double lag) noexcept {
  const double v_set = queue_.start_at(v);
  entry_.start_from(v_set);
  start_lag_ = std::clamp(lag, 0.0, t_);
  return v_set;
}

}  // namespace ncsim::ipo
