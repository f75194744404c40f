// ipo/channel_workspace: the channel's side of the workspace hold against the conveying
// direction (ipo/workspace_hold.hpp; docs/conveyor.md "Workspace: the hold methods"): after
// each cycle the hold decides on the path state of that cycle, and its cap acts on the
// interpolator from the next one (PathInterpolator::set_velocity_cap, a jerk-limited replan).
// The hold looks across block ends: the active entry and the look-ahead window's next entries
// (PathInterpolator::queued_entry, at most kHoldAhead).

#include <array>
#include <cstdio>
#include <cstdlib>

#include "ipo/channel.hpp"

namespace ncsim::ipo {

bool Channel::sync_workspace_cap(const Cycle& c) noexcept {
  HoldState st;
  std::array<HoldEntry, kHoldAhead> ahead{};  // the look-ahead window's next entries
  const planner::PlannedSegment* e = ipo_.active_entry();
  if (c.activity == Activity::motion && e != nullptr && c.programmed != nullptr) {
    st.path = &e->segment.path;
    st.s = c.path.s;
    st.v = c.path.v;
    st.a = c.path.a;
    st.feed = c.feed;
    st.line = c.line;
    st.d_max = e->d_max;
    st.j_max = e->j_max;
    st.stops = e->segment.stop != planner::StopReason::none;
    for (std::size_t k = 0; k < ahead.size(); ++k) {
      const planner::PreparedSegment* next = ipo_.queued_entry(k);
      if (next == nullptr) break;
      ahead[k] = HoldEntry{&next->path, next->limits.v_programmed,
                           next->stop != planner::StopReason::none};
      st.ahead_count = k + 1;
    }
    st.ahead = ahead.data();
  }
  const double cap = sync_->workspace_cap(st);
  ipo_.set_velocity_cap(cap);
  // A belt that stops while the hold caps the path: the cap follows it to 0 and the tool waits
  // with the belt (it stands in MCS and on the workpiece); the belt's restart releases it. A
  // belt that never restarts ends the run after ncsim's wait limit with NC9081.
  const WorkspaceHold* h = sync_->hold();
  if (h != nullptr && h->capped() && cap == 0.0 && c.path.v == 0.0) {
    if (++hold_stood_ > measure_wait_cycles_max_) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "the belt stood for %.6g s (ncsim's limit) while the workspace hold "
                    "(P-AXIS-00555, hold_limit_vel_factor P-CHAN-00366) kept the tool at the "
                    "hold line %.6g mm: the belt was not restarted",
                    measured_value_wait_max_, h->config().line);
      try {
        stop(kHoldBeltStoodId, buf, c, -1);
      } catch (...) {
        std::abort();
      }
      return false;
    }
  } else {
    hold_stood_ = 0;
  }
  return true;
}

bool Channel::workspace_hold_waits() const noexcept {
  const WorkspaceHold* h = sync_ ? sync_->hold() : nullptr;
  return h != nullptr && h->capped() && h->cap() == 0.0;
}

}  // namespace ncsim::ipo
