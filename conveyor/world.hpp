#pragma once
// conveyor/world: the conveyor world behind conveyor::Port (issue 14; docs/conveyor.md "The
// world"): the real belt (scenario encoder belt or MC_MoveVelocity spindle), the encoder
// (dead time through a bounded delay line, seeded noise), the actual-value filters and the
// delay-time compensation (seed 004 §2.1.4, §2.1.5), the sensor and the touch probe with the
// three measuring methods of §4.3 (P-AXIS-00516) and the PLC-side queue.
//
// Inputs: the machine (its conveyor axis and conveyor_sync channel parameters), the scenario's
// [conveyor] (may be absent: a spindle belt without workpieces), the cycle time; per cycle the
// channel's commands and step(t).
// Outputs: Port's belt states and latches; errors with the manual's ids (P-ERR-44001, 44009,
// 44011, 44012) or ncsim's (NC9001..NC9049, docs/diagnostics.md).
// Invariants: deterministic for the same inputs (noise seeded); step() and the commands never
// throw; memory fixed at construction (filters of their orders) plus the MC_MoveVelocity
// commands of the last dead time and the PLC queue (bounded by the scenario's sensor.queue);
// the first error sticks. The dead time is exact: the measured value is a second belt that
// replays the real one (its profile, and each command at its time) a dead time later.

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "conveyor/belt.hpp"
#include "conveyor/filter.hpp"
#include "conveyor/noise.hpp"
#include "conveyor/port.hpp"
#include "conveyor/probe_arming.hpp"
#include "conveyor/sensor.hpp"
#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor {

/// The measuring methods of seed 004 §4.3, told apart by kenngr.measure.signal P-AXIS-00516.
enum class MeasuringMethod {
  drive = 1,        ///< DRIVE_TYPE_DEFAULT, DRIVE, blank: the drive latches the position
  plc_trigger = 2,  ///< PLC, PLC_FIRST_EVENT, PLC_TIMESTAMP: PLC trigger, drive position
  plc_queue = 3,    ///< PLC_EXT_LATCH_CONTROL: the PLC keeps and hands out measured values
};

/// The method of a P-AXIS-00516 value; throws std::invalid_argument (naming P-AXIS-00516) for
/// a value no conveyor method uses (FIXED_STOP, EXT_PROBE_WITH_DRIVE, anything else).
MeasuringMethod measuring_method(std::string_view measure_signal);

class World final : public Port {
 public:
  /// Throws std::invalid_argument naming the parameter for settings it cannot run (see
  /// make_port).
  World(const machines::Machine& machine, const scenario::Scenario* scenario, double t_cycle);
  World(const World&) = delete;  // the sensor points into this world's copy of the scenario
  World& operator=(const World&) = delete;

  void step(double t) noexcept override;
  const BeltState& actual() const noexcept override { return belt_.state(); }
  const BeltState& measured() const noexcept override { return measured_; }
  const BeltState& master() const noexcept override { return master_; }
  bool command_velocity(const machines::MoveVelocity& command) noexcept override;
  void arm_probe(const machines::ProbeArm& command) noexcept override;
  std::optional<double> take_latch() noexcept override;
  void set_reduced_filter(bool on) noexcept override { filter_.set_reduced(on); }
  const std::optional<PortError>& error() const noexcept override { return error_; }
  const LatchInfo& last_latch() const noexcept override { return last_; }
  bool set_axis_params(const machines::ConveyorAxisParams& params) noexcept override;

  /// The measuring method in use (P-AXIS-00516).
  MeasuringMethod method() const noexcept { return method_; }
  /// The filtered measured value before the delay-time compensation (p_f, v_f, a_f).
  const BeltState& filtered() const noexcept { return filter_.state(); }
  /// Workpieces whose front edge passed while the probe was not armed (methods 1, 2: not
  /// measured; method 3 keeps them in the PLC queue instead).
  std::uint64_t missed() const noexcept { return missed_; }
  /// Measured values waiting in the PLC queue (method 3).
  std::size_t queued() const noexcept { return plc_queue_.size(); }
  /// True while a latch is armed and has not seen its edge.
  bool armed() const noexcept { return armed_.has_value(); }

 private:
  struct Command {  // an MC_MoveVelocity the delayed belt has not reached yet
    double t = 0.0;
    double v = 0.0;
    VelocityDynamics dynamics;
  };
  BeltState delayed(double t) noexcept;
  void raise(const char* id, std::string message) noexcept;
  LatchInfo latch(const Edge& edge, double value) const;
  void present_from_queue() noexcept;

  const machines::AxisParams* axis_ = nullptr;
  std::uint8_t axis_index_ = 0;
  double t_cycle_;
  bool encoder_;
  MeasuringMethod method_;
  int probe_input_;          // P-AXIS-00517
  bool default_rising_;      // P-AXIS-00518
  double sign_ = 1.0;        // P-CHAN-00363
  double dead_time_ = 0.0;   // [s]
  double delay_time_ = 0.0;  // P-AXIS-00626 [s]
  double sigma_ = 0.0;       // [mm]
  double sensor_x_ = 0.0;    // [mm]
  std::size_t queue_capacity_ = 16;
  bool camera_ = false;
  std::optional<scenario::Conveyor> conveyor_;  // a copy: the port outlives no scenario
  Belt belt_;
  Sensor sensor_;
  ActualValueFilter filter_;
  Gaussian noise_;
  Gaussian latch_noise_;
  Belt delayed_belt_;             // the same belt a dead time behind (exact, closed form)
  std::deque<Command> commands_;  // commands within the last dead time (bounded by it)
  double t_ = 0.0;
  BeltState measured_;
  BeltState master_;
  std::optional<ProbeArming> armed_;
  std::deque<LatchInfo> pending_;    // latched, not yet taken (bounded by queue_capacity_)
  std::deque<LatchInfo> plc_queue_;  // method 3 (bounded by queue_capacity_)
  LatchInfo last_;
  std::uint64_t missed_ = 0;
  std::optional<PortError> error_;
};

/// The conveyor world of `machine` for `scenario` (may be null) at cycle time t_cycle [s].
/// Throws std::invalid_argument naming the parameter: no conveyor axis (P-AXIS-00708), a
/// scenario mode the axis mode contradicts (P-AXIS-00015), P-AXIS-00516 no method uses,
/// P-AXIS-00518 not POS/NEG, t_cycle not > 0.
std::unique_ptr<Port> make_port(const machines::Machine& machine,
                                const scenario::Scenario* scenario, double t_cycle);

}  // namespace ncsim::conveyor
