// interp/axis_commands.cpp: axis-bracket commands, one function per kind: X[INDP_SYN ...] /
// X[INDP_ASYN ...] (isg-language.md §6.1), S1[MC_MoveVelocity ...] (PROG-208363915),
// S1[MC_TouchProbe ...] (PROG-306968203).
#include "interp/axis_commands.hpp"

#include <cmath>

#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

/// The value of item `key`: nullopt on an evaluation error (reported), an empty optional
/// when the item is absent or has no value.
struct ItemNumbers {
  Interpreter::Impl& impl;
  const ast::Block& b;
  Items items;
  std::optional<std::optional<double>> operator()(const char* key) const {
    const ast::Item* it = items.find(key);
    if (it == nullptr || it->value == ast::kNoNode) return std::optional<double>{};
    auto v = impl.eval(b, it->value);
    if (!v) return std::nullopt;
    return v;
  }
};

}  // namespace

bool AxisCommands::run(const ast::Block& b) {
  for (const ast::AxisCommand& ac : b.axis_commands) {
    auto axis = ip_.axis_index(ac.axis);
    if (!axis) {
      return ip_.fail(
          ac.loc, "NC4103",
          "axis " + std::string(ac.axis) + " does not exist on machine " + ip_.machine.name);
    }
    bool ok = true;
    switch (ac.kind) {
      case ast::AxisCommandKind::indp_syn:
      case ast::AxisCommandKind::indp_asyn:
        ok = axis_indp(b, ac, *axis);
        break;
      case ast::AxisCommandKind::mc_move_velocity:
        ok = axis_move_velocity(b, ac, *axis);
        break;
      case ast::AxisCommandKind::mc_touch_probe:
        ok = axis_touch_probe(b, ac, *axis);
        break;
      default:
        return ip_.fail(ac.loc, "NC4512",
                        "this MC_ command is not supported by ncsim (only MC_MoveVelocity and "
                        "MC_TouchProbe)");
    }
    if (!ok) return false;
  }
  return true;
}

bool AxisCommands::axis_indp(const ast::Block& b, const ast::AxisCommand& ac, std::uint8_t axis) {
  const Items items{b, ac.first_item, ac.item_count};
  const ItemNumbers num{ip_, b, items};
  AxisCommand c;
  c.kind = ac.kind == ast::AxisCommandKind::indp_syn ? IndpKind::syn : IndpKind::asyn;
  c.axis = axis;
  bool absolute = !ip_.modal.incremental;
  for (std::uint32_t k = ac.first_item; k < ac.first_item + ac.item_count; ++k) {
    const ast::Item& it = b.items[k];
    if (!grammar::iequals(it.keyword, "G")) continue;
    auto g = ip_.eval(b, it.value);
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
  if (!*pos) return ip_.fail(ac.loc, "NC4510", "INDP command without POS");
  c.target = absolute ? **pos : ip_.position[axis] + **pos;
  if (*feed_value && **feed_value <= 0.0) {
    return ip_.fail(ac.loc, "NC4030", "INDP FEED must be greater than 0");
  }
  if (*time && **time <= 0.0) return ip_.fail(ac.loc, "NC4030", "INDP TIME must be greater than 0");
  if (*time && !(**time <= core::kLongestTime)) {
    return ip_.fail(ac.loc, "NC4032", longest_time_text("INDP TIME", **time));
  }
  if (*feed_value) c.feed = **feed_value / 60.0;  // mm/min -> mm/s (PROG-208612235)
  c.time = *time;
  c.interruptible = items.find("INTERRUPTIBLE") != nullptr;
  c.frame = ip_.frames.frame();
  if (c.interruptible && !ip_.machine.channel.conveyor) {
    return ip_.fail(ac.loc, "50603", "INTERRUPTIBLE needs conveyor synchronisation (FCT_DLM)");
  }
  if (!c.rapid && !c.feed && !c.time) {
    return ip_.fail(ac.loc, "20008", "INDP G01 motion needs FEED or TIME");
  }
  ip_.position[axis] = c.target;
  // INDP_ASYN runs on beside the program; INTERRUPTIBLE may be cut short by the next #SYNC IN:
  // where the axis is afterwards is run-time state (decode-only: the target).
  if (c.kind == IndpKind::asyn || c.interruptible) {
    const AxisMask bit = AxisMask{1} << axis;
    // INDP_ASYN: asked for only by the blocks that program the axis again (P-CHAN-00451). An
    // INTERRUPTIBLE motion (cut short by the next #SYNC IN) and an axis unknown for another
    // reason (#SYNC, G74) stay asked for by every block that uses the position.
    const bool other = (ip_.unknown_axes & ~ip_.indp_unknown & bit) != 0;
    if (c.kind == IndpKind::asyn && !other)
      ip_.indp_unknown |= bit;
    else
      ip_.indp_unknown &= ~bit;
    ip_.unknown_axes |= bit;
  }
  ip_.emit(ip_.line, c);
  ip_.blocks_without_motion = 0;
  return true;
}

bool AxisCommands::axis_move_velocity(const ast::Block& b, const ast::AxisCommand& ac,
                                      std::uint8_t axis) {
  const ItemNumbers num{ip_, b, Items{b, ac.first_item, ac.item_count}};
  MoveVelocity m;
  m.axis = axis;
  auto v = num("VELOCITY"), a = num("ACCELERATION"), d = num("DECELERATION"), j = num("JERK"),
       dir = num("DIRECTION");
  if (!v || !a || !d || !j || !dir) return false;
  if (!*v) return ip_.fail(ac.loc, "NC4511", "MC_MoveVelocity needs Velocity");
  // PLCopen: the velocity is a magnitude, Direction gives the sign (PROG-208363915).
  if (**v < 0.0) {
    return ip_.fail(ac.loc, "NC4030", "MC_MoveVelocity Velocity must not be negative");
  }
  m.velocity = **v / 1000.0;  // um/s -> mm/s (PROG-208363915), once, here
  m.acceleration = a->value_or(0.0);
  m.deceleration = d->value_or(0.0);
  m.jerk = j->value_or(0.0);
  // MC_Direction: 1 positive, 3 negative, 4 current (PROG-208363915); 2 (shortest way) is for
  // modulo positioning, not for a velocity.
  const double code = dir->value_or(1.0);
  if (code == 1.0) {
    m.direction = VelocityDirection::positive;
  } else if (code == 3.0) {
    m.direction = VelocityDirection::negative;
  } else if (code == 4.0) {
    m.direction = VelocityDirection::current;
  } else {
    return ip_.fail(ac.loc, "NC4030",
                    "MC_MoveVelocity Direction " + core::number_text(code) +
                        " is not 1 (positive), 3 (negative) or 4 (current)");
  }
  ip_.emit(ip_.line, m);
  return true;
}

bool AxisCommands::axis_touch_probe(const ast::Block& b, const ast::AxisCommand& ac,
                                    std::uint8_t axis) {
  const ItemNumbers num{ip_, b, Items{b, ac.first_item, ac.item_count}};
  ProbeArm p;
  p.axis = axis;
  auto ch = num("CHANNEL"), mode = num("MODE");
  if (!ch || !mode) return false;
  p.channel = static_cast<int>(std::lround(ch->value_or(1.0)));
  if (*mode) {
    // Mode 1 falling, 2 rising edge (PROG-306968203); absent: P-AXIS-00518.
    if (**mode == 1.0) {
      p.edge = ProbeEdge::falling;
    } else if (**mode == 2.0) {
      p.edge = ProbeEdge::rising;
    } else {
      return ip_.fail(ac.loc, "NC4030",
                      "MC_TouchProbe Mode " + core::number_text(**mode) +
                          " is not 1 (falling edge) or 2 (rising edge)");
    }
  }
  ip_.emit(ip_.line, p);
  return true;
}

}  // namespace ncsim::interp
