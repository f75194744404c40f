#pragma once
// channel/conveyor_tracking: conveyor tracking in the channel (issue 14; docs/conveyor.md
// "Synchronisation", "Workspace: the hold methods", "Static processing unit").
//
// Purpose: the channel's side of ConveyorSync: the conveyor events (#SYNC IN waiting for the
// measured value, the catch-up / departure PTP as a Motion event, #SYNC OUT, MC_TouchProbe,
// MC_MoveVelocity, #MACHINE DATA of the filters; channel_conveyor.cpp), the moving hand-over of
// FEED_CONT > 0 / FEED_CONT_AUTO (channel_sync_entry.cpp), per cycle the conveyor world's step
// with the V.E. values of a latch, the conveyor workspace and the workspace hold with its belt
// cap (channel_workspace.cpp) and the static unit's override (channel_static.cpp).
// Inputs: the ChannelConfig's measured-value wait; the channel's ConveyorSync and the parts it
// acts on (the interpolator, the axes, the INDP axes, the kinematic stage), bound at
// construction. Outputs: EventOutcome per event; the interpolator's velocity cap and override;
// hold() where the path stands after a catch-up / departure; run-time errors (NC9054, NC9060,
// NC9061, NC9081, the workspace's, the Port's) through raise(); V.E. values into the player's
// store.
// Invariants: noexcept; no allocation per cycle.

#include <cstdint>
#include <optional>
#include <span>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/event_context.hpp"
#include "channel/indp_stage.hpp"
#include "channel/kinematic_stage.hpp"
#include "ipo/interpolator.hpp"
#include "scenario/player.hpp"
#include "tracking/conveyor_sync.hpp"
#include "tracking/sync_entry.hpp"
#include "tracking/sync_error.hpp"

namespace ncsim::channel {

class ConveyorTracking {
 public:
  /// The references are the channel's own parts and must outlive this one. Throws
  /// std::invalid_argument unless `measured_value_wait_max` [s] > 0.
  ConveyorTracking(std::optional<tracking::ConveyorSync>& sync, ipo::PathInterpolator& ipo,
                   AxisStage& axes, IndpStage& indp, KinematicStage& kin,
                   const tracking::SyncErrorStop& after, std::optional<RunTimeError>& error,
                   ipo::Sink* sink, double measured_value_wait_max,
                   std::optional<machines::ConveyorAxisParams> conveyor_axis);
  ConveyorTracking(const ConveyorTracking&) = delete;
  ConveyorTracking& operator=(const ConveyorTracking&) = delete;

  /// A static processing unit (P-CHAN-00364 x_virtual).
  bool static_unit() const noexcept { return static_unit_; }
  void set_static_unit(bool on) noexcept { static_unit_ = on; }
  /// The channel moves with the conveyor (catch-up or PCS1 tracking).
  bool tracking() const noexcept {
    return sync_ && (sync_->phase() == tracking::SyncPhase::catching_up ||
                     sync_->phase() == tracking::SyncPhase::tracking);
  }
  /// Where the path stands after a catch-up / departure until its next block moves.
  std::optional<planner::AxisVec>& hold() noexcept { return sync_hold_; }

  // The conveyor events (channel_conveyor.cpp, channel_sync_entry.cpp).
  EventOutcome on_sync_in(const interp::SyncIn& command, const program::ChannelEvent& e) noexcept;
  EventOutcome on_sync_out(const interp::SyncOut& command, const program::ChannelEvent& e) noexcept;
  /// The catch-up after #SYNC IN / the departure after #SYNC OUT (ProgramSource::sync_motion).
  EventOutcome on_sync_motion(const interp::Motion& motion,
                              const program::ChannelEvent& e) noexcept;
  EventOutcome on_probe_arm(const interp::ProbeArm& command,
                            const program::ChannelEvent& e) noexcept;
  EventOutcome on_move_velocity(const interp::MoveVelocity& command,
                                const program::ChannelEvent& e) noexcept;
  /// `#MACHINE DATA` on the conveyor axis's filters and delay time (program/machine_data.hpp):
  /// passed to the Port with the path standing (isg-language.md §5.10).
  EventOutcome on_machine_data(const interp::MachineData& command,
                               const program::ChannelEvent& e) noexcept;

  // Per cycle (channel_workspace.cpp, channel_static.cpp); each does nothing without a
  // ConveyorSync.
  /// A synchronised static unit: the path override is the belt's master velocity over the
  /// planned kXvPlanFactor * CONV_VEL, so the virtual X follows the belt; the operator's
  /// override is restored after #SYNC OUT.
  void static_override() noexcept;
  /// The conveyor world's cycle at cycle `c` (latch, 50653, the Port's errors), and the V.E.
  /// values of a workpiece just measured into `player`'s store (null: none), where the next
  /// barrier reads them (docs/conveyor.md "Wiring"). False: a run-time error raised.
  bool world_step(const ipo::Cycle& c, scenario::Player* player) noexcept;
  /// After the mapping: the conveyor workspace on the cycle's MCS setpoints while synchronised,
  /// then the hold against the conveying direction (its path velocity cap for the next cycle).
  /// False: a run-time error raised (the workspace's, NC9081).
  bool workspace(const ipo::Cycle& c) noexcept;
  /// The hold caps the path at 0 (the belt stands): the tool waits for the belt, not for the
  /// operator (no NC6301).
  bool hold_waits() const noexcept;

 private:
  /// The conveyor workspace on the cycle's MCS setpoints while synchronised; false: stopped.
  bool check_workspace(const ipo::Cycle& c) noexcept;
  /// Gives the interpolator the hold's path velocity cap; false: NC9081 (the belt stood under
  /// the hold longer than ncsim's wait limit).
  bool workspace_cap(const ipo::Cycle& c) noexcept;
  /// The relative velocity the catch-up from `start` to `target` meets its target with: the
  /// #SYNC IN's, reduced to what the path's first block allows (tracking/sync_entry); 0: at rest.
  double sync_entry_velocity(std::span<const axes::MotionState> start,
                             std::span<const double> target) noexcept;
  /// The catch-up meets its target `lag` [s] into this cycle: the path starts there, moving.
  EventOutcome sync_hand_over(double lag, const program::ChannelEvent& e) noexcept;
  /// After a command the Port took (MC_TouchProbe, MC_MoveVelocity): a refusal it raised
  /// (P-ERR-44009 retrigger, 44001, 44011, 44012 of seed 004 §6.3.1; NC9003; NC9005 above the
  /// conveyor axis's P-AXIS-00212) is that block's error, at its line and cycle, not the next
  /// cycle's step's at the block after it.
  EventOutcome port_outcome(const program::ChannelEvent& e) noexcept;
  /// Lowers the hold's cap where a belt slower than CONV_VEL would take an axis of a block
  /// planned against the belt (v_max + CONV_VEL) above its v_max.
  void sync_belt_cap(const ipo::Cycle& c) noexcept;
  double t_cycle() const noexcept { return ipo_.t_cycle(); }  ///< [s]

  std::optional<tracking::ConveyorSync>& sync_;
  ipo::PathInterpolator& ipo_;
  AxisStage& axes_;
  IndpStage& indp_;
  KinematicStage& kin_;
  const tracking::SyncErrorStop& after_;  ///< the axes' limits (v_max) of the after-error stop
  std::optional<RunTimeError>& error_;
  ipo::Sink* sink_;
  double measured_value_wait_max_;             ///< ChannelConfig::measured_value_wait_max [s]
  std::uint64_t measure_wait_cycles_max_ = 0;  ///< the same in cycles
  std::uint64_t measure_waited_ = 0;           ///< cycles #SYNC IN waited so far
  std::uint32_t sync_tag_ = 0;                 ///< the event being executed
  std::optional<planner::AxisVec> sync_hold_;  ///< see hold()
  tracking::SyncEntry sync_entry_{};           ///< the hand-over decided at the catch-up's start
  planner::AxisVec sync_u_{};                  ///< the catch-up's direction (FEED_CONT's) [1]
  std::optional<machines::ConveyorAxisParams> conveyor_axis_;  ///< as changed so far
  bool static_unit_ = false;                                   ///< P-CHAN-00364 x_virtual
  std::optional<double> operator_override_;  ///< the override before the static unit took it
  std::uint64_t hold_stood_ = 0;             ///< cycles the belt stood under the hold
  std::uint64_t ve_workpiece_ = 0;  ///< the measured workpiece whose V.E. values were written
};

}  // namespace ncsim::channel
