#!/usr/bin/env python3
"""bench/bound_test.py: bench/bound.py against answers known in closed form (no ncsim).

- a straight rest-to-rest line that reaches V: t = L / V + V / A, and with the jerk estimate
  t + A / J (the 1-D S-curve);
- the same line at 45 degrees in XY: the path may accelerate at A / cos 45 (each axis at A);
- the maximum velocity curve on a circle: u = A R where the normal lies along an axis, and
  u = sqrt(2) A R at 45 degrees (each axis then sees v^2 / R / sqrt(2));
- a 90 degree knee: exact stop v = 0; ball r: the fillet of radius r tan(45) = r has its normal
  along an axis at its ends, so v^2 <= A r; the time of two lines with a stop between them.
Exit 0 when every case holds.
"""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bound  # noqa: E402

AXIS = """getriebe[0].dynamik.vb_max {v_um}
getriebe[0].vb_eilgang {v_um}
getriebe[0].dynamik.a_max {a}
getriebe[0].slope_profil.a_beschl {a}
getriebe[0].slope_profil.a_brems {a}
getriebe[0].slope_profil.a_grenz {a}
getriebe[0].slope_profil.tr_beschl_zu {tr}
getriebe[0].slope_profil.tr_beschl_ab {tr}
getriebe[0].slope_profil.tr_brems_zu {tr}
getriebe[0].slope_profil.tr_brems_ab {tr}
getriebe[0].slope_profil.tr_grenz {tr}
getriebe[0].dynamik.tr_min {tr}
"""

failures = []


def near(name, got, want, rel=1e-6):
    ok = abs(got - want) <= rel * max(1.0, abs(want))
    print(f"{'ok' if ok else 'FAIL'}   {name}: {got:.9g} (want {want:.9g})")
    if not ok:
        failures.append(name)


def machine(folder, v=100.0, a=1000.0, j=1e5):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "machine.lis"), "w") as f:
        f.write("channel channel.lis\naxis X x.lis\naxis Y y.lis\naxis Z z.lis\n")
    with open(os.path.join(folder, "channel.lis"), "w") as f:
        f.write("ncsim.cycle_time 1000\n")
    for name in ("x", "y", "z"):
        with open(os.path.join(folder, f"{name}.lis"), "w") as f:
            f.write(AXIS.format(v_um=v * 1000, a=a, tr=a / j * 1e6))
    return folder


def run(folder, text, mode="exact", ds=0.01):
    prog = os.path.join(folder, "p.nc")
    with open(prog, "w") as f:
        f.write(text)
    m = bound.lists.load(folder)
    blocks, devs = bound.parse(prog, m.axes)
    path = bound.Path(blocks, m, ds)
    caps = path.knee_caps(mode, devs)
    dt, jc = path.times(path.topp(caps))
    return path, caps, dt.sum(), (dt + jc).sum()


def main():
    with tempfile.TemporaryDirectory() as tmp:
        mach = machine(os.path.join(tmp, "m"))
        _, _, t, tj = run(mach, "G01 X100 F6000\n")
        near("line rest to rest: L/V + V/A", t, 100 / 100 + 100 / 1000)
        near("line with the jerk estimate: + A/J", tj, 1.1 + 1000 / 1e5)
        _, _, t, _ = run(mach, "G01 X100 Y100 F12000\n")
        near("45 degree line: each axis at V and A", t, 100 / 100 + 100 / 1000)

        r = 10.0
        t_axis = np.array([[0.0, 1.0, 0.0], [-math.sqrt(0.5), math.sqrt(0.5), 0.0]])
        k = np.array([[-1 / r, 0.0, 0.0], [-math.sqrt(0.5) / r, -math.sqrt(0.5) / r, 0.0]])
        lim = np.full((2, 3), 1000.0)
        u, _ = bound.max_u(t_axis, k, np.full(2, np.inf), lim, lim)
        near("circle, normal along X: u = A R", u[0], 1000 * r)
        near("circle at 45 degrees: u = sqrt(2) A R", u[1], math.sqrt(2) * 1000 * r)

        square = "#CONTOUR MODE [DEV PATH_DEV=0.01]\nG01 X50 F6000\nG01 Y50\n"
        path, caps, t, _ = run(mach, square, "exact")
        knee = path.last[0]
        near("exact stop at the knee: v = 0", caps[knee], 0.0)
        near("two lines with a stop: 2 (L/V + V/A)", t, 2 * (50 / 100 + 100 / 1000))
        path, caps, t_ball, _ = run(mach, square, "ball")
        near("ball of 0.01 at 90 degrees: u = A r", caps[knee], 1000 * 0.01)
        if not t_ball < t:
            failures.append("the ball is faster than the stop")
    if failures:
        print(f"{len(failures)} failed: {', '.join(failures)}")
        return 1
    print("all passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
