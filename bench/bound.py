#!/usr/bin/env python3
"""bench/bound.py: time-optimal lower bounds for an NC program, independent of ncsim's code.

Issue 36 asks for "an independent time-optimal bound tool (acceleration-only and jerk-aware) for
any program" and a per-block comparison of ncsim's `time` against it. This tool reads the
program's path (G00/G01/G02/G03 in G17/G18/G19, G90, F in mm/min, #CONTOUR MODE PATH_DEV) and
the machine's limits through the checker's own list reader (tests/checker/lists.py, no ncsim
code), and computes, by a time-optimal path parameterisation (TOPP), the shortest time the axes'
limits allow along that path:

  exact   v = 0 at every block end (what G60 may at best reach);
  ball    at a knee of inner angle alpha the path may turn on the circular fillet tangent to both
          sides at distance r = PATH_DEV from the corner (ncsim's tolerance ball, docs/planner.md
          "Tolerance balls"; R = r tan(alpha / 2)); the knee's velocity is capped by the
          per-axis centripetal limit on that fillet (the worst point of it);
  dev     as `ball`, with the largest fillet whose deviation from the programmed contour is
          PATH_DEV (R = r / (1 - sin(alpha / 2))): what a blend measured against the contour
          (LinuxCNC's G64 P, the hidden study's "ideal blends") may reach.
A tangent joint (below 1e-6 rad) has no cap. The fillet's shorter path is not credited
(< 2 r a knee).

TOPP (acceleration only): the path is sampled every ds (both ends of every block; a knee is
two samples at distance 0). With u = v^2, per axis i, direction cosine t_i and curvature vector
k_i: |t_i| v <= V_i (the feed's or G00's axis velocity), v <= F, and the axis acceleration
k_i u + t_i u'/2 within [-A-_i, A+_i] (A+ when the axis speeds up, in its direction of motion).
The maximum velocity curve is exact per sample (the feasible (u, a) set is a polygon; its
largest u is a minimum over pairs of constraint lines); a forward pass u_(k+1) = u_k + 2 ds
a_hi(u_k) and a backward pass, both capped by it; the time is sum 2 ds / (v_k + v_(k+1)).

Jerk estimate (not a proof): a jerk-limited profile needs |da/dt| <= J_path (J_path = min_i
J_i / |t_i|); every step of the path acceleration that the acceleration-only profile takes
faster than that (|da| > J_path dt over its piece) costs about |da| / (4 J_path): exact for a
straight rest-to-rest move that reaches its acceleration and velocity (four steps of a; t = L/v
+ v/a + a/j). Reported as `+jerk`; where the accelerations are short (small blocks) the true
cost is larger, and the jerk of curvature changes is not counted.

Output: the totals, and with --blocks ncsim's per-block time (`ncsim time --blocks`) next to
each bound's, largest loss first.

usage: bound.py PROGRAM --machine DIR [--ds MM] [--ncsim PATH] [--blocks N] [--from-line L]
"""
from __future__ import annotations

import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "tests", "checker"))
import lists  # noqa: E402  (the checker's own list reader)

TANGENT = 1e-6  # [rad] a joint below this turning angle is tangent


class Block:
    def __init__(self, line, start, end, feed, rapid, arc=None):
        self.line = line
        self.start = np.array(start, float)
        self.end = np.array(end, float)
        self.feed = feed    # [mm/s], inf for G00
        self.rapid = rapid
        self.arc = arc      # (centre, normal, radius, sweep, plane axes) or None
        self.length = 0.0

    def kind(self):
        """G00, arc, z (a move of the third axis alone) or line."""
        if self.rapid:
            return "G00"
        if self.arc:
            return "arc"
        return "z" if np.allclose(self.start[:2], self.end[:2], rtol=0.0, atol=1e-9) else "line"

    def samples(self, ds):
        """Points along the block: (s, tangent, curvature vector) arrays."""
        if self.arc is None:
            d = self.end - self.start
            self.length = float(np.linalg.norm(d))
            n = max(1, math.ceil(self.length / ds))
            s = np.linspace(0.0, self.length, n + 1)
            t = np.tile(d / self.length, (n + 1, 1))
            return s, t, np.zeros_like(t)
        _, r, phi0, sweep, (p, q), axial = self.arc
        arc_len = abs(sweep) * r
        self.length = math.hypot(arc_len, axial)
        n = max(1, math.ceil(self.length / ds))
        s = np.linspace(0.0, self.length, n + 1)
        phi = phi0 + sweep * s / self.length
        sgn = 1.0 if sweep > 0 else -1.0
        dim = len(self.start)
        t = np.zeros((n + 1, dim))
        k = np.zeros((n + 1, dim))
        c = arc_len / self.length  # share of the path in the plane
        t[:, p] = -sgn * np.sin(phi) * c
        t[:, q] = sgn * np.cos(phi) * c
        h = 3 - p - q if dim >= 3 else None
        if h is not None:
            t[:, h] = axial / self.length
        kappa = c * c / r
        k[:, p] = -np.cos(phi) * kappa
        k[:, q] = -np.sin(phi) * kappa
        return s, t, k


def parse(path, axes):
    """The program's moves; the machine's axis names give the coordinate order."""
    names = [a.name for a in axes]
    pos = [0.0] * len(names)
    blocks = []
    feed = None
    motion = None
    plane = (0, 1)
    path_dev = 1.0
    devs = []
    word = re.compile(r"([A-Z]+)\s*=?\s*(-?[0-9.]+(?:[eE][-+]?[0-9]+)?)")
    with open(path) as f:
        for line_no, raw in enumerate(f, 1):
            text = raw.split(";", 1)[0].strip().upper()
            text = re.sub(r"\(.*?\)", "", text)
            if not text or text.startswith("%"):
                continue
            if text.startswith("#"):
                m = re.search(r"PATH_DEV\s*=\s*([0-9.eE+-]+)", text)
                if m:
                    path_dev = float(m.group(1))
                continue
            words = word.findall(text)
            target = list(pos)
            centre_off = {}
            moved = False
            for letter, value in words:
                v = float(value)
                if letter == "G":
                    g = int(v)
                    if g in (0, 1, 2, 3):
                        motion = g
                    elif g in (17, 18, 19):
                        plane = {17: (0, 1), 18: (2, 0), 19: (1, 2)}[g]
                    elif g == 91:
                        sys.exit(f"{path}:{line_no}: G91 not supported by bound.py")
                elif letter == "F":
                    feed = v / 60.0
                elif letter in names:
                    target[names.index(letter)] = v
                    moved = True
                elif letter in ("I", "J", "K"):
                    centre_off["IJK".index(letter)] = v
                elif letter == "M":
                    pass
                else:
                    sys.exit(f"{path}:{line_no}: word {letter} not supported by bound.py")
            if not moved:
                continue
            if motion is None:
                sys.exit(f"{path}:{line_no}: a move with no G0/G1/G2/G3")
            rapid = motion == 0
            if motion in (2, 3):
                p, q = plane
                cp = pos[p] + centre_off.get(p, 0.0)
                cq = pos[q] + centre_off.get(q, 0.0)
                r0 = math.hypot(pos[p] - cp, pos[q] - cq)
                phi0 = math.atan2(pos[q] - cq, pos[p] - cp)
                phi1 = math.atan2(target[q] - cq, target[p] - cp)
                sweep = phi1 - phi0
                if motion == 3:
                    while sweep <= 1e-12:
                        sweep += 2 * math.pi
                else:
                    while sweep >= -1e-12:
                        sweep -= 2 * math.pi
                h = 3 - p - q
                axial = target[h] - pos[h] if len(names) > 2 else 0.0
                arc = ((cp, cq), r0, phi0, sweep, (p, q), axial)
            else:
                arc = None
            if math.dist(pos, target) < 1e-9 and arc is None:
                pos = target
                continue
            blocks.append(Block(line_no, pos, target, math.inf if rapid else feed, rapid, arc))
            devs.append(path_dev)
            pos = target
    return blocks, devs


def limits_arrays(machine):
    ax = machine.axes
    return (np.array([a.v_max for a in ax]), np.array([a.v_rapid for a in ax]),
            np.array([a.a_up for a in ax]), np.array([a.a_down for a in ax]),
            np.array([a.a_rapid for a in ax]), np.array([a.j for a in ax]),
            np.array([a.j_rapid for a in ax]))


def accel_lines(t, k, a_up, a_down):
    """Per sample and axis, the path acceleration interval as lines in u: lo = c_lo + m u,
    hi = c_hi + m u (a = u'/2). Axis acceleration t_i a + k_i u in [-A-, A+] in the
    direction of motion sign(t_i); an axis at rest (t_i = 0) is left to max_u."""
    moving = np.abs(t) > 1e-12
    ts = np.where(moving, t, 1.0)
    forward = ts > 0
    up = np.where(forward, a_up, a_down)    # the bound above t_i a + k_i u
    dn = np.where(forward, a_down, a_up)    # the bound below
    # t_i a <= up - k_i u  and  t_i a >= -dn - k_i u, divided by t_i (its sign swaps them)
    m = -k / ts
    c_hi = np.where(forward, up, -dn) / ts
    c_lo = np.where(forward, -dn, up) / ts
    return moving, c_lo, m, c_hi, m


def max_u(t, k, u_cap, a_up, a_down):
    """The maximum velocity curve u_max per sample (exact for the polygon of constraints),
    at most u_cap."""
    moving, c_lo, m_lo, c_hi, m_hi = accel_lines(t, k, a_up, a_down)
    u = np.array(u_cap, float)
    # axes at rest: |k_i| u <= min(A+, A-) (they may start either way)
    still = ~moving & (np.abs(k) > 1e-15)
    cap_still = np.where(still, np.minimum(a_up, a_down) / np.where(still, np.abs(k), 1.0),
                         np.inf)
    u = np.minimum(u, cap_still.min(axis=1))
    n_ax = t.shape[1]
    for j in range(n_ax):
        for i in range(n_ax):
            # hi_j(u) - lo_i(u) >= 0 with both axes moving
            c = c_hi[:, j] - c_lo[:, i]
            m = m_hi[:, j] - m_lo[:, i]
            ok = moving[:, j] & moving[:, i] & (m < 0)
            root = np.where(ok, -c / np.where(ok, m, -1.0), np.inf)
            u = np.minimum(u, root)
    return np.maximum(u, 0.0), (moving, c_lo, m_lo, c_hi, m_hi)


def fillet_cap(t_in, t_out, radius_of, a_up, a_down, u_cap):
    """u at most at a knee: the worst point of the fillet (21 points along it)."""
    cosang = float(np.clip(np.dot(t_in, t_out), -1.0, 1.0))
    theta = math.acos(cosang)
    if theta < TANGENT:
        return math.inf
    alpha = math.pi - theta
    if alpha < 1e-9:
        return 0.0  # a reversal
    radius = radius_of(alpha)
    # the fillet's plane: t_in, t_out; its tangent turns from t_in to t_out
    e1 = t_in
    e2 = t_out - cosang * t_in
    e2 = e2 / np.linalg.norm(e2)
    ang = np.linspace(0.0, theta, 21)
    t = np.outer(np.cos(ang), e1) + np.outer(np.sin(ang), e2)
    normal = -np.outer(np.sin(ang), e1) + np.outer(np.cos(ang), e2)
    k = normal / radius
    u, _ = max_u(t, k, np.full(len(ang), u_cap), a_up, a_down)
    return float(u.min())


class Path:
    def __init__(self, blocks, machine, ds):
        v_max, v_rapid, a_up, a_down, a_rapid, j, j_rapid = limits_arrays(machine)
        self.blocks = blocks
        ss, ts, ks, caps, aus, ads, blk, jp = [], [], [], [], [], [], [], []
        s0 = 0.0
        for b_i, b in enumerate(blocks):
            s, t, k = b.samples(ds)
            vax = v_rapid if b.rapid else v_max
            au = np.broadcast_to(a_rapid if b.rapid else a_up, t.shape)
            ad = np.broadcast_to(a_rapid if b.rapid else a_down, t.shape)
            with np.errstate(divide="ignore"):
                v_axes = np.min(np.where(np.abs(t) > 1e-12, vax / np.abs(t), np.inf), axis=1)
                j_path = np.min(np.where(np.abs(t) > 1e-12,
                                         (j_rapid if b.rapid else j) / np.abs(t), np.inf), axis=1)
            v = np.minimum(v_axes, b.feed)
            ss.append(s0 + s)
            ts.append(t)
            ks.append(k)
            caps.append(v * v)
            aus.append(au)
            ads.append(ad)
            blk.append(np.full(len(s), b_i))
            jp.append(j_path)
            s0 += b.length
        self.s = np.concatenate(ss)
        self.t = np.concatenate(ts)
        self.k = np.concatenate(ks)
        self.a_up = np.concatenate(aus)
        self.a_down = np.concatenate(ads)
        self.block = np.concatenate(blk)
        self.j_path = np.concatenate(jp)
        self.u_max, self.lines = max_u(self.t, self.k, np.concatenate(caps), self.a_up,
                                       self.a_down)
        # the first and last sample of each block
        self.first = np.flatnonzero(np.r_[True, self.block[1:] != self.block[:-1]])
        self.last = np.r_[self.first[1:] - 1, len(self.s) - 1]

    def knee_caps(self, mode, devs):
        caps = np.full(len(self.s), np.inf)
        caps[0] = 0.0
        caps[-1] = 0.0
        for b_i in range(len(self.blocks) - 1):
            e, f = self.last[b_i], self.first[b_i + 1]
            if mode == "exact":
                cap = 0.0
            else:
                r = devs[b_i]
                if mode == "ball":
                    def radius_of(alpha, r=r):
                        return r * math.tan(alpha / 2)
                else:
                    def radius_of(alpha, r=r):
                        return r / (1.0 - math.sin(alpha / 2))
                if self.blocks[b_i].rapid and not self.blocks[b_i + 1].rapid:
                    cap = 0.0  # G00 then a feed block: a stop (docs/planner.md "Stops")
                else:
                    cap = fillet_cap(self.t[e], self.t[f], radius_of,
                                     np.minimum(self.a_up[e], self.a_up[f]),
                                     np.minimum(self.a_down[e], self.a_down[f]),
                                     min(self.u_max[e], self.u_max[f]))
            caps[e] = min(caps[e], cap)
            caps[f] = min(caps[f], cap)
        return caps

    def topp(self, caps):
        moving, c_lo, m_lo, c_hi, m_hi = self.lines
        u_lim = np.minimum(self.u_max, caps)
        n = len(self.s)
        ds = np.diff(self.s)

        def a_hi(k, u):
            return np.where(moving[k], c_hi[k] + m_hi[k] * u, np.inf).min()

        def a_lo(k, u):
            return np.where(moving[k], c_lo[k] + m_lo[k] * u, -np.inf).max()

        fw = np.empty(n)
        fw[0] = u_lim[0]
        for i in range(n - 1):
            if ds[i] <= 0.0:
                fw[i + 1] = min(u_lim[i + 1], fw[i])
            else:
                fw[i + 1] = min(u_lim[i + 1], fw[i] + 2 * ds[i] * max(a_hi(i, fw[i]), 0.0))
        bw = np.empty(n)
        bw[-1] = fw[-1]
        for i in range(n - 2, -1, -1):
            if ds[i] <= 0.0:
                bw[i] = min(fw[i], bw[i + 1])
            else:
                bw[i] = min(fw[i], bw[i + 1] - 2 * ds[i] * min(a_lo(i + 1, bw[i + 1]), 0.0))
        return bw

    def times(self, u):
        v = np.sqrt(np.maximum(u, 0.0))
        ds = np.diff(self.s)
        vm = v[:-1] + v[1:]
        dt = np.where(ds > 0, 2 * ds / np.where(vm > 0, vm, np.inf), 0.0)
        if np.any((ds > 0) & (vm <= 0)):
            raise SystemExit("bound.py: the profile stands still on a path piece")
        # the path acceleration per piece (0 before the start and after the end) and the jerk
        # estimate at each step between pieces, booked to the piece after the step (the last
        # step to the last piece)
        acc = np.where(ds > 0, (u[1:] - u[:-1]) / (2 * np.where(ds > 0, ds, 1.0)), 0.0)
        acc_ext = np.r_[0.0, acc, 0.0]
        dt_ext = np.r_[0.0, dt, 0.0]
        dacc = np.abs(np.diff(acc_ext))                 # one per piece boundary, len(dt) + 1
        span = 0.5 * (dt_ext[:-1] + dt_ext[1:])
        jp = self.j_path                                 # per sample = per piece boundary
        extra = np.where(dacc > jp * span, dacc, 0.0) / (4 * jp)
        jerk_cost = extra[:-1].copy()
        jerk_cost[-1] += extra[-1]
        return dt, jerk_cost

    def per_block(self, dt):
        out = np.zeros(len(self.blocks))
        np.add.at(out, self.block[1:], dt)
        return out


def ncsim_blocks(ncsim, program, machine):
    r = subprocess.run([ncsim, "time", "--blocks", program, "--machine", machine],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"ncsim time: {r.stderr.strip()}")
    times = {}
    for line in r.stdout.splitlines():
        if line.startswith("#") or not line[:1].isdigit():
            continue
        cols = line.split()
        times[int(cols[0])] = times.get(int(cols[0]), 0.0) + float(cols[1])
    return times


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("program")
    ap.add_argument("--machine", required=True)
    ap.add_argument("--ds", type=float, default=0.01, help="sample step [mm]")
    ap.add_argument("--from-line", type=int, default=0,
                    help="count only blocks from this line on (the body)")
    ap.add_argument("--ncsim", help="ncsim binary: compare `time --blocks` per block")
    ap.add_argument("--blocks", type=int, default=0, help="list the N blocks that lose most")
    a = ap.parse_args(argv)
    machine = lists.load(a.machine)
    blocks, devs = parse(a.program, machine.axes)
    if not blocks:
        sys.exit(f"{a.program}: no moves")
    path = Path(blocks, machine, a.ds)
    body = np.array([b.line >= a.from_line for b in blocks])
    results = {}
    for mode in ("exact", "ball", "dev"):
        u = path.topp(path.knee_caps(mode, devs))
        dt, jc = path.times(u)
        results[mode] = (path.per_block(dt), path.per_block(jc))
    print(f"# {a.program} on {a.machine}: {len(blocks)} moves, ds {a.ds} mm, "
          f"body from line {a.from_line}")
    print(f"{'bound':>8} {'acc-only':>10} {'+jerk':>10}")
    for mode, (t, jc) in results.items():
        print(f"{mode:>8} {t[body].sum():>10.3f} {(t + jc)[body].sum():>10.3f}")
    if a.ncsim:
        nc = ncsim_blocks(a.ncsim, a.program, a.machine)
        lines = [b.line for b in blocks]
        mine = np.array([nc.get(ln, 0.0) for ln in lines])
        print(f"{'ncsim':>8} {mine[body].sum():>10.3f}")
        ball, ball_j = results["ball"]
        kinds = {}
        for i, b in enumerate(blocks):
            if not body[i]:
                continue
            k = kinds.setdefault(b.kind(), [0, 0.0, 0.0])
            k[0] += 1
            k[1] += mine[i]
            k[2] += ball[i] + ball_j[i]
        print(f"{'kind':>6} {'n':>5} {'ncsim':>9} {'ball+j':>9} {'loss':>8}")
        for kind, (n, t_nc, t_b) in kinds.items():
            print(f"{kind:>6} {n:>5} {t_nc:>9.3f} {t_b:>9.3f} {t_nc - t_b:>8.3f}")
        if a.blocks:
            loss = (mine - ball - ball_j) * body
            order = np.argsort(-loss)[:a.blocks]
            print(f"{'line':>6} {'len_mm':>8} {'F':>8} {'kind':>5} {'ncsim':>8} "
                  f"{'ball':>8} {'+jerk':>8} {'loss':>8}")
            for i in order:
                b = blocks[i]
                print(f"{b.line:>6} {b.length:>8.3f} {b.feed * 60:>8.0f} {b.kind():>5} "
                      f"{mine[i]:>8.3f} {ball[i]:>8.3f} {ball[i] + ball_j[i]:>8.3f} "
                      f"{loss[i]:>8.3f}")


if __name__ == "__main__":
    main()
