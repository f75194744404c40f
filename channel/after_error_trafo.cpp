// channel/after_error_trafo: the after-error stop's `tcp` case, a run-time error raised while
// synchronised under #TRAFO ON (sync-trafo, issue 14; seed 004 §2.3 l.492-498, §2.2 l.609,
// l.687; tracking/sync_error_trafo.hpp; docs/conveyor.md "Errors while synchronised", "Under
// #TRAFO ON").
//
// Flow: as the `axes` case (after_error.cpp), but the stop acts on the TCP: every cycle the path's
// PCS1 point (braking to 0 by the feed hold) plus the belt's offset is the TCP
// (KinematicStage::map), and a SyncErrorStop over the TCP's X, Y, Z (the conveyor workspace's
// faces as their limits, dynamics derived from the joints' at the points the following passes)
// decides when it must brake and brakes it, each Cartesian coordinate jerk-limited to rest, so
// that the TCP leaves the belt on its own line (Z does not move towards the belt). The joints
// come from the braking TCP by the joint stage. The joints themselves are watched too (the axes'
// SyncErrorStop on the joint setpoints): a joint that following would take above its V or whose
// own stop would pass its soft limit starts the TCP's stop as well.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "channel/after_error.hpp"
#include "core/number_text.hpp"
#include "tracking/sync_error_trafo.hpp"

namespace ncsim::channel {

bool AfterErrorStop::begin_tcp() noexcept {
  joint_ = -1;
  if (!kin_.configured()) return false;
  const std::size_t n = std::min(axes_.size(), sync_->axis_count());
  std::array<int, 3> xyz{-1, -1, -1};
  std::array<tracking::AfterErrorAxis, planner::kMaxAxes> joints{};
  planner::AxisVec p{};
  for (std::size_t i = 0; i < n; ++i) {
    if (const int k = sync_->xyz(i); k >= 0 && k < 3)
      xyz[static_cast<std::size_t>(k)] = static_cast<int>(i);
    // The tighter of the joint's feed / G00 limits (the audit's) and its PTP dynamics.
    tracking::AfterErrorAxis a = axes_stop_.limits(i);
    const axes::Dynamics& d = sync_->dynamics(i);
    a.v_max = std::min(a.v_max, d.v_max);
    a.a_max = std::min(a.a_max, d.a_max);
    a.d_max = std::min(a.d_max, d.d_max);
    a.j_max = std::min(a.j_max, d.j_max);
    joints[i] = a;
    p[i] = kin_.tcp()[i].p;
  }
  // A TCP beyond a face of the workspace already (NC9052 / NC9053 themselves, a listing whose
  // working height is outside it): the limit is passed, the run ends at once as in the
  // Cartesian case of an axis beyond its soft limit (docs/conveyor.md).
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz[k] < 0) return false;
    const double x = p[static_cast<std::size_t>(xyz[k])];
    if (x < box_.lower[static_cast<int>(k)] || x > box_.upper[static_cast<int>(k)]) return false;
  }
  Eigen::Vector3d dir = sync_->frame().direction();
  if (sync_->belt_velocity() < 0.0) dir = -dir;
  const auto lim = tracking::tcp_after_error_axes(kin_.stage().inverse(), xyz,
                                                  std::span(joints.data(), n), box_, dir, p);
  if (!lim || !tcp_stop_.configure(std::span(lim->data(), n), ipo_.t_cycle())) return false;
  tcp_stop_.begin();
  case_ = Case::tcp;
  return true;
}

std::string AfterErrorStop::tcp_note() const {
  static constexpr const char* kXyz[3] = {"X", "Y", "Z"};
  std::string what;
  if (joint_ >= 0) {
    const auto i = static_cast<std::size_t>(joint_);
    what = "the TCP braked: joint " + axes_.config(i).name + " " +
           (joint_why_ == tracking::AfterErrorEnd::velocity
                ? "would have exceeded its maximum velocity following the belt"
                : "would have passed its soft limit");
  } else if (tcp_stop_.why() == tracking::AfterErrorEnd::soft_limit && tcp_stop_.axis() >= 0) {
    const auto i = static_cast<std::size_t>(tcp_stop_.axis());
    const int k = sync_ ? sync_->xyz(i) : -1;
    const tracking::AfterErrorAxis& l = tcp_stop_.limits(i);
    const double p = kin_.tcp()[i].p;
    const bool up = std::fabs(l.soft.max_position - p) < std::fabs(p - l.soft.min_position);
    static constexpr const char* kUpper[3] = {"00859", "00861", "00863"};
    static constexpr const char* kLower[3] = {"00860", "00862", "00864"};
    const std::size_t kk = k >= 0 && k < 3 ? static_cast<std::size_t>(k) : 0;
    what = std::string("the TCP braked before the conveyor workspace's ") + kXyz[kk] + " face " +
           core::human(up ? l.soft.max_position : l.soft.min_position) + " mm (P-CHAN-" +
           (up ? kUpper[kk] : kLower[kk]) + "), standing at " + core::human(p) + " mm";
  } else if (tcp_stop_.why() == tracking::AfterErrorEnd::belt_stop) {
    what = "the TCP stood with the belt";
  } else {
    what = "the TCP braked after ncsim's longest following";
  }
  return "synchronisation kept after " + held_->id +
         " under #TRAFO ON (004 §2.3): the path braked to 0 in PCS1, the TCP followed the belt "
         "for " +
         core::human(tcp_stop_.followed()) + " s; " + what +
         "; it stood at t=" + core::human(end_t_) + " s" + passed_;
}

}  // namespace ncsim::channel
