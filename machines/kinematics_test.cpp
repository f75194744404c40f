#include "machines/kinematics.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "machines/delta_kinematics.hpp"

namespace ncsim::machines {
namespace {

// The TF5264 pick & place parameters (seed 004 §4.9.1), converted to mm / deg.
std::array<double, 74> picker_params() {
  std::array<double, 74> p{};
  p[3] = 48.0;
  p[4] = 200.0;
  p[5] = 1050.0;
  p[6] = 465.544;
  p[10] = -180.0;
  p[11] = 180.0;
  return p;
}

std::unique_ptr<Kinematics> picker() {
  KinematicsBuild b = make_kinematics(37, picker_params());
  REQUIRE_FALSE(b.error.has_value());
  return std::move(b.kinematics);
}

TEST_CASE("kinematic 0 is the Cartesian identity") {
  KinematicsBuild b = make_kinematics(0, {});
  REQUIRE(b.kinematics);
  const Eigen::Vector3d p(1.5, -2.0, 300.0);
  CHECK(b.kinematics->forward(p).value == p);
  CHECK(b.kinematics->inverse(p).value == p);
  CHECK(b.kinematics->id() == 0);
}

TEST_CASE("an unknown kinematic id is error 292005") {
  const KinematicsBuild b = make_kinematics(12, {});
  REQUIRE(b.error.has_value());
  CHECK(b.error->id == "292005");
  CHECK(b.error->message.find("12") != std::string::npos);
  CHECK(b.kinematics == nullptr);
}

TEST_CASE("delta with a zero-length arm is rejected with NC3203") {
  auto p = picker_params();
  p[6] = 0.0;
  const KinematicsBuild b = make_kinematics(37, p);
  REQUIRE(b.error.has_value());
  CHECK(b.error->id == "NC3203");
}

TEST_CASE("delta: the seed's pick & place points are reachable and round-trip") {
  const auto kin = picker();
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(-100, 0, -700), Eigen::Vector3d(-50, 0, -800),
        Eigen::Vector3d(300, 500, -750), Eigen::Vector3d(300, 500, -800)}) {
    CAPTURE(p.transpose());
    const KinResult q = kin->inverse(p);
    REQUIRE(q.ok());
    const KinResult back = kin->forward(q.value);
    REQUIRE(back.ok());
    CHECK((back.value - p).norm() < 1e-9);
  }
}

TEST_CASE("delta: arms at equal angles put the TCP on the Z axis") {
  const auto kin = picker();
  const KinResult p = kin->forward(Eigen::Vector3d(30.0, 30.0, 30.0));
  REQUIRE(p.ok());
  CHECK(std::abs(p.value.x()) < 1e-9);
  CHECK(std::abs(p.value.y()) < 1e-9);
  CHECK(p.value.z() < -500.0);
}

// Elbow outside the shoulder-wrist line: the branch inverse() returns (delta header).
bool on_outer_branch(const DeltaGeometry& g, const Eigen::Vector3d& joints_deg,
                     const Eigen::Vector3d& tcp) {
  const Eigen::Vector3d p = tcp - g.base_mm + g.tcp_offset * Eigen::Vector3d::UnitZ();
  for (int arm = 0; arm < 3; ++arm) {
    const double az = 2.0 * std::numbers::pi / 3.0 * arm;
    const Eigen::Vector3d u(std::cos(az), std::sin(az), 0.0);
    const double th = (joints_deg[arm] - g.zero_offset_deg[static_cast<std::size_t>(arm)]) *
                      std::numbers::pi / 180.0;
    const double wx = p.dot(u) + g.r_effector - g.r_base;
    const double wz = p.z();
    const double cross = wx * (-g.l_upper * std::sin(th)) - wz * (g.l_upper * std::cos(th));
    if (cross <= 1e-6) return false;
  }
  return true;
}

TEST_CASE("delta: random joint angles -> forward -> inverse give the same angles (1e-9)") {
  const auto kin = picker();
  const auto& g = dynamic_cast<const DeltaKinematics&>(*kin).geometry();
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> angle(-40.0, 85.0);
  int checked = 0;
  for (int n = 0; n < 2000; ++n) {
    const Eigen::Vector3d q(angle(rng), angle(rng), angle(rng));
    const KinResult p = kin->forward(q);
    if (!p.ok() || !on_outer_branch(g, q, p.value)) continue;
    const KinResult back = kin->inverse(p.value);
    REQUIRE(back.ok());
    CHECK((back.value - q).norm() < 1e-9);
    ++checked;
  }
  CHECK(checked > 1000);
}

TEST_CASE("delta: random reachable points -> inverse -> forward give the same point (1e-9)") {
  auto params = picker_params();
  params[0] = 10.0;  // base offset and TCP offset take part too
  params[2] = 50.0;
  params[7] = 2.0;
  params[12] = 80.0;
  KinematicsBuild b = make_kinematics(37, params);
  REQUIRE(b.kinematics);
  std::mt19937_64 rng(4711);
  std::uniform_real_distribution<double> xy(-400.0, 400.0);
  std::uniform_real_distribution<double> z(-1300.0, -500.0);
  int checked = 0;
  for (int n = 0; n < 3000; ++n) {
    const Eigen::Vector3d p(xy(rng), xy(rng), z(rng));
    const KinResult q = b.kinematics->inverse(p);
    if (!q.ok()) continue;
    const KinResult back = b.kinematics->forward(q.value);
    REQUIRE(back.ok());
    CHECK((back.value - p).norm() < 1e-9);
    ++checked;
  }
  CHECK(checked > 1000);
}

TEST_CASE("delta: a point beyond the arms is a workspace error naming the point") {
  const auto kin = picker();
  const KinResult q = kin->inverse(Eigen::Vector3d(0.0, 0.0, -3000.0));
  REQUIRE_FALSE(q.ok());
  CHECK(q.error->id == "NC3201");
  CHECK(q.error->message.find("-3000") != std::string::npos);
}

TEST_CASE("delta: joint limits are enforced in both directions") {
  auto params = picker_params();
  params[10] = -10.0;
  params[11] = 60.0;
  KinematicsBuild b = make_kinematics(37, params);
  REQUIRE(b.kinematics);
  const KinResult f = b.kinematics->forward(Eigen::Vector3d(0.0, 70.0, 0.0));
  REQUIRE_FALSE(f.ok());
  CHECK(f.error->id == "NC3202");
  CHECK(f.error->message.find("drive 2") != std::string::npos);
  // A point right below the base, high up, needs the drives far above the horizontal.
  const KinResult i = b.kinematics->inverse(Eigen::Vector3d(0.0, 0.0, -620.0));
  REQUIRE_FALSE(i.ok());
  CHECK(i.error->id == "NC3202");
}

}  // namespace
}  // namespace ncsim::machines
