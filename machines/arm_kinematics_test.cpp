#include "machines/arm_kinematics.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace ncsim::machines {
namespace {

// machines/arm6_belt's geometry (docs/machines.md "Kinematic 45"), converted to mm / deg.
std::array<double, 74> arm_params(int code = 0) {
  std::array<double, 74> p{};
  p[3] = 450.0;  // d1
  p[4] = 150.0;  // a1
  p[5] = 600.0;  // a2
  p[6] = 120.0;  // a3
  p[7] = 640.0;  // d4
  p[8] = 100.0;  // d6
  p[9] = 150.0;  // tool
  p[10] = code * 1e-4;
  const std::array<double, 6> lo{-170, -120, -170, -175, -125, -175};
  const std::array<double, 6> hi{170, 150, 170, 175, 125, 175};
  for (std::size_t i = 0; i < 6; ++i) {
    p[11 + 2 * i] = lo[i];
    p[12 + 2 * i] = hi[i];
  }
  return p;
}

// The same arm with every joint free over -180..180 deg (each solution reachable everywhere).
std::array<double, 74> wide_params(int code = 0) {
  std::array<double, 74> p = arm_params(code);
  for (std::size_t i = 0; i < 6; ++i) {
    p[11 + 2 * i] = -180.0;
    p[12 + 2 * i] = 180.0;
  }
  return p;
}

std::unique_ptr<Kinematics> arm(const std::array<double, 74>& p) {
  KinematicsBuild b = make_kinematics(45, p);
  REQUIRE_FALSE(b.error.has_value());
  return std::move(b.kinematics);
}

const ArmKinematics& as_arm(const Kinematics& k) {
  return dynamic_cast<const ArmKinematics&>(k);
}

double angle_diff(double a, double b) {
  return std::abs(std::remainder(a - b, 360.0));
}

// Max difference of positions [mm] and angles [deg] between two poses; orientation compared by
// the rotation, not by its angles (at B = +-90 deg they are not unique).
double pose_diff(const KinAxes& a, const KinAxes& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < 3; ++k)
    d = std::max(d, std::abs(a[k] - b[k]));
  for (std::size_t k = 3; k < 6; ++k)
    d = std::max(d, angle_diff(a[k], b[k]));
  return d;
}

TEST_CASE("kinematic 45 builds from its parameters and maps six axes") {
  const auto kin = arm(arm_params());
  CHECK(kin->id() == 45);
  CHECK(kin->axis_count() == 6);
  // A 3-axis call is refused as a value, never a wrong number.
  CHECK(kin->forward(Eigen::Vector3d::Zero()).error->id == "NC3203");
  CHECK(kin->inverse(Eigen::Vector3d::Zero()).error->id == "NC3203");
}

TEST_CASE("kinematic 45 at zero joints: upper arm up, forearm along +X") {
  const auto kin = arm(arm_params());
  const KinAxesResult p = kin->forward_axes({0, 0, 0, 0, 0, 0});
  REQUIRE(p.ok());
  // Wrist centre (a1 + d4, 0, d1 + a2 + a3), the flange axis along +X.
  CHECK(p.value[0] == doctest::Approx(150.0 + 640.0 + 250.0));
  CHECK(p.value[1] == doctest::Approx(0.0));
  CHECK(p.value[2] == doctest::Approx(450.0 + 600.0 + 120.0));
  // Tool down needs joint 5 at 90 deg: then A = B = C = 0.
  const KinAxesResult down = kin->forward_axes({0, 0, 0, 0, 90, 0});
  REQUIRE(down.ok());
  CHECK(down.value[2] == doctest::Approx(450.0 + 600.0 + 120.0 - 250.0));
  for (std::size_t k = 3; k < 6; ++k)
    CHECK(std::abs(down.value[k]) < 1e-9);
}

TEST_CASE("kinematic 45: inverse(forward(q)) == q on random joints, for each of the 8 solutions") {
  const auto kin = arm(arm_params());
  const ArmKinematics& a = as_arm(*kin);
  std::mt19937_64 rng(45);
  const ArmGeometry& g = a.geometry();
  std::array<int, 8> found{};
  for (int trial = 0; trial < 20000; ++trial) {
    KinAxes q{};
    for (std::size_t i = 0; i < 6; ++i) {
      std::uniform_real_distribution<double> u(g.joint_min_deg[i] + 1.0, g.joint_max_deg[i] - 1.0);
      q[i] = u(rng);
    }
    if (std::abs(std::sin(q[4] * std::numbers::pi / 180.0)) < 0.05) continue;  // near singular
    const KinAxesResult pose = kin->forward_axes(q);
    REQUIRE(pose.ok());
    const ArmSolution s = a.solution_of(q);
    const KinAxesResult back = a.inverse_on(pose.value, s);
    if (!back.ok()) {
      // Only the shoulder singularity (wrist centre on joint 1's axis) may refuse a pose.
      CHECK(back.error->id == "NC3204");
      continue;
    }
    ++found[static_cast<std::size_t>(s.code())];
    for (std::size_t i = 0; i < 6; ++i)
      CHECK(angle_diff(back.value[i], q[i]) < 1e-8);
    const KinAxesResult again = kin->forward_axes(back.value);
    REQUIRE(again.ok());
    CHECK(pose_diff(again.value, pose.value) < 1e-8);
  }
  for (int c = 0; c < 8; ++c)
    CHECK_MESSAGE(found[static_cast<std::size_t>(c)] > 100, c);
}

TEST_CASE("kinematic 45: forward(inverse(p)) == p on random reachable tool-down poses") {
  for (int code = 0; code < 8; ++code) {
    const auto kin = arm(arm_params(code));
    const ArmKinematics& a = as_arm(*kin);
    std::mt19937_64 rng(static_cast<std::uint64_t>(100 + code));
    std::uniform_real_distribution<double> x(-900, 900), z(-300, 900), c(-170, 170), ab(-20, 20);
    int reached = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      const KinAxes p{x(rng), x(rng), z(rng), ab(rng), ab(rng), c(rng)};
      const KinAxesResult q = kin->inverse_axes(p);
      if (!q.ok()) continue;
      ++reached;
      CHECK(a.solution_of(q.value).code() == code);  // the configured solution, always
      const KinAxesResult back = kin->forward_axes(q.value);
      REQUIRE(back.ok());
      CHECK(pose_diff(back.value, p) < 1e-8);
    }
    CHECK_MESSAGE(reached > 50, code);
  }
}

TEST_CASE("kinematic 45: one pose, eight different joint sets") {
  const auto kin = arm(wide_params());
  const ArmKinematics& a = as_arm(*kin);
  // The wrist tilted a little off vertical: every solution is reachable and none is singular.
  const KinAxes pose{600, 200, 300, 10, 20, 30};
  std::vector<KinAxes> all;
  for (int code = 0; code < 8; ++code) {
    const ArmSolution s{(code & 1) != 0, (code & 2) != 0, (code & 4) != 0};
    const KinAxesResult q = a.inverse_on(pose, s);
    REQUIRE_MESSAGE(q.ok(), code, " ", (q.ok() ? "" : q.error->message));
    CHECK(a.solution_of(q.value) == s);
    CHECK(pose_diff(kin->forward_axes(q.value).value, pose) < 1e-8);
    for (const KinAxes& other : all) {
      double d = 0.0;
      for (std::size_t i = 0; i < 6; ++i)
        d = std::max(d, angle_diff(other[i], q.value[i]));
      CHECK(d > 1.0);
    }
    all.push_back(q.value);
  }
}

TEST_CASE("kinematic 45: the solution is kept along a path, the joints move continuously") {
  for (int code : {0, 2, 4}) {
    const auto kin = arm(wide_params(code));
    const ArmKinematics& a = as_arm(*kin);
    // Across the front of the robot, tool down, 1 mm steps.
    const KinAxes from{500, -600, 100, 0, 0, 0}, to{700, 600, 250, 0, 0, 90};
    KinAxes last{};
    const int n = 1500;
    for (int k = 0; k <= n; ++k) {
      KinAxes p{};
      for (std::size_t i = 0; i < 6; ++i)
        p[i] = from[i] + (to[i] - from[i]) * k / n;
      const KinAxesResult q = kin->inverse_axes(p);
      REQUIRE_MESSAGE(q.ok(), code, " ", k, " ", (q.ok() ? "" : q.error->message));
      CHECK(a.solution_of(q.value).code() == code);
      if (k > 0) {
        double step = 0.0;
        for (std::size_t i = 0; i < 6; ++i)
          step = std::max(step, std::abs(q.value[i] - last[i]));
        CHECK(step < 1.0);
      }
      last = q.value;
    }
  }
}

TEST_CASE("kinematic 45: out of reach is NC3201, singular positions NC3204") {
  const auto kin = arm(arm_params());
  const ArmKinematics& a = as_arm(*kin);
  SUBCASE("beyond the stretched arm") {
    const KinAxesResult q = kin->inverse_axes({2000, 0, 400, 0, 0, 0});
    REQUIRE_FALSE(q.ok());
    CHECK(q.error->id == "NC3201");
    CHECK(q.error->message.find("out of reach") != std::string::npos);
  }
  SUBCASE("tool down straight above joint 1: shoulder singularity") {
    const KinAxesResult q = kin->inverse_axes({0.3, 0.2, 400, 0, 0, 0});
    REQUIRE_FALSE(q.ok());
    CHECK(q.error->id == "NC3204");
    CHECK(q.error->message.find("shoulder") != std::string::npos);
  }
  SUBCASE("tool along the forearm: wrist singularity, on either side of 0") {
    for (double q5 : {0.5, -0.9}) {
      const KinAxesResult pose = kin->forward_axes({20, 30, 10, 40, q5, 50});
      REQUIRE(pose.ok());
      const KinAxesResult q = a.inverse_axes(pose.value);
      REQUIRE_FALSE(q.ok());
      CHECK(q.error->id == "NC3204");
      CHECK(q.error->message.find("wrist singular band") != std::string::npos);
    }
    // Just outside the band it maps.
    const KinAxesResult pose = kin->forward_axes({20, 30, 10, 40, 1.5, 50});
    CHECK(a.inverse_axes(pose.value).ok());
  }
}

TEST_CASE("kinematic 45: joints outside their limits are NC3202 both ways") {
  auto p = arm_params();
  p[11] = -90.0;  // joint 1 only -90..90
  p[12] = 90.0;
  const auto kin = arm(p);
  const KinAxesResult behind = kin->inverse_axes({-700, 100, 200, 0, 0, 0});
  REQUIRE_FALSE(behind.ok());
  CHECK(behind.error->id == "NC3202");
  CHECK(behind.error->message.find("joint 1") != std::string::npos);
  const KinAxesResult fwd = kin->forward_axes({0, 0, 0, 0, 130, 0});
  REQUIRE_FALSE(fwd.ok());
  CHECK(fwd.error->id == "NC3202");
  CHECK(fwd.error->message.find("joint 5") != std::string::npos);
}

TEST_CASE("kinematic 45: unusable parameters are NC3203") {
  auto check_bad = [](std::array<double, 74> p, const char* text) {
    const KinematicsBuild b = make_kinematics(45, p);
    REQUIRE(b.error.has_value());
    CHECK(b.error->id == "NC3203");
    CHECK_MESSAGE(b.error->message.find(text) != std::string::npos, b.error->message);
  };
  auto p = arm_params();
  p[5] = 0.0;
  check_bad(p, "upper arm");
  p = arm_params();
  p[10] = 9e-4;
  check_bad(p, "solution code");
  p = arm_params();
  p[10] = 1.5e-4;
  check_bad(p, "solution code");
  p = arm_params();
  p[22] = 200.0;
  check_bad(p, "within -180..180");
  p = arm_params();
  p[13] = 10.0;
  p[14] = -10.0;
  check_bad(p, "must be below");
}

}  // namespace
}  // namespace ncsim::machines
