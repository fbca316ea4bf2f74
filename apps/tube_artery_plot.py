#!/usr/bin/env python3
"""Plots of a tube_artery_study run (docs/tube-artery.md): pressure (mmHg) and flow (ml/s) over the last,
periodic cycle at inlet, middle and outlet of the carotid; and the cycle-to-cycle change against the cycle.

Usage: tube_artery_plot.py OUTPUT_DIR   (reads tube_artery_waveforms.csv, tube_artery_cycles.csv;
                                          writes tube_artery_waveforms.png there)
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import script_args  # noqa: E402

MMHG = 133.322
PROBES = (("in", "inlet (s = 0)", "tab:red"), ("mid", "middle (s = L/2)", "tab:green"),
          ("out", "outlet (s = L)", "tab:blue"))


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(out):
    waves = read(script_args.input_file(out, "tube_artery_waveforms.csv"))
    cycles = read(script_args.input_file(out, "tube_artery_cycles.csv"))
    t = [float(r["t_s"]) for r in waves]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for key, label, colour in PROBES:
        axes[0].plot(t, [float(r[f"p_{key}_Pa"]) / MMHG for r in waves], color=colour, label=label)
        axes[1].plot(t, [float(r[f"Q_{key}_m3s"]) * 1e6 for r in waves], color=colour, label=label)
    axes[0].set(xlabel="t in cycle (s)", ylabel="p - p_ext (mmHg)", title="carotid: pressure, periodic cycle")
    axes[1].set(xlabel="t in cycle (s)", ylabel="Q (ml/s)", title="flow")
    for ax in axes[:2]:
        ax.legend()
        ax.grid(alpha=0.3)
    m = [int(r["cycle"]) for r in cycles[1:]]
    axes[2].semilogy(m, [float(r["change_p"]) for r in cycles[1:]], "o-", label="pressure")
    axes[2].semilogy(m, [float(r["change_Q"]) for r in cycles[1:]], "s-", label="flow")
    axes[2].axhline(1e-3, color="0.5", ls="--", label="1e-3 criterion")
    axes[2].set(xlabel="cycle", ylabel="max |x_m - x_(m-1)| / max |x_m|", title="approach to periodicity")
    axes[2].legend()
    axes[2].grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "tube_artery_waveforms.png"), dpi=120)


if __name__ == "__main__":
    args = script_args.positional(0, "usage: tube_artery_plot.py [OUTPUT_DIR]   (default output/tube_artery)", 1)
    main(args[0] if args else "output/tube_artery")
