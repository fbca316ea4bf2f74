#!/usr/bin/env python3
"""Figures of the gas-in-tube study (docs/tube-gas.md 4) from apps/tube_shock_study's CSVs.

    python3 apps/tube_shock_study_plot.py [dir=.]   ->  dir/tube_shock_mach.png, dir/tube_sod_profile.png
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
    args = script_args.positional(0, "usage: tube_shock_study_plot.py [OUTPUT_DIR]   (default .)", 1)
    d = args[0] if args else "."
    m = read(script_args.input_file(d, "tube_shock_mach.csv"))
    ratios = [1 + i * 0.05 for i in range(int(49 / 0.05) + 1)]
    relation = [math.sqrt(1 + (GAMMA + 1) / (2 * GAMMA) * (r - 1)) for r in ratios]
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot(ratios, relation, "k-", label=r"$M_s=\sqrt{1+\frac{\gamma+1}{2\gamma}(p_2/p_1-1)}$ (tube.md 3)")
    a.plot(m["pressure_ratio"], m["mach_400"], "o", mfc="none", label="TubeGas, 400 cells")
    a.set_xscale("log")
    a.set_xlabel("$p_2/p_1$")
    a.set_ylabel("shock Mach number $M_s = c/a_1$")
    a.legend(fontsize=8)
    a.grid(alpha=0.3)
    b.semilogx(m["pressure_ratio"], [abs(x) for x in m["rel_error_200"]], "s-", label="200 cells")
    b.semilogx(m["pressure_ratio"], [abs(x) for x in m["rel_error_400"]], "o-", label="400 cells")
    b.set_yscale("log")
    b.set_xlabel("$p_2/p_1$")
    b.set_ylabel("|measured / relation - 1|")
    b.legend(fontsize=8)
    b.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(f"{d}/tube_shock_mach.png", dpi=120)

    s = read(script_args.input_file(d, "tube_sod_profile.csv"))
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.5))
    for ax, k in zip(axes, ["rho", "u", "p"]):
        ax.plot(s["s"], s[k + "_exact"], "k-", lw=1, label="exact")
        ax.plot(s["s"], s[k], ".", ms=3, label="TubeGas, 200 cells")
        ax.set_xlabel("s")
        ax.set_title(k)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{d}/tube_sod_profile.png", dpi=120)


if __name__ == "__main__":
    main()
