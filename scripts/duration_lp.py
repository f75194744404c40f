#!/usr/bin/env python3
"""scripts/duration_lp.py: numerical evidence whether a prescribed duration is feasible.

Analysis only (not built, not run by CI; needs Debian's python3-scipy). docs/axes-profile.md,
"Prescribed durations", uses it for durations the relaxed bounds of
axes/profile_duration_bound.hpp do not decide.

The jerk is piecewise constant on N equal steps of T/N (|j| <= J), the state is integrated
exactly at the nodes, and at every node the velocity keeps the sign of a given pattern (the
start's sign, flipped at each crossing time) with the path limits of that sign (v >= 0:
-A- <= a <= A+, v <= 0: -A+ <= a <= A-) and |v| <= V; the node nearest a crossing may have
either sign, with |a| <= max(A+, A-) (relaxed at that one node). The end is (v1, a = 0). Two linear
programs give the lowest and highest end position over that set; D inside [min, max] means
a profile of duration T with that crossing pattern exists (to the grid's resolution: limits
are held at the nodes only), D outside for every pattern tried is evidence of a gap, not a
proof (the grid restricts the profiles and the patterns are sampled).

usage: duration_lp.py p0 v0 a0 V A+ A- J p1 v1 T N CROSSINGS
  CROSSINGS: comma-separated patterns, each a '/'-separated list of crossing times [s]
  (e.g. 0.2354/0.4028: one turn back and one forward again; 1e9: no crossing)
"""
import sys

import numpy as np
import scipy.sparse as sp
from scipy.optimize import linprog


def end_range(start, lim, target, t_total, n, crossings):
    """Lowest and highest end position (frame toward the target) or None when infeasible."""
    v0, a0 = start
    v_max, a_plus, a_minus, jerk = lim
    v1 = target
    dt = t_total / n
    na = n + 1
    nvar = n + 3 * na

    def ia(k):
        return n + k

    def iv(k):
        return n + na + k

    def ip(k):
        return n + 2 * na + k

    rows, cols, vals, rhs = [], [], [], []

    def eq(entries, value):
        r = len(rhs)
        for c, v in entries:
            rows.append(r)
            cols.append(c)
            vals.append(v)
        rhs.append(value)

    eq([(ia(0), 1.0)], a0)
    eq([(iv(0), 1.0)], v0)
    eq([(ip(0), 1.0)], 0.0)
    for k in range(n):
        eq([(ia(k + 1), 1.0), (ia(k), -1.0), (k, -dt)], 0.0)
        eq([(iv(k + 1), 1.0), (iv(k), -1.0), (ia(k), -dt), (k, -dt * dt / 2)], 0.0)
        eq([(ip(k + 1), 1.0), (ip(k), -1.0), (iv(k), -dt), (ia(k), -dt * dt / 2),
            (k, -dt ** 3 / 6)], 0.0)
    eq([(ia(n), 1.0)], 0.0)
    eq([(iv(n), 1.0)], v1)
    a_eq = sp.csr_matrix((vals, (rows, cols)), shape=(len(rhs), nvar))
    ks = [int(round(t / dt)) for t in crossings]
    s0 = -1 if v0 < 0 else 1
    a_bounds, v_bounds = [], []
    a_cross = max(a_plus, a_minus)
    for k in range(na):
        s = s0 * (-1) ** sum(1 for kk in ks if k > kk)
        if k in ks:  # the crossing's node: either sign, both sides' limits
            a_bounds.append((-a_cross, a_cross))
            v_bounds.append((-v_max, v_max))
        elif s > 0:
            a_bounds.append((-a_minus, a_plus))
            v_bounds.append((0.0, v_max))
        else:
            a_bounds.append((-a_plus, a_minus))
            v_bounds.append((-v_max, 0.0))
    a_bounds[0] = (a0, a0)
    v_bounds[0] = (v0, v0)
    bounds = [(-jerk, jerk)] * n + a_bounds + v_bounds + [(None, None)] * na
    out = []
    for sense in (1.0, -1.0):
        c = np.zeros(nvar)
        c[ip(n)] = sense
        res = linprog(c, A_eq=a_eq, b_eq=np.array(rhs), bounds=bounds, method="highs")
        if res.status != 0:
            print("  linprog", sense, res.status, res.message, file=sys.stderr)
            return None
        out.append(sense * res.fun)
    return tuple(out)


def main():
    p0, v0, a0, v_max, a_plus, a_minus, jerk, p1, v1 = (float(x) for x in sys.argv[1:10])
    t_total = float(sys.argv[10])
    n = int(sys.argv[11])
    f = 1.0 if p1 > p0 else -1.0
    dist = f * (p1 - p0)
    for pattern in sys.argv[12].split(","):
        crossings = [float(t) for t in pattern.split("/")]
        r = end_range((f * v0, f * a0), (v_max, a_plus, a_minus, jerk), f * v1, t_total, n,
                      crossings)
        verdict = "infeasible pattern" if r is None else (
            "FEASIBLE" if r[0] <= dist <= r[1] else "D outside")
        print(f"T={t_total} N={n} crossings={pattern} D={dist!r} end range={r} {verdict}")


if __name__ == "__main__":
    main()
