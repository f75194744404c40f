#pragma once
// axes/homing: NC-guided homing (G74) of one axis as a small state machine, pure data in and
// set values out. The sequence is the standard one of 000_* 7.2.4:
//   1. search_cam   move in the cam search direction at "Homing Velocity (towards plc cam)"
//                   until the referencing cam signal is seen;
//   2. leave_cam    move in the sync search direction at "Homing Velocity (off plc cam)"
//                   (a reversal when the two directions differ, as in the manual's sequence)
//                   until the falling edge of the cam signal;
//   3. search_sync  (reference mode sync_pulse only) keep moving until the sync pulse (latch
//                   signal or encoder zero pulse);
//   4. latch        the position of the sync event (the falling cam edge in mode cam_only) is
//                   given the "Home Position (Calibration Value)": the coordinate system is
//                   shifted, the mechanics do not move;
//   5. stopping     the axis stops; it stands a little beyond the home position (000_* 7.2.4:
//                   "The standstill position of the axis deviates slightly");
//   6. to_home      ncsim option (move_to_home, default on): position on the home position, so
//                   that G74 ends on the reference point;
//   7. done, or failed when the cam is not found within max_search_distance.
// All motions are planned with axes/profile.hpp from the current set value (continuous).
//
// Inputs per cycle: the cam and sync signals as seen at the last set value. Outputs per cycle:
// the set value in the (new, after the latch) axis coordinates, the phase, and in the latch
// cycle the coordinate shift the position controller must apply (PositionControlModel::shift).
// Invariants: step() is noexcept and does not allocate; parameters are validated once.

#include <optional>
#include <string_view>

#include "axes/profile.hpp"

namespace ncsim::axes {

/// "Reference Mode (Sync condition)" (000_* 7.2.4), the two NC-guided variants ncsim models.
enum class HomingReference {
  cam_only,    ///< "Default / Homing Sensor Only": the falling cam edge is the sync event
  sync_pulse,  ///< "Hardware Sync" / "Hardware Latch": a separate pulse after the cam
};

struct HomingParams {
  double v_to_cam = 10.0;  ///< [mm/s] "Homing Velocity (towards plc cam)" (000_* 7.1.2), > 0
  double v_off_cam = 1.0;  ///< [mm/s] "Homing Velocity (off plc cam)" (000_* 7.1.2), > 0
  bool invert_cam_search = false;  ///< "Invert Direction for Homing Sensor Search": false =
                                   ///< positive direction (000_* 7.2.4)
  bool invert_sync_search = true;  ///< "Invert Direction for Sync Impuls Search": false =
                                   ///< positive direction (000_* 7.2.4)
  double home_position = 0.0;      ///< [mm] "Home Position (Calibration Value)" (000_* 7.2.4)
  HomingReference reference = HomingReference::cam_only;
  bool move_to_home = true;          ///< ncsim: end on the home position
  double max_search_distance = 1e4;  ///< [mm] ncsim: give up the cam search after this, > 0
  Dynamics dynamics{1000.0, 1000.0, 1000.0, 10000.0};  ///< V, A+, A-, J of the motions
};

enum class HomingPhase { search_cam, leave_cam, search_sync, stopping, to_home, done, failed };

/// The ncsim id of a failed homing ("NC5530": cam not found).
inline constexpr std::string_view kIdHomingCamNotFound = "NC5530";

struct HomingInput {
  bool cam = false;         ///< referencing cam signal (bCalibrationCam)
  bool sync_pulse = false;  ///< sync pulse / latch signal (reference mode sync_pulse)
};

struct HomingOutput {
  Setpoint setpoint;  ///< this cycle's set value, in axis coordinates
  HomingPhase phase = HomingPhase::search_cam;
  std::optional<double> shift;  ///< [mm] in the latch cycle: new coordinate - old coordinate
};

class Homing {
 public:
  /// Starts homing from rest at `position`. Throws std::invalid_argument naming the parameter
  /// when a velocity, the search distance or the dynamics are not finite and > 0.
  Homing(const HomingParams& params, double position);

  HomingOutput step(const HomingInput& input, double t_cycle) noexcept;

  HomingPhase phase() const noexcept { return phase_; }
  bool finished() const noexcept {
    return phase_ == HomingPhase::done || (phase_ == HomingPhase::failed && !moving());
  }
  /// [mm] position of the sync event in the coordinates before homing, once latched.
  std::optional<double> latched_at() const noexcept { return latched_at_; }
  const Setpoint& setpoint() const noexcept { return setpoint_; }

 private:
  bool moving() const noexcept;
  void plan(Result result, const Profile& profile) noexcept;
  void move_at(double velocity) noexcept;
  void stop() noexcept;
  void latch() noexcept;

  HomingParams params_;
  HomingPhase phase_ = HomingPhase::search_cam;
  Profile profile_;     // in the coordinates before the latch, shifted by shift_
  double t_ = 0.0;      // [s] since profile_ started
  double shift_ = 0.0;  // [mm] coordinate shift from the latch
  double start_ = 0.0;  // [mm] where the cam search began
  bool cam_seen_ = false;
  std::optional<double> latched_at_;
  std::optional<double> pending_shift_;
  Setpoint setpoint_;
};

}  // namespace ncsim::axes
