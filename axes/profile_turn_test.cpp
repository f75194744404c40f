// ProfileRule::time_optimal for braking starts that must turn round (issue 11;
// docs/axes-profile.md, "Shape-free reference (LP)", "Found, then built"): the start moves against
// the arrival velocity and brakes, the target is close. The six cases the shape-free LP reference
// found (five from its runs, one found while building it), each with the reference's time: T_exact
// of its exact refinement (tier 2, a valid profile: the kernel may not be slower by more than 1e-9
// relative), or for case 5, where tier 2 did not converge, the LP's own valid motion T_lp.
// Before the family "dip, then cross v = 0" the kernel was 1.3 %..50 % slower in these.

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <string>

#include "axes/profile.hpp"
#include "axes/profile_limits_check.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;

struct TurnCase {
  const char* name;
  double v0, a0, d, v1;
  Dynamics dyn;
  double t_ref;  ///< the reference's time [s] (LP tier 2 T_exact, case 5 T_lp)
};

// docs/axes-profile.md, "Found: the kernel is slower than the reference" (cases 1-5 and the
// one found while building); T_exact printed to 17 digits by profile_lp_reference.hpp's refine.
const std::array<TurnCase, 6> kCases{{
    {"1: brake at -A-, cross, free peak under A+", 30.755055101159236, -2281.4148891720456,
     -0.00062384400654988035, -27.02324398652776,
     Dynamics{30.817911263540864, 51226.788134431597, 2281.4148891720456, 189576.91767045239},
     0.0359833451570408},
    {"2: ease, brake at -A-, down to -A+ at v = 0", 560.63969987548012, -493.10211676106934,
     -0.20479221361386707, -403.61797898318753,
     Dynamics{1756.1440744696347, 381.70998424668522, 951.10661984949877, 6042.5359087992847},
     1.8190197358933706},
    {"3: from -V, ease, brake at A-, down to A+ at v = 0", -1.1547333050735233, 39.94081319027773,
     0.00046208984836659822, 0.81070721630241049,
     Dynamics{1.1547333050735233, 13.258806347527093, 49.13520777706119, 3421.8510707034088},
     0.10351990643249593},
    {"4: ease, brake at -A-, release through v = 0", 23.873402222686558, -1065.3911714351636,
     4.3219491985463126e-05, -15.919189945746771,
     Dynamics{34.941061168100212, 50461.396783538155, 1717.2454649841802, 74561.75322087745},
     0.037410469486385837},
    {"5: brake at -A-, cross, free peak (T_lp)", 3725.3133998096091, -587.39127612960851,
     75.435575945266336, -3413.212795537745,
     Dynamics{7946.1457871543153, 35104.528468307406, 5944.1871276547599, 7647.5928874282527},
     1.908803963009067},
    {"found while building: ease, free peak, down to -A+ at v = 0", 607.11562738920634,
     -3244.5028669987282, 0.062772232656176208, -415.35355842183287,
     Dynamics{1178.4256171221843, 1501.190383994202, 9003.8746960466251, 82283.864753735179},
     0.46277605693801051},
}};

}  // namespace

TEST_CASE(
    "time-optimal: a braking start that must turn round keeps braking through v = 0 (never "
    "slower than the LP reference, within limits, exact end)") {
  for (const TurnCase& c : kCases) {
    INFO(c.name);
    const MotionState start{0.0, c.v0, c.a0};
    Profile p;
    REQUIRE(ncsim::axes::plan_position(start, PositionTarget{c.d, c.v1}, c.dyn, p,
                                       ProfileRule::time_optimal) == Result::ok);
    INFO("kernel ", p.duration(), " s, reference ", c.t_ref, " s");
    CHECK(p.duration() <= c.t_ref * (1.0 + 1e-9));
    const auto end = p.at(p.duration());
    CHECK(end.p == c.d);
    CHECK(end.v == c.v1);
    CHECK(end.a == 0.0);
    const std::string bad = ncsim::test::profile_limit_violation(p, c.dyn, start);
    CHECK_MESSAGE(bad.empty(), bad);
  }
}

TEST_CASE("time-optimal: the braking turns of the reference are met to 1e-9 where it is exact") {
  // Where tier 2 converged its arcs are this family's (ease to a dip, then the crossing of
  // crossing_ramp), so the kernel's time is T_exact both ways, not only not slower.
  for (const TurnCase& c : kCases) {
    if (c.name[0] == '5') continue;  // T_lp: the LP's grid motion, slower than the optimum
    INFO(c.name);
    Profile p;
    REQUIRE(ncsim::axes::plan_position(MotionState{0.0, c.v0, c.a0}, PositionTarget{c.d, c.v1},
                                       c.dyn, p, ProfileRule::time_optimal) == Result::ok);
    CHECK(p.duration() == doctest::Approx(c.t_ref).epsilon(1e-9));
  }
}

TEST_CASE("the manual rule (default) plans the braking turns as before (stop and return)") {
  // 002 2.3: the default does not take the time-optimal family. Its durations, pinned from the
  // kernel before the family existed (session 31), so that a change shows.
  const std::array<double, 6> manual_before{0.069108926884532657, 2.5426008450601105,
                                            0.15372903681116143,  0.062766198169849075,
                                            3.0914484050765267,   0.6964057429814553};
  for (std::size_t i = 0; i < kCases.size(); ++i) {
    const TurnCase& c = kCases[i];
    INFO(c.name);
    Profile manual;
    REQUIRE(ncsim::axes::plan_position(MotionState{0.0, c.v0, c.a0}, PositionTarget{c.d, c.v1},
                                       c.dyn, manual) == Result::ok);
    CHECK(manual.duration() == doctest::Approx(manual_before[i]).epsilon(1e-12));
  }
}
