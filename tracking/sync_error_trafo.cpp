// tracking/sync_error_trafo: the TCP's stop after an error under #TRAFO ON (see the header).

#include "tracking/sync_error_trafo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "tracking/trafo_sync.hpp"

namespace ncsim::tracking {

namespace {

// How far the TCP can follow the belt from `p` along `dir` before a face of `box` [mm], >= 0.
double room_ahead(const machines::Workspace& box, const Eigen::Vector3d& dir,
                  const Eigen::Vector3d& p) noexcept {
  double room = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (dir[k] > kTiny) room = std::min(room, (box.upper[k] - p[k]) / dir[k]);
    if (dir[k] < -kTiny) room = std::min(room, (box.lower[k] - p[k]) / dir[k]);
  }
  return std::isfinite(room) ? std::max(room, 0.0) : 0.0;
}

}  // namespace

std::optional<std::array<AfterErrorAxis, planner::kMaxAxes>> tcp_after_error_axes(
    const planner::JointMap& inverse, std::array<int, 3> xyz,
    std::span<const AfterErrorAxis> joints, const machines::Workspace& box,
    const Eigen::Vector3d& direction, const planner::AxisVec& tcp) noexcept {
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  if (!inverse || n == 0) return std::nullopt;
  for (const int k : xyz)
    if (k < 0 || static_cast<std::size_t>(k) >= n) return std::nullopt;
  Eigen::Vector3d p;
  for (std::size_t k = 0; k < 3; ++k)
    p[static_cast<int>(k)] = tcp[static_cast<std::size_t>(xyz[k])];
  // The points the following passes: the TCP, then along the belt up to the face ahead; a point
  // the transform cannot map ends the samples (the joints' check stops the TCP before it).
  std::array<planner::AxisVec, kTcpFollowSamples> points{};
  std::size_t count = 0;
  const double room = room_ahead(box, direction, p);
  for (std::size_t s = 0; s < kTcpFollowSamples; ++s) {
    const double d = room * static_cast<double>(s) / static_cast<double>(kTcpFollowSamples - 1);
    planner::AxisVec x = tcp;
    for (std::size_t k = 0; k < 3; ++k)
      x[static_cast<std::size_t>(xyz[k])] += d * direction[static_cast<int>(k)];
    planner::AxisVec q{};
    bool ok = false;
    try {
      ok = inverse(x, q);
    } catch (...) {
      ok = false;
    }
    if (!ok) break;
    points[count++] = x;
    if (room == 0.0) break;
  }
  if (count == 0) return std::nullopt;
  std::array<axes::Dynamics, planner::kMaxAxes> dyn{};
  for (std::size_t i = 0; i < n; ++i)
    dyn[i] = axes::Dynamics{joints[i].v_max, joints[i].a_max, joints[i].d_max, joints[i].j_max};
  const auto d =
      tcp_dynamics(inverse, xyz, std::span(dyn.data(), n), std::span(points.data(), count));
  if (!d) return std::nullopt;
  std::array<AfterErrorAxis, planner::kMaxAxes> out{};
  for (std::size_t i = 0; i < n; ++i)
    out[i] = joints[i];  // an axis beside the TCP (a gripper C) keeps its own
  for (std::size_t k = 0; k < 3; ++k) {
    AfterErrorAxis& a = out[static_cast<std::size_t>(xyz[k])];
    a.soft.min_enabled = a.soft.max_enabled = true;
    a.soft.min_position = box.lower[static_cast<int>(k)];
    a.soft.max_position = box.upper[static_cast<int>(k)];
    a.v_max = kTcpFollowVelocity;
    a.a_max = a.d_max = std::min(d->a_max, d->d_max);
    a.j_max = d->j_max;
  }
  return out;
}

}  // namespace ncsim::tracking
