#!/usr/bin/env python3
"""Assert that two tube runs (e.g. on 1 and 3 OpenMP threads) wrote bitwise the same results: every dataset of
every dump (tube_NNNNNN.h5) and every CSV (tip.csv, waveforms.csv, ...), and summary.json's step count.

usage: same_tube_runs.py DIR_A DIR_B
"""
import glob
import json
import os
import sys

import h5py
import numpy as np


def differences(a, b):
    dumps = sorted(os.path.basename(p) for p in glob.glob(os.path.join(a, "tube_*.h5")))
    if not dumps or dumps != sorted(os.path.basename(p) for p in glob.glob(os.path.join(b, "tube_*.h5"))):
        yield f"dumps differ or are missing: {dumps}"
        return
    for name in dumps:
        with h5py.File(os.path.join(a, name), "r") as fa, h5py.File(os.path.join(b, name), "r") as fb:
            if sorted(fa) != sorted(fb):
                yield f"{name}: datasets {sorted(fa)} against {sorted(fb)}"
            for key in fa:
                x, y = fa[key][()], fb[key][()]
                if x.shape != y.shape or not np.array_equal(x, y):
                    gap = np.max(np.abs(x - y)) if x.shape == y.shape else "shape"
                    yield f"{name}/{key} differs (largest difference {gap})"
    for path in sorted(glob.glob(os.path.join(a, "*.csv"))):
        other = os.path.join(b, os.path.basename(path))
        if not os.path.exists(other) or open(path).read() != open(other).read():
            yield f"{os.path.basename(path)} differs"
    steps = [json.load(open(os.path.join(d, "summary.json"))).get("steps") for d in (a, b)]
    if steps[0] != steps[1]:
        yield f"steps {steps[0]} against {steps[1]}"


def main():
    a, b = sys.argv[1:3]
    found = list(differences(a, b))
    for line in found:
        print(f"same_tube_runs: {line}")
    print("same_tube_runs: FAIL" if found else f"same_tube_runs: PASS ({a}, {b})")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
