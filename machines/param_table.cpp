#include "machines/param_table.hpp"

#include <array>

namespace ncsim::machines {
namespace {

constexpr double kSgn32Min = -2147483648.0;
constexpr double kSgn32Max = 2147483647.0;
constexpr double kUns16Max = 65535.0;
constexpr double kUns32Max = 4294967295.0;
constexpr double kRealMax = 1.0e300;   // MAX(REAL64) in practice; keeps messages readable
constexpr double kAboveZero = 1.0e-9;  // least value of a real that must be > 0 (a window, a feed)

// Conversions (docs/machines.md, "Units"): 0.1 um -> mm and 0.0001 deg -> deg share 1e-4;
// 0.1 mdeg is 1e-4 deg too (seed 004 §5.2.2 P-CHAN-00371); us -> s; 0.1 % -> fraction.
constexpr double kTenthMicron = 1.0e-4;
constexpr double kMicrosecond = 1.0e-6;
constexpr double kPerMille = 1.0e-3;
constexpr double kMilli = 1.0e-3;  // um/s -> mm/s, 0.001 deg/s -> deg/s
constexpr double kCenti = 1.0e-2;  // 0.01/s -> 1/s

constexpr ListKind A = ListKind::axis;
constexpr ListKind C = ListKind::channel;
constexpr ListKind Z = ListKind::zero;
constexpr Need kOpt = Need::optional;
constexpr Need kMust = Need::mandatory;
constexpr Need kDerived = Need::derived;

// clang-format off
constexpr std::array kTable = {
  // Axis list: head and characteristics
  ParamSpec{"NCSIM-AXIS-001", "kopf.log_achs_name", A, ValueType::word, 0, 0, "", 1, "", "", kMust, -1, -1, "004 §4.8.1 (listing)"},
  ParamSpec{"NCSIM-AXIS-002", "kopf.achs_nr", A, ValueType::uns16, 1, kUns16Max, "", 1, "", "", kMust, -1, -1, "004 §4.8.1 (listing)"},
  ParamSpec{"NCSIM-AXIS-003", "kenngr.achs_typ", A, ValueType::uns16, 1, 4, "1 T, 2 R, 4 S", 1, "", "1", kOpt, -1, -1, "004 §4.8.1 (type == 4 spindle)"},
  ParamSpec{"P-AXIS-00015", "kenngr.achs_mode", A, ValueType::axis_mode, 0x1, kUns32Max, "bits", 1, "", "0x00000001", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00020", "kenngr.antr_typ", A, ValueType::uns16, 0, kUns16Max, "", 1, "", "0", kOpt, -1, -1, "004 §2.1.6, §4.10.1"},
  ParamSpec{"P-AXIS-00177", "kenngr.swe_neg", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "-10000000", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00178", "kenngr.swe_pos", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "10000000", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00555", "kenngr.conv_sync_optim", A, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00516", "kenngr.measure.signal", A, ValueType::word, 0, 0, "", 1, "", "DRIVE_TYPE_DEFAULT", kOpt, -1, -1, "004 §4.3 (id inferred)"},
  ParamSpec{"P-AXIS-00517", "kenngr.measure.input", A, ValueType::uns16, 0, 255, "", 1, "", "1", kOpt, -1, -1, "TF5200 P-AXIS-00517 (UNS08; default: ncsim, the seeds' Channel=1)"},
  ParamSpec{"P-AXIS-00518", "kenngr.measure.edge", A, ValueType::word, 0, 0, "POS | NEG", 1, "", "POS", kOpt, -1, -1, "TF5200 P-AXIS-00518 (blank: P-AXIS-00113 = 0, positive)"},
  ParamSpec{"NCSIM-AXIS-004", "kenngr.messachse", A, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §4.9.1 (listing)"},
  // Axis list: conveyor axis (seed 004 §5.2.1)
  ParamSpec{"P-AXIS-00620", "conv_sync.enable_filter", A, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"NCSIM-AXIS-005", "conv_sync.type_pos_filter", A, ValueType::uns32, 0, 1, "0 FIR, 1 average", 1, "", "0", kOpt, -1, -1, "004 §4.8.1 (listing)"},
  ParamSpec{"NCSIM-AXIS-006", "conv_sync.order_pos_filter", A, ValueType::uns32, 0, 1000, "", 1, "", "0", kOpt, -1, -1, "004 §4.8.1 (listing)"},
  ParamSpec{"P-AXIS-00623", "conv_sync.order_v_filter", A, ValueType::uns32, 0, 1000, "", 1, "", "20", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00624", "conv_sync.order_post_v_filter", A, ValueType::uns32, 0, 1000, "", 1, "", "6", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00625", "conv_sync.order_v_filter_dyn", A, ValueType::uns32, 0, 1000, "", 1, "", "10", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00626", "conv_sync.delay_time", A, ValueType::uns32, 0, kUns32Max, "us", kMicrosecond, "s", "0", kOpt, -1, -1, "004 §5.2.1"},
  ParamSpec{"P-AXIS-00708", "conv_sync.is_master", A, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §5.2.1"},
  // Axis list: exact stop (seed 001 §3.2)
  ParamSpec{"P-AXIS-00236", "getriebe[].window", A, ValueType::sgn32, 1, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "500", kOpt, 7, -1, "001 §3.2"},
  ParamSpec{"P-AXIS-00532", "getriebe[].position_settling_time", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "us", kMicrosecond, "s", "-1", kOpt, 7, -1, "001 §3.2"},
  // Axis list: dynamics of gear i, jerk-limited ("non-linear") slope (ISG axis parameter
  //      manual TF5200, docs/machines.md "Axis dynamics" names each page) ------------------------
  ParamSpec{"P-AXIS-00212", "getriebe[].dynamik.vb_max", A, ValueType::uns32, 1, 2000000000, "um/s | 0.001 deg/s", kMilli, "mm/s | deg/s", "200000", kOpt, 7, -1, "TF5200 P-AXIS-00212"},
  ParamSpec{"P-AXIS-00008", "getriebe[].dynamik.a_max", A, ValueType::uns32, 1, 100000000, "mm/s^2 | deg/s^2", 1, "mm/s^2 | deg/s^2", "1000", kOpt, 7, -1, "TF5200 P-AXIS-00008"},
  ParamSpec{"P-AXIS-00209", "getriebe[].vb_eilgang", A, ValueType::uns32, 1, 2000000000, "um/s | 0.001 deg/s", kMilli, "mm/s | deg/s", "166666", kOpt, 7, -1, "TF5200 P-AXIS-00209 (<= P-AXIS-00212)"},
  ParamSpec{"P-AXIS-00001", "getriebe[].slope_profil.a_beschl", A, ValueType::uns32, 1, 100000000, "mm/s^2 | deg/s^2", 1, "mm/s^2 | deg/s^2", "1000", kOpt, 7, -1, "TF5200 P-AXIS-00001 (<= P-AXIS-00008)"},
  ParamSpec{"P-AXIS-00002", "getriebe[].slope_profil.a_brems", A, ValueType::uns32, 1, 100000000, "mm/s^2 | deg/s^2", 1, "mm/s^2 | deg/s^2", "1000", kOpt, 7, -1, "TF5200 P-AXIS-00002 (<= P-AXIS-00008)"},
  ParamSpec{"P-AXIS-00004", "getriebe[].slope_profil.a_grenz", A, ValueType::uns32, 1, 100000000, "mm/s^2 | deg/s^2", 1, "mm/s^2 | deg/s^2", "1000", kOpt, 7, -1, "TF5200 P-AXIS-00004 (<= P-AXIS-00008)"},
  ParamSpec{"P-AXIS-00053", "getriebe[].slope_profil.a_feedh", A, ValueType::uns32, 0, 100000000, "mm/s^2 | deg/s^2", 1, "mm/s^2 | deg/s^2", "0", kOpt, 7, -1, "TF5200 P-AXIS-00053 (0: = P-AXIS-00004)"},
  ParamSpec{"P-AXIS-00196", "getriebe[].slope_profil.tr_beschl_zu", A, ValueType::uns32, 1, kUns32Max, "us", kMicrosecond, "s", "50000", kOpt, 7, -1, "TF5200 P-AXIS-00196 (>= P-AXIS-00201)"},
  ParamSpec{"P-AXIS-00195", "getriebe[].slope_profil.tr_beschl_ab", A, ValueType::uns32, 1, kUns32Max, "us", kMicrosecond, "s", "50000", kOpt, 7, -1, "TF5200 P-AXIS-00195 (>= P-AXIS-00201)"},
  ParamSpec{"P-AXIS-00198", "getriebe[].slope_profil.tr_brems_zu", A, ValueType::uns32, 1, kUns32Max, "us", kMicrosecond, "s", "50000", kOpt, 7, -1, "TF5200 P-AXIS-00198 (>= P-AXIS-00201)"},
  ParamSpec{"P-AXIS-00197", "getriebe[].slope_profil.tr_brems_ab", A, ValueType::uns32, 1, kUns32Max, "us", kMicrosecond, "s", "50000", kOpt, 7, -1, "TF5200 P-AXIS-00197 (>= P-AXIS-00201)"},
  ParamSpec{"P-AXIS-00200", "getriebe[].slope_profil.tr_grenz", A, ValueType::uns32, 1, kUns32Max, "us", kMicrosecond, "s", "10000", kOpt, 7, -1, "TF5200 P-AXIS-00200 (>= P-AXIS-00201)"},
  ParamSpec{"P-AXIS-00081", "getriebe[].slope_profil.tr_feedh", A, ValueType::uns32, 0, kUns32Max, "us", kMicrosecond, "s", "0", kOpt, 7, -1, "TF5200 P-AXIS-00081 (0: = P-AXIS-00200)"},
  ParamSpec{"P-AXIS-00201", "getriebe[].dynamik.tr_min", A, ValueType::uns32, 0, kUns32Max, "us", kMicrosecond, "s", "10000", kOpt, 7, -1, "TF5200 P-AXIS-00201"},
  ParamSpec{"P-AXIS-00199", "getriebe[].dynamik.tr_geom", A, ValueType::uns32, 0, kUns32Max, "us", kMicrosecond, "s", "10000", kOpt, 7, -1, "TF5200 P-AXIS-00199"},
  // Axis list: homing, G74 (the static saw; TF5200 homing parameters)
  ParamSpec{"P-AXIS-00152", "getriebe[].pos_refpkt", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "0", kOpt, 7, -1, "TF5200 P-AXIS-00152"},
  ParamSpec{"P-AXIS-00219", "getriebe[].vb_refmax", A, ValueType::uns32, 1, 2000000000, "um/s | 0.001 deg/s", kMilli, "mm/s | deg/s", "83333", kOpt, 7, -1, "TF5200 P-AXIS-00219 (capped at P-AXIS-00212)"},
  // Axis list: the NC I path model (seed 000 §7.1.7); no ISG key, ncsim ids
  ParamSpec{"NCSIM-AXIS-020", "nci.velo_jump_factor", A, ValueType::real64, 0, kRealMax, "", 1, "", "1.0", kOpt, -1, -1, "000 §7.1.7 (C0)"},
  ParamSpec{"NCSIM-AXIS-030", "ncsim.profile_rule", A, ValueType::word, 0, 0, "manual | time_optimal", 1, "", "manual", kOpt, -1, -1, "002 2.1, 2.3 (manual); docs/axes-profile.md"},
  // Axis list: position control
  ParamSpec{"P-AXIS-00099", "getriebe[].kv", A, ValueType::uns32, 1, kUns32Max, "0.01/s", kCenti, "1/s", "1000", kOpt, 7, -1, "TF5200 P-AXIS-00099"},
  ParamSpec{"NCSIM-AXIS-023", "drive.pt1_time", A, ValueType::real64, 0, kRealMax, "s", 1, "s", "0.0", kOpt, -1, -1, "000 §7.5.8"},
  ParamSpec{"NCSIM-AXIS-024", "monitoring.position_lag", A, ValueType::boolean, 0, 1, "", 1, "", "1", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"NCSIM-AXIS-025", "monitoring.position_lag_max", A, ValueType::real64, kAboveZero, kRealMax, "mm | deg", 1, "mm | deg", "5.0", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"NCSIM-AXIS-026", "monitoring.position_lag_filter_time", A, ValueType::real64, 0, kRealMax, "s", 1, "s", "0.02", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"NCSIM-AXIS-027", "monitoring.target_position", A, ValueType::boolean, 0, 1, "", 1, "", "1", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"NCSIM-AXIS-028", "monitoring.target_position_window", A, ValueType::real64, kAboveZero, kRealMax, "mm | deg", 1, "mm | deg", "2.0", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"NCSIM-AXIS-029", "monitoring.target_position_time", A, ValueType::real64, 0, kRealMax, "s", 1, "s", "0.02", kOpt, -1, -1, "000 §7.1.5"},
  ParamSpec{"P-AXIS-00126", "getriebe[].moduloo", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "3600000", kOpt, 7, -1, "TF5200 P-AXIS-00126 (> P-AXIS-00127)"},
  ParamSpec{"P-AXIS-00127", "getriebe[].modulou", A, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "0", kOpt, 7, -1, "TF5200 P-AXIS-00127"},
  // Channel list
  ParamSpec{"P-CHAN-00650", "configuration.interpolator.function", C, ValueType::flag_set, 0, 0, "", 1, "", "FCT_IPO_DEFAULT", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00653", "configuration.interpolator.number_blocks_lah", C, ValueType::uns32, 0, 10000, "blocks", 1, "", "120", kOpt, -1, -1, "TF5200 channel parameters: data range 10..10000, default 120, read only with FCT_LOOK_AHEAD_CUSTOM; below 10: 50611"},
  ParamSpec{"P-CHAN-00009", "corr_v_trans_jerk", C, ValueType::boolean, 0, 1, "", 1, "", "1", kOpt, -1, -1, "isg-language §7.1; TF5200 channel parameters P-CHAN-00009 (BOOLEAN; the manual's default 0, ncsim's 1: docs/machines.md)"},
  ParamSpec{"P-CHAN-00071", "prog_start.slope.profile", C, ValueType::uns16, 0, 3, "0 STEP, 1 TRAPEZ, 2 SIN2, 3 HSC", 1, "", "0", kOpt, -1, -1, "isg-language §5.5 (PROG-207190411; 3 HSC: NC3013)"},
  ParamSpec{"P-CHAN-00362", "conveyor_sync.log_number_master", C, ValueType::uns16, 1, kUns16Max, "", 1, "", "", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00363", "conveyor_sync.move_direction", C, ValueType::uns16, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00364", "conveyor_sync.x_virtual", C, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00365", "conveyor_sync.sync_in_tolerance", C, ValueType::real64, 0, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00366", "conveyor_sync.hold_limit_vel_factor", C, ValueType::uns16, 0, kUns16Max, "0.1 %", kPerMille, "fraction", "1000", kOpt, -1, -1, "004 §5.2.2 (>1000: warning 21483)"},
  ParamSpec{"P-CHAN-00367", "conveyor_sync.hold_limit_tolerance", C, ValueType::real64, 0, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §4.8.1 (listing only)"},
  ParamSpec{"P-CHAN-00368", "conveyor_sync.cart_t0_shift_x", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00369", "conveyor_sync.cart_t0_shift_y", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00370", "conveyor_sync.cart_t0_shift_z", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00371", "conveyor_sync.cart_t0_rot_a", C, ValueType::real64, 0, 3599999.999999, "0.1 mdeg", kTenthMicron, "deg", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00372", "conveyor_sync.cart_t0_rot_b", C, ValueType::real64, 0, 3599999.999999, "0.1 mdeg", kTenthMicron, "deg", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00373", "conveyor_sync.cart_t0_rot_c", C, ValueType::real64, 0, 3599999.999999, "0.1 mdeg", kTenthMicron, "deg", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00374", "conveyor_sync.pos_limit", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2 (range widened, see docs)"},
  ParamSpec{"P-CHAN-00859", "conveyor_sync.cart_swe_pos_x", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00860", "conveyor_sync.cart_swe_pos_y", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00861", "conveyor_sync.cart_swe_pos_z", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00862", "conveyor_sync.cart_swe_neg_x", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00863", "conveyor_sync.cart_swe_neg_y", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00864", "conveyor_sync.cart_swe_neg_z", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um", kTenthMicron, "mm", "0.0", kOpt, -1, -1, "004 §5.2.2"},
  ParamSpec{"P-CHAN-00262", "trafo[].id", C, ValueType::uns32, 0, kUns32Max, "", 1, "", "0", kOpt, 9, -1, "isg-language §8"},
  ParamSpec{"P-CHAN-00829", "trafo[].type", C, ValueType::uns32, 0, kUns32Max, "", 1, "", "0", kOpt, 9, -1, "isg-language §8"},
  ParamSpec{"P-CHAN-00263", "trafo[].param[]", C, ValueType::real64, -kRealMax, kRealMax, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "0.0", kOpt, 9, 73, "isg-language §8"},
  ParamSpec{"P-CHAN-00394", "coordinate_system.rotation_sequence", C, ValueType::word, 0, 0, "", 1, "", "ZYX", kOpt, -1, -1, "isg-language §5.8"},
  ParamSpec{"NCSIM-CHAN-001", "spdl_anzahl", C, ValueType::uns16, 0, kUns16Max, "", 1, "", "0", kOpt, -1, -1, "004 §4.9.1 (listing)"},
  ParamSpec{"NCSIM-CHAN-002", "main_spindle_ax_nr", C, ValueType::uns16, 1, kUns16Max, "", 1, "", "", kOpt, -1, -1, "004 §4.9.1 (listing)"},
  ParamSpec{"NCSIM-CHAN-003", "main_spindle_name", C, ValueType::word, 0, 0, "", 1, "", "", kOpt, -1, -1, "004 §4.9.1 (listing)"},
  ParamSpec{"NCSIM-CHAN-610", "ncsim.cycle_time", C, ValueType::uns32, 1, 1000000, "us", kMicrosecond, "s", "1000", kOpt, -1, -1, "no key in the manuals at hand (docs/ipo.md \"The cycle time\"); the bounds of --cycle-us, which overrides it"},
  ParamSpec{"NCSIM-CHAN-620", "ncsim.default_path_dev", C, ValueType::real64, kAboveZero, kRealMax, "mm", 1, "mm", "1.0", kOpt, -1, -1, "isg-language §5.3 (PROG-475164939: PATH_DEV 1 mm); no ISG key: G261's ball radius where #CONTOUR MODE gives no PATH_DEV"},
  ParamSpec{"NCSIM-CHAN-640", "conveyor_sync.ncsim_dynamics_reserve", C, ValueType::uns16, 0, 500, "0.1 %", kPerMille, "fraction", "0", kOpt, -1, -1, "004 l.454 (reduce the dynamic axis limits; no ISG key)"},
  ParamSpec{"NCSIM-CHAN-630", "ncsim.path_override_type", C, ValueType::word, 0, 0, "REDUCED | ORIGINAL | REDUCED_ABOVE_100", 1, "", "REDUCED", kOpt, -1, -1, "000 §7.5.6 (override types; no ISG key)"},
  ParamSpec{"P-CHAN-00160", "g80_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00160 (G80's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00161", "g81_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00161 (G81's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00162", "g82_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00162 (G82's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00163", "g83_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00163 (G83's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00164", "g84_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00164 (G84's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00165", "g85_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00165 (G85's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00166", "g86_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00166 (G86's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00167", "g87_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00167 (G87's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00168", "g88_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00168 (G88's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00169", "g89_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00169 (G89's implicit subroutine, PROG-206278923)"},
  ParamSpec{"P-CHAN-00187", "g800_prog_file[]", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, 39, -1, "TF5200 P-CHAN-00187 (G800-G839's implicit subroutines, [i] for G8(00+i))"},
  ParamSpec{"P-CHAN-00118", "m6_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00118 (M6 calls this global subroutine instead of being an M function)"},
  ParamSpec{"P-CHAN-00429", "d_prog_file", C, ValueType::file_name, 0, 0, "", 1, "", "", kOpt, -1, -1, "TF5200 P-CHAN-00429 (a D word also calls this global subroutine)"},
  ParamSpec{"P-CHAN-00108", "prog_start.feedrate_factor", C, ValueType::real64, -1, kRealMax, "", 1, "", "100", kOpt, -1, -1, "TF5200 P-CHAN-00108 (100: F in mm/min, 0.1: m/min; F [mm/min] = F x 100 / factor; <= 0: 100)"},
  ParamSpec{"P-CHAN-00099", "prog_start.feedrate", C, ValueType::real64, 0, kRealMax, "mm/min", 1.0 / 60.0, "mm/s", "0", kOpt, -1, -1, "TF5200 P-CHAN-00099 (the feed of G01/G02/G03 before any F; 0: none)"},
  ParamSpec{"P-CHAN-00090", "vector.velocity", C, ValueType::real64, kAboveZero, kRealMax, "mm/min", 1.0 / 60.0, "mm/s", "2000000000", kOpt, -1, -1, "TF5200 P-CHAN-00090 (#VECTOR LIMIT ON [VEL] without a value)"},
  ParamSpec{"P-CHAN-00041", "m_synch[]", C, ValueType::flag_set, 0, 0, "NO_SYNCH | MOS | MVS_SVS | MVS_SNS | MNS_SNS | 0x...", 1, "", "MOS", kOpt, 999, -1, "TF5200 P-CHAN-00041 (M function i's synchronisation type; ncsim's default MOS, docs/interp.md \"Technology functions\")"},
  ParamSpec{"P-CHAN-00027", "h_synch[]", C, ValueType::flag_set, 0, 0, "NO_SYNCH | MOS | MVS_SVS | MVS_SNS | MNS_SNS | 0x...", 1, "", "MOS", kOpt, 999, -1, "TF5200 P-CHAN-00027 (H function i's synchronisation type)"},
  ParamSpec{"P-CHAN-00081", "spindel[].s_synch", C, ValueType::flag_set, 0, 0, "NO_SYNCH | MOS | MVS_SVS | MVS_SNS | MNS_SNS | 0x...", 1, "", "MOS", kOpt, 0, -1, "TF5200 P-CHAN-00081 (the S function's synchronisation type; ncsim has one spindle entry, [0])"},
  ParamSpec{"P-CHAN-00086", "tool.synch", C, ValueType::flag_set, 0, 0, "NO_SYNCH | MOS | MVS_SVS | MVS_SNS | MNS_SNS | 0x...", 1, "", "MOS", kOpt, -1, -1, "TF5200 P-CHAN-00086 (the T function's synchronisation type)"},
  ParamSpec{"NCSIM-CHAN-650", "ncsim.m_duration[]", C, ValueType::real64, 0, 1e9, "ms", kMilli, "s", "0", kOpt, 999, -1, "no ISG key (the PLC acknowledges): M function i's execution time, output -> acknowledgement"},
  ParamSpec{"NCSIM-CHAN-651", "ncsim.h_duration[]", C, ValueType::real64, 0, 1e9, "ms", kMilli, "s", "0", kOpt, 999, -1, "no ISG key: H function i's execution time"},
  ParamSpec{"NCSIM-CHAN-652", "ncsim.s_duration", C, ValueType::real64, 0, 1e9, "ms", kMilli, "s", "0", kOpt, -1, -1, "no ISG key: the S function's execution time"},
  ParamSpec{"NCSIM-CHAN-653", "ncsim.t_duration", C, ValueType::real64, 0, 1e9, "ms", kMilli, "s", "0", kOpt, -1, -1, "no ISG key: the T function's (tool change's) execution time"},
  ParamSpec{"P-CHAN-00014", "einrechnen_mit_t", C, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "TF5200 P-CHAN-00014 (1: a T word also executes the D word of the same number, 'T80' = 'T80 D80')"},
  ParamSpec{"P-CHAN-00097", "use_drive_curr_limit", C, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "TF5200 P-CHAN-00097 (0: a feed hold decelerates at the currently valid deceleration; 1, the feed-hold ramps P-AXIS-00053 / 00081: NC3013)"},
  ParamSpec{"P-CHAN-00463", "create_cycle_param_on_read", C, ValueType::boolean, 0, 1, "", 1, "", "1", kOpt, -1, -1, "TF5200 P-CHAN-00463 (1: a @P read that the call did not program creates it; 0: error 20394)"},
  // Zero-offset list (TF5200 "Zero offsets", P-ZERO; np_grp[i] is G53..G59 / G159=i)
  ParamSpec{"P-ZERO-00001", "g53_verfuegbar", Z, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, -1, -1, "TF5200 P-ZERO-00001 (0: G53 deselects every offset; 1: np_grp[0] is an offset too)"},
  ParamSpec{"P-ZERO-00002", "default_index", Z, ValueType::uns16, 0, 96, "", 1, "", "0", kOpt, -1, -1, "TF5200 P-ZERO-00002 (the group active at program start)"},
  ParamSpec{"P-ZERO-00003", "np_grp[].achse[].versch", Z, ValueType::sgn32, kSgn32Min, kSgn32Max, "0.1 um | 0.0001 deg", kTenthMicron, "mm | deg", "0", kOpt, 96, 31, "TF5200 P-ZERO-00003 (achse[j]: the channel axis j, machine.lis order)"},
  ParamSpec{"NCSIM-ZERO-001", "np_grp[].achse[].inaktiv", Z, ValueType::boolean, 0, 1, "", 1, "", "0", kOpt, 96, 31, "TF5200 zero-offset list example (1: the axis's offset of this group is not applied)"},
  ParamSpec{"NCSIM-CHAN-004", "log_number_tracking_axis", C, ValueType::uns16, 1, kUns16Max, "", 1, "", "", kOpt, -1, -1, "004 §4.10.1 (listing, id cut off)"},
};

// Keys ncsim read before it used the ISG axis-list keys (issue 10), and keys of models ncsim
// does not run. Each names what to write instead.
constexpr std::array kRetired = {
  RetiredKey{"dynamics.max_velocity", A, "NC3015", "write getriebe[0].dynamik.vb_max (P-AXIS-00212) in um/s (0.001 deg/s): the old value x 1000"},
  RetiredKey{"dynamics.max_acceleration", A, "NC3015", "write getriebe[0].dynamik.a_max (P-AXIS-00008) in mm/s^2 (deg/s^2)"},
  RetiredKey{"dynamics.max_deceleration", A, "NC3015", "write getriebe[0].dynamik.a_max (P-AXIS-00008); the ISG list has one maximum for both directions"},
  RetiredKey{"dynamics.max_jerk", A, "NC3015", "write the ramp times getriebe[0].slope_profil.tr_beschl_zu/_ab, tr_brems_zu/_ab (P-AXIS-00196/00195/00198/00197) in us: t = a / j"},
  RetiredKey{"dynamics.default_velocity", A, "NC3015", "remove the line: feed comes from the program, G0 from getriebe[0].vb_eilgang (P-AXIS-00209)"},
  RetiredKey{"dynamics.default_acceleration", A, "NC3015", "write getriebe[0].slope_profil.a_beschl (P-AXIS-00001) in mm/s^2"},
  RetiredKey{"dynamics.default_deceleration", A, "NC3015", "write getriebe[0].slope_profil.a_brems (P-AXIS-00002) in mm/s^2"},
  RetiredKey{"dynamics.default_jerk", A, "NC3015", "write the ramp times getriebe[0].slope_profil.tr_beschl_zu/_ab, tr_brems_zu/_ab (P-AXIS-00196/00195/00198/00197) in us: t = a / j"},
  RetiredKey{"dynamics.reference_velocity", A, "NC3015", "remove the line: the TwinCAT NC reference velocity has no ISG axis-list key and ncsim does not use it"},
  RetiredKey{"nci.rapid_traverse_velocity", A, "NC3015", "write getriebe[0].vb_eilgang (P-AXIS-00209) in um/s (0.001 deg/s): the old value x 1000"},
  RetiredKey{"enc.modulo_factor", A, "NC3015", "write getriebe[0].moduloo / getriebe[0].modulou (P-AXIS-00126 / 00127) in 0.0001 deg (0.1 um): upper = lower + the old value x 10000"},
  RetiredKey{"ctrl.kv", A, "NC3015", "write getriebe[0].kv (P-AXIS-00099) in 0.01/s: the old value x 100"},
  RetiredKey{"nci.tolerance_ball", A, "NC3015", "write ncsim.default_path_dev (NCSIM-CHAN-620) in the channel list, in mm: the radius G261 uses where #CONTOUR MODE gives no PATH_DEV (the per-axis NC I ball was never read)"},
  RetiredKey{"getriebe[].lslope_profil.a_feedh", A, "NC3013", "write getriebe[i].slope_profil.a_feedh (P-AXIS-00053): P-AXIS-00024 belongs to the step-shaped (linear) slope, which ncsim does not model"},
};
// clang-format on

}  // namespace

std::span<const ParamSpec> param_table() {
  return kTable;
}

std::span<const RetiredKey> retired_keys() {
  return kRetired;
}

const RetiredKey* find_retired(ListKind list, std::string_view pattern) {
  for (const RetiredKey& r : kRetired) {
    if (r.list == list && r.key == pattern) return &r;
  }
  return nullptr;
}

const ParamSpec* find_param(ListKind list, std::string_view pattern) {
  for (const ParamSpec& spec : kTable) {
    if (spec.list == list && spec.key == pattern) return &spec;
  }
  return nullptr;
}

std::string_view type_name(ValueType type) {
  switch (type) {
    case ValueType::boolean:
      return "BOOLEAN";
    case ValueType::uns16:
      return "UNS16";
    case ValueType::uns32:
      return "UNS32";
    case ValueType::sgn32:
      return "SGN32";
    case ValueType::real64:
      return "REAL64";
    case ValueType::word:
      return "STRING";
    case ValueType::flag_set:
      return "STRING (flags)";
    case ValueType::axis_mode:
      return "UNS32 (bits)";
    case ValueType::file_name:
      return "STRING (file name)";
  }
  return "?";
}

}  // namespace ncsim::machines
