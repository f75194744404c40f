#pragma once
// channel/after_error: the channel after a run-time error raised while synchronised (seed 004
// §2.3 l.492-498; tracking/sync_error.hpp; docs/conveyor.md "Errors while synchronised").
//
// Purpose: the one after-error state machine of the channel. The manual keeps the
// synchronisation after an error: the path velocity in PCS1 goes to 0 (the channel's feed hold),
// the machine moves on with the belt until it must brake before its limit, and a belt the PLC
// stops stops the machine with it. When the program's cycle raised an error, enter() decides
// whether it keeps the synchronisation; if so the error is held back, the cycle is completed and
// every later cycle is step()'s, until the machine stands; the run then ends with the original
// error (its id, line and time) and note() says what the machine did.
// States: idle -> following (the belt followed, the path braking) -> braking (the stop's ramps)
// -> ended (the machine stood, or a limit or the kinematic's reach ended the run); idle ->
// dropped (the error's own cycle would pass a soft limit: the run ends as always, no note).
// Cases, chosen at the error: `axes` (the axes follow the belt; a SyncErrorStop on them brakes
// them before their soft limits or above their v_max); `tcp` under #TRAFO ON (a SyncErrorStop on
// the TCP's X, Y, Z with the conveyor workspace's faces as limits, tracking/sync_error_trafo;
// the joints come from the TCP and are watched against their V and soft limits). INDP axes owned
// at the error brake on their own ramps beside the `axes` case (after_error_indp.cpp).
// Inputs: the axes' after-error limits and the workspace box (configure()); the channel's parts
// it acts on, bound at construction. Outputs: the setpoints of the cycles after the error, the
// shown cycle, the sink's cycles, the channel's error at the end, note().
// Invariants: noexcept per cycle; once a run; no monitors after the error (the channel is in its
// error state): only the soft limits are kept, no axis gets a set position beyond them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "channel/axis_mapping.hpp"
#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/conveyor_tracking.hpp"
#include "channel/indp_stage.hpp"
#include "channel/kinematic_stage.hpp"
#include "channel/scenario_play.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "tracking/conveyor_sync.hpp"
#include "tracking/sync_error.hpp"

namespace ncsim::channel {

class AfterErrorStop {
 public:
  enum class State : std::uint8_t {
    idle,       ///< no error kept the synchronisation (yet)
    following,  ///< the machine follows the belt, the path brakes by feed hold
    braking,    ///< the axes (or the TCP) brake on the stop's ramps
    ended,      ///< the run ended with the error held back
    dropped,    ///< the error's own cycle would pass a soft limit: the run ended with it at once
  };

  /// The references are the channel's own parts and must outlive this one; `shown` is the
  /// channel's shown cycle, `sink` may be null.
  AfterErrorStop(ipo::PathInterpolator& ipo, AxisStage& axes, KinematicStage& kin, IndpStage& indp,
                 AxisMapping& mapping, ScenarioPlay& play, const ConveyorTracking& tracking,
                 std::optional<tracking::ConveyorSync>& sync, std::optional<RunTimeError>& error,
                 const ipo::Cycle*& shown, ipo::Sink* sink) noexcept;
  AfterErrorStop(const AfterErrorStop&) = delete;
  AfterErrorStop& operator=(const AfterErrorStop&) = delete;

  /// With a conveyor: the axes' limits (interpolated order) and the conveyor workspace the TCP
  /// brakes before (P-CHAN-00859..00864 [mm]); `t_cycle` [s]. Without it no error keeps the
  /// synchronisation.
  void configure(std::span<const tracking::AfterErrorAxis> axes, const machines::Workspace& box,
                 double t_cycle) noexcept;
  /// The axes' stop (ConveyorTracking reads its limits' v_max).
  const tracking::SyncErrorStop& axes_stop() const noexcept { return axes_stop_; }
  State state() const noexcept { return state_; }
  /// The machine moves on after the error: the channel's cycles are step()'s.
  bool active() const noexcept { return state_ == State::following || state_ == State::braking; }

  /// The program's cycle raised the channel's error: keeps the synchronisation if the error
  /// may and completes the cycle (`own_cycle`: the interpolator advanced in it, its first
  /// `driven` axes were driven), else Status::error (the run ends with it as always).
  ipo::Status enter(bool own_cycle, std::size_t driven) noexcept;
  /// One cycle after the error (active()): the path brakes, the machine follows the belt or
  /// brakes; Status::error when a limit ended the run, else running.
  ipo::Status step() noexcept { return cycle(true, 0); }
  /// What the machine did after the error (empty: none): the following, the stop, why.
  std::string note() const;

 private:
  enum class Case : std::uint8_t { axes, tcp };

  /// The error keeps the synchronisation (once a run): held back, the path brakes by feed hold.
  bool keep() noexcept;
  /// One cycle: `fresh` a new one (else the error's own cycle is completed from axis `first`).
  ipo::Status cycle(bool fresh, std::size_t first) noexcept;
  /// The cycle shown after the error: the interpolator's, or at rest after its end.
  const ipo::Cycle& next_cycle(bool fresh) noexcept;
  /// The stop's part of cycle `c`: the setpoints followed or braked; `end` when the machine
  /// stands. False: the TCP left the kinematic's reach.
  bool stop_cycle(const ipo::Cycle& c, bool& end) noexcept;
  /// The first axis from `first` whose setpoint is beyond its soft limit ends the run.
  bool beyond_soft_limit(const ipo::Cycle& c, bool fresh, std::size_t first) noexcept;
  /// The run ends with the error held back; the machine stood at `t` [s].
  void finish(double t) noexcept;
  std::string axes_note() const;

  // the `tcp` case (after_error_trafo.cpp)
  /// The TCP's stop under #TRAFO ON; false: not built or the TCP beyond the workspace already.
  bool begin_tcp() noexcept;
  std::string tcp_note() const;

  // INDP axes owned at the error (after_error_indp.cpp)
  /// Stops the owned INDP axes; false: not built (INDP axes under #TRAFO ON), the run ends.
  bool begin_indp() noexcept;
  /// Steps the INDP axes once for cycle `c` (unless IndpStage::step() did) and applies them.
  void step_indp(const ipo::Cycle& c) noexcept;
  /// Their setpoints into the AxisStage and the shown cycle (after the stop wrote all axes).
  void apply_indp() noexcept;
  /// What the stop decides on: the axes' setpoints with the INDP axes at rest, or the TCP.
  std::array<axes::Setpoint, planner::kMaxAxes> seen() const noexcept;
  /// Every INDP axis braked at the error stands.
  bool indp_stood() const noexcept;
  std::string indp_note() const;

  ipo::PathInterpolator& ipo_;
  AxisStage& axes_;
  KinematicStage& kin_;
  IndpStage& indp_;
  AxisMapping& mapping_;
  ScenarioPlay& play_;
  const ConveyorTracking& tracking_;
  std::optional<tracking::ConveyorSync>& sync_;
  std::optional<RunTimeError>& error_;
  const ipo::Cycle*& shown_;
  ipo::Sink* sink_;

  State state_ = State::idle;
  Case case_ = Case::axes;
  std::optional<RunTimeError> held_;   ///< the error held back while the machine moves
  tracking::SyncErrorStop axes_stop_;  ///< the axes' stop (the joints' watch under #TRAFO ON)
  tracking::SyncErrorStop tcp_stop_;   ///< the TCP's stop (X, Y, Z: the workspace box)
  machines::Workspace box_;            ///< P-CHAN-00859..00864 [mm]
  ipo::Cycle cycle_;                   ///< the cycle shown after the error
  bool path_ended_ = false;            ///< the interpolator gave its last cycle
  double end_t_ = 0.0;                 ///< [s] the machine stood
  std::string passed_;                 ///< a limit passed after all (the note says it)
  int joint_ = -1;  ///< the joint whose limit decided the TCP's stop (-1: the TCP's)
  tracking::AfterErrorEnd joint_why_ = tracking::AfterErrorEnd::soft_limit;  ///< why for that joint
  planner::AxisMask indp_mask_ = 0;  ///< the INDP axes owned at the error
};

}  // namespace ncsim::channel
