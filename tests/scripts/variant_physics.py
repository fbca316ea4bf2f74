#!/usr/bin/env python3
"""The variant scenes (tests/scenes/variants2d.yaml, variants3d.yaml) exercise their variant's physics, on every rank:
checks on the last dump of the hydro, elastic, heat, plastic and plastic_heat runs of one dimension, order and rank
count (a run on several ranks, so that the rank-agreement tests compare something that crosses the partition).

usage: variant_physics.py SIGMA_Y PATTERN [PATTERN ...]
PATTERN is a run folder with {} for the variant name (e.g. work/variant2d_{}_o1_np3). Asserts, for each:
  - yield reached: SIGMA_Y <= max von Mises stress <= 1.5 SIGMA_Y in plastic and plastic_heat (the flow stress);
  - and only through the law: the elastic run's max von Mises stress > 10 SIGMA_Y;
  - heat conducts: thermal_impulse nonzero and the peak specific internal energy (the temperature: cv = 1) < half the
    non-conducting run's (heat vs hydro, plastic_heat vs plastic);
  - the fields of each variant and no others: G and von_mises_stress only with strain, temperature ... only with heat;
  - every rank holds part of the blast: cells moving (|v| > 1e-3) in every run, cells at yield (von Mises >= SIGMA_Y)
    in the plastic runs, cells with |J| > 1e-3 in the heat runs.
"""
import glob
import sys

import h5py
import numpy as np

VARIANTS = {"hydro": (False, False), "elastic": (True, False), "heat": (False, True), "plastic": (True, False),
            "plastic_heat": (True, True)}


def last(d):
    files = sorted(glob.glob(f"{d}/unilag_*.h5"))
    if not files:
        sys.exit(f"variant_physics: no unilag_*.h5 in {d}")
    with h5py.File(files[-1], "r") as f:
        return {k: f[k][...] for k in f}


def main():
    sy = float(sys.argv[1])
    bad = []
    for pattern in sys.argv[2:]:
        runs = {v: last(pattern.format(v)) for v in VARIANTS}
        for v, (strain, heat) in VARIANTS.items():
            f = runs[v]
            if ("von_mises_stress" in f) != strain or ("G" in f) != strain:
                bad.append(f"{pattern.format(v)}: strain fields {'missing' if strain else 'present'}")
            if ("temperature" in f and "thermal_impulse" in f) != heat:
                bad.append(f"{pattern.format(v)}: heat fields {'missing' if heat else 'present'}")
        if bad:
            break
        vm = {v: runs[v]["von_mises_stress"].max() for v in ("elastic", "plastic", "plastic_heat")}
        tmax = {v: runs[v]["specific_internal_energy"].max() for v in VARIANTS}
        jmax = {v: np.abs(runs[v]["thermal_impulse"]).max() for v in ("heat", "plastic_heat")}
        print(f"{pattern}: max von Mises / sigma_Y: " + ", ".join(f"{v} {s / sy:.3g}" for v, s in vm.items()) +
              "; max eps: " + ", ".join(f"{v} {t:.3g}" for v, t in tmax.items()) +
              "; max |J|: " + ", ".join(f"{v} {j:.3g}" for v, j in jmax.items()))
        for v, f in runs.items():
            rank = f["rank"][:, 0].astype(int)
            parts = {"moving": np.linalg.norm(f["velocity"], axis=1) > 1e-3}
            if v in ("plastic", "plastic_heat"):
                parts["at yield"] = f["von_mises_stress"][:, 0] >= sy
            if v in ("heat", "plastic_heat"):
                parts["|J| > 1e-3"] = np.linalg.norm(f["thermal_impulse"], axis=1) > 1e-3
            for what, cells in parts.items():
                counts = [int(cells[rank == r].sum()) for r in range(rank.max() + 1)]
                print(f"  {v}: cells {what} per rank {counts}")
                if min(counts) == 0:
                    bad.append(f"{pattern.format(v)}: a rank has no cells {what}: {counts}")
        for v in ("plastic", "plastic_heat"):
            if not sy <= vm[v] <= 1.5 * sy:
                bad.append(f"{pattern.format(v)}: max von Mises {vm[v]:.4g} outside [1, 1.5] x sigma_Y = {sy:.4g}")
        if not vm["elastic"] > 10 * sy:
            bad.append(f"{pattern.format('elastic')}: max von Mises {vm['elastic']:.4g} <= 10 sigma_Y")
        for v, ref in (("heat", "hydro"), ("plastic_heat", "plastic")):
            if not jmax[v] > 0 or not tmax[v] < 0.5 * tmax[ref]:
                bad.append(f"{pattern.format(v)}: max |J| {jmax[v]:.3g}, max eps {tmax[v]:.3g} not below half "
                           f"of {ref}'s {tmax[ref]:.3g}")
    if bad:
        print("variant_physics: FAIL\n  " + "\n  ".join(bad))
        sys.exit(1)
    print("variant_physics: PASS")


if __name__ == "__main__":
    main()
