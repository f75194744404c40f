// ipo/program_kinematics: #KIN ID / #TRAFO ON / OFF at the adapter (docs/ipo.md "Kinematics in
// run and time").
//
// Under #TRAFO ON the interpreter gives X, Y, Z as the Cartesian TCP (re-based at the switch by
// the kinematic's forward / inverse transform); the Moves carry Move::transformed and the
// planner limits them by the joints (planner::Preparer::set_joints). Here:
// - a switch of #TRAFO (ON after OFF or OFF after ON) hands out a 0 s Dwell first: the path
//   stops at the block end before the switch, the rest of that cycle is dropped, and the next
//   Move starts from the transformed position (decision: the kernel's axes and TCP views cannot
//   both be interpolated across one cycle; 0 s costs no time beyond the stop itself);
// - only the machine's first kinematic (trafo[0]) is wired into the channel: #TRAFO ON with
//   another #KIN ID is NC6001 `not supported`;
// - a transformed Move is sampled along its path (the planner's spacing, planner::kJointSpacing)
//   through the inverse transform: a point outside the workspace or beyond a drive limit is the
//   kinematic's error (NC3201 / NC3202, machines/delta_kinematics.hpp) at the block's line, so
//   the program stops at the last good block with a positioned diagnostic.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ipo/program_source.hpp"
#include "planner/joint_limits.hpp"
#include "planner/path.hpp"

namespace ncsim::ipo {

void ProgramSource::fail_with(std::uint32_t line, const std::string& id, const std::string& what) {
  core::Diagnostic d;
  d.file = interp_.file_name(file_);
  d.loc = {line, 1};
  d.id = id;
  d.message = what;
  error_ = d;
  throw Stop{};
}

bool ProgramSource::kinematics(const interp::Kinematics& k, std::uint32_t line, Item& out) {
  if (k.trafo_on == trafo_on_) return false;  // #KIN ID alone, or no change
  if (k.trafo_on) {
    if (!trafo_) trafo_ = machine_trafo(machine_, machine_config(machine_, 0.001));
    if (!trafo_)
      fail(line, "#TRAFO ON: machine '" + machine_.name + "' has no kinematic ncsim can build");
    if (k.kin_id && *k.kin_id != trafo_->kin_id)
      fail(line, "#TRAFO ON with kinematic id " + std::to_string(*k.kin_id) +
                     " (the channel drives the machine's first kinematic, id " +
                     std::to_string(trafo_->kin_id) + ")");
  }
  trafo_on_ = k.trafo_on;
  out = Dwell{0.0, line};  // the path stands at the switch
  return true;
}

void ProgramSource::check_workspace(const planner::Move& move, std::uint32_t line) {
  if (!trafo_) fail(line, "motion under #TRAFO ON without a kinematic");
  const planner::Segment seg = planner::Segment::from_move(move);
  const double length = seg.length();
  const int n = std::clamp(static_cast<int>(std::ceil(length / planner::kJointSpacing)),
                           planner::kJointMinSamples, planner::kJointMaxSamples);
  const std::array<int, 3>& xyz = trafo_->xyz;
  // The target first (its error names the programmed point), then the path towards it.
  for (int i = 0; i <= n; ++i) {
    const int k = i == 0 ? n : i - 1;
    const double s = length * static_cast<double>(k) / n;
    const planner::AxisVec x = k == n ? move.end : seg.point(s);
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (std::size_t a = 0; a < 3; ++a)
      if (xyz[a] >= 0) p[static_cast<Eigen::Index>(a)] = x[static_cast<std::size_t>(xyz[a])];
    const machines::KinResult r = trafo_->kinematics->inverse(p);
    if (r.ok()) continue;
    char where[160];
    std::snprintf(where, sizeof where, "TCP X%.6g Y%.6g Z%.6g", p[0], p[1], p[2]);
    fail_with(line, r.error->id,
              std::string(k == n ? "target " : "path point ") + where +
                  " under #TRAFO ON (kinematic " + std::to_string(trafo_->kin_id) +
                  "): " + r.error->message);
  }
}

namespace {

constexpr double kBeltMargin = 1.1;      // 50653 lets the belt run 10 % above CONV_VEL
constexpr int kBeltShareSamples = 32;    // samples along the block, at most
constexpr int kBeltShareShifts = 9;      // belt positions across the workspace
constexpr double kBeltShareStep = 0.05;  // finite-difference step [mm]

}  // namespace

void ProgramSource::reserve_belt_share(planner::Move& move, std::uint32_t line) {
  if (!trafo_ || !machine_.channel.conveyor || move.rapid || move.block_time ||
      !(belt_conv_vel_ > 0.0))
    return;  // G00 keeps the joints' rapid rule, G93 its time (docs/conveyor.md)
  const machines::ConveyorSyncChannel& conv = *machine_.channel.conveyor;
  const Eigen::Vector3d dir = conv.t0().rotation.col(0);  // PCS0 +X in MCS
  const planner::Segment seg = planner::Segment::from_move(move);
  const double length = seg.length();
  if (!(length > 0.0)) return;
  const std::array<int, 3>& xyz = trafo_->xyz;
  const planner::JointMap& ik = trafo_->limits.inverse;
  const std::vector<planner::AxisLimits>& joints = trafo_->limits.joints;
  const double share_v = kBeltMargin * belt_conv_vel_;
  const int n = std::clamp(static_cast<int>(std::ceil(length / 5.0)), 4, kBeltShareSamples);
  double cap = move.feed;
  for (int k = 0; k <= n; ++k) {
    const double s = length * static_cast<double>(k) / n;
    const planner::AxisVec p = seg.point(s);
    const planner::AxisVec pa = seg.point(std::max(0.0, s - kBeltShareStep));
    const planner::AxisVec pb = seg.point(std::min(length, s + kBeltShareStep));
    const double ds = std::min(length, s + kBeltShareStep) - std::max(0.0, s - kBeltShareStep);
    // Where the belt may carry this point while synchronised: along the conveying direction
    // across the configured workspace (004 l.687: it must be configured under kinematics).
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    for (std::size_t a = 0; a < 3; ++a)
      if (xyz[a] >= 0) at[static_cast<Eigen::Index>(a)] = p[static_cast<std::size_t>(xyz[a])];
    double t_lo = 0.0, t_hi = 0.0;
    if (conv.workspace_configured) {
      t_lo = t_hi = 0.0;
      bool first = true;
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner((c & 1) ? conv.workspace.upper[0] : conv.workspace.lower[0],
                                     (c & 2) ? conv.workspace.upper[1] : conv.workspace.lower[1],
                                     (c & 4) ? conv.workspace.upper[2] : conv.workspace.lower[2]);
        const double t = (corner - at).dot(dir);
        t_lo = first ? t : std::min(t_lo, t);
        t_hi = first ? t : std::max(t_hi, t);
        first = false;
      }
    }
    for (int m = 0; m < kBeltShareShifts; ++m) {
      const double t =
          kBeltShareShifts == 1 ? 0.0 : t_lo + (t_hi - t_lo) * m / (kBeltShareShifts - 1);
      auto shifted = [&](planner::AxisVec x, double extra) {
        for (std::size_t a = 0; a < 3; ++a)
          if (xyz[a] >= 0)
            x[static_cast<std::size_t>(xyz[a])] += (t + extra) * dir[static_cast<Eigen::Index>(a)];
        return x;
      };
      planner::AxisVec qa{}, qb{}, qm{}, qp{};
      if (!ik(shifted(pa, 0.0), qa) || !ik(shifted(pb, 0.0), qb) ||
          !ik(shifted(p, -kBeltShareStep), qm) || !ik(shifted(p, kBeltShareStep), qp))
        continue;  // the belt cannot carry the block there (the run stops it: NC3201)
      for (std::size_t i = 0; i < joints.size(); ++i) {
        const double dq_ds = std::fabs(qb[i] - qa[i]) / ds;
        const double dq_belt = std::fabs(qp[i] - qm[i]) / (2.0 * kBeltShareStep);
        const double left = joints[i].v_max - share_v * dq_belt;
        if (!(left > 0.0)) {
          char what[260];
          std::snprintf(what, sizeof what,
                        "the belt at 1.1 x CONV_VEL (%.6g mm/s) alone needs %.6g of joint %s's "
                        "V %.6g (P-AXIS-00212) at TCP X%.6g Y%.6g Z%.6g (PCS1 moved %.6g mm "
                        "along the belt) under #TRAFO ON",
                        share_v, share_v * dq_belt, machine_.axes[axes_[i]].name.c_str(),
                        joints[i].v_max, at[0], at[1], at[2], t);
          fail_with(line, "NC6211", what);
        }
        if (dq_ds > 1e-12) cap = std::min(cap, left / dq_ds);
      }
    }
  }
  move.feed = cap;
}

}  // namespace ncsim::ipo
