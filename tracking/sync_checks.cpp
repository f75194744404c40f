// tracking/sync_checks: the run-time checks of conveyor tracking (see the header).

#include "tracking/sync_checks.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_text.hpp"

namespace ncsim::tracking {

namespace {

std::string mm_s(double v) {
  return core::human(v) + " mm/s";
}

}  // namespace

std::optional<SyncError> check_belt_velocity(double v_belt, double conv_vel) {
  const double limit = kBeltVelocityTolerance * conv_vel;
  if (!(std::fabs(v_belt) > limit * (1.0 + kBeltVelocityRounding))) return std::nullopt;
  return SyncError{kBeltTooFastId, "the conveyor moves at " + mm_s(std::fabs(v_belt)) +
                                       ", more than 10 % above CONV_VEL " + mm_s(conv_vel) +
                                       " (limit " + mm_s(limit) + ")"};
}

std::optional<SyncError> check_conv_vel(const planner::AxisLimits& axis, double conveying,
                                        double conv_vel, const std::string& axis_name) {
  const double share = std::fabs(conveying) * conv_vel;
  if (!(share > axis.v_max)) return std::nullopt;
  return SyncError{kConvVelTooHighId,
                   "CONV_VEL " + mm_s(conv_vel) + " puts " + mm_s(share) + " on axis " + axis_name +
                       ", above its maximum velocity " + mm_s(axis.v_max) + " (P-AXIS-00212)"};
}

planner::AxisLimits pcs1_limits(const planner::AxisLimits& axis, double conveying,
                                double conv_vel) {
  return planner::belt_limits(axis, pcs1_belt(conveying, conv_vel));
}

double pcs1_belt(double conveying, double conv_vel) noexcept {
  return std::fabs(conveying) * kBeltVelocityTolerance * conv_vel;
}

}  // namespace ncsim::tracking
