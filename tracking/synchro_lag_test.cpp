// synchro_lag against the real workpiece (tracking/synchro_lag.hpp): its sign, the master's delay,
// the sensor's offset against T0, and no value before the frame moves.

#include "tracking/synchro_lag.hpp"

#include <doctest/doctest.h>

#include <array>
#include <vector>

#include "conveyor/port.hpp"

namespace {

using namespace ncsim::tracking;
namespace axes = ncsim::axes;
namespace conveyor = ncsim::conveyor;
namespace interp = ncsim::interp;

constexpr double kT = 0.001;
constexpr double kV = 300.0;  // [mm/s]

// A belt at constant velocity whose master runs `late` seconds behind the real belt (dead time
// not compensated); one workpiece whose front edge passed the sensor at real position 0,
// latched by the drive (the real position, method 1).
class LatePort final : public conveyor::Port {
 public:
  LatePort(double late, double sensor_x) : late_(late) {
    edge_.workpiece = 1;
    edge_.sensor_x = sensor_x;
  }
  void step(double t) noexcept override {
    real_ = {kV * t, kV, 0.0};
    master_ = {kV * (t - late_), kV, 0.0};
  }
  const conveyor::BeltState& actual() const noexcept override { return real_; }
  const conveyor::BeltState& measured() const noexcept override { return master_; }
  const conveyor::BeltState& master() const noexcept override { return master_; }
  bool command_velocity(const interp::MoveVelocity&) noexcept override { return false; }
  void arm_probe(const interp::ProbeArm&) noexcept override {}
  std::optional<double> take_latch() noexcept override {
    if (taken_) return std::nullopt;
    taken_ = true;
    return 0.0;
  }
  void set_reduced_filter(bool) noexcept override {}
  const std::optional<conveyor::PortError>& error() const noexcept override { return error_; }
  const conveyor::LatchInfo& last_latch() const noexcept override { return edge_; }

 private:
  double late_;
  bool taken_ = false;
  conveyor::BeltState real_, master_;
  conveyor::LatchInfo edge_;
  std::optional<conveyor::PortError> error_;
};

ncsim::machines::ConveyorSyncChannel channel() {
  ncsim::machines::ConveyorSyncChannel c;
  c.t0_shift = Eigen::Vector3d(-100.0, 0.0, 0.0);
  return c;
}

struct Tracking {
  LatePort port;
  std::vector<SyncAxis> ax;
  ConveyorSync sync;
  std::uint64_t k = 0;
  Tracking(double late, double sensor_x)
      : port(late, sensor_x),
        ax{SyncAxis{"X", 0, axes::Dynamics{1000.0, 5000.0, 5000.0, 50000.0}},
           SyncAxis{"Y", 1, axes::Dynamics{1000.0, 5000.0, 5000.0, 50000.0}},
           SyncAxis{"Z", 2, axes::Dynamics{1000.0, 5000.0, 5000.0, 50000.0}}},
        sync(channel(), ax, kT) {
    sync.attach(&port);
    interp::SyncIn in;
    in.conv_vel = kV;
    REQUIRE_FALSE(sync.sync_in(in));
    cycle();
    REQUIRE(sync.phase() == SyncPhase::latched);
  }
  void cycle() { REQUIRE_FALSE(sync.step(static_cast<double>(++k) * kT)); }
  // Catches up onto the PCS1 point (10, 20, 0) and runs on until tracking.
  void catch_up() {
    const std::array<axes::MotionState, 3> start{};
    const std::array<double, 3> target{-90.0, 20.0, 0.0};  // PCS1 (10, 20, 0), T0 applied
    REQUIRE(sync.start_catch_up(start, target, 0.0) == axes::Result::ok);
    while (sync.phase() == SyncPhase::catching_up)
      cycle();
    REQUIRE(sync.phase() == SyncPhase::tracking);
  }
  // The MCS command of the PCS1 point (10, 20, 0) in this cycle.
  Eigen::Vector3d command() const { return sync.frame().to_mcs({10.0, 20.0, 0.0}, sync.travel()); }
};

}  // namespace

TEST_CASE("synchro_lag: none before the frame moves (waiting, latched, catching up)") {
  Tracking r(0.0, -100.0);
  CHECK_FALSE(tracking_lag(r.sync, r.command(), r.command()));
  ConveyorSync detached(channel(), r.ax, kT);
  CHECK_FALSE(tracking_lag(detached, r.command(), r.command()));
}

TEST_CASE("synchro_lag is 0 when the master is the real belt and the axes follow exactly") {
  Tracking r(0.0, -100.0);
  r.catch_up();
  for (int i = 0; i < 100; ++i) {
    r.cycle();
    const auto lag = tracking_lag(r.sync, r.command(), r.command());
    REQUIRE(lag);
    CHECK(*lag == doctest::Approx(0.0).epsilon(1e-9));
  }
}

TEST_CASE("synchro_lag = -v D when the master runs D late: the machine is behind (delay too low)") {
  const double late = 0.017455;  // the dead time [s]
  Tracking r(late, -100.0);
  r.catch_up();
  r.cycle();
  const auto lag = tracking_lag(r.sync, r.command(), r.command());
  REQUIRE(lag);
  CHECK(*lag == doctest::Approx(-kV * late).epsilon(1e-9));
  // The actual position 0.2 mm ahead of the command in the conveying direction adds +0.2.
  const auto ahead =
      tracking_lag(r.sync, r.command(), r.command() + Eigen::Vector3d(0.2, 0.0, 0.0));
  REQUIRE(ahead);
  CHECK(*ahead == doctest::Approx(-kV * late + 0.2).epsilon(1e-9));
  // A Y or Z error is not along the conveying direction.
  const auto side =
      tracking_lag(r.sync, r.command(), r.command() + Eigen::Vector3d(0.0, 0.5, -0.5));
  CHECK(*side == doctest::Approx(-kV * late).epsilon(1e-9));
}

TEST_CASE("synchro_lag sees a sensor mounted off T0: the real workpiece is ahead by the offset") {
  Tracking r(0.0, -98.0);  // the real sensor 2 mm further in +X than P-CHAN-00368 = -100
  r.catch_up();
  r.cycle();
  const auto lag = tracking_lag(r.sync, r.command(), r.command());
  REQUIRE(lag);
  CHECK(*lag == doctest::Approx(-2.0).epsilon(1e-9));
  CHECK(real_travel(r.sync) == doctest::Approx(r.sync.travel() + 2.0).epsilon(1e-9));
}

TEST_CASE("synchro_lag from the axes: their X/Y/Z slots, and none under #TRAFO ON (joints)") {
  Tracking r(0.017455, -100.0);
  r.catch_up();
  r.cycle();
  const Eigen::Vector3d c = r.command();
  const std::array<double, 3> command{c.x(), c.y(), c.z()};
  const std::array<double, 3> actual{c.x() + 0.2, c.y(), c.z()};
  const auto lag = axes_lag(r.sync, command, actual, false);
  REQUIRE(lag);
  CHECK(*lag == doctest::Approx(*tracking_lag(r.sync, c, c + Eigen::Vector3d(0.2, 0.0, 0.0))));
  // Under #TRAFO ON the axes' positions are joint angles: no synchro_lag (the report took
  // them for X/Y/Z before).
  CHECK_FALSE(axes_lag(r.sync, command, actual, true));
}

TEST_CASE(
    "synchro_lag under #TRAFO ON: the commanded TCP against the forward transform of the "
    "joints' actual positions") {
  Tracking r(0.017455, -100.0);
  r.catch_up();
  r.cycle();
  const Eigen::Vector3d c = r.command();
  // A toy kinematics: joint 0 = X / 2, joint 1 = Y + 5, joint 2 = -Z; forward is its inverse.
  const ncsim::planner::JointMap forward = [](const ncsim::planner::AxisVec& q,
                                              ncsim::planner::AxisVec& x) {
    x = q;
    x[0] = 2.0 * q[0];
    x[1] = q[1] - 5.0;
    x[2] = -q[2];
    return true;
  };
  const std::array<double, 3> tcp{c.x(), c.y(), c.z()};
  ncsim::planner::AxisVec joints{};
  joints[0] = (c.x() + 0.2) / 2.0;  // the actual TCP 0.2 mm ahead in the conveying direction
  joints[1] = c.y() + 5.0 + 0.3;    // and 0.3 mm off in Y (not along it)
  joints[2] = -c.z();
  const auto lag = tcp_lag(r.sync, tcp, joints, forward);
  REQUIRE(lag);
  CHECK(*lag == doctest::Approx(-kV * 0.017455 + 0.2).epsilon(1e-9));
  // Where the transform does not map, and without one, there is no value (never the joints).
  const ncsim::planner::JointMap fails = [](const ncsim::planner::AxisVec&,
                                            ncsim::planner::AxisVec&) { return false; };
  CHECK_FALSE(tcp_lag(r.sync, tcp, joints, fails));
  CHECK_FALSE(tcp_lag(r.sync, tcp, joints, ncsim::planner::JointMap{}));
}
