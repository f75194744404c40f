#pragma once
// channel/channel_types: the values the channel and its parts share: one axis as configured
// (ChannelAxis), the axes after a cycle (AxesState), a run-time error (RunTimeError, raise()),
// a technology output (TechOutput) and the channel's own error ids.
// Invariants: value types only; raise() never throws (it aborts when out of memory).

#include <cstdint>
#include <optional>
#include <string>

#include "axes/control.hpp"
#include "axes/monitor.hpp"
#include "channel/indp_axes.hpp"
#include "interp/command.hpp"
#include "ipo/interpolator.hpp"

namespace ncsim::channel {

/// NC6101: the exact-stop window P-AXIS-00236 was not reached within
/// ChannelConfig::exact_stop_wait_max while P-AXIS-00532 does not monitor the time.
inline constexpr const char* kExactStopWaitId = "NC6101";

/// NC6102: a scenario's path override is above the largest the channel's override type
/// (NCSIM-CHAN-630) accepts.
inline constexpr const char* kOverrideRangeId = "NC6102";

/// NC6301: the path stands by feed hold or override 0 and nothing in the scenario can release
/// it (the run would never end).
inline constexpr const char* kHeldForeverId = "NC6301";

/// NC9081: the belt stood while the workspace hold kept the tool at the hold line for longer
/// than ChannelConfig::measured_value_wait_max (the belt was not restarted).
inline constexpr const char* kHoldBeltStoodId = "NC9081";

/// NC9054: #SYNC IN waited longer than ChannelConfig::measured_value_wait_max for its measured
/// value (no workpiece edge latched).
inline constexpr const char* kMeasuredValueWaitId = "NC9054";
/// NC9060: #SYNC IN FEED_CONT > 0 / FEED_CONT_AUTO on a static processing unit
/// (x_virtual): its feed follows the belt (004 l.438); docs/conveyor.md S-1.
inline constexpr const char* kStaticFeedContId = "NC9060";
/// NC9061: #MACHINE DATA of the conveyor's filters or delay time while the channel tracks the
/// belt (catch-up or PCS1): the filters' restart would step the frame under the tool
/// (docs/conveyor.md F-7).
inline constexpr const char* kFilterWhileTrackingId = "NC9061";
/// NC6103: the path programs an axis while its INDP motion runs or away from where it left it.
inline constexpr const char* kIndpPathId = "NC6103";
/// NC6105: a scenario axis override names no channel axis or is outside 0 .. 100 %.
inline constexpr const char* kIndpOverrideId = "NC6105";

/// A technology function the channel output (M/H/S/T/D, to the PLC side).
struct TechOutput {
  double t = 0.0;          ///< [s] end of the cycle in which it was output
  std::uint32_t line = 0;  ///< source line
  std::uint16_t file = 0;  ///< interp::Command::file (0: the main program)
  interp::TechKind kind = interp::TechKind::m;
  double value = 0.0;           ///< the function's number (M3 -> 3)
  std::optional<double> extra;  ///< M/H additional value (M200=1200 -> 1200)
};

/// One interpolated axis as the channel drives it.
struct ChannelAxis {
  std::string name;                     ///< axis name (messages)
  axes::PositionControlParams control;  ///< position control model (axes/control.hpp)
  axes::AxisMonitorParams monitor;      ///< soft limits, lag, exact stop, ...
  IndpAxisConfig indp;                  ///< the axis as an INDP axis (channel/indp_axes.hpp)
  // G74 (channel/homing.hpp, docs/homing.md)
  double reference_position = 0.0;  ///< P-AXIS-00152 pos_refpkt [mm | deg]
  double homing_velocity = 83.333;  ///< P-AXIS-00219 vb_refmax [mm/s | deg/s]
};

/// A run-time error: the channel stopped as the kernel would (the axes and the path compound).
struct RunTimeError {
  std::string id;          ///< the manual's id (P-ERR-70082, 0x4550) or ncsim's (NC5501, NC6101)
  std::string message;     ///< what happened, with the value and the limit
  std::uint32_t line = 0;  ///< source line of the active block
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main program)
  double t = 0.0;          ///< [s] end of the cycle that raised it
  int axis = -1;           ///< interpolated axis index
};

/// The axes after a cycle.
struct AxesState {
  planner::AxisVec command{};          ///< set positions [mm | deg] (the mapped path point)
  planner::AxisVec actual{};           ///< measured actual positions [mm | deg]
  planner::AxisVec following_error{};  ///< set - actual [mm | deg] (000 7.1.5)
};

/// Records the run-time error `id` with `message` at cycle `c`'s line, file and time into
/// `error` (`axis`: the interpolated axis, -1: none). Never throws.
void raise(std::optional<RunTimeError>& error, const char* id, std::string message,
           const ipo::Cycle& c, int axis) noexcept;

}  // namespace ncsim::channel
