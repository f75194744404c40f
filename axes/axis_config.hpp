#pragma once
// axes/axis_config: the one mapping from a loaded machine's axis parameters (machines/, read from
// the ISG axis lists) onto the axis core's configurations: setpoint generator, position control
// model and monitors.
//
// Inputs: machines::AxisParams (internal units: mm | deg, s). Outputs: GeneratorConfig,
// PositionControlParams, AxisMonitorParams, as values; nothing is validated against a cycle time
// here (the constructors of the axis objects do that and throw naming the parameter).
// Mapping (docs/machines.md "From a machine to its axes"; each value names its parameter id):
//   generator  V   = P-AXIS-00209 getriebe[0].vb_eilgang (a PTP move without its own velocity
//                    runs at the rapid velocity)
//              A+  = P-AXIS-00001 slope_profil.a_beschl, A- = P-AXIS-00002 slope_profil.a_brems
//              J   = Dynamics::jerk_feed(): the smallest a / t over the four feed ramps
//                    P-AXIS-00195..00198
//              v_axis_max = P-AXIS-00212 dynamik.vb_max
//              increment  = 0.1 um (0.0001 deg), the ISG list position unit (kListIncrement)
//   control    Kv = P-AXIS-00099 getriebe[0].kv; drive PT1 = NCSIM-AXIS-023; feedforward
//              weight 1, Ka 0, no encoder noise (no list key; axes defaults); the noise seed is the
//              logical axis number, so every axis draws its own deterministic sequence
//   monitors   soft limits P-AXIS-00177/00178, on for linear and non-modulo rotary axes, off for
//              spindles and modulo axes; position lag NCSIM-AXIS-024..026; target position
//              NCSIM-AXIS-027..029; exact stop window P-AXIS-00236 and settling time
//              P-AXIS-00532 (not monitored -> 0, which disables it); position range and motion
//              monitoring have no list key and keep the axes defaults.
//   modulo     for axes with ACHSMODE_MODULO (P-AXIS-00015 bit 0x4) only: factor = P-AXIS-00126
//              - P-AXIS-00127; the axis core counts modulo positions from 0, so a lower limit
//              other than 0 throws std::invalid_argument naming P-AXIS-00127 (not supported).
//              Spindles without the bit (the bundled conveyors: belt positions in mm) stay
//              unbounded.
// Invariants: pure functions of their input; the same machine always gives the same configs.

#include <optional>
#include <vector>

#include "axes/control.hpp"
#include "axes/modulo.hpp"
#include "axes/monitor.hpp"
#include "axes/profile_generator.hpp"
#include "machines/machine.hpp"

namespace ncsim::axes {

/// Position resolution of the ISG lists (0.1 um | 0.0001 deg) [mm | deg]: moves shorter than
/// this do not start (002_* 2.1, GeneratorConfig::increment).
inline constexpr double kListIncrement = 1.0e-4;

/// Everything the axis core needs for one axis.
struct AxisConfig {
  GeneratorConfig generator;           ///< setpoint generator (PTP, MC_MoveVelocity)
  PositionControlParams control;       ///< position control model
  AxisMonitorParams monitor;           ///< soft limits, lag, target position, exact stop
  std::optional<ModuloParams> modulo;  ///< set for modulo axes only
};

/// Setpoint generator configuration of one axis (mapping above).
GeneratorConfig make_generator_config(const machines::AxisParams& axis);
/// Position control parameters of one axis (mapping above).
PositionControlParams make_position_control(const machines::AxisParams& axis);
/// Monitor parameters of one axis (mapping above).
AxisMonitorParams make_monitor_params(const machines::AxisParams& axis);
/// Modulo parameters of a modulo axis, nullopt for any other (mapping above; throws for a
/// modulo axis whose P-AXIS-00127 is not 0).
std::optional<ModuloParams> make_modulo_params(const machines::AxisParams& axis);
/// All of them for one axis.
AxisConfig make_axis_config(const machines::AxisParams& axis);
/// One AxisConfig per axis of the machine, in machine order.
std::vector<AxisConfig> make_axis_configs(const machines::Machine& machine);

}  // namespace ncsim::axes
