#pragma once
// ipo/joint_stage: the per-cycle joint stage under a kinematic transform (#TRAFO ON).
//
// Purpose: the path interpolator plans and samples the path in Cartesian space (X, Y, Z of the
// TCP); the joints (ACS axes, e.g. the three arms of a delta robot, #KIN ID[37]) receive their
// own setpoints every cycle: position, velocity, acceleration and jerk.
// Inputs (per cycle): the Cartesian point x and its time derivatives v, a, j (ipo::Cycle x, v,
//   a, j; axes 0..2 = X, Y, Z, any further axes pass through unchanged). At construction: the
//   inverse transform (planner::JointMap, the same map the planner limits the path with), the
//   number of joints it gives, and the number of axes in the Cartesian vector.
// Outputs: JointSetpoint: q (positions by the inverse transform, exactly IK(x)), and q', q'',
//   q''' in time.
// Method (docs/ipo.md "Joint stage"): the Cartesian motion around the cycle instant is its own
//   third-order Taylor polynomial x(tau) = x + v tau + a tau^2 / 2 + j tau^3 / 6 (exact for the
//   interpolator's closed-form jerk-limited pieces up to the next jerk switch); the joints at
//   tau = 0, +-h, +-2h (h = kJointStageStep) give q', q'', q''' by central differences:
//     q'   = (q(h) - q(-h)) / 2h,            q'' = (q(h) - 2 q(0) + q(-h)) / h^2,
//     q''' = (q(2h) - 2 q(h) + 2 q(-h) - q(-2h)) / 2h^3,
//   errors O(h^2) in the truncation and ~eps |q| / h^3 in the rounding (0.02 deg/s^3 at
//   |q| = 100 deg): far below any joint limit. At standstill (v = a = j = 0) q', q'', q''' are 0.
// Errors: step() returns false (never throws; the per-cycle path) when the transform fails at
//   one of the five points; failed_point() then holds the Cartesian point: the caller stops
//   the channel with the kinematic's error (NC3201 workspace) at the active block's line.
// Invariants: no allocation after construction; deterministic; q equals IK(x) bit for bit.

#include <cstddef>

#include "ipo/interpolator.hpp"
#include "planner/joint_limits.hpp"

namespace ncsim::ipo {

using planner::AxisVec;

/// Time step of the stage's central differences [s].
inline constexpr double kJointStageStep = 1e-4;

/// One cycle's joint setpoints (joint i at index i, joint units: deg or mm).
struct JointSetpoint {
  AxisVec q{};  ///< position [deg | mm]
  AxisVec v{};  ///< velocity [deg/s | mm/s]
  AxisVec a{};  ///< acceleration [deg/s^2 | mm/s^2]
  AxisVec j{};  ///< jerk [deg/s^3 | mm/s^3]
};

class JointStage {
 public:
  /// `inverse` maps a Cartesian point to `joint_count` joint values (1..kMaxAxes). Throws
  /// std::invalid_argument on an empty map or a joint count outside 1..kMaxAxes.
  JointStage(planner::JointMap inverse, std::size_t joint_count);

  /// The joints of the Cartesian state (x, v, a, j) [mm, mm/s, mm/s^2, mm/s^3]. False when the
  /// transform fails (see failed_point()); `out` is then unchanged. Never throws.
  bool step(const AxisVec& x, const AxisVec& v, const AxisVec& a, const AxisVec& j,
            JointSetpoint& out) const noexcept;

  std::size_t joint_count() const noexcept { return n_; }
  /// The inverse transform the stage maps with.
  const planner::JointMap& inverse() const noexcept { return inverse_; }
  /// The Cartesian point at which the last failing step() could not be transformed [mm].
  const AxisVec& failed_point() const noexcept { return failed_; }

 private:
  planner::JointMap inverse_;
  std::size_t n_ = 0;
  mutable AxisVec failed_{};
};

/// Whether cycle `c` runs under the transform (#TRAFO ON): its programmed block's
/// Move::transformed for a motion cycle; otherwise (dwell, exact stop, starved) the state of the
/// cycle before, `last`. The path stands at every switch (docs/ipo.md "Kinematics in run and
/// time"), so no cycle mixes the two.
inline bool transformed(const Cycle& c, bool last) noexcept {
  return c.activity == Activity::motion && c.programmed != nullptr ? c.programmed->transformed
                                                                   : last;
}

}  // namespace ncsim::ipo
