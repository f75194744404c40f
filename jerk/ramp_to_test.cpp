// Tests of velocity_ramp_to: hand-checked ramps with an end acceleration, agreement with
// velocity_ramp at a1 = 0, and seeded random cases against an independent reference: the
// shortest duration found by scanning T and bisecting on a feasibility check (for a duration T
// the reachable velocity changes lie between the areas of the lower and upper acceleration
// envelopes), with the distance integrated numerically along that envelope.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "jerk/jerk.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::jerk::StateRamp;
using ncsim::test::log_uniform;

// Upper acceleration envelope min(a0 + j t, a1 + j (T - t), cap) at t.
double upper(double a0, double a1, double cap, double j, double T, double t) {
  return std::min({a0 + j * t, a1 + j * (T - t), cap});
}

struct Case {
  double v0, a0, v1, a1, a_up, a_down, j;
};

std::vector<double> knots(double a0, double a1, double cap, double j, double T);

// Exact area of the upper envelope on [0, T]: trapezoids between its knots.
double upper_area(double a0, double a1, double cap, double j, double T) {
  const std::vector<double> k = knots(a0, a1, cap, j, T);
  double area = 0.0;
  for (std::size_t i = 1; i < k.size(); ++i)
    area += 0.5 * (k[i] - k[i - 1]) *
            (upper(a0, a1, cap, j, T, k[i - 1]) + upper(a0, a1, cap, j, T, k[i]));
  return area;
}

// dv reachable in exactly T (T >= |a1 - a0| / j), with a relative tolerance.
bool feasible(const Case& c, double T) {
  const double dv = c.v1 - c.v0;
  const double hi = upper_area(c.a0, c.a1, c.a_up, c.j, T);
  const double lo = -upper_area(-c.a0, -c.a1, c.a_down, c.j, T);
  const double tol = 1e-12 * (std::abs(dv) + std::abs(hi) + std::abs(lo) + 1e-9);
  return lo - tol <= dv && dv <= hi + tol;
}

// Knots of the upper envelope on [0, T] (between them it is linear), sorted.
std::vector<double> knots(double a0, double a1, double cap, double j, double T) {
  std::vector<double> k{0.0, T, (cap - a0) / j, T - (cap - a1) / j, 0.5 * (a1 - a0 + j * T) / j};
  for (double& x : k)
    x = std::clamp(x, 0.0, T);
  std::sort(k.begin(), k.end());
  return k;
}

// Roots of a convex f on [lo, hi]: its minimiser by golden-section search, then a bisection on
// each side where f changes sign.
template <class F>
std::vector<double> convex_roots(const F& f, double lo, double hi) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo;
  double b = hi;
  for (int i = 0; i < 300 && b - a > 1e-16 * b; ++i) {
    const double x1 = b - g * (b - a);
    const double x2 = a + g * (b - a);
    (f(x1) <= f(x2) ? b : a) = f(x1) <= f(x2) ? x2 : x1;
  }
  const double m = 0.5 * (a + b);
  std::vector<double> out;
  const auto bisect = [&](double x_neg, double x_pos) {
    for (int i = 0; i < 300 && std::abs(x_pos - x_neg) > 1e-16 * std::abs(x_pos); ++i) {
      const double mid = 0.5 * (x_neg + x_pos);
      (f(mid) <= 0.0 ? x_neg : x_pos) = mid;
    }
    out.push_back(x_pos);
  };
  if (f(m) <= 0.0) {
    if (f(lo) > 0.0) bisect(m, lo);
    if (f(hi) > 0.0) bisect(m, hi);
  }
  return out;
}

// The shortest feasible T. The feasible set is {T >= T_min: lower area <= dv <= upper area};
// the upper area is convex in T (its slope is the envelope's peak, which grows with T) and the
// lower one concave, so its smallest point is T_min or a root of one of the two: all found by
// convex_roots, the smallest that passes feasible() wins.
double reference_time(const Case& c) {
  const double t_min = std::abs(c.a1 - c.a0) / c.j;
  if (feasible(c, t_min)) return t_min;
  const double a_small = std::min(c.a_up, c.a_down);
  const double dv = std::abs(c.v1 - c.v0) + (c.a0 * c.a0 + c.a1 * c.a1) / c.j;
  const double t_hi = (std::abs(c.a0) + std::abs(c.a1)) / c.j +
                      2.0 * std::max(c.a_up, c.a_down) / c.j + 2.0 * dv / a_small;
  REQUIRE(feasible(c, t_hi));
  const double target = c.v1 - c.v0;
  auto cand = convex_roots(
      [&](double T) { return upper_area(c.a0, c.a1, c.a_up, c.j, T) - target; }, t_min, t_hi);
  const auto more = convex_roots(
      [&](double T) { return upper_area(-c.a0, -c.a1, c.a_down, c.j, T) + target; }, t_min, t_hi);
  cand.insert(cand.end(), more.begin(), more.end());
  std::sort(cand.begin(), cand.end());
  for (double T : cand)
    if (feasible(c, T)) return T;
  FAIL("no root of the envelope areas is feasible");
  return t_hi;
}

// Distance along the envelope of duration T that carries dv (the one whose area is nearer dv),
// integrated exactly between its knots (a is linear there).
double reference_distance(const Case& c, double T) {
  const double dv = c.v1 - c.v0;
  const double hi = upper_area(c.a0, c.a1, c.a_up, c.j, T);
  const double lo = -upper_area(-c.a0, -c.a1, c.a_down, c.j, T);
  const bool use_upper = std::abs(dv - hi) <= std::abs(dv - lo);
  const auto a_of = [&](double t) {
    return use_upper ? upper(c.a0, c.a1, c.a_up, c.j, T, t)
                     : -upper(-c.a0, -c.a1, c.a_down, c.j, T, t);
  };
  const std::vector<double> k =
      use_upper ? knots(c.a0, c.a1, c.a_up, c.j, T) : knots(-c.a0, -c.a1, c.a_down, c.j, T);
  double v = c.v0;
  double s = 0.0;
  for (std::size_t i = 1; i < k.size(); ++i) {
    const double h = k[i] - k[i - 1];
    const double a_l = a_of(k[i - 1]);
    const double a_r = a_of(k[i]);
    s += h * v + h * h * (2.0 * a_l + a_r) / 6.0;
    v += 0.5 * h * (a_l + a_r);
  }
  return s;
}

struct End {
  double v = 0.0, a = 0.0, a_min = 0.0, a_max = 0.0;
};

End walk(const Case& c, const StateRamp& r) {
  ncsim::jerk::State st{0.0, c.v0, c.a0};
  End e{c.v0, c.a0, c.a0, c.a0};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(r.duration[i] >= 0.0);
    CHECK((r.duration[i] == 0.0 || std::abs(std::abs(r.jerk[i]) - c.j) <= 0.0 || r.jerk[i] == 0.0));
    st = ncsim::jerk::advance(st, r.jerk[i], r.duration[i]);
    e.a_min = std::min(e.a_min, st.a);
    e.a_max = std::max(e.a_max, st.a);
  }
  e.v = st.v;
  e.a = st.a;
  return e;
}

StateRamp ramp_of(const Case& c) {
  return ncsim::jerk::velocity_ramp_to(c.v0, c.a0, c.v1, c.a1, c.a_up, c.a_down, c.j);
}

}  // namespace

TEST_CASE("velocity_ramp_to: rest to an acceleration of A in one jerk phase (hand-checked)") {
  // J = 1e5, A = 1000: a = 1000 after 0.01 s, dv = J t^2 / 2 = 5 mm/s, s = J t^3 / 6.
  const StateRamp r = ncsim::jerk::velocity_ramp_to(0.0, 0.0, 5.0, 1000.0, 1000.0, 1000.0, 1e5);
  CHECK(r.time() == doctest::Approx(0.01).epsilon(1e-14));
  CHECK(r.duration[1] == 0.0);
  CHECK(r.duration[2] == 0.0);
  CHECK(ncsim::jerk::distance(0.0, 0.0, r) == doctest::Approx(1e5 * 1e-6 / 6.0).epsilon(1e-13));
}

TEST_CASE("velocity_ramp_to: a gain beyond the build-up holds A and ends at a1 = A") {
  // dv = 10: 5 mm/s in the build-up to A, the other 5 at A (0.005 s), no jerk back.
  const StateRamp r = ncsim::jerk::velocity_ramp_to(0.0, 0.0, 10.0, 1000.0, 1000.0, 1000.0, 1e5);
  CHECK(r.duration[0] == doctest::Approx(0.01).epsilon(1e-14));
  CHECK(r.duration[1] == doctest::Approx(0.005).epsilon(1e-13));
  CHECK(r.duration[2] == 0.0);
  CHECK(r.a_peak == 1000.0);
  // s = J t1^3 / 6 + (5 t_h + A t_h^2 / 2) = 1/60 + 0.025 + 0.0125.
  CHECK(ncsim::jerk::distance(0.0, 0.0, r) ==
        doctest::Approx(1.0 / 60.0 + 0.025 + 0.0125).epsilon(1e-12));
}

TEST_CASE("velocity_ramp_to: both accelerations negative and a small gain needs a positive peak") {
  // a0 = a1 = -500, dv = 0: no motion of a at all; dv = +1e-3: a must become positive, so the
  // duration jumps from 0 to more than 2 * 500 / J (the problem's own discontinuity).
  const double j = 1e5;
  const StateRamp same = ncsim::jerk::velocity_ramp_to(10.0, -500.0, 10.0, -500.0, 1e3, 1e3, j);
  CHECK(same.time() == 0.0);
  const StateRamp gain = ncsim::jerk::velocity_ramp_to(10.0, -500.0, 10.001, -500.0, 1e3, 1e3, j);
  CHECK(gain.time() > 2.0 * 500.0 / j);
  CHECK(gain.a_peak > 0.0);
  const StateRamp loss = ncsim::jerk::velocity_ramp_to(10.0, -500.0, 9.999, -500.0, 1e3, 1e3, j);
  CHECK(loss.time() < 1e-4);
  CHECK(loss.a_peak < -500.0);
}

TEST_CASE("velocity_ramp_to with a1 = 0 is velocity_ramp (seeded)") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 0; n < 2000; ++n) {
    const double v_max = log_uniform(rng, 1.0, 1e4);
    const double a_up = log_uniform(rng, 10.0, 1e5);
    const double a_down = log_uniform(rng, 10.0, 1e5);
    const double j = log_uniform(rng, 1e2, 1e7);
    const double v0 = v_max * unit(rng);
    const double v1 = v_max * unit(rng);
    const double a0 = n % 3 == 0 ? 0.0 : (unit(rng) > 0.0 ? a_up : a_down) * unit(rng);
    const double a0c = std::clamp(a0, -a_down, a_up);
    const StateRamp r = ncsim::jerk::velocity_ramp_to(v0, a0c, v1, 0.0, a_up, a_down, j);
    const ncsim::jerk::Ramp ref = ncsim::jerk::velocity_ramp(v0, a0c, v1, a_up, a_down, j);
    const double scale_t = ref.time() + (a_up + a_down) / j;
    CHECK(r.time() == doctest::Approx(ref.time()).epsilon(1e-9).scale(scale_t));
    const double d_ref = ncsim::jerk::distance(v0, a0c, ref);
    CHECK(ncsim::jerk::distance(v0, a0c, r) ==
          doctest::Approx(d_ref).epsilon(1e-9).scale(std::abs(d_ref) + v_max * scale_t));
  }
}

TEST_CASE(
    "velocity_ramp_to is the shortest change to (v1, a1) and reaches it (seeded, reference)") {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int pulses = 0;
  int holds = 0;
  for (int n = 0; n < 400; ++n) {
    Case c{};
    const double v_max = log_uniform(rng, 1.0, 1e4);
    c.a_up = log_uniform(rng, 10.0, 1e5);
    c.a_down = log_uniform(rng, 10.0, 1e5);
    c.j = log_uniform(rng, 1e2, 1e7);
    const auto draw_a = [&](int kind) {
      switch (kind) {
        case 0:
          return 0.0;
        case 1:
          return c.a_up;
        case 2:
          return -c.a_down;
        default:
          return unit(rng) > 0.0 ? c.a_up * std::abs(unit(rng)) : -c.a_down * std::abs(unit(rng));
      }
    };
    c.a0 = draw_a(n % 7);
    c.a1 = draw_a((n / 7) % 5);
    c.v0 = v_max * unit(rng);
    // A fifth of the velocity changes are small (of the order of the jerk phases').
    const double small = (c.a_up * c.a_up + c.a_down * c.a_down) / c.j;
    c.v1 = n % 5 == 0 ? c.v0 + small * unit(rng) : v_max * unit(rng);
    const StateRamp r = ramp_of(c);
    CAPTURE(n);
    CAPTURE(c.v0);
    CAPTURE(c.a0);
    CAPTURE(c.v1);
    CAPTURE(c.a1);
    CAPTURE(c.a_up);
    CAPTURE(c.a_down);
    CAPTURE(c.j);
    const End e = walk(c, r);
    const double v_scale = std::abs(c.v0) + std::abs(c.v1) + (c.a_up + c.a_down) * r.time();
    CHECK(e.v == doctest::Approx(c.v1).epsilon(1e-10).scale(v_scale));
    CHECK(e.a == doctest::Approx(c.a1).epsilon(1e-10).scale(c.a_up + c.a_down));
    CHECK(e.a_max <= c.a_up + 1e-12 * (c.a_up + c.a_down));
    CHECK(e.a_min >= -c.a_down - 1e-12 * (c.a_up + c.a_down));
    CHECK(r.v_end == c.v1);
    CHECK(r.a_end == c.a1);
    const double t_ref = reference_time(c);
    const double t_scale = t_ref + (c.a_up + c.a_down) / c.j;
    CHECK(r.time() == doctest::Approx(t_ref).epsilon(1e-8).scale(t_scale));
    const double s_ref = reference_distance(c, t_ref);
    CHECK(ncsim::jerk::distance(c.v0, c.a0, r) ==
          doctest::Approx(s_ref).epsilon(1e-6).scale(std::abs(s_ref) + v_scale * t_ref));
    pulses += r.duration[0] > 0.0 && r.duration[2] > 0.0 ? 1 : 0;
    holds += r.duration[1] > 0.0 ? 1 : 0;
  }
  // The draws cover both shapes: pulses with and without a hold at a limit.
  CHECK(pulses > 100);
  CHECK(holds > 50);
}

TEST_CASE("time_at_distance and state_at cut a ramp at a distance (seeded, forward ramps)") {
  // Ramps between positive velocities from accelerations within the limits; each is cut at the
  // position of a random instant, and the cut must return that instant's state.
  std::mt19937_64 rng(2211);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cuts = 0;
  for (int n = 0; n < 2000; ++n) {
    const double v_max = log_uniform(rng, 1.0, 1e4);
    const double a_up = log_uniform(rng, 10.0, 1e5);
    const double a_down = log_uniform(rng, 10.0, 1e5);
    const double j = log_uniform(rng, 1e2, 1e7);
    const double v0 = v_max * (0.5 + 0.5 * unit(rng));
    const double v1 = v_max * (0.5 + 0.5 * unit(rng));
    // Small accelerations relative to the velocity: the velocity stays positive.
    const double a_small = std::min(std::sqrt(0.5 * v_max * j), std::min(a_up, a_down));
    const double a0 = a_small * (2.0 * unit(rng) - 1.0) * 0.9;
    const double a1 = a_small * (2.0 * unit(rng) - 1.0) * 0.9;
    const StateRamp r = ncsim::jerk::velocity_ramp_to(v0, a0, v1, a1, a_up, a_down, j);
    const double t = r.time() * unit(rng);
    const ncsim::jerk::State at = ncsim::jerk::state_at(v0, a0, r, t);
    if (!(at.v > 0.0)) continue;
    ++cuts;
    CAPTURE(n);
    const double t_cut = ncsim::jerk::time_at_distance(v0, a0, r, at.p);
    CHECK(t_cut == doctest::Approx(t).epsilon(1e-9).scale(r.time() + 1e-12));
    const ncsim::jerk::State cut = ncsim::jerk::state_at(v0, a0, r, t_cut);
    CHECK(cut.v == doctest::Approx(at.v).epsilon(1e-9).scale(v_max));
    CHECK(cut.a == doctest::Approx(at.a).epsilon(1e-9).scale(a_up + a_down));
  }
  CHECK(cuts > 1500);
  // The ends: 0 before the start, the whole ramp beyond its distance.
  const StateRamp r = ncsim::jerk::velocity_ramp_to(10.0, 0.0, 20.0, 500.0, 1e3, 1e3, 1e5);
  CHECK(ncsim::jerk::time_at_distance(10.0, 0.0, r, -1.0) == 0.0);
  CHECK(ncsim::jerk::time_at_distance(10.0, 0.0, r, 1e9) == r.time());
  const ncsim::jerk::State end = ncsim::jerk::state_at(10.0, 0.0, r, r.time());
  CHECK(end.v == 20.0);
  CHECK(end.a == 500.0);
}
