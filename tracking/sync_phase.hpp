#pragma once
// tracking/sync_phase: the phase of conveyor tracking in a cycle (ConveyorSync::phase()).
//
// Purpose: the one value the observers of the cycle stream (audit/workpiece_cycles) need from
// conveyor tracking, apart from ConveyorSync itself.

#include <cstdint>

namespace ncsim::tracking {

enum class SyncPhase : std::uint8_t {
  off,          ///< not synchronised: MCS
  waiting,      ///< after #SYNC IN, until the Port has a latch ("waiting for measured value")
  latched,      ///< PCS1 moves with the belt; the next G00/G01 is the catch-up
  catching_up,  ///< the catch-up profile runs
  tracking,     ///< synchronised: PCS1 blocks run on the moving frame
  leaving,      ///< after #SYNC OUT: MCS, the axes still move with the belt until the next motion
  departing,    ///< the desynchronisation PTP from the moving state to a fixed MCS target
};

}  // namespace ncsim::tracking
