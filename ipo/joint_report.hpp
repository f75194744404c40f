#pragma once
// ipo/joint_report: the joints the path passes, told to the Sink (Detail::axes).
//
// Purpose: describe each joint the path passes for the audit: the joint between two planned
// segments (its class, stop, link rule, the axis velocity and acceleration steps at the
// velocity and acceleration the path arrives with, and under #TRAFO ON the joints' steps),
// and the knees inside a chain (planner/corner.hpp), bounded by the chain's caps.
// Inputs: the segments, the programmed Moves (SegmentQueue::programmed), the axis count,
// P-CHAN-00009 (ChannelLimits::limit_c1_by_jerk), the joint limits under #TRAFO ON.
// Outputs: Joint records to the Sink, in path order; nothing without a Sink or with
// Detail::path.
// Invariants: pure evaluation apart from the Sink calls; nothing here throws.

#include <cstddef>
#include <optional>

#include "ipo/cycle.hpp"
#include "ipo/segment_queue.hpp"
#include "planner/lookahead.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

class JointReport {
 public:
  /// `sink` may be null (no reports); `queue` and `joints` must outlive the part.
  JointReport(Sink* sink, Detail detail, const SegmentQueue& queue, std::size_t axis_count,
              bool c1_limited, const std::optional<planner::JointLimits>& joints) noexcept
      : sink_(detail == Detail::axes ? sink : nullptr),
        queue_(queue),
        axis_count_(axis_count),
        c1_limited_(c1_limited),
        joints_(joints) {}
  JointReport(const JointReport&) = delete;
  JointReport& operator=(const JointReport&) = delete;

  /// The joint between `in` (ending) and `out` (starting) at time `t` [s], passed at path
  /// velocity `v` [mm/s] and acceleration `a` [mm/s^2].
  void between(const planner::PlannedSegment& in, const planner::PlannedSegment& out, double t,
               double v, double a) const noexcept;
  /// The knees inside `entry`'s chain passed in (s_from, s_to] [mm], reported at time `t` [s],
  /// with the path velocity and acceleration at most `v` [mm/s] and `a` [mm/s^2] there (the
  /// ceilings of the plan followed: above the chain's caps under an override above 100 %).
  void inner(const planner::PlannedSegment& entry, double s_from, double s_to, double t, double v,
             double a) const noexcept;

 private:
  Sink* sink_ = nullptr;  ///< null: no reports (no Sink, or Detail::path)
  const SegmentQueue& queue_;
  std::size_t axis_count_ = 0;
  bool c1_limited_ = true;  ///< P-CHAN-00009 (ChannelLimits::limit_c1_by_jerk)
  const std::optional<planner::JointLimits>& joints_;
};

}  // namespace ncsim::ipo
