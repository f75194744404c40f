#pragma once
// tracking/trafo_sync: conveyor tracking under #TRAFO ON (issue 14; seed 004 §2.2, l.266, l.454,
// l.609; docs/conveyor.md "Conveyor tracking under #TRAFO ON").
//
// Purpose: under a kinematic transform the catch-up after #SYNC IN and the departure after
// #SYNC OUT are TCP motions (004 l.609: "not planned at axis level but as TCP movements"); the
// manual leaves the joints' dynamics "not ensured". ncsim keeps them where it can: the TCP
// dynamics the catch-up is planned with are derived from the joints' own PTP dynamics at the
// points the motion passes, and every cycle the joints' setpoints are checked against those
// dynamics (a warning NC6210 names the first overrun; the audit lists them all). While machining
// in PCS1 (belt-jerk), belt_share() gives the belt's share of the joints' v, a and j on a block
// (the adapter's feed cap and the planner's lowered joint limits; see its note below).
// Inputs: the inverse transform (planner::JointMap over interpolated-axis vectors), the
// interpolated indices of the Cartesian X, Y, Z, one PTP Dynamics per joint (the machine
// axes' P-AXIS-00212 V, A+, A-, J), the TCP points to cover [mm].
// Outputs: one Dynamics for the Cartesian X, Y, Z of the TCP (the same V, A, J on each);
// the first joint overrun of a cycle; a block's BeltShare (or the joint it overloads).
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
#include <variant>

#include "axes/profile.hpp"
#include "ipo/joint_stage.hpp"
#include "planner/joint_limits.hpp"
#include "planner/path.hpp"

namespace ncsim::tracking {

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
                                           std::span<const planner::AxisVec> points) noexcept;

// Machining in PCS1 under #TRAFO ON (docs/conveyor.md "Machining in PCS1").
// A PCS1 block x(s) runs with the belt's travel b along the conveying direction e on top: the
// joints are q(s, b) = IK(x(s) + b e). With v = s', a = s'', j = s''' and the belt at constant
// velocity w = b' (a belt's own acceleration goes into the joints unreserved, l.454):
//   q'   = q_s v + q_b w
//   q''  = q_ss v^2 + q_s a + 2 q_sb v w + q_bb w^2
//   q''' = q_sss v^3 + 3 q_ss v a + q_s j + 3 q_ssb v^2 w + 3 q_sbb v w^2 + q_bbb w^3
//          + 3 q_sb a w
// (tcp_dynamics' chain rule, along the path and the belt instead of X, Y, Z). The planner keeps
// the terms without w inside each joint's limits with the path's derivatives at belt travel 0
// (planner/joint_limits.hpp); what the belt adds, and what those terms grow by where the belt
// carries the block, is the belt's share: a feed cap for the velocity, each joint's a and j
// lowered for the rest (belt_share(); planner::JointShare, planner::belt_joint_limits).

/// The joints' derivatives at a path point carried by the belt [deg | mm per mm^k]: of
/// q(a, b) = IK(x(s + a) + (shift + b) e) at a = b = 0, x the path's third-order Taylor
/// polynomial at the point.
struct PathBeltDerivatives {
  planner::AxisVec s{};    ///< dq/ds
  planner::AxisVec ss{};   ///< d2q/ds2
  planner::AxisVec sss{};  ///< d3q/ds3
  planner::AxisVec b{};    ///< dq/db
  planner::AxisVec sb{};   ///< d2q/ds db
  planner::AxisVec bb{};   ///< d2q/db2
  planner::AxisVec ssb{};  ///< d3q/ds2 db
  planner::AxisVec sbb{};  ///< d3q/ds db2
  planner::AxisVec bbb{};  ///< d3q/db3
};

/// The derivatives at `p` (a point of a curve over `axis_count` axes) moved by `shift` [mm]
/// along `e` (unit; MCS X, Y, Z at `xyz`), by central differences of step kTcpDynamicsStep on
/// 13 points; false when the transform fails at one of them. Never throws.
bool path_belt_derivatives(const planner::JointMap& inverse, std::array<int, 3> xyz,
                           const planner::PathPoint& p, std::size_t axis_count,
                           const std::array<double, 3>& e, double shift, std::size_t joint_count,
                           PathBeltDerivatives& out) noexcept;

/// Where and how fast the belt carries a PCS1 block.
struct BeltCarry {
  std::array<double, 3> e{1.0, 0.0, 0.0};  ///< conveying direction in MCS (T0's X), unit
  double v_belt = 0.0;                     ///< the belt velocity reserved for [mm/s]
  /// The configured conveyor workspace (P-CHAN-00859..00864; lower, upper corner) [mm]: each
  /// point of the block is sampled at kBeltShareShifts belt travels b >= 0 (the belt moves
  /// forward from the latch) up to where the belt carries it out of the workspace (the
  /// monitoring ends the run beyond: NC9052 / NC9053); nullopt: at belt travel 0 only.
  std::optional<std::array<std::array<double, 3>, 2>> workspace;
};

/// Samples along a block, at most (every 5 mm, at least 4).
inline constexpr int kBeltShareSamples = 32;
/// Belt travels per sample over the travel it can run at.
inline constexpr int kBeltShareShifts = 9;

/// What the belt takes of the joints on one PCS1 block.
struct BeltShare {
  double feed = 0.0;           ///< the block's feed, capped for the joints' V [mm/s]
  planner::JointShare joints;  ///< acceleration and jerk taken of each joint
};

/// A belt whose share leaves a joint nothing somewhere on the block, the path at rest.
struct BeltOverload {
  std::size_t joint = 0;
  char quantity = 'v';          ///< 'v' velocity, 'a' acceleration, 'j' jerk
  double needed = 0.0;          ///< the belt's share [deg/s^k | mm/s^k]
  double limit = 0.0;           ///< the joint's V, min(A+, A-) or J
  std::array<double, 3> tcp{};  ///< the block's point at belt travel 0 (MCS) [mm]
  double shift = 0.0;           ///< how far the belt carried it there [mm]
};

/// The belt's share of the joints on `segment` (the PCS1 block in MCS at belt travel 0, at
/// `feed` [mm/s]) under the joints' feed limits `joints`, sampled at up to kBeltShareSamples + 1
/// points x kBeltShareShifts belt travels (BeltCarry::workspace; method: docs/conveyor.md
/// "Machining in PCS1"), per joint i and sample c:
///  - feed <= (V_i - w |q_b|) / |q_s| (the velocity split);
///  - a_ic = (|q_ss| - m2)+ V^2 + 2 |q_sb| V w + |q_bb| w^2 + (|q_s| - m1)+ A,
///  - j_ic = (|q_sss| - m3)+ V^3 + 3 (|q_ss| - m2)+ V A + 3 |q_ssb| V^2 w + 3 |q_sbb| V w^2
///          + |q_bbb| w^3 + 3 |q_sb| A w + (|q_s| - m1)+ J,
///    a_i, j_i the maxima over c; m1, m2, m3 the largest |q_s|, |q_ss|, |q_sss| of joint i at
///    belt travel 0 (no larger than the planner's bounds); V an upper bound of the path's
///    velocity; A, J the largest path acceleration and jerk the lowered limits leave (the fixed
///    points A = min_ic (max(A+_i, A-_i) - a_ic|A=0) / (m1_i + (|q_s| - m1_i)+), likewise J).
/// Where a share takes more than half of a joint's min(A+, A-) or J (more than half of what it
/// leaves with the path at rest, if that is more), the feed is capped by bisection on V.
/// BeltOverload: the belt alone needs a joint's V, or its share with the path at rest (V = 0)
/// leaves less than 1 % of a joint's A or J. Samples at which the transform fails are skipped
/// (the run stops there with NC3201). Never throws.
std::variant<BeltShare, BeltOverload> belt_share(const planner::Segment& segment, double feed,
                                                 const planner::JointMap& inverse,
                                                 std::array<int, 3> xyz,
                                                 std::span<const planner::AxisLimits> joints,
                                                 const BeltCarry& carry) noexcept;

/// One joint beyond its dynamics in a cycle.
struct JointOverrun {
  std::size_t joint = 0;
  char quantity = 'v';  ///< 'v' velocity, 'a' acceleration, 'j' jerk
  double value = 0.0;   ///< |v| [deg/s | mm/s], |a| [deg/s^2 | mm/s^2] or |j| [deg/s^3 | mm/s^3]
  double limit = 0.0;   ///< the joint's V, max(A+, A-) or J
};

/// The first joint of `s` whose |v| exceeds V, |a| exceeds max(A+, A-) or, with `jerk`, |j|
/// exceeds J of `joints` (a relative tolerance of 1e-6 absorbs the joint stage's rounding).
/// `jerk` false: s.j is not checked (a slope or a difference stencil that is not
/// jerk-limited, or a stencil that holds a documented path step: the audit's exemptions).
/// Never throws.
std::optional<JointOverrun> joint_overrun(const ipo::JointSetpoint& s,
                                          std::span<const axes::Dynamics> joints,
                                          bool jerk = true) noexcept;

}  // namespace ncsim::tracking
