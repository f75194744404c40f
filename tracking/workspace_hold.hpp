#pragma once
// tracking/workspace_hold: the workspace limit against the conveying direction (seed 004 §2.1.3,
// §4.4.2, P-AXIS-00555, P-CHAN-00366, P-CHAN-00367, P-CHAN-00374; docs/conveyor.md
// "Workspace: the hold methods").
//
// Purpose: decide, once per cycle while synchronised, whether the path velocity must be capped
// at hold_limit_vel_factor x v_conv so that the TCP does not cross the hold line in MCS against
// the conveying direction: the simple method (P-AXIS-00555 = 0) caps the whole run of blocks
// against the conveying direction whose contour, run at its feeds, would cross the line; the
// optimised method (= 1) caps at the last cycle from which a jerk-limited braking ramp still
// reaches factor x v_conv before the line. Both look across block ends into the look-ahead
// window (tracking/hold_path: the rest of the active entry and up to kHoldAhead following entries;
// beyond them the worst case). The cap holds while the path runs against the conveying
// direction: at a block end it is kept when the new block moves against it, else released
// (and decided afresh in the same cycle). A path velocity <= v_conv never moves the TCP
// against the conveying direction in MCS (|dx/ds| <= 1), so once capped a line stands at the
// line (factor 1000) or drifts away (950), and an arc is pushed away.
// Inputs: HoldConfig (from the machine), per cycle HoldState (the active path chain, s, v, a,
// the line of the active block, the following look-ahead entries, the belt travel and
// velocity along the conveying direction).
// Outputs: the path velocity cap [mm/s] (+inf: none), which the channel gives the interpolator
// (PathOverride::set_velocity_cap: a jerk-limited replan, the override machinery), and the
// check of the line + P-CHAN-00367 on the commanded TCP (NC9080).
// Invariants: pure decisions on the inputs (deterministic); never throws; no allocation.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "machines/machine.hpp"
#include "planner/chain.hpp"
#include "tracking/hold_path.hpp"

namespace ncsim::tracking {

/// NC9080: the TCP passed the hold line against the conveying direction by more than
/// hold_limit_tolerance P-CHAN-00367 (or the workspace face) while synchronised.
inline constexpr const char* kWorkspaceHoldId = "NC9080";

enum class HoldMethod : std::uint8_t {
  simple,     ///< P-AXIS-00555 = 0: the crossing block runs at factor x v_conv
  optimised,  ///< P-AXIS-00555 = 1: braking so that v_path = factor x v_conv at the line
};

/// The hold line and its method, fixed per channel.
struct HoldConfig {
  HoldMethod method = HoldMethod::simple;
  double factor = 1.0;     ///< P-CHAN-00366 [fraction] in [0, 1]
  double tolerance = 0.0;  ///< P-CHAN-00367: allowed pass of the line before NC9080 [mm]
  int coord = 0;           ///< MCS coordinate of the against face (0, 1, 2: X, Y, Z)
  double sign = 1.0;       ///< +1: the conveying direction is +coord (the line is a lower bound)
  double share = 1.0;      ///< the belt's share on coord (direction()[coord]), |share| > 0.5
  double line = 0.0;       ///< the hold line in MCS [mm] (pos_limit or the face)
  double face = 0.0;       ///< the workspace face against the conveying direction [mm]
  int axis = -1;           ///< interpolated axis index of coord (-1: none: no hold)
};

/// The hold configuration of a conveyor channel: the against face of the cuboid whose outward
/// normal n has n.e < -cos 60 deg (none: nullopt), its line (P-CHAN-00374 pos_limit when set
/// and inside the cuboid, else the face), `optimised` from P-AXIS-00555, `axis` the
/// interpolated axis that is MCS coordinate `coord`.
std::optional<HoldConfig> hold_config(const machines::ConveyorSyncChannel& channel,
                                      const Eigen::Vector3d& direction, bool optimised,
                                      const int* xyz_of_axis, std::size_t axis_count) noexcept;

/// One cycle's inputs.
struct HoldState {
  const planner::Chain* path = nullptr;  ///< active entry's chain (PCS1), null: none
  double s = 0.0;                        ///< arc length on it [mm]
  double v = 0.0;                        ///< path velocity [mm/s]
  double a = 0.0;                        ///< path acceleration [mm/s^2]
  double feed = 0.0;                     ///< programmed feed of the active block [mm/s]
  std::uint32_t line = 0;                ///< source line of the active block
  double d_max = 0.0;                    ///< path deceleration of the entry [mm/s^2]
  double j_max = 0.0;                    ///< path jerk of the entry [mm/s^3]
  double travel = 0.0;                   ///< belt travel since the latch [mm]
  double belt_v = 0.0;                   ///< belt velocity along the conveying direction [mm/s]
  double t_cycle = 0.001;                ///< [s]
  bool stops = false;                    ///< the path stops at the end of the active entry
  const HoldEntry* ahead = nullptr;      ///< the following look-ahead entries, in path order
  std::size_t ahead_count = 0;           ///< entries at `ahead` (kHoldAhead are used at most)
};

class WorkspaceHold {
 public:
  static constexpr double kNone = std::numeric_limits<double>::infinity();

  explicit WorkspaceHold(const HoldConfig& config) noexcept : cfg_(config) {}

  /// The path velocity cap for the next cycle [mm/s] (kNone: none).
  double decide(const HoldState& st) noexcept;
  /// Releases the cap (not synchronised any more).
  void reset() noexcept {
    capped_ = false;
    cap_ = kNone;
  }
  bool capped() const noexcept { return capped_; }
  double cap() const noexcept { return cap_; }
  std::uint32_t capped_line() const noexcept { return line_; }
  const HoldConfig& config() const noexcept { return cfg_; }

  /// Signed distance of the MCS coordinate q [mm] to the line, > 0 inside.
  double inside(double q) const noexcept { return cfg_.sign * (q - cfg_.line); }
  /// NC9080 message when the commanded MCS coordinate q is beyond the line by more than the
  /// tolerance or beyond the face; nullopt otherwise.
  std::optional<std::string> check(double q) const;

  /// Simple method: the run against the conveying direction that starts at the active block
  /// or after the blocks before it (each block run at max(its feed, v), the belt at its
  /// velocity) crosses the line, and the cap must start now: at once when the run is the
  /// active block, else when braking to `target` from one cycle ahead no longer fits before
  /// the run starts.
  bool run_crosses(const HoldState& st, double target) const noexcept;
  /// Optimised method: a braking ramp from the state one cycle ahead would still keep the
  /// TCP inside (false: brake now).
  bool can_wait_a_cycle(const HoldState& st, double target) const noexcept;
  /// The rest of the active block moves against the conveying direction (in PCS1).
  bool active_block_against(const HoldState& st) const noexcept;

 private:
  HoldPath path_of(const HoldState& st) const noexcept;
  /// MCS distance to the line of the PCS1 coordinate q at time dt from now.
  double inside_at(const HoldState& st, double q, double dt) const noexcept;

  HoldConfig cfg_;
  bool capped_ = false;
  double cap_ = kNone;
  std::uint32_t line_ = 0;
};

}  // namespace ncsim::tracking
