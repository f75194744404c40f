#!/usr/bin/env python3
"""bench/gbench.py: a Google Benchmark binary pinned to one core, least and median of 3+ runs.

usage: gbench.py BINARY [--filter REGEX] [--reps 3] [--core 1] [--min-time 0.3]

Runs BINARY with --benchmark_repetitions=REPS (JSON), pinned to core CORE (default 1, or
$CORE), and prints one line per benchmark: the least and the median CPU time per iteration and,
the rates the benchmark counts (items/s, its blocks/s, iterations/s, x_real_time: the best
and the median), with the load average at the
start. CPU time, not wall time: the machine may be shared.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys


# Rates (higher is better: best and median) and values printed beside the CPU time: Google
# Benchmark's items/s and the benchmarks' own counters (rates per CPU second).
RATES = (("items_per_second", "M items/s", 1e6, ".3g"), ("blocks/s", "M blocks/s", 1e6, ".3g"),
         ("iterations/s", "M iterations/s", 1e6, ".3g"), ("x_real_time", "x real time", 1.0, ",.0f"))
VALUES = ("program_s", "commands")


def human_time(ns):
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("us", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--filter", default="")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--core", default=os.environ.get("CORE", "1"))
    ap.add_argument("--min-time", default="0.3")
    a = ap.parse_args()
    os.sched_setaffinity(0, {int(a.core)})
    load = os.getloadavg()
    cmd = [a.binary, f"--benchmark_repetitions={a.reps}", "--benchmark_format=json",
           f"--benchmark_min_time={a.min_time}"]
    if a.filter:
        cmd.append(f"--benchmark_filter={a.filter}")
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.stderr.write(res.stderr)
        sys.exit(f"gbench.py: {a.binary} exited {res.returncode}")
    runs = {}
    for b in json.loads(res.stdout)["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        runs.setdefault(b["run_name"], []).append(b | {"cpu_ns": b["cpu_time"] * scale})
    for name, rs in runs.items():
        times = sorted(r["cpu_ns"] for r in rs)
        line = f"{name}: CPU {human_time(times[0])} / {human_time(statistics.median(times))}"
        for key, unit, scale, fmt in RATES:
            rates = sorted((r[key] for r in rs if r.get(key)), reverse=True)
            if rates:
                line += f", {rates[0] / scale:{fmt}} / {statistics.median(rates) / scale:{fmt}} {unit}"
        for key in VALUES:
            if key in rs[0]:
                line += f", {key} {rs[0][key]:.6g}"
        print(line + f" (least / median of {len(rs)}; load {load[0]:.2f})")


if __name__ == "__main__":
    main()
