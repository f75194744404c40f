// ipo/trafo_sync: the catch-up's TCP dynamics from the joints, the per-cycle joint check (see
// the header).

#include "ipo/trafo_sync.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncsim::ipo {

namespace {

using Jacobian = std::array<std::array<double, 3>, planner::kMaxAxes>;  // [joint][k]
using Hessian = std::array<Jacobian, 3>;                                // [l][joint][k]

// p moved by `d` along Cartesian axis l (a missing axis: p itself).
AxisVec moved(const AxisVec& p, const std::array<int, 3>& xyz, std::size_t l, double d) noexcept {
  AxisVec x = p;
  if (xyz[l] >= 0) x[static_cast<std::size_t>(xyz[l])] += d;
  return x;
}

// dq_i/dx_k at p by central differences; false when the transform fails.
bool jacobian(const planner::JointMap& inverse, const std::array<int, 3>& xyz, const AxisVec& p,
              Jacobian& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  out = Jacobian{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz[k] < 0) continue;
    AxisVec qlo{};
    AxisVec qhi{};
    try {
      if (!inverse(moved(p, xyz, k, -h), qlo) || !inverse(moved(p, xyz, k, h), qhi)) return false;
    } catch (...) {
      return false;
    }
    for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
      out[i][k] = (qhi[i] - qlo[i]) / (2.0 * h);
  }
  return true;
}

// H[l][i][k] = d2q_i/dx_k dx_l at p: the Jacobian at p +- h e_l.
bool hessian(const planner::JointMap& inverse, const std::array<int, 3>& xyz, const AxisVec& p,
             Hessian& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  out = Hessian{};
  for (std::size_t l = 0; l < 3; ++l) {
    if (xyz[l] < 0) continue;
    Jacobian lo{};
    Jacobian hi{};
    if (!jacobian(inverse, xyz, moved(p, xyz, l, -h), lo) ||
        !jacobian(inverse, xyz, moved(p, xyz, l, h), hi))
      return false;
    for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        out[l][i][k] = (hi[i][k] - lo[i][k]) / (2.0 * h);
  }
  return true;
}

// The transform's derivative sums at one point (the header's r_i, c_i, d_i).
struct Sums {
  std::array<double, planner::kMaxAxes> r{};  // sum_k |dq_i/dx_k|
  std::array<double, planner::kMaxAxes> c{};  // sum_kl |d2q_i/dx_k dx_l|
  std::array<double, planner::kMaxAxes> d{};  // sum_klm |d3q_i/dx_k dx_l dx_m|
};

bool sums(const planner::JointMap& inverse, const std::array<int, 3>& xyz, const AxisVec& p,
          std::size_t n, Sums& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  out = Sums{};
  Jacobian jac{};
  Hessian hes{};
  if (!jacobian(inverse, xyz, p, jac) || !hessian(inverse, xyz, p, hes)) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      out.r[i] += std::fabs(jac[i][k]);
      for (std::size_t l = 0; l < 3; ++l)
        out.c[i] += std::fabs(hes[l][i][k]);
    }
  // T_iklm = d(H_ikl)/dx_m: the second derivatives at p +- h e_m.
  for (std::size_t m = 0; m < 3; ++m) {
    if (xyz[m] < 0) continue;
    Hessian lo{};
    Hessian hi{};
    if (!hessian(inverse, xyz, moved(p, xyz, m, -h), lo) ||
        !hessian(inverse, xyz, moved(p, xyz, m, h), hi))
      return false;
    for (std::size_t l = 0; l < 3; ++l)
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          out.d[i] += std::fabs((hi[l][i][k] - lo[l][i][k]) / (2.0 * h));
  }
  return true;
}

}  // namespace

std::optional<axes::Dynamics> tcp_dynamics(const planner::JointMap& inverse, std::array<int, 3> xyz,
                                           std::span<const axes::Dynamics> joints,
                                           std::span<const AxisVec> points) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double tiny = 1e-12;
  if (!inverse || points.empty()) return std::nullopt;
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  double v = inf;
  double a = inf;
  double j = inf;
  for (const AxisVec& p : points) {
    Sums s{};
    if (!sums(inverse, xyz, p, n, s)) return std::nullopt;
    // V first (velocity, the velocity-product share of the acceleration and the velocity-cube
    // share of the jerk), then A, then J: each from what the earlier ones leave.
    double vp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > tiny)) continue;  // a joint the TCP does not move (C beside the TCP)
      const axes::Dynamics& dq = joints[i];
      const double aq = std::min(dq.a_max, dq.d_max);
      vp = std::min(vp, dq.v_max / s.r[i]);
      if (s.c[i] > tiny) vp = std::min(vp, std::sqrt(aq / (2.0 * s.c[i])));
      if (s.d[i] > tiny) vp = std::min(vp, std::cbrt(dq.j_max / (kTcpJerkCubeShare * s.d[i])));
    }
    if (!std::isfinite(vp)) continue;  // the TCP moves no joint here
    double ap = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > tiny)) continue;
      const axes::Dynamics& dq = joints[i];
      const double aq = std::min(dq.a_max, dq.d_max);
      ap = std::min(ap, (aq - s.c[i] * vp * vp) / s.r[i]);
      if (s.c[i] > tiny)
        ap = std::min(ap, (dq.j_max - s.d[i] * vp * vp * vp) / (6.0 * s.c[i] * vp));
    }
    double jp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > tiny)) continue;
      const double left = joints[i].j_max - 3.0 * s.c[i] * vp * ap - s.d[i] * vp * vp * vp;
      jp = std::min(jp, left / s.r[i]);
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
