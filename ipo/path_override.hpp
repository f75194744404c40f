#pragma once
// ipo/path_override: what the operator and the channel ask of the path velocity at run time.
//
// Purpose: hold the path override factor (NCSIM-CHAN-630 type), the feed hold and a path
// velocity cap from outside (the workspace hold, issue 14), as they are set between cycles.
// Inputs: the setters below (scenario, channel, tests).
// Outputs: the factor the path follows (effective_factor(): 0 under feed hold) and the cap;
// the interpolator replans from the path state when either changes (docs/ipo.md "Override and
// feed hold"), with jerk-limited ramps.
// Invariants: the factor lies in [0, max_override(type)] (set_override() throws otherwise);
// the cap is >= 0 (+inf: none).

#include <limits>

#include "ipo/override.hpp"

namespace ncsim::ipo {

class PathOverride {
 public:
  explicit PathOverride(OverrideType type) noexcept : type_(type) {}

  /// Path override factor (1 = 100 %), in [0, max_override(type)]; takes effect from the next
  /// step() with jerk-limited ramps (after the tolerance ball if the path is inside one).
  /// Throws std::invalid_argument naming the value and NCSIM-CHAN-630 when out of range.
  void set_override(double factor);
  /// Feed hold: the path stops on the contour as soon as the ramps allow and holds until
  /// released (then it resumes at the override). Acts inside a tolerance ball too (a stop).
  void set_feed_hold(bool on) noexcept { hold_ = on; }
  /// Caps the path velocity [mm/s] (+inf: none) from the next step(): a jerk-limited replan
  /// from the path state as for an override change (also inside a tolerance ball); the entry
  /// that starts while capped starts capped. Negative or NaN values are taken as 0.
  void set_velocity_cap(double cap) noexcept { cap_ = cap >= 0.0 ? cap : 0.0; }
  double override_factor() const noexcept { return override_; }  ///< set factor [1]
  bool feed_hold() const noexcept { return hold_; }
  double velocity_cap() const noexcept { return cap_; }  ///< [mm/s]
  OverrideType override_type() const noexcept { return type_; }
  /// The factor the path follows [1]: 0 under feed hold, else the set one.
  double effective_factor() const noexcept { return hold_ ? 0.0 : override_; }

 private:
  OverrideType type_ = OverrideType::reduced;
  double override_ = 1.0;                                 ///< set factor [1]
  bool hold_ = false;                                     ///< feed hold requested
  double cap_ = std::numeric_limits<double>::infinity();  ///< velocity cap set [mm/s]
};

}  // namespace ncsim::ipo
