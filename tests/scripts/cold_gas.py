#!/usr/bin/env python3
"""A Sedov run (a cold gas, pressure 0 ahead of the shock, docs/cold-gas.md; or any other) against its bounds, from its
output directory:
  - summary.json: status "completed" and t_final = T_END (the run reached its end time: a cold gas no longer stops
    at t = 0 on a zero impedance);
  - every field of the last output is finite (no NaN, no inf), the pressure and the specific internal energy are
    >= 0 up to the solver's round-off floor (the ambient gas stays cold or is heated, never below 0), the density
    positive;
  - L1(density) against the exact solution (summary.json) <= MAX_L1, and at least MIN_L1 (a sanity floor: an
    error far below the measured one means the exact profile or the run is not what the bound was set for);
  - with MAX_MIDPOINT (an ars222 run): between 1 and MAX_MIDPOINT steps taken by the midpoint scheme where ARS(2,2,2)
    left a cell inadmissible (summary.json midpoint_steps): the fallback acted, and ARS took the rest.

usage: cold_gas.py RUN_DIR T_END MAX_L1 MIN_L1 [MAX_MIDPOINT]
"""
import glob
import json
import sys

import h5py
import numpy as np


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    run, t_end, max_l1, min_l1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    max_midpoint = int(sys.argv[5]) if len(sys.argv) == 6 else None
    ok = True
    with open(f"{run}/summary.json") as f:
        s = json.load(f)
    done = s["status"] == "completed" and abs(s["t_final"] - t_end) <= 1e-12 * max(1.0, t_end)
    print(f"status {s['status']}, t_final {s['t_final']:.12g} after {s['steps']} steps: "
          f"{'reached the end' if done else 'DID NOT FINISH'}")
    ok &= done
    with h5py.File(sorted(glob.glob(f"{run}/unilag_*.h5"))[-1], "r") as f:
        for k in f:
            v = f[k][...]
            if np.issubdtype(v.dtype, np.floating) and not np.all(np.isfinite(v)):
                print(f"field {k}: {np.count_nonzero(~np.isfinite(v))} non-finite values  FAIL")
                ok = False
        rho, p, eps = f["density"][...], f["pressure"][...], f["specific_internal_energy"][...]
        vel, vol = f["velocity"][...], f["volume"][...]
    # The solver's round-off floor (Material::epsRoundoff): 1e-14 of the mean specific total energy. A cold cell's
    # eps = E - v^2/2 is 0 up to that subtraction's round-off (seen: -1e-268 at order 2), never below it.
    mass = rho[:, 0] * vol[:, 0]
    energy = np.sum(mass * (eps[:, 0] + 0.5 * np.sum(vel * vel, axis=1)))
    floor = 1e-14 * abs(energy) / mass.sum()
    signs = rho.min() > 0.0 and p.min() >= -floor and eps.min() >= -floor
    print(f"min density {rho.min():.4g}, max density {rho.max():.4g}, min pressure {p.min():.4g}, "
          f"min specific internal energy {eps.min():.4g} (round-off floor -{floor:.3g}){'' if signs else '  FAIL'}")
    ok &= signs
    l1 = s.get("l1_density_error", float("nan"))  # absent if the run stopped early
    good = min_l1 <= l1 <= max_l1
    print(f"L1(density) {l1:.5g} (bounds {min_l1:.3g} .. {max_l1:.3g}){'' if good else '  FAIL'}")
    ok &= good
    if max_midpoint is not None:
        steps = s.get("midpoint_steps", -1)
        good = 1 <= steps <= max_midpoint
        print(f"midpoint steps {steps} of {s['steps']} (bounds 1 .. {max_midpoint}){'' if good else '  FAIL'}")
        ok &= good
    print("cold_gas:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
