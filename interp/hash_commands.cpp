// interp/hash_commands.cpp: # commands, one function per command (run_hash dispatches).
// Axis-bracket commands (INDP, MC_*) are in axis_commands.cpp.
#include <cmath>

#include "core/number_text.hpp"
#include "grammar/keywords.hpp"
#include "interp/cs_select.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

using ast::HashKind;

/// Conveyor velocity unit factor to mm/s (seed 004 §3 "#SYNC IN", VEL_RESOLUTION).
std::optional<double> velocity_factor(std::string_view unit) {
  if (unit.empty() || grammar::iequals(unit, "mm/min")) return 1.0 / 60.0;
  if (grammar::iequals(unit, "m/min")) return 1000.0 / 60.0;
  if (grammar::iequals(unit, "m/s")) return 1000.0;
  if (grammar::iequals(unit, "mm/s")) return 1.0;
  if (grammar::iequals(unit, "um/min")) return 1.0 / 60000.0;
  if (grammar::iequals(unit, "um/s")) return 1.0 / 1000.0;
  return std::nullopt;
}

}  // namespace

bool Interpreter::Impl::spline_on(core::SourceLoc at) {
  // #SPLINE ON or G151 (PROG-207209611, PROG-207256971): the last chosen type; the current
  // position is the first vertex.
  if (modal.contouring) {
    return fail(at, "120255", "spline together with polynomial contouring (DIAG 120255)");
  }
  spline = OpenSpline{spline_type, 1};
  emit(line, SplineBegin{spline_type, frames.frame(), position, snapshot()});
  return true;
}

bool Interpreter::Impl::spline_off(core::SourceLoc at) {
  // #SPLINE OFF or G150: Akima needs >= 3 vertices (PROG-207216267), B-spline >= 4 control
  // points (PROG-207263627).
  if (!spline) return fail(at, "NC4403", "#SPLINE OFF / G150 without #SPLINE ON / G151");
  // Repeated vertices count once, as the planner counts them (issue 34: check refuses what
  // time / run would).
  const std::size_t need = spline->type == SplineType::akima ? 3 : 4;
  if (spline->distinct < need) {
    std::string has = std::to_string(spline->distinct);
    if (spline->distinct != spline->points)
      has += " distinct (" + std::to_string(spline->points) + " with repeated ones)";
    return fail(at, "NC4401",
                std::string(spline->type == SplineType::akima ? "Akima" : "B-spline") +
                    " #SPLINE OFF needs at least " + std::to_string(need) + " points, has " + has);
  }
  emit(line, SplineEnd{spline->type, spline->points});
  spline.reset();
  return true;
}

SlopeType Interpreter::Impl::channel_slope() const {
  switch (machine.channel.start_slope) {
    case machines::SlopeProfile::step:
      return SlopeType::step;
    case machines::SlopeProfile::trapez:
      return SlopeType::trapez;
    case machines::SlopeProfile::sin2:
      return SlopeType::sin2;
  }
  return SlopeType::step;
}

std::optional<double> HashCommands::item_value(const ast::Block& b, const ast::Item* it) {
  if (it == nullptr || it->value == ast::kNoNode) return std::nullopt;
  return ip_.eval(b, it->value);
}

// One function per # command (or family); run_hash only dispatches.
bool HashCommands::run_hash(const ast::Block& b, const ast::HashCommand& h) {
  const core::SourceLoc at = h.loc;
  switch (h.kind) {
    case HashKind::sync_in:
      return hash_sync_in(b, h);
    case HashKind::sync_out:
    case HashKind::sync_off:
      return hash_sync_out(b, h);
    case HashKind::cs_def:
    case HashKind::cs_on:
    case HashKind::cs_off:
    case HashKind::cs_off_all:
      return hash_cs(b, h);
    case HashKind::kin_id:
    case HashKind::trafo_on:
    case HashKind::trafo_off:
    case HashKind::trafo_steps:
      return hash_kinematics(b, h);
    case HashKind::caxtrack_on:
    case HashKind::caxtrack_off:
      return hash_caxtrack(b, h);
    case HashKind::spline_type_akima:
    case HashKind::spline_type_bspline:
      ip_.spline_type =
          h.kind == HashKind::spline_type_akima ? SplineType::akima : SplineType::bspline;
      return true;
    case HashKind::spline_on:
      return ip_.spline_on(at);
    case HashKind::spline_off:
      return ip_.spline_off(at);
    case HashKind::contour_mode:
    case HashKind::contour_mode_on:
    case HashKind::contour_mode_off:
      return hash_contour_mode(b, h);
    case HashKind::slope:
    case HashKind::slope_default:
      return hash_slope(b, h);
    case HashKind::machine_data:
      return hash_machine_data(b, h);
    case HashKind::msg:
      return hash_msg(b, h);
    case HashKind::flush:
    case HashKind::flush_continue:
    case HashKind::flush_wait:
      ip_.emit(ip_.line, Flush{h.kind == HashKind::flush            ? FlushKind::stop
                               : h.kind == HashKind::flush_continue ? FlushKind::continue_
                                                                    : FlushKind::wait});
      return true;
    case HashKind::time:
      return hash_time(b, h);
    case HashKind::transvelmin_on:
      return hash_transvelmin_on(b, h);
    case HashKind::transvelmin_off:
      ip_.modal.transvelmin.reset();
      return true;
    case HashKind::wait_indp_all:
      ip_.emit(ip_.line, WaitIndp{0});
      ip_.blocks_without_motion = 0;
      return true;
    case HashKind::wait_indp:
      return hash_wait_indp(b, h);
    case HashKind::delete_:
      return hash_delete(b, h);
    case HashKind::pre_if:
    case HashKind::pre_else:
      return hash_pre_if(b, h);
    case HashKind::file_name:
      return ip_.subs.hash_file_name(b, h);
    case HashKind::hsc_on:
    case HashKind::hsc_off:
      return ip_.offsets.hash_hsc(b, h);
    case HashKind::tangfeed:
      return ip_.trc_words.hash_tangfeed(b, h);
    case HashKind::vector_limit_on:
    case HashKind::vector_limit_off:
      return ip_.offsets.hash_vector_limit(b, h);
    case HashKind::scale_on:
    case HashKind::scale_off:
      return ip_.offsets.hash_scale(b, h);
    case HashKind::mcs_on:
    case HashKind::mcs_off:
      return ip_.offsets.hash_mcs(b, h);
    case HashKind::accepted:
      return hash_accepted(b);
    case HashKind::signal:
    case HashKind::signal_syn:
    case HashKind::wait_signal:
    case HashKind::wait_signal_syn:
    case HashKind::signal_read:
    case HashKind::signal_remove:
    case HashKind::signal_remove_syn:
      return hash_signal(b, h);
    case HashKind::pset:
      return ip_.offsets.hash_pset(b, h);
    case HashKind::bcs_def:
    case HashKind::bcs_on:
    case HashKind::bcs_off:
    case HashKind::bcs_off_all:
      return ip_.fail(at, "NC4104", "#BCS is not supported by ncsim");
    default:
      return true;  // #VAR, #ENDVAR, #COMMENT, #INIT, #ENDIF: nothing to do at run time
  }
}

bool HashCommands::hash_sync_in(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const core::SourceLoc at = h.loc;
  if (ip_.modal.synchronised) return ip_.fail(at, "22265", "#SYNC IN while already synchronised");
  if (ip_.cs.active_count() > 0) {
    return ip_.fail(at, "22262", "#SYNC IN with an active #CS coordinate system");
  }
  if (!duplicate_free(b, h, {"CONVEYOR", "CONV_VEL", "VEL_RESOLUTION", "FEED_CONT"})) return false;
  std::optional<std::uint8_t> conveyor;
  if (const ast::Item* c = items.find("CONVEYOR")) {
    // The word names the axis: its faults are the word's, not the machine's.
    conveyor = ip_.axis_index(c->text);
    if (!conveyor) {
      return ip_.fail(
          c->loc, "NC4103",
          "CONVEYOR=" + std::string(c->text) + ": no such axis on machine " + ip_.machine.name);
    }
    if (!ip_.machine.axes[*conveyor].conveyor.has_value()) {
      return ip_.fail(c->loc, "NC4501",
                      "CONVEYOR=" + std::string(c->text) +
                          " is not a conveyor axis (conv_sync.is_master is not set in its list)");
    }
  } else if (ip_.machine.channel.conveyor) {
    if (const auto* a =
            ip_.machine.find_axis_number(ip_.machine.channel.conveyor->master_axis_number)) {
      conveyor = ip_.axis_index(a->name);
    }
  }
  if (!conveyor || !ip_.machine.channel.conveyor ||
      !ip_.machine.axes[*conveyor].conveyor.has_value()) {
    return ip_.fail(
        at, "NC4501",
        "#SYNC IN needs a conveyor axis (FCT_DLM in P-CHAN-00650, conv_sync.is_master)");
  }
  const ast::Item* vel = items.find("CONV_VEL");
  if (vel == nullptr) return ip_.fail(at, "NC4507", "#SYNC IN needs CONV_VEL");
  auto v = item_value(b, vel);
  if (!v) return false;
  if (*v <= 0.0) {  // the expected belt velocity; 0 or less synchronises with nothing
    return ip_.fail(vel->loc, "NC4030",
                    "CONV_VEL " + core::number_text(*v) + " must be greater than 0");
  }
  const ast::Item* res = items.find("VEL_RESOLUTION");
  auto factor = velocity_factor(res != nullptr ? res->text : std::string_view{});
  if (!factor)
    return ip_.fail(res->loc, "NC4507", "unknown VEL_RESOLUTION " + std::string(res->text));
  SyncIn s;
  s.conveyor = *conveyor;
  s.conv_vel =
      ip_.options.conv_vel ? *ip_.options.conv_vel : *v * *factor;  // sweep --conv-vel follow
  // Under #TRAFO ON the axis X is a joint: its V [deg/s] is no velocity in the conveying
  // direction (decision, docs/conveyor.md "50587"); the belt's share of the joints is checked
  // per block at run time (NC6211, program/trafo_path.cpp).
  if (ip_.xyz[0] && !ip_.machine.channel.conveyor->x_virtual && !ip_.modal.kinematics_on) {
    const double v_max = ip_.machine.axes[*ip_.xyz[0]].dynamics.v_max;
    if (v_max > 0.0 && s.conv_vel > v_max) {
      return ip_.fail(at, "50587",
                      "CONV_VEL " + core::number_text(s.conv_vel) +
                          " mm/s exceeds the maximum velocity in the conveying "
                          "direction " +
                          core::number_text(v_max) + " mm/s");
    }
  }
  if (!feed_cont(b, items, s.feed_cont)) return false;
  s.feed_cont_auto = items.find("FEED_CONT_AUTO") != nullptr;
  s.kinematics = ip_.modal.kinematics_on;
  s.latch = ip_.latch;  // answered by the barrier before this block
  ip_.emit(ip_.line, s);
  ip_.blocks_without_motion = 0;
  ++ip_.world_waits;
  // The catch-up starts where the tool is in PCS1: run-time state (a barrier before the
  // next block that uses the position); decode-only: belt travel 0.
  ip_.position = ip_.frames.sync_rebased(true, ip_.position);
  ip_.unknown_axes = ip_.path_axes;
  ip_.indp_unknown &= ~ip_.path_axes;
  ip_.modal.synchronised = true;
  ip_.motion_since_sync = false;
  return true;
}

bool HashCommands::duplicate_free(const ast::Block& b, const ast::HashCommand& h,
                                  std::initializer_list<std::string_view> keywords) {
  for (std::string_view key : keywords) {
    const ast::Item* first = nullptr;
    for (std::uint32_t k = 0; k < h.item_count && k < b.items.size(); ++k) {
      if (!grammar::iequals(b.items[k].keyword, key)) continue;
      if (first != nullptr) {
        return ip_.fail(b.items[k].loc, "NC4507",
                        std::string(key) + " is given twice (first at column " +
                            std::to_string(first->loc.column) + ")");
      }
      first = &b.items[k];
    }
  }
  return true;
}

bool HashCommands::feed_cont(const ast::Block& b, const Items& items, std::optional<double>& out) {
  // FEED_CONT: relative velocity in mm/min (seed 004 l.529), converted once, here.
  const ast::Item* fc = items.find("FEED_CONT");
  if (fc == nullptr) return true;
  auto f = item_value(b, fc);
  if (!f) return false;
  if (*f < 0.0) {
    return ip_.fail(fc->loc, "NC4030", "FEED_CONT " + core::number_text(*f) + " is negative");
  }
  out = *f / 60.0;
  return true;
}

bool HashCommands::hash_sync_out(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const core::SourceLoc at = h.loc;
  if (!ip_.modal.synchronised) return ip_.fail(at, "NC4503", "#SYNC OUT without #SYNC IN");
  if (ip_.cs.active_count() > 0) {
    return ip_.fail(at, "22263", "#SYNC OUT with an active #CS coordinate system");
  }
  if (!duplicate_free(b, h, {"FEED_CONT"})) return false;
  SyncOut s;
  if (!feed_cont(b, items, s.feed_cont)) return false;
  s.feed_cont_auto = items.find("FEED_CONT_AUTO") != nullptr;
  ip_.emit(ip_.line, s);
  ip_.position = ip_.frames.sync_rebased(false, ip_.position);
  ip_.unknown_axes = ip_.path_axes;  // where the tool left the moving workpiece: run time
  ip_.indp_unknown &= ~ip_.path_axes;
  ip_.modal.synchronised = false;
  ip_.motion_since_sync = true;
  ip_.departure_pending = true;
  return true;
}

bool HashCommands::hash_cs(const ast::Block& b, const ast::HashCommand& h) {
  const core::SourceLoc at = h.loc;
  if (ip_.modal.synchronised && !ip_.motion_since_sync) {
    return ip_.fail(at, "NC4505", "#CS only after the synchronisation movement (seed 004 §2.1.1)");
  }
  std::vector<const ast::Item*> g0, g1;
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    (b.items[k].group == 0 ? g0 : g1).push_back(&b.items[k]);
  }
  std::optional<int> id;
  std::vector<const ast::Item*>* values = nullptr;
  if (g1.empty() && g0.size() > 1) {
    values = &g0;
  } else {
    if (g0.size() == 1) {
      auto v = item_value(b, g0[0]);
      if (!v) return false;
      id = static_cast<int>(std::lround(*v));
    }
    if (!g1.empty()) values = &g1;
  }
  ip_.offsets.follow_cs_base();
  SelectCs sel;
  sel.id = id;
  sel.base = ip_.offsets.cs_base();
  if (values != nullptr) {
    std::array<double, 6> vals{};
    for (std::size_t k = 0; k < values->size() && k < 6; ++k) {
      if ((*values)[k]->kind == ast::ItemKind::empty) continue;
      auto v = item_value(b, (*values)[k]);
      if (!v) return false;
      vals[k] = *v;
    }
    sel.values = vals;
  }
  sel.op = h.kind == HashKind::cs_def   ? CsOp::def
           : h.kind == HashKind::cs_on  ? CsOp::on
           : h.kind == HashKind::cs_off ? CsOp::off
                                        : CsOp::off_all;
  const machines::Frame before = ip_.cs.active_frame();
  if (const auto err = apply_selection(ip_.cs, sel)) return ip_.fail(at, err->id, err->message);
  if (sel.op != CsOp::def) ip_.frames.rebase_cs(before, ip_.position);
  sel.active_count = static_cast<std::uint8_t>(ip_.cs.active_count());
  ip_.emit(ip_.line, sel);
  return true;
}

bool HashCommands::hash_kinematics(const ast::Block& b, const ast::HashCommand& h) {
  const core::SourceLoc at = h.loc;
  if (ip_.modal.synchronised) {
    return ip_.fail(at, "NC4504",
                    "kinematic selection inside #SYNC IN/OUT is not allowed (seed 004 §2.1.1)");
  }
  if (ip_.departure_pending) {
    // The first motion after #SYNC OUT is the desynchronisation movement from the belt's
    // motion (004 l.529), planned in the coordinates the tool left the workpiece in.
    return ip_.fail(at, "NC4504",
                    "kinematic selection between #SYNC OUT and its desynchronisation motion (the "
                    "first motion after #SYNC OUT, seed 004 §2.1.1): program that motion first");
  }
  if (h.kind == HashKind::kin_id) {
    if (h.item_count == 0) return ip_.fail(at, "292005", "#KIN ID needs an id");
    auto v = item_value(b, &b.items[0]);
    if (!v) return false;
    const int id = static_cast<int>(std::lround(*v));
    bool known = false;
    for (const auto& t : ip_.machine.channel.trafos)
      known = known || t.id == id;
    if (!known) {
      return ip_.fail(at, "292005",
                      "kinematic id " + std::to_string(id) + " is not configured on machine " +
                          ip_.machine.name);
    }
    if (ip_.modal.kinematics_on) return ip_.fail(at, "NC4508", "#KIN ID while #TRAFO ON is active");
    ip_.kin_id = id;
  } else if (h.kind == HashKind::trafo_on || h.kind == HashKind::trafo_off) {
    const bool on = h.kind == HashKind::trafo_on;
    if (on && !ip_.kin_id && ip_.machine.channel.trafos.empty()) {
      return ip_.fail(at, "292005", "#TRAFO ON without a configured kinematic");
    }
    if (on && !ip_.kin_id) ip_.kin_id = ip_.machine.channel.trafos.front().id;
    if (ip_.modal.kinematics_on != on) {  // the position goes through the kinematic
      const auto e = ip_.frames.rebase_trafo(on, ip_.kin_id, ip_.position);
      if (e) return ip_.fail(at, e->id, e->message);
    }
    ip_.modal.kinematics_on = on;
  } else {
    return ip_.fail(at, "NC4104", "#TRAFO [...] multi-step form is not supported by ncsim");
  }
  ip_.emit(ip_.line, Kinematics{ip_.kin_id, ip_.modal.kinematics_on});
  return true;
}

bool HashCommands::hash_caxtrack(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const core::SourceLoc at = h.loc;
  CaxTrack c;
  c.on = h.kind == HashKind::caxtrack_on;
  if (const ast::Item* ax = items.find("AX")) {
    c.axis = ip_.axis_index(ax->text);
    if (!c.axis)
      return ip_.fail(ax->loc, "NC4103", "axis " + std::string(ax->text) + " does not exist");
  }
  for (auto [key, slot] : {std::pair<const char*, double*>{"ANGLIMIT", &c.anglimit},
                           {"OFFSET", &c.offset},
                           {"ANGPOS", &c.angpos}}) {
    if (const ast::Item* it = items.find(key)) {
      auto v = item_value(b, it);
      if (!v) return false;
      *slot = *v;
    }
  }
  // ROTMODE, ANGPOS given, the words ncsim does not run (docs/caxtrack.md)
  c.angpos_given = items.find("ANGPOS") != nullptr;
  if (const ast::Item* it = items.find("ROTMODE")) {
    auto v = item_value(b, it);
    if (!v) return false;
    c.rotmode = *v;
  }
  for (const char* key : {"OPTALIGN", "SCALEFACT", "AXNR", "START_STROKE"})
    if (c.unsupported.empty() && items.find(key) != nullptr) c.unsupported = key;
  if (c.anglimit < 0.0 || c.anglimit > 360.0 || std::fabs(c.offset) > 360.0 ||
      std::fabs(c.angpos) > 360.0) {
    return ip_.fail(at, "21135", "#CAXTRACK: ANGLIMIT, OFFSET or ANGPOS out of range");
  }
  ip_.modal.caxtrack = c.on;
  ip_.emit(ip_.line, c);
  return true;
}

bool HashCommands::hash_contour_mode(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  if (h.kind == HashKind::contour_mode_off) {
    ip_.modal.contouring = false;
    return true;
  }
  static constexpr std::pair<const char*, ContourKind> kKinds[] = {
      {"DEV", ContourKind::dev},
      {"DIST", ContourKind::dist},
      {"DIST_SOFT", ContourKind::dist_soft},
      {"DIST_MASTER", ContourKind::dist_master},
      {"POS", ContourKind::pos},
      {"PTP", ContourKind::ptp}};
  for (const auto& [name, kind] : kKinds) {
    if (items.find(name) != nullptr) ip_.modal.contour.kind = kind;
  }
  for (auto [key, slot] : {std::pair<const char*, double*>{"PATH_DEV", &ip_.modal.contour.path_dev},
                           {"PRE_DIST", &ip_.modal.contour.pre_dist},
                           {"POST_DIST", &ip_.modal.contour.post_dist}}) {
    if (const ast::Item* it = items.find(key)) {
      auto v = item_value(b, it);
      if (!v) return false;
      // A ball of radius 0 or a blend from 0 mm before the corner cannot be (§5.3's values are
      // lengths; the planner's blend needs them > 0).
      if (!(*v > 0.0) || !std::isfinite(*v)) {
        return ip_.fail(it->loc, "NC4031",
                        std::string("#CONTOUR MODE ") + key + " must be a length > 0 mm, got " +
                            core::number_text(*v));
      }
      *slot = *v;
    }
  }
  // TF5200 PROG-475135755: CONST_VEL=0 (the default) runs the contouring section at the
  // maximum permissible velocity, as the planner does; CONST_VEL=1 (constant velocity in it,
  // 000 l.366's tolerance ball) is not planned (docs/planner.md "Tolerance balls").
  if (const ast::Item* it = items.find("CONST_VEL")) {
    auto v = item_value(b, it);
    if (!v) return false;
    if (*v != 0.0)
      return ip_.fail(it->loc, "NC4104",
                      "#CONTOUR MODE CONST_VEL=" + core::number_text(*v) +
                          " (a constant path velocity in the contouring section) is not "
                          "supported by ncsim; it plans CONST_VEL=0, the default");
  }
  if (h.kind == HashKind::contour_mode_on) ip_.modal.contouring = true;
  return true;
}

bool HashCommands::hash_slope(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const core::SourceLoc at = h.loc;
  if (ip_.modal.synchronised) {
    return ip_.fail(at, "NC4506", "#SLOPE is not allowed while synchronised (seed 004 §2.1.7)");
  }
  // `#SLOPE DEFAULT` restores P-CHAN-00071 prog_start.slope.profile (isg-language.md §5.5,
  // PROG-207190411).
  if (h.kind == HashKind::slope_default) {
    ip_.modal.slope = ip_.channel_slope();
    return true;
  }
  ip_.modal.slope = SlopeType::step;
  if (const ast::Item* t = items.find("TYPE")) {
    if (grammar::iequals(t->text, "TRAPEZ"))
      ip_.modal.slope = SlopeType::trapez;
    else if (grammar::iequals(t->text, "SIN2"))
      ip_.modal.slope = SlopeType::sin2;
    else if (grammar::iequals(t->text, "HSC"))
      ip_.modal.slope = SlopeType::hsc;
    else if (!grammar::iequals(t->text, "STEP")) {
      return ip_.fail(t->loc, "NC4509", "unknown #SLOPE TYPE " + std::string(t->text));
    }
  }
  return true;
}

bool HashCommands::hash_msg(const ast::Block& b, const ast::HashCommand& h) {
  Message m;
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    const ast::Item& it = b.items[k];
    if (it.kind == ast::ItemKind::string) m.text = std::string(it.text);
    if (grammar::iequals(it.keyword, "SYN")) m.mode = MessageMode::syn;
    if (grammar::iequals(it.keyword, "ACK")) m.mode = MessageMode::ack;
    if (grammar::iequals(it.keyword, "SYN_ACK")) m.mode = MessageMode::syn_ack;
  }
  ip_.emit(ip_.line, std::move(m));
  return true;
}

bool HashCommands::hash_wait_indp(const ast::Block& b, const ast::HashCommand& h) {
  WaitIndp w;
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    const ast::Item& it = b.items[k];
    const std::string_view name = it.keyword.empty() ? it.text : it.keyword;
    auto index = ip_.axis_index(name);
    if (!index) return ip_.fail(it.loc, "NC4103", "axis " + std::string(name) + " does not exist");
    w.axes |= AxisMask{1} << *index;
  }
  ip_.emit(ip_.line, w);
  ip_.blocks_without_motion = 0;
  return true;
}

bool HashCommands::hash_pre_if(const ast::Block& b, const ast::HashCommand& h) {
  const core::SourceLoc at = h.loc;
  if (h.kind == HashKind::pre_if) {
    auto v = ip_.eval(b, h.expr);
    if (!v) return false;
    if (is_true(*v)) return true;
  }
  // skip to the matching #ELSE (from a false #IF) or #ENDIF (isg-language.md §4.8)
  int depth = 0;
  const bool from_if = h.kind == HashKind::pre_if;
  for (std::uint32_t k = ip_.pc.ordinal;; ++k) {
    const ast::Block* nb = ip_.fetch({ip_.pc.file, k});
    if (nb == nullptr) return ip_.fail(at, "NC4026", "#IF without #ENDIF");
    const auto* nh = std::get_if<ast::HashCommand>(&nb->body);
    if (nh == nullptr) continue;
    if (nh->kind == HashKind::pre_if) ++depth;
    if (nh->kind == HashKind::pre_endif) {
      if (depth == 0) {
        ip_.pc.ordinal = k + 1;
        return true;
      }
      --depth;
    }
    if (nh->kind == HashKind::pre_else && depth == 0 && from_if) {
      ip_.pc.ordinal = k + 1;
      return true;
    }
  }
}

bool HashCommands::hash_time(const ast::Block& b, const ast::HashCommand& h) {
  if (h.item_count == 0) return ip_.fail(h.loc, "20013", "#TIME without a time");
  auto v = item_value(b, &b.items[0]);
  if (!v) return false;
  if (*v < 0.0) return ip_.fail(h.loc, "20013", "negative dwell time");
  if (!(*v <= core::kLongestTime)) return ip_.fail(h.loc, "20751", longest_time_text("dwell", *v));
  ip_.emit(ip_.line, Dwell{*v});
  if (*v > 0.0) ip_.blocks_without_motion = 0;  // a 0 s dwell passes no time
  return true;
}

bool HashCommands::hash_transvelmin_on(const ast::Block& b, const ast::HashCommand& h) {
  ip_.modal.transvelmin = 0.0;
  if (h.item_count > 0) {
    auto v = item_value(b, &b.items[0]);
    if (!v) return false;
    ip_.modal.transvelmin = *v / 60.0;  // mm/min -> mm/s (PROG-207486091)
  }
  return true;
}

bool HashCommands::hash_delete(const ast::Block& b, const ast::HashCommand& h) {
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    VarRef ref;
    if (b.items[k].value == ast::kNoNode) continue;
    if (!ip_.evaluator.resolve(b, b.items[k].value, ref)) return ip_.fail_eval();
    ip_.vars.remove(ref);
  }
  return true;
}

bool HashCommands::hash_accepted(const ast::Block& b) {
  // Read, shown in trace, no effect on motion or time in ncsim's model (docs/language.md).
  Message m;
  m.mode = MessageMode::accepted;
  m.text = std::string(b.text.substr(0, std::min<std::size_t>(b.text.size(), 200)));
  while (!m.text.empty() && (m.text.back() == ' ' || m.text.back() == '\r'))
    m.text.pop_back();
  ip_.emit(ip_.line, std::move(m));
  return true;
}

}  // namespace ncsim::interp
