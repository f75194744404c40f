#pragma once
// conveyor/shared_port: one conveyor world shared by the channels of a line (docs/lines.md
// "The shared world").
//
// Purpose: every channel of a line attaches its own SharedPort; all of them lead to one world,
// stepped once per cycle: the first channel that steps in a cycle moves the world to the
// cycle's end, the others find it there (the same t). The line steps it itself when no channel
// did (no channel tracks the conveyor) through step_once(). Everything else goes to the world
// unchanged: the belt, the latches (the channels share one queue of measured values: which
// channel takes which workpiece is issue 37's next step), the commands.
// Inputs: the world (must outlive every SharedPort). Outputs: the world's, per channel.
// Invariants: the world sees step(t) once per t, t increasing; noexcept as Port.

#include <optional>

#include "conveyor/port.hpp"

namespace ncsim::conveyor {

/// The world and the last time it was stepped to, shared by the line's SharedPorts.
class SharedWorld {
 public:
  explicit SharedWorld(Port& world) noexcept : world_(world) {}
  /// Steps the world to `t` unless it is there already.
  void step_once(double t) noexcept {
    if (stepped_ && *stepped_ >= t) return;
    stepped_ = t;
    world_.step(t);
  }
  Port& world() noexcept { return world_; }

 private:
  Port& world_;
  std::optional<double> stepped_;  ///< [s] the last step's t
};

class SharedPort final : public Port {
 public:
  explicit SharedPort(SharedWorld& shared) noexcept : shared_(shared), w_(shared.world()) {}
  void step(double t) noexcept override { shared_.step_once(t); }
  const BeltState& actual() const noexcept override { return w_.actual(); }
  const BeltState& measured() const noexcept override { return w_.measured(); }
  const BeltState& master() const noexcept override { return w_.master(); }
  bool command_velocity(const machines::MoveVelocity& command) noexcept override {
    return w_.command_velocity(command);
  }
  void arm_probe(const machines::ProbeArm& command) noexcept override { w_.arm_probe(command); }
  std::optional<double> take_latch() noexcept override { return w_.take_latch(); }
  void set_reduced_filter(bool on) noexcept override { w_.set_reduced_filter(on); }
  const std::optional<PortError>& error() const noexcept override { return w_.error(); }
  bool set_axis_params(const machines::ConveyorAxisParams& params) noexcept override {
    return w_.set_axis_params(params);
  }
  const LatchInfo& last_latch() const noexcept override { return w_.last_latch(); }

 private:
  SharedWorld& shared_;
  Port& w_;
};

}  // namespace ncsim::conveyor
