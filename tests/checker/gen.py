#!/usr/bin/env python3
"""Seeded random programs, machine variants and scenarios for the trajectory checker.

`gen.py --seed S --out DIR` writes DIR/prog.nc, DIR/machine/ (a variant of machines/portal_3x
with changed list values), DIR/scenario.toml (for some seeds) and DIR/meta.json. Everything
follows from the seed (random.Random(S)): the same seed gives the same files byte for byte.

Programs: lines, 1e-3 mm segments, near-collinear knees (0.01..2 degrees), reversals, arcs in
G17 / G18 / G19 with I/J/K or R, helices, G00 mixed in, G60 / G09, every #SLOPE type, G261 with
#CONTOUR MODE [DEV PATH_DEV=0.001..3] and G260, #TRANSVELMIN, feeds 1..60000 mm/min (a slow
feed only on a short block, so that a run stays well under a second of wall time).
Machines: C0 0.3..2.5 per axis, A+ != A-, G00 velocity / acceleration / jerk below the feed
values, ramp times 20..100 ms, 1 or 2 ms cycles, sometimes P-CHAN-00009 = 0 (the manual's
default); override above 100 % only on REDUCED_ABOVE_100 (NCSIM-CHAN-630).
Scenarios (docs/scenario.md): override steps 0..150 % (..300 % above 100), feed holds with a
duration, and a last event at 100 % so that every run ends.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lists  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = os.path.normpath(os.path.join(HERE, "..", "..", "machines", "portal_3x"))
BOX = ((60.0, 740.0), (60.0, 540.0), (-240.0, 140.0))  # inside portal_3x's soft limits


def fmt(x: float) -> str:
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


# -- machine variants ----------------------------------------------------------------------------
def machine_variant(rng: random.Random, out_dir: str, above_100: bool) -> dict:
    """Write a portal_3x variant into out_dir; returns what was changed."""
    os.makedirs(out_dir, exist_ok=True)
    _, axis_files = lists.index(BASE)
    cycle_us = rng.choice([1000, 1000, 2000])
    corr = 0 if rng.random() < 0.1 else 1
    rapid_below = rng.random() < 0.5
    desc = {"cycle_us": cycle_us, "corr_v_trans_jerk": corr, "rapid_below_feed": rapid_below,
            "axes": {}}
    with open(os.path.join(out_dir, "channel.lis"), "w") as f:
        f.write("# checker variant of portal_3x (tests/checker/gen.py)\n")
        f.write("configuration.interpolator.function   FCT_IPO_DEFAULT\n")
        f.write(f"ncsim.cycle_time {cycle_us}\n")
        f.write(f"corr_v_trans_jerk {corr}\n")
        if above_100:
            f.write("ncsim.path_override_type REDUCED_ABOVE_100\n")
    with open(os.path.join(out_dir, "machine.lis"), "w") as f:
        f.write("name checker_variant\nchannel channel.lis\n")
        for name, path in axis_files:
            f.write(f"axis {name} {name.lower()}.lis\n")
    for name, path in axis_files:
        values = lists.read_list(path)
        v_max = float(values["getriebe[0].dynamik.vb_max"])
        a_max = rng.choice([2000, 3000, 4000, 5000])
        a_up = rng.randint(a_max // 3, a_max)
        a_down = rng.randint(a_max // 3, a_max)
        if rapid_below:
            v_rapid = int(v_max * rng.uniform(0.3, 0.9))
            a_rapid = rng.randint(a_max // 4, min(a_up, a_down))
        else:
            v_rapid = int(v_max)
            a_rapid = rng.randint(a_max // 3, a_max)
        ramps = {k: rng.randint(20, 100) * 1000 for k in
                 ("tr_beschl_zu", "tr_beschl_ab", "tr_brems_zu", "tr_brems_ab")}
        tr_grenz = rng.randint(20, 100) * 1000
        if rapid_below:  # G00 jerk below the feed jerk
            j_feed = min(a_up / ramps["tr_beschl_zu"], a_up / ramps["tr_beschl_ab"],
                         a_down / ramps["tr_brems_zu"], a_down / ramps["tr_brems_ab"])
            tr_grenz = max(tr_grenz, int(math.ceil(a_rapid / (0.7 * j_feed) / 1000.0)) * 1000)
        c0 = round(rng.uniform(0.3, 2.5), 3)
        values.update({
            "getriebe[0].vb_eilgang": str(v_rapid),
            "getriebe[0].dynamik.a_max": str(a_max),
            "getriebe[0].slope_profil.a_beschl": str(a_up),
            "getriebe[0].slope_profil.a_brems": str(a_down),
            "getriebe[0].slope_profil.a_grenz": str(a_rapid),
            "getriebe[0].slope_profil.tr_grenz": str(tr_grenz),
            "getriebe[0].dynamik.tr_geom": str(min(ramps.values())),
            "nci.velo_jump_factor": str(c0),
        })
        for k, t in ramps.items():
            values["getriebe[0].slope_profil." + k] = str(t)
        with open(os.path.join(out_dir, name.lower() + ".lis"), "w") as f:
            f.write(f"# checker variant of portal_3x axis {name}\n")
            for k, v in values.items():
                f.write(f"{k} {v}\n")
        desc["axes"][name] = {"a_max": a_max, "a_up": a_up, "a_down": a_down, "v_rapid_um_s": v_rapid,
                              "a_rapid": a_rapid, "tr_grenz": tr_grenz, "c0": c0, **ramps}
    return desc


# -- programs ------------------------------------------------------------------------------------
class Writer:
    def __init__(self, rng: random.Random):
        self.rng = rng
        self.lines = ["%checker", "G17 G90 G71 G94"]
        self.pos = [rng.uniform(*BOX[0]), rng.uniform(*BOX[1]), rng.uniform(*BOX[2])]
        self.lines.append("G00 X%s Y%s Z%s" % tuple(fmt(c) for c in self.pos))
        self.pos = [float(fmt(c)) for c in self.pos]
        self.dir = [1.0, 0.0, 0.0]
        self.feed = None
        self.plane = 17
        self.contour = False
        self.time = 0.0      # a rough estimate of the machine time [s]
        self.features = {}

    def note(self, what):
        self.features[what] = self.features.get(what, 0) + 1

    def inside(self, p, margin=0.0):
        return all(lo + margin <= c <= hi - margin for c, (lo, hi) in zip(p, BOX))

    def feed_word(self, length, force=False):
        rng = self.rng
        if rng.random() < 0.05:
            f = rng.uniform(1, 30)         # a crawl: only on short blocks
        else:
            f = math.exp(rng.uniform(math.log(30), math.log(60000)))
        t = length / (f / 60.0)
        if t > 1.0:                        # keep each run short
            f = length * 60.0 / 1.0
        f = max(1.0, min(60000.0, f))
        self.time += length / (f / 60.0) + 0.05
        if force or self.feed is None or rng.random() < 0.8:
            self.feed = f
            return " F" + fmt(round(f, 3))
        return ""

    def suffix(self):
        r = self.rng.random()
        if r < 0.06:
            self.note("G60")
            return "G60 "
        if r < 0.12:
            self.note("G09")
            return "G09 "
        return ""

    def line_to(self, p, rapid=False):
        p = [float(fmt(c)) for c in p]
        if not self.inside(p):
            return False
        d = [b - a for a, b in zip(self.pos, p)]
        length = math.sqrt(sum(c * c for c in d))
        if length < 5e-4:
            return False
        words = " ".join(f"{a}{fmt(c)}" for a, c, o in zip("XYZ", p, self.pos) if fmt(c) != fmt(o))
        if not words:
            return False
        if rapid:
            self.lines.append(f"{self.suffix()}G00 {words}")
            self.time += length / 100.0 + 0.1
            self.note("G00")
        else:
            self.lines.append(f"{self.suffix()}G01 {words}{self.feed_word(length, self.feed is None)}")
        self.dir = [c / length for c in d]
        self.pos = p
        return True

    def random_dir(self):
        rng = self.rng
        v = [rng.gauss(0, 1) for _ in range(3)]
        if rng.random() < 0.5:
            v[2] *= 0.1
        n = math.sqrt(sum(c * c for c in v)) or 1.0
        return [c / n for c in v]

    def turned(self, degrees):
        """The current direction turned by about `degrees` about a random axis."""
        r = self.random_dir()
        d = self.dir
        dot = sum(a * b for a, b in zip(r, d))
        perp = [a - dot * b for a, b in zip(r, d)]
        n = math.sqrt(sum(c * c for c in perp)) or 1.0
        perp = [c / n for c in perp]
        th = math.radians(degrees)
        return [math.cos(th) * a + math.sin(th) * b for a, b in zip(d, perp)]

    def step(self):
        rng = self.rng
        r = rng.random()
        if r < 0.22:   # a line in any direction
            length = math.exp(rng.uniform(math.log(0.05), math.log(60)))
            d = self.random_dir()
            self.note("line")
            return self.line_to([p + length * c for p, c in zip(self.pos, d)])
        if r < 0.30:   # a 1e-3 mm segment
            d = self.random_dir()
            self.note("micro")
            return self.line_to([p + 1e-3 * c for p, c in zip(self.pos, d)])
        if r < 0.40:   # a near-collinear knee
            d = self.turned(math.exp(rng.uniform(math.log(0.01), math.log(2.0))))
            length = math.exp(rng.uniform(math.log(0.05), math.log(20)))
            self.note("knee")
            return self.line_to([p + length * c for p, c in zip(self.pos, d)])
        if r < 0.46:   # a reversal
            length = math.exp(rng.uniform(math.log(0.05), math.log(20)))
            self.note("reversal")
            return self.line_to([p - length * c for p, c in zip(self.pos, self.dir)])
        if r < 0.52:   # a corner of 10..170 degrees
            d = self.turned(rng.uniform(10, 170))
            length = math.exp(rng.uniform(math.log(0.2), math.log(30)))
            self.note("corner")
            return self.line_to([p + length * c for p, c in zip(self.pos, d)])
        if r < 0.58:   # G00
            d = self.random_dir()
            length = rng.uniform(1, 80)
            return self.line_to([p + length * c for p, c in zip(self.pos, d)], rapid=True)
        if r < 0.78:
            return self.arc()
        if r < 0.84:
            slope = rng.choice(["STEP", "TRAPEZ", "SIN2"])
            self.lines.append(f"#SLOPE [TYPE={slope}]")
            self.note("slope_" + slope)
            return True
        if r < 0.92:
            if self.contour and rng.random() < 0.4:
                self.lines.append("G260")
                self.contour = False
                return True
            dev = math.exp(rng.uniform(math.log(0.001), math.log(3.0)))
            self.lines.append(f"#CONTOUR MODE [DEV PATH_DEV={fmt(round(dev, 4) or 0.001)}]")
            self.lines.append("G261")
            self.contour = True
            self.note("G261")
            return True
        if r < 0.96:
            if rng.random() < 0.6:
                self.lines.append(f"#TRANSVELMIN ON [{fmt(round(rng.uniform(60, 12000), 1))}]")
                self.note("transvelmin")
            else:
                self.lines.append("#TRANSVELMIN OFF")
            return True
        return self.arc(helix=True)

    def arc(self, helix=False):
        rng = self.rng
        plane = rng.choice([17, 18, 19])
        u, v, n = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}[plane]
        radius = math.exp(rng.uniform(math.log(0.5), math.log(40)))
        a0 = rng.uniform(0, 2 * math.pi)
        c = list(self.pos)
        c[u] -= radius * math.cos(a0)
        c[v] -= radius * math.sin(a0)
        lo = [c[i] - (radius if i in (u, v) else 0) for i in range(3)]
        hi = [c[i] + (radius if i in (u, v) else 0) for i in range(3)]
        rise = rng.uniform(-10, 10) if helix else 0.0
        lo[n] = min(self.pos[n], self.pos[n] + rise)
        hi[n] = max(self.pos[n], self.pos[n] + rise)
        if not (self.inside(lo) and self.inside(hi)):
            return False
        ccw = rng.random() < 0.5
        use_r = not helix and rng.random() < 0.35
        while True:
            sweep = rng.uniform(math.radians(5), math.radians(350))
            if not use_r or abs(math.degrees(sweep) - 180) > 10:
                break
        a1 = a0 + (sweep if ccw else -sweep)
        end = list(self.pos)
        end[u] = c[u] + radius * math.cos(a1)
        end[v] = c[v] + radius * math.sin(a1)
        end[n] = self.pos[n] + rise
        end = [float(fmt(x)) for x in end]
        names = "XYZ"
        if plane != self.plane:
            self.lines.append(f"G{plane}")
            self.plane = plane
        words = " ".join(f"{names[i]}{fmt(end[i])}" for i in (u, v, n) if (i != n or helix))
        if use_r:
            words += f" R{fmt(radius if sweep <= math.pi else -radius)}"
            self.note("arc_R")
        else:
            ij = "IJK"
            words += f" {ij[u]}{fmt(c[u] - self.pos[u])} {ij[v]}{fmt(c[v] - self.pos[v])}"
            self.note("helix" if helix else f"arc_G{plane}")
        length = math.hypot(radius * sweep, rise)
        g = "G03" if ccw else "G02"
        self.lines.append(f"{self.suffix()}{g} {words}{self.feed_word(length, self.feed is None)}")
        # the tangent at the end (for the next knee)
        t = [0.0, 0.0, 0.0]
        s = 1.0 if ccw else -1.0
        t[u], t[v] = -s * math.sin(a1) * radius, s * math.cos(a1) * radius
        t[n] = rise / sweep
        nrm = math.sqrt(sum(x * x for x in t)) or 1.0
        self.dir = [x / nrm for x in t]
        self.pos = end
        return True


def program(rng: random.Random):
    w = Writer(rng)
    if rng.random() < 0.7:
        slope = rng.choice(["STEP", "TRAPEZ", "SIN2"])
        w.lines.append(f"#SLOPE [TYPE={slope}]")
        w.note("slope_" + slope)
    target = rng.randint(6, 18)
    moves = 0
    tries = 0
    while moves < target and tries < 200:
        tries += 1
        before = len(w.lines)
        if w.step() and len(w.lines) > before and w.lines[-1][:1] in "GX":
            moves += 1
    w.lines.append("M30")
    return "\n".join(w.lines) + "\n", w.time, w.features


def scenario(rng: random.Random, duration: float, above_100: bool) -> str:
    events = []
    t = 0.0
    for _ in range(rng.randint(1, 5)):
        t += rng.uniform(0.02, max(0.05, duration / 3))
        kind = rng.random()
        if kind < 0.6:
            value = rng.choice([0, 10, 50, 80, 120, 150, 200, 300]) if above_100 else \
                rng.choice([0, 5, 30, 60, 90, 100])
            if not above_100:
                value = min(value, 100)
            events.append(f"[[event]]\nat = {t:.3f}\noverride = {value}\n")
        else:
            events.append(f"[[event]]\nat = {t:.3f}\nfeed_hold = true\n"
                          f"duration = {rng.uniform(0.01, 0.3):.3f}\n")
    t += rng.uniform(0.02, 0.5)
    events.append(f"[[event]]\nat = {t:.3f}\noverride = 100\n")
    return ("description = \"tests/checker/gen.py\"\n\n" + "\n".join(events)
            + "\n[stop]\ntime = 120\n")


def generate(seed: int, out: str) -> dict:
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    with_scenario = rng.random() < 0.4
    above_100 = with_scenario and rng.random() < 0.4
    desc = machine_variant(rng, os.path.join(out, "machine"), above_100)
    text, est, features = program(rng)
    with open(os.path.join(out, "prog.nc"), "w") as f:
        f.write(text)
    meta = {"seed": seed, "machine": desc, "estimated_s": round(est, 3), "features": features,
            "scenario": None}
    if with_scenario:
        with open(os.path.join(out, "scenario.toml"), "w") as f:
            f.write(scenario(rng, est, above_100))
        meta["scenario"] = "scenario.toml"
    with open(os.path.join(out, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1, sort_keys=True)
    return meta


def main(argv=None):
    ap = argparse.ArgumentParser(description="seeded random programs for the checker")
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args(argv)
    print(json.dumps(generate(args.seed, args.out), sort_keys=True))


if __name__ == "__main__":
    main()
