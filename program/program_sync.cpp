// program/program_sync: the PCS1 velocity split of ProgramSource (issue 14; seed 004 l.311-319;
// docs/conveyor.md "Machining in PCS1: the velocity split").
//
// Purpose: while synchronised, every PCS1 block is planned with the axes' velocity limits
// lowered by what the conveyor takes of them (planner::Move::belt, planner::belt_limits).
// Inputs: the commands as they pass the adapter (#SYNC IN's CONV_VEL, #SYNC OUT), the
// machine's T0 (P-CHAN-00371..00373: the conveying direction in MCS) and X/Y/Z axes.
// Outputs: ProgramSource::belt_, per interpolated axis |share| x 1.10 x CONV_VEL [mm/s] from
// #SYNC IN to #SYNC OUT, 0 elsewhere; --- belt-split: a line's Move::belt is -|share| x CONV_VEL
// on the axes it moves against the belt (split_belt).
// Invariants: never allocates; x_virtual (P-CHAN-00364) lowers nothing (no real X follows the
// belt: the static-saw helper's).

#include <cmath>
#include <variant>

#include "program/program_source.hpp"
#include "tracking/sync_checks.hpp"
#include "tracking/sync_frame.hpp"

namespace ncsim::ipo {

void ProgramSource::sync_belt(const interp::CommandBody& body) {
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
  const Eigen::Vector3d e = SyncFrame(*conveyor).direction();
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz_[k] < 0) continue;
    const int slot = slot_[static_cast<std::size_t>(xyz_[k])];
    if (slot < 0) continue;
    belt_[static_cast<std::size_t>(slot)] =
        pcs1_belt(e[static_cast<Eigen::Index>(k)], in->conv_vel);
    belt_dir_[static_cast<std::size_t>(slot)] = e[static_cast<Eigen::Index>(k)] * in->conv_vel;
  }
}

// --- belt-split (004 l.317-319): a line moves each axis one way. Along the belt's velocity on
// that axis the PCS0 velocity is relative + belt: v_max - 1.10 CONV_VEL as before (S-5).
// Against it the PCS0 velocity is relative - belt: the manual's v_max + v_conv with v_conv =
// CONV_VEL; a belt slower than CONV_VEL would push the axis above v_max, so the channel caps
// the path at run time (Channel::sync_belt_cap). An axis the line does not move keeps belt_.
void ProgramSource::split_belt(planner::Move& move) const noexcept {
  move.belt = belt_;
  for (std::size_t i = 0; i < move.belt.size(); ++i) {
    const double along = (move.end[i] - move.start[i]) * belt_dir_[i];
    if (along < 0.0) move.belt[i] = -std::fabs(belt_dir_[i]);
  }
}

}  // namespace ncsim::ipo
