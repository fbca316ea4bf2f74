#!/usr/bin/env python3
"""tube_modules.py gas|artery OUTPUT_DIR [options]: asserts a gas or artery scene's output (src/tube/GasRun,
ArteryRun).

gas: the files are there; the leading shock's speed measured from the run within --speed-tol (relative) of the
exact one and its position within two cells of the exact one; L1(density) below --l1 when given.
artery: the files are there; periodic within --cycles cycles; the mean outlet pressure within 1% of
mean(Q) (R1 + R2), what a periodic RCR outlet must give (docs/tube-artery.md); waveforms.csv has every sample.
Prints "tube_modules: PASS" or the failures."""
import argparse
import csv
import json
import os
import sys


def files_present(out, names):
    return [f"missing {n}" for n in names if not os.path.isfile(os.path.join(out, n))]


def check_gas(out, a):
    fails = files_present(out, ["summary.json", "scene.yaml", "tube.xmf"])
    s = json.load(open(os.path.join(out, "summary.json")))
    h = 1.0 / s["cells"]  # the Sod scene's unit length
    speed, exact = s["shock_speed"], s["shock_speed_exact"]
    print(f"shock speed {speed:.6g} (exact {exact:.6g}), position {s['shock_position']:.6g} "
          f"(exact {s['shock_position_exact']:.6g}), L1(rho) {s['l1_density']:.4g}")
    if not abs(speed - exact) <= a.speed_tol * exact:
        fails.append(f"shock speed {speed} vs exact {exact}: more than {a.speed_tol} relative")
    if not abs(s["shock_position"] - s["shock_position_exact"]) <= 2 * h:
        fails.append("shock position more than two cells from the exact one")
    if a.l1 is not None and not s["l1_density"] <= a.l1:
        fails.append(f"L1(density) {s['l1_density']} > {a.l1}")
    return fails


def check_artery(out, a):
    fails = files_present(out, ["summary.json", "scene.yaml", "tube.xmf", "waveforms.csv"])
    s = json.load(open(os.path.join(out, "summary.json")))
    rows = list(csv.reader(open(os.path.join(out, "waveforms.csv"))))[1:]
    q_in = [float(r[2]) for r in rows[-200:]]
    mean_q = sum(q_in) / len(q_in)
    expected = mean_q * (2.4875e8 + 1.8697e9)
    p_out = s["mean_pressure_Pa"]["outlet"]
    print(f"periodic after {s['cycles_to_periodicity']} cycles; mean p outlet {p_out:.6g} Pa vs "
          f"Q (R1 + R2) = {expected:.6g} Pa; {len(rows)} samples")
    if not 0 < s["cycles_to_periodicity"] <= a.cycles:
        fails.append(f"cycles to periodicity {s['cycles_to_periodicity']} not in [1, {a.cycles}]")
    if not abs(p_out - expected) <= 0.01 * expected:
        fails.append("mean outlet pressure differs from mean(Q) (R1 + R2) by more than 1%")
    if len(rows) != s["cycles"] * 200:
        fails.append(f"waveforms.csv has {len(rows)} rows, not {s['cycles']} x 200")
    return fails


def main():
    p = argparse.ArgumentParser()
    p.add_argument("kind", choices=["gas", "artery"])
    p.add_argument("out")
    p.add_argument("--speed-tol", type=float, default=0.01)
    p.add_argument("--l1", type=float)
    p.add_argument("--cycles", type=int, default=6)
    a = p.parse_args()
    fails = (check_gas if a.kind == "gas" else check_artery)(a.out, a)
    for f in fails:
        print("FAIL:", f)
    print("tube_modules: PASS" if not fails else "tube_modules: FAIL")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
