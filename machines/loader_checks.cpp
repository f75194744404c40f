// machines/loader_checks: checks that need more than one value or more than one list, and the
// values derived from them (look-ahead size, conveyor workspace, kinematics). Every rule cites
// the manual it comes from or says that it is an ncsim decision (docs/machines.md).
#include <algorithm>
#include <array>
#include <cstdio>
#include <initializer_list>

#include "machines/kinematics.hpp"
#include "machines/loader_detail.hpp"

namespace ncsim::machines::detail {
namespace {

using core::Severity;

struct Reporter {
  core::DiagnosticList& list;
  void error(const std::string& file, core::SourceLoc loc, const char* id, std::string message) {
    list.add(make_diag(Severity::error, file, loc, id, std::move(message)));
  }
  void warning(const std::string& file, core::SourceLoc loc, const char* id, std::string message) {
    list.add(make_diag(Severity::warning, file, loc, id, std::move(message)));
  }
};

// False when any of `keys` was written with a rejected value: a check that compares it would
// compare against its default and report a follow-on error (issue 9: one error per bad value).
bool usable(const ListValues& v, std::initializer_list<std::string_view> keys) {
  return std::none_of(keys.begin(), keys.end(), [&v](std::string_view k) { return v.rejected(k); });
}

// True when `value` is what the list wrote for `key` (not a default, and not the value a 0
// stands for, as P-AXIS-00053 / P-AXIS-00081 = 0 stand for the G0 values): only such a value
// is named in a warning.
bool written(const ListValues& v, std::string_view key, double value) {
  return v.given(key) && v.internal(key) == value;
}

// The location of `key`, or of `fallback` when `key` was not written.
core::SourceLoc loc_of(const ListValues& v, std::string_view key, std::string_view fallback) {
  const core::SourceLoc loc = v.loc(key);
  return loc.line > 0 ? loc : v.loc(fallback);
}

void check_axis(AxisParams& axis, const ListValues& v, Reporter& r) {
  const std::string& file = v.file();
  // kenngr.achs_typ: 1 translatory, 2 rotary, 4 spindle (seed 004 §4.8.1 "type == 4 spindle").
  const double typ = v.number("kenngr.achs_typ");
  if (typ != 1.0 && typ != 2.0 && typ != 4.0 && usable(v, {"kenngr.achs_typ"})) {
    r.error(file, v.loc("kenngr.achs_typ"), "NC3004",
            param_ref("kenngr.achs_typ", ListKind::axis) + " = " + number_text(typ) +
                " must be 1 (linear), 2 (rotary) or 4 (spindle)");
  }
  const std::string rule = v.text("ncsim.profile_rule");
  if (rule != "manual" && rule != "time_optimal") {
    r.error(file, v.loc("ncsim.profile_rule"), "NC3004",
            param_ref("ncsim.profile_rule", ListKind::axis) + " = " + rule +
                " must be manual or time_optimal");
  }
  // Seed 004 §5.2.1 note (1): ACHSMODE_LINEAR or ACHSMODE_MODULO must always be set.
  if ((axis.mode_bits & (axis_mode::kLinear | axis_mode::kModulo)) == 0U &&
      usable(v, {"kenngr.achs_mode"})) {
    r.error(file, v.loc("kenngr.achs_mode"), "NC3007",
            param_ref("kenngr.achs_mode", ListKind::axis) + " = " + hex_text(axis.mode_bits) +
                " sets neither ACHSMODE_LINEAR (0x00000001) nor ACHSMODE_MODULO (0x00000004); "
                "one of them must be set");
  }
  // Seed 004 §5.2.1: MIN(SGN32) < swe_neg < P-AXIS-00178.
  if (axis.soft_limits.neg >= axis.soft_limits.pos &&
      usable(v, {"kenngr.swe_neg", "kenngr.swe_pos"})) {
    r.error(file, loc_of(v, "kenngr.swe_neg", "kenngr.swe_pos"), "NC3007",
            param_ref("kenngr.swe_neg", ListKind::axis) + " = " +
                number_text(v.number("kenngr.swe_neg")) + " must be below " +
                param_ref("kenngr.swe_pos", ListKind::axis) + " = " +
                number_text(v.number("kenngr.swe_pos")));
  }
  // TF5200 P-AXIS-00126: modulou < moduloo. The kernel resets both to defaults with a warning
  // (ID 110052); ncsim reports the contradiction (NC3007) rather than run a range not written.
  const char* upper_key = "getriebe[0].moduloo";
  const char* lower_key = "getriebe[0].modulou";
  if (axis.modulo_lower >= axis.modulo_upper && usable(v, {upper_key, lower_key})) {
    r.error(file, loc_of(v, lower_key, upper_key), "NC3007",
            param_ref(lower_key, ListKind::axis) + " = " + number_text(v.number(lower_key)) +
                " must be below " + param_ref(upper_key, ListKind::axis) + " = " +
                number_text(v.number(upper_key)));
  }
  // TF5200 P-AXIS-00209: 1 <= vb_eilgang <= P-AXIS-00212. ncsim: an error, since a G0 faster
  // than the axis may move is a contradiction, not a default to be trimmed.
  Dynamics& d = axis.dynamics;
  const char* v_max_key = "getriebe[0].dynamik.vb_max";
  const char* rapid_key = "getriebe[0].vb_eilgang";
  if (d.v_rapid > d.v_max && usable(v, {rapid_key, v_max_key})) {
    r.error(file, loc_of(v, rapid_key, v_max_key), "NC3007",
            param_ref(rapid_key, ListKind::axis) + " = " + number_text(v.number(rapid_key)) +
                " must not exceed " + param_ref(v_max_key, ListKind::axis) + " = " +
                number_text(v.number(v_max_key)));
  }
  // TF5200: every slope acceleration lies in 1 .. P-AXIS-00008, every ramp time in
  // P-AXIS-00201 .. MAX(UNS32). ncsim limits a value outside with warning NC3020 (as the kernel
  // corrects list values with a warning, e.g. ID 110083 for P-AXIS-00201).
  struct Bounded {
    double* value;
    const char* key;
  };
  const char* a_max_key = "getriebe[0].dynamik.a_max";
  const std::array<Bounded, 4> accelerations = {{
      {&d.acc_feed, "getriebe[0].slope_profil.a_beschl"},
      {&d.dec_feed, "getriebe[0].slope_profil.a_brems"},
      {&d.acc_rapid, "getriebe[0].slope_profil.a_grenz"},
      {&d.dec_feedhold, "getriebe[0].slope_profil.a_feedh"},
  }};
  for (const Bounded& b : accelerations) {
    if (*b.value > d.acc_max && written(v, b.key, *b.value) && usable(v, {b.key, a_max_key})) {
      r.warning(file, v.loc(b.key), "NC3020",
                param_ref(b.key, ListKind::axis) + " = " + number_text(v.number(b.key)) +
                    " exceeds " + param_ref(a_max_key, ListKind::axis) + " = " +
                    number_text(v.number(a_max_key)) + "; limited to the maximum");
    }
    *b.value = std::min(*b.value, d.acc_max);
  }
  const char* ramp_min_key = "getriebe[0].dynamik.tr_min";
  const std::array<Bounded, 6> ramps = {{
      {&d.ramp_acc_up, "getriebe[0].slope_profil.tr_beschl_zu"},
      {&d.ramp_acc_down, "getriebe[0].slope_profil.tr_beschl_ab"},
      {&d.ramp_dec_up, "getriebe[0].slope_profil.tr_brems_zu"},
      {&d.ramp_dec_down, "getriebe[0].slope_profil.tr_brems_ab"},
      {&d.ramp_rapid, "getriebe[0].slope_profil.tr_grenz"},
      {&d.ramp_feedhold, "getriebe[0].slope_profil.tr_feedh"},
  }};
  for (const Bounded& b : ramps) {
    if (*b.value < d.ramp_min && written(v, b.key, *b.value) && usable(v, {b.key, ramp_min_key})) {
      r.warning(file, v.loc(b.key), "NC3020",
                param_ref(b.key, ListKind::axis) + " = " + number_text(v.number(b.key)) +
                    " is below " + param_ref(ramp_min_key, ListKind::axis) + " = " +
                    number_text(v.number(ramp_min_key)) + "; raised to the minimum");
    }
    *b.value = std::max(*b.value, d.ramp_min);
  }
  // Seed 004 §4.2: the conveyor is a spindle axis, or a pure encoder axis (ACHSMODE_COUNTER).
  if (axis.conveyor && axis.kind != AxisKind::spindle && !axis.encoder_only) {
    r.error(file, v.loc("conv_sync.is_master"), "NC3008",
            param_ref("conv_sync.is_master", ListKind::axis) + " = 1 on axis " + axis.name +
                ", which is neither a spindle (kenngr.achs_typ 4) nor an encoder axis "
                "(kenngr.achs_mode bit 0x00100000)");
  }
}

// P-CHAN-00650 flag names (seed 004 §5.2.2, interpolation function table).
constexpr std::array<std::string_view, 16> kKnown = {
    "FCT_IPO_DEFAULT",         "FCT_LOOK_AHEAD_LOW",
    "FCT_LOOK_AHEAD_STANDARD", "FCT_LOOK_AHEAD_HIGH",
    "FCT_LOOK_AHEAD_CUSTOM",   "FCT_SYNC",
    "FCT_LOOK_AHEAD_OPT",      "FCT_LIFT_UP_TIME",
    "FCT_SHIFT_NCBL",          "FCT_CALC_STATE_AT_T",
    "FCT_CALC_TIME",           "FCT_CONTOUR_LAH",
    "FCT_DYN_POS_LIMIT",       "FCT_EXTENSION_EQUIDIST",
    "FCT_CALC_POS_V_0",        "FCT_DLM"};

// P-CHAN-00653 `configuration.interpolator.number_blocks_lah`, the look-ahead size of
// FCT_LOOK_AHEAD_CUSTOM (isg-language.md §7.1 "CUSTOM [10 .. P-CHAN-00653]"; TF5200's channel
// parameters: data range 10..10000, default 120). A value below 10 is the kernel's error 50611
// "number of look-ahead blocks too small", class 3, "controller corrects the value": a
// warning, and the window is 10. Above 500 (the upper limit from build V3.1.3067.07; 10000 only
// with #SLOPE[TYPE=STEP], which a channel list cannot know) NC3020, limited to 500: a window
// entry may hold a chain of 64 blocks (~70 KB), so 10000 entries would take ~0.7 GB.
int custom_look_ahead(const ListValues& v, Reporter& r) {
  const char* key = "configuration.interpolator.number_blocks_lah";
  const int blocks = static_cast<int>(v.number(key));
  constexpr int kMaxBlocks = 500;
  if (blocks > kMaxBlocks) {
    r.warning(v.file(), v.loc(key), "NC3020",
              param_ref(key, ListKind::channel) + " = " + std::to_string(blocks) +
                  " is above 500 blocks, the limit of TF5200 builds from V3.1.3067.07 (10000 only "
                  "with #SLOPE[TYPE=STEP]); limited to 500");
    return kMaxBlocks;
  }
  if (blocks >= 10) return blocks;
  r.warning(v.file(), v.loc(key), "50611",
            param_ref(key, ListKind::channel) + " = " + std::to_string(blocks) +
                ": the number of look-ahead blocks is too small (at least 10); corrected to 10");
  return 10;
}

// P-CHAN-00650 flags (seed 004 §5.2.2, interpolation function table). False when a flag is
// unknown (reported here), so that checks depending on the flags stay silent.
bool interpret_functions(ChannelParams& ch, const ListValues& v, Reporter& r) {
  const char* key = "configuration.interpolator.function";
  const std::string ref = param_ref(key, ListKind::channel);
  const std::string text = v.text(key);
  InterpolatorFunction& f = ch.interpolator;
  std::string size_flag;
  bool all_known = true;
  for (const std::string& flag : split_flags(text)) {
    if (std::find(kKnown.begin(), kKnown.end(), flag) == kKnown.end()) {
      r.error(v.file(), v.loc(key), "NC3003", ref + ": unknown function '" + flag + "'");
      all_known = false;
      continue;
    }
    f.flags.push_back(flag);
    int blocks = 0;
    if (flag == "FCT_IPO_DEFAULT" || flag == "FCT_LOOK_AHEAD_STANDARD") blocks = 120;
    if (flag == "FCT_LOOK_AHEAD_LOW") blocks = 30;
    if (flag == "FCT_LOOK_AHEAD_HIGH") blocks = 190;
    if (flag == "FCT_LOOK_AHEAD_CUSTOM") blocks = custom_look_ahead(v, r);
    if (blocks > 0) {
      if (!size_flag.empty() && blocks != f.look_ahead_blocks) {
        r.error(v.file(), v.loc(key), "NC3007",
                ref + ": " + size_flag + " and " + flag + " set different look-ahead sizes");
      }
      size_flag = flag;
      f.look_ahead_blocks = blocks;
    }
    f.conveyor_tracking = f.conveyor_tracking || flag == "FCT_DLM";
    f.sync = f.sync || flag == "FCT_SYNC";
    f.look_ahead_opt = f.look_ahead_opt || flag == "FCT_LOOK_AHEAD_OPT";
  }
  return all_known;
}

void check_conveyor(Machine& m, const ListValues& ch, const std::vector<ListValues>& axes,
                    bool functions_known, Reporter& r) {
  const std::string& file = ch.file();
  // At most one conveyor axis (P-CHAN-00362 names exactly one). The one the channel names is
  // kept; every other one is reported (without a named one: all but the first).
  const int named = ch.given("conveyor_sync.log_number_master")
                        ? static_cast<int>(ch.number("conveyor_sync.log_number_master"))
                        : 0;
  const AxisParams* first = nullptr;
  for (const AxisParams& a : m.axes) {
    if (a.conveyor && (first == nullptr || a.number == named)) first = &a;
    if (a.conveyor && a.number == named) break;
  }
  for (std::size_t i = 0; i < m.axes.size(); ++i) {
    if (!m.axes[i].conveyor || &m.axes[i] == first) continue;
    r.error(axes[i].file(), axes[i].loc("conv_sync.is_master"), "NC3008",
            param_ref("conv_sync.is_master", ListKind::axis) + " = 1 on axis " + m.axes[i].name +
                ", but axis " + first->name + " (" + first->list_file +
                ") is already the conveyor axis; only one is allowed");
  }
  if (!m.channel.interpolator.conveyor_tracking) {
    // Seed 004 §1: FCT_DLM is required to use conveyor tracking.
    if (first != nullptr && functions_known) {
      r.error(file, ch.loc("configuration.interpolator.function"), "NC3008",
              "axis " + first->name + " is a conveyor axis (conv_sync.is_master = 1), but " +
                  param_ref("configuration.interpolator.function", ListKind::channel) +
                  " does not contain FCT_DLM");
    }
    m.channel.conveyor.reset();
    return;
  }
  ConveyorSyncChannel& c = *m.channel.conveyor;
  const char* master_key = "conveyor_sync.log_number_master";
  if (!ch.given(master_key) && !ch.rejected(master_key)) {
    r.error(file, ch.loc("configuration.interpolator.function"), "NC3006",
            "missing mandatory " + param_ref(master_key, ListKind::channel) +
                ": FCT_DLM needs the logical number of the conveyor axis");
  } else if (ch.given(master_key)) {
    const AxisParams* master = m.find_axis_number(c.master_axis_number);
    if (master == nullptr) {
      std::string numbers;
      for (const AxisParams& a : m.axes) {
        numbers += (numbers.empty() ? "" : ", ") + std::to_string(a.number);
      }
      r.error(file, ch.loc(master_key), "NC3008",
              param_ref(master_key, ListKind::channel) + " = " +
                  std::to_string(c.master_axis_number) +
                  " names no axis (axis numbers: " + numbers + ")");
    } else if (!master->conveyor) {
      r.error(file, ch.loc(master_key), "NC3008",
              param_ref(master_key, ListKind::channel) + " = " +
                  std::to_string(c.master_axis_number) + " names axis " + master->name +
                  ", which is not a conveyor axis (conv_sync.is_master (P-AXIS-00708) is 0)");
    }
  }
  // Seed 004 §5.2.2 P-CHAN-00366: too large -> warning 21483 and the maximum is used.
  const char* factor_key = "conveyor_sync.hold_limit_vel_factor";
  if (ch.number(factor_key) > 1000.0) {
    r.warning(file, ch.loc(factor_key), "21483",
              param_ref(factor_key, ListKind::channel) + " = " +
                  number_text(ch.number(factor_key)) + " is above 1000 (100 %); limited to 1000");
    c.hold_limit_vel_factor = 1.0;
  }
  // P-AXIS-00555 on the X axis (index 0, the 4.8.1 listing) or the conveyor axis.
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    if (m.axes[i].conv_sync_optim && (i == 0 || m.axes[i].conveyor)) c.optimised_monitoring = true;
  // Workspace (seed 004 §4.4.1): configured cuboid, else the soft limits of the first three
  // axes; with a kinematic transformation it must be configured.
  if (c.workspace_configured) {
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      const std::string neg = std::string("conveyor_sync.cart_swe_neg_") + names[i];
      const std::string pos = std::string("conveyor_sync.cart_swe_pos_") + names[i];
      if (c.workspace.lower[i] >= c.workspace.upper[i] && usable(ch, {neg, pos})) {
        r.error(file, loc_of(ch, neg, pos), "NC3007",
                param_ref(neg, ListKind::channel) + " = " + number_text(ch.number(neg)) +
                    " must be below " + param_ref(pos, ListKind::channel) + " = " +
                    number_text(ch.number(pos)));
      }
    }
  } else {
    const bool kinematic = !m.channel.trafos.empty() && m.channel.trafos[0].id != 0;
    if (kinematic) {
      r.error(file, ch.loc("trafo[0].id"), "NC3006",
              "with a kinematic transformation the conveyor workspace "
              "conveyor_sync.cart_swe_pos_x..cart_swe_neg_z (P-CHAN-00859..00864) must be "
              "configured (seed 004 section 4.4.1)");
    }
    for (int i = 0; i < 3 && i < static_cast<int>(m.axes.size()); ++i) {
      c.workspace.lower[i] = m.axes[static_cast<std::size_t>(i)].soft_limits.neg;
      c.workspace.upper[i] = m.axes[static_cast<std::size_t>(i)].soft_limits.pos;
    }
  }
}

void check_channel_refs(Machine& m, const ListValues& ch, Reporter& r) {
  const std::string& file = ch.file();
  const std::string seq = ch.text("coordinate_system.rotation_sequence");
  if (!parse_rotation_sequence(seq)) {
    r.error(file, ch.loc("coordinate_system.rotation_sequence"), "NC3004",
            param_ref("coordinate_system.rotation_sequence", ListKind::channel) + " = " + seq +
                " must be one of XYZ XZY YXZ YZX ZXY ZYX XYX XZX YXY YZY ZXZ ZYZ");
  }
  // P-CHAN-00071: "0 step, 1 trapez, 2 sin2, 3 HSC" (isg-language.md §5.5, PROG-207190411).
  // ncsim does not model the HSC profile; a channel whose every program would start on it is
  // refused rather than planned with another profile (docs/machines.md).
  if (ch.number("prog_start.slope.profile") == 3.0) {
    r.error(file, ch.loc("prog_start.slope.profile"), "NC3013",
            param_ref("prog_start.slope.profile", ListKind::channel) +
                " = 3 (HSC; \"0 step, 1 trapez, 2 sin2, 3 HSC\", PROG-207190411): ncsim does "
                "not model the HSC slope profile; write 0 (STEP), 1 (TRAPEZ) or 2 (SIN2)");
  }
  // P-CHAN-00097: "0: When FEEDHOLD is set, deceleration takes place using the currently valid
  // deceleration rate. 1: ... the parameterised delay" (P-AXIS-00053 / P-AXIS-00081). ncsim's
  // feed hold is the first (ipo/override); a channel asking for the feed-hold ramps is refused
  // rather than run with other ramps (docs/interp.md "Dynamics weighting").
  if (ch.number("use_drive_curr_limit") != 0.0) {
    r.error(file, ch.loc("use_drive_curr_limit"), "NC3013",
            param_ref("use_drive_curr_limit", ListKind::channel) +
                " = 1 (a feed hold decelerates on the feed-hold ramps P-AXIS-00053 / P-AXIS-00081, "
                "TF5200 P-CHAN-00097): ncsim's feed hold decelerates at the currently valid "
                "deceleration (0, the default) only; write 0");
  }
  // P-CHAN-00108: "<= 0: warning output, internal default 100 (mm/min); -1 or absent: no
  // warning, also 100".
  const double factor = ch.number("prog_start.feedrate_factor");
  if (factor <= 0.0) {
    if (factor != -1.0) {
      r.warning(file, ch.loc("prog_start.feedrate_factor"), "NC3022",
                param_ref("prog_start.feedrate_factor", ListKind::channel) + " = " +
                    number_text(factor) + " must be > 0 (100: F in mm/min, 0.1: m/min); 100 taken");
    }
    m.channel.feedrate_factor = 100.0;
  } else if (factor < 1e-6) {  // ncsim's bound: F x 100 / factor must stay a finite feed
    r.error(file, ch.loc("prog_start.feedrate_factor"), "NC3004",
            param_ref("prog_start.feedrate_factor", ListKind::channel) + " = " +
                number_text(factor) + " is below 1e-6 (100: F in mm/min, 0.1: m/min)");
  }
  const std::string override_type = ch.text("ncsim.path_override_type");
  if (override_type != "REDUCED" && override_type != "ORIGINAL" &&
      override_type != "REDUCED_ABOVE_100") {
    r.error(file, ch.loc("ncsim.path_override_type"), "NC3004",
            param_ref("ncsim.path_override_type", ListKind::channel) + " = " + override_type +
                " must be one of REDUCED ORIGINAL REDUCED_ABOVE_100");
  }
  if (m.channel.main_spindle_number) {
    const AxisParams* a = m.find_axis_number(*m.channel.main_spindle_number);
    if (a == nullptr || a->kind != AxisKind::spindle) {
      r.error(file, ch.loc("main_spindle_ax_nr"), "NC3007",
              param_ref("main_spindle_ax_nr", ListKind::channel) + " = " +
                  std::to_string(*m.channel.main_spindle_number) + " names no spindle axis");
    }
  }
  if (!m.channel.main_spindle_name.empty()) {
    const AxisParams* a = m.find_axis(m.channel.main_spindle_name);
    if (a == nullptr || a->kind != AxisKind::spindle) {
      r.error(file, ch.loc("main_spindle_name"), "NC3007",
              param_ref("main_spindle_name", ListKind::channel) + " = " +
                  m.channel.main_spindle_name + " names no spindle axis");
    }
  }
  if (m.channel.tracking_axis_number &&
      m.find_axis_number(*m.channel.tracking_axis_number) == nullptr) {
    r.error(file, ch.loc("log_number_tracking_axis"), "NC3007",
            param_ref("log_number_tracking_axis", ListKind::channel) + " = " +
                std::to_string(*m.channel.tracking_axis_number) + " names no axis");
  }
  // trafo[j].param / type without trafo[j].id.
  for (const char* pattern : {"trafo[].param[]", "trafo[].type"}) {
    for (const StoredValue* p : ch.matching(pattern)) {
      const std::string id_key = p->key.substr(0, p->key.find(']') + 1) + ".id";
      if (!ch.given(id_key) && !ch.rejected(id_key)) {
        r.error(file, p->loc, "NC3006",
                p->key + " is given but " + param_ref(id_key, ListKind::channel) + " is missing");
      }
    }
  }
  // Each configured kinematic must be buildable (unknown id: 292005, isg-language §5.9).
  for (std::size_t j = 0; j < m.channel.trafos.size(); ++j) {
    const TrafoParams& t = m.channel.trafos[j];
    const std::string id_key = "trafo[" + std::to_string(j) + "].id";
    if (!ch.given(id_key)) continue;
    // A rejected parameter of this kinematic would be built from its default: skip the build.
    const std::string prefix = "trafo[" + std::to_string(j) + "].";
    bool complete = !ch.rejected(prefix + "type");
    for (std::size_t k = 0; k < t.param.size() && complete; ++k) {
      complete = !ch.rejected(prefix + "param[" + std::to_string(k) + "]");
    }
    if (!complete) continue;
    const int kin_id = t.type != 0 ? t.type : t.id;
    const KinematicsBuild built = make_kinematics(kin_id, t.param);
    if (built.error) {
      r.error(file, ch.loc(id_key), built.error->id.c_str(),
              param_ref(id_key, ListKind::channel) + ": " + built.error->message);
      continue;
    }
    // Its joints are the channel's axes named by its slots (X, Y, Z [, A, B, C]).
    for (std::size_t k = 0; k < built.kinematics->axis_count(); ++k) {
      if (m.find_axis(kKinAxisNames[k]) != nullptr) continue;
      r.error(
          file, ch.loc(id_key), "NC3006",
          param_ref(id_key, ListKind::channel) + " = " + std::to_string(t.id) + ": kinematic " +
              std::to_string(kin_id) + " drives " + std::to_string(built.kinematics->axis_count()) +
              " joints, the axes named X, Y, Z, A, B, C by their slots; the channel has no axis " +
              kKinAxisNames[k]);
    }
  }
}

}  // namespace

std::vector<std::string> split_flags(const std::string& text) {
  std::vector<std::string> flags;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t bar = text.find('|', start);
    flags.push_back(text.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
    start = bar == std::string::npos ? text.size() + 1 : bar + 1;
  }
  return flags;
}

std::string hex_text(std::uint32_t bits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", bits);
  return buf;
}

void check_machine(Machine& m, const ListValues& ch, const std::vector<ListValues>& axes,
                   core::DiagnosticList& diagnostics) {
  Reporter r{diagnostics};
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    check_axis(m.axes[i], axes[i], r);
  // Names and logical numbers are unique (ncsim decision: the channel addresses axes by both).
  for (std::size_t i = 0; i < m.axes.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (m.axes[i].number == m.axes[k].number && axes[i].given("kopf.achs_nr")) {
        r.error(axes[i].file(), axes[i].loc("kopf.achs_nr"), "NC3012",
                param_ref("kopf.achs_nr", ListKind::axis) + " = " +
                    std::to_string(m.axes[i].number) + " is also the number of axis " +
                    m.axes[k].name + " (" + m.axes[k].list_file + ")");
      }
      if (m.axes[i].name == m.axes[k].name && axes[i].given("kopf.log_achs_name")) {
        r.error(axes[i].file(), axes[i].loc("kopf.log_achs_name"), "NC3012",
                param_ref("kopf.log_achs_name", ListKind::axis) + " = " + m.axes[i].name +
                    " is also the name of the axis in " + m.axes[k].list_file);
      }
    }
  }
  const bool functions_known = interpret_functions(m.channel, ch, r);
  check_channel_refs(m, ch, r);
  read_tech_table(m.channel, ch, diagnostics);
  check_conveyor(m, ch, axes, functions_known, r);
}

}  // namespace ncsim::machines::detail
