#!/usr/bin/env python3
"""Energy of a free gas-filled tube against the step (docs/tube-gas-rod.md) from apps/tube_gas_rod_study's CSV.

    python3 apps/tube_gas_rod_study_plot.py [dir=.]  ->  dir/tube_gas_rod_energy.png
"""
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import script_args  # noqa: E402


def main():
    args = script_args.positional(0, "usage: tube_gas_rod_study_plot.py [OUTPUT_DIR]   (default .)", 1)
    d = args[0] if args else "."
    with open(script_args.input_file(d, "tube_gas_rod_energy.csv")) as f:
        rows = list(csv.DictReader(f))
    runs = {}
    for r in rows:
        runs.setdefault(r["cfl"], ([], []))
        runs[r["cfl"]][0].append(float(r["t"]))
        runs[r["cfl"]][1].append(float(r["energy_error"]))
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    cfls, worst = [], []
    for cfl, (t, e) in sorted(runs.items(), reverse=True):
        a.plot(t, e, label=f"cfl {cfl} (rod sub-steps scaled alike)")
        cfls.append(float(cfl))
        worst.append(max(abs(x) for x in e))
    a.axhline(0.0, color="grey", lw=0.5)
    a.set_xlabel("t")
    a.set_ylabel(r"$E(t)/E(0) - 1$ (rod + gas)")
    a.set_title("soft free tube, Sod inside, 100 segments", fontsize=9)
    a.legend(fontsize=8)
    b.loglog(cfls, worst, "o-", label="max |E/E0 - 1| over the run")
    b.loglog(cfls, [worst[0] * (c / cfls[0]) ** 2 for c in cfls], "k--", label="slope 2")
    b.set_xlabel("step (cfl number)")
    b.set_ylabel("max energy error")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{d}/tube_gas_rod_energy.png", dpi=120)


if __name__ == "__main__":
    main()
