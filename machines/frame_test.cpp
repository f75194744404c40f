#include "machines/frame.hpp"

#include <doctest/doctest.h>

#include <random>

#include "machines/cs_stack.hpp"

namespace ncsim::machines {
namespace {

constexpr double kTol = 1e-9;  // [mm]

constexpr std::array<RotationSequence, 12> kAllSequences = {
    RotationSequence::XYZ, RotationSequence::XZY, RotationSequence::YXZ, RotationSequence::YZX,
    RotationSequence::ZXY, RotationSequence::ZYX, RotationSequence::XYX, RotationSequence::XZX,
    RotationSequence::YXY, RotationSequence::YZY, RotationSequence::ZXZ, RotationSequence::ZYZ};

Frame random_frame(std::mt19937_64& rng, RotationSequence sequence) {
  std::uniform_real_distribution<double> shift(-1000.0, 1000.0);
  std::uniform_real_distribution<double> angle(-180.0, 180.0);
  return Frame::from_angles(Eigen::Vector3d(shift(rng), shift(rng), shift(rng)),
                            {angle(rng), angle(rng), angle(rng)}, sequence);
}

TEST_CASE("all 12 rotation sequences parse, print and give proper rotations") {
  std::mt19937_64 rng(12);
  for (RotationSequence s : kAllSequences) {
    CAPTURE(to_string(s));
    CHECK(parse_rotation_sequence(to_string(s)) == s);
    const Frame f = random_frame(rng, s);
    CHECK((f.rotation * f.rotation.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    CHECK(f.rotation.determinant() == doctest::Approx(1.0));
  }
  CHECK_FALSE(parse_rotation_sequence("zyx").has_value());
  CHECK_FALSE(parse_rotation_sequence("ZZY").has_value());
}

TEST_CASE("ZYX gives Rz(phi1) * Ry(phi2) * Rx(phi3)") {
  const Eigen::Matrix3d r = rotation_from_angles({90.0, 0.0, 0.0}, RotationSequence::ZYX);
  const Eigen::Vector3d x = r * Eigen::Vector3d::UnitX();
  CHECK((x - Eigen::Vector3d::UnitY()).norm() < kTol);  // 90 deg about Z turns X into Y
  const Eigen::Matrix3d r2 = rotation_from_angles({0.0, 0.0, 90.0}, RotationSequence::ZYX);
  CHECK((r2 * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm() < kTol);
}

TEST_CASE("frame round trips hold to 1e-9 mm over seeded random frames and points") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> coord(-2000.0, 2000.0);
  for (RotationSequence s : kAllSequences) {
    for (int n = 0; n < 200; ++n) {
      const Frame a = random_frame(rng, s);
      const Frame b = random_frame(rng, s);
      const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
      CHECK((a.inverse().apply(a.apply(p)) - p).norm() < kTol);
      CHECK(((a * b).apply(p) - a.apply(b.apply(p))).norm() < kTol);
      CHECK(((a * b).inverse().apply((a * b).apply(p)) - p).norm() < kTol);
    }
  }
}

TEST_CASE("T0 rotates A about X, B about Y, C about Z and then shifts") {
  const Frame t0 = t0_frame(Eigen::Vector3d(-100.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 90.0));
  CHECK((t0.apply(Eigen::Vector3d(10.0, 0.0, 0.0)) - Eigen::Vector3d(-100.0, 10.0, 0.0)).norm() <
        kTol);
  const Frame ta = t0_frame(Eigen::Vector3d::Zero(), Eigen::Vector3d(90.0, 0.0, 0.0));
  CHECK((ta.apply(Eigen::Vector3d::UnitY()) - Eigen::Vector3d::UnitZ()).norm() < kTol);
}

CsValues shift(double x, double y, double z, double phi3 = 0.0) {
  CsValues v;
  v.v_mm = Eigen::Vector3d(x, y, z);
  v.phi_deg = {0.0, 0.0, phi3};
  return v;
}

TEST_CASE("#CS ON with values defines and activates; OFF returns to the identity") {
  CsStack cs;
  REQUIRE_FALSE(cs.on(1, shift(10, 20, 30)));
  CHECK((cs.active_frame().apply(Eigen::Vector3d::Zero()) - Eigen::Vector3d(10, 20, 30)).norm() <
        kTol);
  REQUIRE_FALSE(cs.off());
  CHECK(cs.active_count() == 0);
  CHECK(cs.is_defined(1));  // a numbered system stays stored after OFF
  CHECK((cs.active_frame().apply(Eigen::Vector3d(1, 2, 3)) - Eigen::Vector3d(1, 2, 3)).norm() <
        kTol);
}

TEST_CASE("activating a second system chains it inside the first") {
  CsStack cs;
  REQUIRE_FALSE(cs.def(1, shift(100, 0, 0, 90.0)));  // phi3 about X in ZYX
  REQUIRE_FALSE(cs.def(2, shift(0, 10, 0)));
  REQUIRE_FALSE(cs.on(1, std::nullopt));
  REQUIRE_FALSE(cs.on(2, std::nullopt));
  CHECK(cs.active_count() == 2);
  // p in system 2 -> system 1: +10 in Y; system 1 -> parent: rotate 90 deg about X, +100 in X.
  const Eigen::Vector3d p = cs.active_frame().apply(Eigen::Vector3d::Zero());
  CHECK((p - Eigen::Vector3d(100, 0, 10)).norm() < kTol);
  REQUIRE_FALSE(cs.off());  // deactivates the last activated (2)
  CHECK((cs.active_frame().apply(Eigen::Vector3d::Zero()) - Eigen::Vector3d(100, 0, 0)).norm() <
        kTol);
}

TEST_CASE("#CS ON without an id activates the last defined system") {
  CsStack cs;
  REQUIRE_FALSE(cs.def(3, shift(1, 0, 0)));
  REQUIRE_FALSE(cs.def(4, shift(0, 2, 0)));
  REQUIRE_FALSE(cs.on(std::nullopt, std::nullopt));
  CHECK((cs.active_frame().apply(Eigen::Vector3d::Zero()) - Eigen::Vector3d(0, 2, 0)).norm() <
        kTol);
}

TEST_CASE("a system defined without an id is lost after OFF") {
  CsStack cs;
  REQUIRE_FALSE(cs.on(std::nullopt, shift(5, 5, 5)));
  CHECK(cs.stored_count() == 1);
  REQUIRE_FALSE(cs.off());
  CHECK(cs.stored_count() == 0);
  const auto e = cs.on(std::nullopt, std::nullopt);
  REQUIRE(e.has_value());
  CHECK(e->id == "NC3103");
}

TEST_CASE("#CS errors are values: 6th stored system, undefined id, OFF with none, bad id") {
  CsStack cs;
  for (int id = 1; id <= 5; ++id)
    REQUIRE_FALSE(cs.def(id, shift(id, 0, 0)));
  const auto full = cs.def(6, shift(0, 0, 0));
  REQUIRE(full.has_value());
  CHECK(full->id == "NC3102");
  CHECK_FALSE(cs.def(5, shift(9, 9, 9)));  // redefining a stored id is fine
  const auto undefined = cs.on(7, std::nullopt);
  REQUIRE(undefined.has_value());
  CHECK(undefined->id == "NC3103");
  CHECK(undefined->message.find('7') != std::string::npos);
  const auto none = cs.off();
  REQUIRE(none.has_value());
  CHECK(none->id == "NC3105");
  const auto bad = cs.def(0, shift(0, 0, 0));
  REQUIRE(bad.has_value());
  CHECK(bad->id == "NC3101");
}

TEST_CASE("at most 5 activations are chained and OFF ALL clears them") {
  CsStack cs;
  REQUIRE_FALSE(cs.def(1, shift(1, 0, 0)));
  for (int n = 0; n < 5; ++n)
    REQUIRE_FALSE(cs.on(1, std::nullopt));
  CHECK((cs.active_frame().apply(Eigen::Vector3d::Zero()) - Eigen::Vector3d(5, 0, 0)).norm() <
        kTol);
  const auto deep = cs.on(1, std::nullopt);
  REQUIRE(deep.has_value());
  CHECK(deep->id == "NC3104");
  cs.off_all();
  CHECK(cs.active_count() == 0);
  CHECK(cs.is_defined(1));
}

TEST_CASE("#CS stack round trip over seeded random chains holds to 1e-9 mm") {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-500.0, 500.0);
  std::uniform_real_distribution<double> ang(-180.0, 180.0);
  for (int n = 0; n < 100; ++n) {
    CsStack cs(kAllSequences[static_cast<std::size_t>(n) % 12]);
    for (int id = 1; id <= 3; ++id) {
      CsValues v;
      v.v_mm = Eigen::Vector3d(u(rng), u(rng), u(rng));
      v.phi_deg = {ang(rng), ang(rng), ang(rng)};
      REQUIRE_FALSE(cs.on(id, v));
    }
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    const Frame f = cs.active_frame();
    CHECK((f.inverse().apply(f.apply(p)) - p).norm() < kTol);
  }
}

}  // namespace
}  // namespace ncsim::machines
