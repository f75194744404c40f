// tracking/sync_error: the stop after an error while synchronised (see the header).

#include "tracking/sync_error.hpp"

#include <algorithm>
#include <cmath>

namespace ncsim::tracking {

namespace {

constexpr double kMargin = 1e-6;  ///< the stop ends at least this far before the limit [mm]

bool positive(double x) noexcept {
  return std::isfinite(x) && x > 0.0;
}

}  // namespace

AfterErrorAxis after_error_axis(const planner::AxisLimits& limits,
                                const axes::SoftLimitParams& soft) noexcept {
  const planner::AxisLimits rapid = planner::rapid_limits(limits);
  AfterErrorAxis a;
  a.soft = soft;
  a.v_max = limits.v_max;
  if (limits.v_reference > 0.0) a.v_max = std::min(a.v_max, limits.v_reference);
  a.a_max = std::min(limits.a_max, rapid.a_max);
  a.d_max = std::min(limits.d_max, rapid.d_max);
  a.j_max = std::min(limits.j_max, rapid.j_max);
  return a;
}

bool SyncErrorStop::keeps_synchronisation(std::string_view id) noexcept {
  return id != axes::kIdSoftLimitMin && id != axes::kIdSoftLimitMax;
}

bool SyncErrorStop::configure(std::span<const AfterErrorAxis> axes, double t_cycle) noexcept {
  usable_ = false;
  if (axes.size() > planner::kMaxAxes || !positive(t_cycle)) return false;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    AfterErrorAxis a = axes[i];
    if (!positive(a.v_max) || !positive(a.a_max) || !positive(a.d_max)) return false;
    if (!positive(a.j_max)) a.j_max = a.d_max / t_cycle;
    axes_[i] = a;
  }
  n_ = axes.size();
  t_cycle_ = t_cycle;
  usable_ = true;
  return true;
}

void SyncErrorStop::begin() noexcept {
  stopping_ = false;
  elapsed_ = 0.0;
  duration_ = 0.0;
  followed_ = 0.0;
  axis_ = -1;
}

bool SyncErrorStop::must_stop(std::span<const axes::Setpoint> sp, AfterErrorEnd& why,
                              int& axis) const noexcept {
  const double t = t_cycle_;
  for (std::size_t i = 0; i < n_ && i < sp.size(); ++i) {
    const AfterErrorAxis& l = axes_[i];
    const axes::Setpoint& s = sp[i];
    // The state one cycle ahead if the axis keeps following (the jerk is not known here: the
    // error of leaving it out is of order j T^3, far inside kMargin's neighbourhood of a cycle).
    const double p1 = s.p + s.v * t + 0.5 * s.a * t * t;
    const double v1 = s.v + s.a * t;
    if (std::fabs(v1) > l.v_max) {
      why = AfterErrorEnd::velocity;
      axis = static_cast<int>(i);
      return true;
    }
    double dir = 0.0;
    if (v1 > 0.0 || (v1 == 0.0 && s.a > 0.0)) dir = 1.0;
    if (v1 < 0.0 || (v1 == 0.0 && s.a < 0.0)) dir = -1.0;
    if (dir == 0.0) continue;
    double room = 0.0;
    if (dir > 0.0 && l.soft.max_enabled) {
      room = l.soft.max_position - p1;
    } else if (dir < 0.0 && l.soft.min_enabled) {
      room = p1 - l.soft.min_position;
    } else {
      continue;  // no limit ahead
    }
    const double stop = jerk::stopping_distance(dir * v1, dir * s.a, l.d_max, l.j_max).s;
    if (stop >= room - kMargin) {
      why = AfterErrorEnd::soft_limit;
      axis = static_cast<int>(i);
      return true;
    }
  }
  if (followed_ >= kFollowMax) {
    why = AfterErrorEnd::time_limit;
    axis = -1;
    return true;
  }
  return false;
}

void SyncErrorStop::start_stopping(std::span<const axes::Setpoint> sp, AfterErrorEnd why,
                                   int axis) noexcept {
  stopping_ = true;
  why_ = why;
  axis_ = axis;
  elapsed_ = 0.0;
  duration_ = 0.0;
  for (std::size_t i = 0; i < n_ && i < sp.size(); ++i) {
    const AfterErrorAxis& l = axes_[i];
    Brake& b = brake_[i];
    const axes::Setpoint& s = sp[i];
    b.dir = s.v < 0.0 || (s.v == 0.0 && s.a < 0.0) ? -1.0 : 1.0;
    b.from = jerk::State{b.dir * s.p, b.dir * s.v, b.dir * s.a};
    b.ramp = jerk::velocity_ramp(b.from.v, b.from.a, 0.0, l.a_max, l.d_max, l.j_max);
    duration_ = std::max(duration_, b.ramp.time());
  }
}

axes::Setpoint SyncErrorStop::at(const Brake& b, double t) noexcept {
  jerk::State x = b.from;
  double j = 0.0;
  double left = t;
  for (std::size_t p = 0; p < 3; ++p) {
    const double dur = std::min(left, b.ramp.duration[p]);
    if (!(dur > 0.0)) continue;
    x = jerk::advance(x, b.ramp.jerk[p], dur);
    j = b.ramp.jerk[p];
    left -= dur;
  }
  if (t >= b.ramp.time()) {  // at rest: the ramp's rounding is not carried on
    x.v = 0.0;
    x.a = 0.0;
    j = 0.0;
  }
  return axes::Setpoint{b.dir * x.p, b.dir * x.v, b.dir * x.a, b.dir * j};
}

void SyncErrorStop::step(std::span<axes::Setpoint> sp) noexcept {
  if (!stopping_) return;
  elapsed_ += t_cycle_;
  for (std::size_t i = 0; i < n_ && i < sp.size(); ++i)
    sp[i] = at(brake_[i], elapsed_);
}

}  // namespace ncsim::tracking
