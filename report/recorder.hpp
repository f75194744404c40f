#pragma once
// report/recorder: what the HTML run report shows, gathered from the channel loop in one pass
// (docs/report.md).
//
// Purpose: `ncsim report` and `ncsim run --report` run the channel once; this Sink sees every
// joint and cycle and keeps, in bounded memory, what the page plots and lists.
// Inputs: the cycle stream (ipo::Sink: on_joint / on_cycle), the axes' state after each cycle
// (set_axes(): following error), the axis limits and cycle of the channel configuration;
// optionally per cycle the PCS1 tool point and named series (set_pcs1(), set_value()); on a
// channel that tracks a conveyor (set_conveyor()) the conveyor series, read from its
// tracking::ConveyorSync and conveyor::Port each cycle (belt velocity real / measured / filtered,
// current_pos_master, pos_master_comp, synchro_lag, the sync phases; the time per workpiece),
// and its workspace cuboid and pos_limit (set_limits()); at the end the run's outcome
// (finish()).
// Outputs: ReportData: decimated time series (per axis position, v, a, j, following error;
// path velocity and programmed feed; the named series, the conveyor's among them), the thinned
// toolpath in MCS (and PCS1), the workspace cuboid and pos_limit line, the per-workpiece rows,
// the slowest blocks (audit::TimeCounter, the machinery of `time --blocks`), the audit verdict
// (audit::Audit in the same pass), the totals, the stop reason and the run-time error.
// Invariants: memory bounded by the decimation sizes, kSlowest and kWorkpieceRows, never by the
// run length;
// deterministic.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "audit/workpiece_cycles.hpp"
#include "channel/channel.hpp"
#include "ipo/interpolator.hpp"
#include "planner/joint_limits.hpp"
#include "report/decimate.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::report {

/// A named series beside the axes (conveyor: current_pos_master, synchro_lag, ...).
struct NamedSeries {
  std::string name;  ///< column name (docs/report.md "Data contract")
  std::string unit;  ///< e.g. "mm", "mm/s"
};

/// The conveyor's workspace as the toolpath panels draw it (seed 004 §2.1.3, §4.4).
struct WorkspaceView {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();  ///< cuboid in MCS X, Y, Z [mm]
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();  ///< (P-CHAN-00859..00864 or soft limits)
  double pos_limit = 0.0;                           ///< P-CHAN-00374, an MCS X position [mm]
  /// PCS0 +X in MCS is +-MCS X (T0 without rotation in XY/XZ): the Y and Z faces stand still
  /// against the workpiece and are drawn on the PCS1 panels too.
  bool along_x = true;
  int sign = 1;  ///< +1: the belt conveys towards +X (P-CHAN-00363), -1: towards -X
};

/// Everything the page shows.
struct ReportData {
  std::string program;            ///< program file as given
  std::string machine;            ///< machine name
  double t_cycle = 0.0;           ///< [s]
  std::vector<std::string> axes;  ///< interpolated axis names, channel order
  /// Series per axis i at 5 i + {0 position [mm|deg], 1 v [/s], 2 a [/s^2], 3 j [/s^3],
  /// 4 following error [mm|deg]}; then path velocity [mm/s], programmed feed [mm/s]; then the
  /// named series in order.
  Decimated time;
  std::uint64_t bucket_width = 1;  ///< cycles per decimation bucket
  std::vector<NamedSeries> named;  ///< the named series (empty: no conveyor panels)
  /// Per axis the soft position limits P-AXIS-00177 / 00178 [mm | deg] (NaN: not monitored).
  std::vector<std::array<double, 2>> soft_limits;
  std::size_t path_dims = 0;               ///< coordinates per toolpath point (first axes, <= 3)
  std::vector<double> path_mcs;            ///< thinned toolpath in MCS, path_dims per point
  double path_tolerance = 0.0;             ///< thinning tolerance reached [mm]
  std::vector<double> path_pcs1;           ///< thinned toolpath in PCS1 (empty: no conveyor frame)
  std::optional<WorkspaceView> workspace;  ///< only on a channel that tracks a conveyor
  /// Time per workpiece (audit::WorkpieceCycles; only with a conveyor world): the summary of
  /// every row and the first kWorkpieceRows rows.
  std::optional<audit::WorkpieceSummary> workpieces;
  std::vector<audit::WorkpieceCycle> workpiece_rows;
  audit::TimeResult time_total;           ///< cycles, total, distance, split
  std::uint64_t blocks = 0;               ///< block records (time --blocks rows)
  std::vector<audit::BlockTime> slowest;  ///< the kSlowest longest blocks, longest first
  audit::Verdict verdict;                 ///< the audit of the same pass
  std::string outcome = "ok";             ///< "ok", "stopped" (scenario [stop]) or "error"
  std::string stop;                       ///< the scenario's stop reason, if any
  std::string error;                      ///< the run-time / program error text, if any
};

/// The run's end as the caller saw it.
struct RunEnd {
  std::string program;
  std::string machine;
  std::string stop;   ///< scenario stop reason ("" if none)
  std::string error;  ///< error text ("" if none)
};

class Recorder final : public ipo::Sink {
 public:
  static constexpr std::size_t kSlowest = 50;         ///< blocks listed
  static constexpr std::size_t kBuckets = 2000;       ///< time buckets per series
  static constexpr std::size_t kWorkpieceRows = 500;  ///< per-workpiece rows kept (the first)
  /// Toolpath vertices at most: below 4 per pixel of a view's ~380 px plot area, where uPlot's
  /// line builder starts a decimation that assumes x sorted (docs/report.md "Decimation").
  static constexpr std::size_t kPathPoints = 1000;
  /// The conveyor series set_conveyor() appends, in this order (docs/report.md "Conveyor"):
  /// belt velocity real, measured (raw) and filtered [mm/s]; current_pos_master and
  /// pos_master_comp [mm] (null before the first measurement); synchro_lag [mm]
  /// (tracking::tracking_lag: null unless PCS1 moves); then one 0/1 indicator per sync phase (unit
  /// "phase"): waiting, catch_up, synchronised, leaving.
  static constexpr std::array<std::array<const char*, 2>, 10> kConveyorSeries{{
      {"belt_v_actual", "mm/s"},
      {"belt_v_raw", "mm/s"},
      {"belt_v_filtered", "mm/s"},
      {"current_pos_master", "mm"},
      {"pos_master_comp", "mm"},
      {"synchro_lag", "mm"},
      {"phase.waiting", "phase"},
      {"phase.catch_up", "phase"},
      {"phase.synchronised", "phase"},
      {"phase.leaving", "phase"},
  }};

  /// `axes` names and `limits` one per interpolated axis (same order; std::invalid_argument
  /// otherwise), `start` the positions before the first cycle, `named` the extra series.
  Recorder(std::vector<std::string> axes, std::span<const planner::AxisLimits> limits,
           double t_cycle, const ipo::AxisVec& start, std::vector<NamedSeries> named = {});
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// The axes whose following error is recorded (read at each on_cycle); null: zero.
  void set_axes(const channel::AxesState* state) noexcept { axes_state_ = state; }
  /// The setpoints the machine axes received: the recorder's audit checks the axis limits on
  /// them (audit::Audit::set_setpoints).
  void set_setpoints(const std::array<axes::Setpoint, planner::kMaxAxes>* set) noexcept {
    audit_.set_setpoints(set);
    set_ = set;
  }
  /// The belt's share of those setpoints (audit::Audit::set_belt).
  void set_belt(const tracking::BeltOffset* belt) noexcept { audit_.set_belt(belt); }
  /// The TCP in MCS of a cycle under #TRAFO ON (channel::Channel::tcp(); null: none): on a
  /// conveyor channel the MCS toolpath of a transformed cycle (the setpoints are joints there).
  void set_tcp(const std::array<axes::Setpoint, planner::kMaxAxes>* tcp) noexcept { tcp_ = tcp; }
  // The MCS toolpath of a kinematic machine before #TRAFO ON.
  /// The machine's forward transform, axis positions -> the same vector with the TCP's X, Y, Z
  /// [mm] (program::forward_map; false where it does not map): on a machine whose axes are joints,
  /// an untransformed cycle's MCS toolpath point is the joints' TCP, not their angles (empty:
  /// the axes as they are). An unmapped point is left out.
  void set_forward(planner::JointMap forward) { forward_ = std::move(forward); }
  /// The channel's conveyor tracking (null: none): the setpoints are then the MCS toolpath, and
  /// while it moves PCS1 or drives a catch-up the cycle's path point is the PCS1 toolpath. With
  /// a conveyor world attached (sync->port()) the conveyor series kConveyorSeries are appended
  /// to the named series; call before the first cycle (std::logic_error otherwise).
  void set_conveyor(const tracking::ConveyorSync* sync);
  /// The soft position limits of the channel's axes (P-AXIS-00177 / 00178, where enabled),
  /// drawn on the position charts, `config.axes` in the recorder's axis order; and the
  /// conveyor workspace and pos_limit of `config.conveyor` (drawn when set_conveyor() gave one);
  /// the joints' limits under a kinematic transform (`config.path.joints`, on_joints()).
  void set_limits(const channel::ChannelConfig& config);
  /// The PCS1 tool point of the cycle on_cycle() sees next (mm; enables the PCS1 panels).
  void set_pcs1(std::span<const double> p);
  /// Named series `index` (constructor order) for the next cycle; held until set again.
  void set_value(std::size_t index, double value);

  void on_joint(const ipo::Joint& joint) override;
  void on_cycle(const ipo::Cycle& cycle) override;
  /// The joints a cycle under #TRAFO ON gave the machine axes (channel::Channel::joints(), after
  /// the cycle's on_cycle()): the recorder's audit checks them apart, as the CLI's audit does.
  void on_joints(const ipo::Cycle& cycle, const ipo::JointSetpoint& joints) {
    audit_.on_joints(cycle, joints);
  }

  /// The page's data; the recorder is spent afterwards.
  ReportData finish(const RunEnd& end);

 private:
  void block_done(const audit::BlockTime& b);
  void conveyor_values();
  /// Adds the cycle's MCS toolpath point from the axis positions `axes` (set_forward()).
  void add_mcs(const ipo::AxisVec& axes);

  std::vector<std::string> names_;
  std::vector<NamedSeries> named_;
  double t_cycle_;
  audit::Audit audit_;
  audit::TimeCounter counter_;
  MinMaxDecimator series_;
  PathThinner mcs_;
  std::unique_ptr<PathThinner> pcs1_;
  std::vector<double> pcs1_point_;
  const std::array<axes::Setpoint, planner::kMaxAxes>* set_ = nullptr;  ///< set_setpoints()
  const tracking::ConveyorSync* conveyor_ = nullptr;                    ///< set_conveyor()
  const std::array<axes::Setpoint, planner::kMaxAxes>* tcp_ = nullptr;  ///< set_tcp()
  std::vector<double> mcs_point_;  ///< scratch: the MCS tool point of the cycle
  planner::JointMap forward_;      ///< set_forward()
  std::vector<double> values_;     ///< one row of series_
  const channel::AxesState* axes_state_ = nullptr;
  bool transformed_ = false;  ///< the last cycle ran under #TRAFO ON (ipo::transformed)
  std::vector<std::array<double, 2>> soft_limits_;
  std::optional<WorkspaceView> workspace_;          ///< set_limits(), with config.conveyor
  std::size_t conveyor_first_ = 0;                  ///< values_ index of kConveyorSeries[0]
  bool conveyor_series_ = false;                    ///< kConveyorSeries are recorded
  bool started_ = false;                            ///< a cycle was seen
  std::unique_ptr<audit::WorkpieceCycles> cycles_;  ///< with the conveyor series
  std::vector<audit::WorkpieceCycle> rows_;         ///< the first kWorkpieceRows rows
  std::vector<audit::BlockTime> slowest_;           ///< longest first, ties in execution order
  std::uint64_t blocks_ = 0;
};

}  // namespace ncsim::report
