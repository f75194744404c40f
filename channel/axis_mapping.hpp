#pragma once
// channel/axis_mapping: the path point of a cycle -> the machine axes' setpoints (step "the
// mapping" of Channel::step; docs/ipo.md "The channel loop").
//
// Purpose: identity outside #TRAFO (the path is planned in machine axis values, MCS); where a
// catch-up / departure left the path it stands until its next block moves; the catch-up /
// departure drive the axes; the conveyor's moving PCS1 frame adds the belt's offset (p, v, a).
// Under #TRAFO ON the KinematicStage maps the TCP (with the frame and the catch-up acting on it)
// to the joints. Publishes the belt's share of the setpoints (belt(): Channel::belt_share()).
// Inputs: the cycle; the channel's KinematicStage, ConveyorTracking (the hold), ConveyorSync and
// AxisStage, bound at construction. Outputs: the AxisStage's setpoints, belt(); NC3201 (the
// kinematic's) raised into the channel's error.
// Invariants: noexcept; no allocation per cycle.

#include <optional>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/conveyor_tracking.hpp"
#include "channel/kinematic_stage.hpp"
#include "tracking/belt_offset.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::channel {

class AxisMapping {
 public:
  /// The references are the channel's own parts and must outlive this one; `t_cycle` [s].
  AxisMapping(KinematicStage& kin, ConveyorTracking& tracking,
              const std::optional<tracking::ConveyorSync>& sync, AxisStage& axes,
              std::optional<RunTimeError>& error, double t_cycle) noexcept
      : kin_(kin),
        tracking_(tracking),
        sync_(sync),
        axes_(axes),
        error_(error),
        t_cycle_(t_cycle) {}
  AxisMapping(const AxisMapping&) = delete;
  AxisMapping& operator=(const AxisMapping&) = delete;

  /// Each axis's share of one mm of belt travel (fixed by T0: set once, with a ConveyorSync).
  void set_shares() noexcept;
  /// Cycle `c`'s setpoints into the AxisStage; false when it raised a run-time error (NC3201).
  bool map(const ipo::Cycle& c) noexcept;
  /// The belt's share of the setpoints in the last cycle mapped.
  const tracking::BeltOffset& belt() const noexcept { return belt_; }

 private:
  KinematicStage& kin_;
  ConveyorTracking& tracking_;
  const std::optional<tracking::ConveyorSync>& sync_;
  AxisStage& axes_;
  std::optional<RunTimeError>& error_;
  double t_cycle_;             ///< [s]
  tracking::BeltOffset belt_;  ///< the belt's share of the setpoints
};

}  // namespace ncsim::channel
