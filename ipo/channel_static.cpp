// ipo/channel_static: the static processing unit on the channel side (issue 14; seed 004
// §2.1.6; docs/conveyor.md "Static processing unit").
//
// The adapter plans every synchronised block of a static unit (P-CHAN-00364 = 1) with the feed
// whose X component is kXvPlanFactor * CONV_VEL (ipo/x_virtual.hpp). Each cycle while the
// channel tracks the belt, the path override is the belt's master velocity (filtered, delay
// compensated: what the PCS1 frame follows) over that planned velocity, so the path's X
// component equals the belt's and the virtual X stands still in MCS; "the feed rate ... cannot
// be influenced independently" (004 l.438): the operator's override is set aside until the
// tracking ends and then restored.

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ipo/channel.hpp"
#include "ipo/x_virtual.hpp"

namespace ncsim::ipo {

namespace {

/// Smallest override change passed on [1]: the belt's measurement noise must not replan the
/// path every cycle (2e-4 of 300 mm/s is 0.06 mm/s).
constexpr double kOverrideStep = 2e-4;

}  // namespace

void Channel::static_override() noexcept {
  if (!sync_ || !static_unit_) return;
  if (sync_->phase() != SyncPhase::tracking) {
    if (operator_override_) {
      try {
        ipo_.set_override(*operator_override_);  // it was accepted before: in range
      } catch (...) {
        std::abort();
      }
      operator_override_.reset();
    }
    return;
  }
  if (!operator_override_) operator_override_ = ipo_.override_factor();
  const double belt = sync_->frame().sign() * sync_->display().v_master_comp;  // [mm/s]
  const double planned = kXvPlanFactor * sync_->conv_vel();
  const double f = planned > 0.0 ? std::clamp(belt / planned, 0.0, 1.0) : 0.0;
  if (std::fabs(f - ipo_.override_factor()) > kOverrideStep ||
      (f == 0.0) != (ipo_.override_factor() == 0.0)) {
    try {
      ipo_.set_override(f);
    } catch (...) {
      std::abort();  // every override type accepts 0 .. 1
    }
  }
}

}  // namespace ncsim::ipo
