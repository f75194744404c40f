// ipo/program_sync: the PCS1 velocity split of ProgramSource (issue 14; seed 004 l.311-319;
// docs/conveyor.md "Machining in PCS1: the velocity split").
//
// Purpose: while synchronised, every PCS1 block is planned with the axes' velocity limits
// lowered by what the conveyor takes of them (planner::Move::belt, planner::belt_limits).
// Inputs: the commands as they pass the adapter (#SYNC IN's CONV_VEL, #SYNC OUT), the
// machine's T0 (P-CHAN-00371..00373: the conveying direction in MCS) and X/Y/Z axes.
// Outputs: ProgramSource::belt_, per interpolated axis |share| x 1.10 x CONV_VEL [mm/s] from
// #SYNC IN to #SYNC OUT, 0 elsewhere.
// Invariants: never allocates; x_virtual (P-CHAN-00364) lowers nothing (no real X follows the
// belt: the static-saw helper's).

#include <variant>

#include "ipo/program_source.hpp"
#include "ipo/sync_checks.hpp"
#include "ipo/sync_frame.hpp"

namespace ncsim::ipo {

void ProgramSource::sync_belt(const interp::CommandBody& body) {
  if (std::holds_alternative<interp::SyncOut>(body)) {
    belt_ = planner::AxisVec{};
    return;
  }
  const auto* in = std::get_if<interp::SyncIn>(&body);
  if (in == nullptr) return;
  belt_ = planner::AxisVec{};
  const auto& conveyor = machine_.channel.conveyor;
  if (!conveyor || conveyor->x_virtual) return;
  const Eigen::Vector3d e = SyncFrame(*conveyor).direction();
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz_[k] < 0) continue;
    const int slot = slot_[static_cast<std::size_t>(xyz_[k])];
    if (slot < 0) continue;
    belt_[static_cast<std::size_t>(slot)] =
        pcs1_belt(e[static_cast<Eigen::Index>(k)], in->conv_vel);
  }
}

}  // namespace ncsim::ipo
