#pragma once
// cli/line_world: what `ncsim sweep`, `ncsim tune-delay` and the accuracy benchmark change in
// the conveyor world and watch in the channel (docs/conveyor.md "The line's limits offline").
//
// Purpose: one place for the belt velocity override and the workspace margin.
// Inputs: the loaded machine and scenario (before the world is built), the channel after each
// cycle. Outputs: the changed machine / scenario, a Port decorator, the margin.
// Belt velocity (decision): a spindle belt (the program's S1[MC_MoveVelocity]) keeps the
// program's commands but every Velocity > 0 becomes the candidate (direction, dynamics kept;
// CONV_VEL is the caller's: runner::RunSpec::conv_vel);
// an encoder belt has its scenario velocity at t = 0 and every profile velocity scaled by
// candidate / velocity at t = 0 (fluctuation, noise, dead time unchanged: relative).
// Workspace margin: while synchronised, the distance of the commanded TCP (the setpoints of
// X/Y/Z; under #TRAFO ON the channel's TCP, Channel::tcp()) to the conveyor workspace's faces in
// the conveying direction (the faces whose outward normal is within 60 deg of it, as
// tracking/workspace classifies them); the smallest over the run.
// Invariants: pure functions and small value objects; never throw (except make_unique).

#include <cstdint>
#include <memory>
#include <optional>

#include "channel/channel.hpp"
#include "conveyor/port.hpp"
#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::cli {

/// How set_belt_velocity found the world.
struct BeltSetting {
  bool conveyor = false;      ///< the machine has a conveyor axis and conveyor tracking
  bool encoder = false;       ///< the scenario moves the belt (encoder mode)
  bool encoder_zero = false;  ///< encoder mode with velocity 0 at t = 0: not scalable
};

/// Sets the belt velocity to `v` [mm/s] in an encoder scenario (scaled); the spindle belt is
/// overridden by override_belt().
BeltSetting set_belt_velocity(const machines::Machine& machine,
                              std::optional<scenario::Scenario>& scenario, double v) noexcept;

/// An encoder belt's velocity and every profile velocity scaled so that its velocity at t = 0 is
/// `v` [mm/s] (fluctuation, noise, dead time relative); false (unchanged) when it is 0 there.
bool scale_encoder_belt(scenario::Conveyor& conveyor, double v) noexcept;

/// `port` with every MC_MoveVelocity Velocity > 0 replaced by `v` [mm/s].
std::unique_ptr<conveyor::Port> override_belt(std::unique_ptr<conveyor::Port> port, double v);

/// The smallest distance to the workspace's conveying face while synchronised.
struct WorkspaceMargin {
  bool valid = false;      ///< a synchronised cycle was seen
  double distance = 0.0;   ///< [mm] (< 0: beyond the face)
  double t = 0.0;          ///< [s] the cycle's end
  std::uint32_t line = 0;  ///< the cycle's source line
};

class WorkspaceWatch {
 public:
  /// Takes the workspace and the conveying direction of `machine` (none: no margin).
  void configure(const machines::Machine& machine) noexcept;
  /// One cycle of `channel`.
  void on_cycle(const channel::Channel& channel) noexcept;
  const WorkspaceMargin& margin() const noexcept { return margin_; }

 private:
  std::optional<machines::Workspace> box_;
  WorkspaceMargin margin_;
};

}  // namespace ncsim::cli
