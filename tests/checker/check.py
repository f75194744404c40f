#!/usr/bin/env python3
"""Independent trajectory checker: finite differences of ncsim's CSV against the machine lists.

Shares no code with ncsim. Limits come from the machine folder's lists (lists.py), the blocks
and their geometry from the checker's own reading of the program (ncprog.py), the positions
from the CSV `run` writes (`t,line,X,...`; the `line` column is the block each cycle ends in).

Per axis, with x_0 the start (every bundled machine starts at 0) and x_k the CSV row k:
  v_k = (x_k - x_{k-1}) / T             the mean of v over cycle k
  a_k = (x_{k+1} - 2 x_k + x_{k-1}) / T^2   a hat-weighted mean of a over cycles k, k+1
  j_k = (x_{k+2} - 3 x_{k+1} + 3 x_k - x_{k-1}) / T^3   a quadratic-B-spline mean of j over k..k+2
Each is a mean with non-negative weights of total 1, so a bound that holds at every instant of
its stencil bounds it too. The bound of an instant is that of the block moving then: a cycle
holds every block from the line of the row before to the line of its own row. A step in the
velocity (dv) or acceleration (da) at an instant inside cycle k adds at most |dv|/T to a_{k-1},
a_k, |dv|/T^2 + |da|/T to j_{k-2}, j_{k-1}, j_k (the B-spline weights are at most 1), and
nothing elsewhere. README.md gives the formulas, their manual lines and the rounding argument.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lists  # noqa: E402
import ncprog  # noqa: E402

# Rounding (README "Rounding"): a position is a double below 1e4 mm computed by a closed form of
# at most ~100 operations, so it is within 100 ulp(1e4) = 1.8e-10 mm of its exact value; the
# checker allows DELTA_X = 1e-9 mm per position, i.e. 2, 4, 8 DELTA_X / T^n on v, a, j. Limits
# reached exactly by the planner may come out a few ulp above: a relative 1e-9 on every limit.
DELTA_X = 1e-9
REL = 1e-9
BLEND_MAX_TURN = math.radians(175.0)  # docs/planner.md: turns above 175 degrees are not blended


@dataclasses.dataclass
class Finding:
    kind: str        # velocity, acceleration, jerk, velojump, c1-step, unlisted-step
    axis: str
    k: int           # cycle index (row k, t = k T)
    t: float
    line: int
    value: float
    limit: float
    note: str = ""

    def text(self) -> str:
        return (f"{self.kind} t={self.t:.6g} s line {self.line} axis {self.axis} "
                f"{self.value:.6g} > {self.limit:.6g}{(' ' + self.note) if self.note else ''}")


@dataclasses.dataclass
class Boundary:
    k: int                # the cycle interval (t_{k-1}, t_k] holding it
    a: ncprog.Block
    b: ncprog.Block
    stop: bool
    blended: bool
    dv_allow: np.ndarray  # per axis [mm/s]
    da_allow: np.ndarray  # per axis [mm/s^2]
    rule: str


def read_csv(path: str):
    """(T from the header or None, lines[int], positions[N, axes], axis names, error text)."""
    t_cycle, names, rows, lines_col, error = None, None, [], [], ""
    with open(path, encoding="utf-8") as f:
        for raw in f:
            if raw.startswith("#"):
                if raw.startswith("# cycle:"):
                    t_cycle = float(raw.split(":", 1)[1].split()[0])
                elif raw.startswith("# error:"):
                    error = raw[2:].strip()
                continue
            if names is None:
                cols = raw.strip().split(",")
                names = [c for c in cols[2:] if "." not in c]
                continue
            cells = raw.strip().split(",")
            lines_col.append(int(cells[1]) if cells[1] else 0)
            rows.append([float(c) for c in cells[2:2 + len(names)]])
    return t_cycle, np.array(lines_col, dtype=np.int64), np.array(rows, dtype=float).reshape(
        -1, len(names or [])), names or [], error


class Checker:
    def __init__(self, machine: lists.Machine, blocks: list[ncprog.Block], t_cycle: float):
        self.m = machine
        self.blocks = blocks
        self.T = t_cycle
        self.ax = machine.axes
        n = len(self.ax)
        self.v_max = np.array([a.v_max for a in self.ax])
        self.v_rapid = np.array([a.v_rapid for a in self.ax])
        self.a_up = np.array([a.a_up for a in self.ax])
        self.a_down = np.array([a.a_down for a in self.ax])
        self.a_rapid = np.array([a.a_rapid for a in self.ax])
        self.j = np.array([a.j for a in self.ax])
        self.j_rapid = np.array([a.j_rapid for a in self.ax])
        self.c0 = np.array([a.c0 for a in self.ax])
        self.a_all = np.maximum.reduce([self.a_up, self.a_down, self.a_rapid])
        self.n = n

    # -- which blocks move in which cycle ------------------------------------------------------
    def _block_index(self, lines: np.ndarray) -> np.ndarray:
        """Execution index of each row's block (a row on a non-motion line: the block before)."""
        src = np.array([b.line for b in self.blocks])
        idx = np.searchsorted(src, lines, side="right") - 1
        return np.clip(idx, 0, len(self.blocks) - 1)

    def _accel_pair(self, blk: ncprog.Block):
        """(A+, |A-|) in force on a block: G00 both ways a_rapid, feed a_beschl / a_brems."""
        return (self.a_rapid, self.a_rapid) if blk.rapid else (self.a_up, self.a_down)

    def _boundary(self, k: int, a: ncprog.Block, b: ncprog.Block, v_up: float) -> Boundary:
        n, T = self.n, self.T
        zero = np.zeros(n)
        # G60 / G09 stop the path; G00 followed by G01/G02/G03 always behaves like G09
        # (isg-language.md §2.4 table, §7.1): no step at all.
        stop = a.stop or (a.rapid and not b.rapid)
        ta, tb = a.tangent(True), b.tangent(False)
        dt = np.abs(tb - ta)[:n] if n <= 3 else np.pad(np.abs(tb - ta), (0, n - 3))[:n]
        turn = math.acos(max(-1.0, min(1.0, float(np.dot(ta, tb)))))
        up_a, down_a = self._accel_pair(a)
        up_b, down_b = self._accel_pair(b)
        # 000 l.108: v_jump[i] = C0[i] min(A+[i], -A-[i]) T, with the limits of both blocks.
        formula = self.c0 * np.minimum.reduce([up_a, down_a, up_b, down_b]) * T
        geometric = v_up * dt  # the step a link at path velocity <= v_up makes at this knee
        g00 = "+G00" if (a.rapid or b.rapid) else ""
        if stop:
            return Boundary(k, a, b, True, False, zero, zero, "stop")
        blended = a.contour and turn <= BLEND_MAX_TURN and not np.all(geometric <= formula)
        dv = np.minimum(formula, geometric)
        rule = "velojump"
        if blended:
            # G261 (docs/planner.md "Tolerance balls", issue 36): a tolerance ball, whose end
            # (where the line changes) is a C2 joint with no step, or the programmed corner,
            # kept where VELOJUMP passes it faster than the ball would: a C0 knee within 000
            # l.108's formula. Which of the two it was is not taken from ncsim: the CSV shows
            # it. The allowance is the corner's; the step measured at the joint bounds what it
            # adds to a and j (README "Measuring a step"), so a ball that does not step gets
            # nothing, and a step there must be listed by the audit as any VELOJUMP step.
            rule = "ball|velojump"
        if a.transvelmin is not None and not a.contour:  # isg-language.md §5.6: priority
            dv = np.maximum(dv, min(a.transvelmin, v_up) * dt)
            rule = "transvelmin"
        jerk_limited = a.slope != 0 and b.slope != 0
        if not jerk_limited:
            da = zero
        elif self.m.corr_v_trans_jerk or (a.arc is None and b.arc is None):
            j_a = self.j_rapid if a.rapid else self.j
            j_b = self.j_rapid if b.rapid else self.j
            da = np.minimum(j_a, j_b) * T  # P-CHAN-00009: the axis jerk limits hold: j T
        else:  # P-CHAN-00009 = 0: no reduction for the curvature jump, only the a limits
            da = np.maximum(up_a, down_a) + np.maximum(up_b, down_b)
            rule += "+c1-unbounded"
        return Boundary(k, a, b, False, blended, dv, da, rule + g00)

    # -- the checks -----------------------------------------------------------------------------
    def check(self, lines: np.ndarray, pos: np.ndarray, start=None):
        T, n = self.T, self.n
        N = len(lines)
        if N < 4:
            return [], [], {}
        x = np.vstack([np.zeros((1, n)) if start is None else start, pos])  # x_0 .. x_N
        idx = self._block_index(lines)
        idx = np.concatenate([[idx[0]], idx])                               # idx_0 .. idx_N
        lo = np.minimum(idx[:-1], idx[1:])  # blocks moving in interval k = lo[k-1] .. hi[k-1]
        hi = np.maximum(idx[:-1], idx[1:])
        nb = len(self.blocks)
        rapid = np.array([b.rapid for b in self.blocks])
        jerk_lim = np.array([b.slope != 0 for b in self.blocks])
        # per interval k (1..N; array position k-1): does it hold a G00 / feed / STEP block
        cum_rapid = np.concatenate([[0], np.cumsum(rapid)])
        cum_feed = np.concatenate([[0], np.cumsum(~rapid)])
        cum_step = np.concatenate([[0], np.cumsum(~jerk_lim)])
        has_rapid = (cum_rapid[hi + 1] - cum_rapid[lo]) > 0
        has_feed = (cum_feed[hi + 1] - cum_feed[lo]) > 0
        has_step = (cum_step[hi + 1] - cum_step[lo]) > 0

        v = np.diff(x, axis=0) / T                  # v_1 .. v_N
        a = np.diff(x, 2, axis=0) / T**2            # a_1 .. a_{N-1}
        j = np.diff(x, 3, axis=0) / T**3            # j_1 .. j_{N-2}
        speed = np.linalg.norm(v[:, :min(3, n)], axis=1)
        e_v, e_a, e_j = 2 * DELTA_X / T, 4 * DELTA_X / T**2, 8 * DELTA_X / T**3

        # boundaries, grouped by their interval
        groups = {}
        for kk in range(1, N + 1):
            if hi[kk - 1] == lo[kk - 1]:
                continue
            around = speed[max(0, kk - 2):min(N, kk + 1)]
            v_up = float(around.max()) + 2 * T * float(np.linalg.norm(self.a_all[:min(3, n)]))
            for i in range(lo[kk - 1], hi[kk - 1]):
                groups.setdefault(kk, []).append(
                    self._boundary(kk, self.blocks[i], self.blocks[i + 1], v_up))
        findings, steps = [], []
        dv_eff, rules = {}, {}

        def rules_near(ks):
            return "|".join(sorted({rules[q] for q in ks if q in rules and np.any(dv_eff[q][0] + dv_eff[q][1] > 0)}))
        line_of = lines
        names = [ax.name for ax in self.ax]

        def t_of(k):
            return k * T

        # the time a finding is reported at: the centre of its stencil (v_k: interval k;
        # a_k: t_k; j_k: the middle of intervals k..k+2; a step: the middle of its interval)
        centre = {"velocity": -0.5, "acceleration": 0.0, "jerk": 0.5, "velojump": -0.5,
                  "c1-step": -0.5}

        def add(kind, axis, k, value, limit, note=""):
            row = min(max(k, 1), N)
            findings.append(Finding(kind, names[axis], k, t_of(k + centre[kind]), int(line_of[row - 1]),
                                    float(value), float(limit), note))

        # the steps at each group: measured against the formula (needs 3 clean cycles each side)
        keys = sorted(groups)
        for gi, kk in enumerate(keys):
            grp = groups[kk]
            dv_allow = np.sum([b.dv_allow for b in grp], axis=0)
            da_allow = np.sum([b.da_allow for b in grp], axis=0)
            moving = [b for b in grp if not b.stop]
            isolated = (kk - 3 >= 1 and kk + 2 <= N - 1
                        and (gi == 0 or keys[gi - 1] < kk - 3)
                        and (gi + 1 == len(keys) or keys[gi + 1] > kk + 3))
            est = None
            if isolated:
                # a_{k-2} and a_{k+1} do not see the instant in interval k
                a_l, a_r = a[kk - 3], a[kk]
                jl = not has_step[kk - 4:kk + 2].any()
                d_a = a_r - a_l              # = T (j_{k-2} + j_{k-1} + j_k): dv cancels
                if jl:
                    jmax = np.where(has_rapid[kk - 4:kk + 2].any(), np.maximum(self.j, self.j_rapid),
                                    self.j) if has_feed[kk - 4:kk + 2].any() else self.j_rapid
                    dv_est = v[kk] - v[kk - 2] - T * (a_l + a_r)
                    err = 6 * jmax * T**2 + T * np.abs(d_a) + 4 * e_v
                    da_meas = np.abs(d_a) - 3 * T * jmax - 2 * e_a
                else:
                    dv_est = v[kk] - v[kk - 2]
                    err = 2 * T * self.a_all + 4 * e_v
                    da_meas = None
                est = (dv_est, err)
                for i in range(n):
                    dv_low = abs(dv_est[i]) - err[i]        # the step is at least this
                    if moving and dv_low > dv_allow[i] * (1 + REL):
                        add("velojump", i, kk, dv_low, dv_allow[i],
                            f"(|dv| >= {dv_low:.6g} mm/s at {grp[0].rule}, lines "
                            f"{grp[0].a.line}->{grp[-1].b.line})")
                    if da_meas is not None and da_meas[i] > da_allow[i] * (1 + REL) + 0:
                        add("c1-step", i, kk, da_meas[i], da_allow[i],
                            f"(|da| >= {da_meas[i]:.6g} mm/s^2 at {grp[0].rule}, lines "
                            f"{grp[0].a.line}->{grp[-1].b.line})")
                    if dv_low > 0 or (da_meas is not None and da_meas[i] > 0):
                        steps.append({"k": kk, "t": t_of(kk), "axis": names[i],
                                      "dv_min": max(dv_low, 0.0),
                                      "da_min": max(float(da_meas[i]), 0.0) if da_meas is not None else 0.0,
                                      "dv_allow": float(dv_allow[i]), "da_allow": float(da_allow[i]),
                                      "rule": grp[0].rule, "lines": (grp[0].a.line, grp[-1].b.line)})
            eff = dv_allow.copy()
            if est is not None and len(moving) == 1:
                # one step: it is at most what was measured (the sum of several steps at
                # different instants of the cycle does not bound their effects one by one)
                eff = np.minimum(dv_allow, np.abs(est[0]) + est[1])
            dv_eff[kk] = (eff, da_allow)
            rules[kk] = "|".join(sorted({b.rule for b in moving})) or "stop"

        # per-cycle allowances from the steps (README "Steps")
        acc_allow = np.zeros((N + 2, n))
        jerk_allow = np.zeros((N + 2, n))
        for kk, (eff, da) in dv_eff.items():
            for m in (kk - 1, kk):
                if 1 <= m <= N:
                    acc_allow[m] += eff / T
            for m in (kk - 2, kk - 1, kk):
                if 1 <= m <= N:
                    jerk_allow[m] += eff / T**2 + da / T

        # velocity: v_k on interval k
        vlim = np.where(has_rapid[:, None], self.v_rapid, 0.0)
        vlim = np.maximum(vlim, np.where(has_feed[:, None], self.v_max, 0.0))
        bad = np.abs(v) > vlim * (1 + REL) + e_v
        for k0, i in zip(*np.nonzero(bad)):
            add("velocity", i, k0 + 1, abs(v[k0, i]), vlim[k0, i])

        # acceleration: a_k on intervals k, k+1
        if len(a):
            r2 = has_rapid[:-1] | has_rapid[1:]
            f2 = has_feed[:-1] | has_feed[1:]
            va, vb = v[:-1], v[1:]
            steps2 = np.array([sum(1 for kk in dv_eff if kk in (k, k + 1) and np.any(dv_eff[kk][0] > 0))
                               for k in range(1, N)]) if dv_eff else np.zeros(N - 1)
            margin = 2 * T * self.a_all
            same_sign = (np.sign(va) == np.sign(vb)) & (np.minimum(np.abs(va), np.abs(vb)) > margin)
            same_sign &= (steps2 == 0)[:, None]
            speeding = same_sign & (a * np.sign(va) > 0)
            slowing = same_sign & (a * np.sign(va) < 0)
            feed_lim = np.where(speeding, self.a_up, np.where(slowing, self.a_down,
                                                               np.maximum(self.a_up, self.a_down)))
            alim = np.maximum(np.where(r2[:, None], self.a_rapid, 0.0),
                              np.where(f2[:, None], feed_lim, 0.0))
            allow = acc_allow[1:N]
            bad = np.abs(a) > alim * (1 + REL) + allow + e_a
            for k0, i in zip(*np.nonzero(bad)):
                note = "(A+)" if speeding[k0, i] else "(A-)" if slowing[k0, i] else ""
                if allow[k0, i] > 0:
                    note += f" (+{allow[k0, i]:.6g} for steps at {rules_near((k0 + 1, k0 + 2))})"
                add("acceleration", i, k0 + 1, abs(a[k0, i]), alim[k0, i] + allow[k0, i], note.strip())

        # jerk: j_k on intervals k..k+2, only where every block there is jerk-limited
        if len(j):
            r3 = has_rapid[:-2] | has_rapid[1:-1] | has_rapid[2:]
            f3 = has_feed[:-2] | has_feed[1:-1] | has_feed[2:]
            s3 = has_step[:-2] | has_step[1:-1] | has_step[2:]
            jlim = np.maximum(np.where(r3[:, None], self.j_rapid, 0.0),
                              np.where(f3[:, None], self.j, 0.0))
            allow = jerk_allow[1:N - 1]
            bad = (~s3[:, None]) & (np.abs(j) > jlim * (1 + REL) + allow + e_j)
            for k0, i in zip(*np.nonzero(bad)):
                note = (f"(+{allow[k0, i]:.6g} for steps at {rules_near((k0 + 1, k0 + 2, k0 + 3))})"
                        if allow[k0, i] > 0 else "")
                add("jerk", i, k0 + 1, abs(j[k0, i]), jlim[k0, i] + allow[k0, i], note)
        stats = {"cycles": int(N), "boundaries": int(sum(len(g) for g in groups.values())),
                 "jerk_cycles": int((~(has_step[:-2] | has_step[1:-1] | has_step[2:])).sum()) if N > 2 else 0}
        return findings, steps, stats


def run_ncsim(ncsim, prog, machine, out_csv, scenario=None, audit=True, extra=()):
    """`ncsim run PROG --machine DIR [--scenario S] -o out.csv [--audit --audit-steps]`."""
    cmd = [ncsim, "run", prog, "--machine", machine, "-o", out_csv]
    if scenario:
        cmd += ["--scenario", scenario]
    if audit:
        cmd += ["--audit-steps"]
    cmd += list(extra)
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout + p.stderr, p.stderr


def check_files(machine_dir, prog, csv_path):
    machine = lists.load(machine_dir)
    t_csv, lines, pos, names, error = read_csv(csv_path)
    T = t_csv or machine.t_cycle
    blocks = ncprog.read(prog, machine.start_slope)
    chk = Checker(machine, blocks, T)
    findings, steps, stats = chk.check(lines, pos)
    stats["error"] = error
    return findings, steps, stats, T


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("program")
    ap.add_argument("--machine", required=True)
    ap.add_argument("--scenario")
    ap.add_argument("--csv", help="check this CSV instead of running ncsim")
    ap.add_argument("--ncsim", default=os.environ.get("NCSIM", "ncsim"))
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    csv_path = args.csv
    if not csv_path:
        import tempfile
        tmp = tempfile.mkdtemp(prefix="ncsim-check-")
        csv_path = os.path.join(tmp, "out.csv")
        run_ncsim(args.ncsim, args.program, args.machine, csv_path, args.scenario, audit=False)
    findings, steps, stats, T = check_files(args.machine, args.program, csv_path)
    if args.json:
        print(json.dumps({"stats": stats, "findings": [dataclasses.asdict(f) for f in findings]}))
    else:
        for f in findings:
            print("checker: violation " + f.text())
        print(f"checker: {stats['cycles']} cycles, {stats['boundaries']} block boundaries, "
              f"{len(findings)} violations")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
