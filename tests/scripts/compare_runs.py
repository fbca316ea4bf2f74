#!/usr/bin/env python3
"""Compare the final cell fields of unilag runs (e.g. on 1, 2, 3 ranks), matched by global cell id.

usage: compare_runs.py RTOL DIR_A DIR_B [DIR_C ...]
Exits 1 if any field differs by more than RTOL relative to its largest magnitude; prints the differences.
"""
import glob
import sys

import h5py
import numpy as np

FIELDS = ["density", "pressure", "velocity", "specific_internal_energy", "volume"]
# GPR fields, compared when the first run has them (strain / heat variants)
OPTIONAL = ["G", "von_mises_stress", "temperature", "thermal_impulse"]


def last_dump(d):
    files = sorted(glob.glob(f"{d}/unilag_*.h5"))
    if not files:
        sys.exit(f"compare_runs: no unilag_*.h5 in {d}")
    with h5py.File(files[-1], "r") as f:
        order = np.argsort(f["global_id"][:, 0])
        keys = FIELDS + [k for k in OPTIONAL if k in f]
        return files[-1], {k: f[k][...][order] for k in keys}


def main():
    rtol = float(sys.argv[1])
    ref_name, ref = last_dump(sys.argv[2])
    worst = 0.0
    for d in sys.argv[3:]:
        name, other = last_dump(d)
        for k in ref:
            if k not in other:
                sys.exit(f"compare_runs: {k} is in {ref_name} but not in {name}")
            if other[k].shape != ref[k].shape:
                sys.exit(f"compare_runs: {k}: shape {other[k].shape} in {name} vs {ref[k].shape} in {ref_name}")
            scale = max(np.abs(ref[k]).max(), 1e-300)
            diff = np.abs(other[k] - ref[k]).max() / scale
            worst = max(worst, diff)
            print(f"{name} vs {ref_name}: {k} max relative difference {diff:.3e}")
    if worst > rtol:
        print(f"compare_runs: FAIL, {worst:.3e} > {rtol:.1e}")
        sys.exit(1)
    print(f"compare_runs: PASS ({worst:.3e} <= {rtol:.1e})")


if __name__ == "__main__":
    main()
