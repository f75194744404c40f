#pragma once
// axes/control: the position-control model that makes an axis's actual value differ from its
// command value, and the encoder axis whose command value *is* its actual value.
//
// Model (one step per interpolation cycle T, "velocity interface": position control in the NC,
// 000_* 7.4.2):
//   1. the drive moves for one cycle with the velocity it was given last cycle:
//        p_true += v_drive * T
//   2. the encoder samples it, optionally with seeded uniform noise in [-a, +a]:
//        p_act = p_true + noise
//   3. the P position controller with feedforward computes the velocity set value
//        (000_* 7.4.2 "Output velocity = feed forward velocity + Kv * following error";
//         feedforward weighted by "Pre-Control Weighting [0.0 .. 1.0]", plus Ka * a_set from
//         "Feedforward Acceleration: Output velocity component = Ka * setpoint acceleration"):
//        v_out = w_ff * v_set + Ka * a_set + Kv * (p_set - p_act)
//   4. the drive follows v_out as a PT1 element (filter formula of 000_* 7.5.8):
//        I = T / (T + T_pt1);  v_drive = I * v_out + (1 - I) * v_drive
// Following error (position lag) = set position - actual position (000_* 7.1.5).
// At constant set velocity v the lag settles at v * (1 - w_ff) / Kv, exactly, also in discrete
// time; with w_ff = 1 it settles at 0.
//
// Inputs: command values per cycle (axes::Setpoint of axes/profile.hpp). Outputs: actual values per
// cycle. Invariants: step() never throws and never allocates; parameters are validated once, in the
// constructor (std::invalid_argument naming the parameter and the value).

#include <cstdint>
#include <random>

#include "axes/profile.hpp"

namespace ncsim::axes {

/// The actual value of one axis at one cycle, as the NC sees it (through the encoder).
struct ActualValue {
  double position = 0.0;         ///< [mm] measured actual position (with encoder noise)
  double velocity = 0.0;         ///< [mm/s] drive velocity
  double following_error = 0.0;  ///< [mm] set position - measured actual position
};

/// PT1 filter of 000_* 7.5.8: I = T / (T + T_filter), x = I * x_new + (1 - I) * x_old.
/// T_filter = 0 passes the new value through unchanged.
class Pt1Filter {
 public:
  Pt1Filter() = default;
  /// Throws std::invalid_argument unless t_cycle > 0 and t_filter >= 0 (both finite).
  Pt1Filter(double t_cycle, double t_filter, double initial = 0.0);

  double step(double x_new) noexcept {
    value_ = weight_ * x_new + (1.0 - weight_) * value_;
    return value_;
  }
  double value() const noexcept { return value_; }
  void reset(double x) noexcept { value_ = x; }
  double weight() const noexcept { return weight_; }  ///< I of 7.5.8, in (0, 1]

 private:
  double weight_ = 1.0;
  double value_ = 0.0;
};

/// Seeded uniform noise in [-amplitude, +amplitude]. The sequence depends only on the seed:
/// the engine (std::mt19937_64) is fully specified by the standard and the mapping to double
/// is ours, so every platform draws the same numbers.
class EncoderNoise {
 public:
  EncoderNoise(double amplitude, std::uint64_t seed) : amplitude_(amplitude), engine_(seed) {}
  double draw() noexcept;

 private:
  double amplitude_ = 0.0;  // [mm]
  std::mt19937_64 engine_;
};

/// Parameters of the position control loop. Names follow 000_* 7.4 (Axes | Axis | Ctrl) and
/// 7.2.1 (Enc); axes/axis_config.hpp maps a machine's axis lists onto them.
struct PositionControlParams {
  double kv = 10.0;  ///< [1/s] "Position control: Proportional Factor Kv" (000_* 7.4.2);
                     ///< default: ISG P-AXIS-00099 getriebe[i].kv, 1000 x 0.01/s
  double feedforward_weight = 1.0;  ///< [-] "Feedforward Velocity: Pre-Control Weighting
                                    ///< [0.0 .. 1.0]" (000_* 7.4.2)
  double ka = 0.0;  ///< [s] "Feedforward Acceleration: Proportional Factor Ka" (000_* 7.4.2)
  double drive_pt1_time = 0.0;   ///< [s] time constant of the drive's PT1 behaviour (ncsim)
  double noise_amplitude = 0.0;  ///< [mm] "Noise level of simulation encoder" (000_* 7.2.1),
                                 ///< uniform in [-a, +a]
  std::uint64_t noise_seed = 1;  ///< seed of the axis's own noise generator
};

/// Throws std::invalid_argument naming the parameter when `params` cannot run at `t_cycle`:
/// Kv must be > 0 with Kv * T <= 1, the weight in [0, 1], Ka, T_pt1 and the noise >= 0.
void validate(const PositionControlParams& params, double t_cycle);

class PositionControlModel {
 public:
  /// Axis at rest at `position`. Throws like validate().
  PositionControlModel(const PositionControlParams& params, double t_cycle, double position);

  /// Advances one cycle with this cycle's command value; returns the actual value sampled at
  /// the same instant. noexcept, no allocation.
  ActualValue step(const Setpoint& command) noexcept;

  /// The last actual value returned by step() (or the initial rest state).
  const ActualValue& actual() const noexcept { return actual_; }
  /// [mm] position of the mechanics without encoder noise.
  double true_position() const noexcept { return p_true_; }

  /// Axis at rest at `position` (e.g. after the controller enable is toggled).
  void reset(double position) noexcept;
  /// Shifts the coordinate system by `delta` without moving the mechanics (homing sets the
  /// actual position to the reference value this way).
  void shift(double delta) noexcept;

 private:
  PositionControlParams params_;
  double t_cycle_ = 0.0;  // [s]
  Pt1Filter drive_;       // velocity of the drive [mm/s]
  EncoderNoise noise_;    // encoder noise
  double p_true_ = 0.0;   // [mm]
  ActualValue actual_;
};

/// Encoder axis (000_* 6.1.2): a pure encoder integrated as an axis. It has no setpoint
/// generator: its set value is its actual value, noise included, which couplings pass on to
/// their slaves. Velocity and acceleration are difference quotients, each smoothed by a PT1
/// ("Filter Time for Actual Velocity / Acceleration (P-T1)", 000_* 7.2.3).
struct EncoderAxisParams {
  double noise_amplitude = 0.0;           ///< [mm] uniform noise in [-a, +a] (000_* 7.2.1)
  std::uint64_t noise_seed = 1;           ///< seed of the encoder's noise generator
  double velocity_filter_time = 0.0;      ///< [s] PT1 of the actual velocity (000_* 7.2.3)
  double acceleration_filter_time = 0.0;  ///< [s] PT1 of the actual acceleration (000_* 7.2.3)
};

class EncoderAxis {
 public:
  /// Throws std::invalid_argument for a negative noise or filter time, or t_cycle <= 0.
  EncoderAxis(const EncoderAxisParams& params, double t_cycle, double position);

  /// Takes the physical position of the measured object for this cycle and returns the axis's
  /// set value (= its measured actual value). noexcept, no allocation.
  Setpoint step(double physical_position) noexcept;
  const Setpoint& value() const noexcept { return value_; }

 private:
  double t_cycle_ = 0.0;  // [s]
  EncoderNoise noise_;
  Pt1Filter velocity_;
  Pt1Filter acceleration_;
  Setpoint value_;
};

}  // namespace ncsim::axes
