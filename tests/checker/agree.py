"""Agreement between the checker and ncsim's audit (`--audit-steps` output).

Read only from the audit's printed lines (the interface), never from its code:
  audit: violation t=T s line L axis A QUANTITY (METHOD) VALUE > LIMIT
  audit: step KIND t=T s line L axis A |dv| V of B mm/s at the link velocity W mm/s
  audit: ... N more violations | audit: ... N more steps   (lists cut at 1000)
Rules (README "Agreement"):
  1. every checker violation has an audit violation on the same axis, of a matching quantity,
     within MATCH_CYCLES cycles; matching quantities: velocity-velocity, acceleration-
     acceleration, jerk-jerk; a checker step beyond its formula (velojump / c1-step) is the same
     defect as the audit's step violation or as the acceleration / jerk its differences make;
  2. every audit violation (contour excepted: the checker does not measure the contour; counted
     apart) has a checker violation by the same rule;
  3. every step the audit lists lies at a block boundary of its line (its line changes in the
     CSV within MATCH_CYCLES cycles of it, or the line ends in a tolerance ball, whose joints
     carry the line), is within the checker's own formula for that boundary, and its bound is
     the checker's formula (VELOJUMP C0 min(A+, |A-|) T, C1 j T; relative 1e-6);
  4. every step the checker measures for certain (README "Steps") inside its allowance is
     listed by the audit within MATCH_CYCLES cycles on that axis (the audit must list every
     step it allows, issue 36 item 5).
"""
from __future__ import annotations

import re

MATCH_CYCLES = 2
# The audit prints values with 6 significant digits (cli human()): relative 5e-6 from rounding;
# values and bounds compare within 1e-5 relative.
PRINTED = 1e-5
# Tangents from end points written to 1e-6 mm (and arcs whose end radius the interpreter
# corrects): |dx'| compares within 1e-6, the planner's own tangent tolerance (docs/planner.md).
TANGENT = 1e-6
VIOL = re.compile(r"^audit: violation t=(\S+) s line (\S+) axis (\S+) (\S+) \(([^)]*)\) (\S+) > (\S+)")
STEP = re.compile(r"^audit: step (\S+) t=(\S+) s line (\S+) axis (\S+) \|(d[va])\| (\S+) of (\S+) "
                  r"mm/s(?:\^2)? at the link velocity (\S+) mm/s")
SAME = {
    "velocity": {"velocity"},
    "acceleration": {"acceleration"},
    "jerk": {"jerk"},
    "velojump": {"velojump", "transvelmin", "acceleration", "jerk"},
    "c1-step": {"c1-step", "jerk"},
}


def _line(text):
    try:
        return int(text)
    except ValueError:
        return -1  # a line of a subroutine file


def parse(stdout: str) -> dict:
    out = {"violations": [], "steps": [], "more_violations": 0, "more_steps": 0, "seen": False}
    for raw in stdout.splitlines():
        if not raw.startswith("audit:"):
            continue
        out["seen"] = True
        m = VIOL.match(raw)
        if m:
            out["violations"].append({"t": float(m[1]), "line": _line(m[2]), "axis": m[3],
                                      "kind": m[4], "method": m[5], "value": float(m[6]),
                                      "limit": float(m[7])})
            continue
        m = STEP.match(raw)
        if m:
            out["steps"].append({"rule": m[1], "t": float(m[2]), "line": _line(m[3]),
                                 "axis": m[4], "dq": m[5], "value": float(m[6]),
                                 "bound": float(m[7]), "v_link": float(m[8])})
            continue
        m = re.match(r"^audit: \.\.\. (\d+) more (violations|steps)", raw)
        if m:
            out["more_" + m[2]] = int(m[1])
    return out


def _compatible(checker_kind, audit_kind):
    if checker_kind in SAME and audit_kind in SAME[checker_kind]:
        return True
    return audit_kind in SAME and checker_kind in SAME[audit_kind]


def compare(findings, steps, audit, chk, lines, blocks, T):
    """Disagreements as dicts (where, axis, checker's value, audit's value, why)."""
    tol = MATCH_CYCLES * T + 1e-9
    out = []
    horizon_v = max((v["t"] for v in audit["violations"]), default=0.0) \
        if audit["more_violations"] else float("inf")
    horizon_s = max((s["t"] for s in audit["steps"]), default=0.0) \
        if audit["more_steps"] else float("inf")
    for f in findings:
        if f.t > horizon_v + tol:
            continue
        if not any(v["axis"] == f.axis and _compatible(f.kind, v["kind"]) and abs(v["t"] - f.t) <= tol
                   for v in audit["violations"]):
            out.append({"why": "checker violation the audit does not list", "t": f.t, "line": f.line,
                        "axis": f.axis, "kind": f.kind, "checker": f.value, "checker_limit": f.limit,
                        "audit": None, "note": f.note})
    for v in audit["violations"]:
        if v["kind"] == "contour":
            continue
        if not any(f.axis == v["axis"] and _compatible(f.kind, v["kind"]) and abs(v["t"] - f.t) <= tol
                   for f in findings):
            out.append({"why": f"audit violation ({v['method']}) the checker does not find",
                        "t": v["t"], "line": v["line"], "axis": v["axis"], "kind": v["kind"],
                        "checker": None, "audit": v["value"], "audit_limit": v["limit"]})
    # 3. the audit's listed steps
    names = [a.name for a in chk.ax]
    change_k = [k for k in range(1, len(lines)) if lines[k] != lines[k - 1]]
    change_t = [(k + 1) * T for k in change_k]  # row index k is cycle k+1
    by_line = {b.line: i for i, b in enumerate(blocks)}
    for s in audit["steps"]:
        axis = names.index(s["axis"]) if s["axis"] in names else None
        i = by_line.get(s["line"])
        if axis is None or i is None:
            out.append({"why": "audit step on a line or axis the checker does not know", **s})
            continue
        blk = blocks[i]
        nxt = blocks[i + 1] if i + 1 < len(blocks) else None
        at_change = any(abs(ct - s["t"]) <= tol + T for ct in change_t)
        in_ball = blk.contour and nxt is not None and not blk.stop
        if not (at_change or in_ball):
            out.append({"why": "audit step not at a block boundary", **s})
        ax = chk.ax[axis]
        if s["rule"] == "C1":
            mine = min(ax.j_rapid if blk.rapid else ax.j,
                       (ax.j_rapid if (nxt and nxt.rapid) else ax.j)) * T
            if not chk.m.corr_v_trans_jerk:
                mine = float("inf")
        elif s["rule"] == "VELOJUMP":
            lim = [ax.a_rapid] if blk.rapid else [ax.a_up, ax.a_down]
            if nxt is not None:
                lim += [ax.a_rapid] if nxt.rapid else [ax.a_up, ax.a_down]
            mine = ax.c0 * min(lim) * T
        else:  # #TRANSVELMIN: v_min |dx'_i|
            if nxt is None or blk.transvelmin is None:
                mine = 0.0
            else:
                mine = blk.transvelmin * abs(nxt.tangent(False)[axis] - blk.tangent(True)[axis])
        g00 = blk.rapid or (nxt is not None and nxt.rapid)
        where = " at a joint with a G00 block" if g00 else ""
        if s["value"] > mine * (1 + PRINTED) + 1e-12:
            out.append({"why": f"audit step above the checker's formula{where}", "checker_bound": mine, **s})
        elif abs(s["bound"] - mine) > PRINTED * max(mine, 1e-12) and s["rule"] != "#TRANSVELMIN":
            out.append({"why": f"audit step bound is not the checker's formula{where}",
                        "checker_bound": mine, **s})
        elif s["rule"] == "#TRANSVELMIN" and abs(s["bound"] - mine) > (
                PRINTED * mine + blk.transvelmin * TANGENT):
            out.append({"why": "audit #TRANSVELMIN bound is not v_min |dx'|", "checker_bound": mine, **s})
    # 4. steps measured for certain and allowed must be listed
    for st in steps:
        if st["t"] > horizon_s + tol:
            continue
        certain_dv = st["dv_min"] > 0 and st["dv_min"] <= st["dv_allow"] * (1 + 1e-9)
        certain_da = st["da_min"] > 0 and st["da_min"] <= st["da_allow"] * (1 + 1e-9)
        if not (certain_dv or certain_da):
            continue
        if not any(s["axis"] == st["axis"] and abs(s["t"] - st["t"]) <= tol + T for s in audit["steps"]):
            out.append({"why": "step allowed by the checker's formula but not listed by the audit",
                        "t": st["t"], "line": st["lines"][0], "axis": st["axis"],
                        "checker": st["dv_min"] if certain_dv else st["da_min"],
                        "kind": "dv" if certain_dv else "da", "rule": st["rule"],
                        "checker_limit": st["dv_allow"] if certain_dv else st["da_allow"]})
    return out
