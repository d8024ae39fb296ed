#!/usr/bin/python3
"""doc/figures/ironing_force_ratio.png: the ironing benchmark's reaction
ratio |F_x| / |F_z| against the die's slide, for the mortar pair
(parameter_files/ironing.prm, the die's driving condition press_force_*,
and the pair's own tangential / normal force) and the node-to-surface
variant (parameter_files/ironing_rigid_die.prm, the rigid cylinder's
die_force_*). Lower panel: in steady sliding (slide >= 1.5, as
tests/model/ironing.sh), each ratio less its least-squares cubic in the
slide, in % of its mean: the oscillation without the smooth drift.

    /usr/bin/python3 doc/scripts/ironing_figure.py MORTAR_CSV RIGID_CSV PNG \
        [STEADY SLAB_LENGTH]

STEADY (default 1.5) is the slide from which the lower panel is drawn;
benchmarks/ironing.sh with its longer slab (SLAB_LENGTH 18, default 9)
measures from a slide of 3.0 (doc/figures/ironing_force_ratio_long.png).

MORTAR_CSV and RIGID_CSV are the runs' time_history.csv (e.g. from
tests/model/ironing.sh, which leaves ironing/time_history.csv and
ironing_rigid_die/time_history.csv in its build directory). Needs
matplotlib (Debian: python3-matplotlib).
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

T1, T2, SLIDE, MU = 0.2, 1.5, 4.0, 0.3  # the load path of both .prm files
STEADY = 1.5  # slide from which tests/model/ironing.sh measures


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def slide(t):
    return SLIDE * (t - T1) / (T2 - T1)


def series(rows, fx, fz):
    s, r = [], []
    for row in rows:
        t = float(row["time"])
        if t > T1 + 1e-9 and float(row[fz]) != 0.0:
            s.append(slide(t))
            r.append(abs(float(row[fx])) / abs(float(row[fz])))
    return s, r


def detrended(s, r, steady):
    s, r = np.array(s), np.array(r)
    keep = s >= steady - 1e-9
    s, r = s[keep], r[keep]
    trend = np.polyval(np.polyfit(s - 2.44, r, 3), s - 2.44)
    return s, 100 * (r - trend) / r.mean()


def main():
    mortar, rigid, png = sys.argv[1:4]
    steady = float(sys.argv[4]) if len(sys.argv) > 4 else STEADY
    length = sys.argv[5] if len(sys.argv) > 5 else "9"
    m, g = read(mortar), read(rigid)
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True,
                                 gridspec_kw={"height_ratios": [2, 1]})
    ax.axhline(MU, color="0.6", lw=0.8, ls="--", label="mu = 0.3")
    sg, rg = series(g, "die_force_x", "die_force_z")
    ax.plot(sg, rg, color="tab:red", lw=1.2,
            label="node-to-surface, rigid cylinder: |F_x| / |F_z|")
    sm, rm = series(m, "press_force_x", "press_force_z")
    ax.plot(sm, rm, color="tab:blue", lw=1.6,
            label="mortar pair, die's reaction: |F_x| / |F_z|")
    s, r = series(m, "ironing_tangential_force", "ironing_normal_force")
    ax.plot(s, r, color="tab:blue", lw=1.0, ls=":",
            label="mortar pair: tangential / normal contact force")
    ax.axvline(steady, color="0.6", lw=0.8, ls=":")
    ax.set_ylabel("force ratio (-)")
    ax.set_title("Ironing (Puso & Laursen 2004), plane strain, mu = 0.3:\n"
                 "die pressed 1.4 into a neo-Hookean slab " + length +
                 " long, then slid")
    ax.grid(True, lw=0.3)
    ax.legend(loc="lower right", fontsize=9)
    s, e = detrended(sg, rg, steady)
    bx.plot(s, e, color="tab:red", lw=1.0, marker=".", ms=3,
            label="node-to-surface")
    s, e = detrended(sm, rm, steady)
    bx.plot(s, e, color="tab:blue", lw=1.4, marker=".", ms=3,
            label="mortar")
    bx.set_xlabel("slide of the die (mm)")
    bx.set_ylabel("|F_x| / |F_z| less its cubic\ntrend (% of the mean)")
    bx.set_xlim(0, max(sm[-1], sg[-1]) + 0.1)
    bx.grid(True, lw=0.3)
    bx.legend(loc="lower right", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
