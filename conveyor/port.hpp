#pragma once
// conveyor/port: what the channel loop asks of the conveyor each cycle (issue 14).
//
// Purpose: the one seam between the channel loop (ipo/, #SYNC IN/OUT, the PCS1 frame, the
// catch-up, workspace monitoring) and the conveyor world (conveyor/: the belt from the scenario
// or driven by MC_MoveVelocity, the encoder with noise and dead time, the touch-probe latch and
// its queue, the actual-value filters and the delay-time compensation of seed 004 §2.1.4/2.1.5).
// The channel owns a Port (made by conveyor/, or a test double) and calls it once per cycle.
// Inputs: the channel's commands (MC_MoveVelocity, MC_TouchProbe, the reduced filter), the
// cycle's end time. Outputs: the belt as the NC sees it (master(): filtered and delay-
// compensated: this moves PCS1), the real belt (actual(): for the contour error on the moving
// workpiece), the latched front edges, errors with the manual's ids.
// Units: mm, mm/s, mm/s^2, s, positions of the conveying axis (the belt's travel).
// Invariants: deterministic (noise seeded); step() never throws; memory bounded by the
// workpieces on the belt between the sensor and the tool (the probe queue), never by run time.

#include <cstdint>
#include <optional>
#include <string>

#include "interp/command.hpp"

namespace ncsim::conveyor {

/// Position, velocity and acceleration of the conveying axis.
struct BeltState {
  double p = 0.0;  ///< [mm]
  double v = 0.0;  ///< [mm/s]
  double a = 0.0;  ///< [mm/s^2]
};

/// A run-time error of the conveyor (the channel stops with it, positioned at its block).
struct PortError {
  std::string id;       ///< the manual's id (P-ERR-44009, ...) or ncsim's (NC90xx)
  std::string message;  ///< what happened, with the values
};

class Port {
 public:
  virtual ~Port() = default;

  /// Advances the world to the end of the cycle that ends at `t` [s] (called once per cycle,
  /// t increasing by the cycle time). Never throws; an error is kept for error().
  virtual void step(double t) noexcept = 0;

  /// The belt as it really moves at the last step() (no noise, no dead time).
  virtual const BeltState& actual() const noexcept = 0;
  /// The conveying axis's measured value as the NC reads it (noise, dead time), unfiltered:
  /// current_pos_master / current_v_master / current_a_master before the PCS offset.
  virtual const BeltState& measured() const noexcept = 0;
  /// What the PCS1 frame follows: the filtered measured value (P-AXIS-00620..00625) plus the
  /// delay-time compensation (P-AXIS-00626: filtered velocity x delay time); pos_master_comp,
  /// v_master_comp, a_master_comp.
  virtual const BeltState& master() const noexcept = 0;

  /// S1[MC_MoveVelocity ...] on the conveying axis (spindle mode): the belt ramps to the new
  /// velocity with the command's (or the axis list's) dynamics from the next step() on.
  /// Ignored (returns false) in encoder mode, where the scenario moves the belt.
  virtual bool command_velocity(const interp::MoveVelocity& command) noexcept = 0;
  /// S1[MC_TouchProbe ...]: arms the latch. A retrigger while armed is P-ERR-44009 (error()).
  virtual void arm_probe(const interp::ProbeArm& command) noexcept = 0;
  /// The oldest latched front edge not yet taken, as a conveyor position [mm] (the measured
  /// value #SYNC IN waits for), and removes it; nullopt while none is latched.
  virtual std::optional<double> take_latch() noexcept = 0;
  /// The reduced actual-value filter (P-AXIS-00625, then P-AXIS-00624) on or off: by the
  /// scenario's MCV_SetReducedFilter and by a conveyor feed hold.
  virtual void set_reduced_filter(bool on) noexcept = 0;

  /// The error raised by the world, if any (the channel stops with it).
  virtual const std::optional<PortError>& error() const noexcept = 0;
};

}  // namespace ncsim::conveyor
