// ipo/workspace_hold: the workspace limit against the conveying direction (see the header).

#include "ipo/workspace_hold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "jerk/jerk.hpp"

namespace ncsim::ipo {

namespace {

constexpr double kCos60 = 0.5;
constexpr double kSampleStep = 0.5;  ///< simple method: contour sample spacing [mm]
constexpr int kMaxSamples = 256;     ///< simple method: samples per block, at most
constexpr int kRampSamples = 8;      ///< optimised method: samples per ramp phase
constexpr double kEps = 1e-9;        ///< [mm]
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

double WorkspaceHold::inside_at(const HoldState& st, double s, double dt) const noexcept {
  const double x =
      st.path->point(std::clamp(s, 0.0, st.path->length()))[static_cast<std::size_t>(cfg_.axis)];
  const double q = x + cfg_.share * (st.travel + st.belt_v * dt);
  return inside(q);
}

bool WorkspaceHold::block_crosses(const HoldState& st) const noexcept {
  const planner::Chain& path = *st.path;
  // The end of the block the path is on: the end of the chain's part that contains s.
  double end = path.length();
  for (std::size_t k = 0; k < path.parts(); ++k) {
    if (path.part_end(k) > st.s) {
      end = path.part_end(k);
      break;
    }
  }
  const double v_run = std::max({st.feed, st.v, 1e-9});
  const double rest = std::max(0.0, end - st.s);
  const int n = std::clamp(static_cast<int>(std::ceil(rest / kSampleStep)), 1, kMaxSamples);
  for (int m = 0; m <= n; ++m) {
    const double s = st.s + rest * static_cast<double>(m) / n;
    if (inside_at(st, s, (s - st.s) / v_run) < 0.0) return true;
  }
  return false;
}

bool WorkspaceHold::can_wait_a_cycle(const HoldState& st, double target) const noexcept {
  // The state one cycle ahead at the present acceleration (the plan's jerk is not known here:
  // the ramps that follow are sampled against the line, so a small error is on the early side).
  const double t = st.t_cycle;
  const double s1 = st.s + std::max(0.0, st.v * t + 0.5 * st.a * t * t);
  const double v1 = std::max(0.0, st.v + st.a * t);
  if (inside_at(st, s1, t) < 0.0) return false;
  const double d = st.d_max > 0.0 ? st.d_max : 1.0;
  const double j = st.j_max > 0.0 && std::isfinite(st.j_max) ? st.j_max : d / t;
  const jerk::Ramp ramp = jerk::velocity_ramp(v1, st.a, target, d, d, j);
  jerk::State x{s1, v1, st.a};
  double elapsed = t;
  for (int p = 0; p < 3; ++p) {
    const double dur = ramp.duration[static_cast<std::size_t>(p)];
    if (!(dur > 0.0)) continue;
    const double jp = ramp.jerk[static_cast<std::size_t>(p)];
    const jerk::State from = x;
    for (int m = 1; m <= kRampSamples; ++m) {
      const double dt = dur * static_cast<double>(m) / kRampSamples;
      const jerk::State at = jerk::advance(from, jp, dt);
      if (inside_at(st, at.p, elapsed + dt) < 0.0) return false;
    }
    x = jerk::advance(from, jp, dur);
    elapsed += dur;
  }
  return true;
}

double WorkspaceHold::decide(const HoldState& st) noexcept {
  if (st.path == nullptr || cfg_.axis < 0) return cap_;
  const double target = cfg_.factor * std::max(0.0, st.belt_v);
  if (capped_ && st.line != line_) reset();  // the capped block has ended
  if (capped_) {
    // The cap follows the belt (a belt slowing down must slow the tool too), with hysteresis.
    if (std::fabs(target - cap_) > kCapHysteresis * cap_ + kCapSlack) cap_ = target;
    return cap_;
  }
  const bool brake =
      cfg_.method == HoldMethod::simple ? block_crosses(st) : !can_wait_a_cycle(st, target);
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
  char buf[256];
  if (cfg_.sign * (q - cfg_.face) < -kEps) {
    std::snprintf(buf, sizeof buf,
                  "%s %.6g mm beyond the conveyor workspace's face %.6g mm against the conveying "
                  "direction while synchronised (the hold of P-AXIS-00555 did not keep it)",
                  name, q, cfg_.face);
    return std::string(buf);
  }
  const double past = -inside(q);
  if (past > cfg_.tolerance + kEps) {
    std::snprintf(buf, sizeof buf,
                  "%s %.6g mm passed the hold line %.6g mm against the conveying direction by "
                  "%.6g mm, more than hold_limit_tolerance P-CHAN-00367 %.6g mm, while "
                  "synchronised",
                  name, q, cfg_.line, past, cfg_.tolerance);
    return std::string(buf);
  }
  return std::nullopt;
}

}  // namespace ncsim::ipo
