#!/usr/bin/env python3
"""Step throughput against mesh size from unilag_bench_portable's CSVs (apps/bench_portable.cpp):
`apps/portable_bench_plot.py OUT.csv IN.csv...` concatenates the inputs into OUT.csv and draws OUT.png, the hydro
rows, one line per backend, dimension and numbering (cells per second of the first-order step, and of the order-2
gradients dashed)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(out, inputs):
    rows = []
    for name in inputs:
        with open(name, newline="") as f:
            rows.extend(csv.DictReader(f))
    if not rows:
        sys.exit("portable_bench_plot.py: no rows in " + " ".join(inputs))
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    rows = [r for r in rows if r.get("physics", "hydro") == "hydro"]  # the variants: docs/parallel.md 7's table
    lines = sorted({(r["backend"], r["concurrency"], r["dim"], r["shuffled"]) for r in rows})
    for backend, conc, dim, shuffled in lines:
        sel = sorted((r for r in rows if (r["backend"], r["concurrency"], r["dim"], r["shuffled"]) ==
                      (backend, conc, dim, shuffled)), key=lambda r: int(r["cells"]))
        cells = [int(r["cells"]) for r in sel]
        label = f"{backend} ({'GPU' if backend == 'Cuda' else conc + ' threads'}), {dim}D" + \
            (", shuffled" if shuffled == "1" else "")
        style = dict(marker="o" if dim == "2" else "s", linestyle=":" if shuffled == "1" else "-")
        line, = ax.plot(cells, [float(r["step_cells_per_s"]) for r in sel], label=label, **style)
        if shuffled == "0":
            ax.plot(cells, [int(r["cells"]) / float(r["gradients_s"]) for r in sel], color=line.get_color(),
                    linestyle="--", marker=style["marker"], markerfacecolor="none", alpha=0.6)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cells")
    ax.set_ylabel("cell-steps/s (solid: order-1 step; dashed: order-2 gradients)")
    ax.set_title("unilag_bench_portable: one rank, generated meshes")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    png = out.rsplit(".", 1)[0] + ".png"
    fig.savefig(png, dpi=120)
    print("wrote", out, "and", png)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
