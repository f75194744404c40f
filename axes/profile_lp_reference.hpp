#pragma once
// axes/profile_lp_reference: a shape-free independent reference for time-optimal PTP profiles
// (test support only, used by profile_lp_reference_test.cpp; links GLPK).
//
// Purpose: issue 11's "never slower than an independent reference" for every shape, including
// those the shape enumeration of profile_reference.hpp does not build (two turns, three
// acceleration extremes, a cruise after a turn). Nothing here assumes a shape.
// Tier 1 (`LpOracle`): for a duration T, "is there a motion with piecewise-constant jerk on N
// equal steps from (v0, a0) to (d, v1, 0) keeping |j| <= J, |v| <= V and the path limits of
// the acceleration at the nodes" is a linear program in the N jerks (the states are linear in
// them). The path limits (002_* 2.1, as axes/profile_limits_check.hpp reads them): where v > 0
// a lies in [-A-, A+], where v < 0 in [-A+, A-] (A+ speeds the motion up, A- slows it down).
// That set is not convex, so each step gets a sign: + or - (the box of that sign, v of that
// sign inside the whole step) or free (v either sign, a within +-min(A+, A-), valid for both);
// |v| <= V is held inside every step (a margin |j| h^2 / 8 at the nodes). Patterns: a few
// seeds (all free, the start's sign, the target's side, caller's seeds), then the signs of
// the best solution, free within two steps of a change, until T stops falling. Every pattern
// restricts the true problem, so its least T (bisection) is the time of a valid motion (up to
// GLPK's tolerance and the first and last step, see LpOracle); T_lp is the least found.
// Tier 2 (`refine`): the LP solution's arcs (runs of jerk +J, -J, 0 with a on a bound, 0 with
// v on +-V) become unknown durations; their junction conditions (a on the bound where a hold
// starts, a = 0 and v = +-V where a cruise starts, v = 0 where an arc ends on a crossing the
// LP shows) and the end conditions (a = 0, v = v1, p = d) are solved by Newton in long double,
// and the result is checked against the limits on every piece (`arcs_violation`). A valid
// result is a real profile, so a kernel that is optimal is never slower than its T_exact.

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ncsim::test::lp {

using Real = long double;

/// One move: from (0, v0, a0) to (d, v1, 0) under V, A+ (ap), A- (am), J.
struct Problem {
  Real v0 = 0, a0 = 0, d = 0, v1 = 0;
  Real vmax = 0, ap = 0, am = 0, j = 0;
};

/// The acceleration box at a node of velocity sign s (+1, -1; 0: both signs allowed).
inline std::pair<Real, Real> acc_box(const Problem& q, int s) {
  if (s > 0) return {-q.am, q.ap};
  if (s < 0) return {-q.ap, q.am};
  const Real m = std::min(q.ap, q.am);
  return {-m, m};
}

/// Node states (a_k, v_k), k = 0..n, of the jerks J u_k on n equal steps of a duration t.
inline void node_states(const Problem& q, const std::vector<double>& u, Real t,
                        std::vector<Real>& a, std::vector<Real>& v) {
  const int n = static_cast<int>(u.size());
  const Real h = t / n;
  a.assign(static_cast<std::size_t>(n + 1), 0);
  v.assign(static_cast<std::size_t>(n + 1), 0);
  a[0] = q.a0;
  v[0] = q.v0;
  for (int k = 0; k < n; ++k) {
    const auto ks = static_cast<std::size_t>(k);
    const Real jk = q.j * u[ks];
    v[ks + 1] = v[ks] + h * a[ks] + h * h * jk / 2;
    a[ks + 1] = a[ks] + h * jk;
  }
}

/// Tier 1: the LP on n steps of h = T / n. Columns: the acceleration change of each step u_i =
/// j_i h / A (A = max(A+, A-), |u_i| <= J h / A) and w_i >= |u_i| (for the extraction's
/// objective, sum w). Rows: a_k and v_k at the nodes k = 1..n (the last ones fixed to 0 and
/// v1), p_n = d, and w_i -+ u_i >= 0. Divided by A, h A and h^2 A the rows' coefficients do not
/// depend on T, so a new T changes only bounds and the dual simplex restarts from the last
/// basis. `u()` gives the jerks as fractions j_i / J.
/// Inside a step v is a quadratic that lies within c_k = |u_k| J h^2 / 8 of its chord, so each
/// inner node k keeps v_k + c w <= V and v_k - c w >= -V for the w of both steps it bounds (the
/// coefficient w / 8 of the scaled row does not depend on T either): |v| <= V holds everywhere.
/// Each step has a sign (+1, -1, 0 = free). A signed step keeps s v_k - c w >= 0 at its inner
/// nodes, so v keeps its sign inside the step, and a within the box of that sign at both nodes
/// (a is linear in a step); a free step keeps a within +-min(A+, A-), valid for either sign.
/// So every solution is a valid jerk-limited motion: the LP restricts the true problem, and
/// T_lp >= T_opt. (Not at the fixed start and end nodes: inside the first and the last step
/// |v| may pass V, or v change its sign against the step's, by at most J h^2 / 8; a start on
/// |v0| = V needs that leniency.)
class LpOracle {
 public:
  LpOracle(const Problem& q, int n) : q_(q), n_(n), sign_(static_cast<std::size_t>(n), 0) {
    glp_term_out(GLP_OFF);
    lp_ = glp_create_prob();
    glp_set_obj_dir(lp_, GLP_MIN);
    glp_add_cols(lp_, 2 * n);
    for (int i = 1; i <= n; ++i) {
      glp_set_col_bnds(lp_, i, GLP_DB, -1.0, 1.0);
      glp_set_col_bnds(lp_, n + i, GLP_DB, 0.0, 1.0);
    }
    glp_add_rows(lp_, 4 * n + 1 + 4 * (n - 1));
    std::vector<int> ia{0}, ja{0};
    std::vector<double> ar{0.0};
    const auto put = [&](int r, int c, double x) {
      ia.push_back(r);
      ja.push_back(c);
      ar.push_back(x);
    };
    for (int k = 1; k <= n; ++k) {
      for (int i = 0; i < k; ++i) {  // a_k: sum u_i; v_k: sum (k - i - 1/2) u_i
        const double cv = static_cast<double>(k - i) - 0.5;
        put(row_a(k), i + 1, 1.0);
        put(row_v(k), i + 1, cv);
        if (k < n)
          for (int r = 0; r < 4; ++r)
            put(row_m(k, r), i + 1, cv);
      }
      if (k < n) {  // v_k +- c w of the step before (r = 0, 1) and after (r = 2, 3) the node
        put(row_m(k, 0), n + k, 1.0 / 8.0);
        put(row_m(k, 1), n + k, -1.0 / 8.0);
        put(row_m(k, 2), n + k + 1, 1.0 / 8.0);
        put(row_m(k, 3), n + k + 1, -1.0 / 8.0);
      }
    }
    for (int i = 0; i < n; ++i) {  // p_n: sum (3 m^2 - 3 m + 1) / 6 u_i, m = n - i
      const double m = static_cast<double>(n - i);
      put(2 * n + 1, i + 1, (3.0 * m * m - 3.0 * m + 1.0) / 6.0);
    }
    for (int i = 1; i <= n; ++i) {  // w_i - u_i >= 0, w_i + u_i >= 0
      put(2 * n + 1 + i, n + i, 1.0);
      put(2 * n + 1 + i, i, -1.0);
      glp_set_row_bnds(lp_, 2 * n + 1 + i, GLP_LO, 0.0, 0.0);
      put(3 * n + 1 + i, n + i, 1.0);
      put(3 * n + 1 + i, i, 1.0);
      glp_set_row_bnds(lp_, 3 * n + 1 + i, GLP_LO, 0.0, 0.0);
    }
    glp_load_matrix(lp_, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
    glp_scale_prob(lp_, GLP_SF_AUTO);
    glp_std_basis(lp_);
  }
  ~LpOracle() { glp_delete_prob(lp_); }
  LpOracle(const LpOracle&) = delete;
  LpOracle& operator=(const LpOracle&) = delete;

  int steps() const { return n_; }
  /// Sign pattern of the steps 0..n-1 (+1, -1, 0 = free).
  void set_pattern(std::vector<int> s) { sign_ = std::move(s); }
  const std::vector<int>& pattern() const { return sign_; }

  /// Is there a discretised motion of duration t? On success the jerks are in `u()`.
  /// `l1`: minimise sum |u| (the extraction's regularisation) instead of any feasible point.
  bool feasible(Real t, bool l1 = false) {
    const Real h = t / n_;
    // Columns: the acceleration change of a step in units of as_ (|u| <= J h / as_); rows
    // divided by as_, h as_ and h^2 as_, so that the bounds are of the size of the limits'
    // ratios (GLPK's feasibility tolerance is relative to max(1, |bound|)).
    const Real as = std::max(q_.ap, q_.am);
    const Real ub = q_.j * h / as;
    const Real sa = as, sv = h * as, sp = h * h * as;
    for (int i = 1; i <= n_; ++i) {
      glp_set_col_bnds(lp_, i, GLP_DB, static_cast<double>(-ub), static_cast<double>(ub));
      glp_set_col_bnds(lp_, n_ + i, GLP_DB, 0.0, static_cast<double>(ub));
    }
    // The fixed nodes against their step's sign.
    const auto sgn0 = sign_.front(), sgn1 = sign_.back();
    if (sgn0 * q_.v0 < 0 || sgn1 * q_.v1 < 0) return false;
    if (sgn0 != 0) {
      const auto box = acc_box(q_, sgn0);
      if (q_.a0 < box.first * (1 + 1e-12L) || q_.a0 > box.second * (1 + 1e-12L)) return false;
    } else if (std::fabs(q_.a0) > std::min(q_.ap, q_.am) * (1 + 1e-12L)) {
      return false;
    }
    for (int k = 1; k <= n_; ++k) {
      const Real ca = q_.a0;
      const Real cv = q_.v0 + k * h * q_.a0;
      if (k == n_) {
        glp_set_row_bnds(lp_, row_a(k), GLP_FX, static_cast<double>(-ca / sa), 0.0);
        glp_set_row_bnds(lp_, row_v(k), GLP_FX, static_cast<double>((q_.v1 - cv) / sv), 0.0);
        continue;
      }
      glp_set_row_bnds(lp_, row_v(k), GLP_FR, 0.0, 0.0);
      Real alo = -INFINITY, ahi = INFINITY;
      for (int side = 0; side < 2; ++side) {
        const int st = sign_[static_cast<std::size_t>(k - 1 + side)];
        const auto box = acc_box(q_, st);
        alo = std::max(alo, box.first);
        ahi = std::min(ahi, box.second);
        // v_k + c w <= V (0 for a step of sign -), v_k - c w >= -V (0 for a step of sign +)
        const Real hi = st < 0 ? Real(0) : q_.vmax;
        const Real lo = st > 0 ? Real(0) : -q_.vmax;
        glp_set_row_bnds(lp_, row_m(k, 2 * side), GLP_UP, 0.0, static_cast<double>((hi - cv) / sv));
        glp_set_row_bnds(lp_, row_m(k, 2 * side + 1), GLP_LO, static_cast<double>((lo - cv) / sv),
                         0.0);
      }
      if (!(alo <= ahi)) return false;
      glp_set_row_bnds(lp_, row_a(k), GLP_DB, static_cast<double>((alo - ca) / sa),
                       static_cast<double>((ahi - ca) / sa));
    }
    const Real nh = n_ * h;
    const Real cp = nh * q_.v0 + nh * nh * q_.a0 / 2;
    glp_set_row_bnds(lp_, 2 * n_ + 1, GLP_FX, static_cast<double>((q_.d - cp) / sp), 0.0);
    for (int i = 1; i <= n_; ++i)
      glp_set_obj_coef(lp_, n_ + i, l1 ? 1.0 : 0.0);
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = GLP_MSG_OFF;
    parm.meth = GLP_DUALP;
    // GLPK's primal and dual feasibility tolerances, tighter than its 1e-7 defaults (a
    // solver setting, not one of ncsim's tolerances).
    parm.tol_bnd = 1e-10;
    parm.tol_dj = 1e-10;
    // An iteration limit, not a time limit (deterministic): a solve that stalls (seen once in
    // 1000 cases, the extraction's objective cycling) counts as infeasible, which only makes
    // T_lp larger (still a valid motion's time) or keeps the feasibility solution.
    parm.it_lim = 40 * n_;
    int rc = glp_simplex(lp_, &parm);
    if (rc != 0) {  // a basis the changed bounds made unusable: start again
      glp_std_basis(lp_);
      rc = glp_simplex(lp_, &parm);
    }
    ++solves_;
    if (rc != 0) return false;
    const int st = glp_get_status(lp_);
    if (st != GLP_OPT && st != GLP_FEAS) return false;
    u_.resize(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i)
      u_[static_cast<std::size_t>(i)] =
          std::clamp(static_cast<double>(glp_get_col_prim(lp_, i + 1) / ub), -1.0, 1.0);
    return true;
  }

  /// Least feasible duration with the current pattern, bisected in [lo, hi] to `rel`
  /// (hi grown while infeasible, lo lowered while feasible); infinity when none is found.
  Real bisect(Real lo, Real hi, Real rel) {
    int grow = 0;
    while (!feasible(hi)) {
      lo = hi;
      hi *= 2;
      if (++grow > 6) return INFINITY;
    }
    std::vector<double> u_hi = u_;
    int shrink = 0;
    while (lo > 0 && feasible(lo)) {
      hi = lo;
      u_hi = u_;
      lo /= 2;
      if (++shrink > 6) break;
    }
    while (hi - lo > rel * hi) {
      const Real mid = (lo + hi) / 2;
      if (feasible(mid)) {
        hi = mid;
        u_hi = u_;
      } else {
        lo = mid;
      }
    }
    u_ = u_hi;
    return hi;
  }

  /// T_lp: the least over sign patterns. Seeds: all free, all of the start's sign, all of the
  /// target's side, the start's sign for the first quarter then free, and `more_seeds` (any
  /// pattern: whatever its source, a feasible LP solution is a valid motion); each seed bisected
  /// to 1e-3, then from the best the signs of the last solution (free within two steps of a
  /// change) until T stops falling; the last bisection to `rel`, and the jerks of that
  /// duration with the least sum |u| are left in `u()`. `t_guess` only places the brackets.
  Real min_time(Real t_guess, const std::vector<std::vector<int>>& more_seeds = {},
                Real rel = 1e-9L, int passes = 4) {
    const int s0 = q_.v0 > 0 ? 1 : (q_.v0 < 0 ? -1 : 0);
    const int sd = q_.d > 0 ? 1 : (q_.d < 0 ? -1 : 0);
    const int s1 = q_.v1 > 0 ? 1 : (q_.v1 < 0 ? -1 : 0);
    std::vector<std::vector<int>> seeds;
    const auto sz = static_cast<std::size_t>(n_);
    seeds.emplace_back(sz, 0);
    if (s0 != 0) seeds.emplace_back(sz, s0);
    if (sd != 0 && sd != s0 && (s1 == sd || s1 == 0)) seeds.emplace_back(sz, sd);
    if (s0 != 0) {
      std::vector<int> q(sz, 0);
      std::fill(q.begin(), q.begin() + n_ / 4, s0);
      seeds.push_back(q);
    }
    for (const auto& m : more_seeds)
      if (static_cast<int>(m.size()) == n_) seeds.push_back(m);
    Real best = INFINITY;
    std::vector<int> s_best;
    for (const auto& sd_pattern : seeds) {
      set_pattern(sd_pattern);
      const Real hi = std::isfinite(static_cast<double>(best)) ? best : t_guess * 1.5L;
      const Real t = bisect(std::min(hi, t_guess) / 2, hi, 1e-3L);
      if (t < best) {
        best = t;
        s_best = sign_;
      }
    }
    if (!std::isfinite(static_cast<double>(best))) return best;
    set_pattern(s_best);
    best = bisect(best * 0.99L, best, rel);
    std::vector<double> u_best = u_;
    for (int pass = 1; pass < passes; ++pass) {
      set_pattern(signs_of(u_best, best));
      if (sign_ == s_best) break;
      const Real t = bisect(best * 0.9L, best * 1.001L, rel);
      if (!(t < best * (1 - 1e-9L))) break;
      best = t;
      u_best = u_;
      s_best = sign_;
    }
    sign_ = s_best;
    if (feasible(best, true)) u_best = u_;  // the least sum |u| at that duration
    u_ = u_best;
    return best;
  }

  const std::vector<double>& u() const { return u_; }
  long solves() const { return solves_; }

 private:
  int row_a(int k) const { return k; }
  int row_v(int k) const { return n_ + k; }
  int row_m(int k, int r) const { return 4 * n_ + 1 + 4 * (k - 1) + r + 1; }

  // Step signs of the jerks u of duration t: the sign where both nodes keep |v| >= 2 c,
  // free within two steps of a change of sign or of a free step.
  std::vector<int> signs_of(const std::vector<double>& u, Real t) const {
    std::vector<Real> a, v;
    node_states(q_, u, t, a, v);
    const Real h = t / n_;
    std::vector<int> s(static_cast<std::size_t>(n_), 0);
    for (int k = 0; k < n_; ++k) {
      const Real x = v[static_cast<std::size_t>(k)], y = v[static_cast<std::size_t>(k + 1)];
      const Real c2 = q_.j * h * h / 4 * std::fabs(u[static_cast<std::size_t>(k)]);
      s[static_cast<std::size_t>(k)] = (x > c2 && y > c2) ? 1 : ((x < -c2 && y < -c2) ? -1 : 0);
    }
    std::vector<int> out = s;
    for (int k = 0; k < n_; ++k) {
      const auto ks = static_cast<std::size_t>(k);
      const bool change = s[ks] == 0 || (k + 1 < n_ && s[ks + 1] != s[ks]);
      if (!change) continue;
      for (int m = std::max(0, k - 1); m <= std::min(n_ - 1, k + 2); ++m)
        out[static_cast<std::size_t>(m)] = 0;
    }
    return out;
  }

  Problem q_;
  int n_;
  std::vector<int> sign_;
  std::vector<double> u_;
  glp_prob* lp_ = nullptr;
  long solves_ = 0;
};

// Tier 2 -----------------------------------------------------------------------------------

struct Arc {
  int kind = 0;    // +1: jerk +J, -1: jerk -J, 2: hold at a = bound, 3: cruise at v = bound
  Real bound = 0;  // the hold's acceleration or the cruise's velocity
  Real t = 0;      // duration
  int node = 0;    // LP node where the arc starts (junction evidence)
};

inline Real arc_jerk(const Problem& q, const Arc& a) {
  return a.kind == 1 ? q.j : (a.kind == -1 ? -q.j : Real(0));
}

/// First limit violation of the arcs from (0, v0, a0) (relative tolerance tol), or empty:
/// |v| <= V, the path limits on every piece between the roots of a and v, end (d, v1, 0).
inline std::string arcs_violation(const Problem& q, const std::vector<Arc>& arcs, Real tol) {
  Real p = 0, v = q.v0, a = q.a0;
  const Real tv = tol * q.vmax, ta = tol * std::max(q.ap, q.am);
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const Arc& g = arcs[i];
    if (g.t < 0) return "negative duration at arc " + std::to_string(i);
    const Real jj = arc_jerk(q, g);
    std::vector<Real> cut{0, g.t};
    if (jj != 0) {
      const Real tz = -a / jj;
      if (tz > 0 && tz < g.t) cut.push_back(tz);
      const Real disc = a * a - 2 * jj * v;
      if (disc >= 0) {
        const Real sq = std::sqrt(disc);
        for (const Real r : {(-a - sq) / jj, (-a + sq) / jj})
          if (r > 0 && r < g.t) cut.push_back(r);
      }
    } else if (a != 0) {
      const Real r = -v / a;
      if (r > 0 && r < g.t) cut.push_back(r);
    }
    std::sort(cut.begin(), cut.end());
    const auto vel = [&](Real x) { return v + x * (a + x * jj / 2); };
    for (std::size_t k = 0; k + 1 < cut.size(); ++k) {
      const Real x0 = cut[k], x1 = cut[k + 1];
      for (const Real x : {x0, x1})
        if (std::fabs(vel(x)) > q.vmax + tv)
          return "|v| " + std::to_string(static_cast<double>(vel(x))) + " > V at arc " +
                 std::to_string(i);
      const Real vm = vel((x0 + x1) / 2);
      if (std::fabs(vm) <= tv) continue;  // a piece at v = 0: both boxes meet at the ends
      const auto box = acc_box(q, vm > 0 ? 1 : -1);
      for (const Real x : {x0, x1}) {
        const Real ax = a + jj * x;
        if (ax > box.second + ta || ax < box.first - ta)
          return "a " + std::to_string(static_cast<double>(ax)) + " beyond the path limit at v " +
                 std::to_string(static_cast<double>(vm)) + ", arc " + std::to_string(i);
      }
    }
    p += g.t * (v + g.t * (a / 2 + g.t * jj / 6));
    v += g.t * (a + g.t * jj / 2);
    a += g.t * jj;
  }
  const Real p_scale = std::max(std::fabs(q.d), Real(1e-300));
  if (std::fabs(a) > ta) return "end a " + std::to_string(static_cast<double>(a));
  if (std::fabs(v - q.v1) > tv) return "end v " + std::to_string(static_cast<double>(v));
  if (std::fabs(p - q.d) > 1e-9L * p_scale)
    return "end p " + std::to_string(static_cast<double>(p));
  return {};
}

/// Result of the exact refinement.
struct Exact {
  bool ok = false;        // converged and valid
  Real t = INFINITY;      // T_exact
  std::vector<Arc> arcs;  // the structure (durations solved)
  std::string why;        // when not ok
  int unknowns = 0, equations = 0;
};

namespace detail {

// Arcs from the LP's jerks: runs of +J, -J, and 0 with a on a bound or v on +-V; a step with a
// partial jerk is a switch inside the step (its time goes to the arcs either side) or, between
// two arcs of other kinds, a short arc of its own.
inline std::vector<Arc> arcs_from_lp(const Problem& q, const std::vector<double>& u, Real t,
                                     const std::vector<Real>& a, const std::vector<Real>& v) {
  const int n = static_cast<int>(u.size());
  const Real h = t / n;
  const Real eps = 1e-6L;
  const std::vector<Real> bounds{q.ap, -q.ap, q.am, -q.am};
  // Step classes: +1/-1 full jerk, 0 zero jerk, 9 partial.
  std::vector<int> cls(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Real x = u[static_cast<std::size_t>(k)];
    cls[static_cast<std::size_t>(k)] =
        x > 1 - eps ? 1 : (x < -1 + eps ? -1 : (std::fabs(x) < eps ? 0 : 9));
  }
  // Zero-jerk steps: a hold (a on a bound) or a cruise (v on +-V).
  const auto zero_arc = [&](int k, Arc& out) {
    const Real ak = a[static_cast<std::size_t>(k)];
    const Real vk = v[static_cast<std::size_t>(k)];
    Real bb = 0, err = INFINITY;
    for (const Real b : bounds)
      if (std::fabs(ak - b) < err) {
        err = std::fabs(ak - b);
        bb = b;
      }
    if (err <= 1e-5L * std::max(q.ap, q.am)) {
      out.kind = 2;
      out.bound = bb;
      return true;
    }
    if (std::fabs(std::fabs(vk) - q.vmax) <= 1e-5L * q.vmax &&
        std::fabs(ak) <= 1e-5L * std::max(q.ap, q.am)) {
      out.kind = 3;
      out.bound = vk > 0 ? q.vmax : -q.vmax;
      return true;
    }
    return false;  // a coast at neither: not a time-optimal arc
  };
  std::vector<Arc> arcs;
  const auto same = [](const Arc& x, const Arc& y) {
    return x.kind == y.kind && (x.kind < 2 || x.bound == y.bound);
  };
  const auto push = [&](Arc g) {
    if (!arcs.empty() && same(arcs.back(), g)) {
      arcs.back().t += g.t;
      return;
    }
    arcs.push_back(g);
  };
  Real carry = 0;  // time of a partial step owed to the next arc
  for (int k = 0; k < n; ++k) {
    const int c = cls[static_cast<std::size_t>(k)];
    Arc g;
    g.node = k;
    if (c != 9) {
      if (c == 1 || c == -1) {
        g.kind = c;
      } else if (!zero_arc(k, g)) {
        g.kind = 4;  // unclassified coast
        g.bound = a[static_cast<std::size_t>(k)];
      }
      g.t = h + carry;
      carry = 0;
      push(g);
      continue;
    }
    // A partial step: a switch inside it, or (between two arcs of other kinds) a short arc.
    const Real x = u[static_cast<std::size_t>(k)];
    const int s = x > 0 ? 1 : -1;
    const int prev = arcs.empty() ? 99 : arcs.back().kind;
    int next = 99;
    for (int m = k + 1; m < n; ++m)
      if (cls[static_cast<std::size_t>(m)] != 9) {
        next = cls[static_cast<std::size_t>(m)];
        break;
      }
    // The share at jerk s: between +J and -J the net jerk x = th s - (1 - th) s.
    const bool flip = (prev == 1 || prev == -1) && next == -prev;
    const Real th = flip ? (1 + std::fabs(x)) / 2 : std::fabs(x);
    const Real t_s = h * th;
    const Real t_o = h - t_s;
    if (prev == s) {
      arcs.back().t += t_s + carry;
      carry = t_o;
    } else if (next == s) {
      if (!arcs.empty()) arcs.back().t += t_o + carry;
      carry = t_s;  // to the jerk arc that follows
    } else {
      if (!arcs.empty()) arcs.back().t += carry + t_o / 2;
      Arc js;
      js.kind = s;
      js.node = k;
      js.t = t_s;
      push(js);
      carry = t_o / 2;
    }
  }
  if (!arcs.empty()) arcs.back().t += carry;
  return arcs;
}

// States at the start of every arc and at the end (index arcs.size()).
struct Node {
  Real p, v, a, t;
};
inline std::vector<Node> integrate(const Problem& q, const std::vector<Arc>& arcs) {
  std::vector<Node> out;
  Node s{0, q.v0, q.a0, 0};
  out.push_back(s);
  for (const Arc& g : arcs) {
    const Real jj = arc_jerk(q, g);
    s.p += g.t * (s.v + g.t * (s.a / 2 + g.t * jj / 6));
    s.v += g.t * (s.a + g.t * jj / 2);
    s.a += g.t * jj;
    s.t += g.t;
    out.push_back(s);
  }
  return out;
}

struct Eq {
  int at;      // node index (arc start; arcs.size() = end)
  int what;    // 0: a, 1: v, 2: p
  Real value;  // target
};

// Solve A x = b (m x n, row-major) in the least-squares / minimum-norm sense by Gaussian
// elimination on the normal equations of the smaller side.
inline bool solve_ls(const std::vector<Real>& A, const std::vector<Real>& b, int m, int n,
                     std::vector<Real>& x) {
  const bool wide = n > m;  // minimum norm: x = A^T (A A^T)^-1 b
  const int k = wide ? m : n;
  std::vector<Real> M(static_cast<std::size_t>(k * k), 0), r(static_cast<std::size_t>(k), 0);
  const auto at = [&](int i, int j) { return A[static_cast<std::size_t>(i * n + j)]; };
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      Real s = 0;
      if (wide)
        for (int c = 0; c < n; ++c)
          s += at(i, c) * at(j, c);
      else
        for (int c = 0; c < m; ++c)
          s += at(c, i) * at(c, j);
      M[static_cast<std::size_t>(i * k + j)] = s;
    }
    Real s = 0;
    if (wide)
      s = b[static_cast<std::size_t>(i)];
    else
      for (int c = 0; c < m; ++c)
        s += at(c, i) * b[static_cast<std::size_t>(c)];
    r[static_cast<std::size_t>(i)] = s;
  }
  // Square systems (m == n) directly, better conditioned than the normal equations.
  std::vector<Real> S = M, y = r;
  int dim = k;
  if (m == n) {
    S = A;
    y = b;
    dim = n;
  }
  for (int c = 0; c < dim; ++c) {
    int piv = c;
    for (int i = c + 1; i < dim; ++i)
      if (std::fabs(S[static_cast<std::size_t>(i * dim + c)]) >
          std::fabs(S[static_cast<std::size_t>(piv * dim + c)]))
        piv = i;
    if (!(std::fabs(S[static_cast<std::size_t>(piv * dim + c)]) > 1e-300L)) return false;
    if (piv != c) {
      for (int j = 0; j < dim; ++j)
        std::swap(S[static_cast<std::size_t>(c * dim + j)],
                  S[static_cast<std::size_t>(piv * dim + j)]);
      std::swap(y[static_cast<std::size_t>(c)], y[static_cast<std::size_t>(piv)]);
    }
    for (int i = c + 1; i < dim; ++i) {
      const Real f =
          S[static_cast<std::size_t>(i * dim + c)] / S[static_cast<std::size_t>(c * dim + c)];
      for (int j = c; j < dim; ++j)
        S[static_cast<std::size_t>(i * dim + j)] -= f * S[static_cast<std::size_t>(c * dim + j)];
      y[static_cast<std::size_t>(i)] -= f * y[static_cast<std::size_t>(c)];
    }
  }
  std::vector<Real> z(static_cast<std::size_t>(dim), 0);
  for (int i = dim - 1; i >= 0; --i) {
    Real s = y[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < dim; ++j)
      s -= S[static_cast<std::size_t>(i * dim + j)] * z[static_cast<std::size_t>(j)];
    z[static_cast<std::size_t>(i)] = s / S[static_cast<std::size_t>(i * dim + i)];
  }
  x.assign(static_cast<std::size_t>(n), 0);
  if (m == n || !wide) {
    for (int i = 0; i < n; ++i)
      x[static_cast<std::size_t>(i)] = z[static_cast<std::size_t>(i)];
  } else {
    for (int c = 0; c < n; ++c)
      for (int i = 0; i < m; ++i)
        x[static_cast<std::size_t>(c)] += at(i, c) * z[static_cast<std::size_t>(i)];
  }
  return true;
}

}  // namespace detail

namespace detail {

// The arcs' durations solved from their junction and end conditions (Newton, long double),
// then checked against the limits. a_n, v_n: the LP's node states (junction evidence).
inline Exact solve_arcs(const Problem& q, std::vector<Arc> arcs, const std::vector<Real>& a_n,
                        const std::vector<Real>& v_n, Real h, Real t_lp, bool halve) {
  Exact ex;
  for (const Arc& g : arcs)
    if (g.kind == 4) {
      ex.why = "a coast neither on an acceleration bound nor at V";
      return ex;
    }
  // Equations.
  std::vector<detail::Eq> eqs;
  const int na = static_cast<int>(arcs.size());
  for (int i = 1; i < na; ++i) {
    const Arc& g = arcs[static_cast<std::size_t>(i)];
    if (g.kind == 2) eqs.push_back({i, 0, g.bound});
    if (g.kind == 3) {
      eqs.push_back({i, 0, 0});
      eqs.push_back({i, 1, g.bound});
    }
  }
  eqs.push_back({na, 0, 0});
  eqs.push_back({na, 1, q.v1});
  eqs.push_back({na, 2, q.d});
  // Junctions the LP puts on v = 0 (a crossing at the switch of the path limits) where the
  // equations leave a duration free.
  if (na > static_cast<int>(eqs.size())) {
    std::vector<std::pair<Real, int>> cand;
    for (int i = 1; i < na; ++i) {
      const int k = arcs[static_cast<std::size_t>(i)].node;
      const Real vk = std::fabs(v_n[static_cast<std::size_t>(k)]);
      const Real ak = std::fabs(a_n[static_cast<std::size_t>(k)]);
      // a crossing: v changes its sign within three steps either side
      const int last = static_cast<int>(v_n.size()) - 1;
      const Real vb = v_n[static_cast<std::size_t>(std::max(0, k - 3))];
      const Real va = v_n[static_cast<std::size_t>(std::min(last, k + 3))];
      if (vb * va < 0 && vk <= 4 * (ak * h + q.j * h * h))
        cand.push_back({vk / (ak * h + q.j * h * h), i});
    }
    std::sort(cand.begin(), cand.end());
    for (const auto& c : cand) {
      if (static_cast<int>(eqs.size()) >= na) break;
      eqs.push_back({c.second, 1, 0});
    }
  }
  const int m = static_cast<int>(eqs.size());
  ex.unknowns = na;
  ex.equations = m;
  if (na != m) {
    ex.why = "arcs " + std::to_string(na) + " against equations " + std::to_string(m);
    ex.arcs = arcs;
    return ex;
  }
  const Real sc_a = std::max(q.ap, q.am), sc_v = q.vmax;
  const Real sc_p = std::max(std::fabs(q.d), q.vmax * t_lp);
  // The step is accepted where the 2-norm falls (Newton's descent direction); converged by
  // the largest residual.
  bool l2 = true;
  const auto residual = [&](const std::vector<detail::Node>& nd, std::vector<Real>& f) {
    f.resize(static_cast<std::size_t>(m));
    Real norm = 0, sum2 = 0;
    for (int e = 0; e < m; ++e) {
      const auto& eq = eqs[static_cast<std::size_t>(e)];
      const auto& s = nd[static_cast<std::size_t>(eq.at)];
      const Real x = eq.what == 0
                         ? (s.a - eq.value) / sc_a
                         : (eq.what == 1 ? (s.v - eq.value) / sc_v : (s.p - eq.value) / sc_p);
      f[static_cast<std::size_t>(e)] = x;
      norm = std::max(norm, std::fabs(x));
      sum2 += x * x;
    }
    return l2 ? std::sqrt(sum2) : norm;
  };
  std::vector<Real> f, jac(static_cast<std::size_t>(m * na)), step;
  Real norm = residual(detail::integrate(q, arcs), f);
  for (int it = 0; it < 200 && norm > 1e-17L; ++it) {
    const auto nd = detail::integrate(q, arcs);
    // d(state at node at) / d t_i for arcs i < at: the state's time derivative at the end of
    // arc i carried to the node (linear in the remaining time tau).
    for (int e = 0; e < m; ++e) {
      const auto& eq = eqs[static_cast<std::size_t>(e)];
      for (int i = 0; i < na; ++i) {
        Real dval = 0;
        if (i < eq.at) {
          const auto& se = nd[static_cast<std::size_t>(i + 1)];
          const Real jj = arc_jerk(q, arcs[static_cast<std::size_t>(i)]);
          const Real tau = nd[static_cast<std::size_t>(eq.at)].t - se.t;
          if (eq.what == 0) dval = jj / sc_a;
          if (eq.what == 1) dval = (se.a + jj * tau) / sc_v;
          if (eq.what == 2) dval = (se.v + se.a * tau + jj * tau * tau / 2) / sc_p;
        }
        jac[static_cast<std::size_t>(e * na + i)] = dval * t_lp;  // in units of t_lp
      }
    }
    std::vector<Real> rhs(f.size());
    for (std::size_t e = 0; e < f.size(); ++e)
      rhs[e] = -f[e];
    if (!detail::solve_ls(jac, rhs, m, na, step)) {
      ex.why = "singular Jacobian";
      ex.arcs = arcs;
      return ex;
    }
    // `halve`: at most half of a duration is taken in one step, so a duration stays positive
    // (a zero one leaves its column of the Jacobian zero); else a negative one is cut to 0.
    Real alpha = 1;
    for (int i = 0; i < na; ++i) {
      const Real d_i = step[static_cast<std::size_t>(i)] * t_lp;
      const Real t_i = arcs[static_cast<std::size_t>(i)].t;
      if (halve && d_i < 0 && t_i > 0) alpha = std::min(alpha, t_i / 2 / -d_i);
    }
    bool moved = false;
    for (int back = 0; back < 60; ++back, alpha /= 2) {
      std::vector<Arc> trial = arcs;
      for (int i = 0; i < na; ++i)
        trial[static_cast<std::size_t>(i)].t =
            std::max(Real(0), trial[static_cast<std::size_t>(i)].t +
                                  alpha * step[static_cast<std::size_t>(i)] * t_lp);
      std::vector<Real> ft;
      const Real nt = residual(detail::integrate(q, trial), ft);
      if (nt < norm) {
        arcs = trial;
        f = ft;
        norm = nt;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  ex.arcs = arcs;
  l2 = false;
  norm = residual(detail::integrate(q, arcs), f);
  if (!(norm <= 1e-13L)) {
    ex.why = "no convergence, residual " + std::to_string(static_cast<double>(norm));
    return ex;
  }
  const std::string bad = arcs_violation(q, arcs, 1e-9L);
  if (!bad.empty()) {
    ex.why = "refined arcs invalid: " + bad;
    return ex;
  }
  Real t = 0;
  for (const Arc& g : arcs)
    t += g.t;
  ex.t = t;
  ex.ok = true;
  return ex;
}

// Arc i removed (its neighbours joined where they are of one kind).
inline std::vector<Arc> without(const std::vector<Arc>& arcs, std::size_t i) {
  std::vector<Arc> out;
  for (std::size_t k = 0; k < arcs.size(); ++k) {
    if (k == i) continue;
    const Arc& g = arcs[k];
    if (!out.empty() && out.back().kind == g.kind && (g.kind < 2 || out.back().bound == g.bound))
      out.back().t += g.t;
    else
      out.push_back(g);
  }
  return out;
}

}  // namespace detail

/// Tier 2: the LP solution `u` of duration `t_lp` refined to exact arc durations. Where the
/// arcs as read do not converge to a valid profile, the variants without one of their arcs
/// shorter than a step (a switch the grid blurred into a spurious short arc) are tried; each
/// with two Newton safeguards; the fastest valid result is kept.
inline Exact refine(const Problem& q, const std::vector<double>& u, Real t_lp) {
  const int n_steps = static_cast<int>(u.size());
  const Real h = t_lp / n_steps;
  std::vector<Real> a_n, v_n;
  node_states(q, u, t_lp, a_n, v_n);
  std::vector<Arc> arcs = detail::arcs_from_lp(q, u, t_lp, a_n, v_n);
  // A jerk arc read as (nearly) empty - a ramp inside one step, blurred into partial jerks -
  // starts Newton from a quarter step, where its column of the Jacobian is not zero.
  for (Arc& g : arcs)
    if ((g.kind == 1 || g.kind == -1) && g.t < h / 4) g.t = h / 4;
  Exact ex;
  for (const bool halve : {false, true}) {
    const Exact e = detail::solve_arcs(q, arcs, a_n, v_n, h, t_lp, halve);
    if (e.ok && (!ex.ok || e.t < ex.t)) ex = e;
    if (!ex.ok && ex.why.empty()) ex = e;
  }
  if (ex.ok) return ex;
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    if (!(arcs[i].t < h) || arcs[i].kind == 4) continue;
    for (const bool halve : {false, true}) {
      const Exact alt = detail::solve_arcs(q, detail::without(arcs, i), a_n, v_n, h, t_lp, halve);
      if (alt.ok && (!ex.ok || alt.t < ex.t)) ex = alt;
    }
  }
  return ex;
}

/// A short text of the arcs (kinds and durations) for messages.
inline std::string describe(const std::vector<Arc>& arcs) {
  std::string s;
  for (const Arc& g : arcs) {
    if (!s.empty()) s += ' ';
    s += g.kind == 1 ? "+J"
                     : (g.kind == -1 ? "-J" : (g.kind == 2 ? "a=" : (g.kind == 3 ? "v=" : "?")));
    if (g.kind >= 2) s += std::to_string(static_cast<double>(g.bound));
    s += '(' + std::to_string(static_cast<double>(g.t)) + ')';
  }
  return s;
}

}  // namespace ncsim::test::lp
