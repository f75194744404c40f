// tracking/trafo_sync: the catch-up's TCP dynamics from the joints, the per-cycle joint check (see
// the header).

#include "tracking/trafo_sync.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/tolerance.hpp"

namespace ncsim::tracking {

namespace {

using Jacobian = std::array<std::array<double, 3>, planner::kMaxAxes>;  // [joint][k]
using Hessian = std::array<Jacobian, 3>;                                // [l][joint][k]

// p moved by `d` along Cartesian axis l (a missing axis: p itself).
planner::AxisVec moved(const planner::AxisVec& p, const std::array<int, 3>& xyz, std::size_t l,
                       double d) noexcept {
  planner::AxisVec x = p;
  if (xyz[l] >= 0) x[static_cast<std::size_t>(xyz[l])] += d;
  return x;
}

// dq_i/dx_k at p by central differences; false when the transform fails.
bool jacobian(const planner::JointMap& inverse, const std::array<int, 3>& xyz,
              const planner::AxisVec& p, Jacobian& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  out = Jacobian{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (xyz[k] < 0) continue;
    planner::AxisVec qlo{};
    planner::AxisVec qhi{};
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
bool hessian(const planner::JointMap& inverse, const std::array<int, 3>& xyz,
             const planner::AxisVec& p, Hessian& out) noexcept {
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

bool sums(const planner::JointMap& inverse, const std::array<int, 3>& xyz,
          const planner::AxisVec& p, std::size_t n, Sums& out) noexcept {
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
                                           std::span<const planner::AxisVec> points) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!inverse || points.empty()) return std::nullopt;
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  double v = inf;
  double a = inf;
  double j = inf;
  for (const planner::AxisVec& p : points) {
    Sums s{};
    if (!sums(inverse, xyz, p, n, s)) return std::nullopt;
    // V first (velocity, the velocity-product share of the acceleration and the velocity-cube
    // share of the jerk), then A, then J: each from what the earlier ones leave.
    double vp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > kTiny)) continue;  // a joint the TCP does not move (C beside the TCP)
      const axes::Dynamics& dq = joints[i];
      const double aq = std::min(dq.a_max, dq.d_max);
      vp = std::min(vp, dq.v_max / s.r[i]);
      if (s.c[i] > kTiny) vp = std::min(vp, std::sqrt(aq / (2.0 * s.c[i])));
      if (s.d[i] > kTiny) vp = std::min(vp, std::cbrt(dq.j_max / (kTcpJerkCubeShare * s.d[i])));
    }
    if (!std::isfinite(vp)) continue;  // the TCP moves no joint here
    double ap = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > kTiny)) continue;
      const axes::Dynamics& dq = joints[i];
      const double aq = std::min(dq.a_max, dq.d_max);
      ap = std::min(ap, (aq - s.c[i] * vp * vp) / s.r[i]);
      if (s.c[i] > kTiny)
        ap = std::min(ap, (dq.j_max - s.d[i] * vp * vp * vp) / (6.0 * s.c[i] * vp));
    }
    double jp = inf;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(s.r[i] > kTiny)) continue;
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

// The belt's share of the joints on a PCS1 block (header, docs/conveyor.md).

bool path_belt_derivatives(const planner::JointMap& inverse, std::array<int, 3> xyz,
                           const planner::PathPoint& p, std::size_t axis_count,
                           const std::array<double, 3>& e, double shift, std::size_t joint_count,
                           PathBeltDerivatives& out) noexcept {
  constexpr double h = kTcpDynamicsStep;
  const std::size_t na = std::min(axis_count, planner::kMaxAxes);
  const std::size_t n = std::min(joint_count, planner::kMaxAxes);
  // q at i steps along the path (its Taylor polynomial) and j steps along the belt.
  const auto q = [&](int i, int j, planner::AxisVec& out_q) noexcept {
    const double a = i * h;
    planner::AxisVec x = p.x;
    for (std::size_t k = 0; k < na; ++k)
      x[k] += a * p.d1[k] + 0.5 * a * a * p.d2[k] + a * a * a / 6.0 * p.d3[k];
    const double b = shift + j * h;
    for (std::size_t l = 0; l < 3; ++l)
      if (xyz[l] >= 0) x[static_cast<std::size_t>(xyz[l])] += b * e[l];
    try {
      return inverse(x, out_q);
    } catch (...) {
      return false;
    }
  };
  // The 13 points: the axes (0, 0), (+-1, 0), (+-2, 0), (0, +-1), (0, +-2) and (+-1, +-1).
  planner::AxisVec q00{}, q10{}, qm10{}, q20{}, qm20{}, q01{}, q0m1{}, q02{}, q0m2{};
  planner::AxisVec q11{}, q1m1{}, qm11{}, qm1m1{};
  if (!q(0, 0, q00) || !q(1, 0, q10) || !q(-1, 0, qm10) || !q(2, 0, q20) || !q(-2, 0, qm20) ||
      !q(0, 1, q01) || !q(0, -1, q0m1) || !q(0, 2, q02) || !q(0, -2, q0m2) || !q(1, 1, q11) ||
      !q(1, -1, q1m1) || !q(-1, 1, qm11) || !q(-1, -1, qm1m1))
    return false;
  out = PathBeltDerivatives{};
  const double h2 = h * h;
  const double h3 = h2 * h;
  for (std::size_t i = 0; i < n; ++i) {
    out.s[i] = (q10[i] - qm10[i]) / (2.0 * h);
    out.ss[i] = (q10[i] - 2.0 * q00[i] + qm10[i]) / h2;
    out.sss[i] = (q20[i] - 2.0 * q10[i] + 2.0 * qm10[i] - qm20[i]) / (2.0 * h3);
    out.b[i] = (q01[i] - q0m1[i]) / (2.0 * h);
    out.bb[i] = (q01[i] - 2.0 * q00[i] + q0m1[i]) / h2;
    out.bbb[i] = (q02[i] - 2.0 * q01[i] + 2.0 * q0m1[i] - q0m2[i]) / (2.0 * h3);
    out.sb[i] = (q11[i] - q1m1[i] - qm11[i] + qm1m1[i]) / (4.0 * h2);
    // d/db of d2q/ds2, d/ds of d2q/db2: second differences one step either side.
    out.ssb[i] =
        ((q11[i] - 2.0 * q01[i] + qm11[i]) - (q1m1[i] - 2.0 * q0m1[i] + qm1m1[i])) / (2.0 * h3);
    out.sbb[i] =
        ((q11[i] - 2.0 * q10[i] + q1m1[i]) - (qm11[i] - 2.0 * qm10[i] + qm1m1[i])) / (2.0 * h3);
  }
  return true;
}

namespace {

// One sample's terms for one joint: what the path's derivatives grow by over belt travel 0
// (e1..e3: (|q_s| - m1)+, ...) and the belt's derivatives (absolute values).
struct ShareTerms {
  double e1 = 0.0, e2 = 0.0, e3 = 0.0;
  double sb = 0.0, bb = 0.0, ssb = 0.0, sbb = 0.0, bbb = 0.0;
};

// Where a sample was taken (for an overload's message).
struct SampleAt {
  std::array<double, 3> tcp{};
  double shift = 0.0;
};

std::array<double, 3> tcp_of(const planner::AxisVec& x, const std::array<int, 3>& xyz) noexcept {
  std::array<double, 3> p{};
  for (std::size_t l = 0; l < 3; ++l)
    if (xyz[l] >= 0) p[l] = x[static_cast<std::size_t>(xyz[l])];
  return p;
}

// The belt travel over which the point at `tcp` (belt travel 0) can run: b >= 0 (the travel
// since the latch; the belt moves forward) with tcp + b e inside the workspace (beyond it the
// monitoring ends the run: NC9052 / NC9053 / NC9080). Empty (lo > hi) when the belt never
// carries the point into it; {0, 0} without a workspace.
std::array<double, 2> shift_range(const std::array<double, 3>& tcp, const BeltCarry& carry) {
  if (!carry.workspace) return {0.0, 0.0};
  const auto& box = *carry.workspace;
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  for (std::size_t l = 0; l < 3; ++l) {
    const double b0 = box[0][l] - kSamePoint - tcp[l];
    const double b1 = box[1][l] + kSamePoint - tcp[l];
    if (std::fabs(carry.e[l]) < kTiny) {
      if (b0 > 0.0 || b1 < 0.0) return {1.0, 0.0};  // beside the box: never inside
      continue;
    }
    const double t0 = b0 / carry.e[l];
    const double t1 = b1 / carry.e[l];
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  }
  return {lo, hi};
}

}  // namespace

std::variant<BeltShare, BeltOverload> belt_share(const planner::Segment& segment, double feed,
                                                 const planner::JointMap& inverse,
                                                 std::array<int, 3> xyz,
                                                 std::span<const planner::AxisLimits> joints,
                                                 const BeltCarry& carry) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double kLeast = 0.01;  // a share leaving less than 1 % of a limit overloads it
  BeltShare out;
  out.feed = feed;
  const double length = segment.length();
  if (!(length > 0.0) || !inverse) return out;
  const std::size_t nj = std::min(joints.size(), planner::kMaxAxes);
  const std::size_t na = segment.axis_count();
  const double w = carry.v_belt;
  // Clamped as a double before the conversion: a huge length would overflow the int.
  const int n = static_cast<int>(
      std::fmin(std::fmax(std::ceil(length / 5.0), 4.0), double{kBeltShareSamples}));
  const auto s_at = [&](int k) { return length * static_cast<double>(k) / n; };

  // Belt travel 0: the largest path derivatives, at most what the planner plans with. The
  // samples' points and their derivatives at travel 0 are kept for the travels below.
  planner::AxisVec m1{}, m2{}, m3{};
  std::vector<planner::PathPoint> points(static_cast<std::size_t>(n + 1));
  std::vector<std::optional<PathBeltDerivatives>> at0(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    points[k] = segment.at(s_at(static_cast<int>(k)));
    PathBeltDerivatives d{};
    if (!path_belt_derivatives(inverse, xyz, points[k], na, carry.e, 0.0, nj, d)) continue;
    for (std::size_t i = 0; i < nj; ++i) {
      m1[i] = std::max(m1[i], std::fabs(d.s[i]));
      m2[i] = std::max(m2[i], std::fabs(d.ss[i]));
      m3[i] = std::max(m3[i], std::fabs(d.sss[i]));
    }
    at0[k] = d;
  }

  // Every sample carried over the travel it can run at: the velocity cap, the terms of a and j.
  std::vector<ShareTerms> terms;
  std::vector<SampleAt> where;
  terms.reserve(static_cast<std::size_t>(n + 1) * kBeltShareShifts * nj);
  where.reserve(static_cast<std::size_t>(n + 1) * kBeltShareShifts);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const planner::PathPoint& p = points[k];
    const std::array<double, 3> tcp = tcp_of(p.x, xyz);
    const auto [t_lo, t_hi] = shift_range(tcp, carry);
    if (t_lo > t_hi) continue;  // the belt never carries this point into the workspace
    const int shifts = carry.workspace && t_hi > t_lo ? kBeltShareShifts : 1;
    for (int m = 0; m < shifts; ++m) {
      const double t = shifts == 1 ? t_lo : t_lo + (t_hi - t_lo) * m / (shifts - 1);
      PathBeltDerivatives d{};
      if (t == 0.0) {
        if (!at0[k]) continue;  // the transform failed there (the run stops it: NC3201)
        d = *at0[k];
      } else if (!path_belt_derivatives(inverse, xyz, p, na, carry.e, t, nj, d)) {
        continue;  // the belt cannot carry the block there (the run stops it: NC3201)
      }
      for (std::size_t i = 0; i < nj; ++i) {
        const double left = joints[i].v_max - w * std::fabs(d.b[i]);
        if (!(left > 0.0))
          return BeltOverload{i, 'v', w * std::fabs(d.b[i]), joints[i].v_max, tcp, t};
        if (std::fabs(d.s[i]) > kTiny) out.feed = std::min(out.feed, left / std::fabs(d.s[i]));
        terms.push_back(
            {std::max(0.0, std::fabs(d.s[i]) - m1[i]), std::max(0.0, std::fabs(d.ss[i]) - m2[i]),
             std::max(0.0, std::fabs(d.sss[i]) - m3[i]), std::fabs(d.sb[i]), std::fabs(d.bb[i]),
             std::fabs(d.ssb[i]), std::fabs(d.sbb[i]), std::fabs(d.bbb[i])});
      }
      where.push_back({tcp, t});
    }
  }
  if (where.empty()) return out;

  // An upper bound V0 of the path's velocity on the block: the planner's own projections
  // (planner/limits.hpp) with m1, m2 in place of its larger bounds.
  double v0 = out.feed;
  bool moves = false;
  for (std::size_t i = 0; i < nj; ++i) {
    const planner::AxisLimits& l = joints[i];
    if (m1[i] > kTiny) {
      moves = true;
      v0 = std::min(v0, l.v_max / m1[i]);
    }
    if (m2[i] > kTiny)
      v0 = std::min(v0, std::sqrt(planner::kCentripetalShare * std::min(l.a_max, l.d_max) / m2[i]));
  }
  if (!moves) return out;  // the block moves no joint at belt travel 0

  // The shares at a bound V of the path's velocity. The path's acceleration under the lowered
  // limits is at most min_k (max(A+_k, A-_k) - a_k) / m1_k, and a_k grows with it (the e1 term):
  // the largest consistent bound is the fixed point A = min_{k,c} (Amax_k - a0_kc) / (m1_k +
  // e1_kc), a0 the share without the e1 term (for the binding k, c the lowered limit leaves the
  // path exactly A); the same for the jerk with J_k.
  struct Shares {
    planner::AxisVec a{};
    planner::AxisVec j{};
    double ratio = inf;  // the largest share over its limit, min(A+, A-) or J
    std::size_t joint = 0;
    char quantity = 'a';
    std::size_t at = 0;  // the sample of that share
    double value = 0.0;  // the share there [deg/s^k]
    void worst(double r, double x, std::size_t i, char q, std::size_t c) {
      ratio = r;
      value = x;
      joint = i;
      quantity = q;
      at = c;
    }
  };
  const std::size_t samples = where.size();
  const auto shares_at = [&](double vv) {
    Shares sh;
    const auto a0 = [&](const ShareTerms& x) {
      return x.e2 * vv * vv + 2.0 * x.sb * vv * w + x.bb * w * w;
    };
    double a = inf;
    for (std::size_t i = 0; i < nj; ++i) {
      if (!(m1[i] > kTiny)) continue;  // a joint the path does not move does not bound it
      const double amax = std::max(joints[i].a_max, joints[i].d_max);
      for (std::size_t c = 0; c < samples; ++c) {
        const ShareTerms& x = terms[c * nj + i];
        const double ai = (amax - a0(x)) / (m1[i] + x.e1);
        if (ai < a) {
          a = ai;
          if (!(a > 0.0)) sh.worst(inf, a0(x), i, 'a', c);  // a0 alone takes the joint's A
        }
      }
    }
    if (!(a > 0.0)) return sh;
    const auto j0 = [&](const ShareTerms& x) {
      return x.e3 * vv * vv * vv + 3.0 * x.e2 * vv * a + 3.0 * x.ssb * vv * vv * w +
             3.0 * x.sbb * vv * w * w + x.bbb * w * w * w + 3.0 * x.sb * a * w;
    };
    double jp = inf;
    for (std::size_t i = 0; i < nj; ++i) {
      if (!(m1[i] > kTiny)) continue;
      for (std::size_t c = 0; c < samples; ++c) {
        const ShareTerms& x = terms[c * nj + i];
        const double ji = (joints[i].j_max - j0(x)) / (m1[i] + x.e1);
        if (ji < jp) {
          jp = ji;
          if (!(jp > 0.0)) sh.worst(inf, j0(x), i, 'j', c);  // j0 alone takes the joint's J
        }
      }
    }
    if (!(jp > 0.0)) return sh;
    sh.ratio = 0.0;
    for (std::size_t i = 0; i < nj; ++i) {
      const double a_limit = std::min(joints[i].a_max, joints[i].d_max);
      for (std::size_t c = 0; c < samples; ++c) {
        const ShareTerms& x = terms[c * nj + i];
        const double ai = a0(x) + x.e1 * a;
        const double ji = j0(x) + x.e1 * jp;
        sh.a[i] = std::max(sh.a[i], ai);
        sh.j[i] = std::max(sh.j[i], ji);
        if (ai / a_limit > sh.ratio) sh.worst(ai / a_limit, ai, i, 'a', c);
        if (ji / joints[i].j_max > sh.ratio) sh.worst(ji / joints[i].j_max, ji, i, 'j', c);
      }
    }
    return sh;
  };

  // The shares grow with V: where they would take more than kShareMost of a joint's A or J (or,
  // when the belt takes more than that with the path at rest, half of what it leaves), the
  // block's feed is capped (bisection on V) so that the path keeps the rest.
  constexpr double kShareMost = 0.5;
  constexpr double kLeastFeed = 1e-12;  // [mm/s] a capped feed stays positive
  const Shares rest = shares_at(0.0);
  if (!(rest.ratio < 1.0 - kLeast)) {
    const double limit = rest.quantity == 'a'
                             ? std::min(joints[rest.joint].a_max, joints[rest.joint].d_max)
                             : joints[rest.joint].j_max;
    return BeltOverload{rest.joint, rest.quantity,      rest.value,
                        limit,      where[rest.at].tcp, where[rest.at].shift};
  }
  const double most = rest.ratio <= kShareMost ? kShareMost : 0.5 * (rest.ratio + 1.0 - kLeast);
  double v = v0;
  Shares sh = shares_at(v);
  if (sh.ratio > most) {
    double lo = 0.0;
    double hi = v;
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (shares_at(mid).ratio <= most ? lo : hi) = mid;
    }
    v = lo;
    sh = lo > 0.0 ? shares_at(lo) : rest;
    out.feed = std::min(out.feed, std::max(v, kLeastFeed));
  }
  out.joints.a = sh.a;
  out.joints.j = sh.j;
  return out;
}

std::optional<JointOverrun> joint_overrun(const ipo::JointSetpoint& s,
                                          std::span<const axes::Dynamics> joints,
                                          bool jerk) noexcept {
  constexpr double tol = 1.0 + 1e-6;
  const std::size_t n = std::min(joints.size(), planner::kMaxAxes);
  for (std::size_t i = 0; i < n; ++i) {
    const axes::Dynamics& d = joints[i];
    if (std::fabs(s.v[i]) > d.v_max * tol) return JointOverrun{i, 'v', std::fabs(s.v[i]), d.v_max};
    const double a = std::max(d.a_max, d.d_max);
    if (std::fabs(s.a[i]) > a * tol) return JointOverrun{i, 'a', std::fabs(s.a[i]), a};
    if (jerk && std::fabs(s.j[i]) > d.j_max * tol)
      return JointOverrun{i, 'j', std::fabs(s.j[i]), d.j_max};
  }
  return std::nullopt;
}

}  // namespace ncsim::tracking
