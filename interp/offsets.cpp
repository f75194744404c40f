// interp/offsets.cpp: zero offsets, #PSET, #SCALE, #MCS, #HSC and #VECTOR LIMIT
// (interp/offsets.hpp).
#include "interp/offsets.hpp"

#include <cmath>

#include "core/number_text.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

using ast::HashKind;

void Offsets::init_zero_offsets() {
  // V.G.NP[i].V.<axis> for every channel axis: the machine's zero-offset list (P-ZERO-00003,
  // already in mm / deg), writable by the program; G53..G59 / G159=i read group i from them.
  for (std::size_t j = 0; j < ip_.machine.axes.size() && j < kMaxAxes; ++j) {
    Variable v;
    v.dims = {kZeroGroups};
    v.values.assign(kZeroGroups, 0.0);
    for (std::size_t i = 0; i < kZeroGroups; ++i)
      v.values[i] = ip_.machine.zero_offsets.offset(i, j);
    zero_names[j] = "NP.V." + grammar::to_upper(ip_.machine.axes[j].name);
    ip_.vars.provide_global(zero_names[j], std::move(v));
  }
  zero_group = static_cast<std::size_t>(ip_.machine.zero_offsets.default_index);
}

double Offsets::zero_offset(std::uint8_t axis) const {
  if (mcs_on) return 0.0;  // #MCS ON: "all offsets included in the axes" are off
  // #PSET's preset shifts the axis whatever zero offset is selected (PROG-207101835).
  // The tool length of the D in force, in the tool axis (interp/trc_words.cpp).
  const double preset = pset_offsets[axis] + ip_.trc_words.length_offset(axis);
  // G53 / G159=0 deselects every offset unless P-ZERO-00001 makes group 0 an offset too.
  if (zero_group == 0 && !ip_.machine.zero_offsets.g53_available) return preset;
  return preset + ip_.vars.global_element(zero_names[axis], zero_group);
}

bool Offsets::cs_carries_offsets() const {
  return ip_.cs.active_count() > 0 && !ip_.modal.kinematics_on && !ip_.modal.synchronised;
}

double Offsets::axis_offset(std::uint8_t axis) const {
  if (cs_carries_offsets()) {
    for (const auto& a : ip_.xyz)
      if (a == axis) return 0.0;
  }
  return zero_offset(axis);
}

std::array<double, 3> Offsets::cs_base() const {
  std::array<double, 3> base{};
  if (ip_.modal.kinematics_on || ip_.modal.synchronised) return base;
  for (std::size_t k = 0; k < 3; ++k)
    if (ip_.xyz[k]) base[k] = zero_offset(*ip_.xyz[k]);
  return base;
}

void Offsets::follow_cs_base() {
  if (!cs_carries_offsets()) return;
  const std::array<double, 3> base = cs_base();
  if (Eigen::Vector3d(base[0], base[1], base[2]) == ip_.cs.base()) return;
  const machines::Frame before = ip_.cs.active_frame();
  ip_.cs.set_base({base[0], base[1], base[2]});
  ip_.frames.rebase_cs(before, ip_.position);
  SelectCs sel;
  sel.op = CsOp::base;
  sel.base = base;
  sel.active_count = static_cast<std::uint8_t>(ip_.cs.active_count());
  ip_.emit(ip_.line, sel);
}

std::optional<double> Offsets::axis_item(const ast::Block& b, const ast::Item& it,
                                         const char* command, std::uint8_t& axis) {
  const auto index = ip_.axis_index(it.keyword);
  if (!index) {
    ip_.fail(it.loc, "NC4103",
             std::string(command) + ": axis " + std::string(it.keyword) +
                 " does not exist on machine " + ip_.machine.name);
    return std::nullopt;
  }
  axis = *index;
  return ip_.eval(b, it.value);
}

bool Offsets::hash_pset(const ast::Block& b, const ast::HashCommand& h) {
  // PROG-207101835: the axis's actual position becomes the programmed value (absolute, in the
  // program's unit); no motion; other axes keep their preset; G74 homing deselects it.
  if (mcs_on || ip_.cs.active_count() > 0 || ip_.modal.kinematics_on || ip_.modal.synchronised) {
    return ip_.fail(
        b.loc, "NC4102",
        "not supported: #PSET under #MCS, #CS, #TRAFO or #SYNC IN (ncsim models the preset "
        "as an axis offset)");
  }
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    const ast::Item& it = b.items[k];
    std::uint8_t axis = 0;
    auto v = axis_item(b, it, "#PSET", axis);
    if (!v) return false;
    if ((ip_.unknown_axes >> axis) & 1u) {
      return ip_.fail(it.loc, "NC4102",
                      "not supported: #PSET of axis " + std::string(it.keyword) +
                          " while its position is known only at run time");
    }
    const bool rotary = ip_.machine.axes[axis].kind == machines::AxisKind::rotary;
    const double value = *v * (rotary || !ip_.modal.inch ? 1.0 : 25.4);
    // Keep the machine position: position = value + zero offset (with the new preset).
    pset_offsets[axis] = 0.0;
    pset_offsets[axis] = ip_.position[axis] - value - zero_offset(axis);
  }
  return true;
}

bool Offsets::select_zero_offset(const ast::Block& b, const ast::Word& w) {
  std::size_t group = 0;
  if (w.code == 159) {
    if (w.value == ast::kNoNode) return ip_.fail(w.loc, "NC4311", "G159 needs a group: G159=<n>");
    auto v = ip_.eval(b, w.value);
    if (!v) return false;
    if (!(*v >= 0.0 && *v < static_cast<double>(kZeroGroups)) || *v != std::trunc(*v)) {
      return ip_.fail(w.loc, "NC4311",
                      "G159=" + core::number_text(*v) + ": the zero-offset group must be 0.." +
                          std::to_string(kZeroGroups - 1) + " (np_grp[i], P-ZERO-00003)");
    }
    group = static_cast<std::size_t>(*v);
  } else {
    group = w.code - 53;  // G53 -> 0, G54 -> 1, ..., G59 -> 6
  }
  zero_group = group;
  return true;
}

bool Offsets::check_offsets_frame(const ast::Block& b, AxisMask used) {
  // The zero offset shifts the axes; under #TRAFO or #SYNC IN the programmed coordinates are
  // not axis values, so the shift would need the chain below them, which ncsim does not model
  // there. Under #CS alone the chain carries the X/Y/Z offsets (follow_cs_base). `used`: the
  // axes whose absolute value the block programs (targets, G161 centres).
  if (mcs_on || (!ip_.modal.kinematics_on && !ip_.modal.synchronised)) return true;
  for (std::size_t i = 0; i < ip_.machine.axes.size() && i < kMaxAxes; ++i) {
    if (((used >> i) & 1u) == 0) continue;
    const double offset = zero_offset(static_cast<std::uint8_t>(i));
    if (offset == 0.0) continue;
    const std::string& name = ip_.machine.axes[i].name;
    core::SourceLoc at = b.loc;  // the axis word, else the block (a G161 centre)
    for (const ast::Word& w : b.words) {
      if (w.kind == ast::WordKind::axis && ip_.axis_index(w.name) == i) at = w.loc;
    }
    const std::string selected = zero_group <= 6 ? "G" + std::to_string(53 + zero_group)
                                                 : "G159=" + std::to_string(zero_group);
    const std::string where = ip_.modal.kinematics_on ? "#TRAFO ON" : "#SYNC IN";
    ip_.fail(at, "NC4102",
             "not supported: the zero offset " + core::number_text(offset) + " of axis " + name +
                 " (" + selected + ", V.G.NP[" + std::to_string(zero_group) + "].V." + name +
                 ") under " + where +
                 ": there the programmed values are not axis values and ncsim does not shift "
                 "them; select G53 (or set the offset to 0) for motions under " +
                 where);
    return false;
  }
  return true;
}

double Offsets::scale_of(std::uint8_t axis) const {
  return scale_on ? scale_factors[axis] : 1.0;
}

bool Offsets::scale_arc(const ast::Block& b, std::array<std::optional<double>, 3>& ijk,
                        std::optional<double>& radius) {
  const std::size_t p1 = ip_.modal.plane == Plane::yz ? 1 : ip_.modal.plane == Plane::zx ? 2 : 0;
  const std::size_t p2 = ip_.modal.plane == Plane::yz ? 2 : ip_.modal.plane == Plane::zx ? 0 : 1;
  const double f1 = ip_.xyz[p1] ? scale_of(*ip_.xyz[p1]) : 1.0;
  const double f2 = ip_.xyz[p2] ? scale_of(*ip_.xyz[p2]) : 1.0;
  if (f1 != f2) {
    ip_.fail(b.loc, "NC4312",
             "#SCALE: an arc needs the same factor on both plane axes (" + core::number_text(f1) +
                 " and " + core::number_text(f2) + ")");
    return false;
  }
  for (std::size_t k = 0; k < 3; ++k)
    if (ijk[k] && ip_.xyz[k]) *ijk[k] *= scale_of(*ip_.xyz[k]);
  if (radius) *radius *= f1;
  return true;
}

bool Offsets::hash_scale(const ast::Block& b, const ast::HashCommand& h) {
  if (h.kind == HashKind::scale_off) {
    scale_on = false;
    return true;
  }
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    const ast::Item& it = b.items[k];
    std::uint8_t axis = 0;
    auto v = axis_item(b, it, "#SCALE", axis);
    if (!v) return false;
    if (!(*v > 0.0) || !std::isfinite(*v)) {  // PROG-207656459: "The factor must be > 0"
      return ip_.fail(it.loc, "NC4312",
                      "#SCALE factor of " + std::string(it.keyword) + " must be > 0, got " +
                          core::number_text(*v));
    }
    if (scale_on && scale_factors[axis] != *v) {  // "Modifying ... while active: an error"
      return ip_.fail(it.loc, "NC4312",
                      "#SCALE: the factor of " + std::string(it.keyword) +
                          " cannot change while scaling is active (#SCALE OFF first)");
    }
    scale_factors[axis] = *v;
  }
  scale_on = true;
  return true;
}

bool Offsets::hash_mcs(const ast::Block& b, const ast::HashCommand& h) {
  if (h.kind == HashKind::mcs_off) {
    mcs_on = false;
    return true;
  }
  if (ip_.cs.active_count() > 0 || ip_.modal.kinematics_on || ip_.modal.synchronised) {
    return ip_.fail(b.loc, "NC4102",
                    "not supported: #MCS ON with #CS, #TRAFO or #SYNC IN active (ncsim models #MCS "
                    "as switching the zero offsets off)");
  }
  mcs_on = true;
  return true;
}

bool Offsets::hash_hsc(const ast::Block& b, const ast::HashCommand& h) {
  // Decision (docs/interp.md "#HSC"): ncsim models HSC smoothing by its tolerance-ball blend
  // (G261) within PATH_DEV; #HSC OFF restores the G260/G261 state it replaced.
  if (h.kind == HashKind::hsc_off) {
    if (hsc_saved) {
      ip_.modal.contouring = hsc_saved->first;
      ip_.modal.contour = hsc_saved->second;
      hsc_saved.reset();
    }
    return true;
  }
  const Items items{b, 0, h.item_count};
  if (!hsc_saved) hsc_saved = std::make_pair(ip_.modal.contouring, ip_.modal.contour);
  ip_.modal.contouring = true;
  ip_.modal.contour.kind = ContourKind::dev;
  if (const ast::Item* it = items.find("PATH_DEV")) {
    auto v = ip_.hash.item_value(b, it);
    if (!v) return false;
    if (!(*v > 0.0) || !std::isfinite(*v)) {
      return ip_.fail(it->loc, "NC4031",
                      "#HSC PATH_DEV must be a length > 0 mm, got " + core::number_text(*v));
    }
    ip_.modal.contour.path_dev = *v;
  }
  return true;
}

bool Offsets::hash_vector_limit(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const bool all = items.find("ALL") != nullptr;
  if (h.kind == HashKind::vector_limit_off) {
    if (all || items.find("VEL") != nullptr || h.item_count == 0) vector_vel.reset();
    return true;
  }
  if (const ast::Item* it = items.find("VEL"); it != nullptr || all) {
    // VEL<vel> in mm/min; without a value the channel's vector.velocity (P-CHAN-00090).
    double vel = ip_.machine.channel.vector_velocity;
    if (it != nullptr && it->value != ast::kNoNode) {
      auto v = ip_.hash.item_value(b, it);
      if (!v) return false;
      if (!(*v > 0.0) || !std::isfinite(*v)) {
        return ip_.fail(it->loc, "NC4030",
                        "#VECTOR LIMIT VEL must be > 0 mm/min, got " + core::number_text(*v));
      }
      vel = *v / 60.0;
    }
    vector_vel = vel;
  }
  for (const char* kw : {"ACC", "DEC", "JERK", "RADIAL_ACC", "RADIAL_JERK", "TRANS_ACC", "RAPID"}) {
    if (const ast::Item* it = items.find(kw)) {
      ip_.warn(it->loc, "NC4310",
               std::string("#VECTOR LIMIT ") + kw +
                   " is not modelled by ncsim: the axes' own limits bound the path (only VEL is)");
    }
  }
  return true;
}

}  // namespace ncsim::interp
