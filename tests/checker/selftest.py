#!/usr/bin/env python3
"""The checker on synthetic trajectories whose answer is known (no ncsim needed): a
jerk-limited move along X within portal_3x's limits is clean; the same move 5 % faster in jerk,
in acceleration, or in velocity is found at the right place; a velocity step is allowed at a
knee up to VELOJUMP and found in the middle of a block."""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import check  # noqa: E402
import lists  # noqa: E402
import ncprog  # noqa: E402

MACHINE = lists.load(os.path.join(HERE, "..", "..", "machines", "portal_3x"))
T = 1e-3


def program(text):
    fd, path = tempfile.mkstemp(suffix=".nc")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    try:
        return ncprog.read(path, 1)
    finally:
        os.remove(path)


def profile(j, a_max, v_max, n):
    """x(t) of a jerk-limited speed-up along one axis, sampled at the ends of n cycles."""
    dt = T / 100
    x = v = a = 0.0
    out = []
    for k in range(1, n + 1):
        for _ in range(100):
            if v + a * a / (2 * j) < v_max:
                a = min(a + j * dt, a_max)
            else:
                a = max(a - j * dt, 0.0)
            v += a * dt
            x += v * dt
        out.append(x)
    return np.array(out)


def run(blocks, xs, lines):
    pos = np.zeros((len(xs), 3))
    pos[:, 0] = xs
    chk = check.Checker(MACHINE, blocks, T)
    return chk.check(np.asarray(lines), pos)[0]


def main():
    blocks = program("#SLOPE [TYPE=TRAPEZ]\nG01 X1000 F30000\nM30\n")
    X = MACHINE.axes[0]
    failures = []

    def expect(name, findings, kinds):
        got = sorted({f.kind for f in findings})
        if got != sorted(kinds):
            failures.append(f"{name}: expected {kinds}, found {got}: "
                            + "; ".join(f.text() for f in findings[:3]))

    n = 400
    lines = [2] * n
    expect("within limits", run(blocks, profile(0.99 * X.j, 0.99 * X.a_up, 0.99 * X.v_max, n), lines), [])
    expect("jerk 5 % over", run(blocks, profile(1.05 * X.j, 0.9 * X.a_up, 0.9 * X.v_max, n), lines), ["jerk"])
    expect("acceleration 5 % over",
           run(blocks, profile(0.9 * X.j, 1.05 * X.a_up, 0.9 * X.v_max, n), lines), ["acceleration"])
    expect("velocity 5 % over",
           run(blocks, profile(0.9 * X.j, 0.9 * X.a_up, 1.05 * X.v_max, n), lines), ["velocity"])
    # a velocity step of half VELOJUMP in the middle of a block, at constant velocity
    step = 0.5 * X.velojump(T)
    xs = np.cumsum(np.where(np.arange(n) < 200, 50.0, 50.0 + step) * T)
    expect("a step inside a block", run(blocks, xs, lines), ["jerk"])
    # the same step at a 90 degree knee (TRAPEZ: VELOJUMP allows C0 min(A+, |A-|) T)
    knee = program("G01 X10 F30000\nG01 Y10\nM30\n")
    expect("the step at a knee", run(knee, xs, [1] * 200 + [2] * (n - 200)), [])
    # and 1.2 x VELOJUMP there
    big = np.cumsum(np.where(np.arange(n) < 200, 50.0, 50.0 + 1.2 * X.velojump(T)) * T)
    expect("a step above VELOJUMP at a knee", run(knee, big, [1] * 200 + [2] * (n - 200)),
           ["jerk", "velojump"])
    # G261 (issue 36): the joint is a ball (C2) or a corner kept because VELOJUMP passes it
    # faster; a step within VELOJUMP is allowed, 1.2 x VELOJUMP is not
    kept = program("#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\nG01 X10 F30000\nG01 Y10\nM30\n")
    expect("the step at a G261 corner", run(kept, xs, [3] * 200 + [4] * (n - 200)), [])
    expect("a step above VELOJUMP at a G261 corner", run(kept, big, [3] * 200 + [4] * (n - 200)),
           ["jerk", "velojump"])
    for f in failures:
        print("selftest: FAILED " + f)
    print(f"selftest: {9 - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
