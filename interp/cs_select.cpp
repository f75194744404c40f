// interp/cs_select: see cs_select.hpp.

#include "interp/cs_select.hpp"

#include <array>
#include <variant>

namespace ncsim::interp {

std::optional<machines::CsError> apply_selection(machines::CsStack& cs, const SelectCs& sel) {
  std::optional<machines::CsValues> values;
  if (sel.values) {
    const std::array<double, 6>& v = *sel.values;
    values = machines::CsValues{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
  }
  cs.set_base({sel.base[0], sel.base[1], sel.base[2]});
  switch (sel.op) {
    case CsOp::base:
      break;
    case CsOp::def:
      return cs.def(sel.id, values.value_or(machines::CsValues{}));
    case CsOp::on:
      return cs.on(sel.id, values);
    case CsOp::off:
      return cs.off();
    case CsOp::off_all:
      cs.off_all();
      break;
  }
  return std::nullopt;
}

std::optional<Command> command_in_mcs(const Command& c, const machines::Frame& pcs_to_mcs,
                                      const machines::Machine& machine) {
  const CoordFrame* frame = nullptr;
  if (const auto* m = std::get_if<Motion>(&c.body)) frame = &m->frame;
  if (const auto* p = std::get_if<SplinePoint>(&c.body)) frame = &p->frame;
  if (frame == nullptr || frame->space != Space::pcs || frame->kinematics) return std::nullopt;
  std::array<int, 3> xyz{-1, -1, -1};
  const char* names[3] = {"X", "Y", "Z"};
  for (std::size_t k = 0; k < 3; ++k)
    if (const machines::AxisParams* a = machine.find_axis(names[k]))
      xyz[k] = static_cast<int>(a - machine.axes.data());
  const auto to_mcs = [&](AxisValues& p) {
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz[k] >= 0) q[static_cast<Eigen::Index>(k)] = p[static_cast<std::size_t>(xyz[k])];
    q = pcs_to_mcs.apply(q);
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz[k] >= 0) p[static_cast<std::size_t>(xyz[k])] = q[static_cast<Eigen::Index>(k)];
  };
  // A rotated chain mixes X, Y and Z: all three MCS targets follow from a programmed one.
  const auto programmed_xyz = [&](AxisMask& programmed) {
    AxisMask xyz_bits = 0;
    for (const int i : xyz)
      if (i >= 0) xyz_bits |= AxisMask{1} << i;
    if ((programmed & xyz_bits) != 0) programmed |= xyz_bits;
  };
  Command out = c;
  if (auto* m = std::get_if<Motion>(&out.body)) {
    to_mcs(m->start);
    to_mcs(m->end);
    programmed_xyz(m->programmed);
    m->frame = CoordFrame{};
    if (m->arc) {
      if (!pcs_to_mcs.rotation.isIdentity(0.0)) {
        m->arc.reset();  // its plane turns: the target alone is decidable here
      } else {           // a shift moves the centre with the points
        for (std::size_t k = 0; k < 3; ++k) {
          const double d = pcs_to_mcs.translation[static_cast<Eigen::Index>(k)];
          if (xyz[k] == m->arc->axis_1) m->arc->centre_1 += d;
          if (xyz[k] == m->arc->axis_2) m->arc->centre_2 += d;
        }
      }
    }
  } else {
    auto& p = std::get<SplinePoint>(out.body);
    to_mcs(p.point);
    programmed_xyz(p.programmed);
    p.frame = CoordFrame{};
  }
  return out;
}

}  // namespace ncsim::interp
