#pragma once
// channel/channel: the channel loop, one interpolation cycle T per Channel::step() (issue 12).
//
// Purpose: what the kernel's channel does each cycle after decoding: the path interpolator
// gives the commanded path point; the point is mapped to machine axis setpoints; every axis
// goes through the PTP axis core's position-control model (axes/control) giving its actual
// position and following error; the monitors (axes/monitor) watch every axis; G60 / G360
// exact stops wait for the actual positions. `ncsim run` and `ncsim time` both step it.
// Inputs: a Source of program items (program::ProgramSource for a program), the ChannelConfig
// (the interpolator's Config plus one ChannelAxis per interpolated axis: position control
// P-AXIS-00099 / NCSIM-AXIS-023, monitors P-AXIS-00177/00178, NCSIM-AXIS-024..026, exact stop
// P-AXIS-00236 / P-AXIS-00532), an optional Sink.
// Outputs: step() returns running / finished / error; cycle() is the path record of the cycle
// (its `x` is the axes' command position), axes() the command, actual position and following
// error of every axis; run_time_error() says why the channel stopped (docs/ipo.md "The
// channel loop").
// The channel is made of owned parts, each with its own file in channel/ (channel/README.md);
// per cycle (Channel::step, Channel::program_cycle), in this order:
//   - the after-error stop (AfterErrorStop): while the machine moves on after a run-time error
//     raised synchronised, the cycle is its own (the steps below do not run);
//   - the scenario's cycle (ScenarioPlay, before the path: actions, [stop] conditions);
//   - a blocked channel event and the events of a ChannelWait the path holds at (ChannelEvents,
//     one dispatch by kind; the parts execute them through an EventContext; NC6001
//     `not supported` for a kind no part executes);
//   - the static unit's override (ConveyorTracking);
//   - the path interpolator's step (PathInterpolator::step; block starts go to the scenario);
//     at its end the events left, and the cycles go on while INDP axes still move;
//   - the scenario's checks on the cycle (an action's error, a path held forever);
//   - the events riding on the blocks started in the cycle (ChannelEvents);
//   - the conveyor world's cycle and the V.E. values of a latch (ConveyorTracking);
//   - the mapping of the path point to machine axis setpoints (AxisMapping: identity plus the
//     conveyor's moving PCS1 frame / the catch-up, or under #TRAFO ON the KinematicStage);
//   - the conveyor workspace and the workspace hold (ConveyorTracking);
//   - the start of an exact stop (ExactStopWait) when the command reached a G60 / G360 block end;
//   - the INDP axes (IndpStage): an axis they own gets its INDP setpoint;
//   - every axis driven (AxisStage: soft limits, position control, monitors);
//   - the exact-stop check on actual positions (release, P-ERR-70082, NC6101);
//   - the Sink sees the cycle, only when no run-time error was raised in it: a stopped run's
//     stream ends with the last good cycle;
//   - a run-time error raised in the cycle goes to the after-error stop, which keeps the
//     synchronisation (the cycles go on until the machine stands) or lets the run end with it.
// Invariants: step() never throws (an error ends the stream with Status::error); it is
// deterministic (encoder noise is seeded per axis); memory is the interpolator's (bounded by
// the look-ahead window) plus one control model and one monitor per axis.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "axes/control.hpp"
#include "axes/monitor.hpp"
#include "channel/after_error.hpp"
#include "channel/axis_mapping.hpp"
#include "channel/axis_stage.hpp"
#include "channel/channel_events.hpp"
#include "channel/channel_types.hpp"
#include "channel/conveyor_tracking.hpp"
#include "channel/exact_stop.hpp"
#include "channel/indp_axes.hpp"
#include "channel/indp_stage.hpp"
#include "channel/kinematic_stage.hpp"
#include "channel/scenario_play.hpp"
#include "ipo/interpolator.hpp"
#include "ipo/joint_stage.hpp"
#include "machines/machine.hpp"
#include "program/channel_event.hpp"
#include "program/signals.hpp"
#include "scenario/player.hpp"
#include "tracking/belt_offset.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::channel {

struct ChannelConfig {
  ipo::Config path;                   ///< the interpolator's (detail and hold_exact_stop are set)
  std::vector<ChannelAxis> axes;      ///< one per entry of path.axes, same order
  double exact_stop_wait_max = 60.0;  ///< [s] longest exact-stop wait without P-AXIS-00532
  double measured_value_wait_max = 600.0;  ///< [s] longest #SYNC IN wait for a measured value
  // conveyor tracking (docs/conveyor.md "Synchronisation")
  std::optional<machines::ConveyorSyncChannel> conveyor;  ///< FCT_DLM channels only
  std::vector<tracking::SyncAxis> sync_axes;  ///< one per entry of path.axes (with `conveyor`)
  /// The conveyor axis's conv_sync.* as loaded: what `#MACHINE DATA` changes at run time
  /// (program/machine_data.hpp); set with `conveyor` when the machine has a conveyor axis.
  std::optional<machines::ConveyorAxisParams> conveyor_axis;
  /// the forward transform of the machine's kinematic (program::forward_map; empty
  /// without one): synchro_lag under #TRAFO ON (Channel::master_display, tracking::cycle_lag).
  planner::JointMap forward;
  /// The run's signal exchange for #SIGNAL SYN / #WAIT SYN and the #WAITs the decoder could
  /// not answer at once (docs/lines.md); null: none (such an event is NC6001). Must outlive the
  /// channel.
  program::SignalPort* signals = nullptr;
};

/// The channel configuration of `machine` (docs/ipo.md "The channel loop"): the interpolator
/// Config of machine_config() and, per interpolated axis, the axis core's position control and
/// monitor parameters through axes/axis_config (the one machine -> axes adapter).
ChannelConfig channel_config(const machines::Machine& machine, double t_cycle);

class Channel {
 public:
  /// Throws std::invalid_argument (value and parameter named) on an unusable configuration
  /// (the interpolator's checks, the control model's Kv * T <= 1, the monitors'). `source`
  /// must outlive the channel; `sink` may be null.
  Channel(ChannelConfig config, ipo::Source& source, ipo::Sink* sink = nullptr);
  Channel(const Channel&) = delete;
  Channel& operator=(const Channel&) = delete;

  /// One interpolation cycle. Never throws. Status::error: the source failed (message()) or
  /// a run-time error stopped the channel (run_time_error()).
  ipo::Status step() noexcept;
  /// The path record of the last cycle step() reported (INDP axes: their setpoints).
  const ipo::Cycle& cycle() const noexcept { return shown_ ? *shown_ : ipo_.cycle(); }
  /// Command, actual position and following error of every axis after the last cycle.
  const AxesState& axes() const noexcept { return axes_.state(); }
  /// Why the channel stopped at run time, if it did.
  const std::optional<RunTimeError>& run_time_error() const noexcept { return error_; }
  /// the first joint overrun while synchronised under #TRAFO ON (warning NC6210,
  /// tracking/trafo_sync.hpp); the run goes on (004 l.609: the joint dynamics are not ensured).
  const std::optional<RunTimeError>& trafo_warning() const noexcept { return kin_.warning(); }
  /// The interpolator's message when the source failed.
  const std::string& message() const noexcept { return ipo_.message(); }
  double t_cycle() const noexcept { return ipo_.t_cycle(); }  ///< [s]
  std::size_t axis_count() const noexcept { return axes_.size(); }

  /// Plays `player`'s scenario from the next cycle on (ScenarioPlay); null: none. `player` must
  /// outlive the channel. The ProgramSource's barriers read player->ve() (the caller wires it:
  /// ProgramSource::answer_barriers_from).
  void play(scenario::Player* player) noexcept { play_.attach(player); }
  /// The [stop] condition that ended the run, if one did (step() then returned finished).
  const std::optional<scenario::StopReason>& scenario_stop() const noexcept {
    return play_.stop_reason();
  }

  // kinematics (channel/kinematic_stage.hpp, docs/ipo.md "Kinematics in run and time")
  /// The last cycle ran under #TRAFO ON: cycle().x is the TCP, the axes got joints().
  bool transformed() const noexcept { return kin_.transformed(); }
  /// The joint setpoints of the last transformed cycle (machine axes in interpolated order).
  const ipo::JointSetpoint& joints() const noexcept { return kin_.joints(); }
  /// The TCP setpoint of the last transformed cycle, in MCS (X, Y, Z first; the PCS1 offset
  /// and the catch-up included): what the joints() were computed from [mm, mm/s, ...].
  const std::array<axes::Setpoint, planner::kMaxAxes>& tcp() const noexcept { return kin_.tcp(); }
  /// ChannelConfig::forward (joints -> TCP; empty without a kinematic).
  const planner::JointMap& forward() const noexcept { return kin_.forward(); }
  /// The setpoint (p, v, a, j) every axis received in the last cycle [mm | deg, /s ...].
  const std::array<axes::Setpoint, planner::kMaxAxes>& setpoints() const noexcept {
    return axes_.setpoints();
  }
  /// the belt's share of setpoints() in the last cycle (Audit::set_belt()).
  const tracking::BeltOffset& belt_share() const noexcept { return mapping_.belt(); }
  // conveyor tracking (docs/conveyor.md "Synchronisation")
  /// The conveyor world the channel steps every cycle and tracks between #SYNC IN and
  /// #SYNC OUT (null: none; #SYNC IN is then NC6001 `not supported`). Must outlive the channel.
  /// Ignored on a channel without conveyor tracking (no FCT_DLM).
  void attach_conveyor(conveyor::Port* port) noexcept {
    port_ = port;
    if (sync_) sync_->attach(port);
  }
  /// The channel's conveyor tracking state; null without FCT_DLM.
  const tracking::ConveyorSync* conveyor_sync() const noexcept { return sync_ ? &*sync_ : nullptr; }
  // the display variables of seed 004 §6 with synchro_lag (tracking/synchro_lag.hpp) of
  // the last cycle; all 0 without FCT_DLM (channel/channel_lag.cpp).
  tracking::MasterDisplay master_display() const noexcept;
  // independent axes (channel/indp_stage.hpp, docs/ipo.md "INDP axes and technology
  // functions"). Conveyor tracking takes an INTERRUPTIBLE INDP_SYN motion over, moving, when
  // the catch-up after the next #SYNC IN starts (IndpAxes::hand_over, docs/conveyor.md S-4).
  IndpAxes& indp() noexcept { return indp_.axes(); }
  const IndpAxes& indp() const noexcept { return indp_.axes(); }
  /// The technology functions (M/H/S/T/D) the channel output in the last step(), in program
  /// order (`run` writes them as CSV comments; docs/ipo.md "INDP axes and technology functions").
  const std::vector<TechOutput>& tech_outputs() const noexcept { return indp_.tech_outputs(); }
  // an error while synchronised keeps the synchronisation (seed 004 §2.3,
  // channel/after_error.hpp, docs/conveyor.md "Errors while synchronised"): the run goes on until
  // the machine stands, then ends with that error.
  /// What the machine did after such an error (empty: none): the following, the stop, why.
  std::string after_error_note() const { return after_.note(); }

 private:
  /// One cycle of the program, the cycle's parts in order (see the header); Status::error when
  /// one raised a run-time error.
  ipo::Status program_cycle() noexcept;
  /// A cycle after the path's end while INDP axes still move (the program end waits for them).
  ipo::Status indp_tail() noexcept;
  /// Drives every axis (AxisStage::drive with the exact stop's and the INDP axes' flags);
  /// false when one raised a run-time error.
  bool drive_axes(const ipo::Cycle& c) noexcept;

  KinematicStage kin_;  ///< #TRAFO ON: the joint stage (declared before ipo_: its relay)
  ipo::PathInterpolator ipo_;
  ipo::Sink* sink_ = nullptr;
  AxisStage axes_;
  ExactStopWait exact_stop_;
  std::optional<RunTimeError> error_;
  std::optional<ipo::Status> ended_;            ///< the interpolator's stream ended so
  std::optional<tracking::ConveyorSync> sync_;  ///< with FCT_DLM only
  conveyor::Port* port_ = nullptr;              ///< the attached conveyor world (reduced filter)
  IndpStage indp_;                              ///< INDP axes and technology outputs
  const ipo::Cycle* shown_ =
      nullptr;              ///< the cycle shown instead of the path's (INDP, after error)
  std::size_t driven_ = 0;  ///< axes driven in the cycle being computed
  ScenarioPlay play_{ipo_, indp_, axes_};  ///< the scenario, before each cycle
  /// The stop after an error while synchronised (declared before tracking_: its limits).
  AfterErrorStop after_;
  ConveyorTracking tracking_;  ///< the channel's side of conveyor tracking
  AxisMapping mapping_;        ///< the path point -> the axes' setpoints
  ChannelEvents events_;       ///< the events due, their dispatch (the interpolator's WaitHandler)
};

}  // namespace ncsim::channel
