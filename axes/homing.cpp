#include "axes/homing.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes {
namespace {

void require_positive(const char* parameter, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string("homing parameter ") + parameter + " = " +
                                core::number_text(value) + ": must be finite and > 0");
  }
}

}  // namespace

Homing::Homing(const HomingParams& params, double position)
    : params_(params), profile_(Profile::at_rest(position)), start_(position) {
  require_positive("Homing Velocity (towards plc cam) [mm/s]", params.v_to_cam);
  require_positive("Homing Velocity (off plc cam) [mm/s]", params.v_off_cam);
  require_positive("max search distance [mm]", params.max_search_distance);
  if (!std::isfinite(params.home_position)) {
    throw std::invalid_argument("homing parameter Home Position (Calibration Value) = " +
                                core::number_text(params.home_position) + ": must be finite");
  }
  if (!valid(params.dynamics)) {
    throw std::invalid_argument("homing dynamics (V, A+, A-, J): each must be finite and > 0");
  }
  setpoint_.p = position;
  move_at(params.invert_cam_search ? -params.v_to_cam : params.v_to_cam);
}

bool Homing::moving() const noexcept {
  return t_ < profile_.duration() || profile_.end_state().v != 0.0;
}

void Homing::plan(Result result, const Profile& profile) noexcept {
  if (result != Result::ok) {
    phase_ = HomingPhase::failed;  // the dynamics were validated; should not happen
    return;
  }
  profile_ = profile;
  t_ = 0.0;
}

void Homing::move_at(double velocity) noexcept {
  Profile profile;
  const MotionState now{setpoint_.p - shift_, setpoint_.v, setpoint_.a};
  plan(plan_velocity(now, velocity, params_.dynamics, profile), profile);
}

void Homing::stop() noexcept {
  Profile profile;
  const MotionState now{setpoint_.p - shift_, setpoint_.v, setpoint_.a};
  plan(plan_stop(now, params_.dynamics, profile), profile);
}

void Homing::latch() noexcept {
  // The sync event belongs to the last set value: it becomes the home position.
  const double old_position = setpoint_.p - shift_;
  latched_at_ = old_position;
  pending_shift_ = params_.home_position - old_position;
  shift_ = *pending_shift_;
  setpoint_.p = params_.home_position;
  stop();
  phase_ = HomingPhase::stopping;
}

HomingOutput Homing::step(const HomingInput& input, double t_cycle) noexcept {
  const double v_sync = params_.invert_sync_search ? -params_.v_off_cam : params_.v_off_cam;
  switch (phase_) {
    case HomingPhase::search_cam:
      if (input.cam) {
        cam_seen_ = true;
        move_at(v_sync);
        phase_ = HomingPhase::leave_cam;
      } else if (std::fabs(setpoint_.p - start_) > params_.max_search_distance) {
        stop();
        phase_ = HomingPhase::failed;
      }
      break;
    case HomingPhase::leave_cam:
      if (!input.cam) {
        if (params_.reference == HomingReference::cam_only) {
          latch();
        } else {
          phase_ = HomingPhase::search_sync;
        }
      }
      break;
    case HomingPhase::search_sync:
      if (input.sync_pulse) latch();
      break;
    case HomingPhase::stopping:
      if (!moving()) {
        if (params_.move_to_home && std::fabs(setpoint_.p - params_.home_position) > kSamePoint) {
          Profile profile;
          const MotionState now{setpoint_.p - shift_, 0.0, 0.0};
          plan(plan_position(now, PositionTarget{params_.home_position - shift_, 0.0},
                             params_.dynamics, profile),
               profile);
          phase_ = HomingPhase::to_home;
        } else {
          phase_ = HomingPhase::done;
        }
      }
      break;
    case HomingPhase::to_home:
      if (!moving()) phase_ = HomingPhase::done;
      break;
    case HomingPhase::done:
    case HomingPhase::failed:
      break;
  }

  t_ += t_cycle;
  setpoint_ = profile_.at(t_);
  setpoint_.p += shift_;
  HomingOutput output{setpoint_, phase_, pending_shift_};
  pending_shift_.reset();
  return output;
}

}  // namespace ncsim::axes
