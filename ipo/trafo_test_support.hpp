#pragma once
// ipo/trafo_test_support.hpp: the set-up the conveyor tests under #TRAFO ON share (tests only).

#include <Eigen/Core>

#include "interp/test_support.hpp"
#include "machines/machine.hpp"

namespace ncsim::ipo::test {

/// The delta picker with a conveyor workspace that holds its working height (the bundled
/// list's +-500 mm does not: programs/pick_and_place).
inline machines::Machine picker() {
  machines::Machine m = interp::test::machine("delta_picker");
  m.channel.conveyor->workspace.lower = Eigen::Vector3d(-600, -600, -900);
  m.channel.conveyor->workspace.upper = Eigen::Vector3d(600, 600, 0);
  return m;
}

}  // namespace ncsim::ipo::test
