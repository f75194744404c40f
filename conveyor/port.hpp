#pragma once
// conveyor/port: what the channel loop asks of the conveyor each cycle (issue 14).
//
// Purpose: the one seam between the channel loop (channel/, #SYNC IN/OUT, the PCS1 frame, the
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
#include <utility>
#include <vector>

#include "machines/machine.hpp"
#include "machines/motion_blocks.hpp"

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

/// What the world knows about the latch take_latch() handed out last (conveyor-world,
/// docs/conveyor.md "The world"): the workpiece it belongs to, the V.E. values the PLC side
/// writes for it, and the truth the measured value approximates.
struct LatchInfo {
  std::uint64_t workpiece = 0;  ///< 1-based number in order of arrival at the sensor; 0: none
  double position = 0.0;        ///< [mm] the latched value (what take_latch() returned)
  double true_position = 0.0;   ///< [mm] the real conveyor position when the front edge passed
  double sensor_x = 0.0;        ///< [mm] MCS X of the real sensor (scenario, else P-CHAN-00368)
  std::vector<std::pair<std::string, double>> ve;  ///< V.E. NAME (upper case), value
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
  /// Returns false when not taken: in encoder mode, where the scenario moves the belt, and for
  /// a velocity above the axis's P-AXIS-00212; error() then says why (NC9006, NC9005).
  virtual bool command_velocity(const machines::MoveVelocity& command) noexcept = 0;
  /// S1[MC_TouchProbe ...]: arms the latch. A retrigger while armed is P-ERR-44009 (error()).
  virtual void arm_probe(const machines::ProbeArm& command) noexcept = 0;
  /// The oldest latched front edge not yet taken, as a conveyor position [mm] (the measured
  /// value #SYNC IN waits for), and removes it; nullopt while none is latched.
  virtual std::optional<double> take_latch() noexcept = 0;
  /// The reduced actual-value filter (P-AXIS-00625, then P-AXIS-00624) on or off: by the
  /// scenario's MCV_SetReducedFilter and by a conveyor feed hold.
  virtual void set_reduced_filter(bool on) noexcept = 0;

  /// The error raised by the world, if any (the channel stops with it).
  virtual const std::optional<PortError>& error() const noexcept = 0;

  /// `#MACHINE DATA` on the conveyor axis's conv_sync.* (P-AXIS-00620..00626): the filters
  /// restart from the current measured value with the new orders, the delay time applies
  /// from the next step(). Returns false when this Port does not support it (the default).
  virtual bool set_axis_params(const machines::ConveyorAxisParams& params) noexcept {
    (void)params;
    return false;
  }

  /// The latch take_latch() returned last (workpiece 0 before the first; a test double
  /// without workpieces may keep this default).
  virtual const LatchInfo& last_latch() const noexcept {
    static const LatchInfo kNone;
    return kNone;
  }
};

}  // namespace ncsim::conveyor
