// ipo/channel_lag: Channel::master_display(), the conveyor display variables of the last cycle
// with synchro_lag (line; ipo/synchro_lag.hpp, docs/conveyor.md "synchro_lag sign").

#include "ipo/channel.hpp"
#include "ipo/synchro_lag.hpp"

namespace ncsim::ipo {

MasterDisplay Channel::master_display() const noexcept {
  if (!sync_) return MasterDisplay{};
  MasterDisplay d = sync_->display();
  // Under #TRAFO the setpoints are joints, not X/Y/Z: no synchro_lag there (0).
  if (transformed_) return d;
  Eigen::Vector3d command = Eigen::Vector3d::Zero();
  Eigen::Vector3d actual = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (const int k = sync_->xyz(i); k >= 0) {
      command[k] = setpoint_[i].p;
      actual[k] = state_.actual[i];
    }
  }
  if (const auto lag = tracking_lag(*sync_, command, actual)) d.synchro_lag = *lag;
  return d;
}

}  // namespace ncsim::ipo
