// tracking/synchro_lag: synchro_lag against the real workpiece (see the header).

#include "tracking/synchro_lag.hpp"

#include <algorithm>

namespace ncsim::tracking {

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

std::optional<double> axes_lag(const ConveyorSync& sync, std::span<const double> command,
                               std::span<const double> actual, bool transformed) noexcept {
  if (transformed) return std::nullopt;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  const std::size_t n = std::min({sync.axis_count(), command.size(), actual.size()});
  for (std::size_t i = 0; i < n; ++i) {
    if (const int k = sync.xyz(i); k >= 0) {
      c[k] = command[i];
      a[k] = actual[i];
    }
  }
  return tracking_lag(sync, c, a);
}

std::optional<double> tcp_lag(const ConveyorSync& sync, std::span<const double> tcp,
                              const planner::AxisVec& joints,
                              const planner::JointMap& forward) noexcept {
  planner::AxisVec x{};
  if (!forward || !forward(joints, x)) return std::nullopt;
  return axes_lag(sync, tcp, std::span<const double>(x.data(), x.size()), false);
}

std::optional<double> cycle_lag(const ConveyorSync& sync, std::span<const double> command,
                                std::span<const double> actual, bool transformed,
                                const std::array<axes::Setpoint, planner::kMaxAxes>* tcp,
                                const planner::JointMap& forward) noexcept {
  if (!transformed) return axes_lag(sync, command, actual, false);
  if (tcp == nullptr) return std::nullopt;
  const std::size_t n = std::min({command.size(), actual.size(), tcp->size()});
  planner::AxisVec x{};
  planner::AxisVec q{};
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (*tcp)[i].p;
    q[i] = actual[i];
  }
  return tcp_lag(sync, std::span<const double>(x.data(), n), q, forward);
}

}  // namespace ncsim::tracking
