// channel/channel_lag: Channel::master_display(), the conveyor display variables of the last cycle
// with synchro_lag (line; tracking/synchro_lag.hpp, docs/conveyor.md "synchro_lag sign").

#include "channel/channel.hpp"
#include "tracking/synchro_lag.hpp"

namespace ncsim::channel {

tracking::MasterDisplay Channel::master_display() const noexcept {
  if (!sync_) return tracking::MasterDisplay{};
  tracking::MasterDisplay d = sync_->display();
  const std::size_t n = axes_.size();
  if (const auto lag =
          tracking::cycle_lag(*sync_, std::span<const double>(axes_.state().command.data(), n),
                              std::span<const double>(axes_.state().actual.data(), n),
                              kin_.transformed(), &kin_.tcp(), kin_.forward()))
    d.synchro_lag = *lag;
  return d;
}

}  // namespace ncsim::channel
