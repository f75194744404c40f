#pragma once
// planner/test_support: small builders shared by the planner's tests (and ipo's).

#include "planner/move.hpp"

namespace ncsim::planner::test {

/// An axis vector with X, Y, Z set and every other axis 0 [mm].
inline AxisVec vec(double x, double y, double z = 0.0) {
  AxisVec v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

/// Limits of one axis: v_max = v_reference = v_rapid = v [mm/s], A+ = |A-| = a [mm/s^2],
/// j [mm/s^3], VELOJUMP factor c0.
inline AxisLimits axis(double v, double a, double j, double c0 = 1.0) {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = v;
  ax.a_max = ax.d_max = a;
  ax.j_max = j;
  ax.c0 = c0;
  return ax;
}

}  // namespace ncsim::planner::test
