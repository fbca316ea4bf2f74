#!/usr/bin/env python3
"""stability.png of a tube stability run: u_cf(beta) (first panel) and, one panel per beta, the Argand loci of
the lowest modes, Im(omega) against Re(omega) as u grows from 0 (dot) to 1.25 u_cf, from stability.csv and
stability_loci.csv in the folder given.

Convention (docs/tube-model.md 4): eta ~ exp(i omega tau); a mode is unstable where Im(omega) < 0.
Usage: tube_stability_plot.py OUTPUT_DIR
"""
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import script_args  # noqa: E402


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def plot_critical_speed(ax, rows):
    beta = [float(r["beta"]) for r in rows]
    ucf = [float(r["u_cf"]) for r in rows]
    ax.plot(beta, ucf, "-", color="0.6", lw=1)
    for kind, marker in (("flutter", "o"), ("divergence", "s")):
        pts = [(b, u) for b, u, r in zip(beta, ucf, rows) if r["instability"] == kind]
        if pts:
            ax.plot(*zip(*pts), marker, ms=5, label=kind)
    ax.set_xlabel(r"mass ratio $\beta$")
    ax.set_ylabel(r"critical flow speed $u_{cf}$")
    ax.set_title("first instability")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)


def plot_loci(ax, rows, beta, ucf):
    """Im(omega) against Re(omega) of each tracked mode as u grows, the onset marked."""
    modes = sum(1 for k in rows[0] if k.startswith("re_omega_"))
    for m in range(1, modes + 1):
        pts = [(float(r[f"re_omega_{m}"]), float(r[f"im_omega_{m}"])) for r in rows]
        pts = [(x, y) for x, y in pts if math.isfinite(x) and math.isfinite(y)]
        if pts:
            ax.plot(*zip(*pts), "-", lw=1.2, label=f"mode {m}")
            ax.plot(*pts[0], "k.", ms=4)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_title(rf"$\beta$ = {beta:g}, u to {float(rows[-1]['u']):.3g}" +
                 (rf" ($u_{{cf}}$ = {ucf:.4g})" if math.isfinite(ucf) else ""), fontsize=9)
    ax.set_xlabel(r"Re $\omega$", fontsize=8)
    ax.set_ylabel(r"Im $\omega$ (unstable < 0)", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.grid(alpha=0.3)


def main():
    folder = script_args.positional(1, "usage: tube_stability_plot.py OUTPUT_DIR   (a tube stability run's folder)")[0]
    rows = read_csv(script_args.input_file(folder, "stability.csv"))
    loci = read_csv(script_args.input_file(folder, "stability_loci.csv"))
    betas = [float(r["beta"]) for r in rows]
    panels = 1 + len(betas)
    cols = min(4, panels)
    lines = (panels + cols - 1) // cols
    fig, axes = plt.subplots(lines, cols, figsize=(3.6 * cols, 3.2 * lines), squeeze=False)
    axes = axes.ravel()
    plot_critical_speed(axes[0], rows)
    for i, (beta, row) in enumerate(zip(betas, rows)):
        plot_loci(axes[1 + i], [r for r in loci if float(r["beta"]) == beta], beta, float(row["u_cf"]))
    axes[1].legend(fontsize=7)
    for ax in axes[panels:]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(f"{folder}/stability.png", dpi=110)


if __name__ == "__main__":
    main()
