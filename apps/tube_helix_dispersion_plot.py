#!/usr/bin/env python3
"""Plots of a tube_helix_dispersion run (docs/tube-helix.md 5): for each model, Re omega and Im omega against k
(rows) at u = 0 and u = 2 (columns), one colour per case (K = 0 at p0 = 0, K = 0 without base force, K = 0.5, 1);
and the largest growth rate against u. Convention: exp(i (omega t - k s)); unstable where Im omega < 0.

Usage: tube_helix_dispersion_plot.py OUTPUT_DIR   (writes dispersion_<model>.png, stability.png there)
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import script_args  # noqa: E402

COLOURS = {"K0_p0": "tab:red", "K0_f0": "0.4", "K0.5": "tab:blue", "K1": "tab:green"}
LABELS = {"K0_p0": "K = 0, p0 = 0", "K0_f0": "K = 0, f0 = 0", "K0.5": "K = 0.5", "K1": "K = 1"}


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def dispersion(rows, model, out):
    fig, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    for col, u in enumerate(("0", "2")):
        for case, colour in COLOURS.items():
            pts = [r for r in rows if r["model"] == model and r["case"] == case and float(r["u"]) == float(u)]
            if not pts or (u == "0" and case == "K0_f0"):
                continue
            k = [float(r["k"]) for r in pts]
            axes[0][col].plot(k, [float(r["re_omega"]) for r in pts], ".", ms=1.5, color=colour, label=LABELS[case])
            axes[1][col].plot(k, [float(r["im_omega"]) for r in pts], ".", ms=1.5, color=colour)
        axes[0][col].set_title(f"{model}, beta = 0.2, kappa = pi/4, u = {u}")
        axes[0][col].set_ylim(-60, 60)
        axes[0][col].set_ylabel("Re omega")
        axes[1][col].set_ylabel("Im omega (< 0: unstable)")
        axes[1][col].set_xlabel("k")
        for ax in (axes[0][col], axes[1][col]):
            ax.grid(alpha=0.3)
    axes[0][1].legend(markerscale=6, fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"dispersion_{model}.png"), dpi=120)
    plt.close(fig)


def stability(rows, out):
    fig, ax = plt.subplots(figsize=(6, 4))
    for model, style in (("geometric", "-"), ("inextensible", "--")):
        for case, colour in COLOURS.items():
            pts = [r for r in rows if r["model"] == model and r["case"] == case]
            ax.plot([float(r["u"]) for r in pts], [float(r["max_growth"]) for r in pts], style, color=colour,
                    label=f"{model}, {LABELS[case]}")
    ax.set_xlabel("u")
    ax.set_ylabel("max over |k| <= 12 of -Im omega")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stability.png"), dpi=120)
    plt.close(fig)


def main():
    out = script_args.positional(1, __doc__)[0]
    rows = read(script_args.input_file(out, "dispersion.csv"))
    for model in ("geometric", "inextensible"):
        dispersion(rows, model, out)
    stability(read(script_args.input_file(out, "stability.csv")), out)


if __name__ == "__main__":
    main()
