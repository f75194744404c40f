"""The machine folder's ISG parameter lists, read by the checker itself (no ncsim code).

A machine folder holds `machine.lis` (`channel FILE`, `axis NAME FILE`, paths relative to the
folder) and one list per channel and axis: `key value` lines, `#` comments and a trailing
`#` or `(` comment after the value (docs/machines.md "List syntax"). From them, per axis, the
limits the checker holds each cycle against, in mm, s:

  v_max    P-AXIS-00212 getriebe[0].dynamik.vb_max [um/s] x 1e-3           (feed cycles)
  v_rapid  min(P-AXIS-00209 getriebe[0].vb_eilgang [um/s] x 1e-3, v_max)   (G00 cycles, 000 l.360)
  a_up     A+  min(P-AXIS-00001 slope_profil.a_beschl, P-AXIS-00008 dynamik.a_max)
  a_down   |A-| min(P-AXIS-00002 slope_profil.a_brems, P-AXIS-00008)
  a_rapid  min(P-AXIS-00004 slope_profil.a_grenz, P-AXIS-00008), both ways (G00)
  j        min over the four feed ramps of a / t_ramp (P-AXIS-00195..00198; a ramp time is the
           time in which the acceleration is built up or taken down, so j = a / t), each ramp
           time at least P-AXIS-00201 dynamik.tr_min
  j_rapid  a_rapid / max(P-AXIS-00200 tr_grenz, tr_min)
  c0       nci.velo_jump_factor (000 l.108's C0[i], NCSIM-AXIS-020)
Channel: the cycle T (ncsim.cycle_time [us], NCSIM-CHAN-610), P-CHAN-00009 corr_v_trans_jerk
(ncsim's default 1), the start slope P-CHAN-00071. Defaults are the TF5200 defaults of the table
in docs/machines.md.
"""
from __future__ import annotations

import dataclasses
import os
import re

AXIS_DEFAULTS = {
    "getriebe[0].dynamik.vb_max": 200000.0,
    "getriebe[0].vb_eilgang": 166666.0,
    "getriebe[0].dynamik.a_max": 1000.0,
    "getriebe[0].slope_profil.a_beschl": 1000.0,
    "getriebe[0].slope_profil.a_brems": 1000.0,
    "getriebe[0].slope_profil.a_grenz": 1000.0,
    "getriebe[0].slope_profil.tr_beschl_zu": 50000.0,
    "getriebe[0].slope_profil.tr_beschl_ab": 50000.0,
    "getriebe[0].slope_profil.tr_brems_zu": 50000.0,
    "getriebe[0].slope_profil.tr_brems_ab": 50000.0,
    "getriebe[0].slope_profil.tr_grenz": 10000.0,
    "getriebe[0].dynamik.tr_min": 10000.0,
    "nci.velo_jump_factor": 1.0,
}
CHANNEL_DEFAULTS = {
    "ncsim.cycle_time": 1000.0,
    "corr_v_trans_jerk": 1.0,
    "prog_start.slope.profile": 0.0,
    "ncsim.path_override_type": "REDUCED",
}


def read_list(path: str) -> dict:
    """key -> value text of one list (the last line of a key wins)."""
    values = {}
    with open(path, encoding="utf-8-sig") as f:
        for raw in f:
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            parts = line.split(None, 1)
            if len(parts) < 2:
                continue
            key, rest = parts
            value = re.split(r"\s*[#(]", rest, maxsplit=1)[0].strip()
            values[key] = value
    return values


def number(text: str) -> float:
    text = text.strip()
    return float(int(text, 16)) if text.lower().startswith("0x") else float(text)


@dataclasses.dataclass(frozen=True)
class AxisLimits:
    name: str
    v_max: float    # [mm/s]
    v_rapid: float  # [mm/s]
    a_up: float     # A+ [mm/s^2]
    a_down: float   # |A-| [mm/s^2]
    a_rapid: float  # [mm/s^2]
    j: float        # [mm/s^3]
    j_rapid: float  # [mm/s^3]
    c0: float       # VELOJUMP factor

    def velojump(self, t_cycle: float) -> float:
        """000 l.108: v_jump[i] = C0[i] * min(A+[i], -A-[i]) * T [mm/s]."""
        return self.c0 * min(self.a_up, self.a_down) * t_cycle


@dataclasses.dataclass(frozen=True)
class Machine:
    folder: str
    axes: tuple          # AxisLimits in machine.lis order (= CSV column order)
    t_cycle: float       # [s]
    corr_v_trans_jerk: bool
    start_slope: int     # 0 STEP, 1 TRAPEZ, 2 SIN2
    override_type: str


def axis_limits(name: str, values: dict) -> AxisLimits:
    def get(key):
        return number(values[key]) if key in values else AXIS_DEFAULTS[key]

    a_max = get("getriebe[0].dynamik.a_max")
    v_max = get("getriebe[0].dynamik.vb_max") * 1e-3
    a_up = min(get("getriebe[0].slope_profil.a_beschl"), a_max)
    a_down = min(get("getriebe[0].slope_profil.a_brems"), a_max)
    a_rapid = min(get("getriebe[0].slope_profil.a_grenz"), a_max)
    tr_min = get("getriebe[0].dynamik.tr_min")

    def ramp(key):  # [s], never below P-AXIS-00201
        return max(get(key), tr_min) * 1e-6

    j = min(a_up / ramp("getriebe[0].slope_profil.tr_beschl_zu"),
            a_up / ramp("getriebe[0].slope_profil.tr_beschl_ab"),
            a_down / ramp("getriebe[0].slope_profil.tr_brems_zu"),
            a_down / ramp("getriebe[0].slope_profil.tr_brems_ab"))
    return AxisLimits(
        name=name, v_max=v_max,
        v_rapid=min(get("getriebe[0].vb_eilgang") * 1e-3, v_max),
        a_up=a_up, a_down=a_down, a_rapid=a_rapid, j=j,
        j_rapid=a_rapid / ramp("getriebe[0].slope_profil.tr_grenz"),
        c0=get("nci.velo_jump_factor"))


def index(folder: str):
    """(channel file, [(axis name, axis file)]) of machine.lis, paths absolute."""
    channel, axes = None, []
    with open(os.path.join(folder, "machine.lis"), encoding="utf-8-sig") as f:
        for raw in f:
            words = raw.split("#", 1)[0].split()
            if len(words) >= 2 and words[0] == "channel":
                channel = os.path.join(folder, words[1])
            elif len(words) >= 3 and words[0] == "axis":
                axes.append((words[1], os.path.join(folder, words[2])))
    return channel, axes


def load(folder: str) -> Machine:
    channel_file, axis_files = index(folder)
    ch = dict(CHANNEL_DEFAULTS)
    if channel_file:
        ch.update(read_list(channel_file))
    axes = tuple(axis_limits(name, read_list(path)) for name, path in axis_files)
    return Machine(
        folder=folder, axes=axes,
        t_cycle=number(str(ch["ncsim.cycle_time"])) * 1e-6,
        corr_v_trans_jerk=number(str(ch["corr_v_trans_jerk"])) != 0,
        start_slope=int(number(str(ch["prog_start.slope.profile"]))),
        override_type=str(ch["ncsim.path_override_type"]))
