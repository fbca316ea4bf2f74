#!/usr/bin/env python3
"""Studies of the geometric tube model (docs/tube-model.md 7), each a series of `unilag run` on the talk's rubber
tube (inputs/tube_rubber_geometric.yaml, tube.md 2.2), written as CSV + PNG into the output folder:

  slenderness  u_cf against L / r_g at the tube's own beta (0.36), K = 0, with the Euler-Bernoulli value
               (inputs/tube_rubber.yaml) as a line: slenderness.csv, slenderness.png
  area_change  the critical speed (m/s) and frequency against K / R^2 (R = 5 mm, the outer radius), L = 1 m,
               dynamic-pressure loading, with K = 0 as a dashed line: area_change.csv, area_change.png

Every run goes through the CLI with --check (the onset recomputed on a twice finer discretisation, 1e-3), at
40 elements (24 modes), else 80 (36), else 160 (48): the first that passes (column 'check': failed if none).
Usage: tube_geometric_studies.py {slenderness|area_change} [--output DIR] [--unilag BIN]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GEOMETRIC = os.path.join(ROOT, "inputs", "tube_rubber_geometric.yaml")
EULER_BERNOULLI = os.path.join(ROOT, "inputs", "tube_rubber.yaml")
SLENDERNESS = [5, 10, 20, 30, 50, 100, 200, 300, 1000]
# K / R^2: u_cf rises steeply and the tube no longer flutters from 0.0325 (measured: 19.9 m/s at 0.03; speed_max u = 60)
AREA_CHANGE = [0.0, 0.0025, 0.005, 0.0075, 0.01, 0.0125, 0.015, 0.0175, 0.02, 0.0225, 0.025, 0.0275, 0.03, 0.0325,
               0.035, 0.0375, 0.04, 0.05, 0.075, 0.1]


# (elements, modes) tried in turn until --check passes: a stubby tube needs the finer ones
RESOLUTIONS = [(40, 24), (80, 36), (160, 48)]


def run(unilag, scene, folder, sets):
    """`unilag run --check` at the first resolution that passes the check; returns the stability.csv row (with the
    resolution used) and summary.json."""
    for elements, modes in RESOLUTIONS:
        command = [unilag, "run", scene, "--check", "--output", folder, "--set", "output.plot=false",
                   "--set", f"stability.elements={elements}", "--set", f"stability.modes={modes}"]
        if scene == EULER_BERNOULLI:
            command[-1] = "stability.modes=16"
        for s in sets:
            command += ["--set", s]
        done = subprocess.run(command, capture_output=True, text=True)
        converged = done.returncode == 0
        if done.returncode == 3:
            print(done.stderr.strip())
            if (elements, modes) != RESOLUTIONS[-1]:
                continue
        elif done.returncode != 0:
            sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
        with open(os.path.join(folder, "stability.csv")) as f:
            row = next(csv.DictReader(f))
        row["elements"] = elements
        row["check"] = "passed" if converged else "failed"
        with open(os.path.join(folder, "summary.json")) as f:
            return row, json.load(f)


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    print("wrote", path)


def slenderness(unilag, out):
    eb_row, _ = run(unilag, EULER_BERNOULLI, os.path.join(out, "runs", "euler_bernoulli"), [])
    u_eb = float(eb_row["u_cf"])
    _, summary = run(unilag, GEOMETRIC, os.path.join(out, "runs", "probe"),
                     ["tube.area_change=0.0", "stability.speed_max=12.0"])
    r_g = summary["geometric"]["radius_of_gyration"]
    rows = []
    for s in SLENDERNESS:
        length = s * r_g
        row, summary = run(unilag, GEOMETRIC, os.path.join(out, "runs", f"slenderness_{s}"),
                           ["tube.area_change=0.0", f"tube.length={length!r}", "stability.speed_max=12.0"])
        u = float(row["u_cf"])
        g = summary["geometric"]
        rows.append([s, length, g["shear"], g["extension"], g["rotary_inertia"], row["elements"], u, row["omega_cf"],
                     row["mode"], row["check"], u_eb, 100.0 * (u / u_eb - 1.0)])
        print(f"L/r_g {s:5g}: u_cf {u:.6f} ({rows[-1][-1]:+.3f}% vs EB {u_eb:.6f}), mode {row['mode']}")
    write_csv(os.path.join(out, "slenderness.csv"),
              ["slenderness", "length_m", "shear", "extension", "rotary_inertia", "elements", "u_cf", "omega_cf", "mode",
               "check", "u_cf_euler_bernoulli", "change_percent"], rows)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogx([r[0] for r in rows], [r[6] for r in rows], "o-", label="geometric model (K = 0)")
    ax.axhline(u_eb, color="k", ls="--", lw=1, label=f"Euler-Bernoulli {u_eb:.4f}")
    ax.set_xlabel(r"slenderness $L / r_g$")
    ax.set_ylabel(r"critical flow speed $u_{cf}$")
    ax.set_title(rf"cantilever, rubber tube, $\beta$ = {float(eb_row['beta']):.2f}")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "slenderness.png"), dpi=120)
    print("wrote", os.path.join(out, "slenderness.png"))


def area_change(unilag, out):
    rows = []
    for k in AREA_CHANGE:
        row, summary = run(unilag, GEOMETRIC, os.path.join(out, "runs", f"k_{k}"), [f"tube.area_change={k * 25e-6!r}"])
        omega = float(row["omega_cf"]) / summary["physical"]["time_scale"]  # rad/s
        rows.append([k, k * 25e-6, row["u_cf"], row["U_cf_m_per_s"], omega, row["f_cf_hz"], row["mode"],
                     row["instability"], row["elements"], row["check"]])
        print(f"K = {k:g} R^2: U_cf {row['U_cf_m_per_s']} m/s, omega {omega:.4g} 1/s, mode {row['mode']}")
    write_csv(os.path.join(out, "area_change.csv"),
              ["K_over_R2", "K_m2", "u_cf", "U_cf_m_per_s", "omega_cf_rad_per_s", "f_cf_hz", "mode", "instability",
               "elements", "check"],
              rows)
    k = [r[0] for r in rows]
    speed = [float(r[3]) for r in rows]
    omega = [float(r[4]) for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, values, label in ((axes[0], speed, "critical speed $U_{cf}$ (m/s)"),
                              (axes[1], omega, r"critical frequency $\omega_{cf}$ (1/s)")):
        ax.plot(k, values, "o-", label="K > 0")
        ax.axhline(values[0], color="k", ls="--", lw=1, label="K = 0")
        stable = [x for x, v in zip(k, values) if not math.isfinite(v)]
        if stable:
            ax.axvspan(min(stable), max(k), color="0.9", label="no flutter up to u = 60")
        ax.set_xlabel(r"area change $K / R^2$ (R = 5 mm)")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("rubber tube, 1 m, geometric model, dynamic-pressure loading of the area change")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "area_change.png"), dpi=120)
    print("wrote", os.path.join(out, "area_change.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=["slenderness", "area_change"])
    parser.add_argument("--output", help="folder (default output/tube_<study>)")
    parser.add_argument("--unilag", default=os.path.join(ROOT, "build", "release", "apps", "unilag"))
    args = parser.parse_args()
    out = args.output or os.path.join("output", f"tube_{args.study}")
    os.makedirs(out, exist_ok=True)
    (slenderness if args.study == "slenderness" else area_change)(args.unilag, out)


if __name__ == "__main__":
    main()
