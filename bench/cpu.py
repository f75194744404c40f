#!/usr/bin/env python3
"""bench/cpu.py: CPU time of a command, pinned to one core, over several runs.

usage: cpu.py [--runs N] [--core C] [--label TEXT] [--sim SECONDS | --sim-json] [--blocks N]
              [--target-x X] [--target-rate R] [--target-mb MB] [--stdout FILE] -- COMMAND...

Runs COMMAND N times (default 3) pinned to core C (default 1, or $CORE; like `taskset -c C`)
and prints one line: the least and the median CPU time (user + system of the child, from
wait4: not stretched by other processes on a shared machine, unlike the wall time), the peak
RSS (of one more run, under /usr/bin/time), the load average at the start, and, where given,
the rate: --blocks N gives N / CPU blocks/s; --sim S (simulated seconds) or --sim-json (the
command is `ncsim time --json ...`, whose "total_s" is read) gives x real time = simulated /
CPU. The --target-* options add "met" / "MISSED" (judged on the median) against a lower bound
of x real time or blocks/s and an upper bound of the peak RSS in MB. A command that exits with
another status than --ok-exit's (default 0) is an error (exit 1).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def measure(cmd, stdout_path):
    """One run: exit status, the tail of its stderr, CPU seconds (user + system of the child)."""
    out = open(stdout_path, "wb") if stdout_path else subprocess.DEVNULL
    with tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)
        err.seek(0)
        stderr = err.read()[-2000:]
    if stdout_path:
        out.close()
    return os.waitstatus_to_exitcode(status), stderr, usage.ru_utime + usage.ru_stime


def peak_rss_mb(cmd, stdout_path):
    """The peak RSS of one more run, from /usr/bin/time: a child's own ru_maxrss would count the
    pages of the Python process it was forked from."""
    out = open(stdout_path, "wb") if stdout_path else subprocess.DEVNULL
    with tempfile.NamedTemporaryFile("r") as kb:
        subprocess.run(["/usr/bin/time", "-q", "-f", "%M", "-o", kb.name] + cmd, stdout=out,
                       stderr=subprocess.DEVNULL)
        lines = kb.read().strip().splitlines()
    if stdout_path:
        out.close()
    return int(lines[-1]) / 1024.0 if lines and lines[-1].isdigit() else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--core", default=os.environ.get("CORE", "1"))
    ap.add_argument("--label", default="")
    ap.add_argument("--sim", type=float)
    ap.add_argument("--sim-json", action="store_true")
    ap.add_argument("--blocks", type=int)
    ap.add_argument("--target-x", type=float)
    ap.add_argument("--target-rate", type=float)
    ap.add_argument("--target-mb", type=float)
    ap.add_argument("--stdout")
    ap.add_argument("--ok-exit", type=int, nargs="*", default=[0])
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.cmd[1:] if a.cmd and a.cmd[0] == "--" else a.cmd
    if not cmd:
        ap.error("no command")
    if not os.path.exists("/usr/bin/time"):
        sys.exit("cpu.py: needs /usr/bin/time (apt-get install time)")
    os.sched_setaffinity(0, {int(a.core)})  # inherited by every child: no taskset process
    load = os.getloadavg()
    sim = a.sim
    times = []
    stdout_path = a.stdout or ("/tmp/ncsim-bench-cpu.out" if a.sim_json else None)
    for _ in range(a.runs):
        rc, stderr, cpu = measure(cmd, stdout_path)
        if rc not in a.ok_exit:
            sys.stderr.write(stderr.decode(errors="replace"))
            sys.exit(f"cpu.py: {' '.join(cmd)} exited {rc}")
        times.append(cpu)
    if a.sim_json:
        with open(stdout_path) as f:
            sim = json.load(f)["total_s"]
    rss = peak_rss_mb(cmd, stdout_path)
    least, median = min(times), statistics.median(times)
    parts = [a.label or " ".join(a.cmd), f"CPU {least:.3f} / {median:.3f} s (least / median of {a.runs})"]
    verdicts = []
    if sim is not None:
        x_least, x_median = sim / least, sim / median
        parts.append(f"simulated {sim:.3f} s = {x_least:,.0f}x / {x_median:,.0f}x real time")
        if a.target_x is not None:
            verdicts.append(f">= {a.target_x:g}x: {'met' if x_median >= a.target_x else 'MISSED'}")
    if a.blocks:
        r_least, r_median = a.blocks / least, a.blocks / median
        parts.append(f"{r_least / 1e6:.2f} / {r_median / 1e6:.2f} M blocks/s")
        if a.target_rate is not None:
            verdicts.append(f">= {a.target_rate / 1e6:g} M/s: {'met' if r_median >= a.target_rate else 'MISSED'}")
    parts.append(f"peak RSS {rss:.1f} MB")
    if a.target_mb is not None:
        verdicts.append(f"< {a.target_mb:g} MB: {'met' if rss < a.target_mb else 'MISSED'}")
    parts.append(f"load {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(" | ".join(parts) + ("" if not verdicts else " | " + "; ".join(verdicts)))


if __name__ == "__main__":
    main()
