#!/usr/bin/env python3
"""bench/dense_chords.py: dense CAM programs of 0.1 mm chords for `ncsim time` / `ncsim run`.

usage: dense_chords.py walk [--chords 200000] [--turn 0.06] [--path-dev 0.01] [--seed 7]
       dense_chords.py circle [--chords 10000000]

walk:   chords of 0.1 mm at F6000 whose heading takes a random step of +-turn/2 rad per chord
        (0.06 rad: +-1.7 degrees), turned back by pi where it would leave X 20..700 / Y 0..500
        (portal_3x's table); with --path-dev D > 0 under `#CONTOUR MODE [DEV, PATH_DEV=D]` and
        G261 (tolerance balls), with --path-dev 0 at VELOJUMP corners (G260).
circle: chords of 0.1 mm at F6000 round a circle of R 20 mm about X100 Y100 (a 0.29 degree knee
        each, 0.005 rad per chord), no tolerance balls: the long-program row (10 M blocks).
The program goes to standard output. Random numbers: Python's random.Random(seed), which gives
the same sequence on every platform and Python 3 version; no clock.
"""
import argparse
import math
import random
import sys


def walk(out, chords, turn, path_dev, seed):
    rnd = random.Random(seed)
    out.write("%dense_walk\nN1 G17 G90 G71 G94\n")
    if path_dev > 0:
        out.write(f"#CONTOUR MODE [DEV, PATH_DEV={path_dev:g}]\nG261\n")
    out.write("N2 G01 X20 Y0 F6000\n")
    x, y, h = 20.0, 0.0, 0.0
    for _ in range(chords):
        h += (rnd.random() - 0.5) * turn
        x += 0.1 * math.cos(h)
        y += 0.1 * math.sin(h)
        if x > 700 or x < 20 or y > 500 or y < 0:
            h += math.pi
        out.write(f"X{x:.4f} Y{y:.4f}\n")
    out.write("G260\nM30\n")


def circle(out, chords):
    out.write("%dense_circle\nN1 G17 G90 G71 G94\nN2 G01 X120.000000 Y100.000000 F6000\n")
    write = out.write
    for k in range(1, chords + 1):
        a = k * 0.005
        write(f"X{100 + 20 * math.cos(a):.6f} Y{100 + 20 * math.sin(a):.6f}\n")
    out.write("M30\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="kind", required=True)
    w = sub.add_parser("walk")
    w.add_argument("--chords", type=int, default=200000)
    w.add_argument("--turn", type=float, default=0.06)
    w.add_argument("--path-dev", type=float, default=0.01)
    w.add_argument("--seed", type=int, default=7)
    c = sub.add_parser("circle")
    c.add_argument("--chords", type=int, default=10000000)
    a = ap.parse_args()
    out = sys.stdout
    if a.kind == "walk":
        walk(out, a.chords, a.turn, a.path_dev, a.seed)
    else:
        circle(out, a.chords)


if __name__ == "__main__":
    main()
