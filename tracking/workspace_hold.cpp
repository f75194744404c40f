// tracking/workspace_hold: the workspace limit against the conveying direction (see the header).

#include "tracking/workspace_hold.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "jerk/jerk.hpp"

namespace ncsim::tracking {

namespace {

constexpr double kCos60 = 0.5;
constexpr double kSampleStep = 0.5;  ///< simple method: contour sample spacing [mm]
constexpr int kMaxSamples = 256;     ///< simple method: samples per block, at most
constexpr int kSampleBudget = 2048;  ///< simple method: samples per cycle over the blocks ahead
constexpr int kRampSamples = 8;      ///< optimised method: samples per ramp phase
/// The least velocity the time ahead of a block is reckoned with [mm/s]: a standing path
/// still reaches its samples (a divisor, not a tolerance).
constexpr double kLeastRunVelocity = 1e-9;
/// A block moves against the conveying direction when its coordinate goes back by more than
/// this between two samples [mm] (a Y line's rounding does not count).
constexpr double kMoveEps = 1e-6;
/// The cap follows the belt's velocity only when factor x v_conv moved by more than this share
/// of it (plus kCapSlack): a noisy belt would replan every cycle otherwise.
constexpr double kCapHysteresis = 0.01;
constexpr double kCapSlack = 0.1;  ///< [mm/s]

}  // namespace

std::optional<HoldConfig> hold_config(const machines::ConveyorSyncChannel& channel,
                                      const Eigen::Vector3d& direction, bool optimised,
                                      const int* xyz_of_axis, std::size_t axis_count) noexcept {
  for (int k = 0; k < 3; ++k) {
    // The lower face's outward normal is -e_k: against when -direction[k] < -cos 60 deg.
    double sign = 0.0;
    if (direction[k] > kCos60) sign = 1.0;
    if (direction[k] < -kCos60) sign = -1.0;
    if (sign == 0.0) continue;
    HoldConfig c;
    c.method = optimised ? HoldMethod::optimised : HoldMethod::simple;
    c.factor = std::clamp(channel.hold_limit_vel_factor, 0.0, 1.0);
    c.tolerance = std::max(0.0, channel.hold_limit_tolerance);
    c.coord = k;
    c.sign = sign;
    c.share = direction[k];
    const double lo = channel.workspace.lower[k];
    const double hi = channel.workspace.upper[k];
    c.face = sign > 0.0 ? lo : hi;
    // P-CHAN-00374 pos_limit: 0 is "not set" (its default; pick & place's list); a value
    // inside the cuboid on this coordinate moves the line inwards (docs/conveyor.md).
    const double pl = channel.pos_limit;
    c.line = pl != 0.0 && pl > lo && pl < hi ? pl : c.face;
    for (std::size_t i = 0; i < axis_count; ++i)
      if (xyz_of_axis[i] == k) c.axis = static_cast<int>(i);
    if (c.axis < 0) return std::nullopt;
    return c;
  }
  return std::nullopt;
}

HoldPath WorkspaceHold::path_of(const HoldState& st) const noexcept {
  return HoldPath(*st.path, st.s, st.feed, st.stops, st.ahead, st.ahead_count, cfg_.axis,
                  cfg_.sign);
}

double WorkspaceHold::inside_at(const HoldState& st, double q, double dt) const noexcept {
  return inside(q + cfg_.share * (st.travel + st.belt_v * dt));
}

namespace {

/// Samples of one block: n + 1 points [from, to], n = ceil(length / kSampleStep) in
/// [1, kMaxSamples].
int samples_of(const HoldBlock& b) noexcept {
  // Clamped as a double before the conversion: a huge length would overflow the int.
  return static_cast<int>(
      std::fmin(std::fmax(std::ceil((b.to - b.from) / kSampleStep), 1.0), double{kMaxSamples}));
}

}  // namespace

bool WorkspaceHold::active_block_against(const HoldState& st) const noexcept {
  HoldPath path = path_of(st);
  HoldBlock b;
  if (!path.next_block(b)) return false;
  const auto coord = static_cast<std::size_t>(cfg_.axis);
  const int n = samples_of(b);
  double q_prev = b.path->point(b.from)[coord];
  for (int m = 1; m <= n; ++m) {
    const double q = b.path->point(b.from + (b.to - b.from) * m / n)[coord];
    if (cfg_.sign * (q - q_prev) < -kMoveEps) return true;
    q_prev = q;
  }
  return false;
}

bool WorkspaceHold::run_crosses(const HoldState& st, double target) const noexcept {
  HoldPath path = path_of(st);
  const auto coord = static_cast<std::size_t>(cfg_.axis);
  // Nothing known ahead can reach the line when the TCP is farther from it than the known
  // path is long (|dq/ds| <= 1, a belt moving on carries the TCP away).
  if (st.belt_v >= 0.0 && inside_at(st, path.q(0.0), 0.0) > path.known() + kSamePoint) return false;
  double t = 0.0;              // time ahead at the block's start [s]
  double run_start = -1.0;     // distance ahead where the run against starts [mm]
  int budget = kSampleBudget;  // samples left this cycle
  HoldBlock b;
  bool crossing = false;
  while (!crossing && budget > 0 && path.next_block(b)) {
    const double v_run = std::max({b.feed, st.v, kLeastRunVelocity});
    const int n = samples_of(b);
    budget -= n + 1;
    bool against = false;
    double q_prev = b.path->point(b.from)[coord];
    for (int m = 0; m <= n && !crossing; ++m) {
      const double s = b.from + (b.to - b.from) * m / n;
      const double q = m == 0 ? q_prev : b.path->point(s)[coord];
      if (cfg_.sign * (q - q_prev) < -kMoveEps) against = true;
      q_prev = q;
      crossing = against && inside_at(st, q, t + (s - b.from) / v_run) < 0.0;
    }
    if (against && run_start < 0.0) run_start = b.ahead;
    if (!against && run_start >= 0.0) break;  // the run ended inside the line
    t += (b.to - b.from) / v_run;
  }
  if (!crossing) return false;
  if (run_start <= kSamePoint) return true;
  // The run starts later: enter it at factor x v_conv, braking as late as the ramp allows.
  const double tc = st.t_cycle;
  const double d1 = std::max(0.0, st.v * tc + 0.5 * st.a * tc * tc);
  const double v1 = std::max(0.0, st.v + st.a * tc);
  if (v1 <= target) return d1 >= run_start;
  const double d = st.d_max > 0.0 ? st.d_max : 1.0;
  const double j = st.j_max > 0.0 && std::isfinite(st.j_max) ? st.j_max : d / tc;
  const jerk::Ramp ramp = jerk::velocity_ramp(v1, st.a, target, d, d, j);
  return d1 + jerk::distance(v1, st.a, ramp) >= run_start;
}

bool WorkspaceHold::can_wait_a_cycle(const HoldState& st, double target) const noexcept {
  HoldPath path = path_of(st);
  // The state one cycle ahead at the present acceleration (the plan's jerk is not known here:
  // the ramps that follow are sampled against the line, so a small error is on the early side).
  const double t = st.t_cycle;
  const double d1 = std::max(0.0, st.v * t + 0.5 * st.a * t * t);
  const double v1 = std::max(0.0, st.v + st.a * t);
  if (inside_at(st, path.q(d1), t) < 0.0) return false;
  const double d = st.d_max > 0.0 ? st.d_max : 1.0;
  const double j = st.j_max > 0.0 && std::isfinite(st.j_max) ? st.j_max : d / t;
  const jerk::Ramp ramp = jerk::velocity_ramp(v1, st.a, target, d, d, j);
  jerk::State x{d1, v1, st.a};
  double elapsed = t;
  for (int p = 0; p < 3; ++p) {
    const double dur = ramp.duration[static_cast<std::size_t>(p)];
    if (!(dur > 0.0)) continue;
    const double jp = ramp.jerk[static_cast<std::size_t>(p)];
    const jerk::State from = x;
    for (int m = 1; m <= kRampSamples; ++m) {
      const double dt = dur * static_cast<double>(m) / kRampSamples;
      const jerk::State at = jerk::advance(from, jp, dt);
      if (inside_at(st, path.q(std::max(0.0, at.p)), elapsed + dt) < 0.0) return false;
    }
    x = jerk::advance(from, jp, dur);
    elapsed += dur;
  }
  return true;
}

double WorkspaceHold::decide(const HoldState& st) noexcept {
  if (st.path == nullptr || cfg_.axis < 0) return cap_;
  const double target = cfg_.factor * std::max(0.0, st.belt_v);
  if (capped_ && st.line != line_) {
    // A block end while capped: the cap holds while the path goes on against the conveying
    // direction; else it is released and decided afresh (so a run ahead keeps it at once).
    if (active_block_against(st))
      line_ = st.line;
    else
      reset();
  }
  if (capped_) {
    // The cap follows the belt (a belt slowing down must slow the tool too), with hysteresis.
    if (std::fabs(target - cap_) > kCapHysteresis * cap_ + kCapSlack) cap_ = target;
    return cap_;
  }
  const bool brake =
      cfg_.method == HoldMethod::simple ? run_crosses(st, target) : !can_wait_a_cycle(st, target);
  if (brake) {
    capped_ = true;
    line_ = st.line;
    cap_ = target;
  }
  return cap_;
}

std::optional<std::string> WorkspaceHold::check(double q) const {
  static constexpr const char* kNames[3] = {"X", "Y", "Z"};
  const char* name = kNames[cfg_.coord];
  if (cfg_.sign * (q - cfg_.face) < -kSamePoint)
    return name + (" " + core::human(q)) + " mm beyond the conveyor workspace's face " +
           core::human(cfg_.face) +
           " mm against the conveying direction while synchronised (the hold of P-AXIS-00555 "
           "did not keep it)";
  const double past = -inside(q);
  if (past > cfg_.tolerance + kSamePoint)
    return name + (" " + core::human(q)) + " mm passed the hold line " + core::human(cfg_.line) +
           " mm against the conveying direction by " + core::human(past) +
           " mm, more than hold_limit_tolerance P-CHAN-00367 " + core::human(cfg_.tolerance) +
           " mm, while synchronised";
  return std::nullopt;
}

}  // namespace ncsim::tracking
