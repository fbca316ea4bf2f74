#!/usr/bin/env python3
"""Time order of scheme.integrator ars222 at a fixed mesh: SCENE at CFL_A, CFL_B = CFL_A / 2 and a reference CFL_REF;
the volume-weighted L2 differences of the final cell velocities and specific total energies (matched by global id)
against the reference, d_A and d_B, must each fall at order log(d_A / d_B) / log(CFL_A / CFL_B) >= MIN_ORDER (the
energy too: the midpoint step's falls to 1.1-1.25 on the vortex while its velocity's is 1.45-1.7). time.max_growth =
20 keeps every step proportional to the CFL number (the default 10% ramp per step is not).

usage: ars_time_order.py UNILAG SCENE WORKDIR CFL_A CFL_B CFL_REF MIN_ORDER [--set KEY=VALUE ...]
"""
import glob
import math
import os
import subprocess
import sys

import h5py
import numpy as np


def run(unilag, scene, work, cfl, extra):
    out = os.path.join(work, f"ars_cfl{cfl}")
    subprocess.run([unilag, "run", scene, "--quiet", "--output", out, "--set", "scheme.order=2", "--set",
                    "scheme.integrator=ars222", "--set", f"time.cfl={cfl}", "--set", "output.interval=0",
                    "--set", "time.max_growth=20", *extra],
                   check=True)
    with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
        gid, vel = f["global_id"][:, 0], f["velocity"][...]
        energy = f["specific_internal_energy"][:, 0] + 0.5 * np.sum(vel**2, axis=1)
        p = f["coordinates"][...][f["connectivity"][...]]
    a, b = p[:, 1, :2] - p[:, 0, :2], p[:, 2, :2] - p[:, 0, :2]
    area = 0.5 * np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    o = np.argsort(gid)
    return {"velocity": vel[o], "energy": energy[o].reshape(-1, 1)}, area[o]


def main():
    if len(sys.argv) < 8:
        sys.exit(__doc__)
    unilag, scene, work = sys.argv[1:4]
    ca, cb, cref, min_order = (float(x) for x in sys.argv[4:8])
    extra = sys.argv[8:]
    ref, w = run(unilag, scene, work, cref, extra)
    runs = [run(unilag, scene, work, c, extra)[0] for c in (ca, cb)]
    ok = True
    for name in ("velocity", "energy"):
        d = [math.sqrt(np.sum(w * np.sum((r[name] - ref[name]) ** 2, axis=1)) / np.sum(w)) for r in runs]
        order = math.log(d[0] / d[1]) / math.log(ca / cb)
        print(f"ars222: {name} against cfl {cref}: {d[0]:.4e} at cfl {ca}, {d[1]:.4e} at cfl {cb}: order {order:.3f}"
              f" (required >= {min_order})")
        ok = ok and order >= min_order
    print("ars_time_order:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
