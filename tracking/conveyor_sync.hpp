#pragma once
// tracking/conveyor_sync: the channel's conveyor tracking, #SYNC IN to #SYNC OUT (seed 004 §2.1,
// §3; docs/conveyor.md "Synchronisation").
//
// Purpose: the state the channel keeps while it tracks a conveyor, apart from the channel loop
// so that it can be tested against a test-double conveyor::Port.
// Inputs: the channel's conveyor_sync parameters, one SyncAxis per interpolated axis (its
// X/Y/Z slot and PTP dynamics), the Port (attach()), the program's SyncIn / SyncOut, the axes'
// command states when the catch-up starts, the cycle times.
// Outputs: per cycle the MCS offset of every interpolated axis (position, velocity,
// acceleration of the PCS1 frame against PCS0), the catch-up setpoints, the phase (waiting for
// the measured value, catching up, synchronised), errors with the manual's ids.
// Phases: off -> (sync_in) waiting: the path stands until the Port has a latch, "waiting for
// measured value" -> (a latch) latched: the frame moves, the next G00/G01 is the catch-up ->
// (start_catch_up) catching_up -> (profile ended) tracking: PCS1 blocks run on the moving
// frame -> (sync_out) off, the axes keep the belt's velocity until the next motion.
// Invariants: step() never throws; the offset is continuous (it is the master travel, which
// the Port makes continuous) except at a new latch, where it restarts at the master travel
// since that latch (the frame is re-based while the path stands).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "axes/profile.hpp"
#include "conveyor/port.hpp"
#include "interp/command.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "tracking/catch_up.hpp"
#include "tracking/sync_checks.hpp"
#include "tracking/sync_frame.hpp"
#include "tracking/sync_phase.hpp"
#include "tracking/workspace.hpp"
#include "tracking/workspace_hold.hpp"

namespace ncsim::tracking {

/// One interpolated axis as conveyor tracking sees it.
struct SyncAxis {
  std::string name;         ///< axis name (messages)
  int xyz = -1;             ///< 0, 1, 2: the axis is X, Y, Z (its share of the belt); -1: none
  axes::Dynamics dynamics;  ///< PTP dynamics of the catch-up (V, A+, A-, J)
};

class ConveyorSync {
 public:
  /// Throws std::invalid_argument when an axis's dynamics are not usable (value named).
  ConveyorSync(const machines::ConveyorSyncChannel& channel, std::span<const SyncAxis> axes,
               double t_cycle);

  /// The conveyor world (null: none; then #SYNC IN is not supported). Must outlive this.
  void attach(conveyor::Port* port) noexcept { port_ = port; }
  conveyor::Port* port() const noexcept { return port_; }

  /// #SYNC IN: from now the path waits for the measured value. Error 50587 when CONV_VEL puts
  /// more than an axis's V on it (a rotated T0; X is the interpreter's check); not with
  /// `joints` (#TRAFO ON: the axes are joints, their V no velocity along the belt; the belt's
  /// share of them is NC6211 per block, docs/conveyor.md "50587").
  std::optional<SyncError> sync_in(const interp::SyncIn& command, bool joints = false);
  /// #SYNC OUT: back to MCS. The axes keep moving with the belt until the next motion, which
  /// leaves from that moving state (start_departure). Before the catch-up ran (no motion
  /// between #SYNC IN and #SYNC OUT) nothing moved with the belt: straight back to off.
  void sync_out(const interp::SyncOut& command) noexcept;
  /// Starts the desynchronisation movement: every axis from its moving command state `start`
  /// to the fixed MCS point `target`, at rest, all axes together (FEED_CONT 0); also from off
  /// (a #SYNC OUT before any catch-up: the first motion after it is still a PTP).
  axes::Result start_departure(std::span<const axes::MotionState> start,
                               std::span<const double> target,
                               std::span<const axes::Dynamics> dynamics = {}) noexcept;

  /// Once per cycle, before the path: steps the Port to `t` [s] (end of the cycle), takes a
  /// latch while waiting, checks 50653 while synchronised and passes the Port's error on with its
  /// own id. A second call for the same (or an earlier) t does nothing.
  std::optional<SyncError> step(double t) noexcept;

  /// Starts the catch-up at the end of the cycle just done: `start` the command state of every
  /// interpolated axis (MCS), `target` the programmed point in MCS at belt travel 0 (T0
  /// applied: the ProgramSource's Move end), `feed_cont` the relative velocity [mm/s] along
  /// catch_up_direction(), --- sync-feed: reduced to the largest one the axes can meet the
  /// target with ("reduced as required", 004 l.284) when no plan exists for it.
  /// `dynamics` (one per axis, or empty: the axes' own) replaces the axes' PTP
  /// dynamics (under #TRAFO ON the TCP's, tracking/trafo_sync); a catch-up not stepped yet may be
  /// started again (re-planned with other dynamics).
  axes::Result start_catch_up(std::span<const axes::MotionState> start,
                              std::span<const double> target, double feed_cont,
                              std::span<const axes::Dynamics> dynamics = {}) noexcept;
  // FEED_CONT > 0 / FEED_CONT_AUTO (docs/conveyor.md S-1, tracking/sync_entry.hpp)
  /// The relative velocity #SYNC IN asked for [mm/s]: FEED_CONT, +inf for FEED_CONT_AUTO, 0
  /// without either.
  double feed_cont_wanted() const noexcept { return feed_cont_; }
  /// FEED_CONT's direction for a catch-up from `start` to `target` (start_catch_up's
  /// arguments): the unit vector over the X/Y/Z axes from the start to where the target is now
  /// (0 on the other axes; all 0 when they coincide).
  planner::AxisVec catch_up_direction(std::span<const axes::MotionState> start,
                                      std::span<const double> target) const noexcept;
  /// The relative velocity the running catch-up meets its target with [mm/s] (start_catch_up's
  /// `feed_cont` as reduced there).
  double v_relative() const noexcept { return v_relative_; }
  /// A catch-up that meets its target moving (v_relative() > 0) hands over to the path inside
  /// the next cycle: the time from that cycle's start to the meeting [s], in [0, T); none
  /// otherwise (a catch-up at rest relative to the target rides along until the cycle after).
  std::optional<double> handover_lag() const noexcept;
  /// The setpoint of axis i in the cycle step() prepared (catching_up and departing only).
  axes::Setpoint catch_up_setpoint(std::size_t i) const noexcept;
  const CatchUp& catch_up() const noexcept { return catch_up_; }

  /// True while the channel drives the axes from the catch-up or departure profile.
  bool driving() const noexcept {
    return phase_ == SyncPhase::catching_up || phase_ == SyncPhase::departing;
  }
  /// True while the path's point is in PCS1 and shifted by offset() (tracking, leaving). Before
  /// the catch-up the path still stands at its MCS point.
  bool moving_frame() const noexcept {
    return phase_ == SyncPhase::tracking || phase_ == SyncPhase::leaving;
  }
  /// The PCS1 offset of axis i in MCS in the current cycle (0 off the conveyor's X/Y/Z share).
  double offset(std::size_t i) const noexcept { return share_[i] * s_; }
  /// Axis i's share of one mm of travel along the conveying direction (MCS).
  double share(std::size_t i) const noexcept { return share_[i]; }
  /// True while the axes move with the belt: the catch-up, PCS1 and after #SYNC OUT until the
  /// departure starts (the audit's belt share, audit/audit.hpp).
  bool following() const noexcept { return phase_ == SyncPhase::catching_up || moving_frame(); }
  /// The velocity of offset(i) at the cycle's end [mm/s]: the frame's velocity (v_frame_), the
  /// axes' velocity feed-forward; not the master's reported velocity (docs/conveyor.md F-8).
  double offset_v(std::size_t i) const noexcept { return share_[i] * v_frame_; }
  double offset_a(std::size_t i) const noexcept { return share_[i] * a_; }  ///< [mm/s^2]

  SyncPhase phase() const noexcept { return phase_; }
  double conv_vel() const noexcept { return conv_vel_; }  ///< CONV_VEL [mm/s] --- static-saw
  /// Within P-CHAN-00365 of the target since the catch-up (docs/conveyor.md).
  bool synchronised() const noexcept { return synchronised_; }
  const SyncFrame& frame() const noexcept { return frame_; }
  double travel() const noexcept { return s_; }             ///< master travel since the latch [mm]
  double belt_velocity() const noexcept { return v_; }      ///< along PCS0 X [mm/s] (--- trafo)
  double belt_acceleration() const noexcept { return a_; }  ///< along PCS0 X [mm/s^2]
  /// Time spent waiting for the measured value so far [s].
  double waited() const noexcept { return waited_; }
  /// The workspace (004 §2.1.3, §4.4) for the commanded TCP `p_mcs` [mm], only while
  /// synchronised: the conveying face NC9052, a side face NC9053, the face against the
  /// conveying direction or the hold line + P-CHAN-00367 NC9080 (docs/conveyor.md "Workspace").
  std::optional<SyncError> workspace(const Eigen::Vector3d& p_mcs) const;
  // The hold methods against the conveying direction (tracking/workspace_hold.hpp)
  /// The path velocity cap for the next cycle [mm/s] (+inf: none): while tracking and
  /// synchronised, the hold decision on `st` (path, s, v, a, feed, line, d, j of the cycle
  /// just done; travel, belt velocity and cycle time are filled in here).
  double workspace_cap(HoldState st) noexcept;
  /// The hold (none when no face is against the conveying direction or no axis is on it).
  const WorkspaceHold* hold() const noexcept { return hold_ ? &*hold_ : nullptr; }
  /// The display variables of the current cycle.
  MasterDisplay display() const noexcept;
  std::size_t axis_count() const noexcept { return n_; }
  /// The PTP dynamics of axis i (V [mm/s | deg/s], A+, A-, J).
  const axes::Dynamics& dynamics(std::size_t i) const noexcept { return axes_[i].dynamics; }
  /// 0, 1, 2: interpolated axis i is X, Y, Z; -1: none.
  int xyz(std::size_t i) const noexcept { return axes_[i].xyz; }

 private:
  SyncFrame frame_;
  machines::Workspace box_;
  double tolerance_ = 0.0;  ///< P-CHAN-00365 [mm]
  double reserve_ = 0.0;    ///< NCSIM-CHAN-640 [fraction] (--- conveyor)
  double t_cycle_ = 0.0;
  std::array<SyncAxis, planner::kMaxAxes> axes_{};
  std::array<double, planner::kMaxAxes> share_{};  ///< conveying component per axis
  std::size_t n_ = 0;
  conveyor::Port* port_ = nullptr;
  SyncPhase phase_ = SyncPhase::off;
  bool synchronised_ = false;
  double conv_vel_ = 0.0;               ///< CONV_VEL [mm/s]
  double s_ = 0.0, v_ = 0.0, a_ = 0.0;  ///< master travel, velocity, acceleration along PCS0 X
  /// The master position's slope over the last cycle along PCS0 X [mm/s]: the catch-up's
  /// forecast. It differs from v_ (the filtered velocity) while a delay-compensated belt
  /// accelerates (F-5: p = filtered p + filtered v x delay time).
  double v_slope_ = 0.0;
  /// The PCS1 frame's velocity at the cycle's end along PCS0 X [mm/s]: v_slope_ + a_ T / 2, the
  /// velocity the master position moves at (F-5 moves it at filtered v + filtered a x delay
  /// time, and the position filter's slope is not the velocity filter's); exact for a master
  /// position of constant acceleration a_. What offset_v() and the catch-up's setpoints carry,
  /// so the axes' velocity is the derivative of their position (docs/conveyor.md F-8, issue 36
  /// items 7 and 8; 004 l.422-428).
  double v_frame_ = 0.0;
  double p_last_ = 0.0;  ///< the master position of the last step() [mm] (stepped_t_ >= 0)
  double waited_ = 0.0;
  CatchUp catch_up_;
  double t_catch_ = 0.0;  ///< time since the catch-up started [s] (the prepared cycle's end)
  std::array<axes::Setpoint, planner::kMaxAxes> catch_sp_{};
  std::optional<WorkspaceHold> hold_;  ///< --- workspace
  double feed_cont_ = 0.0;             ///< --- sync-feed: feed_cont_wanted() [mm/s]
  double v_relative_ = 0.0;            ///< --- sync-feed: v_relative() [mm/s]
  /// The moving hand-over is due in the cycle being prepared.
  bool handover_due() const noexcept {
    return phase_ == SyncPhase::catching_up && v_relative_ > 0.0 &&
           t_catch_ + t_cycle_ > catch_up_.duration();
  }
  double stepped_t_ = -1.0;  ///< --- workspace: the last step()'s t [s]
};

}  // namespace ncsim::tracking
