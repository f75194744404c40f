#pragma once
// axes/coupling: linear slave axes (002_* 3.2) and their online decoupling.
//
// A linear slave's set values are an affine image of its master's set values (002_* 3.2.2):
//   slave position = factor * master position + offset,   slave velocity = factor * master v
// (acceleration and jerk likewise). The offset comes from the coupling positions: coupling
// happens at standstill of both axes and is only a logical assignment, so the slave does not
// move when it is coupled. The factor must be non-zero and may be negative.
//
// Online factor change (002_* 3.2.2 "Aenderungen des Koppelfaktors"): allowed; the slave's
// set position stays continuous (the offset is recomputed at the switching instant) and its
// set velocity jumps from f_old * v_master to f_new * v_master, which the position controller
// sees as following error: the manual leaves that to the user. A sign change reverses the
// slave.
//
// Online decoupling (002_* 3.2.3): the slave becomes a (pseudo) master that carries on as if it
// were still coupled and can then be stopped, sent to a velocity or to a new end position on
// its own. ncsim's reading of "carries on": from its current set position, velocity and
// acceleration, the acceleration is brought to zero with the jerk limit (plan_velocity of
// axes/profile.hpp to the velocity it reaches doing so), so position, velocity and
// acceleration stay continuous. Decoupling at standstill ("offline") leaves it at rest.
//
// Masters are given as set values (axes::Setpoint), so any axis can lead: a PTP axis, another
// slave (cascade), or an encoder axis (000_* 6.1.2) whose set value is its noisy actual value.
// An encoder axis is never a slave: there is no slave type for it.
//
// Invariants: step() is noexcept and does not allocate; commands return a CouplingResult.

#include <optional>
#include <string_view>

#include "axes/profile.hpp"

namespace ncsim::axes {

enum class CouplingResult {
  ok,
  error_zero_factor,  ///< factor 0 or not finite (002_* 3.2.2) [NC5520]
  error_not_at_rest,  ///< coupling needs master and slave at standstill [NC5521]
  error_not_coupled,  ///< factor change or decoupling of an uncoupled axis [NC5522]
  error_coupled,      ///< motion command to a coupled slave (002_* 3: no own start/stop)
                      ///< [NC5523]
  error_profile,      ///< the setpoint generator refused the request [NC5524]
};

std::string_view diagnostic_id(CouplingResult result) noexcept;
std::string_view describe(CouplingResult result) noexcept;

/// The affine map of a linear coupling.
struct LinearCoupling {
  double factor = 1.0;  ///< [-] Koppelfaktor, != 0
  double offset = 0.0;  ///< [mm] slave position - factor * master position at coupling time

  Setpoint slave_of(const Setpoint& master) const noexcept {
    return Setpoint{factor * master.p + offset, factor * master.v, factor * master.a,
                    factor * master.j};
  }
};

/// A PTP axis that can be coupled to a master as linear slave and decoupled online.
class SlaveAxis {
 public:
  /// At rest at `position`; `dynamics` (V, A+, A-, J) are used for motions after decoupling.
  /// Throws std::invalid_argument when the dynamics are not all finite and > 0.
  SlaveAxis(const Dynamics& dynamics, double position);

  /// Couples to `master` (its current set value) with `factor`; both must be at rest.
  CouplingResult couple(const Setpoint& master, double factor) noexcept;
  /// Online change of the factor at the master's current set value (position continuous).
  CouplingResult set_factor(const Setpoint& master, double factor) noexcept;
  /// Decouples: carries on from the current set value (see the header note).
  CouplingResult decouple() noexcept;

  /// After decoupling (or when never coupled): stop, go to a velocity, go to a position,
  /// each planned with axes/profile.hpp from the current set value.
  CouplingResult stop() noexcept;
  CouplingResult move_velocity(double v_target) noexcept;  ///< [mm/s], signed
  CouplingResult move_position(double target) noexcept;    ///< [mm]

  /// Advances one cycle. `master` is the master's set value of this cycle (ignored when
  /// decoupled). Returns this cycle's set value of the slave.
  Setpoint step(const Setpoint& master, double t_cycle) noexcept;

  bool coupled() const noexcept { return coupling_.has_value(); }
  std::optional<LinearCoupling> coupling() const noexcept { return coupling_; }
  const Setpoint& setpoint() const noexcept { return setpoint_; }
  /// True while decoupled and the planned motion has not yet ended.
  bool moving() const noexcept;

 private:
  MotionState state() const noexcept { return MotionState{setpoint_.p, setpoint_.v, setpoint_.a}; }
  CouplingResult adopt(Result result, const Profile& profile) noexcept;

  Dynamics dynamics_;
  std::optional<LinearCoupling> coupling_;
  Profile profile_;  // motion when not coupled
  double t_ = 0.0;   // [s] time since profile_ started
  Setpoint setpoint_;
};

}  // namespace ncsim::axes
