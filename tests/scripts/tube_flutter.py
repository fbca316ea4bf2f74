#!/usr/bin/env python3
"""Check nonlinear flutter runs (summary.json of `unilag run` on a tube scene with `dynamics:`) against the linear
stability of the same tube: the run below u_cf decays, the run above grows, and its fitted growth rate is within
TOL (relative) of the linear growth rate at the same speed. Also checks the tube's XDMF polyline and tip.csv.

Usage: tube_flutter.py BELOW_DIR ABOVE_DIR [--tol 0.05]
"""
import argparse
import json
import os
import sys


def load(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("below")
    p.add_argument("above")
    p.add_argument("--tol", type=float, default=0.05)
    a = p.parse_args()
    below, above = load(a.below), load(a.above)
    ok = True
    for name, s in (("below", below), ("above", above)):
        print(f"{name}: u/u_cf {s['u_over_u_cf']:.4f} beta {s['beta']:.4f} growth {s['growth_rate_dimensionless']:.5g} "
              f"(linear {s['linear_growth_rate_dimensionless']:.5g}) frequency {s['frequency_dimensionless']:.5g} "
              f"(linear {s['linear_frequency_dimensionless']:.5g}) peaks {s['tip_peaks_fitted']}")
    ok &= below["growth_rate_dimensionless"] < 0.0 and above["growth_rate_dimensionless"] > 0.0
    lin = above["linear_growth_rate_dimensionless"]
    err = abs(above["growth_rate_dimensionless"] - lin) / abs(lin)
    print(f"growth rate above u_cf: relative difference to linear {err:.4f} (tolerance {a.tol})")
    ok &= err <= a.tol
    fr = abs(above["frequency_dimensionless"] - above["linear_frequency_dimensionless"]) / above[
        "linear_frequency_dimensionless"]
    print(f"frequency above u_cf: relative difference to linear {fr:.4f} (tolerance 0.01)")
    ok &= fr <= 0.01
    for folder in (a.below, a.above):
        for f in ("tube.xmf", "tip.csv", "scene.yaml"):
            present = os.path.isfile(os.path.join(folder, f))
            ok &= present
            if not present:
                print(f"missing {folder}/{f}")
    print("tube_flutter:", "PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
