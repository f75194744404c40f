#pragma once
// axes/profile_compensation: position compensation (seed 002_* 2.5), a trapezoidal velocity
// profile (not jerk-limited, 3 phases, ramps AK+ and AK-) superimposed on the base dynamics as a
// path control ("Streckensteuerung"): its clock is the base distance travelled divided by the
// process velocity VP, so it follows every change of the base dynamics, even override 0.
// Inputs: CompensationRequest (L, D, VP, VK, AK+, AK-). Outputs: offset c(s) and its first
// and second derivative in the virtual time tau = s / VP.
// Invariants: the compensation covers the whole length L; |D| is reduced to the largest
// feasible value when the request cannot be met (002_* 2.5 "maximal moegliche Kompensation").

#include <array>
#include <optional>

namespace ncsim::axes {

/// Start parameters of 002_* 2.5 "Positionskompensation: Startparameter".
struct CompensationRequest {
  double length = 0.0;      ///< L, base distance over which to compensate [mm], > 0
  double difference = 0.0;  ///< D, extra distance [mm], != 0, may be negative
  double v_process = 0.0;   ///< VP, process velocity the overspeed refers to [mm/s], > 0
  double v_extra = 0.0;     ///< VK, permitted velocity increase/decrease [mm/s], > 0
  double acc = 0.0;         ///< AK+, permitted extra acceleration [mm/s^2], > 0
  double dec = 0.0;         ///< AK-, permitted extra deceleration [mm/s^2], > 0
};

/// Offset and derivatives with respect to the virtual time tau [s].
struct CompensationValue {
  double c = 0.0;        ///< offset [mm]
  double dc = 0.0;       ///< dc/dtau [mm/s]
  double ddc = 0.0;      ///< d2c/dtau2 [mm/s^2]
  bool done = false;     ///< tau at or beyond the end
  bool braking = false;  ///< in the final ramp
};

/// A planned compensation: up to three constant-acceleration phases in virtual time.
class Compensation {
 public:
  /// Plans the request; nullopt when a parameter is not finite or out of range.
  static std::optional<Compensation> plan(const CompensationRequest& request) noexcept;

  CompensationValue at(double tau) const noexcept;
  /// Compensation stop at tau: ramps the current overspeed down with AK- from here; no effect
  /// (false) when already in the final ramp or done.
  bool stop_at(double tau) noexcept;

  double difference() const noexcept { return difference_; }  ///< activated D [mm]
  bool reduced() const noexcept { return reduced_; }          ///< D was cut to the feasible maximum
  double duration() const noexcept { return tau_end_; }       ///< [s] of virtual time
  double v_process() const noexcept { return v_process_; }    ///< VP [mm/s]

 private:
  struct Ramp {
    double tau_start = 0.0;  // [s]
    double c = 0.0;          // [mm]
    double dc = 0.0;         // [mm/s]
    double ddc = 0.0;        // [mm/s^2]
  };
  std::array<Ramp, 4> ramps_{};  // accel, constant, decel, end
  double tau_end_ = 0.0;
  double difference_ = 0.0;
  double v_process_ = 0.0;
  double dec_ = 0.0;
  bool reduced_ = false;
};

}  // namespace ncsim::axes
