#!/usr/bin/env python3
"""Nonlinear flutter of a cantilevered tube conveying fluid: `unilag run SCENE` (a tube scene with a `dynamics:`
section) at several flow speeds u / u_cf (dynamics.flow.critical_fraction), then, in OUT:
  flutter.csv  u_over_u_cf, u, growth rate fitted on the tip's peaks and the linear one (per tau, tube.md 2.1),
               frequency, the last tip amplitude and whether it had saturated (a limit cycle)
  flutter.png  growth rate against u/u_cf (nonlinear dots, linear line) and the limit-cycle tip amplitude against
               u - u_cf
A run counts as saturated when its tip amplitude over the last tenth of the run is within 5% of that over the
tenth before. Usage:
  tube_flutter_study.py UNILAG SCENE OUT --fractions 0.98,1.02,1.1,1.2 [--end-time T] [--fit-from F]
                        [--set key=value ...]
The growth rate is fitted on the linear phase (tip amplitude below dynamics.fit_below = 1% of the length by
default), the amplitude on the last tenth of the run.
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


def tip_saturation(folder):
    """The tip amplitude over the last tenth of the run, and its ratio to that over the tenth before."""
    with open(os.path.join(folder, "tip.csv")) as f:
        rows = [(float(r["t"]), float(r["distance"])) for r in csv.DictReader(f)]
    end = rows[-1][0]
    last = max(d for t, d in rows if t >= 0.9 * end)
    before = max(d for t, d in rows if 0.8 * end <= t < 0.9 * end)
    return last, last / before if before > 0 else float("inf")


def run_one(args, fraction):
    folder = os.path.join(args.out, "u%.4f" % fraction)
    cmd = [args.unilag, "run", args.scene, "--output", folder, "--set",
           "dynamics.flow.critical_fraction=%r" % fraction]
    if args.end_time is not None:
        cmd += ["--set", "dynamics.end_time=%r" % args.end_time]
    if args.fit_from is not None:  # else the scene's own, so that a fraction's figures are the scene's run
        cmd += ["--set", "dynamics.fit_from=%r" % args.fit_from]
    for s in args.set:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(folder, "summary.json")) as f:
        s = json.load(f)
    amplitude, ratio = tip_saturation(folder)
    for key in ("growth_rate_dimensionless", "frequency_dimensionless"):  # null: no fit (too few peaks)
        s[key] = float("nan") if s[key] is None else s[key]
    return {
        "u_over_u_cf": s["u_over_u_cf"], "u": s["u"], "u_cf_linear": s["u_cf_linear"],
        "growth_rate": s["growth_rate_dimensionless"], "linear_growth_rate": s["linear_growth_rate_dimensionless"],
        "frequency": s["frequency_dimensionless"], "linear_frequency": s["linear_frequency_dimensionless"],
        "tip_amplitude_m": amplitude, "saturated": int(abs(ratio - 1.0) < 0.05),
        "out_of_plane_ratio": s["out_of_plane_ratio"],
    }


def plot(rows, path):
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    x = [r["u_over_u_cf"] for r in rows]
    a.plot(x, [r["linear_growth_rate"] for r in rows], "-", color="0.5", label="linear (same tube)")
    a.plot(x, [r["growth_rate"] for r in rows], "o", label="nonlinear, fitted on the tip")
    a.axhline(0.0, color="k", lw=0.5)
    a.set_xlabel("u / u_cf")
    a.set_ylabel("growth rate (per tau)")
    a.legend()
    sat = [r for r in rows if r["saturated"]]
    b.plot([r["u"] - r["u_cf_linear"] for r in sat], [r["tip_amplitude_m"] for r in sat], "o-", label="limit cycle")
    rest = [r for r in rows if not r["saturated"] and r["u_over_u_cf"] > 1]
    if rest:
        b.plot([r["u"] - r["u_cf_linear"] for r in rest], [r["tip_amplitude_m"] for r in rest], "x",
               color="0.5", label="still growing at the end")
    near = [r for r in sat if r["u"] > r["u_cf_linear"]][:2]
    if near:  # a supercritical Hopf bifurcation: amplitude ~ c sqrt(u - u_cf) near onset
        c = sum(r["tip_amplitude_m"] / math.sqrt(r["u"] - r["u_cf_linear"]) for r in near) / len(near)
        top = max(r["u"] - r["u_cf_linear"] for r in sat)
        xs = [top * i / 100 for i in range(101)]
        b.plot(xs, [c * math.sqrt(x) for x in xs], "--", color="0.5", label="c sqrt(u - u_cf), near onset")
    b.set_xlabel("u - u_cf")
    b.set_ylabel("tip amplitude (m)")
    b.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("unilag")
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--fractions", default="0.98,1.02,1.1,1.2,1.3")
    p.add_argument("--end-time", type=float, default=None)
    p.add_argument("--fit-from", type=float, default=None,
                   help="fraction of the run after which the growth is fitted (default: the scene's dynamics.fit_from)")
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = [run_one(args, float(f)) for f in args.fractions.split(",")]
    with open(os.path.join(args.out, "flutter.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(args.out, "flutter.png"))
    for r in rows:
        print("u/u_cf %.4f  growth %.5g (linear %.5g)  tip amplitude %.4g m%s" % (
            r["u_over_u_cf"], r["growth_rate"], r["linear_growth_rate"], r["tip_amplitude_m"],
            "  (limit cycle)" if r["saturated"] else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
