#pragma once
// axes/profile_generator: the stateful PTP setpoint generator of one axis (the "Satzausfuehrung"
// of seed 002_* 2.1) with the online changes of 002_* 2.2 to 2.5.
//
// Inputs: commands (position start, MC_MoveVelocity, override, stop, new end position, new
// velocity and end position with activation position, position compensation and its stop),
// then step(t_cycle) once per cycle.
// Outputs: setpoint() after each step: command position, velocity, acceleration, jerk.
// Invariants: every online change replans from the current command state, so position,
// velocity and acceleration stay continuous (compensation: position and velocity, 002_* 2.5
// is a trapezoid, not jerk-limited). step() never throws; commands return a Result.
// Configuration errors (GeneratorConfig) throw std::invalid_argument naming the parameter.

#include <optional>

#include "axes/profile.hpp"
#include "axes/profile_compensation.hpp"

namespace ncsim::axes {

/// Override reference (000_* 6.2.1.3.6 "Velocity Override Type", 7.5.6).
enum class OverrideType : std::uint8_t {
  reduced_iterated,   ///< override times the level activated at start (possibly reduced)
  original_iterated,  ///< override times the velocity the command asked for
};

/// MC_MoveVelocity direction (isg-language.md 6.3): 1 positive, 3 negative, 4 current.
enum class MoveDirection : std::uint8_t { positive = 1, negative = 3, current = 4 };

/// MC_MoveVelocity parameters in ncsim's internal units (isg-language.md 6.3).
struct VelocityCommand {
  double velocity = 0.0;      ///< [mm/s] (rotary: deg/s), > 0; the interpreter converts the
                              ///< program's um/s once at the program boundary (isg-language.md 6.3)
  double acceleration = 0.0;  ///< [mm/s^2]; <= 0 takes the axis value
  double deceleration = 0.0;  ///< [mm/s^2]; <= 0 takes the axis value
  double jerk = 0.0;          ///< [mm/s^3]; <= 0 takes the axis value
  MoveDirection direction = MoveDirection::positive;
};

/// Axis parameters the generator needs.
struct GeneratorConfig {
  Dynamics dynamics;        ///< default V, A+, A-, J of the axis
  double v_axis_max = 0.0;  ///< maximum permitted axis velocity [mm/s]; starts above it fail
  double increment = 1e-4;  ///< encoder increment [mm]; shorter moves do not start (002_* 2.1)
  OverrideType override_type = OverrideType::reduced_iterated;
  /// Shape of position motions (NCSIM-AXIS-030 `ncsim.profile_rule`, docs/axes-profile.md):
  /// the manual's rules (default) or the fastest single-peak profile.
  ProfileRule profile_rule = ProfileRule::manual;
};

class SetpointGenerator {
 public:
  /// Throws std::invalid_argument when a configuration value is not finite and positive.
  explicit SetpointGenerator(const GeneratorConfig& config, double p_start = 0.0);

  /// Absolute position start with velocity `v` [mm/s] (<= 0: the axis V) and optional
  /// dynamics (missing: the axis values).
  Result start_position(double target, double v = 0.0,
                        const std::optional<Dynamics>& dynamics = std::nullopt) noexcept;
  /// Position start that arrives at `target` with velocity `v_end` (sync-in, FEED_CONT).
  Result start_position_moving(double target, double v_end, double v = 0.0,
                               const std::optional<Dynamics>& dynamics = std::nullopt) noexcept;
  /// Endless velocity motion (MC_MoveVelocity).
  Result start_velocity(const VelocityCommand& command) noexcept;

  /// Override in [0, 1] (002_* 2.2); 0 stops and keeps the target. Values outside: error.
  Result set_override(double fraction) noexcept;
  /// Stop with priority (002_* 2.2); the motion ends at rest, the target is dropped.
  Result stop() noexcept;
  /// Not-Stop (002_* 2.2): stop with new deceleration and jerk if both exceed the current ones.
  Result emergency_stop(double dec_max, double jerk_max) noexcept;
  /// New end position (002_* 2.3); overshoot: stop, then return.
  Result new_end_position(double target) noexcept;
  /// New velocity v_new from activation position a_pos on, new end position e_pos (002_* 2.4).
  Result new_velocity_and_end_position(double v_new, double e_pos, double a_pos) noexcept;
  /// Position compensation (002_* 2.5).
  Result start_compensation(const CompensationRequest& request) noexcept;
  /// Compensation stop (002_* 2.5 "Kompensationsstop").
  Result stop_compensation() noexcept;

  /// Advances one cycle of t_cycle [s]; working, finished, or ok when idle.
  Result step(double t_cycle) noexcept;

  Setpoint setpoint() const noexcept { return setpoint_; }  ///< after the last step
  bool moving() const noexcept { return mode_ != Mode::idle; }
  bool in_braking_phase() const noexcept;
  bool stopping() const noexcept { return stopping_; }
  bool compensation_active() const noexcept { return compensation_.has_value(); }
  /// The activated compensation difference (reduced if infeasible) [mm]; 0 when none.
  double compensation_difference() const noexcept;
  double override_fraction() const noexcept { return override_; }
  const Profile& profile() const noexcept { return base_; }  ///< base dynamics (no compensation)
  double target() const noexcept { return target_; }  ///< end position incl. compensation [mm]

 private:
  enum class Mode : std::uint8_t { idle, position, velocity };
  Result replan() noexcept;
  Result begin_position(double target_base, double v_end) noexcept;
  MotionState base_state() const noexcept;
  void update_setpoint() noexcept;

  GeneratorConfig config_;
  Dynamics dynamics_;  // of the active motion
  Profile base_;       // base dynamics (Grunddynamik), without compensation
  double t_ = 0.0;     // time since base_ started [s]
  Mode mode_ = Mode::idle;
  double target_base_ = 0.0;    // base end position [mm]
  double target_ = 0.0;         // end position incl. compensation [mm]
  double v_end_ = 0.0;          // velocity at the target [mm/s]
  double v_user_ = 0.0;         // velocity the command asked for [mm/s]
  double v_start_level_ = 0.0;  // level activated at start (reduced) [mm/s]
  double v_velocity_ = 0.0;     // signed velocity target of a velocity motion [mm/s]
  double override_ = 1.0;
  bool stopping_ = false;
  bool held_ = false;                // override 0: stopped, target kept
  std::optional<double> pending_v_;  // 002_* 2.4: velocity waiting for a_pos
  double activation_pos_ = 0.0;      // [mm]
  double comp_offset_ = 0.0;         // finished compensations [mm]
  std::optional<Compensation> compensation_;
  double comp_start_p_ = 0.0;  // base position where the compensation started [mm]
  double comp_dir_ = 1.0;      // logical direction of the compensation
  Setpoint setpoint_;
};

}  // namespace ncsim::axes
