// The PCS1 frame and the conveyor display variables (seed 004 §2.1 l.227-235, P-CHAN-00363
// l.1267-1275, T0 P-CHAN-00368..00373, display variables §6 l.1508-1610, A17).

#include "tracking/sync_frame.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

namespace {

using ncsim::conveyor::BeltState;
using ncsim::machines::ConveyorSyncChannel;
using ncsim::machines::MoveDirection;
using ncsim::tracking::master_display;
using ncsim::tracking::SyncFrame;
using ncsim::tracking::synchro_lag;

ConveyorSyncChannel channel(MoveDirection dir = MoveDirection::positive_x) {
  ConveyorSyncChannel c;
  c.direction = dir;
  c.t0_shift = Eigen::Vector3d(-100.0, 20.0, 5.0);
  return c;
}

TEST_CASE("PCS1 is PCS0 moved by the belt travel since the latch along PCS0 X") {
  SyncFrame f(channel());
  f.latch(1000.0);
  CHECK(f.travel(1000.0) == 0.0);
  CHECK(f.travel(1250.0) == doctest::Approx(250.0));
  // At the latch PCS1 is PCS0: T0 alone.
  const Eigen::Vector3d p(10.0, 2.0, 3.0);
  CHECK((f.to_mcs(p, 0.0) - Eigen::Vector3d(-90.0, 22.0, 8.0)).norm() < 1e-12);
  // 250 mm later the same PCS1 point is 250 mm further in +X of MCS.
  CHECK((f.to_mcs(p, 250.0) - Eigen::Vector3d(160.0, 22.0, 8.0)).norm() < 1e-12);
  CHECK((f.to_pcs1(f.to_mcs(p, 250.0), 250.0) - p).norm() < 1e-12);
}

TEST_CASE("P-CHAN-00363 = 1: the conveyor moves at negative velocity in +X") {
  SyncFrame f(channel(MoveDirection::negative_x));
  f.latch(500.0);
  CHECK(f.sign() == -1.0);
  CHECK(f.travel(400.0) == doctest::Approx(100.0));  // belt position falling: travel in +X
  CHECK(f.along_x(-300.0) == doctest::Approx(300.0));
}

TEST_CASE("a rotated T0 moves PCS1 along its X axis in MCS") {
  ConveyorSyncChannel c = channel();
  c.t0_rot_abc = Eigen::Vector3d(0.0, 0.0, 90.0);  // C = 90 deg: PCS0 X is MCS Y
  SyncFrame f(c);
  CHECK((f.direction() - Eigen::Vector3d::UnitY()).norm() < 1e-12);
  CHECK((f.offset(10.0) - Eigen::Vector3d(0.0, 10.0, 0.0)).norm() < 1e-12);
}

TEST_CASE("seeded: to_mcs and to_pcs1 are inverse for any T0 and travel") {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-500.0, 500.0), ang(-180.0, 180.0);
  for (int k = 0; k < 200; ++k) {
    ConveyorSyncChannel c;
    c.t0_shift = Eigen::Vector3d(u(rng), u(rng), u(rng));
    c.t0_rot_abc = Eigen::Vector3d(ang(rng), ang(rng), ang(rng));
    SyncFrame f(c);
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    const double s = u(rng);
    CHECK((f.to_pcs1(f.to_mcs(p, s), s) - p).norm() < 1e-9);
    CHECK(std::fabs(f.direction().norm() - 1.0) < 1e-12);
    // Moving the belt by ds moves the MCS point by ds along the conveying direction.
    CHECK(((f.to_mcs(p, s + 1.0) - f.to_mcs(p, s)) - f.direction()).norm() < 1e-9);
  }
}

TEST_CASE("current_pos_master jumps to P-CHAN-00368 at the measurement, then grows (A17)") {
  SyncFrame f(channel());
  const BeltState measured{2000.0, 300.0, 0.0};
  const BeltState master{2000.5, 299.0, 1.0};
  CHECK_FALSE(master_display(f, measured, master).valid);
  CHECK(master_display(f, measured, master).current_pos_master == 0.0);
  f.latch(2000.0);
  auto d = master_display(f, measured, master);
  CHECK(d.valid);
  CHECK(d.current_pos_master == doctest::Approx(-100.0));  // saw: P-CHAN-00368 = -100 mm
  CHECK(d.current_v_master == doctest::Approx(300.0));
  CHECK(d.pos_master_comp == doctest::Approx(-99.5));
  CHECK(d.v_master_comp == doctest::Approx(299.0));
  CHECK(d.a_master_comp == doctest::Approx(1.0));
  d = master_display(f, BeltState{2030.0, 300.0, 0.0}, master);
  CHECK(d.current_pos_master == doctest::Approx(-70.0));
}

TEST_CASE("synchro_lag is positive when the machine is ahead of the workpiece") {
  SyncFrame f(channel());
  f.latch(0.0);
  const Eigen::Vector3d p(10.0, 0.0, 0.0);
  const Eigen::Vector3d on = f.to_mcs(p, 50.0);
  CHECK(synchro_lag(f, on, p, 50.0) == doctest::Approx(0.0));
  CHECK(synchro_lag(f, on + Eigen::Vector3d(0.3, 0.0, 0.0), p, 50.0) == doctest::Approx(0.3));
  CHECK(synchro_lag(f, on, p, 50.3) == doctest::Approx(-0.3));  // the workpiece is ahead
  SyncFrame g(channel(MoveDirection::negative_x));  // the sign is along PCS0 X, not the belt's
  g.latch(0.0);
  CHECK(synchro_lag(g, g.to_mcs(p, 5.0) + Eigen::Vector3d(0.2, 0, 0), p, 5.0) ==
        doctest::Approx(0.2));
}

}  // namespace
