// ipo/override_trafo: the raised cap of a path override above 100 % under #TRAFO ON (issue 12;
// docs/ipo.md "Override and feed hold"). Above 100 % (REDUCED_ABOVE_100) the cap is the G00
// velocity along the path (000 l.360); under a transform the Cartesian X, Y, Z have stand-in
// limits only (program/trafo.hpp), so the cap comes from the joints: each joint at MIN(rapid,
// reference, maximum) over its own derivative bound along the entry, the path a and j those the
// joints allow at that velocity (planner::limits_from_bounds, as for the axes).

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "ipo/override.hpp"

namespace ncsim::ipo {

RaisedLimits raised_limits_joints(const planner::PlannedSegment& entry,
                                  const planner::JointLimits& joints) noexcept {
  const RaisedLimits planned{entry.segment.limits.v_max, entry.a_max, entry.d_max, entry.j_max};
  const std::size_t n = std::min(joints.joints.size(), planner::kMaxAxes);
  if (!joints.inverse || n == 0) return planned;
  planner::DerivativeBounds b;
  try {
    const planner::Chain& path = entry.segment.path;
    for (std::size_t p = 0; p < path.parts(); ++p) {
      const auto pb = planner::joint_bounds(path.part(p), joints.inverse, n);
      if (!pb) return planned;
      for (std::size_t i = 0; i < n; ++i) {
        b.d1[i] = std::max(b.d1[i], pb->d1[i]);
        b.d2[i] = std::max(b.d2[i], pb->d2[i]);
        b.d3[i] = std::max(b.d3[i], pb->d3[i]);
      }
    }
  } catch (...) {
    return planned;  // a throwing map is a failing map: the per-cycle path never throws
  }
  double rapid = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const planner::AxisLimits& q = joints.joints[i];
    if (b.d1[i] > kTiny)
      rapid = std::min(rapid, std::min({q.v_rapid, q.v_reference, q.v_max}) / b.d1[i]);
  }
  if (!std::isfinite(rapid)) return planned;
  const bool jerk = std::isfinite(entry.segment.limits.j_max);
  const planner::PathLimits lim = planner::limits_from_bounds(
      b, std::span<const planner::AxisLimits>(joints.joints.data(), n), rapid, jerk);
  if (!(lim.v_max > planned.v_max)) return planned;  // nothing to gain
  RaisedLimits out = planned;
  out.v_max = lim.v_max;
  out.a = std::min(out.a, lim.a_max);
  out.d = std::min(out.d, lim.d_max);
  if (std::isfinite(lim.j_max)) out.j = std::min(out.j, lim.j_max);
  if (!(out.a > 0.0) || !(out.d > 0.0) || !(out.j > 0.0)) return planned;
  return out;
}

}  // namespace ncsim::ipo
