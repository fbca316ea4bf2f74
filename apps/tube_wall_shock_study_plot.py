#!/usr/bin/env python3
"""Figures of the shock in a latex-like gas-filled tube (docs/tube-wall.md 4) from apps/tube_wall_shock_study's CSVs.

    python3 apps/tube_wall_shock_study_plot.py [dir=.]  ->  dir/tube_wall_shock_mach.png, dir/tube_wall_shock_profile.png
"""
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import script_args  # noqa: E402

GAMMA = 1.4


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    args = script_args.positional(0, "usage: tube_wall_shock_study_plot.py [OUTPUT_DIR]   (default .)", 1)
    d = args[0] if args else "."
    m = read(script_args.input_file(d, "tube_wall_shock_mach.csv"))
    ratios = [1 + i * 0.01 for i in range(int(max(m["p2_over_p1"]) * 100) - 99)]
    rigid = [math.sqrt(1 + (GAMMA + 1) / (2 * GAMMA) * (r - 1)) for r in ratios]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(ratios, rigid, "k-", label="rigid tube: normal-shock relation (tube.md 3)")
    ax.plot(m["p2_over_p1"], m["mach_a1"], "o-", label=r"latex tube, $U_s/a_1$ (gas sound speed)")
    ax.plot(m["p2_over_p1"], m["mach_c1"], "s-", label=r"latex tube, $U_s/c_1$ (compliant speed)")
    ax.axhline(1.0, color="grey", lw=0.5)
    ax.set_xlabel(r"shock strength $p_2/p_1$")
    ax.set_ylabel("shock Mach number")
    ax.set_title("E 1 MPa, h 1 mm, R0 5 mm, air at p_ext", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{d}/tube_wall_shock_mach.png", dpi=120)

    p = read(f"{d}/tube_wall_shock_profile.csv")
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    a.plot(p["s"], [x / 1e5 for x in p["p"]])
    a.set_ylabel("p (bar)")
    b.plot(p["s"], [x * 1e3 for x in p["R"]])
    b.set_ylabel("R (mm)")
    b.set_xlabel("s (m)")
    a.set_title("p4/p1 = 2, closed latex tube, end of the run", fontsize=9)
    fig.tight_layout()
    fig.savefig(f"{d}/tube_wall_shock_profile.png", dpi=120)


if __name__ == "__main__":
    main()
