// ipo/channel_workspace: the channel's side of the workspace hold against the conveying
// direction (ipo/workspace_hold.hpp; docs/conveyor.md "Workspace: the hold methods"): after
// each cycle the hold decides on the path state of that cycle, and its cap acts on the
// interpolator from the next one (PathInterpolator::set_velocity_cap, a jerk-limited replan).

#include "ipo/channel.hpp"

namespace ncsim::ipo {

void Channel::sync_workspace_cap(const Cycle& c) noexcept {
  HoldState st;
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
  }
  ipo_.set_velocity_cap(sync_->workspace_cap(st));
}

}  // namespace ncsim::ipo
