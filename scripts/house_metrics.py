#!/usr/bin/env python3
"""scripts/house_metrics.py: the measures of issue 35 ("the house") on the tracked sources.

Prints each folder's share of the source lines (tests excluded), the hand-written functions
longer than 120 lines, the classes with more than 30 member functions, and the includes of a
room at or above the file's own (docs/design.md). Heuristic, not a
parser: a function is a definition starting at column 0 and ending at the next `}` at column
0; member functions are the declarations and inline definitions inside a class body. Run from
anywhere: python3 scripts/house_metrics.py [--all]
"""
import os
import re
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
files = subprocess.run(["git", "ls-files", "*.cpp", "*.hpp"], cwd=root, capture_output=True,
                       text=True, check=True).stdout.split()
sources = [f for f in files if not f.endswith("_test.cpp") and "test_support" not in f
           and not f.startswith(("fuzz/", "tests/"))]

lines = {}
for f in sources:
    with open(os.path.join(root, f), encoding="utf-8", errors="replace") as fh:
        lines[f] = fh.read().split("\n")

total = sum(len(v) for v in lines.values())
by_folder = {}
for f, v in lines.items():
    by_folder[f.split("/")[0]] = by_folder.get(f.split("/")[0], 0) + len(v)
print(f"source lines: {total}")
for folder, n in sorted(by_folder.items(), key=lambda x: -x[1]):
    flag = "  > 15 %" if n > 0.15 * total else ""
    print(f"  {folder:12s} {n:6d} {100.0 * n / total:5.1f} %{flag}")

start = re.compile(r"^[A-Za-z].*[)]\s*(const\s*)?(noexcept\s*)?(override\s*)?(->.*)?\{\s*$")
long_functions = []
for f, v in lines.items():
    i = 0
    while i < len(v):
        if start.match(v[i]) and not v[i].startswith(("namespace", "struct", "class", "enum")):
            j = i + 1
            while j < len(v) and not v[j].startswith("}"):
                j += 1
            n = j - i + 1
            if n > 120:
                long_functions.append((n, f, i + 1, v[i].strip()[:70]))
            i = j
        i += 1
print(f"functions over 120 lines: {len(long_functions)}")
for n, f, ln, head in sorted(long_functions, reverse=True):
    print(f"  {n:4d} {f}:{ln} {head}")

decl = re.compile(r"^\s+(?:virtual\s+|static\s+|explicit\s+|inline\s+|constexpr\s+|\[\[nodiscard\]\]\s+)*"
                  r"[\w:<>,\s\*&~]*?\b(~?\w+|operator\S+)\s*\([^;{]*\)\s*(const)?\s*(noexcept)?\s*"
                  r"(override)?\s*(=\s*(default|delete|0))?\s*[;{]")
big = []
for f, v in lines.items():
    if not f.endswith(".hpp"):
        continue
    depth_stack = []
    name = None
    count = 0
    depth = 0
    for line in v:
        m = re.match(r"^\s*(class|struct)\s+(\w+)[^;]*\{", line)
        if m and name is None:
            name, count, depth = m.group(2), 0, 0
        if name is not None:
            if depth == 1 and decl.match(line) and "return" not in line and "=" not in line.split("(")[0]:
                count += 1
            depth += line.count("{") - line.count("}")
            if depth <= 0 and "}" in line:
                if count > 30:
                    big.append((count, f, name))
                name = None
print(f"classes over 30 member functions: {len(big)}")
for n, f, c in sorted(big, reverse=True):
    print(f"  {n:4d} {c} ({f})")

# Includes from a lower room to a higher one (docs/design.md "from the bottom"); rooms on one
# level may not include each other either (audit / program, runner / report / golden). Tests
# are excluded (they use audit/ as their oracle, docs/design.md).
levels = [["core"], ["grammar"], ["machines"], ["jerk"], ["axes"], ["interp"], ["planner"],
          ["scenario"], ["conveyor"], ["ipo"], ["tracking"], ["audit", "program"], ["channel"],
          ["runner", "report", "golden"], ["cli"]]
level = {room: k for k, rooms in enumerate(levels) for room in rooms}
include = re.compile(r'^#include "([a-z_]+)/')
upward = []
for f, v in lines.items():
    here = f.split("/")[0]
    if here not in level:
        continue
    for n, line in enumerate(v, 1):
        m = include.match(line)
        if not m or m.group(1) == here or m.group(1) not in level:
            continue
        if level[m.group(1)] >= level[here]:
            upward.append((f, n, m.group(1)))
print(f"includes of a room at or above the file's own: {len(upward)}")
for f, n, room in upward:
    print(f"  {f}:{n} includes {room}/")
