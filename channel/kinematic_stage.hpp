#pragma once
// channel/kinematic_stage: the channel's mapping under #TRAFO ON (docs/ipo.md "Kinematics in
// run and time").
//
// Purpose: the path interpolator gives the TCP (X, Y, Z Cartesian, other axes as they are)
// with its closed-form v, a, j; the joint stage (ipo/joint_stage.hpp) turns them into the
// setpoints of the machine axes, which the position control and the monitors then act on:
// soft limits, lag and the exact-stop window are the joints'. A point the inverse transform
// cannot map (the adapter and the planner check every block before, so only a broken invariant
// of theirs gets here) stops the channel with the kinematic's workspace error NC3201.
// While the channel tracks the conveyor (catch-up, PCS1) the joints are checked against their
// dynamics (warning NC6210, tracking/trafo_sync.hpp), and the catch-up / departure is planned
// as a TCP motion with dynamics derived from the joints'.
// Inputs: the ChannelConfig's joint limits and forward map; per cycle the cycle, where the
// tracking holds the path, the ConveyorSync. Outputs: the joint setpoints (into the
// AxisStage), the TCP, the first NC6210.
// Invariants: noexcept per cycle; no allocation per cycle.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "ipo/joint_stage.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::channel {

class KinematicStage {
 public:
  /// Without `joints` (no kinematic) nothing is ever transformed. `sink` may be null.
  KinematicStage(const std::optional<planner::JointLimits>& joints, std::size_t axis_count,
                 planner::JointMap forward, ipo::Sink* sink);
  KinematicStage(const KinematicStage&) = delete;
  KinematicStage& operator=(const KinematicStage&) = delete;

  /// The interpolator's joint sink: passes joints on to the channel's sink and notes that one
  /// passed (a documented path step: NC6210's jerk stencil leaves it out, as the audit's does).
  ipo::Sink* relay() noexcept { return &relay_; }
  /// Passes a joint the channel itself makes (the catch-up's hand-over) through relay().
  void pass_joint(const ipo::Joint& joint) { relay_.on_joint(joint); }
  /// A kinematic is configured.
  bool configured() const noexcept { return stage_.has_value(); }
  /// Decides whether cycle `c` runs under #TRAFO ON (false without a kinematic).
  bool decide(const ipo::Cycle& c) noexcept {
    transformed_ = stage_ && ipo::transformed(c, transformed_);
    return transformed_;
  }
  /// The last cycle ran under #TRAFO ON.
  bool transformed() const noexcept { return transformed_; }
  const ipo::JointSetpoint& joints() const noexcept { return joints_; }
  /// The TCP setpoint of the last transformed cycle, in MCS [mm, mm/s, ...].
  const std::array<axes::Setpoint, planner::kMaxAxes>& tcp() const noexcept { return tcp_; }
  std::array<axes::Setpoint, planner::kMaxAxes>& tcp() noexcept { return tcp_; }
  const planner::JointMap& forward() const noexcept { return forward_; }
  const std::optional<RunTimeError>& warning() const noexcept { return warning_; }
  const ipo::JointStage& stage() const noexcept { return *stage_; }

  /// Cycle `c` under #TRAFO ON: the TCP (the path's point, or `hold` where a catch-up /
  /// departure left it, or the catch-up's setpoint, or the PCS1 point moved by the belt) to
  /// the joints, into `axes`' setpoints; false: NC3201 raised into `error`.
  /// `t_cycle` [s].
  bool map(const ipo::Cycle& c, const std::optional<planner::AxisVec>& hold,
           const tracking::ConveyorSync* sync, double t_cycle, AxisStage& axes,
           std::optional<RunTimeError>& error) noexcept;
  /// The joints of TCP setpoint tcp() into `axes`' setpoints; false: out of reach.
  bool map_tcp(AxisStage& axes) noexcept;
  /// The catch-up / departure under #TRAFO ON: the TCP's dynamics from the joints
  /// (tracking/trafo_sync); `feed_cont` [mm/s] the catch-up's relative velocity at the meeting
  /// (S-1). False: the plan failed (`r` holds why).
  bool plan_sync_motion(tracking::ConveyorSync& sync, bool catch_up,
                        std::span<const axes::MotionState> start, std::span<const double> target,
                        double feed_cont, axes::Result& r) const noexcept;

 private:
  /// Passes the interpolator's joints on at once; cycles are passed on by the channel.
  class JointRelay final : public ipo::Sink {
   public:
    explicit JointRelay(ipo::Sink* sink) : sink_(sink) {}
    void on_joint(const ipo::Joint& joint) override {
      seen_ = true;
      if (sink_) sink_->on_joint(joint);
    }
    void on_cycle(const ipo::Cycle&) override {}
    /// A joint passed since the last call.
    bool take_seen() noexcept { return std::exchange(seen_, false); }

   private:
    ipo::Sink* sink_;
    bool seen_ = false;
  };
  /// Checks the joints of a synchronised cycle (NC6210 warning).
  void check_sync(const ipo::Cycle& c, const ipo::JointSetpoint& s,
                  const tracking::ConveyorSync& sync, double t_cycle,
                  const AxisStage& axes) noexcept;
  /// The joint setpoints' v and a by differences over this cycle and the two before (what the
  /// drives get and the audit measures); false until two consecutive transformed cycles ran.
  /// `jerk` true: out.j holds the third difference (three consecutive transformed cycles
  /// before, the stencil plain: q_plain_).
  bool differences(const ipo::Cycle& c, const ipo::JointSetpoint& s, std::size_t n, double t_cycle,
                   ipo::JointSetpoint& out, bool& jerk) const noexcept;

  JointRelay relay_;
  std::optional<ipo::JointStage> stage_;
  bool transformed_ = false;
  ipo::JointSetpoint joints_{};
  std::array<axes::Setpoint, planner::kMaxAxes> tcp_{};
  planner::JointMap forward_;            ///< ChannelConfig::forward
  std::optional<RunTimeError> warning_;  ///< the first NC6210 of the run
  /// The joint positions of the three cycles before (q at index - 1, - 2, - 3) and how many of
  /// them are of consecutive transformed cycles: NC6210 checks the setpoints' differences.
  planner::AxisVec q_back1_{}, q_back2_{}, q_back3_{};
  std::uint64_t q_index_ = 0;
  int q_known_ = 0;
  /// This cycle and the two before were jerk-limited (Cycle::interval_jerk_limited) and passed
  /// no path joint: the third difference is checked.
  std::array<bool, 3> q_plain_{false, false, false};
};

}  // namespace ncsim::channel
