// axes/profile_outside.cpp: the recovery from a start outside the limits and the time-optimal
// profile behind it (docs/axes-profile-outside.md).
//
// The recovery works in the frame of the motion (sign of v, else of a; frame v >= 0) and picks,
// state by state, the one excess to remove at full jerk J:
//  A. acceleration beyond its limit (a > A+, or a < -A- while moving): jerk toward a = 0 until
//     the limit (or v = 0, where the limit switches from A- to A+);
//  C. braking whose release ends beyond -V (v - a^2/(2J) < -V): jerk +J to a = 0 (the release
//     velocity is constant under +J: the overshoot is forced, nothing gets inside sooner);
//     braking that crosses v = 0 with |a| beyond A+ (a^2 - 2 J v > A+^2, constant under +J):
//     jerk +J to v = 0, where A then takes the acceleration back to A+;
//  B. |v| > V, or a release ending beyond V: inside at v = V needs a >= -a_b,
//     a_b = min(A-, 2 sqrt(J V), sqrt(A+^2 + 2 J V)) (a release from there stays within -V
//     and crosses v = 0 within A+); the fastest way:
//     -J to a peak p <= A-, [hold], +J to -a_b arriving at v = V (or -J alone where that
//     reaches V with |a| <= a_b).
// Each rule ends on an event (a limit, v = 0, v = V, a = 0) whose value is set exactly, then
// the state is tested again; a start inside gets no phase.
//
// The manual rule's recovery (manual_recover) treats only the starts whose forced part reverses
// the motion: C (then the manual's velocity change to V with A-, a = 0 on arrival, 002_* 2.2,
// as one velocity_ramp in the frame of the release) and A up to v = 0; the manual plan follows.

#include "axes/profile_outside.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axes/profile_builder.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes::detail {

namespace {

constexpr double kForever = std::numeric_limits<double>::infinity();

double release_velocity(double v, double a, double j) noexcept {
  return v + a * std::abs(a) / (2.0 * j);
}

// Smallest t in (0, t_max] at which v + a t + jr t^2 / 2 falls through `level` (velocity
// decreasing there); negative when there is none.
double falling_crossing(double v, double a, double jr, double level, double t_max) noexcept {
  double best = -1.0;
  const auto take = [&](double t) {
    const bool falling = a + jr * t <= kRelRounding * (std::abs(a) + std::abs(jr * t));
    if (t > 0.0 && t <= t_max && falling && (best < 0.0 || t < best)) best = t;
  };
  const double c = v - level;
  if (jr == 0.0) {
    if (a < 0.0) take(-c / a);
    return best;
  }
  double disc = a * a - 2.0 * jr * c;
  if (disc < 0.0 && disc >= -kRelRounding * (a * a + std::abs(2.0 * jr * c)))
    disc = 0.0;  // touching
  if (disc < 0.0) return best;
  const double sq = std::sqrt(disc);
  take((-a - sq) / jr);
  take((-a + sq) / jr);
  return best;
}

// Frame state (v > 0, a < 0) whose fastest release crosses v = 0 with |a| beyond A+ (the
// limit there switches from A- to A+; a^2 - 2 J v is constant under +J, so it is forced).
bool crossing_excess(double v, double a, const Dynamics& dyn) noexcept {
  if (!(v > 0.0 && a < 0.0) || release_velocity(v, a, dyn.j_max) >= 0.0) return false;
  const double two_jv = 2.0 * dyn.j_max * v;  // tolerance relative to the terms' rounding
  return a * a - two_jv > dyn.a_max * dyn.a_max + kRelRounding * (a * a + two_jv);
}

}  // namespace

bool outside_limits(const MotionState& s, const Dynamics& dyn) noexcept {
  const double v_lim = dyn.v_max * (1.0 + kRelRounding);
  if (std::abs(s.v) > v_lim) return true;
  const double av = s.a * s.v;
  const double cap = av < 0.0 ? dyn.d_max : dyn.a_max;  // at v = 0 any a speeds up: A+
  if (std::abs(s.a) > cap * (1.0 + kRelRounding)) return true;
  if (std::abs(release_velocity(s.v, s.a, dyn.j_max)) > v_lim) return true;
  return av < 0.0 && crossing_excess(std::abs(s.v), -std::abs(s.a), dyn);
}

double Recovery::time() const noexcept {
  double t = 0.0;
  for (std::size_t i = 0; i < count; ++i)
    t += duration[i];
  return t;
}

bool recover(const MotionState& start, const Dynamics& dyn, Recovery& out) noexcept {
  out = Recovery{};
  MotionState st = start;
  const double j_max = dyn.j_max;
  const double v_max = dyn.v_max;
  const auto push = [&](double m, double jr, double t) {
    if (!(t > 0.0)) return true;
    if (out.count >= Recovery::kMaxPhases) return false;
    out.jerk[out.count] = m * jr;
    out.duration[out.count] = t;
    ++out.count;
    st = jerk::advance(st, m * jr, t);
    out.a_end[out.count - 1] = st.a;
    return true;
  };
  // After an event's value is set exactly, the last phase ends on it.
  const auto settle = [&] {
    if (out.count > 0) out.a_end[out.count - 1] = st.a;
  };
  for (int round = 0; round < 8; ++round) {
    if (!outside_limits(st, dyn)) {
      out.end = st;
      return true;
    }
    const double m = motion_sign(st, 1.0);
    const double v = m * st.v;
    const double a = m * st.a;
    if (a > dyn.a_max * (1.0 + kRelRounding)) {  // A: speeding up beyond A+
      if (!push(m, -j_max, (a - dyn.a_max) / j_max)) return false;
      st.a = m * dyn.a_max;
      settle();
    } else if (v > 0.0 && a < -dyn.d_max * (1.0 + kRelRounding)) {  // A: braking beyond A-
      const double t_a = (-dyn.d_max - a) / j_max;
      const double disc = a * a - 2.0 * j_max * v;
      const double t_zero = disc >= 0.0 ? (-a - std::sqrt(disc)) / j_max : -1.0;
      if (t_zero > 0.0 && t_zero < t_a) {  // v = 0 first: the limit becomes A+
        if (!push(m, j_max, t_zero)) return false;
        st.v = 0.0;
        settle();
      } else {
        if (!push(m, j_max, t_a)) return false;
        st.a = -m * dyn.d_max;
        settle();
      }
    } else if (crossing_excess(v, a, dyn) &&
               release_velocity(v, a, j_max) >= -v_max * (1.0 + kRelRounding)) {  // C': to v = 0
      const double t_zero = (-a - std::sqrt(std::max(0.0, a * a - 2.0 * j_max * v))) / j_max;
      if (!push(m, j_max, t_zero)) return false;
      st.v = 0.0;
      settle();
    } else if (a < 0.0 && release_velocity(v, a, j_max) < -v_max * (1.0 + kRelRounding)) {  // C
      const double v_release = release_velocity(v, a, j_max);
      if (!push(m, j_max, -a / j_max)) return false;
      st.v = m * v_release;
      st.a = 0.0;
      settle();
    } else {  // B: |v| > V or a release beyond V
      // Inside at v = V needs a >= -a_b (a release within -V). The fastest way there: brake
      // at -J to the peak p (at most A-), [hold], ease at +J to -a_b just as v reaches V.
      const double a_b = std::min({dyn.d_max, 2.0 * std::sqrt(j_max * v_max),
                                   std::sqrt(dyn.a_max * dyn.a_max + 2.0 * j_max * v_max)});
      const double x2 = a * a + 2.0 * j_max * (v - v_max);  // a^2 where -J alone reaches V
      const double p2 = 0.5 * (x2 + a_b * a_b);             // peak^2 of brake-and-ease
      if (x2 <= a_b * a_b) {                                // -J alone reaches v = V inside
        const double t = falling_crossing(v, a, -j_max, v_max, kForever);
        if (!(t >= 0.0) || !push(m, -j_max, t)) return false;
        st.v = m * v_max;
      } else if (a < -std::sqrt(p2)) {  // braking harder than the peak: ease through v = V
        const double t = falling_crossing(v, a, j_max, v_max, kForever);
        if (!(t >= 0.0) || !push(m, j_max, t)) return false;
        st.v = m * v_max;
      } else {
        const double p = std::min(std::sqrt(p2), dyn.d_max);
        if (!push(m, -j_max, (a + p) / j_max)) return false;
        st.a = -m * p;
        settle();
        const double ease = (p * p - a_b * a_b) / (2.0 * j_max);  // velocity the ease removes
        const double hold = (m * st.v - ease - v_max) / p;
        if (hold > 0.0) {
          if (!push(m, 0.0, hold)) return false;
          st.a = -m * p;
          settle();
        }
        if (!push(m, j_max, (p - a_b) / j_max)) return false;
        st.v = m * v_max;
        st.a = -m * a_b;
        settle();
      }
    }
  }
  if (outside_limits(st, dyn)) return false;
  out.end = st;
  return true;
}

namespace {

// `recovery` followed by `cont` (planned from the recovery's end) into `out`, ending exactly on
// the target. False (out untouched) when the phases do not fit into one Profile.
bool concatenate(const MotionState& start, const Recovery& r, const Profile& cont,
                 const PositionTarget& target, Profile& out) noexcept {
  const auto phases = cont.phases();
  if (r.count + phases.size() > Profile::kMaxPhases) return false;
  ProfileBuilder b(out, start);
  for (std::size_t i = 0; i < r.count; ++i) {
    b.add(r.jerk[i], r.duration[i], r.a_end[i]);
  }
  b.set_level(cont.v_level());
  bool braked = false;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (!braked && phases[i].t_start >= cont.t_brake()) {
      b.mark_brake();
      braked = true;
    }
    b.add(phases[i].j, phases[i].duration, i + 1 < phases.size() ? phases[i + 1].a : 0.0);
  }
  if (!braked) b.mark_brake();
  const MotionState end{target.p, target.v, 0.0};
  b.finish(&end);
  return true;
}

}  // namespace

bool plan_from_outside(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                       Profile& out) noexcept {
  Recovery r;
  if (!recover(start, dyn, r)) return false;
  Profile cont;
  if (plan_position(r.end, target, dyn, cont, ProfileRule::time_optimal) != Result::ok) {
    return false;
  }
  return concatenate(start, r, cont, target, out);
}

bool manual_recover(const MotionState& start, const Dynamics& dyn, Recovery& out) noexcept {
  out = Recovery{};
  MotionState st = start;
  const double j_max = dyn.j_max;
  const auto push = [&](double jerk, double t, double a_end) {
    if (!(t > 0.0)) return;
    out.jerk[out.count] = jerk;
    out.duration[out.count] = t;
    out.a_end[out.count] = a_end;
    ++out.count;
    st = jerk::advance(st, jerk, t);
    st.a = a_end;
  };
  if (!outside_limits(st, dyn)) return true;
  const double m = motion_sign(st, 1.0);
  const double v = m * st.v;
  const double a = m * st.a;
  if (a < 0.0 && release_velocity(v, a, j_max) < -dyn.v_max * (1.0 + kRelRounding)) {
    // The release reverses the motion beyond -V (forced); in the frame of the release the
    // velocity change to the level V is a reduction, limited by A- (002_* 2.2: the override's
    // ramp to the new level, a = 0 on arrival). velocity_ramp's first phase is the release
    // itself, continued to the braking peak.
    const double n = -m;
    const jerk::Ramp r =
        jerk::velocity_ramp(n * st.v, n * st.a, dyn.v_max, dyn.a_max, dyn.d_max, j_max);
    push(n * r.jerk[0], r.duration[0], n * r.a_peak);
    push(n * r.jerk[1], r.duration[1], n * r.a_peak);
    push(n * r.jerk[2], r.duration[2], 0.0);
    st.v = n * dyn.v_max;
    st.a = 0.0;
  } else if (v > 0.0 && a < -dyn.d_max * (1.0 + kRelRounding)) {
    // Braking beyond A- that reaches v = 0 before the acceleration is back at -A-: the clamp's
    // jerk (+J) until v = 0 only. Beyond v = 0 the acceleration speeds the motion up (A+), and
    // a clamp to -A- in the old frame would brake the reversed motion with A+ (seen: 367 A-).
    const double disc = a * a - 2.0 * j_max * v;
    const double t_zero = disc >= 0.0 ? (-a - std::sqrt(disc)) / j_max : -1.0;
    if (t_zero > 0.0 && t_zero < (-dyn.d_max - a) / j_max) {
      push(m * j_max, t_zero, -m * std::sqrt(disc));
      st.v = 0.0;
    }
  }
  out.end = st;
  return true;
}

bool plan_manual_from_outside(const MotionState& start, const PositionTarget& target,
                              const Dynamics& dyn, Profile& out) noexcept {
  Recovery r;
  if (!manual_recover(start, dyn, r) || r.count == 0) return false;
  Profile cont;
  if (plan_position(r.end, target, dyn, cont, ProfileRule::manual) != Result::ok) return false;
  return concatenate(start, r, cont, target, out);
}

}  // namespace ncsim::axes::detail
