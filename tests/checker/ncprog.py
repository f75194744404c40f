"""The checker's own reader of the NC subset gen.py writes and the issue's reproductions use.

Per motion block: its source line, G00 or feed, the slope in force (#SLOPE), G261 / G260, the
stop at its end (G60, G09), #TRANSVELMIN, and its geometry (line, arc or helix in G17 XY /
G18 ZX / G19 YZ, centre by I/J/K relative to the start or by R: R > 0 the shorter arc, R < 0
the longer; isg-language.md §2 table "G02 / G03", "R") for the tangents at its ends.
Not a general NC interpreter: no variables, loops, subroutines or frames (gen.py writes none).
"""
from __future__ import annotations

import dataclasses
import math
import re

import numpy as np

SLOPES = {"STEP": 0, "TRAPEZ": 1, "SIN2": 2, "HSC": 1}
PLANES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}  # (u, v, normal) axis indices
WORD = re.compile(r"([A-Z])\s*=?\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)")


@dataclasses.dataclass
class Block:
    line: int                 # source line (1-based)
    rapid: bool               # G00
    slope: int                # 0 STEP, 1 TRAPEZ/HSC, 2 SIN2
    contour: bool             # G261 / G61 in force
    path_dev: float           # [mm]
    stop: bool                # G60 / G09 in this block: v = 0 at its end
    transvelmin: float | None # [mm/s]
    feed: float               # [mm/s]
    start: np.ndarray
    end: np.ndarray
    arc: dict | None = None   # plane, centre, ccw, sweep [rad], radius

    def length(self) -> float:
        if self.arc is None:
            return float(np.linalg.norm(self.end - self.start))
        u, v, n = PLANES[self.arc["plane"]]
        rise = self.end[n] - self.start[n]
        return math.hypot(self.arc["radius"] * self.arc["sweep"], rise)

    def tangent(self, at_end: bool) -> np.ndarray:
        """Unit tangent over X, Y, Z at the start or end (zero for a zero-length block)."""
        if self.arc is None:
            d = self.end - self.start
            n = np.linalg.norm(d)
            return d / n if n > 1e-12 else np.zeros(3)
        u, v, n = PLANES[self.arc["plane"]]
        p = self.end if at_end else self.start
        c = self.arc["centre"]
        ru, rv = p[u] - c[u], p[v] - c[v]
        sgn = 1.0 if self.arc["ccw"] else -1.0
        t = np.zeros(3)
        t[u], t[v] = -sgn * rv, sgn * ru          # |t_plane| = radius
        if self.arc["sweep"] > 0:
            t[n] = (self.end[n] - self.start[n]) / self.arc["sweep"]
        norm = np.linalg.norm(t)
        return t / norm if norm > 0 else t


def _arc(g, plane, start, end, words, centre_abs=False):
    u, v, n = PLANES[plane]
    ccw = g == 3
    if "R" in words:
        r = words["R"]
        du, dv = end[u] - start[u], end[v] - start[v]
        chord = math.hypot(du, dv)
        h = math.sqrt(max(r * r - chord * chord / 4.0, 0.0))
        mu, mv = (start[u] + end[u]) / 2, (start[v] + end[v]) / 2
        lu, lv = -dv / chord, du / chord          # left normal of the chord
        side = (1.0 if ccw else -1.0) * (1.0 if r > 0 else -1.0)
        centre = start.copy()
        centre[u], centre[v] = mu + side * h * lu, mv + side * h * lv
    else:
        centre = start.copy()
        for axis, letter in enumerate("IJK"):
            if letter in words:
                centre[axis] = start[axis] + words[letter]
    radius = math.hypot(start[u] - centre[u], start[v] - centre[v])
    a0 = math.atan2(start[v] - centre[v], start[u] - centre[u])
    a1 = math.atan2(end[v] - centre[v], end[u] - centre[u])
    sweep = (a1 - a0) if ccw else (a0 - a1)
    sweep %= 2 * math.pi
    if sweep < 1e-12:
        sweep = 2 * math.pi
    return {"plane": plane, "centre": centre, "ccw": ccw, "sweep": sweep, "radius": radius}


def read(path: str, start_slope: int = 0) -> list[Block]:
    """The motion blocks in execution order (the programs have no jumps)."""
    blocks = []
    pos = np.zeros(3)
    motion, plane, slope, contour, path_dev = 1, 17, start_slope, False, 1.0
    feed, transvelmin, incremental = 0.0, None, False
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for number, raw in enumerate(lines, start=1):
        text = re.sub(r"\(.*?\)", "", raw.split(";", 1)[0]).strip().upper()
        text = re.sub(r"^N\d+\s*", "", text)
        if not text or text.startswith("%"):
            continue
        if text.startswith("#"):
            if text.startswith("#SLOPE"):
                m = re.search(r"TYPE\s*=\s*(\w+)", text)
                slope = SLOPES[m.group(1)] if m else start_slope
                if "DEFAULT" in text:
                    slope = start_slope
            elif text.startswith("#CONTOUR MODE"):
                m = re.search(r"PATH_DEV\s*=\s*([-+.\deE]+)", text)
                if m:
                    path_dev = float(m.group(1))
            elif text.startswith("#TRANSVELMIN"):
                m = re.search(r"\[\s*([-+.\deE]+)\s*\]", text)
                transvelmin = float(m.group(1)) / 60.0 if ("ON" in text and m) else None
            continue
        words, gs = {}, []
        for letter, value in WORD.findall(text):
            if letter == "G":
                gs.append(int(float(value)))
            else:
                words[letter] = float(value)
        stop = False
        for g in gs:
            if g in (0, 1, 2, 3):
                motion = g
            elif g in PLANES:
                plane = g
            elif g in (60, 9):
                stop = True
            elif g in (61, 261):
                contour = True
            elif g == 260:
                contour = False
            elif g == 90:
                incremental = False
            elif g == 91:
                incremental = True
        if "F" in words:
            feed = words["F"] / 60.0
        if not any(a in words for a in "XYZ") and not (motion in (2, 3) and any(
                k in words for k in "IJK")):
            continue
        end = pos.copy()
        for axis, letter in enumerate("XYZ"):
            if letter in words:
                end[axis] = (pos[axis] if incremental else 0.0) + words[letter]
        arc = _arc(motion, plane, pos, end, words) if motion in (2, 3) else None
        blocks.append(Block(line=number, rapid=motion == 0, slope=slope, contour=contour,
                            path_dev=path_dev, stop=stop, transvelmin=transvelmin,
                            feed=feed, start=pos.copy(), end=end, arc=arc))
        pos = end
    return blocks
