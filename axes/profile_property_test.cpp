// Seeded property tests of the position planner: limits hold, the target is reached exactly,
// no NaN, the closed form agrees with a numerical integration of the jerk, and rest-to-rest
// moves with A+ = A- take the minimum time (independent bisection solver below).
// Case count: NCSIM_PROFILE_CASES (default 100000).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

#include "axes/profile.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::Result;

long case_count() {
  const char* env = std::getenv("NCSIM_PROFILE_CASES");
  if (env == nullptr) return 100000;
  const long n = std::strtol(env, nullptr, 10);
  return n > 0 ? n : 100000;
}

struct Case {
  MotionState start;
  PositionTarget target;
  Dynamics dyn;
};

std::string describe(const Case& c) {
  std::ostringstream out;
  out.precision(17);
  out << "start p=" << c.start.p << " v=" << c.start.v << " a=" << c.start.a
      << " target p=" << c.target.p << " v=" << c.target.v << " V=" << c.dyn.v_max
      << " A+=" << c.dyn.acc_max << " A-=" << c.dyn.dec_max << " J=" << c.dyn.jerk_max;
  return out.str();
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

// A start state inside the limits from which releasing the acceleration neither exceeds V nor
// reverses the motion (the planner's contract for "limits hold"; other starts: own tests).
Case random_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Case c;
  c.dyn.v_max = log_uniform(rng, 1.0, 5000.0);
  c.dyn.acc_max = log_uniform(rng, 10.0, 50000.0);
  c.dyn.dec_max = unit(rng) < 0.3 ? c.dyn.acc_max : log_uniform(rng, 10.0, 50000.0);
  c.dyn.jerk_max = log_uniform(rng, 100.0, 1e6);
  const double distance = log_uniform(rng, 1e-3, 1e4) * (unit(rng) < 0.5 ? -1.0 : 1.0);
  c.start.p = (unit(rng) - 0.5) * 2000.0;
  c.target.p = c.start.p + distance;
  if (unit(rng) < 0.6) {
    const double v = (2.0 * unit(rng) - 1.0) * c.dyn.v_max;
    const double s = v >= 0.0 ? 1.0 : -1.0;
    // path acceleration in [-A-, A+] relative to the direction of motion
    double a = (unit(rng) * (c.dyn.acc_max + c.dyn.dec_max) - c.dyn.dec_max);
    const double reserve_up =
        (1.0 - 1e-6) * std::sqrt(2.0 * c.dyn.jerk_max * (c.dyn.v_max - std::abs(v)));
    const double reserve_down = (1.0 - 1e-6) * std::sqrt(2.0 * c.dyn.jerk_max * std::abs(v));
    a = std::clamp(a, -reserve_down, reserve_up);
    c.start.v = v;
    c.start.a = s * a;
  }
  if (unit(rng) < 0.25) c.target.v = (2.0 * unit(rng) - 1.0) * c.dyn.v_max;
  return c;
}

// Checks phase by phase; returns an empty string when everything holds.
std::string check_limits(const Case& c, const Profile& p) {
  const double tol = 1e-9;
  const double v_lim = c.dyn.v_max * (1.0 + tol);
  for (const auto& ph : p.phases()) {
    if (!(std::isfinite(ph.p) && std::isfinite(ph.v) && std::isfinite(ph.a) &&
          std::isfinite(ph.j) && std::isfinite(ph.duration) && ph.duration > 0.0)) {
      return "non-finite or empty phase";
    }
    if (ph.j != 0.0 && std::abs(std::abs(ph.j) - c.dyn.jerk_max) > tol * c.dyn.jerk_max) {
      return "jerk not 0 or J";
    }
    // acceleration is linear in a phase: check both ends; velocity extremum where a = 0
    const auto s0 = p.at(ph.t_start);
    const auto s1 = p.at(ph.t_start + ph.duration * (1.0 - 1e-15));
    for (const auto& s : {s0, s1}) {
      if (std::abs(s.v) > v_lim) return "velocity above V";
      const double dir = s.v != 0.0 ? (s.v > 0.0 ? 1.0 : -1.0) : (s.a >= 0.0 ? 1.0 : -1.0);
      const double a_path = dir * s.a;
      if (a_path > c.dyn.acc_max * (1.0 + tol) + tol ||
          a_path < -c.dyn.dec_max * (1.0 + tol) - tol) {
        return "acceleration beyond A+/A-";
      }
    }
    if (ph.j != 0.0) {
      const double t_zero = -ph.a / ph.j;
      if (t_zero > 0.0 && t_zero < ph.duration && std::abs(p.at(ph.t_start + t_zero).v) > v_lim) {
        return "velocity above V inside a phase";
      }
    }
  }
  return {};
}

std::string check_target(const Case& c, const Profile& p) {
  const auto end = p.at(p.duration());
  if (end.p != c.target.p || end.v != c.target.v || end.a != 0.0) return "target not exact";
  if (!std::isfinite(p.duration()) || p.duration() < 0.0) return "bad duration";
  if (p.phases().empty()) return {};
  const auto& last = p.phases().back();
  const double dt = last.duration;
  const double p_int = last.p + dt * (last.v + dt * (last.a / 2.0 + dt * last.j / 6.0));
  const double v_int = last.v + dt * (last.a + dt * last.j / 2.0);
  // relative to the length of the way actually travelled (stop-and-return moves go far out)
  double scale = std::abs(c.target.p - c.start.p) + std::abs(c.target.p) * 1e-7 + 1e-9;
  for (const auto& ph : p.phases())
    scale = std::max(scale, 2.0 * std::abs(ph.p - c.start.p));
  if (std::abs(p_int - c.target.p) > 1e-9 * scale) return "position chain misses target";
  if (std::abs(v_int - c.target.v) > 1e-9 * (c.dyn.v_max + 1.0)) return "velocity chain misses";
  return {};
}

// Numerical integration of the jerk read from at(): the state is carried from the start only
// by integrating the jerk over 16 substeps per phase (steps end on the phase boundaries, where
// the jerk switches), and compared with at() after every substep.
std::string check_integration(const Profile& p) {
  const auto s = p.at(0.0);
  double pos = s.p;
  double vel = s.v;
  double acc = s.a;
  double worst = 0.0;
  double scale = 1e-9;
  for (const auto& ph : p.phases()) {
    const double h = ph.duration / 16.0;
    for (int k = 0; k < 16; ++k) {
      const double t0 = ph.t_start + k * h;
      const double j = p.at(t0 + 0.5 * h).j;
      pos += h * (vel + h * (acc / 2.0 + h * j / 6.0));
      vel += h * (acc + h * j / 2.0);
      acc += h * j;
      const auto ref = p.at(std::min(t0 + h, p.duration() * (1.0 - 1e-16)));
      scale = std::max({scale, std::abs(ref.p - s.p), std::abs(ref.v) * p.duration()});
      worst = std::max(worst, std::abs(pos - ref.p));
    }
  }
  if (worst > 1e-8 * scale) return "closed form differs from integrated jerk";
  return {};
}

// Independent minimum-time solver for rest-to-rest, A+ = A- = A: bisection on the peak
// velocity, ramps from the phase durations, distance from the phase polynomials.
double reference_min_time(double dist, double v_max, double acc, double jerk) {
  const auto ramp = [&](double vp, double& time) {
    double t1 = std::sqrt(vp / jerk);
    double t2 = 0.0;
    if (t1 * jerk > acc) {
      t1 = acc / jerk;
      t2 = (vp - acc * t1) / acc;
    }
    time = 2.0 * t1 + t2;
    const double a1 = jerk * t1;
    const double v1 = jerk * t1 * t1 / 2.0;
    const double p1 = jerk * t1 * t1 * t1 / 6.0;
    const double v2 = v1 + a1 * t2;
    const double p2 = p1 + v1 * t2 + a1 * t2 * t2 / 2.0;
    return p2 + v2 * t1 + a1 * t1 * t1 / 2.0 - jerk * t1 * t1 * t1 / 6.0;
  };
  double lo = 0.0;
  double hi = v_max;
  double t_ramp = 0.0;
  if (2.0 * ramp(v_max, t_ramp) > dist) {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (2.0 * ramp(mid, t_ramp) <= dist ? lo : hi) = mid;
    }
  } else {
    lo = v_max;
  }
  const double d = 2.0 * ramp(lo, t_ramp);
  return 2.0 * t_ramp + (dist - d) / lo;
}

}  // namespace

TEST_CASE("random moves: limits hold, targets are exact, closed form matches integration") {
  std::mt19937_64 rng(20240611);
  const long n = case_count();
  long failures = 0;
  long optimal_checked = 0;
  std::string first;
  for (long i = 0; i < n; ++i) {
    Case c = random_case(rng);
    const bool rest_symmetric = i % 4 == 0;
    if (rest_symmetric) {
      c.start.v = c.start.a = c.target.v = 0.0;
      c.dyn.dec_max = c.dyn.acc_max;
    }
    Profile p;
    std::string why;
    if (ncsim::axes::plan_position(c.start, c.target, c.dyn, p) != Result::ok) {
      why = "planning failed";
    }
    if (why.empty()) why = check_target(c, p);
    if (why.empty()) why = check_limits(c, p);
    if (why.empty() && i % 5 == 0) why = check_integration(p);
    if (why.empty() && rest_symmetric) {
      ++optimal_checked;
      const double t_ref = reference_min_time(std::abs(c.target.p - c.start.p), c.dyn.v_max,
                                              c.dyn.acc_max, c.dyn.jerk_max);
      if (std::abs(p.duration() - t_ref) > 1e-8 * t_ref) why = "rest-to-rest not minimum time";
    }
    if (!why.empty() && failures++ < 3) first += why + ": " + describe(c) + "\n";
  }
  INFO(first);
  CHECK(failures == 0);
  CHECK(optimal_checked >= n / 4);
}

TEST_CASE("rest-to-rest moves stay between start and target") {
  std::mt19937_64 rng(7);
  long failures = 0;
  for (int i = 0; i < 2000; ++i) {
    Case c = random_case(rng);
    c.start.v = c.start.a = c.target.v = 0.0;
    Profile p;
    REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, p) == Result::ok);
    const double lo = std::min(c.start.p, c.target.p);
    const double hi = std::max(c.start.p, c.target.p);
    const double tol = 1e-9 * (hi - lo) + 1e-12 * std::abs(hi);
    for (int k = 0; k <= 200; ++k) {
      const double x = p.at(p.duration() * k / 200.0).p;
      if (x < lo - tol || x > hi + tol) ++failures;
    }
  }
  CHECK(failures == 0);
}
