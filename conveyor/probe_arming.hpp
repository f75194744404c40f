#pragma once
// conveyor/probe_arming: the checks of an MC_TouchProbe arming, shared by the world of one
// channel (conveyor/world) and the stations of a line (conveyor/line_world): seed 004 §6.3.1 (a
// measurement is not retriggerable, the active one stays) and the sensor's wiring (it latches
// the conveyor axis through one probing input, P-AXIS-00517).

#include <cstdint>
#include <optional>
#include <string>

#include "conveyor/port.hpp"
#include "machines/motion_blocks.hpp"

namespace ncsim::conveyor {

inline constexpr const char* kProbeInputId = "NC9002";   ///< another probing input than wired
inline constexpr const char* kNoWorkpieceId = "NC9003";  ///< no workpiece left to reach the sensor
inline constexpr const char* kNotConveyorId = "NC9004";  ///< a probe on another axis

/// An active measurement.
struct ProbeArming {
  std::uint8_t axis = 0;
  int channel = 1;
  bool rising = true;
};

/// The error of arming `c` for the edge `rising` while `active` is armed (empty: none), on a
/// sensor that latches the conveyor axis `axis` (named `axis_name`) through probing input
/// `input`; empty when it arms.
std::optional<PortError> probe_arm_error(const machines::ProbeArm& c, bool rising,
                                         const std::optional<ProbeArming>& active,
                                         std::uint8_t axis, const std::string& axis_name,
                                         int input);

}  // namespace ncsim::conveyor
