#pragma once
// tracking/belt_offset: the belt's share of the axes in one cycle (--- conveyor).
//
// Purpose: the value the channel loop publishes each cycle (Channel::belt_share()) and the
// audit reads (Audit::set_belt()) to tell the axes' own motion from the belt's.
// Invariants: a plain value; `share` is meaningful only while `following`.

#include "planner/move.hpp"

namespace ncsim::tracking {

/// The belt's share of the axes in the cycle just played (Channel::belt_share()).
struct BeltOffset {
  bool following = false;     ///< the axes move with the belt (catch-up, PCS1, leaving)
  double travel = 0.0;        ///< the master's travel since the latch [mm]
  double acceleration = 0.0;  ///< the master's acceleration in the setpoints [mm/s^2]
  planner::AxisVec share{};   ///< each axis's share of one mm of travel
};

}  // namespace ncsim::tracking
