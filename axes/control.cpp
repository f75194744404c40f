#include "axes/control.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::axes {
namespace {

[[noreturn]] void reject(const char* parameter, double value, const std::string& requirement) {
  throw std::invalid_argument(std::string("axis parameter ") + parameter + " = " +
                              core::number_text(value) + ": " + requirement);
}

void require_non_negative(const char* parameter, double value) {
  if (!std::isfinite(value) || value < 0.0) reject(parameter, value, "must be finite and >= 0");
}

void require_cycle(double t_cycle) {
  if (!std::isfinite(t_cycle) || t_cycle <= 0.0) {
    reject("cycle time", t_cycle, "must be finite and > 0");
  }
}

}  // namespace

Pt1Filter::Pt1Filter(double t_cycle, double t_filter, double initial) : value_(initial) {
  require_cycle(t_cycle);
  require_non_negative("PT1 filter time", t_filter);
  weight_ = t_cycle / (t_cycle + t_filter);  // 000_* 7.5.8
}

double EncoderNoise::draw() noexcept {
  if (amplitude_ == 0.0) return 0.0;
  // 53 random bits -> [0, 1) -> [-1, 1).
  const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
  return amplitude_ * (2.0 * unit - 1.0);
}

void validate(const PositionControlParams& params, double t_cycle) {
  require_cycle(t_cycle);
  if (!std::isfinite(params.kv) || params.kv <= 0.0) {
    reject("Kv (Position control: Proportional Factor Kv) [1/s]", params.kv, "must be > 0");
  }
  if (params.kv * t_cycle > 1.0) {
    reject("Kv (Position control: Proportional Factor Kv) [1/s]", params.kv,
           "Kv * cycle time must not exceed 1 (" + core::number_text(1.0 / t_cycle) +
               " 1/s at this cycle time)");
  }
  if (!std::isfinite(params.feedforward_weight) || params.feedforward_weight < 0.0 ||
      params.feedforward_weight > 1.0) {
    reject("Feedforward Velocity: Pre-Control Weighting", params.feedforward_weight,
           "must lie in [0.0, 1.0]");
  }
  require_non_negative("Feedforward Acceleration: Proportional Factor Ka [s]", params.ka);
  require_non_negative("drive PT1 time [s]", params.drive_pt1_time);
  require_non_negative("Noise level of simulation encoder [mm]", params.noise_amplitude);
}

PositionControlModel::PositionControlModel(const PositionControlParams& params, double t_cycle,
                                           double position)
    : params_(params),
      t_cycle_(t_cycle),
      noise_(params.noise_amplitude, params.noise_seed),
      p_true_(position) {
  validate(params, t_cycle);
  drive_ = Pt1Filter(t_cycle, params.drive_pt1_time);
  actual_.position = position;
}

ActualValue PositionControlModel::step(const Setpoint& command) noexcept {
  // 1. The drive moved during the past cycle with the velocity it was given then.
  p_true_ += drive_.value() * t_cycle_;
  // 2. The encoder samples the mechanics.
  const double p_act = p_true_ + noise_.draw();
  // 3. P controller with velocity and acceleration feedforward (000_* 7.4.2).
  const double lag = command.p - p_act;
  const double v_out =
      params_.feedforward_weight * command.v + params_.ka * command.a + params_.kv * lag;
  // 4. The drive follows as a PT1 element (000_* 7.5.8).
  actual_.velocity = drive_.value();
  drive_.step(v_out);
  actual_.position = p_act;
  actual_.following_error = lag;
  return actual_;
}

void PositionControlModel::reset(double position) noexcept {
  p_true_ = position;
  drive_.reset(0.0);
  actual_ = ActualValue{position, 0.0, 0.0};
}

void PositionControlModel::shift(double delta) noexcept {
  p_true_ += delta;
  actual_.position += delta;
}

EncoderAxis::EncoderAxis(const EncoderAxisParams& params, double t_cycle, double position)
    : t_cycle_(t_cycle), noise_(params.noise_amplitude, params.noise_seed) {
  require_cycle(t_cycle);
  require_non_negative("Noise level of simulation encoder [mm]", params.noise_amplitude);
  velocity_ = Pt1Filter(t_cycle, params.velocity_filter_time);
  acceleration_ = Pt1Filter(t_cycle, params.acceleration_filter_time);
  value_.p = position;
}

Setpoint EncoderAxis::step(double physical_position) noexcept {
  const double position = physical_position + noise_.draw();
  const double v_raw = (position - value_.p) / t_cycle_;
  const double v_old = velocity_.value();
  const double v = velocity_.step(v_raw);
  const double a = acceleration_.step((v - v_old) / t_cycle_);
  value_ = Setpoint{position, v, a, 0.0};
  return value_;
}

}  // namespace ncsim::axes
