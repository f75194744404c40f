#pragma once
// conveyor/shared_port: a channel's Port in a line (docs/lines.md "The shared world").
//
// Purpose: the channel owns its Port (runner::Loaded::port); in a line the Port it talks to is
// its station of the line's conveyor::LineWorld, which the line owns. SharedPort forwards every
// call to that station unchanged (the station steps the one belt once per cycle, whichever
// channel steps first).
// Inputs: the station (must outlive the SharedPort). Outputs: the station's, for the channel.
// Invariants: noexcept as Port; no state of its own.

#include <optional>

#include "conveyor/port.hpp"

namespace ncsim::conveyor {

class SharedPort final : public Port {
 public:
  explicit SharedPort(Port& station) noexcept : w_(station) {}
  void step(double t) noexcept override { w_.step(t); }
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
  Port& w_;
};

}  // namespace ncsim::conveyor
