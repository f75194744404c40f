#include "report/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/tolerance.hpp"
#include "ipo/joint_stage.hpp"
#include "tracking/synchro_lag.hpp"

namespace ncsim::report {

namespace {
constexpr std::size_t kPerAxis = 5;  // position, v, a, j, following error
}  // namespace

Recorder::Recorder(std::vector<std::string> axes, std::span<const planner::AxisLimits> limits,
                   double t_cycle, const ipo::AxisVec& start, std::vector<NamedSeries> named)
    : names_(std::move(axes)),
      named_(std::move(named)),
      t_cycle_(t_cycle),
      audit_(limits, t_cycle, start),
      counter_(t_cycle, [this](const audit::BlockTime& b) { block_done(b); }),
      series_(kPerAxis * names_.size() + 2 + named_.size(), kBuckets),
      mcs_(std::clamp<std::size_t>(names_.size(), 1, 3), kPathPoints) {
  if (names_.empty() || names_.size() != limits.size())
    throw std::invalid_argument("report recorder: " + std::to_string(names_.size()) +
                                " axis names for " + std::to_string(limits.size()) + " limits");
  values_.assign(series_.series(), std::numeric_limits<double>::quiet_NaN());
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  soft_limits_.assign(names_.size(), {nan, nan});
}

void Recorder::set_limits(const channel::ChannelConfig& config) {
  for (std::size_t i = 0; i < names_.size() && i < config.axes.size(); ++i) {
    const axes::SoftLimitParams& l = config.axes[i].monitor.soft_limits;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    soft_limits_[i] = {l.min_enabled ? l.min_position : nan, l.max_enabled ? l.max_position : nan};
  }
  if (config.path.joints)  // the joints are the machine axes (as the CLI's audit)
    audit_.set_joint_limits(config.path.joints->joints, config.path.start, true);
  workspace_.reset();
  if (config.conveyor) {
    const machines::ConveyorSyncChannel& c = *config.conveyor;
    WorkspaceView w;
    w.lower = c.workspace.lower;
    w.upper = c.workspace.upper;
    w.pos_limit = c.pos_limit;
    // PCS0 +X in MCS (R0 e_x); along MCS X when T0 turns only about X.
    const tracking::SyncFrame frame(c);
    const Eigen::Vector3d e = frame.direction();
    w.along_x = std::abs(std::abs(e.x()) - 1.0) < kRelTol;
    w.sign = e.x() < 0.0 ? -1 : 1;
    workspace_ = w;
  }
}

void Recorder::set_conveyor(const tracking::ConveyorSync* sync) {
  if (started_) throw std::logic_error("report recorder: set_conveyor after the first cycle");
  conveyor_ = sync;
  if (sync == nullptr || sync->port() == nullptr || conveyor_series_) return;
  // The conveyor series go after the named ones: the decimator is made anew (no cycle yet).
  conveyor_first_ = kPerAxis * names_.size() + 2 + named_.size();
  for (const auto& [name, unit] : kConveyorSeries)
    named_.push_back({name, unit});
  series_ = MinMaxDecimator(kPerAxis * names_.size() + 2 + named_.size(), kBuckets);
  values_.resize(series_.series(), std::numeric_limits<double>::quiet_NaN());
  conveyor_series_ = true;
  cycles_ =
      std::make_unique<audit::WorkpieceCycles>(t_cycle_, [this](const audit::WorkpieceCycle& r) {
        if (rows_.size() < kWorkpieceRows) rows_.push_back(r);
      });
}

void Recorder::conveyor_values() {
  const conveyor::Port& port = *conveyor_->port();
  double* v = values_.data() + conveyor_first_;
  v[0] = port.actual().v;
  v[1] = port.measured().v;
  v[2] = port.master().v;
  const tracking::MasterDisplay d = conveyor_->display();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  v[3] = d.valid ? d.current_pos_master : nan;
  v[4] = d.valid ? d.pos_master_comp : nan;
  // synchro_lag against the real workpiece (tracking/synchro_lag.hpp); under #TRAFO ON the TCP's
  // (set_tcp(), set_forward()).
  v[5] = nan;
  if (axes_state_ != nullptr) {
    const std::size_t n = names_.size();
    if (const auto lag =
            tracking::cycle_lag(*conveyor_, {axes_state_->command.data(), n},
                                {axes_state_->actual.data(), n}, transformed_, tcp_, forward_))
      v[5] = *lag;
  }
  // The phases of docs/report.md "Conveyor": synchronised from the catch-up's P-CHAN-00365
  // status (ConveyorSync::synchronised()) to #SYNC OUT.
  const tracking::SyncPhase p = conveyor_->phase();
  const bool sync = conveyor_->synchronised() || p == tracking::SyncPhase::tracking;
  v[6] = p == tracking::SyncPhase::waiting ? 1.0 : 0.0;
  v[7] = !sync && (p == tracking::SyncPhase::latched || p == tracking::SyncPhase::catching_up)
             ? 1.0
             : 0.0;
  v[8] = sync ? 1.0 : 0.0;
  v[9] = p == tracking::SyncPhase::leaving || p == tracking::SyncPhase::departing ? 1.0 : 0.0;
  cycles_->add(p, port.last_latch().workpiece);
}

void Recorder::set_pcs1(std::span<const double> p) {
  if (!pcs1_) pcs1_ = std::make_unique<PathThinner>(mcs_.dims(), kPathPoints);
  pcs1_point_.assign(p.begin(), p.begin() + static_cast<long>(std::min(p.size(), mcs_.dims())));
  pcs1_point_.resize(mcs_.dims(), 0.0);
}

void Recorder::set_value(std::size_t index, double value) {
  if (index >= named_.size())
    throw std::invalid_argument("report recorder: named series " + std::to_string(index) + " of " +
                                std::to_string(named_.size()));
  values_[kPerAxis * names_.size() + 2 + index] = value;
}

void Recorder::on_joint(const ipo::Joint& joint) {
  audit_.on_joint(joint);
}

void Recorder::on_cycle(const ipo::Cycle& c) {
  audit_.on_cycle(c);
  transformed_ = ipo::transformed(c, transformed_);
  counter_.add(c);
  const std::size_t n = names_.size();
  // The axis charts show what each machine axis received (the setpoints: the joints under
  // #TRAFO, PCS1 + the belt's travel under conveyor tracking), as the CSV and the audit do.
  for (std::size_t i = 0; i < n; ++i) {
    double* v = values_.data() + kPerAxis * i;
    if (set_ != nullptr) {
      const axes::Setpoint& sp = (*set_)[i];
      v[0] = sp.p;
      v[1] = sp.v;
      v[2] = sp.a;
      v[3] = sp.j;
    } else {
      v[0] = c.x[i];
      v[1] = c.v[i];
      v[2] = c.a[i];
      v[3] = c.j[i];
    }
    v[4] = axes_state_ != nullptr ? axes_state_->following_error[i] : 0.0;
  }
  values_[kPerAxis * n] = c.path.v;
  values_[kPerAxis * n + 1] = c.feed;
  if (conveyor_series_) conveyor_values();
  started_ = true;
  series_.add(c.t, values_);
  // Toolpaths: on a channel that tracks a conveyor the MCS toolpath is the setpoints (the
  // path point is in PCS1 while it is synchronised, and stands during a catch-up or departure)
  // and the path point is the PCS1 toolpath while PCS1 moves or a catch-up drives the axes;
  // elsewhere the path point is the MCS toolpath (the TCP under #TRAFO). Under #TRAFO on a
  // conveyor channel the setpoints are joints: the MCS toolpath is then the TCP (set_tcp()).
  if (conveyor_ != nullptr && set_ != nullptr) {
    const auto& mcs = transformed_ && tcp_ != nullptr ? *tcp_ : *set_;
    ipo::AxisVec p{};
    for (std::size_t i = 0; i < p.size(); ++i)
      p[i] = mcs[i].p;
    add_mcs(p);
    if (conveyor_->driving() || conveyor_->moving_frame()) {
      if (!pcs1_) pcs1_ = std::make_unique<PathThinner>(mcs_.dims(), kPathPoints);
      pcs1_->add(std::span<const double>(c.x.data(), mcs_.dims()));
    }
  } else {
    add_mcs(c.x);
    if (pcs1_ && !pcs1_point_.empty()) pcs1_->add(pcs1_point_);
  }
}

void Recorder::add_mcs(const ipo::AxisVec& axes) {
  mcs_point_.resize(mcs_.dims());
  // Untransformed, a kinematic machine's axes are joints: their TCP.
  ipo::AxisVec tcp{};
  const bool joints = !transformed_ && forward_;
  if (joints && !forward_(axes, tcp)) return;
  const ipo::AxisVec& p = joints ? tcp : axes;
  for (std::size_t i = 0; i < mcs_point_.size(); ++i)
    mcs_point_[i] = p[i];
  mcs_.add(mcs_point_);
}

void Recorder::block_done(const audit::BlockTime& b) {
  ++blocks_;
  if (slowest_.size() == kSlowest && !(b.time > slowest_.back().time)) return;
  // Longest first; an equal time goes after the earlier block (execution order).
  const auto at = std::upper_bound(
      slowest_.begin(), slowest_.end(), b,
      [](const audit::BlockTime& x, const audit::BlockTime& y) { return x.time > y.time; });
  slowest_.insert(at, b);
  if (slowest_.size() > kSlowest) slowest_.pop_back();
}

ReportData Recorder::finish(const RunEnd& end) {
  ReportData d;
  d.time_total = counter_.finish();
  d.program = end.program;
  d.machine = end.machine;
  d.t_cycle = t_cycle_;
  d.axes = names_;
  d.time = series_.finish();
  d.bucket_width = series_.bucket_width();
  d.named = named_;
  d.soft_limits = soft_limits_;
  if (conveyor_ != nullptr) d.workspace = workspace_;
  if (cycles_) {
    d.workpieces = cycles_->finish();
    d.workpiece_rows = std::move(rows_);
  }
  d.path_dims = mcs_.dims();
  d.path_mcs = mcs_.finish();
  d.path_tolerance = mcs_.tolerance();
  if (pcs1_) d.path_pcs1 = pcs1_->finish();
  d.blocks = blocks_;
  d.slowest = slowest_;
  d.verdict = audit_.verdict();
  d.stop = end.stop;
  d.error = end.error;
  d.outcome = !end.error.empty() ? "error" : !end.stop.empty() ? "stopped" : "ok";
  return d;
}

}  // namespace ncsim::report
