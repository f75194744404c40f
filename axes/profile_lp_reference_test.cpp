// ProfileRule::time_optimal against the shape-free reference of profile_lp_reference.hpp
// (issue 11 "Proof": never slower than an independent reference by more than 1e-9 relative).
// Tier 1 (LP on N equal steps, bisection on T) bounds every case; tier 2 (the LP's arcs
// solved exactly) gives T_exact to ~1e-12 where it converges to a valid profile.

#include "axes/profile_lp_reference.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "axes/profile.hpp"
#include "axes/profile_limits_check.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;
using ncsim::test::log_uniform;
namespace lp = ncsim::test::lp;

struct Case {
  double v0 = 0, a0 = 0, d = 0, v1 = 0;
  Dynamics dyn{};
};

int env_int(const char* name, int fallback) {
  const char* s = std::getenv(name);
  return s ? std::atoi(s) : fallback;
}

lp::Problem problem(const Case& c) {
  return lp::Problem{c.v0, c.a0, c.d, c.v1, c.dyn.v_max, c.dyn.a_max, c.dyn.d_max, c.dyn.j_max};
}

Dynamics draw_dynamics(std::mt19937_64& rng) {
  return Dynamics{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                  log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
}

// An acceleration inside the path limits for v whose release stays within +-V.
double draw_acc(std::mt19937_64& rng, double v, const Dynamics& d) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double x = u(rng);
  const bool slows = x * v < 0.0;
  return x * (slows ? d.d_max : std::min(d.a_max, d.d_max));
}

bool inside(const Case& c) {
  return ncsim::test::limits_detail::inside(c.v0, c.a0, c.dyn, 1e-12);
}

// Mirror a case (the kernel must not care about the sign of the way).
Case mirrored(Case c, bool flip) {
  if (flip) {
    c.v0 = -c.v0;
    c.a0 = -c.a0;
    c.d = -c.d;
    c.v1 = -c.v1;
  }
  return c;
}

struct Outcome {
  double t_kernel = 0;
  double t_lp = 0;
  double t_exact = 0;  // 0 when the refinement failed
  std::string shape, why;
  int turns = 0, extremes = 0;
};

int count_turns(const lp::Problem& q, const std::vector<lp::Arc>& arcs) {
  // Sign changes of v along the arcs (at the ends of arcs and at the extremes inside).
  int turns = 0;
  long double v = q.v0, a = q.a0;
  int last = v > 0 ? 1 : (v < 0 ? -1 : 0);
  const long double eps = 1e-12L * q.vmax;
  for (const auto& g : arcs) {
    const long double jj = lp::arc_jerk(q, g);
    for (int k = 1; k <= 16; ++k) {
      const long double x = g.t * k / 16;
      const long double vx = v + x * (a + x * jj / 2);
      const int s = vx > eps ? 1 : (vx < -eps ? -1 : 0);
      if (s != 0) {
        if (last != 0 && s != last) ++turns;
        last = s;
      }
    }
    v += g.t * (a + g.t * jj / 2);
    a += g.t * jj;
  }
  return turns;
}

int count_extremes(const std::vector<lp::Arc>& arcs) {
  int ext = 0, last = 0;
  for (const auto& g : arcs) {
    if (g.kind != 1 && g.kind != -1) continue;
    if (last != 0 && g.kind != last) ++ext;
    last = g.kind;
  }
  return ext;
}

// Step signs of a profile's velocity on n steps of its duration (free where v may change its
// sign in a step, and one step either side): a seed for the LP's patterns.
std::vector<int> pattern_of(const Profile& p, int n) {
  std::vector<int> s(static_cast<std::size_t>(n), 0);
  const double h = p.duration() / n;
  for (int k = 0; k < n; ++k) {
    bool pos = true, neg = true;
    for (int m = 0; m <= 8; ++m) {
      const double v = p.at((k + m / 8.0) * h).v;
      pos = pos && v > 0.0;
      neg = neg && v < 0.0;
    }
    s[static_cast<std::size_t>(k)] = pos ? 1 : (neg ? -1 : 0);
  }
  std::vector<int> out = s;
  for (int k = 0; k < n; ++k)
    if (s[static_cast<std::size_t>(k)] == 0)
      for (int m = std::max(0, k - 1); m <= std::min(n - 1, k + 1); ++m)
        out[static_cast<std::size_t>(m)] = 0;
  return out;
}

Outcome run_case(const Case& c, int n_steps) {
  Outcome o;
  Profile p;
  REQUIRE(ncsim::axes::plan_position(MotionState{0.0, c.v0, c.a0}, PositionTarget{c.d, c.v1}, c.dyn,
                                     p, ProfileRule::time_optimal) == Result::ok);
  o.t_kernel = p.duration();
  const auto end = p.at(p.duration());
  CHECK(end.p == c.d);
  CHECK(end.v == c.v1);
  CHECK(end.a == 0.0);
  const std::string bad =
      ncsim::test::profile_limit_violation(p, c.dyn, MotionState{0.0, c.v0, c.a0});
  CHECK_MESSAGE(bad.empty(), bad);
  const lp::Problem q = problem(c);
  lp::LpOracle oracle(q, n_steps);
  const long double t_lp = oracle.min_time(o.t_kernel, {pattern_of(p, n_steps)});
  o.t_lp = static_cast<double>(t_lp);
  if (!std::isfinite(o.t_lp)) return o;
  const lp::Exact ex = lp::refine(q, oracle.u(), t_lp);
  o.shape = lp::describe(ex.arcs);
  o.why = ex.why;
  if (ex.ok) {
    o.t_exact = static_cast<double>(ex.t);
    o.turns = count_turns(q, ex.arcs);
    o.extremes = count_extremes(ex.arcs);
  }
  return o;
}

// Cases of issue 11's ranges (V 1..1e4, A+ and A- 10..1e5, J 1e2..1e7, distances 1e-4..1e4 mm
// or relative to the braking scale V^2 / min(A)), starts inside the limits, mirrored at random.
// group 0: forward starts toward the target (v0, v1 >= 0, a0 inside), the proven region;
// 1: arrival velocity against the way to the target (far or close): one or two turns;
// 2: starts on the limit moving away ((-V, +A-) or near it) that must turn round;
// 3: starts moving away from a far target: the turn, then a cruise at V;
// 4: braking starts (v0 > 0, a0 < 0) with a close target (1e-5..0.1 of the braking scale)
//    either side, arriving at rest or moving back: they must turn round (the kernel's slow
//    class, docs/axes-profile.md).
Case draw_case(std::mt19937_64& rng, int group) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Case c;
  c.dyn = draw_dynamics(rng);
  const Dynamics& d = c.dyn;
  const double scale = d.v_max * d.v_max / std::min(d.a_max, d.d_max);
  const bool far = unit(rng) < 0.5;
  if (group == 0) {
    c.v0 = d.v_max * unit(rng);
    c.a0 = draw_acc(rng, c.v0, d);
    c.d = log_uniform(rng, 1e-4, 1e4);
    c.v1 = unit(rng) < 0.3 ? 0.0 : d.v_max * unit(rng);
  } else if (group == 1) {
    c.v0 = d.v_max * (2 * unit(rng) - 1);
    c.a0 = draw_acc(rng, c.v0, d);
    c.d = far ? log_uniform(rng, 1e-4, 1e4) : scale * log_uniform(rng, 1e-4, 1.0);
    c.v1 = -d.v_max * unit(rng);
  } else if (group == 2) {
    c.v0 = -d.v_max * (unit(rng) < 0.5 ? 1.0 : 0.9 + 0.1 * unit(rng));
    c.a0 = d.d_max * (unit(rng) < 0.5 ? 1.0 : 0.5 + 0.5 * unit(rng));
    c.d = far ? log_uniform(rng, 1e-4, 1e4) : scale * log_uniform(rng, 1e-4, 1.0);
    const double r = unit(rng);
    c.v1 = r < 0.4 ? 0.0 : (r < 0.7 ? d.v_max * unit(rng) : -d.v_max * unit(rng));
  } else if (group == 4) {
    c.v0 = d.v_max * unit(rng);
    c.a0 = -std::min(d.d_max, std::sqrt(2.0 * d.j_max * c.v0)) * unit(rng);
    c.d = (unit(rng) < 0.5 ? -1.0 : 1.0) * scale * log_uniform(rng, 1e-5, 1e-1);
    c.v1 = unit(rng) < 0.3 ? 0.0 : -d.v_max * unit(rng);
  } else {
    c.v0 = -d.v_max * unit(rng);
    c.a0 = draw_acc(rng, c.v0, d);
    c.d = far ? log_uniform(rng, 1e-4, 1e4) : scale * (2.0 + 100.0 * unit(rng));
    c.v1 = unit(rng) < 0.4 ? 0.0 : d.v_max * unit(rng);
  }
  return mirrored(c, unit(rng) < 0.5);
}

std::string describe_case(const Case& c, const Outcome& o) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "v0=%.17g a0=%.17g d=%.17g v1=%.17g V=%.17g A+=%.17g A-=%.17g J=%.17g: "
                "kernel %.15g s, T_lp %.15g s, T_exact %.15g s (%s)",
                c.v0, c.a0, c.d, c.v1, c.dyn.v_max, c.dyn.a_max, c.dyn.d_max, c.dyn.j_max,
                o.t_kernel, o.t_lp, o.t_exact, o.shape.c_str());
  return buf;
}

// LP steps (docs/axes-profile.md: the gap this leaves); NCSIM_LP_STEPS for measurements.
const int kSteps = env_int("NCSIM_LP_STEPS", 64);

}  // namespace

TEST_CASE("the LP reference is a restriction: never below the proven rest-to-rest optimum") {
  // Rest to rest the kernel is the minimum time (profile_optimal_test.cpp's reference). The
  // LP's T_lp may exceed it by its discretisation (measured below) but not undercut it by more
  // than GLPK's feasibility tolerance; tier 2 must give the kernel's time to 1e-9 both ways.
  std::mt19937_64 rng(20261125);
  const int cases = env_int("NCSIM_LP_CASES", 60);
  double gap_max = 0.0, gap_min = 1.0, gap_sum = 0.0;
  int exact = 0;
  for (int n = 0; n < cases; ++n) {
    Case c;
    c.dyn = draw_dynamics(rng);
    c.d = log_uniform(rng, 1e-4, 1e4);
    const Outcome o = run_case(c, kSteps);
    INFO(describe_case(c, o));
    REQUIRE(std::isfinite(o.t_lp));
    const double gap = o.t_lp / o.t_kernel - 1.0;
    CHECK(gap >= -1e-5);
    gap_max = std::max(gap_max, gap);
    gap_min = std::min(gap_min, gap);
    gap_sum += gap;
    if (o.t_exact > 0.0) {
      ++exact;
      CHECK(std::abs(o.t_kernel / o.t_exact - 1.0) <= 1e-9);
    }
  }
  MESSAGE("rest to rest, N = ", kSteps, ": T_lp / T_opt - 1 in [", gap_min, ", ", gap_max,
          "], mean ", gap_sum / cases, "; exact refinement ", exact, " of ", cases);
  CHECK(gap_max < 0.05);      // the LP's resolution at N = 64 (measured 0.038)
  CHECK(exact >= cases / 2);  // tier 2 converges (measured 51 of 80)
}

TEST_CASE(
    "time-optimal is never slower than the shape-free LP reference (two turns, three "
    "extremes, cruise after a turn)") {
  std::mt19937_64 rng(20261126);
  const int per_group = env_int("NCSIM_LP_CASES", 60);
  const bool verbose = env_int("NCSIM_LP_VERBOSE", 0) != 0;
  int total = 0, with_lp = 0, with_exact = 0, two_turns = 0, three_ext = 0;
  int slower_lp = 0, slower_exact = 0;
  for (int group = 0; group < 5; ++group) {
    // Group 4 (the braking turns, the class the kernel was slow in until session 31) three times
    // as often; it is drawn last, so groups 0-3 see the same cases.
    const int draws = group == 4 ? 3 * per_group : per_group;
    for (int i = 0; i < draws; ++i) {
      const Case c = draw_case(rng, group);
      if (!inside(c)) continue;  // starts beyond the limits: docs/axes-profile-outside.md
      ++total;
      const Outcome o = run_case(c, kSteps);
      if (verbose)
        std::printf("g%d #%d %s %s\n", group, i, describe_case(c, o).c_str(), o.why.c_str());
      if (!std::isfinite(o.t_lp)) continue;  // the grid cannot resolve the move
      ++with_lp;
      // Tier 1: the LP's motion is valid; 1e-5 covers GLPK's feasibility tolerance (seen: the
      // LP 1.8e-6 below a proven rest-to-rest optimum).
      if (o.t_kernel > o.t_lp * (1.0 + 1e-5)) {
        ++slower_lp;
        MESSAGE("kernel slower than the LP reference (group ", group, "): ", describe_case(c, o));
      }
      if (o.t_exact > 0.0) {
        ++with_exact;
        if (o.turns >= 2) ++two_turns;
        if (o.extremes >= 3) ++three_ext;
        if (o.t_kernel > o.t_exact * (1.0 + 1e-9)) {
          ++slower_exact;
          MESSAGE("kernel slower than the exact reference (group ", group,
                  "): ", describe_case(c, o));
        }
      }
    }
  }
  MESSAGE("cases ", total, ", with an LP time ", with_lp, ", refined exactly ", with_exact,
          " (two turns ", two_turns, ", three acceleration extremes ", three_ext,
          "); kernel slower: than T_lp ", slower_lp, ", than T_exact ", slower_exact);
  CHECK(with_lp >= total * 8 / 10);
  CHECK(with_exact >= total / 4);
  // Braking starts that must turn round and keep braking (or ease, then brake harder) through
  // v = 0 were 2.3 %, 3.5 % and 50 % slower in 3 of these cases until session 31's family
  // "dip, then cross" (jerk/dip_cross.cpp; docs/axes-profile.md, "Shape-free reference (LP)").
  CHECK(slower_lp == 0);
  CHECK(slower_exact == 0);
}

TEST_CASE(
    "the LP reference's exact profile for a braking start that turns is valid; the kernel takes "
    "its time (docs/axes-profile.md)") {
  // The example of the class found while building the reference: ease the braking, brake
  // harder, cross v = 0 on the envelope (-A+ = -1501.19 after it), arrive moving back at v1.
  // The reference alone (no seed from the kernel's profile) finds a valid motion; before the
  // family "dip, then cross" (session 31) the kernel took 0.485882 s, 3.7 % slower than the LP's
  // grid motion and 5.0 % slower than T_exact.
  const lp::Problem q{607.11562738920634L,  -3244.5028669987282L, 0.062772232656176208L,
                      -415.35355842183287L, 1178.4256171221843L,  1501.190383994202L,
                      9003.8746960466251L,  82283.864753735179L};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(
              MotionState{0.0, static_cast<double>(q.v0), static_cast<double>(q.a0)},
              PositionTarget{static_cast<double>(q.d), static_cast<double>(q.v1)},
              Dynamics{static_cast<double>(q.vmax), static_cast<double>(q.ap),
                       static_cast<double>(q.am), static_cast<double>(q.j)},
              p, ProfileRule::time_optimal) == Result::ok);
  lp::LpOracle oracle(q, 64);
  const long double t_lp = oracle.min_time(p.duration());
  const lp::Exact ex = lp::refine(q, oracle.u(), t_lp);
  INFO("kernel ", p.duration(), " T_lp ", static_cast<double>(t_lp), " T_exact ",
       static_cast<double>(ex.t), " ", ex.why, " ", lp::describe(ex.arcs));
  REQUIRE(ex.ok);
  CHECK(static_cast<double>(ex.t) == doctest::Approx(0.462775).epsilon(1e-5));
  CHECK(ex.t <= t_lp);
  CHECK(count_turns(q, ex.arcs) == 1);
  // The kernel's profile is the exact reference's (the same arcs), to rounding.
  CHECK(p.duration() == doctest::Approx(static_cast<double>(ex.t)).epsilon(1e-9));
  CHECK(p.duration() <= static_cast<double>(t_lp));
}
