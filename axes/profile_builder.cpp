// axes/profile_builder.cpp: phase chaining, the 3-phase velocity change and the clamp/stop
// pieces every planner shares (see profile_builder.hpp).

#include "axes/profile_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/tolerance.hpp"

namespace ncsim::axes::detail {

namespace {

// Closed-form advance of (p, v, a) over dt with constant jerk j.
void advance(double& p, double& v, double& a, double j, double dt) noexcept {
  const jerk::State s = jerk::advance(jerk::State{p, v, a}, j, dt);
  p = s.p;
  v = s.v;
  a = s.a;
}

}  // namespace

ProfileBuilder::ProfileBuilder(Profile& out, const MotionState& start) noexcept
    : out_(out), state_(start) {
  out_.count_ = 0;
  out_.start_ = start;
  out_.t_brake_ = 0.0;
  out_.v_level_ = 0.0;
}

void ProfileBuilder::add(double jerk, double duration) noexcept {
  if (!(duration > 0.0)) return;
  if (out_.count_ >= Profile::kMaxPhases) std::abort();  // planners never need more
  out_.phases_[out_.count_++] = Phase{t_, duration, state_.p, state_.v, state_.a, jerk};
  advance(state_.p, state_.v, state_.a, jerk, duration);
  t_ += duration;
}

void ProfileBuilder::add(double jerk, double duration, double a_end) noexcept {
  add(jerk, duration);
  state_.a = a_end;
}

void ProfileBuilder::add(const Profile& tail) noexcept {
  for (const Phase& ph : tail.phases()) {
    if (out_.count_ >= Profile::kMaxPhases) std::abort();  // callers count the phases first
    Phase q = ph;
    q.t_start = t_ + ph.t_start;
    out_.phases_[out_.count_++] = q;
  }
  out_.t_brake_ = t_ + tail.t_brake();
  out_.v_level_ = tail.v_level();
  t_ += tail.duration();
  state_ = tail.end_state();
}

void ProfileBuilder::add_pulse(const std::array<double, 3>& jerk,
                               const std::array<double, 3>& duration, double sign,
                               const std::array<double, 3>& a_end, double v_end) noexcept {
  // The same steps as three add(jerk, duration, a_end) calls, on local copies of the state, the
  // time and the count: the phases written to the profile could alias the builder's members, so
  // the compiler reloaded them after every store (issue 36: ~10 % of a builder's instructions).
  MotionState st = state_;
  double t = t_;
  std::size_t n = out_.count_;
  for (std::size_t i = 0; i < 3; ++i) {
    const double jk = sign * jerk[i];
    const double dt = duration[i];
    if (dt > 0.0) {
      if (n >= Profile::kMaxPhases) std::abort();  // planners never need more
      out_.phases_[n++] = Phase{t, dt, st.p, st.v, st.a, jk};
      st = jerk::advance(st, jk, dt);
      t += dt;
    }
    st.a = a_end[i];
  }
  st.v = v_end;
  out_.count_ = n;
  state_ = st;
  t_ = t;
}

void ProfileBuilder::add(const Ramp& change, double sign) noexcept {
  // Each phase starts from the boundary value it is meant to start from, not from the rounded
  // integration of the one before: a residual acceleration of ~1e-16 A would otherwise grow
  // into a velocity error a t and a position error a t^2/2 over a long cruise that follows.
  const double a_peak = sign * change.a_peak;
  add_pulse(change.jerk, change.duration, sign, {a_peak, a_peak, 0.0}, sign * change.v_end);
}

void ProfileBuilder::add(const jerk::Crossing& cross, double sign) noexcept {
  if (!(cross.time() > 0.0)) return;
  const double a_peak = sign * cross.a_peak;
  add_pulse(cross.jerk, cross.duration, sign, {a_peak, a_peak, sign * cross.a_zero}, 0.0);
}

void ProfileBuilder::finish(const MotionState* exact_end) noexcept {
  if (exact_end != nullptr) state_ = *exact_end;
  state_.a = 0.0;  // every planned motion ends with zero acceleration
  out_.end_ = state_;
  out_.duration_ = t_;
}

void clamp_acceleration(ProfileBuilder& builder, double sign, const Dynamics& dynamics) noexcept {
  const double a = sign * builder.state().a;
  if (a > dynamics.a_max) {
    builder.add(-sign * dynamics.j_max, (a - dynamics.a_max) / dynamics.j_max,
                sign * dynamics.a_max);
  } else if (a < -dynamics.d_max) {
    builder.add(sign * dynamics.j_max, (-dynamics.d_max - a) / dynamics.j_max,
                -sign * dynamics.d_max);
  }
}

void append_rest_to_rest(ProfileBuilder& builder, double p_target,
                         const Dynamics& dynamics) noexcept {
  const double d = p_target - builder.state().p;
  if (d == 0.0) return;
  const double s = d > 0.0 ? 1.0 : -1.0;
  const double dist = std::abs(d);
  const double jerk = dynamics.j_max;
  // 002_* 2.1: "falls V nicht erreicht werden kann ... die groesste erreichbare Geschwindigkeit
  // (unter der symmetrischen Beschleunigung/Verzoegerung A+- = min(A+, A-))".
  const double a_sym = std::min(dynamics.a_max, dynamics.d_max);
  double v_reach = 0.0;
  if (dist * jerk * jerk <= 2.0 * a_sym * a_sym * a_sym) {
    v_reach = std::cbrt(0.25 * dist * dist * jerk);  // A not reached: D = 2 v sqrt(v/J)
  } else {
    const double r = a_sym / jerk;  // A reached: D = v (v/A + A/J)
    v_reach = 0.5 * a_sym * (std::sqrt(r * r + 4.0 * dist / a_sym) - r);
  }
  const double v_level = std::min(dynamics.v_max, v_reach);
  const double d_acc = ramp_distance(v_level, dynamics.a_max, jerk);
  const double d_dec = ramp_distance(v_level, dynamics.d_max, jerk);
  // A cruise that is only the rounding residue of dist - d_acc - d_dec is dropped (Numerics).
  const double d_cruise = dist - d_acc - d_dec;
  const double t_cruise = d_cruise > kResidue * dist ? d_cruise / v_level : 0.0;
  builder.set_level(v_level);
  builder.add(velocity_ramp(0.0, 0.0, v_level, dynamics.a_max, dynamics.d_max, jerk), s);
  builder.add(0.0, t_cruise);
  builder.mark_brake();
  builder.add(velocity_ramp(v_level, 0.0, 0.0, dynamics.a_max, dynamics.d_max, jerk), s);
}

double motion_sign(const MotionState& state, double fallback) noexcept {
  if (state.v != 0.0) return state.v > 0.0 ? 1.0 : -1.0;
  if (state.a != 0.0) return state.a > 0.0 ? 1.0 : -1.0;
  return fallback;
}

void append_stop(ProfileBuilder& builder, const Dynamics& dynamics) noexcept {
  const double s = motion_sign(builder.state(), 1.0);
  clamp_acceleration(builder, s, dynamics);
  const MotionState& st = builder.state();
  builder.add(
      velocity_ramp(s * st.v, s * st.a, 0.0, dynamics.a_max, dynamics.d_max, dynamics.j_max), s);
}

}  // namespace ncsim::axes::detail
