// interp/interpreter_offsets.cpp: what shifts, scales or limits the programmed path without
// being a motion of its own: zero offsets G53..G59 / G159=n and V.G.NP[i].V.<axis> (TF5200
// PROG-206487307, P-ZERO), #SCALE (PROG-207656459), #MCS ON/OFF (PROG-208517515), #HSC and
// #VECTOR LIMIT (PROG-207477899), and the # commands ncsim reads without an effect
// (docs/interp.md "Offsets, scaling and path limits").
#include <cmath>

#include "core/number_text.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {

using ast::HashKind;

void Interpreter::Impl::init_zero_offsets() {
  // V.G.NP[i].V.<axis> for every channel axis: the machine's zero-offset list (P-ZERO-00003,
  // already in mm / deg), writable by the program; G53..G59 / G159=i read group i from them.
  for (std::size_t j = 0; j < machine.axes.size() && j < kMaxAxes; ++j) {
    Variable v;
    v.dims = {kZeroGroups};
    v.values.assign(kZeroGroups, 0.0);
    for (std::size_t i = 0; i < kZeroGroups; ++i)
      v.values[i] = machine.zero_offsets.offset(i, j);
    zero_names[j] = "NP.V." + grammar::to_upper(machine.axes[j].name);
    vars.provide_global(zero_names[j], std::move(v));
  }
  zero_group = static_cast<std::size_t>(machine.zero_offsets.default_index);
}

double Interpreter::Impl::zero_offset(std::uint8_t axis) const {
  if (mcs_on) return 0.0;  // #MCS ON: "all offsets included in the axes" are off
  // #PSET's preset shifts the axis whatever zero offset is selected (PROG-207101835).
  const double preset = pset_offsets[axis];
  // G53 / G159=0 deselects every offset unless P-ZERO-00001 makes group 0 an offset too.
  if (zero_group == 0 && !machine.zero_offsets.g53_available) return preset;
  return preset + vars.global_element(zero_names[axis], zero_group);
}

std::optional<double> Interpreter::Impl::axis_item(const ast::Block& b, const ast::Item& it,
                                                   const char* command, std::uint8_t& axis) {
  const auto index = axis_index(it.keyword);
  if (!index) {
    fail(it.loc, "NC4103",
         std::string(command) + ": axis " + std::string(it.keyword) +
             " does not exist on machine " + machine.name);
    return std::nullopt;
  }
  axis = *index;
  return eval(b, it.value);
}

bool Interpreter::Impl::hash_pset(const ast::Block& b, const ast::HashCommand& h) {
  // PROG-207101835: the axis's actual position becomes the programmed value (absolute, in the
  // program's unit); no motion; other axes keep their preset; G74 homing deselects it.
  if (mcs_on || cs.active_count() > 0 || modal.kinematics_on || modal.synchronised) {
    return fail(b.loc, "NC4102",
                "not supported: #PSET under #MCS, #CS, #TRAFO or #SYNC IN (ncsim models the preset "
                "as an axis offset)");
  }
  for (std::uint32_t k = 0; k < h.item_count; ++k) {
    const ast::Item& it = b.items[k];
    std::uint8_t axis = 0;
    auto v = axis_item(b, it, "#PSET", axis);
    if (!v) return false;
    if ((unknown_axes >> axis) & 1u) {
      return fail(it.loc, "NC4102",
                  "not supported: #PSET of axis " + std::string(it.keyword) +
                      " while its position is known only at run time");
    }
    const bool rotary = machine.axes[axis].kind == machines::AxisKind::rotary;
    const double value = *v * (rotary || !modal.inch ? 1.0 : 25.4);
    // Keep the machine position: position = value + zero offset (with the new preset).
    pset_offsets[axis] = 0.0;
    pset_offsets[axis] = position[axis] - value - zero_offset(axis);
  }
  return true;
}

bool Interpreter::Impl::select_zero_offset(const ast::Block& b, const ast::Word& w) {
  std::size_t group = 0;
  if (w.code == 159) {
    if (w.value == ast::kNoNode) return fail(w.loc, "NC4311", "G159 needs a group: G159=<n>");
    auto v = eval(b, w.value);
    if (!v) return false;
    if (!(*v >= 0.0 && *v < static_cast<double>(kZeroGroups)) || *v != std::trunc(*v)) {
      return fail(w.loc, "NC4311",
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

bool Interpreter::Impl::check_offsets_frame(const ast::Block& b, AxisMask programmed) {
  // The zero offset shifts the axes; under a #CS frame or #TRAFO the programmed coordinates are
  // not axis values, so the shift would need the chain below them, which ncsim does not model.
  if (mcs_on || (cs.active_count() == 0 && !modal.kinematics_on && !modal.synchronised))
    return true;
  for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i) {
    if (((programmed >> i) & 1u) == 0) continue;
    if (zero_offset(static_cast<std::uint8_t>(i)) != 0.0) {
      fail(b.loc, "NC4102",
           "not supported: a zero offset (G" +
               std::to_string(53 + std::min<std::size_t>(zero_group, 6)) + ") of axis " +
               machine.axes[i].name + " together with #CS, #TRAFO or #SYNC IN; select G53 first");
      return false;
    }
  }
  return true;
}

double Interpreter::Impl::scale_of(std::uint8_t axis) const {
  return scale_on ? scale_factors[axis] : 1.0;
}

bool Interpreter::Impl::scale_arc(const ast::Block& b, std::array<std::optional<double>, 3>& ijk,
                                  std::optional<double>& radius) {
  const std::size_t p1 = modal.plane == Plane::yz ? 1 : modal.plane == Plane::zx ? 2 : 0;
  const std::size_t p2 = modal.plane == Plane::yz ? 2 : modal.plane == Plane::zx ? 0 : 1;
  const double f1 = xyz[p1] ? scale_of(*xyz[p1]) : 1.0;
  const double f2 = xyz[p2] ? scale_of(*xyz[p2]) : 1.0;
  if (f1 != f2) {
    fail(b.loc, "NC4312",
         "#SCALE: an arc needs the same factor on both plane axes (" + core::number_text(f1) +
             " and " + core::number_text(f2) + ")");
    return false;
  }
  for (std::size_t k = 0; k < 3; ++k)
    if (ijk[k] && xyz[k]) *ijk[k] *= scale_of(*xyz[k]);
  if (radius) *radius *= f1;
  return true;
}

bool Interpreter::Impl::hash_scale(const ast::Block& b, const ast::HashCommand& h) {
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
      return fail(it.loc, "NC4312",
                  "#SCALE factor of " + std::string(it.keyword) + " must be > 0, got " +
                      core::number_text(*v));
    }
    if (scale_on && scale_factors[axis] != *v) {  // "Modifying ... while active: an error"
      return fail(it.loc, "NC4312",
                  "#SCALE: the factor of " + std::string(it.keyword) +
                      " cannot change while scaling is active (#SCALE OFF first)");
    }
    scale_factors[axis] = *v;
  }
  scale_on = true;
  return true;
}

bool Interpreter::Impl::hash_mcs(const ast::Block& b, const ast::HashCommand& h) {
  if (h.kind == HashKind::mcs_off) {
    mcs_on = false;
    return true;
  }
  if (cs.active_count() > 0 || modal.kinematics_on || modal.synchronised) {
    return fail(b.loc, "NC4102",
                "not supported: #MCS ON with #CS, #TRAFO or #SYNC IN active (ncsim models #MCS "
                "as switching the zero offsets off)");
  }
  mcs_on = true;
  return true;
}

bool Interpreter::Impl::hash_hsc(const ast::Block& b, const ast::HashCommand& h) {
  // Decision (docs/interp.md "#HSC"): ncsim models HSC smoothing by its tolerance-ball blend
  // (G261) within PATH_DEV; #HSC OFF restores the G260/G261 state it replaced.
  if (h.kind == HashKind::hsc_off) {
    if (hsc_saved) {
      modal.contouring = hsc_saved->first;
      modal.contour = hsc_saved->second;
      hsc_saved.reset();
    }
    return true;
  }
  const Items items{b, 0, h.item_count};
  if (!hsc_saved) hsc_saved = std::make_pair(modal.contouring, modal.contour);
  modal.contouring = true;
  modal.contour.kind = ContourKind::dev;
  if (const ast::Item* it = items.find("PATH_DEV")) {
    auto v = item_value(b, it);
    if (!v) return false;
    if (!(*v > 0.0) || !std::isfinite(*v)) {
      return fail(it->loc, "NC4031",
                  "#HSC PATH_DEV must be a length > 0 mm, got " + core::number_text(*v));
    }
    modal.contour.path_dev = *v;
  }
  return true;
}

bool Interpreter::Impl::hash_vector_limit(const ast::Block& b, const ast::HashCommand& h) {
  const Items items{b, 0, h.item_count};
  const bool all = items.find("ALL") != nullptr;
  if (h.kind == HashKind::vector_limit_off) {
    if (all || items.find("VEL") != nullptr || h.item_count == 0) vector_vel.reset();
    return true;
  }
  if (const ast::Item* it = items.find("VEL"); it != nullptr || all) {
    // VEL<vel> in mm/min; without a value the channel's vector.velocity (P-CHAN-00090).
    double vel = machine.channel.vector_velocity;
    if (it != nullptr && it->value != ast::kNoNode) {
      auto v = item_value(b, it);
      if (!v) return false;
      if (!(*v > 0.0) || !std::isfinite(*v)) {
        return fail(it->loc, "NC4030",
                    "#VECTOR LIMIT VEL must be > 0 mm/min, got " + core::number_text(*v));
      }
      vel = *v / 60.0;
    }
    vector_vel = vel;
  }
  for (const char* kw : {"ACC", "DEC", "JERK", "RADIAL_ACC", "RADIAL_JERK", "TRANS_ACC", "RAPID"}) {
    if (const ast::Item* it = items.find(kw)) {
      warn(it->loc, "NC4310",
           std::string("#VECTOR LIMIT ") + kw +
               " is not modelled by ncsim: the axes' own limits bound the path (only VEL is)");
    }
  }
  return true;
}

bool Interpreter::Impl::hash_accepted(const ast::Block& b) {
  // Read, shown in trace, no effect on motion or time in ncsim's model (docs/language.md).
  Message m;
  m.mode = MessageMode::accepted;
  m.text = std::string(b.text.substr(0, std::min<std::size_t>(b.text.size(), 200)));
  while (!m.text.empty() && (m.text.back() == ' ' || m.text.back() == '\r'))
    m.text.pop_back();
  emit(line, std::move(m));
  return true;
}

}  // namespace ncsim::interp
