#pragma once
// program/machine_axes: the machine's interpolated axes, as the adapter lays them out and as the
// interpolator's Config limits them.
//
// Purpose: one place that says which machine axes the path interpolator drives and in which
// order (interpolated order = machine order without spindles, encoder-only axes and the
// conveyor axis), and what the planner knows of them.
// Inputs: a machines::Machine. Outputs: interpolated_axes(), machine_config(), AxisLayout (the
// index maps every part of ProgramSource shares).
// Invariants: an AxisLayout has 1..planner::kMaxAxes axes (else its constructor throws);
// slot[axes[k]] == k; path_axes is never 0.

#include <array>
#include <cstdint>
#include <vector>

#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"

namespace ncsim::program {

/// Machine indices of the axes the path interpolator drives, in machine order: linear and
/// rotary axes; spindles, encoder-only axes and the conveyor axis are not interpolated.
std::vector<std::uint8_t> interpolated_axes(const machines::Machine& machine);

/// The interpolator Config of `machine` (docs/ipo.md "Machine limits"): per interpolated axis
/// v_max P-AXIS-00212, v_reference = v_max (no ISG key), v_rapid P-AXIS-00209,
/// A+ = min(P-AXIS-00001, P-AXIS-00008), A- = min(P-AXIS-00002, P-AXIS-00008),
/// J = Dynamics::jerk_feed(), C0 NCSIM-AXIS-020, G00 slope a_rapid = min(P-AXIS-00004,
/// P-AXIS-00008) and j_rapid = a_rapid / P-AXIS-00200 (Dynamics::jerk_rapid); ExactStop window
/// P-AXIS-00236, settling P-AXIS-00532 (0 when not monitored); window P-CHAN-00650 look-ahead
/// blocks; cycle `t_cycle` [s] (no list key: the manuals at hand name none, the cycle is the NC
/// SAF task's; the CLI's default is the seeds' 1 ms, docs/ipo.md "The cycle time").
ipo::Config machine_config(const machines::Machine& machine, double t_cycle);

/// The CLI's interpolation cycle when `--cycle-us` is not given [s].
inline constexpr double kDefaultCycle = 0.001;

/// The interpolated axes of a machine as index maps.
struct AxisLayout {
  /// Throws std::invalid_argument when `machine` has no interpolated axis or more than
  /// planner::kMaxAxes.
  explicit AxisLayout(const machines::Machine& machine);

  std::vector<std::uint8_t> axes;   ///< interpolated machine indices, in machine order
  std::vector<int> slot;            ///< machine index -> interpolated index, -1: not interpolated
  planner::AxisMask path_axes = 0;  ///< the linear interpolated axes (all when none is linear)
  std::array<int, 3> xyz{-1, -1, -1};  ///< machine indices of X, Y, Z (-1: none)

  /// Number of interpolated axes.
  std::uint8_t count() const noexcept { return static_cast<std::uint8_t>(axes.size()); }
  /// Interpolated index of X, Y or Z (`k` 0..2); -1 when the machine has none or it is not
  /// interpolated.
  int xyz_slot(std::size_t k) const noexcept {
    return xyz[k] < 0 ? -1 : slot[static_cast<std::size_t>(xyz[k])];
  }
};

}  // namespace ncsim::program
