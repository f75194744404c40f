// axes/profile_generator.cpp: command handling and cyclic stepping (002_* 2.1 to 2.5).
// Every online change replans the base dynamics from the command state at the current time;
// the profile is evaluated per cycle, never integrated.

#include "axes/profile_generator.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::axes {

namespace {

void require_positive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("NC5003: GeneratorConfig.") + name +
                                " must be finite and > 0, got " + core::number_text(value));
  }
}

double sign_of(double x, double fallback) noexcept {
  return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : fallback);
}

}  // namespace

SetpointGenerator::SetpointGenerator(const GeneratorConfig& config, double p_start)
    : config_(config), dynamics_(config.dynamics), base_(Profile::at_rest(p_start)) {
  require_positive(config.dynamics.v_max, "dynamics.v_max (V)");
  require_positive(config.dynamics.a_max, "dynamics.a_max (A+)");
  require_positive(config.dynamics.d_max, "dynamics.d_max (A-)");
  require_positive(config.dynamics.j_max, "dynamics.j_max (J)");
  require_positive(config.v_axis_max, "v_axis_max");
  if (!(std::isfinite(config.increment) && config.increment >= 0.0)) {
    throw std::invalid_argument("NC5003: GeneratorConfig.increment must be finite and >= 0, got " +
                                core::number_text(config.increment));
  }
  if (!std::isfinite(p_start)) {
    throw std::invalid_argument("NC5003: start position must be finite, got " +
                                core::number_text(p_start));
  }
  target_base_ = p_start;
  target_ = p_start;
  setpoint_ = Setpoint{p_start, 0.0, 0.0, 0.0};
}

MotionState SetpointGenerator::base_state() const noexcept {
  const Setpoint s = base_.at(t_);
  return MotionState{s.p, s.v, s.a};
}

bool SetpointGenerator::in_braking_phase() const noexcept {
  if (stopping_) return true;
  return mode_ == Mode::position && !held_ && t_ >= base_.t_brake();
}

double SetpointGenerator::compensation_difference() const noexcept {
  return compensation_ ? compensation_->difference() : 0.0;
}

Result SetpointGenerator::replan() noexcept {
  const MotionState st = base_state();
  Profile next;
  Result r = Result::ok;
  if (mode_ == Mode::velocity) {
    r = plan_velocity(st, v_velocity_ * override_, dynamics_, next);
  } else if (override_ == 0.0) {
    r = plan_stop(st, dynamics_, next);  // 002_* 2.2: stop as override 0, target kept
  } else {
    // 002_* 2.2 / 000_* 7.5.6: the override scales the reference velocity; "iterated": an
    // unreachable level is lowered to the best reachable one, which plan_position does.
    const double v_ref =
        config_.override_type == OverrideType::reduced_iterated ? v_start_level_ : v_user_;
    Dynamics d = dynamics_;
    d.v_max = std::max(v_ref * override_, std::abs(v_end_));
    r = plan_position(st, PositionTarget{target_base_, v_end_}, d, next, config_.profile_rule);
  }
  if (r != Result::ok) return r;
  base_ = next;
  t_ = 0.0;
  held_ = mode_ == Mode::position && override_ == 0.0;
  return Result::ok;
}

Result SetpointGenerator::begin_position(double target_base, double v_end) noexcept {
  // The level activated at 100 % (reduced when V is unreachable) is the reference of the
  // override type "Reduced (iterated)" (000_* 7.5.6).
  Profile full;
  Dynamics d = dynamics_;
  d.v_max = std::max(v_user_, std::abs(v_end));
  const Result r = plan_position(base_state(), PositionTarget{target_base, v_end}, d, full,
                                 config_.profile_rule);
  if (r != Result::ok) return r;
  mode_ = Mode::position;
  target_base_ = target_base;
  v_end_ = v_end;
  v_start_level_ = full.v_level();
  target_ = target_base_ + comp_offset_ + compensation_difference();
  if (override_ == 1.0) {
    base_ = full;
    t_ = 0.0;
    held_ = false;
    return Result::ok;
  }
  return replan();
}

Result SetpointGenerator::start_position(double target, double v,
                                         const std::optional<Dynamics>& dynamics) noexcept {
  return start_position_moving(target, 0.0, v, dynamics);
}

Result SetpointGenerator::start_position_moving(double target, double v_end, double v,
                                                const std::optional<Dynamics>& dynamics) noexcept {
  if (stopping_) return Result::rejected_stopping;
  if (compensation_) return Result::rejected_compensation_active;
  Dynamics d = dynamics.value_or(config_.dynamics);
  if (v > 0.0) d.v_max = v;
  if (!valid(d) || !std::isfinite(target) || !std::isfinite(v_end) || std::isnan(v)) {
    return Result::error_invalid_input;
  }
  if (d.v_max > config_.v_axis_max) return Result::error_velocity_limit;  // 002_* 2.1 Tab. 2
  const double target_base = target - comp_offset_;
  if (mode_ == Mode::idle && v_end == 0.0 &&
      std::abs(target_base - base_state().p) < config_.increment) {
    return Result::ignored_below_increment;  // 002_* 2.1 "kleiner als ein Encoder-Inkrement"
  }
  const Dynamics previous = dynamics_;
  const double previous_v = v_user_;
  dynamics_ = d;
  v_user_ = d.v_max;
  pending_v_.reset();
  const Result r = begin_position(target_base, v_end);
  if (r != Result::ok) {
    dynamics_ = previous;
    v_user_ = previous_v;
  }
  return r;
}

Result SetpointGenerator::start_velocity(const VelocityCommand& command) noexcept {
  if (stopping_) return Result::rejected_stopping;
  if (compensation_) return Result::rejected_compensation_active;
  const double v = command.velocity;  // [mm/s], converted from um/s by the interpreter
  if (!(std::isfinite(v) && v > 0.0)) return Result::error_invalid_input;
  if (v > config_.v_axis_max) return Result::error_velocity_limit;
  // isg-language.md 6.3: missing or <= 0 Acceleration/Deceleration/Jerk take the axis values.
  Dynamics d = config_.dynamics;
  if (command.acceleration > 0.0) d.a_max = command.acceleration;
  if (command.deceleration > 0.0) d.d_max = command.deceleration;
  if (command.jerk > 0.0) d.j_max = command.jerk;
  d.v_max = v;
  if (!valid(d)) return Result::error_invalid_input;
  double sign = 1.0;
  switch (command.direction) {
    case MoveDirection::positive:
      sign = 1.0;
      break;
    case MoveDirection::negative:
      sign = -1.0;
      break;
    case MoveDirection::current:  // decision: standing still counts as positive
      sign = sign_of(base_state().v, 1.0);
      break;
  }
  dynamics_ = d;
  v_user_ = v;
  v_velocity_ = sign * v;
  mode_ = Mode::velocity;
  pending_v_.reset();
  return replan();
}

Result SetpointGenerator::set_override(double fraction) noexcept {
  if (!(fraction >= 0.0 && fraction <= 1.0)) return Result::error_invalid_input;
  const double previous = override_;
  override_ = fraction;
  if (mode_ == Mode::idle) return Result::ok;
  if (stopping_) return Result::rejected_stopping;
  // 002_* 2.2: activated only when no stop is active and the braking phase is not reached.
  if (in_braking_phase()) return Result::ignored_braking_phase;
  const Result r = replan();
  if (r != Result::ok) override_ = previous;
  return r;
}

Result SetpointGenerator::stop() noexcept {
  if (mode_ == Mode::idle) return Result::ok;
  Profile next;
  const Result r = plan_stop(base_state(), dynamics_, next);
  if (r != Result::ok) return r;
  base_ = next;
  t_ = 0.0;
  stopping_ = true;
  held_ = false;
  pending_v_.reset();
  if (compensation_) stop_compensation();  // 002_* 2.2 / 2.5: stop also stops compensation
  return Result::ok;
}

Result SetpointGenerator::emergency_stop(double dec_max, double jerk_max) noexcept {
  if (mode_ == Mode::idle) return Result::ok;
  // 002_* 2.2 "Not-Stop": no emergency stop in a braking phase; the new values are taken
  // only when both exceed the ones given at start.
  if (in_braking_phase()) return Result::ignored_braking_phase;
  if (dec_max > dynamics_.d_max && jerk_max > dynamics_.j_max && std::isfinite(dec_max) &&
      std::isfinite(jerk_max)) {
    dynamics_.d_max = dec_max;
    dynamics_.j_max = jerk_max;
  }
  return stop();
}

Result SetpointGenerator::new_end_position(double target) noexcept {
  if (mode_ == Mode::idle) return Result::rejected_not_moving;
  if (stopping_) return Result::rejected_stopping;
  if (compensation_) return Result::rejected_compensation_active;  // 002_* 2.3
  if (!std::isfinite(target)) return Result::error_invalid_input;
  if (mode_ == Mode::velocity) v_user_ = std::abs(v_velocity_);
  pending_v_.reset();
  // 002_* 2.3: overshoot or no longer able to stop before the target: plan_position stops
  // and returns; a formerly unreachable V is reached if the new distance allows it.
  return begin_position(target - comp_offset_, 0.0);
}

Result SetpointGenerator::new_velocity_and_end_position(double v_new, double e_pos,
                                                        double a_pos) noexcept {
  if (!(std::isfinite(v_new) && v_new > 0.0) || !std::isfinite(e_pos) || !std::isfinite(a_pos)) {
    return Result::error_invalid_input;
  }
  if (v_new > config_.v_axis_max) return Result::error_velocity_limit;
  if (mode_ == Mode::idle) return Result::rejected_not_moving;
  if (stopping_) return Result::rejected_stopping;
  if (compensation_) return Result::rejected_compensation_active;  // 002_* 2.4
  if (mode_ == Mode::velocity) v_user_ = std::abs(v_velocity_);
  const MotionState st = base_state();
  const double dir = sign_of(st.v, sign_of(target_base_ - st.p, 1.0));
  const double x = dir * (st.p + comp_offset_);
  const double xa = dir * a_pos;
  const double xe = dir * e_pos;
  pending_v_.reset();
  // 002_* 2.4 "Interner Ablauf: Aktivierungsposition", cases 1 to 6 (logical direction).
  if (x <= xa && xa <= xe) {  // 1: new velocity after passing a_pos
    pending_v_ = v_new;
    activation_pos_ = a_pos;
  } else if (xa <= x && x <= xe) {  // 2: a_pos already passed: new velocity at once
    v_user_ = v_new;
  }
  // 3 to 6: new end position with the old velocity (stop and return where needed).
  return begin_position(e_pos - comp_offset_, 0.0);
}

Result SetpointGenerator::start_compensation(const CompensationRequest& request) noexcept {
  if (mode_ != Mode::position || held_) return Result::rejected_not_moving;
  if (stopping_) return Result::rejected_stopping;                 // 002_* 2.5 note 5
  if (compensation_) return Result::rejected_compensation_active;  // note 4: not iterated
  const MotionState st = base_state();
  CompensationRequest r = request;
  // 002_* 2.5 hint 5: L beyond the remaining distance is replaced by the remaining distance.
  const double remaining = std::abs(target_base_ - st.p);
  if (remaining > 0.0 && r.length > remaining) r.length = remaining;
  const std::optional<Compensation> plan = Compensation::plan(r);
  if (!plan) return Result::error_invalid_input;
  compensation_ = plan;
  comp_start_p_ = st.p;
  comp_dir_ = sign_of(target_base_ - st.p, sign_of(st.v, 1.0));
  target_ = target_base_ + comp_offset_ + compensation_->difference();
  return Result::ok;
}

Result SetpointGenerator::stop_compensation() noexcept {
  if (!compensation_) return Result::rejected_not_moving;
  const double tau = comp_dir_ * (base_state().p - comp_start_p_) / compensation_->v_process();
  if (!compensation_->stop_at(tau)) return Result::ignored_braking_phase;
  target_ = target_base_ + comp_offset_ + compensation_->difference();
  return Result::ok;
}

void SetpointGenerator::update_setpoint() noexcept {
  const Setpoint b = base_.at(t_);
  setpoint_ = Setpoint{b.p + comp_offset_, b.v, b.a, b.j};
  if (!compensation_) return;
  // 002_* 2.5 note 3: path control; the clock of the trapezoid is the base distance / VP.
  const double vp = compensation_->v_process();
  const CompensationValue c = compensation_->at(comp_dir_ * (b.p - comp_start_p_) / vp);
  const double rate = comp_dir_ * b.v / vp;      // dtau/dt
  const double rate_dot = comp_dir_ * b.a / vp;  // d2tau/dt2
  setpoint_.p += c.c;
  setpoint_.v += c.dc * rate;
  setpoint_.a += c.ddc * rate * rate + c.dc * rate_dot;
  setpoint_.j += 3.0 * c.ddc * rate * rate_dot + c.dc * comp_dir_ * b.j / vp;
  if (c.done) {
    comp_offset_ += c.c;
    compensation_.reset();
  }
}

Result SetpointGenerator::step(double t_cycle) noexcept {
  if (!(std::isfinite(t_cycle) && t_cycle > 0.0)) return Result::error_invalid_input;
  if (mode_ == Mode::idle) {
    update_setpoint();
    return Result::ok;
  }
  t_ += t_cycle;
  if (pending_v_) {  // 002_* 2.4 case 1: activation position passed
    const Setpoint b = base_.at(t_);
    const double dir = sign_of(b.v, 1.0);
    if (dir * (b.p + comp_offset_ - activation_pos_) >= 0.0) {
      v_user_ = *pending_v_;
      pending_v_.reset();
      begin_position(target_base_, v_end_);
    }
  }
  update_setpoint();
  if (t_ < base_.duration() || held_) return Result::working;
  if (mode_ == Mode::velocity && !stopping_) return Result::finished;  // at velocity, runs on
  if (compensation_) {  // 002_* 2.5 note 6: end of path ends the compensation
    comp_offset_ = setpoint_.p - base_.end_state().p;
    compensation_.reset();
  }
  target_ = base_.end_state().p + comp_offset_;
  if (!stopping_ && v_end_ != 0.0) {  // arrived moving (sync-in): continue at that velocity
    mode_ = Mode::velocity;
    v_velocity_ = v_end_;
    v_end_ = 0.0;
    return Result::finished;
  }
  stopping_ = false;
  mode_ = Mode::idle;
  return Result::finished;
}

}  // namespace ncsim::axes
