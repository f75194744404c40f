#include "program/trafo_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/number_text.hpp"
#include "planner/blend.hpp"
#include "planner/joint_limits.hpp"

namespace ncsim::program {

namespace {

// A joint that moves more than this between two path samples (at most kJointSpacing apart)
// jumped: the inverse crossed its (-180, 180] range end [deg].
constexpr double kJointJump = 90.0;

}  // namespace

bool TrafoPath::select(const interp::Kinematics& k, std::uint32_t line, ipo::Item& out) {
  if (k.trafo_on == trafo_on_) return false;  // #KIN ID alone, or no change
  if (k.trafo_on) {
    if (!trafo_) trafo_ = machine_trafo(machine_, machine_config(machine_, t_cycle_));
    if (!trafo_)
      errors_.not_supported(
          line, "#TRAFO ON: machine '" + machine_.name + "' has no kinematic ncsim can build");
    if (k.kin_id && *k.kin_id != trafo_->kin_id)
      errors_.not_supported(line, "#TRAFO ON with kinematic id " + std::to_string(*k.kin_id) +
                                      " (the channel drives the machine's first kinematic, id " +
                                      std::to_string(trafo_->kin_id) + ")");
  }
  trafo_on_ = k.trafo_on;
  out = ipo::Dwell{0.0, line};  // the path stands at the switch
  return true;
}

void TrafoPath::on_command(const interp::CommandBody& body) noexcept {
  if (const auto* in = std::get_if<interp::SyncIn>(&body)) belt_conv_vel_ = in->conv_vel;
}

void TrafoPath::check_workspace(const planner::Move& move, std::uint32_t line) const {
  if (!trafo_) errors_.not_supported(line, "motion under #TRAFO ON without a kinematic");
  const planner::Segment seg = planner::Segment::from_move(move);
  const double length = seg.length();
  // Clamped as a double before the conversion: a huge length would overflow the int.
  const int n = static_cast<int>(std::fmin(
      std::fmax(std::ceil(length / planner::kJointSpacing), double{planner::kJointMinSamples}),
      double{planner::kJointMaxSamples}));
  const std::array<int, machines::kKinAxes>& slots = trafo_->slots;
  // The target first (its error names the programmed point), then the path towards it, whose
  // joints must move continuously: a rotary joint's range ends at +-180 deg (the inverse gives
  // (-180, 180]), so a jump between two samples is the path turning a joint across it.
  machines::KinAxes q_before{};
  for (int i = 0; i <= n; ++i) {
    const int k = i == 0 ? n : i - 1;
    const double s = length * static_cast<double>(k) / n;
    const planner::AxisVec x = k == n ? move.end : seg.point(s);
    machines::KinAxes p{};
    for (std::size_t a = 0; a < slots.size(); ++a)
      if (slots[a] >= 0) p[a] = x[static_cast<std::size_t>(slots[a])];
    const machines::KinAxesResult r = trafo_->kinematics->inverse_axes(p);
    // Built only for a message: the check runs on every sample of every transformed block.
    const auto where = [&p, this] {
      return "TCP X" + core::human(p[0]) + " Y" + core::human(p[1]) + " Z" + core::human(p[2]) +
             " under #TRAFO ON (kinematic " + std::to_string(trafo_->kin_id) + "): ";
    };
    if (!r.ok()) {
      errors_.raise(line, r.error->id,
                    std::string(k == n ? "target " : "path point ") + where() + r.error->message);
    }
    for (std::size_t a = 0; i > 1 && a < trafo_->kinematics->axis_count(); ++a) {
      if (std::abs(r.value[a] - q_before[a]) <= kJointJump) continue;
      errors_.raise(line, "NC3202",
                    "path point " + where() + "joint " + std::to_string(a + 1) +
                        " would turn across its +-180 deg range end (" + core::human(q_before[a]) +
                        " -> " + core::human(r.value[a]) + " deg)");
    }
    if (i > 0) q_before = r.value;
  }
}

namespace {

constexpr double kBeltMargin = 1.1;  // 50653 lets the belt run 10 % above CONV_VEL

}  // namespace

bool TrafoPath::belt_carry(tracking::BeltCarry& carry) const {
  if (!trafo_ || !machine_.channel.conveyor || !(belt_conv_vel_ > 0.0)) return false;
  const machines::ConveyorSyncChannel& conv = *machine_.channel.conveyor;
  const Eigen::Vector3d dir = conv.t0().rotation.col(0);  // PCS0 +X in MCS
  carry.e = {dir[0], dir[1], dir[2]};
  carry.v_belt = kBeltMargin * belt_conv_vel_;
  // Where the belt may carry the block while synchronised: forward from the latch to the
  // configured workspace's face (004 l.687: it must be configured under kinematics; belt_share).
  carry.workspace.reset();
  if (conv.workspace_configured)
    carry.workspace = {
        {{conv.workspace.lower[0], conv.workspace.lower[1], conv.workspace.lower[2]},
         {conv.workspace.upper[0], conv.workspace.upper[1], conv.workspace.upper[2]}}};
  return true;
}

tracking::BeltShare TrafoPath::belt_share_at(const planner::Segment& path, double feed,
                                             const planner::Move& at,
                                             std::span<const planner::AxisLimits> joints) const {
  tracking::BeltCarry carry;
  belt_carry(carry);
  const std::variant<tracking::BeltShare, tracking::BeltOverload> share =
      tracking::belt_share(path, feed, trafo_->limits.inverse, trafo_->xyz, joints, carry);
  if (const auto* over = std::get_if<tracking::BeltOverload>(&share)) {
    const std::string limit =
        over->quantity == 'v' ? "V " + core::human(over->limit) + " (P-AXIS-00212)"
        : over->quantity == 'a'
            ? "A " + core::human(over->limit) + " (the smaller of P-AXIS-00001 / 00002)"
            : "J " + core::human(over->limit) + " (P-AXIS-00001 / 00002 over their ramps)";
    errors_.raise_in(
        at.file, at.line, "NC6211",
        "the belt at 1.1 x CONV_VEL (" + core::human(carry.v_belt) + " mm/s) " +
            (over->quantity == 'v' ? "alone needs " : "takes ") + core::human(over->needed) +
            " of joint " + machine_.axes[layout_.axes[over->joint]].name + "'s " + limit +
            " at TCP X" + core::human(over->tcp[0]) + " Y" + core::human(over->tcp[1]) + " Z" +
            core::human(over->tcp[2]) + " (PCS1 moved " + core::human(over->shift) +
            " mm along the belt) under #TRAFO ON");
  }
  return std::get<tracking::BeltShare>(share);
}

namespace {

bool any_taken(const planner::AxisVec& x) {
  return std::any_of(x.begin(), x.end(), [](double y) { return y > 0.0; });
}

}  // namespace

void TrafoPath::reserve_belt_share(planner::Move& move) const {
  tracking::BeltCarry carry;
  if (!belt_carry(carry)) return;
  // G00 runs each joint at its rapid rule (000 l.360: MIN(rapid, reference,
  // maximum), the G00 slope; planner::path_limits): its share is taken of those limits, with
  // no programmed feed to cap (the cap goes into Move::feed, which the planner's joint limits
  // apply to a G00 in PCS1: planner/joint_limits.cpp).
  std::vector<planner::AxisLimits> rapid;
  if (move.rapid) {
    for (const planner::AxisLimits& j : trafo_->limits.joints)
      rapid.push_back(planner::joint_rapid_limits(j));
  }
  // G93 sets the path velocity by the block time (length / time, the
  // planner's programmed velocity, planner::path_limits): a lower cap makes the block longer.
  const planner::Segment path = planner::Segment::from_move(move);
  double feed = move.rapid ? std::numeric_limits<double>::infinity() : move.feed;
  if (move.block_time && *move.block_time > 0.0) feed = path.length() / *move.block_time;
  const tracking::BeltShare s =
      belt_share_at(path, feed, move,
                    move.rapid ? std::span<const planner::AxisLimits>(rapid)
                               : std::span<const planner::AxisLimits>(trafo_->limits.joints));
  if (move.block_time) {
    if (s.feed < feed) move.block_time = path.length() / s.feed;
  } else if (std::isfinite(s.feed)) {  // a G00 that moves no joint: no cap
    move.feed = s.feed;
  }
  // A G00 always carries its shares: they also mark its feed as the velocity share's cap.
  if (move.rapid || any_taken(s.joints.a) || any_taken(s.joints.j))
    move.belt_joints = std::make_shared<const planner::JointShare>(s.joints);
}

// The tolerance ball between two PCS1 blocks (docs/conveyor.md "Machining in PCS1", "The
// ball").
bool TrafoPath::holds_for_ball(const planner::Move& move, bool pcs1) const {
  tracking::BeltCarry carry;
  return move.transformed && pcs1 && planner::contoured(move) && !move.rapid && !move.block_time &&
         !move.exact_stop && move.transition != planner::Transition::stop_at_end &&
         belt_carry(carry);
}

void TrafoPath::reserve_ball_share(planner::Move& in, const planner::Move& out) const {
  if (!out.transformed || !trafo_) return;
  const planner::Segment in_path = planner::Segment::from_move(in);
  const planner::Segment out_path = planner::Segment::from_move(out);
  // As the planner builds it (planner::Preparer::push_path, planner::corner_blend): the ball of
  // radius PATH_DEV (DEV) or the PRE_DIST / POST_DIST curve (DIST), at most half of each block;
  // a block's start trimmed by the ball before it does not change the last half of it, where
  // this ball lies.
  const auto ball =
      planner::corner_blend(in, in_path, out_path, in_path.length() / 2, out_path.length() / 2);
  if (!ball) return;
  // The planner runs the ball at most at the slower of its neighbours' programmed feeds, with
  // the limits of the block before it (in's Move): the ball's share goes into in's.
  double feed = in.feed;
  if (!out.rapid && !out.block_time) feed = std::min(feed, out.feed);
  const tracking::BeltShare s = belt_share_at(ball->curve, feed, in, trafo_->limits.joints);
  planner::JointShare joints = in.belt_joints ? *in.belt_joints : planner::JointShare{};
  for (std::size_t i = 0; i < planner::kMaxAxes; ++i) {
    joints.a[i] = std::max(joints.a[i], s.joints.a[i]);
    joints.j[i] = std::max(joints.j[i], s.joints.j[i]);
  }
  in.feed = std::min(in.feed, s.feed);
  if (any_taken(joints.a) || any_taken(joints.j))
    in.belt_joints = std::make_shared<const planner::JointShare>(joints);
}

}  // namespace ncsim::program
