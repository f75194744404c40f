// ipo/synchro_lag: synchro_lag against the real workpiece (see the header).

#include "ipo/synchro_lag.hpp"

namespace ncsim::ipo {

double real_travel(const ConveyorSync& sync) noexcept {
  const SyncFrame& f = sync.frame();
  const conveyor::Port& port = *sync.port();
  const conveyor::LatchInfo& edge = port.last_latch();
  if (edge.workpiece == 0) return f.travel(port.actual().p);  // no truth known: the latch
  // The NC places the front edge at T0's origin at the latch; it really was at sensor_x.
  const double sensor_offset = f.direction().x() * (edge.sensor_x - f.t0().translation.x());
  return f.sign() * (port.actual().p - edge.true_position) + sensor_offset;
}

std::optional<double> tracking_lag(const ConveyorSync& sync, const Eigen::Vector3d& x_command,
                                   const Eigen::Vector3d& x_actual) noexcept {
  if (sync.port() == nullptr || !sync.moving_frame()) return std::nullopt;
  const SyncFrame& f = sync.frame();
  const Eigen::Vector3d p_pcs1 = f.to_pcs1(x_command, sync.travel());
  return synchro_lag(f, x_actual, p_pcs1, real_travel(sync));
}

}  // namespace ncsim::ipo
