#include "program/belt_split.hpp"

#include <cmath>
#include <variant>

#include "tracking/sync_checks.hpp"
#include "tracking/sync_frame.hpp"

namespace ncsim::program {

void BeltSplit::on_command(const interp::CommandBody& body) {
  if (std::holds_alternative<interp::SyncOut>(body)) {
    belt_ = planner::AxisVec{};
    belt_dir_ = planner::AxisVec{};
    return;
  }
  const auto* in = std::get_if<interp::SyncIn>(&body);
  if (in == nullptr) return;
  belt_ = planner::AxisVec{};
  belt_dir_ = planner::AxisVec{};
  const auto& conveyor = machine_.channel.conveyor;
  if (!conveyor || conveyor->x_virtual) return;
  const Eigen::Vector3d e = tracking::SyncFrame(*conveyor).direction();
  for (std::size_t k = 0; k < 3; ++k) {
    const int slot = layout_.xyz_slot(k);
    if (slot < 0) continue;
    belt_[static_cast<std::size_t>(slot)] =
        tracking::pcs1_belt(e[static_cast<Eigen::Index>(k)], in->conv_vel);
    belt_dir_[static_cast<std::size_t>(slot)] = e[static_cast<Eigen::Index>(k)] * in->conv_vel;
  }
}

// 004 l.317-319: a line moves each axis one way. Along the belt's velocity on that axis the PCS0
// velocity is relative + belt: v_max - 1.10 CONV_VEL as before (S-5). Against it the PCS0
// velocity is relative - belt: the manual's v_max + v_conv with v_conv = CONV_VEL; a belt slower
// than CONV_VEL would push the axis above v_max, so the channel caps the path at run time
// (Channel::sync_belt_cap). An axis the line does not move keeps belt().
void BeltSplit::split(planner::Move& move) const noexcept {
  move.belt = belt_;
  for (std::size_t i = 0; i < move.belt.size(); ++i) {
    const double along = (move.end[i] - move.start[i]) * belt_dir_[i];
    if (along < 0.0) move.belt[i] = -std::fabs(belt_dir_[i]);
  }
}

}  // namespace ncsim::program
