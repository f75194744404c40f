#pragma once
// machines/motion_blocks: the inputs of the PLCopen motion function blocks an NC program calls
// on a machine axis (S1[MC_MoveVelocity ...], S1[MC_TouchProbe ...]).
//
// Purpose: one value type per block, shared by the interpreter that decodes the call
// (interp::MoveVelocity, interp::ProbeArm name these types) and the conveyor world that executes
// it (conveyor::Port), so that neither includes the other.
// Units: mm, s (converted at the program boundary, docs/interp.md "Units").

#include <cstdint>
#include <optional>

namespace ncsim::machines {

/// MC_MoveVelocity Direction (PLCopen MC_Direction): 1 positive, 3 negative, 4 current.
enum class VelocityDirection : std::uint8_t { positive, negative, current };

/// S1[MC_MoveVelocity ...] (PROG-208363915).
struct MoveVelocity {
  std::uint8_t axis = 0;
  double velocity = 0.0;      ///< [mm/s] (program: um/s)
  double acceleration = 0.0;  ///< [mm/s^2]; 0: axis list value
  double deceleration = 0.0;  ///< [mm/s^2]; 0: axis list value
  double jerk = 0.0;          ///< [mm/s^3]; 0: axis list value
  VelocityDirection direction = VelocityDirection::positive;
};

/// MC_TouchProbe Mode: 1 falling, 2 rising edge (PROG-306968203).
enum class ProbeEdge : std::uint8_t { falling, rising };

/// S1[MC_TouchProbe ...] (PROG-306968203): arms the latch.
struct ProbeArm {
  std::uint8_t axis = 0;
  int channel = 1;                ///< Channel (the probe input)
  std::optional<ProbeEdge> edge;  ///< Mode; nullopt: the axis list's P-AXIS-00518
};

}  // namespace ncsim::machines
