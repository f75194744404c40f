// ipo/channel_conveyor: the channel's conveyor tracking hooks (issue 14; docs/conveyor.md
// "Synchronisation"): the Channel members that conveyor-sync owns, kept out of channel.cpp.

#include <cstdlib>
#include <utility>

#include "ipo/channel.hpp"

namespace ncsim::ipo {

bool Channel::sync_check_workspace(const Cycle& c) noexcept {
  if (!sync_->synchronised()) return true;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (const int k = sync_->xyz(i); k >= 0) p[k] = setpoint_[i].p;
  try {
    if (auto e = sync_->workspace(p)) {
      stop(e->id.c_str(), std::move(e->message), c, -1);
      return false;
    }
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error
  }
  return true;
}

}  // namespace ncsim::ipo
