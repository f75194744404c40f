// ipo/trafo_sync: the catch-up's TCP dynamics from the joints, the per-cycle joint check (see
// the header).

#include "ipo/trafo_sync.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncsim::ipo {

namespace {

using Jacobian = std::array<std::array<double, 3>, planner::kMaxAxes>;  // [joint][k]

// dq_i/dx_k at p by central differences; false when the transform fails.
bool jacobian(const planner::JointMap& inverse, const std::array<int, 3>& xyz, const AxisVec& p,
              Jacobian& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  out = Jacobian{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz[k] < 0) continue;
    AxisVec lo = p;
    AxisVec hi = p;
    lo[static_cast<std::size_t>(xyz[k])] -= h;
    hi[static_cast<std::size_t>(xyz[k])] += h;
    AxisVec qlo{};
    AxisVec qhi{};
    try {
      if (!inverse(lo, qlo) || !inverse(hi, qhi)) return false;
    } catch (...) {
      return false;
    }
    for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
      out[i][k] = (qhi[i] - qlo[i]) / (2.0 * h);
  }
  return true;
}

}  // namespace

std::optional<axes::Dynamics> tcp_dynamics(const planner::JointMap& inverse, std::array<int, 3> xyz,
                                           std::span<const axes::Dynamics> joints,
                                           std::span<const AxisVec> points) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double h = kTcpDynamicsStep;
  if (!inverse || points.empty()) return std::nullopt;
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  double v = inf;
  double a = inf;
  double j = inf;
  for (const AxisVec& p : points) {
    Jacobian jac{};
    if (!jacobian(inverse, xyz, p, jac)) return std::nullopt;
    std::array<double, planner::kMaxAxes> r{};
    std::array<double, planner::kMaxAxes> c{};
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        r[i] += std::fabs(jac[i][k]);
    // H_ikl = d(J_ik)/dx_l: the Jacobian at p +- h e_l.
    for (std::size_t l = 0; l < 3; ++l) {
      if (xyz[l] < 0) continue;
      AxisVec lo = p;
      AxisVec hi = p;
      lo[static_cast<std::size_t>(xyz[l])] -= h;
      hi[static_cast<std::size_t>(xyz[l])] += h;
      Jacobian jlo{};
      Jacobian jhi{};
      if (!jacobian(inverse, xyz, lo, jlo) || !jacobian(inverse, xyz, hi, jhi)) return std::nullopt;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          c[i] += std::fabs((jhi[i][k] - jlo[i][k]) / (2.0 * h));
    }
    // V first (velocity and the velocity-product share of the acceleration), then A, then J.
    double vp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(r[i] > 1e-12)) continue;  // a joint the TCP does not move (C beside the TCP)
      const axes::Dynamics& d = joints[i];
      const double aq = std::min(d.a_max, d.d_max);
      vp = std::min(vp, d.v_max / r[i]);
      if (c[i] > 1e-12) vp = std::min(vp, std::sqrt(aq / (2.0 * c[i])));
    }
    if (!std::isfinite(vp)) continue;  // the TCP moves no joint here
    double ap = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(r[i] > 1e-12)) continue;
      const axes::Dynamics& d = joints[i];
      const double aq = std::min(d.a_max, d.d_max);
      ap = std::min(ap, (aq - c[i] * vp * vp) / r[i]);
      if (c[i] > 1e-12) ap = std::min(ap, d.j_max / (6.0 * c[i] * vp));
    }
    double jp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(r[i] > 1e-12)) continue;
      jp = std::min(jp, (joints[i].j_max - 3.0 * c[i] * vp * ap) / r[i]);
    }
    v = std::min(v, vp);
    a = std::min(a, ap);
    j = std::min(j, jp);
  }
  const axes::Dynamics out{v, a, a, j};
  if (!axes::valid(out)) return std::nullopt;
  return out;
}

std::optional<JointOverrun> joint_overrun(const JointSetpoint& s,
                                          std::span<const axes::Dynamics> joints) noexcept {
  constexpr double tol = 1.0 + 1e-6;
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  for (std::size_t i = 0; i < n; ++i) {
    const axes::Dynamics& d = joints[i];
    if (std::fabs(s.v[i]) > d.v_max * tol) return JointOverrun{i, 'v', std::fabs(s.v[i]), d.v_max};
    const double a = std::max(d.a_max, d.d_max);
    if (std::fabs(s.a[i]) > a * tol) return JointOverrun{i, 'a', std::fabs(s.a[i]), a};
  }
  return std::nullopt;
}

}  // namespace ncsim::ipo
