#include "axes/coupling.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::axes {

std::string_view diagnostic_id(CouplingResult result) noexcept {
  switch (result) {
    case CouplingResult::ok:
      return {};
    case CouplingResult::error_zero_factor:
      return "NC5520";
    case CouplingResult::error_not_at_rest:
      return "NC5521";
    case CouplingResult::error_not_coupled:
      return "NC5522";
    case CouplingResult::error_coupled:
      return "NC5523";
    case CouplingResult::error_profile:
      return "NC5524";
  }
  return {};
}

std::string_view describe(CouplingResult result) noexcept {
  switch (result) {
    case CouplingResult::ok:
      return "ok";
    case CouplingResult::error_zero_factor:
      return "the coupling factor must be non-zero and finite";
    case CouplingResult::error_not_at_rest:
      return "coupling needs master and slave at standstill";
    case CouplingResult::error_not_coupled:
      return "the axis is not coupled";
    case CouplingResult::error_coupled:
      return "a coupled slave axis cannot be started or stopped on its own";
    case CouplingResult::error_profile:
      return "the setpoint generator rejected the motion";
  }
  return {};
}

SlaveAxis::SlaveAxis(const Dynamics& dynamics, double position)
    : dynamics_(dynamics), profile_(Profile::at_rest(position)) {
  if (!valid(dynamics)) {
    throw std::invalid_argument(
        "slave axis dynamics (V " + core::number_text(dynamics.v_max) + ", A+ " +
        core::number_text(dynamics.a_max) + ", A- " + core::number_text(dynamics.d_max) + ", J " +
        core::number_text(dynamics.j_max) + "): each must be finite and > 0");
  }
  setpoint_.p = position;
}

CouplingResult SlaveAxis::couple(const Setpoint& master, double factor) noexcept {
  if (!std::isfinite(factor) || factor == 0.0) return CouplingResult::error_zero_factor;
  // 002_* 3.2.2: "Koppeln kann nur im Stillstand beider Achsen erfolgen."
  if (master.v != 0.0 || master.a != 0.0 || moving() || setpoint_.v != 0.0) {
    return CouplingResult::error_not_at_rest;
  }
  coupling_ = LinearCoupling{factor, setpoint_.p - factor * master.p};
  return CouplingResult::ok;
}

CouplingResult SlaveAxis::set_factor(const Setpoint& master, double factor) noexcept {
  if (!coupling_) return CouplingResult::error_not_coupled;
  if (!std::isfinite(factor) || factor == 0.0) return CouplingResult::error_zero_factor;
  // Keep the slave where the old factor puts it at this master position.
  const double p_slave = coupling_->factor * master.p + coupling_->offset;
  coupling_ = LinearCoupling{factor, p_slave - factor * master.p};
  return CouplingResult::ok;
}

CouplingResult SlaveAxis::adopt(Result result, const Profile& profile) noexcept {
  if (result != Result::ok) return CouplingResult::error_profile;
  profile_ = profile;
  t_ = 0.0;
  return CouplingResult::ok;
}

CouplingResult SlaveAxis::decouple() noexcept {
  if (!coupling_) return CouplingResult::error_not_coupled;
  coupling_.reset();
  const MotionState now = state();
  if (now.v == 0.0 && now.a == 0.0) {
    profile_ = Profile::at_rest(now.p);  // offline decoupling
    t_ = 0.0;
    return CouplingResult::ok;
  }
  // Velocity reached when the acceleration is ramped to zero with jerk J.
  const double v_carry = now.v + now.a * std::fabs(now.a) / (2.0 * dynamics_.j_max);
  Profile profile;
  return adopt(plan_velocity(now, v_carry, dynamics_, profile), profile);
}

CouplingResult SlaveAxis::stop() noexcept {
  if (coupling_) return CouplingResult::error_coupled;
  Profile profile;
  return adopt(plan_stop(state(), dynamics_, profile), profile);
}

CouplingResult SlaveAxis::move_velocity(double v_target) noexcept {
  if (coupling_) return CouplingResult::error_coupled;
  Profile profile;
  return adopt(plan_velocity(state(), v_target, dynamics_, profile), profile);
}

CouplingResult SlaveAxis::move_position(double target) noexcept {
  if (coupling_) return CouplingResult::error_coupled;
  Profile profile;
  return adopt(plan_position(state(), PositionTarget{target, 0.0}, dynamics_, profile), profile);
}

bool SlaveAxis::moving() const noexcept {
  if (coupling_) return false;
  return t_ < profile_.duration() || profile_.end_state().v != 0.0;
}

Setpoint SlaveAxis::step(const Setpoint& master, double t_cycle) noexcept {
  if (coupling_) {
    setpoint_ = coupling_->slave_of(master);
  } else {
    t_ += t_cycle;
    setpoint_ = profile_.at(t_);
  }
  return setpoint_;
}

}  // namespace ncsim::axes
