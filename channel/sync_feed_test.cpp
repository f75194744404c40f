// What runs around the synchronisation (issue 14, sync-feed; docs/conveyor.md S-1..S-6):
// #SYNC OUT FEED_CONT, INDP motions after #SYNC OUT leaving from the moving state, the
// on-the-fly change (INDP_SYN ... INTERRUPTIBLE taken over by the next catch-up), the PCS1
// velocity split in the planner.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;

struct Run {
  ipo::Status status = ipo::Status::finished;
  std::vector<std::uint32_t> line;
  std::vector<tracking::SyncPhase> phase;
  std::vector<std::array<double, 3>> x;  // command X, Y, Z (MCS)
  std::vector<double> offset_x;          // PCS1 offset on X
  std::vector<bool> x_indp;              // X driven by the INDP layer in that cycle
  std::optional<channel::RunTimeError> error;
  std::string source_error;
};

// laser_portal: X v_max 1000 mm/s, A 10000 mm/s^2; the belt at 300 mm/s. `override_percent`:
// a path override from t = 0 on a REDUCED_ABOVE_100 channel (a scenario event); null: none.
Run run(const std::string& program, conveyor::Port& port, const char* override_percent = nullptr) {
  const machines::Machine& m = interp::test::machine("laser_portal");
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  // The scenario outlives the player that plays it (scenario::Player keeps a reference).
  const core::SourceFile toml("s.toml", std::string("[[event]]\nat = 0.0\noverride = ") +
                                            (override_percent ? override_percent : "100") + "\n");
  const scenario::LoadResult loaded = scenario::parse_scenario(toml);
  REQUIRE(loaded.scenario);
  std::optional<scenario::Player> player;
  if (override_percent != nullptr) {
    cfg.path.override_type = ipo::OverrideType::reduced_above_100;
    player.emplace(*loaded.scenario);
  }
  channel::test::ConveyorRig rig(program, m, std::move(cfg), &port);
  if (player) rig.ch.play(&*player);
  const channel::Channel& ch = rig.ch;
  Run r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        r.line.push_back(ch.cycle().line);
        r.phase.push_back(s.phase());
        r.x.push_back({ch.axes().command[0], ch.axes().command[1], ch.axes().command[2]});
        r.offset_x.push_back(s.offset(0));
        r.x_indp.push_back(ch.indp().owned(0) && !ch.indp().in_position(0));
      },
      100'000);
  r.error = ch.run_time_error();
  if (const core::Diagnostic* d = rig.src.error()) r.source_error = d->id;
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  return r;
}

double velocity(const Run& r, std::size_t k, std::size_t axis = 0) {
  return (r.x[k][axis] - r.x[k - 1][axis]) / kT;
}

// X continuous within its V and (a few % for the difference estimate) its A.
void check_smooth(const Run& r) {
  for (std::size_t k = 2; k < r.x.size(); ++k) {
    CAPTURE(k);
    CHECK(std::fabs(velocity(r, k)) <= 1000.0 * (1 + 1e-9));
    const double a = (r.x[k][0] - 2 * r.x[k - 1][0] + r.x[k - 2][0]) / (kT * kT);
    CHECK(std::fabs(a) <= 10000.0 * 1.05);
  }
}

}  // namespace

TEST_CASE(
    "#SYNC OUT FEED_CONT=5 and FEED_CONT_AUTO: the desynchronisation ends in position (S-2)") {
  for (const char* out : {"#SYNC OUT [FEED_CONT=5]", "#SYNC OUT [FEED_CONT_AUTO]"}) {
    CAPTURE(out);
    tracking::test::FakePort port(300.0);
    port.latch_at_ = 1;
    const Run r = run(std::string("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\n"
                                  "N30 G01 X100 Y50 F6000\nN40 G04 0.1\nN50 ") +
                          out + "\nN60 G00 X-100 Y0\nN70 M30\n",
                      port);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE(r.x.size() > 3);
    CHECK(r.x.back()[0] == doctest::Approx(-100.0));
    CHECK(std::fabs(velocity(r, r.x.size() - 1)) < 1e-6);  // terminates at velocity 0
    check_smooth(r);
  }
}

TEST_CASE("INDP after #SYNC OUT leaves from the moving state (004 §4.7 desynchronisation)") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Run r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 G04 0.2\nN50 #SYNC OUT [FEED_CONT=5]\n"
          "N60 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS400 INTERRUPTIBLE]\n"
          "N70 M30\n",
          port);
  REQUIRE(r.status == ipo::Status::finished);
  std::size_t first = 0;  // the first cycle X runs its INDP motion
  for (std::size_t k = 1; k < r.x.size() && first == 0; ++k)
    if (r.x_indp[k]) first = k;
  REQUIRE(first > 1);
  // The cycle before, X moved with the belt (300 mm/s); the INDP motion starts from there.
  CHECK(velocity(r, first - 1) == doctest::Approx(300.0).epsilon(1e-6));
  CHECK(std::fabs(velocity(r, first) - 300.0) <= 10000.0 * kT * 1.05);
  check_smooth(r);
  CHECK(r.x.back()[0] == doctest::Approx(0.0));
  CHECK(r.x.back()[1] == doctest::Approx(400.0));
}

namespace {

// Two workpieces; the desynchronisation from the first runs X far back (X -150) as an INDP
// motion; the second workpiece is measured at once.
std::string two_workpieces(const char* indp) {
  return std::string(
             "%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 "
             "F6000\nN40 G04 0.1\nN50 #SYNC OUT [FEED_CONT=5]\nN60 X[") +
         indp +
         " G0 G90 POS-150 INTERRUPTIBLE]\nN70 S1 [MC_TouchProbe Channel=1]\n"
         "N80 #SYNC IN [CONV_VEL=18000]\nN90 G01 X100 Y50 F6000\nN100 G04 0.1\n"
         "N110 #SYNC OUT\nN120 M30\n";
}

}  // namespace

TEST_CASE(
    "INDP_SYN ... INTERRUPTIBLE is taken over by the next catch-up (on-the-fly change, S-4)") {
  tracking::test::FakePort port(300.0);
  port.latches_ = {0.0, 0.0};  // both measured values wait for their #SYNC IN
  const Run r = run(two_workpieces("INDP_SYN"), port);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  check_smooth(r);
  // The second catch-up starts while the INDP motion still runs: X never reaches -150.
  std::size_t catch2 = 0;
  for (std::size_t k = 1; k < r.x.size(); ++k)
    if (r.line[k] == 10 && r.phase[k] == tracking::SyncPhase::catching_up && catch2 == 0)
      catch2 = k;
  REQUIRE(catch2 > 0);
  CHECK(r.x_indp[catch2 - 1]);  // the INDP motion ran up to the catch-up
  const double x_min = std::min_element(r.x.begin(), r.x.end(), [](const auto& a, const auto& b) {
                         return a[0] < b[0];
                       })->at(0);
  CHECK(x_min > -149.0);
  // The second workpiece is tracked: X stands at PCS1 100 during its dwell.
  std::size_t dwell = 0;
  for (std::size_t k = 0; k < r.x.size(); ++k)
    if (r.line[k] == 11 && r.phase[k] == tracking::SyncPhase::tracking) {
      ++dwell;
      CHECK(r.x[k][0] - r.offset_x[k] == doctest::Approx(100.0).epsilon(1e-9));
    }
  CHECK(dwell >= 90);
}

TEST_CASE("INTERRUPTIBLE with INDP_ASYN is ignored: the catch-up waits for the motion's end") {
  tracking::test::FakePort port(300.0);
  port.latches_ = {0.0, 0.0};
  const Run r = run(two_workpieces("INDP_ASYN"), port);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  check_smooth(r);
  const double x_min = std::min_element(r.x.begin(), r.x.end(), [](const auto& a, const auto& b) {
                         return a[0] < b[0];
                       })->at(0);
  CHECK(x_min == doctest::Approx(-150.0));
}

TEST_CASE("PCS1 velocity split: full feed in +X and -X on a 300 mm/s belt keeps X within v_max") {
  // F 60000 mm/min = 1000 mm/s = X's v_max: without the split X would command 1300 mm/s in the
  // conveying direction. N50 asks for F 90000 (1500 mm/s) against it. With it the block along the
  // belt runs at 1000 - 1.1 x 300 = 670 mm/s (S-5), the one against it (belt-split, 004 l.319) at
  // v_max + CONV_VEL = 1300 mm/s relative, X at exactly its v_max in MCS (docs/conveyor.md
  // "velocity split").
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Run r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 G01 X900 F60000\nN50 G01 X100 F90000\nN60 #SYNC OUT\nN70 M30\n",
          port);
  REQUIRE(r.status == ipo::Status::finished);
  double v_plus = 0.0, v_minus = 0.0;
  for (std::size_t k = 1; k < r.x.size(); ++k) {
    CAPTURE(k);
    CHECK(std::fabs(velocity(r, k)) <= 1000.0 * (1 + 1e-9));
    if (r.phase[k] == tracking::SyncPhase::tracking &&
        r.phase[k - 1] == tracking::SyncPhase::tracking) {
      const double v_rel = velocity(r, k) - (r.offset_x[k] - r.offset_x[k - 1]) / kT;
      v_plus = std::max(v_plus, v_rel);
      v_minus = std::min(v_minus, v_rel);
    }
  }
  CHECK(v_plus == doctest::Approx(670.0).epsilon(1e-6));
  CHECK(v_minus == doctest::Approx(-1300.0).epsilon(1e-6));
}

namespace {

// A belt at 300 mm/s that slows to `v_end` [mm/s] at `dec` [mm/s^2] from step `from` on (dec
// 0: a step), master = actual, no noise; latched at step 1.
class RampPort final : public conveyor::Port {
 public:
  /// From cycle `from` the belt slows at `dec` to `v_end` (dec 0: a step); `jerk` > 0: its
  /// deceleration builds up and decays at that jerk (a spindle's MC_MoveVelocity ramp).
  RampPort(long from, double dec, double v_end, double jerk = 0.0)
      : from_(from), dec_(dec), v_end_(v_end), jerk_(jerk) {}
  void step(double t) noexcept override {
    ++steps_;
    double v = 300.0, a = 0.0;
    if (steps_ >= from_ && jerk_ > 0.0) {
      // Per cycle: the deceleration grows at the jerk, and decays in time to end at v_end.
      const double left = v_ - v_end_;
      const bool decay = left <= a_ * a_ / (2.0 * jerk_);
      a_ = decay ? std::max(0.0, a_ - jerk_ * kT) : std::min(dec_, a_ + jerk_ * kT);
      v_ = std::max(v_end_, v_ - a_ * kT);
      v = v_;
      a = v > v_end_ ? -a_ : 0.0;
    } else if (steps_ >= from_) {
      const double dt = static_cast<double>(steps_ - from_) * kT;
      v = dec_ > 0.0 ? std::max(v_end_, 300.0 - dec_ * dt) : v_end_;
      a = dec_ > 0.0 && v > v_end_ ? -dec_ : 0.0;
    }
    p_ += v * (t - t_);
    t_ = t;
    state_ = conveyor::BeltState{p_, v, a};
    if (steps_ == 1) latch_ = p_;
  }
  const conveyor::BeltState& actual() const noexcept override { return state_; }
  const conveyor::BeltState& measured() const noexcept override { return state_; }
  const conveyor::BeltState& master() const noexcept override { return state_; }
  bool command_velocity(const interp::MoveVelocity&) noexcept override { return false; }
  void arm_probe(const interp::ProbeArm&) noexcept override {}
  std::optional<double> take_latch() noexcept override {
    const std::optional<double> l = latch_;
    latch_.reset();
    return l;
  }
  void set_reduced_filter(bool) noexcept override {}
  const std::optional<conveyor::PortError>& error() const noexcept override { return error_; }

 private:
  long from_;
  double dec_, v_end_, jerk_;
  double v_ = 300.0, a_ = 0.0;  ///< the jerk-limited ramp's state (jerk_ > 0)
  long steps_ = 0;
  double p_ = 0.0, t_ = 0.0;
  std::optional<double> latch_;
  std::optional<conveyor::PortError> error_;
  conveyor::BeltState state_;
};

// The split program: N50 runs 800 mm against the belt at 1300 mm/s relative (F 1500 mm/s).
constexpr const char* kAgainst =
    "%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
    "N40 G01 X900 F60000\nN50 G01 X100 F90000\nN60 #SYNC OUT\nN70 M30\n";

// Highest |X velocity| in MCS over the run [mm/s].
double x_peak(const Run& r) {
  double peak = 0.0;
  for (std::size_t k = 1; k < r.x.size(); ++k)
    peak = std::max(peak, std::fabs(velocity(r, k)));
  return peak;
}

}  // namespace

TEST_CASE(
    "velocity split against the belt: a belt that slows caps the path, X over v_max only by the "
    "cap's lag (a ramp) or until braked (a step)") {
  // belt-split (004 l.319, docs/conveyor.md "velocity split"): N50 is planned at v_max +
  // CONV_VEL relative; the channel caps the path when the belt runs slower than CONV_VEL
  // (Channel::sync_belt_cap). The belt slows in the middle of N50's cruise.
  RampPort steady(1'000'000, 0.0, 300.0);
  const Run base = run(kAgainst, steady);
  REQUIRE(base.status == ipo::Status::finished);
  long mid = 0;  // a cycle in N50's cruise
  for (std::size_t k = 1; k < base.x.size() && mid == 0; ++k)
    if (base.line[k] == 6 && velocity(base, k) == doctest::Approx(-1000.0).epsilon(1e-9))
      mid = static_cast<long>(k) + 20;
  REQUIRE(mid > 0);
  CHECK(x_peak(base) <= 1000.0 * (1 + 1e-9));
  struct Case {
    double dec, v_end, bound;  // belt [mm/s^2], [mm/s]; allowed X peak [mm/s]
  };
  // A ramp at r: the jerk-limited replan follows the falling cap r^2 / (2 j) behind (laser
  // portal's path jerk 200000 mm/s^3) plus one cycle's fall r T: measured 1002.97 and 1023.97
  // mm/s. A step the path cannot follow at all: X reads v_max + CONV_VEL until it has braked.
  // The seeds' MC_MoveVelocity ramp (D 2000, J 750000) builds its deceleration in 2.7 ms, which
  // the path (J 200000) cannot match either: measured 1011.22, within the step's 1012.
  const auto residual = [](double r) { return 1000.0 + r * r / (2 * 200000.0) + r * kT; };
  for (const Case c : {Case{1000.0, 0.0, residual(1000.0)}, Case{3000.0, 150.0, residual(3000.0)},
                       Case{0.0, 0.0, 1300.0}, Case{-2000.0, 0.0, residual(2000.0)}}) {
    CAPTURE(c.dec);
    CAPTURE(c.v_end);
    // dec < 0: MC_MoveVelocity's ramp of the seeds (Deceleration=2000 Jerk=750000, 004 l.726)
    RampPort port(mid, std::fabs(c.dec), c.v_end, c.dec < 0.0 ? 750000.0 : 0.0);
    const Run r = run(kAgainst, port);
    REQUIRE(r.status == ipo::Status::finished);
    CHECK_FALSE(r.error);
    MESSAGE("belt " << c.dec << " mm/s^2 to " << c.v_end << " mm/s: X peak " << x_peak(r));
    CHECK(x_peak(r) <= c.bound * (1 + 1e-9));
    CHECK(r.x.back()[0] - r.offset_x.back() == doctest::Approx(100.0));
  }
}

TEST_CASE(
    "an override above 100 % keeps a PCS1 block at its split velocity: X stays within v_max") {
  // REDUCED_ABOVE_100 raises the path above its F up to the G00 rule of the
  // axes (000 l.357, l.360; ipo::raised_limits). The axes' full limits do not know the belt's
  // share of X (the split lowered only the plan), so at 150 % the block of the test above was
  // raised to X's 1000 mm/s in PCS1 and X commanded 1000 + 300 mm/s in MCS (measured before:
  // 1300 mm/s). Now a PCS1 block keeps its 100 % plan above 100 %, as under #TRAFO ON
  // (docs/conveyor.md "Machining in PCS1"); below 100 % the override acts as everywhere.
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Run r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 G01 X900 F60000\nN50 G01 X100 F60000\nN60 #SYNC OUT\nN70 G01 X200 Y0 F6000\n"
          "N75 G01 X0 Y0 F6000\nN80 M30\n",
          port, "150");
  REQUIRE(r.status == ipo::Status::finished);
  double v_max = 0.0, v_plus = 0.0, v_off = 0.0;
  for (std::size_t k = 1; k < r.x.size(); ++k) {
    v_max = std::max(v_max, std::fabs(velocity(r, k)));
    if (r.phase[k] == tracking::SyncPhase::tracking &&
        r.phase[k - 1] == tracking::SyncPhase::tracking)
      v_plus = std::max(v_plus, velocity(r, k) - (r.offset_x[k] - r.offset_x[k - 1]) / kT);
    if (r.line[k] == 9) v_off = std::max(v_off, std::hypot(velocity(r, k), velocity(r, k, 1)));
  }
  MESSAGE("X's largest |v| in MCS " << v_max << " mm/s, in PCS1 " << v_plus
                                    << ", off the belt (N75, F 100 mm/s) " << v_off);
  CHECK(v_max <= 1000.0 * (1 + 1e-9));
  CHECK(v_plus == doctest::Approx(670.0).epsilon(1e-6));
  CHECK(v_off == doctest::Approx(150.0).epsilon(1e-6));  // off the belt 150 % still raises
}

TEST_CASE("PCS1 velocity split on spline pieces: a B-spline at full feed keeps X within v_max") {
  // The pieces of a #SPLINE section in PCS1 get the split as a line does: without it the
  // belt's 300 mm/s came on top of a 1000 mm/s piece (found by belt-jerk2, session 24).
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Run r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 #SPLINE TYPE BSPLINE\nN50 #SPLINE ON\nN60 G01 X300 Y60 F60000\nN70 X500 Y40\n"
          "N80 X700 Y60\nN90 X900 Y50\nN100 #SPLINE OFF\nN110 #SYNC OUT\nN120 M30\n",
          port);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE(r.source_error.empty());
  double v_plus = 0.0;
  for (std::size_t k = 1; k < r.x.size(); ++k) {
    CAPTURE(k);
    CHECK(std::fabs(velocity(r, k)) <= 1000.0 * (1 + 1e-9));
    if (r.phase[k] == tracking::SyncPhase::tracking &&
        r.phase[k - 1] == tracking::SyncPhase::tracking)
      v_plus = std::max(v_plus, velocity(r, k) - (r.offset_x[k] - r.offset_x[k - 1]) / kT);
  }
  CHECK(v_plus > 600.0);  // the pieces run near what the split leaves (670 mm/s along X)
  CHECK(v_plus <= 670.0 * (1 + 1e-6));
}

TEST_CASE("a belt stopped while synchronised stops the machine with it (004 §2.3)") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  port.v_change_at_ = 400;  // during the dwell on the workpiece
  port.v_new_ = 0.0;
  const Run r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 G04 1\nN50 #SYNC OUT\nN60 M30\n",
          port);
  REQUIRE(r.status == ipo::Status::finished);
  std::size_t still = 0;
  for (std::size_t k = 401; k < r.x.size(); ++k)
    if (r.line[k] == 5 && r.phase[k] == tracking::SyncPhase::tracking) {
      ++still;
      CHECK(velocity(r, k) == doctest::Approx(0.0));
      CHECK(r.x[k][0] - r.offset_x[k] == doctest::Approx(100.0).epsilon(1e-9));
    }
  CHECK(still > 100);
}

namespace {

// FakePort that records the reduced-filter switch per step.
class FilterPort final : public conveyor::Port {
 public:
  explicit FilterPort(double v) : belt(v) {}
  void step(double t) noexcept override {
    belt.step(t);
    reduced_at_step.push_back(reduced);
    t_at_step.push_back(t);
  }
  const conveyor::BeltState& actual() const noexcept override { return belt.actual(); }
  const conveyor::BeltState& measured() const noexcept override { return belt.measured(); }
  const conveyor::BeltState& master() const noexcept override { return belt.master(); }
  bool command_velocity(const interp::MoveVelocity& c) noexcept override {
    return belt.command_velocity(c);
  }
  void arm_probe(const interp::ProbeArm& c) noexcept override { belt.arm_probe(c); }
  std::optional<double> take_latch() noexcept override { return belt.take_latch(); }
  void set_reduced_filter(bool on) noexcept override { reduced = on; }
  const std::optional<conveyor::PortError>& error() const noexcept override { return belt.error(); }
  tracking::test::FakePort belt;
  bool reduced = false;
  std::vector<bool> reduced_at_step;
  std::vector<double> t_at_step;  ///< [s]
};

}  // namespace

TEST_CASE("a feed hold while synchronised switches the conveyor's reduced filter (F-4)") {
  const char* program =
      "%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
      "N40 G01 X150 F600\nN50 #SYNC OUT\nN60 G01 Y0 F6000\nN65 G01 Y10 F600\nN70 M30\n";
  // Two holds: one while machining on the workpiece, one after #SYNC OUT.
  const core::SourceFile toml("s.toml",
                              "[[event]]\nat = 0.5\nfeed_hold = true\nduration = 0.2\n"
                              "[[event]]\nline = 8\nfeed_hold = true\nduration = 0.2\n");
  scenario::LoadResult loaded = scenario::parse_scenario(toml);
  REQUIRE(loaded.scenario);
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine("laser_portal");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  scenario::Player player(*loaded.scenario);
  src.answer_barriers_from(&player.ve(), true);
  channel::Channel ch(channel::channel_config(m, kT), src);
  FilterPort port(300.0);
  port.belt.latch_at_ = 1;
  ch.attach_conveyor(&port);
  ch.play(&player);
  std::vector<bool> held, tracking;
  ipo::Status st = ipo::Status::running;
  for (int guard = 0; guard < 100'000 && st == ipo::Status::running; ++guard) {
    st = ch.step();
    held.push_back(ch.cycle().held);
    tracking.push_back(ch.conveyor_sync()->phase() == tracking::SyncPhase::tracking);
  }
  REQUIRE(st == ipo::Status::finished);
  // The switch is handed over at the start of the cycle; the Port is stepped later in it.
  std::size_t on_tracking = 0, held_off_sync = 0;
  for (std::size_t k = 1; k + 1 < held.size() && k < port.reduced_at_step.size(); ++k) {
    if (held[k - 1] && tracking[k - 1] && port.reduced_at_step[k]) ++on_tracking;
    if (held[k - 1] && !tracking[k - 1]) {
      ++held_off_sync;
      CHECK_FALSE(port.reduced_at_step[k]);
    }
  }
  CHECK(on_tracking > 100);
  CHECK(held_off_sync > 100);
}

TEST_CASE(
    "MCV_SetReducedFilter from the scenario reaches the Port's set_reduced_filter at the "
    "event's time") {
  const char* program =
      "%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
      "N40 G01 X150 F600\nN50 #SYNC OUT\nN60 M30\n";
  // The PLC switches the reduced filter on at 0.3 s and off at 0.6 s (docs/conveyor.md F-5).
  const core::SourceFile toml("s.toml",
                              "[[event]]\nat = 0.3\nreduced_filter = true\n"
                              "[[event]]\nat = 0.6\nreduced_filter = false\n");
  scenario::Context wired;
  wired.conveyor_wired = true;
  scenario::LoadResult loaded = scenario::parse_scenario(toml, wired);
  REQUIRE(loaded.scenario);
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine("laser_portal");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  scenario::Player player(*loaded.scenario);
  src.answer_barriers_from(&player.ve(), true);
  channel::Channel ch(channel::channel_config(m, kT), src);
  FilterPort port(300.0);
  port.belt.latch_at_ = 1;
  ch.attach_conveyor(&port);
  ch.play(&player);
  ipo::Status st = ipo::Status::running;
  for (int guard = 0; guard < 100'000 && st == ipo::Status::running; ++guard)
    st = ch.step();
  REQUIRE(st == ipo::Status::finished);
  REQUIRE(port.t_at_step.size() == port.reduced_at_step.size());
  REQUIRE(port.t_at_step.back() > 1.0);
  // The switch is handed over at the start of a cycle and the Port is stepped later in it: the
  // Port sees it from the step after the event's time on (one cycle of slack each side).
  std::size_t on = 0;
  for (std::size_t i = 0; i < port.t_at_step.size(); ++i) {
    const double t = port.t_at_step[i];
    CAPTURE(t);
    if (t < 0.3 - 1e-9 || t > 0.6 + 2.0 * kT + 1e-9) CHECK_FALSE(port.reduced_at_step[i]);
    if (t > 0.3 + 2.0 * kT + 1e-9 && t < 0.6 - 1e-9) {
      CHECK(port.reduced_at_step[i]);
      ++on;
    }
  }
  CHECK(on > 290);
}
