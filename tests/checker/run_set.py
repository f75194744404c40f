#!/usr/bin/env python3
"""Run the trajectory checker over a seeded set (or the known cases) and compare with the audit.

  run_set.py --ncsim PATH --seeds 1..150 --jobs 2 [--expect expected.txt] [--keep DIR]
  run_set.py --ncsim PATH --known [--expect-known]

For each seed: gen.py writes program, machine variant and scenario; `ncsim run --audit-steps`
writes the CSV and the audit; check.py checks the CSV; agree.py compares both. Prints one line
per program with a finding, then a summary table (programs, cycles, violations by kind,
disagreements); with --json a JSON object too. Exit 1 on any violation or disagreement, except
that with --expect FILE the seeds listed there (known findings of issue 36, each with its item)
must fail and every other seed must pass: a new failure or a fixed seed both exit 1.
"""
from __future__ import annotations

import argparse
import collections
import json
import multiprocessing
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import agree  # noqa: E402
import check  # noqa: E402
import gen  # noqa: E402
import lists  # noqa: E402
import ncprog  # noqa: E402


def run_case(ncsim, name, prog, machine_dir, scenario, work):
    """One program: run, check, compare. Returns a result dict (never raises for ncsim)."""
    csv_path = os.path.join(work, "out.csv")
    t0 = time.monotonic()
    rc, out, err = check.run_ncsim(ncsim, prog, machine_dir, csv_path, scenario)
    res = {"name": name, "rc": rc, "wall_s": 0.0, "cycles": 0, "violations": [],
           "disagreements": [], "audit_violations": 0, "audit_contour": 0, "audit_steps": 0,
           "error": ""}
    if not os.path.exists(csv_path):
        res["error"] = "no CSV: " + err.strip().splitlines()[-1] if err.strip() else "no CSV"
        res["wall_s"] = time.monotonic() - t0
        return res
    machine = lists.load(machine_dir)
    t_csv, lines, pos, names, error = check.read_csv(csv_path)
    T = t_csv or machine.t_cycle
    blocks = ncprog.read(prog, machine.start_slope)
    chk = check.Checker(machine, blocks, T)
    findings, steps, stats = chk.check(lines, pos)
    audit = agree.parse(out)
    res["cycles"] = stats["cycles"]
    res["error"] = error
    res["violations"] = [dict(kind=f.kind, axis=f.axis, t=round(f.t, 9), line=f.line,
                              value=f.value, limit=f.limit, note=f.note) for f in findings]
    res["audit_violations"] = len(audit["violations"]) + audit["more_violations"]
    res["audit_contour"] = sum(1 for v in audit["violations"] if v["kind"] == "contour")
    res["audit_steps"] = len(audit["steps"]) + audit["more_steps"]
    if not audit["seen"]:
        res["disagreements"].append({"why": "the run printed no audit", "rc": rc})
    else:
        res["disagreements"] = agree.compare(findings, steps, audit, chk, lines, blocks, T)
    res["wall_s"] = time.monotonic() - t0
    return res


def run_seed(args):
    ncsim, seed, keep = args
    work = tempfile.mkdtemp(prefix=f"checker-{seed}-")
    try:
        meta = gen.generate(seed, work)
        scen = os.path.join(work, meta["scenario"]) if meta["scenario"] else None
        res = run_case(ncsim, f"seed {seed}", os.path.join(work, "prog.nc"),
                       os.path.join(work, "machine"), scen, work)
        res["seed"] = seed
        if keep and (res["violations"] or res["disagreements"] or res["error"]):
            dest = os.path.join(keep, f"seed{seed}")
            shutil.rmtree(dest, ignore_errors=True)
            shutil.copytree(work, dest)
        return res
    finally:
        shutil.rmtree(work, ignore_errors=True)


def known_cases():
    """tests/checker/known/<name>/: prog.nc, machine (a folder, or a file naming a bundled
    machine), optional scenario.toml, README (the issue-36 item)."""
    root = os.path.join(HERE, "known")
    for name in sorted(os.listdir(root)):
        d = os.path.join(root, name)
        if not os.path.isdir(d):
            continue
        machine = os.path.join(d, "machine")
        if os.path.isfile(machine):
            with open(machine) as f:
                machine = os.path.normpath(os.path.join(HERE, "..", "..", "machines", f.read().strip()))
        scen = os.path.join(d, "scenario.toml")
        yield name, os.path.join(d, "prog.nc"), machine, scen if os.path.exists(scen) else None


def run_known(args):
    ncsim, name, prog, machine, scen = args
    work = tempfile.mkdtemp(prefix=f"checker-{name}-")
    try:
        return run_case(ncsim, name, prog, machine, scen, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def parse_seeds(text):
    out = []
    for part in text.split(","):
        if ".." in part:
            a, b = part.split("..")
            out.extend(range(int(a), int(b) + 1))
        elif part:
            out.append(int(part))
    return out


def read_expect(path):
    """key -> expected tags; lines `KEY TAG,TAG,...  # issue 36 item N: ...`."""
    out = {}
    if not path:
        return out
    with open(path) as f:
        for raw in f:
            line = raw.split("#", 1)[0].strip()
            if line:
                key, _, rest = line.partition(" ")
                out[key] = sorted(t for t in rest.strip().split(",") if t)
    return out


def tags(res):
    """The kinds of finding of one result, e.g. `c1-step@transvelmin`, `g00-joint-bound`,
    `audit-only:jerk(finite differences)`: what --expect compares (README "Known findings")."""
    out = set()
    for v in res["violations"]:
        note = v["note"]
        if v["kind"] in ("velojump", "c1-step"):
            rule = note.split(" at ", 1)[1].split(",")[0] if " at " in note else ""
            out.add(f"{v['kind']}@{rule}")
        elif "for steps at " in note:
            out.add(f"{v['kind']}@steps:{note.split('for steps at ', 1)[1].rstrip(')')}")
        else:
            out.add(v["kind"])
    for d in res["disagreements"]:
        why = d["why"]
        if why.startswith("checker violation"):
            out.add("not-in-audit:" + d["kind"])
        elif why.startswith("audit violation"):
            method = why.split("(")[1].split(")")[0].replace(" ", "-")
            out.add(f"audit-only:{d['kind']}({method})")
        elif "G00 block" in why:
            out.add("g00-joint-bound")
        elif why.startswith("step allowed"):
            out.add(f"unlisted-step:{d['kind']}@{d['rule']}")
        elif why.startswith("the run printed no audit"):
            out.add("no-audit")
        else:
            out.add(why.split(" (")[0].replace(" ", "-"))
    return sorted(out)


def describe(res):
    lines = []
    for v in res["violations"]:
        lines.append(f"  violation {v['kind']} t={v['t']:.6g} s line {v['line']} axis {v['axis']} "
                     f"{v['value']:.6g} > {v['limit']:.6g} {v['note']}".rstrip())
    for d in res["disagreements"]:
        parts = [f"{k}={d[k]:.6g}" if isinstance(d[k], float) else f"{k}={d[k]}"
                 for k in d if k != "why" and d[k] is not None]
        lines.append(f"  disagreement: {d['why']}: " + " ".join(parts))
    if res["error"]:
        lines.append(f"  run ended: {res['error']}")
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description="the checker over a seeded set")
    ap.add_argument("--ncsim", default=os.environ.get("NCSIM", "ncsim"))
    ap.add_argument("--seeds", default="")
    ap.add_argument("--known", action="store_true", help="run tests/checker/known/ instead")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--expect", help="file of seeds (or known case names) expected to fail")
    ap.add_argument("--keep", help="copy failing programs to this folder")
    ap.add_argument("--json", help="write every result to this file")
    ap.add_argument("--quiet", action="store_true", help="summary only")
    ap.add_argument("--write-expect", help="write the current tags of every failing key here")
    args = ap.parse_args(argv)
    t0 = time.monotonic()
    if args.known:
        tasks = [(args.ncsim, *case) for case in known_cases()]
        fn, key = run_known, (lambda r: r["name"])
    else:
        tasks = [(args.ncsim, s, args.keep) for s in parse_seeds(args.seeds)]
        fn, key = run_seed, (lambda r: str(r["seed"]))
    with multiprocessing.Pool(max(1, args.jobs)) as pool:
        results = pool.map(fn, tasks, chunksize=1)
    expect = read_expect(args.expect)
    kinds = collections.Counter()
    dis = collections.Counter()
    failing, unexpected, fixed = [], [], []
    for r in results:
        for v in r["violations"]:
            kinds[v["kind"]] += 1
        for d in r["disagreements"]:
            dis[d["why"].split(" (")[0]] += 1
        bad = bool(r["violations"] or r["disagreements"])
        r["tags"] = tags(r)
        if bad:
            failing.append(key(r))
        if not args.quiet and (bad or r["error"]):
            note = "  [expected]" if expect.get(key(r)) == r["tags"] else ""
            print(f"{r['name']}: {len(r['violations'])} violations, "
                  f"{len(r['disagreements'])} disagreements, {r['cycles']} cycles, "
                  f"audit {r['audit_violations']} violations ({r['audit_contour']} contour), "
                  f"exit {r['rc']}{note}")
            print("  tags: " + ",".join(r["tags"]))
            for line in describe(r)[:40]:
                print(line)
        if args.expect and r["tags"] != expect.get(key(r), []):
            (unexpected if bad else fixed).append(key(r))
    wall = time.monotonic() - t0
    print()
    print(f"{'programs':<34}{len(results):>10}")
    print(f"{'cycles':<34}{sum(r['cycles'] for r in results):>10}")
    print(f"{'programs with findings':<34}{len(failing):>10}")
    for k in ("velocity", "acceleration", "jerk", "velojump", "c1-step"):
        print(f"{'violations: ' + k:<34}{kinds.get(k, 0):>10}")
    print(f"{'disagreements':<34}{sum(dis.values()):>10}")
    for k, n in sorted(dis.items()):
        print(f"  {k:<44}{n:>6}")
    print(f"{'audit violations (contour, apart)':<34}{sum(r['audit_contour'] for r in results):>10}")
    print(f"{'audit steps listed':<34}{sum(r['audit_steps'] for r in results):>10}")
    print(f"{'wall time [s]':<34}{wall:>10.1f}")
    if args.write_expect:
        with open(args.write_expect, "w") as f:
            for r in results:
                if r["tags"]:
                    f.write(f"{key(r)} {','.join(r['tags'])}\n")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    if args.expect:
        in_set = {key(r) for r in results}
        print(f"expected failures in this set: {len([k for k in expect if k in in_set])}, "
              f"failing now: {len(failing)}")
        by_key = {key(r): r for r in results}
        for k in unexpected:
            print(f"CHANGED: {k}: expected [{','.join(expect.get(k, []))}], "
                  f"now [{','.join(by_key[k]['tags'])}] (update {args.expect} only for a known cause)")
        for k in fixed:
            print(f"NOW PASSING: {k}: expected [{','.join(expect[k])}]: remove it from {args.expect}")
        return 1 if (unexpected or fixed) else 0
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main())
