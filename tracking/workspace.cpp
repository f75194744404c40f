// tracking/workspace: the conveyor workspace (see the header).

#include "tracking/workspace.hpp"

namespace ncsim::tracking {

namespace {

constexpr double kCos60 = 0.5;

WorkspaceFace face_of(int coord, bool upper, const Eigen::Vector3d& direction) noexcept {
  const double n_dot_e = upper ? direction[coord] : -direction[coord];
  if (n_dot_e > kCos60) return WorkspaceFace::conveying;
  if (n_dot_e < -kCos60) return WorkspaceFace::against;
  return WorkspaceFace::side;
}

}  // namespace

std::optional<WorkspaceViolation> check_workspace(const machines::Workspace& box,
                                                  const Eigen::Vector3d& direction,
                                                  const Eigen::Vector3d& p_mcs) noexcept {
  for (int k = 0; k < 3; ++k) {
    const bool above = p_mcs[k] > box.upper[k];
    if (!above && !(p_mcs[k] < box.lower[k])) continue;
    WorkspaceViolation v;
    v.coord = k;
    v.upper = above;
    v.value = p_mcs[k];
    v.limit = above ? box.upper[k] : box.lower[k];
    v.face = face_of(k, above, direction);
    return v;
  }
  return std::nullopt;
}

}  // namespace ncsim::tracking
