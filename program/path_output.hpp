#pragma once
// program/path_output: the adapter's last stage, which every path Move passes (issue 14;
// docs/caxtrack.md, docs/conveyor.md "Static processing unit").
//
// Purpose: under #CAXTRACK ON the tracker (tracking/caxtrack.hpp) sets the tracking axis's
// values and may put a C-only turn block, after a 0 s Dwell that stops the path, before a Move;
// while a static unit (P-CHAN-00364 = 1) is synchronised, every block gets the belt feed
// (tracking/x_virtual.hpp) and the static unit's errors NC9100..NC9102 are raised at the
// block's line. A part that ends in a tolerance ball waits for the next path part (held part),
// so that both feeds can be raised for the ball; every joint of two parts without a ball is
// checked against the planner's link (joint_belt_check).
// Inputs: path Moves in program order (emit()), #CAXTRACK, #SYNC IN / OUT, path stops.
// Outputs: the items queued for the interpolator (pop()), handed out before the next command.
// Invariants: the queue is empty before each command is pulled (ProgramSource::pull); one
// command queues the parts of at most 4 spline pieces.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "interp/command.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "program/machine_axes.hpp"
#include "program/source_errors.hpp"
#include "tracking/caxtrack.hpp"
#include "tracking/x_virtual.hpp"

namespace ncsim::program {

class PathOutput {
 public:
  /// `machine`, `layout` and `errors` must outlive this; `t_cycle` [s] is the run's cycle (the
  /// static unit's joint check asks the planner's link rules at it).
  PathOutput(const machines::Machine& machine, const AxisLayout& layout, SourceErrors& errors,
             double t_cycle) noexcept
      : machine_(machine), layout_(layout), errors_(errors), t_cycle_(t_cycle) {}

  /// A path Move out: tracked under #CAXTRACK, given the belt feed under a static unit, queued.
  void emit(planner::Move mv);
  /// The oldest queued item into `out`; false when the queue is empty.
  bool pop(ipo::Item& out);
  /// #CAXTRACK ON / OFF: 120626 (a main axis), NC9103 (no tracking axis), NC6001 (ROTMODE
  /// other than 0 / 1, OPTALIGN, SCALEFACT, AXNR, START_STROKE, ANGPOS).
  void caxtrack(const interp::CaxTrack& c, std::uint32_t line);
  /// #SYNC IN / #SYNC OUT: the static unit's belt feed on / off; other commands pass.
  void on_command(const interp::CommandBody& body);
  /// A path stop (`what`: G04, #FLUSH) while the static unit is synchronised: NC9101.
  void check_stop(std::uint32_t line, const char* what) const;
  /// True while the static unit's last part waits for the next path part.
  bool holds_part() const noexcept { return xv_held_.has_value(); }
  /// The held part, as it is (the next command is no path block); its joint with the next part
  /// is still checked unless the path stops between them (path_stopped()).
  planner::Move release_part();
  /// The path stops (a Dwell or a ChannelWait went out): the last part meets no next part.
  void path_stopped() noexcept { xv_last_.reset(); }

 private:
  /// The #CAXTRACK stage (cax_ set): the Moves `mv` becomes (a turn block's stop Dwell queued
  /// first).
  std::vector<planner::Move> track(planner::Move mv);
  /// Without #CAXTRACK: after #CAXTRACK OFF the C axis stands where tracking left it, until a
  /// block moves it (c_hold_).
  void hold_c(planner::Move& mv);
  /// The static unit's stage: `m`'s parts with the belt feed, queued or held.
  void pass_static(planner::Move& m);
  /// Queues the held part (if any) as it is.
  void queue_held();

  const machines::Machine& machine_;
  const AxisLayout& layout_;
  SourceErrors& errors_;
  double t_cycle_;  ///< the run's interpolation cycle [s]
  /// Items not yet handed out (spline pieces, #CAXTRACK turn blocks, the static unit's parts).
  std::deque<ipo::Item> queue_;
  struct CaxState {
    tracking::CaxTrackParams params;
    int slot = -1;  ///< interpolated slot of the tracking axis
    std::optional<tracking::CaxTracker>
        tracker;  ///< built at the first Move (its start is the axis's)
  };
  std::optional<CaxState> cax_;
  std::optional<double> c_hold_;  ///< after OFF: where tracking left the axis [deg]
  int c_hold_slot_ = -1;
  std::optional<tracking::XVirtualParams> xv_;  ///< set while a static unit is synchronised
  std::vector<planner::AxisLimits> xv_limits_;  ///< the planner's limits (NC9100)
  planner::ChannelLimits xv_channel_;           ///< and its channel's (the joints)
  std::vector<std::string> xv_names_;           ///< interpolated axis names
  std::optional<double> xv_tangent_;            ///< XY tangent at the last block's end [deg]
  /// The last part of a block that ends in a tolerance ball (G61 / G261), held until the next
  /// path part is known (blend_belt_feed raises both feeds), then queued; handed out as it is
  /// before any other command's items (release_part()).
  std::optional<planner::Move> xv_held_;
  /// The last part queued with no ball after it, whose joint with the next part is checked
  /// (joint_belt_check).
  std::optional<planner::Move> xv_last_;
};

}  // namespace ncsim::program
