#pragma once
// machines/machine: a loaded machine as honest typed values, in internal units.
//
// Purpose: what every downstream stage reads (planner limits, PTP axes, conveyor, frames,
// kinematics). Built once by load_machine() (loader.hpp) from ISG lists; nothing here is
// looked up by string except the axis name accessors the CLI and interpreter need.
// Units: mm, s, degrees (rotary axes and delta drives), fractions; each member says its unit.
// "mm | deg" means mm for linear axes and spindles used as linear conveyors, deg for rotary.
// Invariants (checked by the loader): soft_limits.neg < soft_limits.pos; axis numbers and names
// are unique; at most one conveyor axis, and it is a spindle or an encoder (COUNTER) axis;
// accelerations never exceed P-AXIS-00008 and ramps are never below P-AXIS-00201 after loading
// (they are limited, with a warning).

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "machines/frame.hpp"
#include "machines/tool_table.hpp"

namespace ncsim::machines {

/// Most axes (path axes and spindles) one channel may have in ncsim (docs/machines.md).
inline constexpr std::size_t kMaxChannelAxes = 16;
/// Largest machine index or parameter list ncsim reads (16 MiB; a real list has a few kB):
/// a larger file is refused with NC3010 before it is read (docs/machines.md).
inline constexpr std::size_t kMaxListBytes = std::size_t{16} << 20;

/// kenngr.achs_typ: 1 translatory, 2 rotary, 4 spindle.
enum class AxisKind { linear, rotary, spindle };

struct SoftLimits {
  double neg = -1000.0;  ///< kenngr.swe_neg P-AXIS-00177 [mm | deg]
  double pos = 1000.0;   ///< kenngr.swe_pos P-AXIS-00178 [mm | deg]
};

/// Dynamics of one axis: gear 0 (getriebe[0]) of the ISG axis list, jerk-limited ("non-linear")
/// slope profile. Ramp times are the time the acceleration takes to build up or die down, so
/// each ramp sets a jerk a / t (docs/machines.md "Axis dynamics"). Loaded values satisfy
/// v_rapid <= v_max, every acceleration <= acc_max and every ramp time >= ramp_min (limited
/// with warning NC3020 otherwise; v_rapid > v_max is error NC3007).
struct Dynamics {
  double v_max = 0.0;          ///< P-AXIS-00212 dynamik.vb_max [mm/s | deg/s]
  double v_rapid = 0.0;        ///< P-AXIS-00209 vb_eilgang, G0 velocity [mm/s | deg/s]
  double acc_max = 0.0;        ///< P-AXIS-00008 dynamik.a_max [mm/s^2 | deg/s^2]
  double acc_feed = 0.0;       ///< P-AXIS-00001 slope_profil.a_beschl, speeding up [mm/s^2]
  double dec_feed = 0.0;       ///< P-AXIS-00002 slope_profil.a_brems, slowing down (> 0) [mm/s^2]
  double acc_rapid = 0.0;      ///< P-AXIS-00004 slope_profil.a_grenz, G0 both ways [mm/s^2]
  double dec_feedhold = 0.0;   ///< P-AXIS-00053 slope_profil.a_feedh (list 0: acc_rapid) [mm/s^2]
  double ramp_acc_up = 0.0;    ///< P-AXIS-00196 slope_profil.tr_beschl_zu [s]
  double ramp_acc_down = 0.0;  ///< P-AXIS-00195 slope_profil.tr_beschl_ab [s]
  double ramp_dec_up = 0.0;    ///< P-AXIS-00198 slope_profil.tr_brems_zu [s]
  double ramp_dec_down = 0.0;  ///< P-AXIS-00197 slope_profil.tr_brems_ab [s]
  double ramp_rapid = 0.0;     ///< P-AXIS-00200 slope_profil.tr_grenz, G0 [s]
  double ramp_feedhold = 0.0;  ///< P-AXIS-00081 slope_profil.tr_feedh (list 0: ramp_rapid) [s]
  double ramp_min = 0.0;       ///< P-AXIS-00201 dynamik.tr_min, lower bound of every ramp [s]
  double ramp_geom = 0.0;      ///< P-AXIS-00199 dynamik.tr_geom, contour jerk (path) [s]; 0: none
  double velo_jump_factor = 1.0;  ///< NCSIM-AXIS-020 VELOJUMP C0 [-] (seed 000 §7.1.7)
  /// NCSIM-AXIS-030 ncsim.profile_rule: false = the manual's rules (002 2.1 symmetric
  /// min(A+, A-), 002 2.3 stop and return), true = time-optimal (docs/axes-profile.md).
  bool time_optimal_profiles = false;

  /// Feed jerk [mm/s^3 | deg/s^3]: the smallest a / t of the four feed ramps, so that no ramp
  /// is steeper than configured.
  double jerk_feed() const;
  /// G0 jerk: acc_rapid / ramp_rapid [mm/s^3 | deg/s^3].
  double jerk_rapid() const { return acc_rapid / ramp_rapid; }
  /// Feed-hold jerk: dec_feedhold / ramp_feedhold [mm/s^3 | deg/s^3].
  double jerk_feedhold() const { return dec_feedhold / ramp_feedhold; }
};

struct Monitoring {
  double exact_stop_window = 0.05;         ///< getriebe[0].window P-AXIS-00236 [mm | deg]
  std::optional<double> settling_time;     ///< P-AXIS-00532 [s]; nullopt: not monitored
  bool position_lag = true;                ///< position lag monitoring on
  double position_lag_max = 5.0;           ///< [mm | deg]
  double position_lag_filter_time = 0.02;  ///< [s]
  bool target_position = true;             ///< target position monitoring on
  double target_position_window = 2.0;     ///< [mm | deg]
  double target_position_time = 0.02;      ///< [s]
};

/// P-AXIS-00099 default, 1000 x 0.01/s (TF5200; docs/machines.md "Axis dynamics").
inline constexpr double kDefaultKv = 10.0;

struct ControlLoop {
  double kv = kDefaultKv;  ///< P-AXIS-00099 getriebe[0].kv, position gain [1/s] ((mm/s)/mm)
  double pt1_time = 0.0;   ///< NCSIM-AXIS-023 drive PT1 time constant [s]; 0 = ideal drive
};

/// conv_sync.* of the conveyor axis (seed 004 §5.2.1); present only when is_master = 1.
struct ConveyorAxisParams {
  bool enable_filter = false;         ///< P-AXIS-00620 position actual value filter on
  int type_pos_filter = 0;            ///< 0 FIR low-pass, 1 average (ncsim decision)
  int order_pos_filter = 0;           ///< position filter order [samples]
  int order_v_filter = 20;            ///< P-AXIS-00623 [samples]
  int order_post_v_filter = 6;        ///< P-AXIS-00624 [samples]
  int order_v_filter_dyn = 10;        ///< P-AXIS-00625 [samples]
  double delay_time = 0.0;            ///< P-AXIS-00626 [s]
  bool optimised_monitoring = false;  ///< kenngr.conv_sync_optim P-AXIS-00555
};

struct AxisParams {
  std::string name;  ///< kopf.log_achs_name, the program name (X, Y, S1, ...)
  int number = 0;    ///< kopf.achs_nr, logical axis number
  AxisKind kind = AxisKind::linear;
  std::uint32_t mode_bits = 1;  ///< kenngr.achs_mode P-AXIS-00015
  bool encoder_only = false;    ///< ACHSMODE_COUNTER: pure encoder axis
  bool modulo = false;          ///< ACHSMODE_MODULO
  double modulo_lower = 0.0;    ///< P-AXIS-00127 getriebe[0].modulou [mm | deg]
  double modulo_upper = 360.0;  ///< P-AXIS-00126 getriebe[0].moduloo, > modulo_lower [mm | deg]
  int drive_type = 0;           ///< kenngr.antr_typ P-AXIS-00020 (stored, not interpreted)
  std::string measure_signal;   ///< kenngr.measure.signal P-AXIS-00516
  int measure_input = 1;        ///< kenngr.measure.input P-AXIS-00517, the probing input
  std::string measure_edge;     ///< kenngr.measure.edge P-AXIS-00518: POS or NEG
  SoftLimits soft_limits;
  Dynamics dynamics;
  Monitoring monitoring;
  ControlLoop control;
  // G74 homing (docs/homing.md)
  double reference_position = 0.0;  ///< getriebe[0].pos_refpkt P-AXIS-00152 [mm | deg]
  double homing_velocity = 83.333;  ///< getriebe[0].vb_refmax P-AXIS-00219 [mm/s | deg/s]
  std::optional<ConveyorAxisParams> conveyor;  ///< set on the conveyor axis only
  /// kenngr.conv_sync_optim P-AXIS-00555 of this axis list (4.8.1 sets it on X; --- workspace)
  bool conv_sync_optim = false;
  std::string list_file;  ///< list the axis came from (for messages)
};

/// Look-ahead and functions of P-CHAN-00650.
struct InterpolatorFunction {
  int look_ahead_blocks = 120;     ///< 30 / 120 / 190 (seed 004 §5.2.2 function table)
  bool conveyor_tracking = false;  ///< FCT_DLM
  bool sync = false;               ///< FCT_SYNC
  bool look_ahead_opt = false;     ///< FCT_LOOK_AHEAD_OPT
  std::vector<std::string> flags;  ///< every flag as written, for display
};

/// Cuboid in MCS (P-CHAN-00859..00864) [mm].
struct Workspace {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();
};

enum class MoveDirection { positive_x, negative_x };

/// conveyor_sync.* channel parameters (seed 004 §5.2.2), converted.
struct ConveyorSyncChannel {
  int master_axis_number = 0;                            ///< P-CHAN-00362 logical axis number
  MoveDirection direction = MoveDirection::positive_x;   ///< P-CHAN-00363
  bool x_virtual = false;                                ///< P-CHAN-00364
  double sync_in_tolerance = 0.0;                        ///< P-CHAN-00365 [mm]
  double hold_limit_vel_factor = 1.0;                    ///< P-CHAN-00366 [fraction], <= 1
  double hold_limit_tolerance = 0.0;                     ///< P-CHAN-00367 [mm]
  Eigen::Vector3d t0_shift = Eigen::Vector3d::Zero();    ///< P-CHAN-00368..00370 [mm]
  Eigen::Vector3d t0_rot_abc = Eigen::Vector3d::Zero();  ///< P-CHAN-00371..00373 [deg]
  double pos_limit = 0.0;                                ///< P-CHAN-00374 [mm]
  /// NCSIM-CHAN-640: the share of A and J the conveying axes keep for the belt's own changes
  /// while synchronised (catch-up, PCS1 blocks; 004 l.454) [fraction], 0..0.5
  double dynamics_reserve = 0.0;
  /// P-CHAN-00859..00864; when not configured: soft limits of the first three axes (§4.4.1).
  Workspace workspace;
  bool workspace_configured = false;  ///< true when any of 00859..00864 was given
  /// P-AXIS-00555 = 1 on the X axis (axis index 0, 4.8.1 l.798) or on the
  /// conveyor axis (l.347): the optimised hold method (docs/conveyor.md)
  bool optimised_monitoring = false;

  /// PCS0 -> MCS.
  Frame t0() const { return t0_frame(t0_shift, t0_rot_abc); }
};

struct TrafoParams {
  int id = 0;                      ///< P-CHAN-00262
  int type = 0;                    ///< P-CHAN-00829 (0: equals id)
  std::array<double, 74> param{};  ///< P-CHAN-00263, converted [mm | deg]
};

/// NCSIM-CHAN-630 ncsim.path_override_type: what the path override refers to (000 §7.5.6).
enum class PathOverrideType {
  reduced,            ///< REDUCED: "Reduced (iterated)", the default
  original,           ///< ORIGINAL: "Original (iterated)"
  reduced_above_100,  ///< REDUCED_ABOVE_100: "Reduced [0 .. >100 %]"
};

/// P-CHAN-00071 `prog_start.slope.profile`: the slope a program starts with and `#SLOPE DEFAULT`
/// restores (isg-language.md §5.5, PROG-207190411: 0 step, 1 trapez, 2 sin2, 3 HSC). 3 (HSC) is
/// NC3013 at load: ncsim does not model the HSC profile (docs/machines.md).
enum class SlopeProfile { step, trapez, sin2 };

/// What the channel does with a technology function, the TF5200 synchronisation types
/// (P-CHAN-00041 m_synch[i], P-CHAN-00027 h_synch[i], P-CHAN-00081 spindel[0].s_synch,
/// P-CHAN-00086 tool.synch) that ncsim runs; docs/interp.md "Technology functions".
enum class TechSync : std::uint8_t {
  none,     ///< NO_SYNCH 0x0: not output to the PLC, takes no time
  mos,      ///< MOS 0x1: output before the block's motion, no acknowledgement awaited
  mvs_svs,  ///< MVS_SVS 0x2: output before the block; its motion starts after the acknowledgement
  mvs_sns,  ///< MVS_SNS 0x4: output before the block; the path stops at its end until acknowledged
  mns_sns,  ///< MNS_SNS 0x8: output after the block's motion; the path waits there
};

/// One technology function's synchronisation and execution time (the PLC's acknowledgement
/// after its output: a tool change, a valve, a laser on / off).
struct TechFunction {
  /// ncsim's default when the list names none: MOS (the manual's NOT_VALID would refuse every
  /// M function a list does not name; docs/interp.md "Technology functions")
  TechSync sync = TechSync::mos;
  double duration = 0.0;  ///< [s] output -> acknowledgement, >= 0 (NCSIM-CHAN-650..653)
};

/// The channel's technology functions by kind and number.
struct TechTable {
  std::map<std::uint32_t, TechFunction> m;  ///< M functions by number
  std::map<std::uint32_t, TechFunction> h;  ///< H functions by number
  TechFunction s;                           ///< the spindle's S function
  TechFunction t;                           ///< the tool request (T)
};

struct ChannelParams {
  InterpolatorFunction interpolator;
  SlopeProfile start_slope = SlopeProfile::step;  ///< P-CHAN-00071 prog_start.slope.profile
  std::optional<ConveyorSyncChannel> conveyor;    ///< set when FCT_DLM is given
  std::vector<TrafoParams> trafos;                ///< trafo[0..]; empty: no kinematic
  RotationSequence cs_rotation_sequence = RotationSequence::ZYX;    ///< P-CHAN-00394
  int spindle_count = 0;                                            ///< spdl_anzahl
  std::optional<int> main_spindle_number;                           ///< main_spindle_ax_nr
  std::string main_spindle_name;                                    ///< main_spindle_name
  std::optional<int> tracking_axis_number;                          ///< log_number_tracking_axis
  PathOverrideType path_override_type = PathOverrideType::reduced;  ///< NCSIM-CHAN-630
  /// P-CHAN-00009 corr_v_trans_jerk: limit the velocity at tangent transitions with a curvature
  /// jump so that the axes' jerk holds (planner::ChannelLimits::limit_c1_by_jerk); ncsim's
  /// default on, the manual's off (docs/machines.md "Checks and decisions")
  bool corr_v_trans_jerk = true;
  /// NCSIM-CHAN-620 ncsim.default_path_dev: G261's tolerance-ball radius where `#CONTOUR MODE`
  /// gives no PATH_DEV [mm] (default the manual's PATH_DEV 1 mm, isg-language.md §5.3)
  double default_path_dev = 1.0;
  /// NCSIM-CHAN-610 ncsim.cycle_time: the interpolation cycle T, whole us in the list, 1 us .. 1 s
  /// (`--cycle-us` overrides it; docs/ipo.md "The cycle time") [s]
  double cycle_time = 0.001;
  /// P-CHAN-00160..00169 g80_prog_file .. g89_prog_file and P-CHAN-00187 g800_prog_file[i]:
  /// the global subroutine each implicit call G80-G89 / G800-G839 runs, by G code
  std::map<std::uint32_t, std::string> implicit_call_files;
  /// P-CHAN-00118 m6_prog_file: M6 calls this global subroutine instead of being an M function
  std::string m6_prog_file;
  /// P-CHAN-00429 d_prog_file: a D word also calls this global subroutine (tool settings)
  std::string d_prog_file;
  /// P-CHAN-00014 einrechnen_mit_t: a T word also executes the D word of its number ("T80"
  /// is "T80 D80"; the manual's default 0)
  bool d_with_t = false;
  /// P-CHAN-00463 create_cycle_param_on_read (the manual's default 1)
  bool create_cycle_param_on_read = true;
  /// P-CHAN-00090 vector.velocity: the path velocity limit `#VECTOR LIMIT ON [VEL]` without a
  /// value activates [mm/s]
  double vector_velocity = 2e9 / 60.0;
  /// P-CHAN-00108 prog_start.feedrate_factor: the F word's unit, F [mm/min] = F x 100 / factor
  /// (100: mm/min, the default; 0.1: m/min); a value <= 0 stands for 100 (warning NC3022)
  double feedrate_factor = 100.0;
  /// P-CHAN-00099 prog_start.feedrate: the feed before the program's first F; 0: none [mm/s]
  double default_feed = 0.0;
  /// Technology functions' synchronisation types and execution times (TechTable)
  TechTable tech;
};

/// The zero-offset list (TF5200 "Zero offsets", P-ZERO-0000x), converted to mm / deg.
struct ZeroOffsets {
  bool g53_available = false;  ///< P-ZERO-00001 g53_verfuegbar
  int default_index = 0;       ///< P-ZERO-00002: the group active at program start (0..96)
  /// P-ZERO-00003 np_grp[i].achse[j].versch by group i, then channel axis j [mm | deg];
  /// groups and axes not listed are 0
  std::map<std::size_t, std::map<std::size_t, double>> offsets;
  double offset(std::size_t group, std::size_t axis) const {
    auto g = offsets.find(group);
    if (g == offsets.end()) return 0.0;
    auto a = g->second.find(axis);
    return a == g->second.end() ? 0.0 : a->second;
  }
};

struct Machine {
  std::string name;              ///< from machine.lis, else the folder name
  std::filesystem::path folder;  ///< where the lists are
  ChannelParams channel;
  std::vector<AxisParams> axes;  ///< machine order: as listed in machine.lis
  ZeroOffsets zero_offsets;      ///< the `zero` list of machine.lis; empty when none
  ToolTable tools;  ///< the `tools <file>` list of machine.lis; empty without one (docs/trc.md)

  /// The axis a program addresses by `program_name` (X, Y, Z, C, S1 ...). A spindle whose list
  /// name is "S" also answers to "S1" and vice versa (ncsim decision: the first spindle).
  const AxisParams* find_axis(std::string_view program_name) const;
  /// The axis with kopf.achs_nr == number.
  const AxisParams* find_axis_number(int number) const;
  /// The conveyor axis (conv_sync.is_master = 1), if any.
  const AxisParams* conveyor_axis() const;
  /// Soft limits of the named axis (for `ncsim check --machine`).
  std::optional<SoftLimits> soft_limits(std::string_view program_name) const;
};

}  // namespace ncsim::machines
