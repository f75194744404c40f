// The recorder: one pass of the cycle stream gives the same totals and block records as
// `time`, the same verdict as the audit, every axis's extremes, and a bounded toolpath.

#include "report/recorder.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "ipo/test_support.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;
using namespace ncsim::audit;
using namespace ncsim::channel;
using namespace ncsim::ipo;
using namespace ncsim::tracking;
using namespace ncsim::ipo::test;
using ncsim::report::NamedSeries;
using ncsim::report::Recorder;
using ncsim::report::ReportData;

/// Passes the cycles to a recorder and a separate audit.
struct Both final : Sink {
  Recorder* r;
  Audit* a;
  double v_max[3] = {0, 0, 0};
  void on_joint(const Joint& j) override {
    r->on_joint(j);
    a->on_joint(j);
  }
  void on_cycle(const Cycle& c) override {
    r->on_cycle(c);
    a->on_cycle(c);
    for (int i = 0; i < 3; ++i)
      v_max[i] = std::max(v_max[i], std::fabs(c.v[static_cast<std::size_t>(i)]));
  }
};

TEST_CASE("one pass: totals and slowest blocks as time, the audit's verdict, the v extremes") {
  std::mt19937_64 rng(1515);
  for (int trial = 0; trial < 8; ++trial) {
    Config cfg;
    cfg.axes = random_limits(rng);
    cfg.channel.t_cycle = 0.001;
    const auto items = random_program(rng, RandomProgram{});
    ListSource src(items);
    Recorder rec({"X", "Y", "Z"}, cfg.axes, cfg.channel.t_cycle, cfg.start);
    Audit audit(cfg.axes, cfg.channel.t_cycle, cfg.start);
    Both both;
    both.r = &rec;
    both.a = &audit;
    PathInterpolator ipo(cfg, src, &both);
    AxisVec last{};
    while (ipo.step() == Status::running)
      last = ipo.cycle().x;
    const ReportData d = rec.finish({"p.nc", "m", "", ""});

    ListSource time_src(items);
    std::vector<BlockTime> blocks;
    const TimeResult r =
        machining_time(cfg, time_src, [&](const BlockTime& b) { blocks.push_back(b); });
    CAPTURE(trial);
    CHECK(d.time_total.cycles == r.cycles);
    CHECK(d.time_total.total == r.total);
    CHECK(d.blocks == blocks.size());
    std::stable_sort(blocks.begin(), blocks.end(),
                     [](const BlockTime& a, const BlockTime& b) { return a.time > b.time; });
    REQUIRE(d.slowest.size() == std::min(blocks.size(), Recorder::kSlowest));
    for (std::size_t k = 0; k < d.slowest.size(); ++k) {
      CHECK(d.slowest[k].line == blocks[k].line);
      CHECK(d.slowest[k].time == blocks[k].time);
    }
    CHECK(d.verdict.violation_count == audit.verdict().violation_count);
    CHECK(d.verdict.cycles == audit.verdict().cycles);
    CHECK(d.verdict.contour_max == audit.verdict().contour_max);
    CHECK(d.outcome == "ok");
    // Each axis's velocity series (index 5 i + 1) keeps its largest |v|.
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& v = d.time.series[5 * i + 1];
      double m = 0.0;
      for (const double x : v)
        m = std::max(m, std::fabs(x));
      CHECK(m == both.v_max[i]);
    }
    CHECK(d.time.t.size() <= 2 * Recorder::kBuckets);
    REQUIRE(d.path_dims == 3);
    CHECK(d.path_mcs.size() / 3 <= Recorder::kPathPoints + 1);
    CHECK(std::equal(d.path_mcs.end() - 3, d.path_mcs.end(), last.begin()));
    CHECK(d.path_pcs1.empty());
  }
}

TEST_CASE("named series and the PCS1 path appear only when given; the outcome names the end") {
  Config cfg;
  cfg.axes.assign(3, axis(100, 1000, 10000));
  cfg.channel.t_cycle = 0.001;
  const std::vector<Item> items = {Item{line(vec(0, 0), vec(10, 5), 50.0, 1)}};
  ListSource src(items);
  Recorder rec({"X", "Y", "Z"}, cfg.axes, 0.001, cfg.start,
               {NamedSeries{"current_pos_master", "mm"}, NamedSeries{"synchro_lag", "mm"}});
  struct Feed final : Sink {
    Recorder* r;
    std::uint64_t n = 0;
    void on_joint(const Joint& j) override { r->on_joint(j); }
    void on_cycle(const Cycle& c) override {
      const double belt = 0.1 * static_cast<double>(n++);
      r->set_value(0, belt);
      r->set_value(1, -belt);
      const double p[3] = {c.x[0] - belt, c.x[1], c.x[2]};
      r->set_pcs1(p);
      r->on_cycle(c);
    }
  } feed;
  feed.r = &rec;
  PathInterpolator ipo(cfg, src, &feed);
  while (ipo.step() == Status::running) {
  }
  REQUIRE(feed.n > 10);
  CHECK_THROWS_AS(rec.set_value(2, 0.0), std::invalid_argument);
  const ReportData d = rec.finish({"p.nc", "m", "", "p.nc:1:1: error: boom"});
  CHECK(d.outcome == "error");
  REQUIRE(d.named.size() == 2);
  REQUIRE(d.time.series.size() == 5 * 3 + 2 + 2);
  const auto& master = d.time.series[17];
  CHECK(master.front() == 0.0);
  CHECK(master.back() == doctest::Approx(0.1 * static_cast<double>(feed.n - 1)));
  REQUIRE(d.path_dims == 3);
  REQUIRE(d.path_pcs1.size() >= 6);
  CHECK(d.path_pcs1[d.path_pcs1.size() - 3] ==
        doctest::Approx(10.0 - 0.1 * static_cast<double>(feed.n - 1)));
}

TEST_CASE("soft position limits: the enabled ones, NaN where not monitored") {
  ChannelConfig cc;
  cc.path.axes.assign(2, axis(100, 1000, 10000));
  cc.axes.resize(2);
  cc.axes[0].monitor.soft_limits = {true, -5.0, true, 800.0};
  cc.axes[1].monitor.soft_limits = {false, -1.0, true, 300.0};
  Recorder rec({"X", "Y"}, cc.path.axes, 0.001, cc.path.start);
  rec.set_limits(cc);
  const ReportData d = rec.finish({"p.nc", "m", "", ""});
  REQUIRE(d.soft_limits.size() == 2);
  CHECK(d.soft_limits[0][0] == -5.0);
  CHECK(d.soft_limits[0][1] == 800.0);
  CHECK(std::isnan(d.soft_limits[1][0]));
  CHECK(d.soft_limits[1][1] == 300.0);
}

TEST_CASE(
    "a conveyor channel: belt velocities, current_pos_master, the sync phases, per workpiece") {
  const axes::Dynamics dyn{1000.0, 5000.0, 5000.0, 50000.0};
  const std::vector<SyncAxis> sync_axes{SyncAxis{"X", 0, dyn}, SyncAxis{"Y", 1, dyn},
                                        SyncAxis{"Z", 2, dyn}};
  ChannelConfig cc;
  cc.path.axes.assign(3, axis(1000, 5000, 50000));
  cc.axes.resize(3);
  machines::ConveyorSyncChannel conv;
  conv.t0_shift = Eigen::Vector3d(-100.0, 0.0, 0.0);
  conv.workspace = {Eigen::Vector3d(-200.0, 0.0, -100.0), Eigen::Vector3d(4000.0, 2500.0, 300.0)};
  conv.pos_limit = -190.0;
  cc.conveyor = conv;
  tracking::test::FakePort port(300.0);
  ConveyorSync sync(conv, sync_axes, 0.001);
  sync.attach(&port);
  Recorder rec({"X", "Y", "Z"}, cc.path.axes, 0.001, cc.path.start);
  rec.set_limits(cc);
  rec.set_conveyor(&sync);
  REQUIRE_FALSE(sync.sync_in([] {
    interp::SyncIn in;
    in.conv_vel = 300.0;
    return in;
  }()));
  Cycle c{};
  for (int k = 1; k <= 300; ++k) {
    c.t = 0.001 * k;
    if (k == 101) port.latches_.push_back(port.p_);  // the front edge at the sensor
    REQUIRE_FALSE(sync.step(c.t));
    rec.on_cycle(c);
  }
  CHECK_THROWS_AS(rec.set_conveyor(&sync), std::logic_error);
  const ReportData d = rec.finish({"p.nc", "m", "", ""});
  REQUIRE(d.named.size() == Recorder::kConveyorSeries.size());
  const auto at = [&](const char* name) -> const std::vector<double>& {
    for (std::size_t k = 0; k < d.named.size(); ++k)
      if (d.named[k].name == name) return d.time.series[5 * 3 + 2 + k];
    FAIL("no series " << name);
    return d.time.series.front();
  };
  const auto& t = d.time.t;
  REQUIRE(t.size() >= 300);  // 300 cycles: fewer than the buckets, no merge
  for (const char* v : {"belt_v_actual", "belt_v_raw", "belt_v_filtered"})
    CHECK(at(v).back() == doctest::Approx(300.0));
  // Null before the measurement; then the jump to P-CHAN-00368 and the belt's travel.
  const auto& pos = at("current_pos_master");
  CHECK(std::isnan(pos.front()));
  CHECK(pos.back() == doctest::Approx(-100.0 + 300.0 * 0.2).epsilon(1e-3));
  CHECK(at("phase.waiting").front() == 1.0);
  CHECK(at("phase.waiting").back() == 0.0);
  CHECK(at("phase.catch_up").front() == 0.0);
  CHECK(at("phase.catch_up").back() == 1.0);  // latched: the next motion is the catch-up
  CHECK(at("phase.synchronised").back() == 0.0);
  CHECK(std::isnan(at("synchro_lag").back()));  // only while PCS1 moves (tracking, leaving)
  // The time per workpiece (audit::WorkpieceCycles): one open row, waiting then catch-up.
  REQUIRE(d.workpieces);
  CHECK(d.workpieces->workpieces == 1);
  CHECK(d.workpieces->complete == 0);
  REQUIRE(d.workpiece_rows.size() == 1);
  CHECK(d.workpiece_rows[0].waiting == doctest::Approx(0.1));
  CHECK(d.workpiece_rows[0].catch_up == doctest::Approx(0.2));
  CHECK(d.workpiece_rows[0].total == doctest::Approx(0.3));
  CHECK_FALSE(d.workpiece_rows[0].complete);
  REQUIRE(d.workspace);
  CHECK(d.workspace->lower.x() == -200.0);
  CHECK(d.workspace->upper.y() == 2500.0);
  CHECK(d.workspace->pos_limit == -190.0);
  CHECK(d.workspace->along_x);
  CHECK(d.workspace->sign == 1);
}

TEST_CASE("a conveyor channel under #TRAFO ON: the MCS toolpath is the TCP, not the joints") {
  const axes::Dynamics dyn{1000.0, 5000.0, 5000.0, 50000.0};
  const std::vector<SyncAxis> sync_axes{SyncAxis{"X", 0, dyn}, SyncAxis{"Y", 1, dyn},
                                        SyncAxis{"Z", 2, dyn}};
  ChannelConfig cc;
  cc.path.axes.assign(3, axis(1000, 5000, 50000));
  cc.axes.resize(3);
  machines::ConveyorSyncChannel conv;
  cc.conveyor = conv;
  ConveyorSync sync(conv, sync_axes, 0.001);
  Recorder rec({"X", "Y", "Z"}, cc.path.axes, 0.001, cc.path.start);
  std::array<axes::Setpoint, planner::kMaxAxes> joints{}, tcp{};
  rec.set_setpoints(&joints);
  rec.set_tcp(&tcp);
  rec.set_conveyor(&sync);
  planner::Move move;
  move.transformed = true;
  Cycle c{};
  c.activity = Activity::motion;
  c.programmed = &move;
  for (int k = 1; k <= 3; ++k) {
    c.t = 0.001 * k;
    for (std::size_t i = 0; i < 3; ++i) {
      joints[i].p = 10.0 * k + static_cast<double>(i);  // joint angles [deg]
      tcp[i].p = -500.0 * k - static_cast<double>(i);   // the TCP [mm]
    }
    rec.on_cycle(c);
  }
  move.transformed = false;  // the same channel without the transform: the setpoints
  c.t = 0.004;
  joints[0].p = 77.0;
  rec.on_cycle(c);
  const ReportData d = rec.finish({"p.nc", "m", "", ""});
  REQUIRE(d.path_dims == 3);
  REQUIRE(d.path_mcs.size() >= 6);
  CHECK(d.path_mcs[0] == -500.0);
  CHECK(d.path_mcs[1] == -501.0);
  CHECK(d.path_mcs[2] == -502.0);
  CHECK(d.path_mcs[d.path_mcs.size() - 3] == 77.0);
}

TEST_CASE("a kinematic machine before #TRAFO ON: the MCS toolpath is the joints' TCP") {
  // Before #TRAFO ON the axes of a delta are its joints [deg]: the MCS toolpath is where they
  // put the TCP (the forward transform), not their angles drawn as millimetres; with and
  // without conveyor tracking. The forward map here: TCP = -10 q - 600 on each axis.
  const axes::Dynamics dyn{1000.0, 5000.0, 5000.0, 50000.0};
  const std::vector<SyncAxis> sync_axes{SyncAxis{"X", 0, dyn}, SyncAxis{"Y", 1, dyn},
                                        SyncAxis{"Z", 2, dyn}};
  for (const bool tracking : {false, true}) {
    CAPTURE(tracking);
    ChannelConfig cc;
    cc.path.axes.assign(3, axis(1000, 5000, 50000));
    cc.axes.resize(3);
    machines::ConveyorSyncChannel conv;
    cc.conveyor = conv;
    ConveyorSync sync(conv, sync_axes, 0.001);
    Recorder rec({"X", "Y", "Z"}, cc.path.axes, 0.001, cc.path.start);
    std::array<axes::Setpoint, planner::kMaxAxes> joints{}, tcp{};
    rec.set_setpoints(&joints);
    rec.set_tcp(&tcp);
    rec.set_conveyor(tracking ? &sync : nullptr);
    rec.set_forward([](const ipo::AxisVec& q, ipo::AxisVec& x) {
      if (q[0] > 90.0) return false;  // outside the transform: no point
      for (std::size_t k = 0; k < x.size(); ++k)
        x[k] = -10.0 * q[k] - 600.0;
      return true;
    });
    planner::Move move;
    move.transformed = false;
    Cycle c{};
    c.activity = Activity::motion;
    c.programmed = &move;
    for (int k = 0; k <= 3; ++k) {
      c.t = 0.001 * (k + 1);
      for (std::size_t i = 0; i < 3; ++i) {
        joints[i].p = k == 3 ? 100.0 : 1.0 * k + static_cast<double>(i);  // joint angles [deg]
        c.x[i] = joints[i].p;  // untransformed: the path point is the axes
      }
      rec.on_cycle(c);
    }
    move.transformed = true;  // under #TRAFO ON: the TCP (set_tcp) or the path point
    c.t = 0.005;
    for (std::size_t i = 0; i < 3; ++i)
      c.x[i] = tcp[i].p = -650.0 - static_cast<double>(i);
    rec.on_cycle(c);
    const ReportData d = rec.finish({"p.nc", "m", "", ""});
    REQUIRE(d.path_dims == 3);
    REQUIRE(d.path_mcs.size() >= 9);
    // The first point: the TCP of the joints at 0, 1, 2 deg, not (0, 1, 2) mm.
    CHECK(d.path_mcs[0] == -600.0);
    CHECK(d.path_mcs[1] == -610.0);
    CHECK(d.path_mcs[2] == -620.0);
    for (const double x : d.path_mcs)
      CHECK(x <= -600.0);  // no joint angle, and nothing of the unmapped cycle
    CHECK(d.path_mcs[d.path_mcs.size() - 3] == -650.0);
  }
}

TEST_CASE("no conveyor tracking: no conveyor series, no workspace") {
  ChannelConfig cc;
  cc.path.axes.assign(3, axis(1000, 5000, 50000));
  cc.axes.resize(3);
  cc.conveyor = machines::ConveyorSyncChannel{};
  Recorder rec({"X", "Y", "Z"}, cc.path.axes, 0.001, cc.path.start);
  rec.set_limits(cc);
  rec.set_conveyor(nullptr);
  const ReportData d = rec.finish({"p.nc", "m", "", ""});
  CHECK(d.named.empty());
  CHECK_FALSE(d.workspace);
  CHECK_FALSE(d.workpieces);
}

TEST_CASE("a recorder needs one name per axis limit") {
  Config cfg;
  cfg.axes.assign(2, axis(100, 1000, 10000));
  CHECK_THROWS_AS(Recorder({"X"}, cfg.axes, 0.001, cfg.start), std::invalid_argument);
}

}  // namespace
