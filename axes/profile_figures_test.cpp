// The parameter sets of seed 002_* 2.1 (figures "Dynamik 1.1" to "Dynamik 3.3"): profile
// durations and phase times, as listed in docs/axes-profile.md.

#include <doctest/doctest.h>

#include <vector>

#include "axes/profile.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::Result;

Profile plan(double acc, double dec, double jerk, double v, double distance) {
  Profile profile;
  const Result r = ncsim::axes::plan_position(MotionState{}, PositionTarget{distance, 0.0},
                                              Dynamics{v, acc, dec, jerk}, profile);
  REQUIRE(r == Result::ok);
  return profile;
}

std::vector<double> phase_times(const Profile& profile) {
  std::vector<double> out;
  for (const auto& phase : profile.phases())
    out.push_back(phase.duration);
  return out;
}

void check_times(const Profile& profile, const std::vector<double>& expected) {
  const std::vector<double> got = phase_times(profile);
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    CAPTURE(i);
    CHECK(got[i] == doctest::Approx(expected[i]).epsilon(1e-9));
  }
}

void check_end(const Profile& profile, double distance) {
  const auto end = profile.at(profile.duration());
  CHECK(end.p == distance);
  CHECK(end.v == 0.0);
  CHECK(end.a == 0.0);
  const auto& last = profile.phases().back();
  const auto before = profile.at(last.t_start + last.duration * (1.0 - 1e-12));
  CHECK(before.p == doctest::Approx(distance).epsilon(1e-9));
}

}  // namespace

TEST_CASE("Dynamik 1.1: A+ = A- = 5000, J = 50000, V = 2000 over 1000 mm takes 1.0 s") {
  const Profile p = plan(5000, 5000, 50000, 2000, 1000);
  CHECK(p.duration() == doctest::Approx(1.0).epsilon(1e-12));
  check_times(p, {0.1, 0.3, 0.1, 0.1, 0.3, 0.1});  // V reached exactly, no cruise
  CHECK(p.v_level() == doctest::Approx(2000.0));
  check_end(p, 1000);
}

TEST_CASE("Dynamik 1.2: A- = 10000 brakes in 0.4 s and leaves a 0.05 s cruise") {
  const Profile p = plan(5000, 10000, 50000, 2000, 1000);
  CHECK(p.duration() == doctest::Approx(0.95).epsilon(1e-12));
  check_times(p, {0.1, 0.3, 0.1, 0.05, 0.2, 0.2});
  check_end(p, 1000);
}

TEST_CASE("Dynamik 1.3: A = 15000 is not reached (J below the critical jerk)") {
  const Profile p = plan(15000, 15000, 50000, 2000, 1000);
  CHECK(ncsim::axes::critical_jerk(Dynamics{2000, 15000, 15000, 50000}) ==
        doctest::Approx(112500.0));
  CHECK(p.duration() == doctest::Approx(0.9).epsilon(1e-12));
  check_times(p, {0.2, 0.2, 0.1, 0.2, 0.2});
  double a_peak = 0.0;
  for (double t = 0.0; t < p.duration(); t += 1e-3)
    a_peak = std::max(a_peak, p.at(t).a);
  CHECK(a_peak == doctest::Approx(10000.0).epsilon(1e-6));
  check_end(p, 1000);
}

TEST_CASE("Dynamik 2.1: J = 20000 makes V = 2000 unreachable: level 1696.772 mm/s") {
  const Profile p = plan(5000, 5000, 20000, 2000, 1000);
  CHECK(p.v_level() == doctest::Approx(1696.77195263).epsilon(1e-9));
  CHECK(p.duration() == doctest::Approx(1.17870878105).epsilon(1e-9));
  check_times(p, {0.25, 0.0893543905252, 0.25, 0.25, 0.0893543905252, 0.25});
  check_end(p, 1000);
}

TEST_CASE("Dynamik 2.2: J = 50000 equals Dynamik 1.1") {
  const Profile p = plan(5000, 5000, 50000, 2000, 1000);
  CHECK(p.duration() == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("Dynamik 2.3: J = 100000 shortens the jerk phases to 0.05 s and adds a cruise") {
  const Profile p = plan(5000, 5000, 100000, 2000, 1000);
  CHECK(p.duration() == doctest::Approx(0.95).epsilon(1e-12));
  check_times(p, {0.05, 0.35, 0.05, 0.05, 0.05, 0.35, 0.05});
  check_end(p, 1000);
}

TEST_CASE("Dynamik 3.1: V = 1500 over 800 mm cruises for 0.1333 s") {
  const Profile p = plan(5000, 5000, 50000, 1500, 800);
  CHECK(p.duration() == doctest::Approx(0.4 + 0.4 + 200.0 / 1500.0).epsilon(1e-12));
  check_times(p, {0.1, 0.2, 0.1, 200.0 / 1500.0, 0.1, 0.2, 0.1});
  check_end(p, 800);
}

TEST_CASE("Dynamik 3.2: V = 1750 over 800 mm cruises for 0.00714 s") {
  const Profile p = plan(5000, 5000, 50000, 1750, 800);
  CHECK(p.duration() == doctest::Approx(0.9 + 12.5 / 1750.0).epsilon(1e-12));
  check_times(p, {0.1, 0.25, 0.1, 12.5 / 1750.0, 0.1, 0.25, 0.1});
  check_end(p, 800);
}

TEST_CASE("Dynamik 3.3: V = 2000 over 800 mm is reduced to 1765.56 mm/s and is faster than 3.2") {
  const Profile p = plan(5000, 5000, 50000, 2000, 800);
  CHECK(p.v_level() == doctest::Approx(1765.56443707).epsilon(1e-9));
  CHECK(p.duration() == doctest::Approx(0.906225774830).epsilon(1e-9));
  check_times(p, {0.1, 0.253112887415, 0.1, 0.1, 0.253112887415, 0.1});
  CHECK(p.duration() < plan(5000, 5000, 50000, 1750, 800).duration());
  check_end(p, 800);
}

TEST_CASE("an unreachable V with A+ != A- uses the symmetric min(A+, A-) level and cruises") {
  // 002_* 2.1: the reachable level under min(A+, A-) = 5000 over 800 mm is 1765.56 mm/s; with
  // the real A- = 10000 (not reached: J < 10000^2 / 1765.56) the braking needs less distance,
  // so a cruise phase appears: 3 acceleration phases, cruise, 2 braking phases.
  const Profile p = plan(5000, 10000, 50000, 2000, 800);
  CHECK(p.v_level() == doctest::Approx(1765.56443707).epsilon(1e-9));
  const auto times = phase_times(p);
  REQUIRE(times.size() == 6);
  CHECK(times[3] > 0.0);
  check_end(p, 800);
}

TEST_CASE("a negative move mirrors the positive one") {
  const Profile fwd = plan(5000, 10000, 50000, 2000, 1000);
  const Profile back = plan(5000, 10000, 50000, 2000, -1000);
  CHECK(back.duration() == doctest::Approx(fwd.duration()).epsilon(1e-12));
  for (double t = 0.0; t < fwd.duration(); t += 0.01) {
    CHECK(back.at(t).p == doctest::Approx(-fwd.at(t).p).epsilon(1e-9));
    CHECK(back.at(t).a == doctest::Approx(-fwd.at(t).a).epsilon(1e-9));
  }
}

TEST_CASE("the jerk is rescaled when a jerk phase would be shorter than one cycle") {
  const Dynamics d{2000, 5000, 10000, 1e9};
  const Dynamics r = ncsim::axes::rescale_jerk(d, 1e-3);
  CHECK(r.j_max == doctest::Approx(5000.0 / 1e-3));
  const Dynamics kept = ncsim::axes::rescale_jerk(Dynamics{2000, 5000, 5000, 50000}, 1e-3);
  CHECK(kept.j_max == 50000.0);
}

TEST_CASE("invalid dynamics are reported as a Result, not thrown") {
  Profile p;
  CHECK(ncsim::axes::plan_position(MotionState{}, PositionTarget{10.0, 0.0},
                                   Dynamics{0.0, 1.0, 1.0, 1.0}, p) == Result::error_invalid_input);
  CHECK(ncsim::axes::plan_position(MotionState{}, PositionTarget{10.0, 0.0},
                                   Dynamics{1.0, 1.0, 1.0, 1.0}, p) == Result::ok);
  CHECK(ncsim::axes::plan_position(MotionState{}, PositionTarget{10.0, 5.0},
                                   Dynamics{1.0, 1.0, 1.0, 1.0}, p) == Result::error_invalid_input);
  CHECK(ncsim::axes::diagnostic_id(Result::error_invalid_input) == "NC5001");
}
