#pragma once
// ipo/trafo_sync: conveyor tracking under #TRAFO ON (issue 14; seed 004 §2.2, l.266, l.454,
// l.609; docs/conveyor.md "Conveyor tracking under #TRAFO ON").
//
// Purpose: under a kinematic transform the catch-up after #SYNC IN and the departure after
// #SYNC OUT are TCP motions (004 l.609: "not planned at axis level but as TCP movements"); the
// manual leaves the joints' dynamics "not ensured". ncsim keeps them where it can: the TCP
// dynamics the catch-up is planned with are derived from the joints' own PTP dynamics at the
// points the motion passes, and every cycle the joints' setpoints are checked against those
// dynamics (a warning NC6210 names the first overrun; the audit lists them all).
// Inputs: the inverse transform (planner::JointMap over interpolated-axis vectors), the
// interpolated indices of the Cartesian X, Y, Z, one PTP Dynamics per joint (the machine
// axes' P-AXIS-00212 V, A+, A-, J), the TCP points to cover [mm].
// Outputs: one Dynamics for the Cartesian X, Y, Z of the TCP (the same V, A, J on each);
// the first joint overrun of a cycle.
// Method (docs/conveyor.md): at each point the Jacobian J (dq_i/dx_k), the second
// derivatives H (d2q_i/dx_k dx_l) and the third derivatives T (d3q_i/dx_k dx_l dx_m) by
// nested central differences (step kTcpDynamicsStep). For a TCP motion x(t) the chain rule
// gives q' = J x', q'' = J x'' + H(x', x'), q''' = J x''' + 3 H(x', x'') + T(x', x', x'), so
// with each Cartesian axis inside |x'| <= V, |x''| <= A, |x'''| <= Jx:
//   |q_i'|   <= r_i V,                               r_i = sum_k |J_ik|,
//   |q_i''|  <= r_i A + c_i V^2,                     c_i = sum_kl |H_ikl|,
//   |q_i'''| <= r_i Jx + 3 c_i V A + d_i V^3,        d_i = sum_klm |T_iklm|.
// V = min_i min(vq_i / r_i, sqrt(aq_i / (2 c_i)), cbrt(jq_i / (kTcpJerkCubeShare d_i))),
// A = min_i min((aq_i - c_i V^2) / r_i, (jq_i - d_i V^3) / (6 c_i V)),
// Jx = min_i (jq_i - 3 c_i V A - d_i V^3) / r_i, each the minimum over the points (every bound
// grows with V, A, Jx, so the minima keep it at every point).
// Invariants: never throws; nullopt when the transform fails at a point or a limit is not
// positive. Between the points the bounds are not guaranteed (the per-cycle check reports).

#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "axes/profile.hpp"
#include "ipo/joint_stage.hpp"
#include "planner/joint_limits.hpp"

namespace ncsim::ipo {

/// Warning id: a joint exceeded its PTP dynamics while the TCP was synchronised or caught up
/// under #TRAFO ON (004 l.454, l.609: the joint dynamics are not ensured there).
inline constexpr const char* kTrafoSyncOverrunId = "NC6210";

/// Finite-difference step of the Jacobian and its derivatives [mm].
inline constexpr double kTcpDynamicsStep = 0.05;

/// The TCP's V leaves the velocity-cube term d_i V^3 at most 1 / kTcpJerkCubeShare of a
/// joint's jerk (the rest is shared by the 3 c_i V A and r_i Jx terms) [1].
inline constexpr double kTcpJerkCubeShare = 4.0;

/// The TCP dynamics (V [mm/s], A+ = A- [mm/s^2], J [mm/s^3]) under which every joint keeps its
/// `joints` dynamics at each of `points` (method in the header). Never throws.
std::optional<axes::Dynamics> tcp_dynamics(const planner::JointMap& inverse, std::array<int, 3> xyz,
                                           std::span<const axes::Dynamics> joints,
                                           std::span<const AxisVec> points) noexcept;

/// One joint beyond its dynamics in a cycle.
struct JointOverrun {
  std::size_t joint = 0;
  char quantity = 'v';  ///< 'v' velocity, 'a' acceleration
  double value = 0.0;   ///< |q'| [deg/s | mm/s] or |q''| [deg/s^2 | mm/s^2]
  double limit = 0.0;   ///< the joint's V or max(A+, A-)
};

/// The first joint of `s` whose |v| exceeds V or |a| exceeds max(A+, A-) of `joints` (a
/// relative tolerance of 1e-6 absorbs the joint stage's rounding). Never throws.
std::optional<JointOverrun> joint_overrun(const JointSetpoint& s,
                                          std::span<const axes::Dynamics> joints) noexcept;

}  // namespace ncsim::ipo
