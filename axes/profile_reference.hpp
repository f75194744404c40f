#pragma once
// axes/profile_reference: the independent reference for time-optimal profiles from moving
// starts (test support, used by profile_reference_test.cpp and profile_outside_test.cpp).
//
// ProfileRule::time_optimal from moving starts (v0, a0) against an independent reference
// (issue 11 "Proof"). The reference is written apart from the kernel and works differently:
// it does not use levels, frames or the kernel's case split. It enumerates the shapes of the
// acceleration a0 -> x1 [hold] -> x2 [hold] -> 0 (every jerk-limited profile with at most two
// acceleration extremes, holds at the limits, and a cruise at V), parametrised by the first
// extreme x1 (or the first hold), solves the velocity condition for x2 in closed form, scans
// the parameter on a fine grid for every sign change of "end position - D" and bisects each
// one in long double; the fastest valid root (v within [0, V], path limits A+ when speeding
// up, A- when slowing down, holds >= 0) is the reference time. Its profiles are valid
// profiles, so the kernel may never be slower than it.

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ncsim::test::reference {

using Real = long double;

struct Seg {
  Real j = 0;
  Real t = 0;
};

// A candidate profile: up to 7 segments from (0, v0, a0).
struct Shape {
  std::array<Seg, 7> seg{};
  int n = 0;
  bool ok = true;
  void push(Real j, Real t) {
    if (t < 0) ok = false;
    if (t > 0) seg[static_cast<std::size_t>(n++)] = Seg{j, t};
  }
};

struct Ref {
  Real v0, a0, v1, d;
  Real vmax, ap, am, j;
  bool reverse = false;  // may the velocity go below 0 (overshoot, start moving away)?
  int clamp = 0;         // tails hold at A+ going up, A- going down (0), or the other way (1)

  // Velocity change of a jerk ramp from acceleration a to b.
  Real dv(Real a, Real b) const { return (a + b) / 2 * std::fabs(b - a) / j; }
  void ramp(Shape& s, Real a, Real b) const { s.push(b > a ? j : -j, std::fabs(b - a) / j); }

  // End state of a shape; false when it leaves v in [v_min, V] (v_min = 0, or -V when the
  // reference may reverse) or the path limits: where v > 0 the acceleration lies in
  // [-A-, A+], where v < 0 in [-A+, A-] (A+ bounds speeding up, A- slowing down, 002_* 2.1).
  bool run(const Shape& s, Real& p_end, Real& v_end, Real& t_end) const {
    if (!s.ok) return false;
    Real p = 0, v = v0, a = a0, t = 0;
    const Real tol_v = 1e-12L * vmax;
    const Real tol_a = 1e-12L * std::max(ap, am);
    const Real v_min = reverse ? -vmax : Real(0);
    const auto v_ok = [&](Real x) { return x >= v_min - tol_v && x <= vmax + tol_v; };
    for (int i = 0; i < s.n; ++i) {
      const Seg& g = s.seg[static_cast<std::size_t>(i)];
      // Split points: where a = 0 (velocity extreme) and where v = 0 (the limits switch).
      std::array<Real, 5> cut{0, g.t, g.t, g.t, g.t};
      int nc = 1;
      if (g.j != 0) {
        const Real tz = -a / g.j;
        if (tz > 0 && tz < g.t) cut[static_cast<std::size_t>(nc++)] = tz;
        const Real disc = a * a - 2 * g.j * v;
        if (disc >= 0) {
          const Real sq = std::sqrt(disc);
          for (const Real r : {(-a - sq) / g.j, (-a + sq) / g.j})
            if (r > 0 && r < g.t) cut[static_cast<std::size_t>(nc++)] = r;
        }
      } else if (a != 0) {
        const Real r = -v / a;
        if (r > 0 && r < g.t) cut[static_cast<std::size_t>(nc++)] = r;
      }
      cut[static_cast<std::size_t>(nc++)] = g.t;
      for (int a_i = 1; a_i < nc; ++a_i)  // insertion sort of <= 5 cut times
        for (int b_i = a_i;
             b_i > 0 && cut[static_cast<std::size_t>(b_i)] < cut[static_cast<std::size_t>(b_i - 1)];
             --b_i)
          std::swap(cut[static_cast<std::size_t>(b_i)], cut[static_cast<std::size_t>(b_i - 1)]);
      const auto vel = [&](Real x) { return v + x * (a + x * g.j / 2); };
      for (int k = 0; k + 1 < nc; ++k) {
        const Real ta = cut[static_cast<std::size_t>(k)];
        const Real tb = cut[static_cast<std::size_t>(k + 1)];
        if (!v_ok(vel(ta)) || !v_ok(vel(tb))) return false;
        const bool fwd = vel((ta + tb) / 2) >= 0;
        const Real hi = fwd ? ap : am;
        const Real lo = fwd ? -am : -ap;
        for (const Real x : {ta, tb}) {
          const Real ax = a + g.j * x;
          if (ax > hi + tol_a || ax < lo - tol_a) return false;
        }
      }
      p += g.t * (v + g.t * (a / 2 + g.t * g.j / 6));
      v += g.t * (a + g.t * g.j / 2);
      a += g.t * g.j;
      t += g.t;
    }
    p_end = p;
    v_end = v;
    t_end = t;
    return std::fabs(a) <= tol_a && std::fabs(v - v1) <= 1e-9L * vmax;
  }

  // Tail x1 (after its hold) -> x2 [hold at the limit] -> 0 gaining the velocity r; the branch
  // picks x2 >= max(x1, 0) (up) or x2 <= min(x1, 0) (down).
  bool tail(Shape& s, Real x1, Real r, bool up) const {
    if (up) {
      const Real q = (x1 * x1 + 2 * j * r) / 2;
      if (q < 0) return false;
      Real x2 = std::sqrt(q);
      if (x2 < std::max(x1, Real(0))) return false;
      Real h = 0;
      const Real cu = clamp == 0 ? ap : am;
      if (x2 > cu) {
        x2 = cu;
        h = (r - dv(x1, cu) - dv(cu, 0)) / cu;
      }
      ramp(s, x1, x2);
      s.push(0, h);
      ramp(s, x2, 0);
      return s.ok;
    }
    const Real q = (x1 * x1 - 2 * j * r) / 2;
    if (q < 0) return false;
    Real x2 = -std::sqrt(q);
    if (x2 > std::min(x1, Real(0))) return false;
    Real h = 0;
    const Real cd = clamp == 0 ? am : ap;
    if (x2 < -cd) {
      x2 = -cd;
      h = (r - dv(x1, -cd) - dv(-cd, 0)) / (-cd);
    }
    ramp(s, x1, x2);
    s.push(0, h);
    ramp(s, x2, 0);
    return s.ok;
  }

  // Shape of kind k with parameter u: k = 0/1 free x1 = u (tail up/down); k = 2..9 x1 at a
  // limit (A+, -A-, A-, -A+: reversed motion swaps them) with hold u (tail up/down).
  bool shape(int k, Real u, Shape& s) const {
    s = Shape{};
    Real x1 = u;
    Real h1 = 0;
    if (k >= 2) {
      const std::array<Real, 4> at{ap, -am, am, -ap};
      x1 = at[static_cast<std::size_t>((k - 2) / 2)];
      h1 = u;
    }
    ramp(s, a0, x1);
    s.push(0, h1);
    const Real r = v1 - v0 - dv(a0, x1) - x1 * h1;
    return tail(s, x1, r, (k % 2) == 0);
  }

  // Fastest valid root of (end position - D) over the parameter grid of kind k.
  Real best_root(int k, const std::vector<Real>& grid) const {
    Real best = INFINITY;
    Real p = 0, v = 0, t = 0;
    const auto f = [&](Real u, bool& valid) {
      Shape s;
      valid = shape(k, u, s) && run(s, p, v, t);
      return p - d;
    };
    // Where validity changes between grid points, the boundary (found by bisection) joins
    // the grid: a root can sit between a valid point and the edge of its valid range.
    std::vector<Real> pts;
    bool v_last = false;
    Real u_last = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      bool valid = false;
      f(grid[i], valid);
      if (i > 0 && valid != v_last) {
        Real lo = u_last, hi = grid[i];  // validity v_last at lo
        for (int it = 0; it < 100; ++it) {
          const Real mid = (lo + hi) / 2;
          bool vm = false;
          f(mid, vm);
          (vm == v_last ? lo : hi) = mid;
        }
        pts.push_back(v_last ? lo : hi);
      }
      pts.push_back(grid[i]);
      v_last = valid;
      u_last = grid[i];
    }
    bool valid_prev = false;
    Real u_prev = 0, f_prev = 0;
    for (const Real u : pts) {
      bool valid = false;
      const Real fu = f(u, valid);
      if (valid && std::fabs(fu) <= 1e-13L * d) best = std::min(best, t);
      if (valid && valid_prev && (fu < 0) != (f_prev < 0)) {
        Real lo = u_prev, hi = u, f_lo = f_prev;
        for (int i = 0; i < 200; ++i) {
          const Real mid = (lo + hi) / 2;
          bool vm = false;
          const Real fm = f(mid, vm);
          if (!vm) break;
          if ((fm < 0) == (f_lo < 0)) {
            lo = mid;
            f_lo = fm;
          } else {
            hi = mid;
          }
        }
        bool vr = false;
        const Real fr = f(lo, vr);
        if (vr && std::fabs(fr) <= 1e-10L * d + 1e-15L) best = std::min(best, t);
      }
      valid_prev = valid;
      u_prev = u;
      f_prev = fu;
    }
    return best;
  }

  // Cruise at V: ramp to V, cruise, ramp to v1 (the one shape with a cruise).
  Real cruise() const {
    Shape s;
    const Real q = (2 * j * (vmax - v0) + a0 * a0) / 2;
    if (q < 0) return INFINITY;
    Real x1 = std::sqrt(q);
    if (x1 < std::max(a0, Real(0))) return INFINITY;
    Real h1 = 0;
    if (x1 > ap) {
      x1 = ap;
      h1 = (vmax - v0 - dv(a0, ap) - dv(ap, 0)) / ap;
    }
    ramp(s, a0, x1);
    s.push(0, h1);
    ramp(s, x1, 0);
    const int mark = s.n;
    Real x2 = -std::sqrt(j * (vmax - v1));
    Real h2 = 0;
    if (x2 < -am) {
      x2 = -am;
      h2 = (vmax - v1 + dv(0, -am) + dv(-am, 0)) / am;
    }
    ramp(s, 0, x2);
    s.push(0, h2);
    ramp(s, x2, 0);
    Real p = 0, v = 0, t = 0;
    if (!run(s, p, v, t) || p > d) return INFINITY;
    (void)mark;
    return t + (d - p) / vmax;
  }

  Real min_time() const {
    std::vector<Real> xs;
    constexpr int kN = 3000;
    const Real x_lo = reverse ? -std::max(ap, am) : -am;
    const Real x_hi = reverse ? std::max(ap, am) : ap;
    for (int i = 0; i <= kN; ++i)
      xs.push_back(x_lo + (x_hi - x_lo) * i / kN);
    // Dense near the special accelerations a0 and 0, where short moves put their extremes.
    const Real scale = std::max(ap, am);
    // Where a tail degenerates (x2 = 0 or x2 = x1: the direct ramp, no overshoot), the valid
    // range of a kind can be narrow: dense points around those breakpoints too.
    std::vector<Real> centres{a0, Real(0)};
    for (const Real sv : {Real(1), Real(-1)})
      for (const Real sa : {Real(1), Real(-1)})
        centres.push_back(sa * std::sqrt(std::fabs(sv * 2 * j * (v1 - v0) + a0 * a0) / 2));
    for (const Real c : centres) {
      for (int e = 1; e <= 15; ++e) {
        const Real off = scale * std::pow(Real(10), Real(-e));
        for (const Real m : {Real(1), Real(2), Real(5)}) {
          xs.push_back(c + m * off);
          xs.push_back(c - m * off);
        }
      }
      xs.push_back(c);
    }
    std::vector<Real> xin;
    for (const Real x : xs)
      if (x >= x_lo && x <= x_hi) xin.push_back(x);
    std::sort(xin.begin(), xin.end());
    // Holds: up to the time of changing the velocity by 2 V at the smaller limit.
    std::vector<Real> hs;
    const Real h_max = 2 * (vmax + std::fabs(v0)) / std::min(ap, am);
    for (int e = 15; e >= 1; --e)
      for (const Real m : {Real(1), Real(2), Real(5)})
        hs.push_back(h_max * m * std::pow(Real(10), Real(-e)) / 10);
    for (int i = 1; i <= kN; ++i)
      hs.push_back(h_max * i / kN);
    for (const Real x1 : {ap, -am, am, -ap}) {
      for (const Real sg : {Real(1), Real(-1)}) {
        const Real hb = (v1 - v0 - dv(a0, x1) - sg * x1 * x1 / (2 * j)) / x1;
        if (!(hb > 0)) continue;
        hs.push_back(hb);
        for (int e = 1; e <= 15; ++e)
          for (const Real m : {Real(1), Real(2), Real(5)})
            for (const Real side : {Real(1), Real(-1)})
              hs.push_back(hb * (1 + side * m * std::pow(Real(10), Real(-e))));
      }
    }
    std::sort(hs.begin(), hs.end());
    Real best = cruise();
    for (int c = 0; c < (reverse ? 2 : 1); ++c) {
      Ref r = *this;
      r.clamp = c;
      for (int k = 0; k < 2; ++k)
        best = std::min(best, r.best_root(k, xin));
      for (int k = 2; k < (reverse ? 10 : 6); ++k)
        best = std::min(best, r.best_root(k, hs));
    }
    return best;
  }
};

}  // namespace ncsim::test::reference
