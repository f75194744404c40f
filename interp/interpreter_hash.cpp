// interp/interpreter_hash.cpp: # commands and axis-bracket commands (INDP, MC_*).
#include <cmath>

#include "core/number_text.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

using ast::HashKind;

struct Items {
  const ast::Block& b;
  std::uint32_t first, count;
  const ast::Item* find(std::string_view keyword) const {
    for (std::uint32_t k = first; k < first + count && k < b.items.size(); ++k) {
      if (grammar::iequals(b.items[k].keyword, keyword)) return &b.items[k];
    }
    return nullptr;
  }
};

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
  spline = Spline{spline_type, {position}, feed.value_or(0.0), snapshot()};
  return true;
}

bool Interpreter::Impl::spline_off(core::SourceLoc at) {
  // #SPLINE OFF or G150: Akima needs >= 3 vertices (PROG-207216267), B-spline >= 4 control
  // points (PROG-207263627).
  if (!spline) return fail(at, "NC4403", "#SPLINE OFF / G150 without #SPLINE ON / G151");
  const std::size_t need = spline->type == SplineType::akima ? 3 : 4;
  if (spline->points.size() < need) {
    return fail(at, "NC4401",
                std::string(spline->type == SplineType::akima ? "Akima" : "B-spline") +
                    " #SPLINE OFF needs at least " + std::to_string(need) + " points, has " +
                    std::to_string(spline->points.size()));
  }
  if (!feed) return fail(at, "20008", "the spline needs a feed F");
  spline->feed = *feed;
  emit(line, std::move(*spline));
  spline.reset();
  return true;
}

bool Interpreter::Impl::run_hash(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const auto value_of = [&](const ast::Item* it) -> std::optional<double> {
    if (it == nullptr || it->value == ast::kNoNode) return std::nullopt;
    return eval(b, it->value);
  };
  const core::SourceLoc at = h.loc;
  switch (h.kind) {
    case HashKind::sync_in: {
      if (modal.synchronised) return fail(at, "22265", "#SYNC IN while already synchronised");
      if (cs.active_count() > 0) {
        return fail(at, "22262", "#SYNC IN with an active #CS coordinate system");
      }
      std::optional<std::uint8_t> conveyor;
      if (const ast::Item* c = items.find("CONVEYOR")) {
        conveyor = axis_index(c->text);
      } else if (machine.channel.conveyor) {
        if (const auto* a =
                machine.find_axis_number(machine.channel.conveyor->master_axis_number)) {
          conveyor = axis_index(a->name);
        }
      }
      if (!conveyor || !machine.channel.conveyor || !machine.axes[*conveyor].conveyor.has_value()) {
        return fail(
            at, "NC4501",
            "#SYNC IN needs a conveyor axis (FCT_DLM in P-CHAN-00650, conv_sync.is_master)");
      }
      const ast::Item* vel = items.find("CONV_VEL");
      if (vel == nullptr) return fail(at, "NC4507", "#SYNC IN needs CONV_VEL");
      auto v = value_of(vel);
      if (!v) return false;
      const ast::Item* res = items.find("VEL_RESOLUTION");
      auto factor = velocity_factor(res != nullptr ? res->text : std::string_view{});
      if (!factor)
        return fail(res->loc, "NC4507", "unknown VEL_RESOLUTION " + std::string(res->text));
      SyncIn s;
      s.conveyor = *conveyor;
      s.conv_vel = *v * *factor;
      if (xyz[0] && !machine.channel.conveyor->x_virtual) {
        const double v_max = machine.axes[*xyz[0]].dynamics.v_max;
        if (v_max > 0.0 && s.conv_vel > v_max) {
          return fail(at, "50587",
                      "CONV_VEL " + core::number_text(s.conv_vel) +
                          " mm/s exceeds the maximum velocity in the conveying "
                          "direction " +
                          core::number_text(v_max) + " mm/s");
        }
      }
      if (const ast::Item* fc = items.find("FEED_CONT")) {
        auto f = value_of(fc);
        if (!f) return false;
        s.feed_cont = *f;
      }
      s.feed_cont_auto = items.find("FEED_CONT_AUTO") != nullptr;
      emit(line, WaitProbe{*conveyor});
      emit(line, s);
      blocks_without_motion = 0;
      modal.synchronised = true;
      motion_since_sync = false;
      return true;
    }
    case HashKind::sync_out:
    case HashKind::sync_off: {
      if (!modal.synchronised) return fail(at, "NC4503", "#SYNC OUT without #SYNC IN");
      if (cs.active_count() > 0) {
        return fail(at, "22263", "#SYNC OUT with an active #CS coordinate system");
      }
      SyncOut s;
      if (const ast::Item* fc = items.find("FEED_CONT")) {
        auto f = value_of(fc);
        if (!f) return false;
        s.feed_cont = *f;
      }
      s.feed_cont_auto = items.find("FEED_CONT_AUTO") != nullptr;
      emit(line, s);
      modal.synchronised = false;
      motion_since_sync = true;
      return true;
    }
    case HashKind::cs_def:
    case HashKind::cs_on:
    case HashKind::cs_off:
    case HashKind::cs_off_all: {
      if (modal.synchronised && !motion_since_sync) {
        return fail(at, "NC4505", "#CS only after the synchronisation movement (seed 004 §2.1.1)");
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
          auto v = value_of(g0[0]);
          if (!v) return false;
          id = static_cast<int>(std::lround(*v));
        }
        if (!g1.empty()) values = &g1;
      }
      SelectCs sel;
      sel.id = id;
      std::optional<machines::CsValues> cv;
      if (values != nullptr) {
        std::array<double, 6> vals{};
        for (std::size_t k = 0; k < values->size() && k < 6; ++k) {
          if ((*values)[k]->kind == ast::ItemKind::empty) continue;
          auto v = value_of((*values)[k]);
          if (!v) return false;
          vals[k] = *v;
        }
        sel.values = vals;
        cv = machines::CsValues{{vals[0], vals[1], vals[2]}, {vals[3], vals[4], vals[5]}};
      }
      std::optional<machines::CsError> err;
      switch (h.kind) {
        case HashKind::cs_def:
          sel.op = CsOp::def;
          err = cs.def(id, cv.value_or(machines::CsValues{}));
          break;
        case HashKind::cs_on:
          sel.op = CsOp::on;
          err = cs.on(id, cv);
          break;
        case HashKind::cs_off:
          sel.op = CsOp::off;
          err = cs.off();
          break;
        default:
          sel.op = CsOp::off_all;
          cs.off_all();
          break;
      }
      if (err) return fail(at, err->id, err->message);
      sel.active_count = static_cast<std::uint8_t>(cs.active_count());
      emit(line, sel);
      return true;
    }
    case HashKind::kin_id:
    case HashKind::trafo_on:
    case HashKind::trafo_off:
    case HashKind::trafo_steps: {
      if (modal.synchronised) {
        return fail(at, "NC4504",
                    "kinematic selection inside #SYNC IN/OUT is not allowed (seed 004 §2.1.1)");
      }
      if (h.kind == HashKind::kin_id) {
        if (h.item_count == 0) return fail(at, "292005", "#KIN ID needs an id");
        auto v = value_of(&b.items[0]);
        if (!v) return false;
        const int id = static_cast<int>(std::lround(*v));
        bool known = false;
        for (const auto& t : machine.channel.trafos)
          known = known || t.id == id;
        if (!known) {
          return fail(at, "292005",
                      "kinematic id " + std::to_string(id) + " is not configured on machine " +
                          machine.name);
        }
        if (modal.kinematics_on) return fail(at, "NC4508", "#KIN ID while #TRAFO ON is active");
        kin_id = id;
      } else if (h.kind == HashKind::trafo_on) {
        if (!kin_id && machine.channel.trafos.empty()) {
          return fail(at, "292005", "#TRAFO ON without a configured kinematic");
        }
        if (!kin_id) kin_id = machine.channel.trafos.front().id;
        modal.kinematics_on = true;
      } else if (h.kind == HashKind::trafo_off) {
        modal.kinematics_on = false;
      } else {
        return fail(at, "NC4104", "#TRAFO [...] multi-step form is not supported by ncsim");
      }
      emit(line, Kinematics{kin_id, modal.kinematics_on});
      return true;
    }
    case HashKind::caxtrack_on:
    case HashKind::caxtrack_off: {
      CaxTrack c;
      c.on = h.kind == HashKind::caxtrack_on;
      if (const ast::Item* ax = items.find("AX")) {
        c.axis = axis_index(ax->text);
        if (!c.axis)
          return fail(ax->loc, "NC4103", "axis " + std::string(ax->text) + " does not exist");
      }
      for (auto [key, slot] : {std::pair<const char*, double*>{"ANGLIMIT", &c.anglimit},
                               {"OFFSET", &c.offset},
                               {"ANGPOS", &c.angpos}}) {
        if (const ast::Item* it = items.find(key)) {
          auto v = value_of(it);
          if (!v) return false;
          *slot = *v;
        }
      }
      if (c.anglimit < 0.0 || c.anglimit > 360.0 || std::fabs(c.offset) > 360.0 ||
          std::fabs(c.angpos) > 360.0) {
        return fail(at, "21135", "#CAXTRACK: ANGLIMIT, OFFSET or ANGPOS out of range");
      }
      modal.caxtrack = c.on;
      emit(line, c);
      return true;
    }
    case HashKind::spline_type_akima:
      spline_type = SplineType::akima;
      return true;
    case HashKind::spline_type_bspline:
      spline_type = SplineType::bspline;
      return true;
    case HashKind::spline_on:
      return spline_on(at);
    case HashKind::spline_off:
      return spline_off(at);
    case HashKind::contour_mode:
    case HashKind::contour_mode_on:
    case HashKind::contour_mode_off: {
      if (h.kind == HashKind::contour_mode_off) {
        modal.contouring = false;
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
        if (items.find(name) != nullptr) modal.contour.kind = kind;
      }
      for (auto [key, slot] : {std::pair<const char*, double*>{"PATH_DEV", &modal.contour.path_dev},
                               {"PRE_DIST", &modal.contour.pre_dist},
                               {"POST_DIST", &modal.contour.post_dist}}) {
        if (const ast::Item* it = items.find(key)) {
          auto v = value_of(it);
          if (!v) return false;
          *slot = *v;
        }
      }
      if (h.kind == HashKind::contour_mode_on) modal.contouring = true;
      return true;
    }
    case HashKind::slope:
    case HashKind::slope_default: {
      if (modal.synchronised) {
        return fail(at, "NC4506", "#SLOPE is not allowed while synchronised (seed 004 §2.1.7)");
      }
      modal.slope = SlopeType::step;
      if (const ast::Item* t = items.find("TYPE")) {
        if (grammar::iequals(t->text, "TRAPEZ"))
          modal.slope = SlopeType::trapez;
        else if (grammar::iequals(t->text, "SIN2"))
          modal.slope = SlopeType::sin2;
        else if (grammar::iequals(t->text, "HSC"))
          modal.slope = SlopeType::hsc;
        else if (!grammar::iequals(t->text, "STEP")) {
          return fail(t->loc, "NC4509", "unknown #SLOPE TYPE " + std::string(t->text));
        }
      }
      return true;
    }
    case HashKind::machine_data: {
      MachineData md;
      md.syn = items.find("SYN") != nullptr;
      md.wait = items.find("WAIT") != nullptr;
      if (const ast::Item* ax = items.find("AX")) {
        md.axis = axis_index(ax->text);
        if (!md.axis)
          return fail(ax->loc, "NC4103", "axis " + std::string(ax->text) + " does not exist");
      }
      if (const ast::Item* nr = items.find("AXNR")) {
        // AXNR: logical axis number, kopf.achs_nr (PROG-207492747).
        if (nr->value == ast::kNoNode) return fail(nr->loc, "NC4002", "AXNR needs a value");
        auto v = value_of(nr);
        if (!v) return false;
        for (std::size_t k = 0; k < machine.axes.size() && k < kMaxAxes; ++k) {
          if (machine.axes[k].number == static_cast<int>(std::lround(*v))) {
            md.axis = static_cast<std::uint8_t>(k);
          }
        }
        if (!md.axis) {
          return fail(nr->loc, "NC4103", "no axis with logical number " + core::number_text(*v));
        }
      }
      if (const ast::Item* p = items.find("AXPARAM")) md.parameter = std::string(p->text);
      for (std::uint32_t k = 0; k < h.item_count; ++k) {
        // <Param_ID>=value / <Param_ID>.<idx> value (PROG-207492747): any keyword outside the
        // command's table is a parameter id; it is passed on as "<id> <value>".
        const ast::Item& it = b.items[k];
        if (it.key != ast::kUnknownKeyword || it.keyword.empty()) continue;
        if (it.value == ast::kNoNode) {
          return fail(it.loc, "NC4002",
                      "#MACHINE DATA: " + std::string(it.keyword) + " needs a value");
        }
        auto v = value_of(&it);
        if (!v) return false;
        if (!md.parameter.empty()) md.parameter += ' ';
        md.parameter += std::string(it.keyword) + " " + core::number_text(*v);
      }
      emit(line, std::move(md));
      return true;
    }
    case HashKind::msg: {
      Message m;
      for (std::uint32_t k = 0; k < h.item_count; ++k) {
        const ast::Item& it = b.items[k];
        if (it.kind == ast::ItemKind::string) m.text = std::string(it.text);
        if (grammar::iequals(it.keyword, "SYN") || grammar::iequals(it.keyword, "ACK") ||
            grammar::iequals(it.keyword, "SYN_ACK")) {
          m.mode = std::string(it.keyword);
        }
      }
      emit(line, std::move(m));
      return true;
    }
    case HashKind::flush:
      emit(line, Flush{FlushKind::stop});
      return true;
    case HashKind::flush_continue:
      emit(line, Flush{FlushKind::continue_});
      return true;
    case HashKind::flush_wait:
      emit(line, Flush{FlushKind::wait});
      return true;
    case HashKind::time: {
      if (h.item_count == 0) return fail(at, "20013", "#TIME without a time");
      auto v = value_of(&b.items[0]);
      if (!v) return false;
      if (*v < 0.0) return fail(at, "20013", "negative dwell time");
      emit(line, Dwell{*v});
      blocks_without_motion = 0;
      return true;
    }
    case HashKind::transvelmin_on: {
      modal.transvelmin = 0.0;
      if (h.item_count > 0) {
        auto v = value_of(&b.items[0]);
        if (!v) return false;
        modal.transvelmin = *v / 60.0;  // mm/min -> mm/s (PROG-207486091)
      }
      return true;
    }
    case HashKind::transvelmin_off:
      modal.transvelmin.reset();
      return true;
    case HashKind::wait_indp_all:
      emit(line, WaitIndp{0});
      blocks_without_motion = 0;
      return true;
    case HashKind::wait_indp: {
      WaitIndp w;
      for (std::uint32_t k = 0; k < h.item_count; ++k) {
        const ast::Item& it = b.items[k];
        const std::string_view name = it.keyword.empty() ? it.text : it.keyword;
        auto index = axis_index(name);
        if (!index) return fail(it.loc, "NC4103", "axis " + std::string(name) + " does not exist");
        w.axes |= AxisMask{1} << *index;
      }
      emit(line, w);
      blocks_without_motion = 0;
      return true;
    }
    case HashKind::delete_:
      for (std::uint32_t k = 0; k < h.item_count; ++k) {
        VarRef ref;
        if (b.items[k].value == ast::kNoNode) continue;
        if (!evaluator.resolve(b, b.items[k].value, ref)) return fail_eval();
        vars.remove(ref);
      }
      return true;
    case HashKind::pre_if: {
      auto v = eval(b, h.expr);
      if (!v) return false;
      if (is_true(*v)) return true;
      [[fallthrough]];
    }
    case HashKind::pre_else: {
      // skip to the matching #ELSE (from a false #IF) or #ENDIF (isg-language.md §4.8)
      int depth = 0;
      const bool from_if = h.kind == HashKind::pre_if;
      for (std::uint32_t k = pc.ordinal;; ++k) {
        const ast::Block* nb = fetch({pc.file, k});
        if (nb == nullptr) return fail(at, "NC4026", "#IF without #ENDIF");
        const auto* nh = std::get_if<ast::HashCommand>(&nb->body);
        if (nh == nullptr) continue;
        if (nh->kind == HashKind::pre_if) ++depth;
        if (nh->kind == HashKind::pre_endif) {
          if (depth == 0) {
            pc.ordinal = k + 1;
            return true;
          }
          --depth;
        }
        if (nh->kind == HashKind::pre_else && depth == 0 && from_if) {
          pc.ordinal = k + 1;
          return true;
        }
      }
    }
    case HashKind::bcs_def:
    case HashKind::bcs_on:
    case HashKind::bcs_off:
    case HashKind::bcs_off_all:
      return fail(at, "NC4104", "#BCS is not supported by ncsim");
    default:
      return true;  // #VAR, #ENDVAR, #COMMENT, #INIT, #ENDIF: nothing to do at run time
  }
}

bool Interpreter::Impl::run_axis_commands(const ast::Block& b) {
  for (const ast::AxisCommand& ac : b.axis_commands) {
    auto axis = axis_index(ac.axis);
    if (!axis) {
      return fail(ac.loc, "NC4103",
                  "axis " + std::string(ac.axis) + " does not exist on machine " + machine.name);
    }
    const Items items{b, ac.first_item, ac.item_count};
    const auto num = [&](const char* key) -> std::optional<std::optional<double>> {
      const ast::Item* it = items.find(key);
      if (it == nullptr || it->value == ast::kNoNode) return std::optional<double>{};
      auto v = eval(b, it->value);
      if (!v) return std::nullopt;
      return v;
    };
    switch (ac.kind) {
      case ast::AxisCommandKind::indp_syn:
      case ast::AxisCommandKind::indp_asyn: {
        AxisCommand c;
        c.kind = ac.kind == ast::AxisCommandKind::indp_syn ? IndpKind::syn : IndpKind::asyn;
        c.axis = *axis;
        bool absolute = !modal.incremental;
        for (std::uint32_t k = ac.first_item; k < ac.first_item + ac.item_count; ++k) {
          const ast::Item& it = b.items[k];
          if (!grammar::iequals(it.keyword, "G")) continue;
          auto g = eval(b, it.value);
          if (!g) return false;
          const int code = static_cast<int>(std::lround(*g));
          if (code == 0) c.rapid = true;
          if (code == 1 || code == 100) c.rapid = false;
          if (code == 90) absolute = true;
          if (code == 91) absolute = false;
        }
        auto pos = num("POS");
        auto feed_value = num("FEED");
        auto time = num("TIME");
        if (!pos || !feed_value || !time) return false;
        if (!*pos) return fail(ac.loc, "NC4510", "INDP command without POS");
        c.target = absolute ? **pos : position[*axis] + **pos;
        if (*feed_value && **feed_value <= 0.0) {
          return fail(ac.loc, "NC4030", "INDP FEED must be greater than 0");
        }
        if (*time && **time <= 0.0)
          return fail(ac.loc, "NC4030", "INDP TIME must be greater than 0");
        if (*feed_value) c.feed = **feed_value / 60.0;  // mm/min -> mm/s (PROG-208612235)
        c.time = *time;
        c.interruptible = items.find("INTERRUPTIBLE") != nullptr;
        if (c.interruptible && !machine.channel.conveyor) {
          return fail(ac.loc, "50603", "INTERRUPTIBLE needs conveyor synchronisation (FCT_DLM)");
        }
        if (!c.rapid && !c.feed && !c.time) {
          return fail(ac.loc, "20008", "INDP G01 motion needs FEED or TIME");
        }
        position[*axis] = c.target;
        emit(line, c);
        blocks_without_motion = 0;
        break;
      }
      case ast::AxisCommandKind::mc_move_velocity: {
        MoveVelocity m;
        m.axis = *axis;
        auto v = num("VELOCITY"), a = num("ACCELERATION"), d = num("DECELERATION"), j = num("JERK"),
             dir = num("DIRECTION");
        if (!v || !a || !d || !j || !dir) return false;
        if (!*v) return fail(ac.loc, "NC4511", "MC_MoveVelocity needs Velocity");
        // PLCopen: the velocity is a magnitude, Direction gives the sign (PROG-208363915).
        if (**v < 0.0) {
          return fail(ac.loc, "NC4030", "MC_MoveVelocity Velocity must not be negative");
        }
        m.velocity = **v / 1000.0;  // um/s -> mm/s (PROG-208363915)
        m.acceleration = a->value_or(0.0);
        m.deceleration = d->value_or(0.0);
        m.jerk = j->value_or(0.0);
        m.direction = static_cast<int>(std::lround(dir->value_or(1.0)));
        emit(line, m);
        break;
      }
      case ast::AxisCommandKind::mc_touch_probe: {
        ProbeArm p;
        p.axis = *axis;
        auto ch = num("CHANNEL"), mode = num("MODE");
        if (!ch || !mode) return false;
        p.channel = static_cast<int>(std::lround(ch->value_or(1.0)));
        if (*mode) p.mode = static_cast<int>(std::lround(**mode));
        emit(line, p);
        break;
      }
      default:
        return fail(ac.loc, "NC4512",
                    "this MC_ command is not supported by ncsim (only MC_MoveVelocity and "
                    "MC_TouchProbe)");
    }
  }
  return true;
}

}  // namespace ncsim::interp
