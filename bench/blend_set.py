#!/usr/bin/env python3
"""bench/blend_set.py: seeded line/arc programs for issue 36's time-optimality study.

Writes, for each seed, a 200-move program in the style the issue describes (arcs of 1-8 mm
radius, arc-arc and arc-line knees, Z-only moves between XY moves, a feed change on most
blocks, #SLOPE [TYPE=TRAPEZ], G261 with PATH_DEV 0.01) and two variants of its machine
(portal_3x_slow's lists, V 100 mm/s, A 1000 mm/s^2 on every axis, with J 1e5 or 1e9 mm/s^3),
then times it with `ncsim time` under G261, G260 and G60 (exact stop at every block) and
prints a table. Same seed, same program (random.Random(seed)); no clock.

usage: blend_set.py --ncsim PATH [--seeds 1..5] [--out DIR] [--moves 200]
"""
import argparse
import math
import os
import random
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def program(seed: int, moves: int) -> list[str]:
    rnd = random.Random(seed)
    x, y, z = 100.0, 100.0, 0.0
    heading = rnd.uniform(0, 2 * math.pi)
    body = []
    n = 0
    feed = 3000.0
    while n < moves:
        kind = rnd.random()
        if rnd.random() < 0.8:
            feed = round(rnd.uniform(900.0, 6000.0), 3)
        fword = f" F{feed:.3f}"
        if kind < 0.12:  # a Z-only move between XY moves
            dz = rnd.uniform(0.5, 8.0) * (1 if z < 0 else -1)
            z += dz
            body.append(f"G01 Z{z:.6f}{fword}")
        elif kind < 0.55:  # a line, a knee of 0..150 degrees (steered back into the field)
            turn = rnd.choice([0.0, rnd.uniform(-2.6, 2.6), rnd.uniform(-0.5, 0.5)])
            heading += turn
            length = rnd.uniform(1.0, 30.0)
            nx, ny = x + length * math.cos(heading), y + length * math.sin(heading)
            if not (0 < nx < 300 and 0 < ny < 300):
                heading = math.atan2(150 - y, 150 - x)
                nx, ny = x + length * math.cos(heading), y + length * math.sin(heading)
            x, y = nx, ny
            body.append(f"G01 X{x:.6f} Y{y:.6f}{fword}")
        else:  # an arc of R 1..8 mm, tangent or with a knee
            if rnd.random() < 0.5:
                heading += rnd.uniform(-1.5, 1.5)
            r = rnd.uniform(1.0, 8.0)
            ccw = rnd.random() < 0.5
            sweep = rnd.uniform(0.3, 3.5)
            side = 1.0 if ccw else -1.0
            cx = x - side * r * math.sin(heading)
            cy = y + side * r * math.cos(heading)
            phi0 = math.atan2(y - cy, x - cx)
            phi1 = phi0 + side * sweep
            ex, ey = cx + r * math.cos(phi1), cy + r * math.sin(phi1)
            if not (0 < ex < 300 and 0 < ey < 300):
                continue
            body.append(f"G0{3 if ccw else 2} X{ex:.6f} Y{ey:.6f} I{cx - x:.6f} J{cy - y:.6f}{fword}")
            x, y = ex, ey
            heading = phi1 + side * math.pi / 2
        n += 1
    return body


def write(out: str, seed: int, moves: int, mode: str) -> str:
    path = os.path.join(out, f"s{seed}_{mode}.nc")
    head = ["%blend_set", "G17 G90 G71 G94", "G00 X100 Y100 Z0", "#SLOPE [TYPE=TRAPEZ]",
            "#CONTOUR MODE [DEV PATH_DEV=0.01]"]
    body = program(seed, moves)
    if mode == "G60":  # an exact stop at every block end (G60 acts in its block)
        body = ["G60 " + b for b in body]
    else:
        head.append(mode)
    with open(path, "w") as f:
        f.write("\n".join(head + body + ["M30"]) + "\n")
    return path


def machine(out: str, jerk: float) -> str:
    """portal_3x_slow with every ramp time set to A / jerk."""
    dst = os.path.join(out, f"machine_j{jerk:g}")
    if os.path.isdir(dst):
        return dst
    shutil.copytree(os.path.join(ROOT, "machines", "portal_3x_slow"), dst)
    shutil.copy(os.path.join(ROOT, "machines", "portal_3x", "channel.lis"), dst)
    lis = os.path.join(dst, "machine.lis")
    text = open(lis).read().replace("../portal_3x/channel.lis", "channel.lis")
    open(lis, "w").write(text)
    ramp_us = 1000.0 / jerk * 1e6
    for name in os.listdir(dst):
        p = os.path.join(dst, name)
        text = open(p).read()
        text = re.sub(r"(tr_(beschl_zu|beschl_ab|brems_zu|brems_ab|grenz|min|geom)\s+)\d+",
                      lambda m: m.group(1) + f"{ramp_us:.6g}", text)
        open(p, "w").write(text)
    return dst


def body_time(ncsim: str, prog: str, mach: str) -> float:
    r = subprocess.run([ncsim, "time", "--blocks", prog, "--machine", mach],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{prog}: {r.stderr.strip()}")
    total = 0.0
    for line in r.stdout.splitlines():
        if line.startswith("#") or not line[:1].isdigit():
            continue
        cols = line.split()
        if int(cols[0]) > 3:  # the body: every block after the start G00
            total += float(cols[1])
    return total


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--ncsim", required=True)
    ap.add_argument("--seeds", default="1..5")
    ap.add_argument("--out", default="/tmp/blend_set")
    ap.add_argument("--moves", type=int, default=200)
    a = ap.parse_args()
    lo, hi = (int(v) for v in a.seeds.split(".."))
    os.makedirs(a.out, exist_ok=True)
    print(f"{'seed':>5} {'J':>6} {'G261':>9} {'G260':>9} {'G60':>9} {'G261/G260':>10}")
    for jerk in (1e5, 1e9):
        mach = machine(a.out, jerk)
        for seed in range(lo, hi + 1):
            t = {m: body_time(a.ncsim, write(a.out, seed, a.moves, m), mach)
                 for m in ("G261", "G260", "G60")}
            print(f"{seed:>5} {jerk:>6g} {t['G261']:>9.3f} {t['G260']:>9.3f} {t['G60']:>9.3f} "
                  f"{t['G261'] / t['G260']:>10.4f}")


if __name__ == "__main__":
    main()
