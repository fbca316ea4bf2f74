#!/usr/bin/env python3
"""Check that an out-of-plane perturbation makes a fluttering tube leave its plane, and that an in-plane one does not.

THREE_D_DIR: a run above u_cf perturbed in y and z: the tip's z amplitude over the last fifth of the run must exceed
ten times that over the first fifth (the out-of-plane motion grows with the flutter) and a fifth of the final y
amplitude (it is not a small remainder). PLANAR_DIR: the same run perturbed in y only: z is 0 at every sample.
Usage: tube_out_of_plane.py THREE_D_DIR PLANAR_DIR
"""
import csv
import sys


def tip(folder):
    with open(f"{folder}/tip.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def amplitude(rows, key, lo, hi):
    end = rows[-1]["t"]
    return max(abs(r[key]) for r in rows if lo * end <= r["t"] <= hi * end)


def main():
    three, planar = tip(sys.argv[1]), tip(sys.argv[2])
    z_first, z_last = amplitude(three, "z", 0.0, 0.2), amplitude(three, "z", 0.8, 1.0)
    y_last = amplitude(three, "y", 0.8, 1.0)
    grew = z_last > 10.0 * z_first
    large = z_last > 0.2 * y_last
    flat = max(abs(r["z"]) for r in planar) == 0.0
    print(f"3D run: z amplitude {z_first:.3e} (first fifth) -> {z_last:.3e} (last fifth), y {y_last:.3e}: "
          f"{'ok' if grew and large else 'FAIL'}")
    print(f"planar run: max |z| = {max(abs(r['z']) for r in planar):.3e}: {'ok' if flat else 'FAIL'}")
    ok = grew and large and flat
    print("tube_out_of_plane:", "PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
