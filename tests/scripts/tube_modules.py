#!/usr/bin/env python3
"""tube_modules.py gas|wall|rod|artery OUTPUT_DIR [options]: asserts a gas, gas + wall, gas + free rod or artery
scene's output (src/tube/GasRun, GasRodRun, ArteryRun).

gas: the files are there; the leading shock's speed measured from the run within --speed-tol (relative) of the
exact one and its position within two cells of the exact one; L1(density) below --l1 when given.
wall: the files are there; tube.xmf's last dump carries radius, wall_speed, density, pressure, velocity and mach per cell;
mass and gas + wall energy kept to 1e-10 (both ends closed); the wall at the left end, where the gas is nearly at
rest at the end, on the quasi-static law (p - p_ext) 2 pi R = b (R - R0) within --quasi-static; the front faster than the compliant speed c1 and slower than the gas's a1, its speed within
--speed-tol of --speed.
rod: the files are there; every dump carries density, pressure, velocity, mach, area, radius per cell and
rod_velocity per node, all finite, radius = sqrt(area / pi), mach = |velocity| / a; the last dump's centreline is
bent (a node off the x axis by more than --bend); mass and momentum kept to 1e-12, the energy's largest deviation
within the scene's bound; the shock's speed within --speed-tol of the rigid tube's exact one.
rod_unstable: a run stopped as non-finite: summary.json says "unstable" and every dump written is finite.
artery: the files are there; periodic within --cycles cycles; the mean outlet pressure within 1% of
mean(Q) (R1 + R2), what a periodic RCR outlet must give (docs/tube-artery.md); waveforms.csv has every sample.
Prints "tube_modules: PASS" or the failures."""
import argparse
import csv
import glob
import json
import math
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


def check_wall(out, a):
    fails = files_present(out, ["summary.json", "scene.yaml", "tube.xmf"])
    dumps = sorted(glob.glob(os.path.join(out, "tube_*.xmf")))  # tube.xmf includes one file per dump
    xmf = open(dumps[-1]).read() if dumps else ""
    for name in ["radius", "wall_speed", "density", "pressure", "velocity", "mach"]:
        if f'Attribute Name="{name}"' not in xmf:
            fails.append(f"tube.xmf has no per-cell {name}")
    s = json.load(open(os.path.join(out, "summary.json")))
    dm, de = s["mass_relative_change"], s["energy_relative_change"]
    r0, w = s["wall_rest_radius"], s["wall"]
    radius = s["radius_final_left_end"]
    load = 2 * math.pi * (s["pressure_final_left_end"] - w["outside_pressure"])
    quasi_static = w["b"] * r0 / (w["b"] - load)
    speed, a1, c1 = s["shock_speed"], s["sound_speed_right"], s["compliant_speed_right"]
    print(f"dM/M {dm:.3g}, dE/E {de:.3g}; R/R0 at the left end {radius / r0:.6g}, quasi-static "
          f"{quasi_static / r0:.6g}; front speed {speed:.6g} "
          f"(U/a1 {speed / a1:.4f}, U/c1 {speed / c1:.4f})")
    if not (abs(dm) <= 1e-10 and abs(de) <= 1e-10):
        fails.append("mass or gas + wall energy not conserved to 1e-10")
    if not abs(radius - quasi_static) <= a.quasi_static * radius:
        fails.append(f"R at the left end {radius} vs the quasi-static {quasi_static}: more than {a.quasi_static}")
    if not c1 < speed < a1:
        fails.append("the front is not between the compliant speed c1 and the gas sound speed a1")
    if a.speed is not None and not abs(speed - a.speed) <= a.speed_tol * a.speed:
        fails.append(f"front speed {speed} vs {a.speed}: more than {a.speed_tol} relative")
    return fails


def check_rod_dump(h5, gamma):
    """The per-cell and per-node fields of one dump: present, finite, consistent with each other."""
    import h5py  # Debian's python3-h5py (the regression suite's interpreter)
    import numpy as np
    fails = []
    with h5py.File(h5, "r") as f:
        names = ["density", "pressure", "velocity", "mach", "area", "radius", "rod_velocity", "coordinates"]
        missing = [n for n in names if n not in f]
        if missing:
            return [f"{h5}: no {', '.join(missing)}"], None
        d = {n: np.asarray(f[n]) for n in names}
    for n, v in d.items():
        if not np.all(np.isfinite(v)):
            fails.append(f"{h5}: {n} is not finite")
    cells = d["density"].size
    if d["coordinates"].shape != (cells + 1, 3) or d["rod_velocity"].size != 3 * (cells + 1):
        fails.append(f"{h5}: {cells} cells but coordinates {d['coordinates'].shape}, rod_velocity {d['rod_velocity'].size}")
    if not np.allclose(d["radius"], np.sqrt(d["area"] / math.pi), rtol=1e-12):
        fails.append(f"{h5}: radius is not sqrt(area / pi)")
    sound = np.sqrt(gamma * d["pressure"] / d["density"])
    if not np.allclose(d["mach"], np.abs(d["velocity"]) / sound, rtol=1e-10, atol=1e-14):
        fails.append(f"{h5}: mach is not |velocity| / a")
    return fails, d["coordinates"]


def check_rod(out, a):
    fails = files_present(out, ["summary.json", "scene.yaml", "tube.xmf"])
    s = json.load(open(os.path.join(out, "summary.json")))
    dumps = sorted(glob.glob(os.path.join(out, "tube_*.h5")))
    coords = None
    for h5 in dumps:
        f, coords = check_rod_dump(h5, s["gamma"])
        fails += f
    bend = float(abs(coords[:, 1:]).max()) if coords is not None else 0.0
    dm, dp, de = s["mass_relative_change"], s["momentum_change_over_scale"], s["energy_max_relative_change"]
    speed, exact = s["shock_speed"], s["shock_speed_rigid_exact"]
    print(f"{len(dumps)} dumps; dM/M {dm:.3g}, dP/P_scale {dp:.3g}, max |dE/E| {de:.3g} (bound {s['energy_bound']:.3g}); "
          f"largest transverse displacement {bend:.4g}; shock speed {speed:.6g} (rigid exact {exact:.6g}), "
          f"max stretch {s['max_stretch']:.3g}")
    if not dumps:
        fails.append("no tube_*.h5 dumps")
    if not (abs(dm) <= 1e-12 and dp <= 1e-12):
        fails.append("mass or total momentum not kept to 1e-12")
    if not de <= s["energy_bound"]:
        fails.append(f"energy deviated by {de} > the scene's bound {s['energy_bound']}")
    if not bend > a.bend:
        fails.append(f"the tube did not bend: largest transverse displacement {bend} <= {a.bend}")
    if not abs(speed - exact) <= a.speed_tol * exact:
        fails.append(f"shock speed {speed} vs the rigid exact {exact}: more than {a.speed_tol} relative")
    return fails


def check_rod_unstable(out, a):
    s = json.load(open(os.path.join(out, "summary.json")))
    dumps = sorted(glob.glob(os.path.join(out, "tube_*.h5")))
    fails = [] if s["status"] == "unstable" else [f"summary.json status {s['status']}, not unstable"]
    for h5 in dumps:
        fails += check_rod_dump(h5, s["gamma"])[0]
    print(f"status {s['status']}; {len(dumps)} dumps written before the stop")
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
    p.add_argument("kind", choices=["gas", "wall", "rod", "rod_unstable", "artery"])
    p.add_argument("out")
    p.add_argument("--speed-tol", type=float, default=0.01)
    p.add_argument("--l1", type=float)
    p.add_argument("--cycles", type=int, default=6)
    p.add_argument("--speed", type=float, help="wall: the expected front speed")
    p.add_argument("--bend", type=float, default=0.0, help="rod: the least transverse displacement of the end state")
    p.add_argument("--quasi-static", type=float, default=0.01, help="wall: tolerance of R on the quasi-static law")
    a = p.parse_args()
    fails = {"gas": check_gas, "wall": check_wall, "rod": check_rod, "rod_unstable": check_rod_unstable, "artery": check_artery}[a.kind](a.out, a)
    for f in fails:
        print("FAIL:", f)
    print("tube_modules: PASS" if not fails else "tube_modules: FAIL")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
