#pragma once
// ipo/cycle: what the path interpolator gives per interpolation cycle.
//
// Purpose: the record of one cycle (Cycle), of a joint passed within it (Joint), and the Sink
// that receives both; the step() result (Status) and how much a cycle computes (Detail).
// Inputs: none (types only).
// Outputs: the types above.
// Invariants: Cycle::index counts the cycles done and Cycle::t = index * T; Cycle::event_tag
// never decreases; a Sink sees the joints of a cycle before the cycle itself.

#include <cstdint>

#include "planner/lookahead.hpp"
#include "planner/move.hpp"

namespace ncsim::ipo {

using planner::AxisVec;

/// How much each cycle computes.
enum class Detail : std::uint8_t {
  path,  ///< path state and line only (`ncsim time`): no point, no axis values, no joints
  axes,  ///< also the point, each axis's v, a, j, and the joints (run, audit)
};

/// What the channel did in a cycle.
enum class Activity : std::uint8_t {
  motion,      ///< the path moved (or reached its end) in this cycle
  dwell,       ///< G04 dwell
  exact_stop,  ///< G60 / G360: waiting for the window and the settling time
  starved,     ///< the source gave nothing that moves (zero-length blocks only)
  channel,     ///< the path stands at a ChannelWait until the channel releases it
  tech,        ///< waiting for a technology function's acknowledgement (Dwell::tech)
};

/// The cycle just done.
struct Cycle {
  std::uint64_t index = 0;  ///< cycles done so far, this one included
  double t = 0.0;           ///< time at the end of this cycle [s] (index * T)
  std::uint32_t line = 0;   ///< source line of the active block
  std::uint16_t file = 0;   ///< source file of `line` (interp::Command::file, 0: main program)
  Activity activity = Activity::motion;
  bool rapid = false;                 ///< the active block is G00
  bool jerk_limited = true;           ///< the active block's slope is TRAPEZ / SIN2 / HSC
  bool interval_jerk_limited = true;  ///< every segment traversed in this cycle is jerk-limited
  double feed = 0.0;                  ///< programmed path velocity of the active segment [mm/s]
  /// The axes' velocity cap of the active segment when it is below `feed` (F capped:
  /// planner::PathLimits::feed_capped) [mm/s]; 0 when the axes allow F.
  double feed_cap = 0.0;
  planner::PathState path;                    ///< s (from the segment start), v, a, j of the path
  double distance = 0.0;                      ///< path length covered in this cycle [mm]
  AxisVec x{};                                ///< axis positions [mm | deg] (Detail::axes)
  AxisVec v{};                                ///< axis velocities, closed form [mm/s]
  AxisVec a{};                                ///< axis accelerations, closed form [mm/s^2]
  AxisVec j{};                                ///< axis jerks, closed form [mm/s^3]
  const planner::Move* programmed = nullptr;  ///< the block x belongs to (motion cycles)
  /// Override and feed hold (issue 13, docs/ipo.md "Override and feed hold"):
  bool held = false;    ///< motion cycle in which the path stands by feed hold / override 0
  double factor = 1.0;  ///< override factor of the plan the path follows (0 while holding)
  double lost = 0.0;    ///< time lost to override and holds in this cycle [s] (< 0: gained)
  /// Channel events up to this tag are due: the largest event_tag of the blocks and dwells
  /// started so far and of the waits reached (never decreases).
  std::uint32_t event_tag = 0;
  /// Set by channel::Channel (docs/ipo.md "INDP axes and technology functions"): bit i: axis i is
  /// driven by its INDP motion in this cycle; x, v, a, j are then the INDP setpoint's, and the
  /// axis is not part of the block's contour.
  planner::AxisMask independent = 0;
};

/// A joint between two planned segments, passed inside a cycle (Detail::axes only).
struct Joint {
  double t = 0.0;          ///< time of the joint [s]
  std::uint32_t line = 0;  ///< line of the incoming block
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main program)
  planner::TransitionClass cls = planner::TransitionClass::c0;
  planner::StopReason stop = planner::StopReason::none;
  bool jerk_limited = true;  ///< both sides jerk-limited slopes
  /// The incoming / outgoing block is G00: the formulas take the slope in force in both
  /// (planner::joint_slope, P-AXIS-00004).
  bool rapid_in = false;
  bool rapid_out = false;
  /// P-CHAN-00009 on (ChannelLimits::limit_c1_by_jerk): the acceleration steps are bounded by
  /// j T; off, the kernel does not reduce the velocity for them and they are not bounded.
  bool c1_limited = true;
  double v = 0.0;                                            ///< path velocity at the joint [mm/s]
  planner::LinkRule rule = planner::LinkRule::segment_caps;  ///< what set the link velocity
  /// #TRANSVELMIN of the incoming block [mm/s] (0: not programmed, or under G261 / G61)
  double transvelmin = 0.0;
  AxisVec dv{};  ///< axis velocity step out - in [mm/s] (VELOJUMP)
  AxisVec da{};  ///< axis acceleration step out - in [mm/s^2] (C1, and C0 on curves)
  /// Under a kinematic transform (Config::joints, both blocks transformed) the joints' steps:
  /// velocity v (q'_out - q'_in), acceleration v^2 (q''_out - q''_in) + a (q'_out - q'_in),
  /// q' = dq/ds from the inverse (planner::joint_derivatives).
  bool joint_steps = false;
  AxisVec dq{};  ///< joint velocity step [mm/s | deg/s]
  AxisVec dw{};  ///< joint acceleration step [mm/s^2 | deg/s^2]
};

/// Receives the cycle stream (audit, CSV writer).
class Sink {
 public:
  virtual ~Sink() = default;
  /// A joint passed within the cycle that on_cycle() reports next.
  virtual void on_joint(const Joint& joint) = 0;
  virtual void on_cycle(const Cycle& cycle) = 0;
};

enum class Status : std::uint8_t {
  running,   ///< a cycle was done
  finished,  ///< the program has ended; no cycle was done
  error,     ///< the source failed or gave a malformed Move; message() says why
};

}  // namespace ncsim::ipo
