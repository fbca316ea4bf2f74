#!/usr/bin/env python3
"""The GPR model's hydrodynamic limit against the Euler solver (inputs/sedov2d_gpr.yaml against inputs/sedov2d.yaml).

The GPR run has c_sh of the order of the shocked gas' sound speed and tau1 = 1e-14, so that its stress
sigma = -rho c_sh^2 G dev G is O(rho c_sh^2) times any error of the relaxed G_e: a G_e that does not relax to
isotropy, or a stress formula off by a factor, shows. Both runs take the same fixed time step (time.initial_dt with
max_growth = 1, below every stable step of either run), which this script verifies from steps.csv; the GPR run's
signal speed sqrt(c0^2 + 4/3 c_sh^2) still enters its nodal solver's impedance rho a, so the two runs differ by that
change of the scheme's dissipation, not by round-off: each field's max difference (relative to its largest value)
is bounded by a figure measured now. Checks:
  - identical time steps;
  - each field within MAX_DIFF of the Euler run;
  - the GPR run's stress: max von Mises stress / max pressure <= MAX_STRESS, max |dev G| / tr G <= MAX_ANISO. In the
    limit both are proportional to tau1 c_sh^2 (the Navier-Stokes deviator, docs/gpr-model.md 1.4).

usage: hydro_limit.py EULER_DIR GPR_DIR MAX_DIFF(field=value,...) MAX_STRESS MAX_ANISO
"""
import glob
import sys

import h5py
import numpy as np

FIELDS = ["density", "pressure", "velocity", "specific_internal_energy", "volume"]


def last(d):
    with h5py.File(sorted(glob.glob(f"{d}/unilag_*.h5"))[-1], "r") as f:
        order = np.argsort(f["global_id"][:, 0])
        return {k: f[k][...][order] for k in f if k in FIELDS + ["von_mises_stress", "G_anisotropy"]}


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    euler_dir, gpr_dir = sys.argv[1], sys.argv[2]
    max_diff = {k: float(v) for k, v in (kv.split("=") for kv in sys.argv[3].split(","))}
    max_stress, max_aniso = float(sys.argv[4]), float(sys.argv[5])
    ok = True
    dt_e = np.genfromtxt(f"{euler_dir}/steps.csv", delimiter=",", names=True)["dt"]
    dt_g = np.genfromtxt(f"{gpr_dir}/steps.csv", delimiter=",", names=True)["dt"]
    same = dt_e.shape == dt_g.shape and np.array_equal(dt_e, dt_g)
    print(f"time steps: {len(dt_e)} (Euler) and {len(dt_g)} (GPR), dt {dt_g.min():.6g} .. {dt_g.max():.6g}: "
          f"{'identical' if same else 'DIFFERENT'}")
    ok &= same
    e, g = last(euler_dir), last(gpr_dir)
    for k in FIELDS:
        d = np.abs(g[k] - e[k]).max() / np.abs(e[k]).max()
        good = d <= max_diff[k]
        ok &= good
        print(f"{k}: max difference from the Euler run {d:.3e} of its largest value (bound {max_diff[k]:.1e})"
              f"{'' if good else '  FAIL'}")
    stress = g["von_mises_stress"].max() / g["pressure"].max()
    aniso = g["G_anisotropy"].max()
    for name, v, b in (("max von Mises stress / max pressure", stress, max_stress),
                       ("max |dev G| / tr G", aniso, max_aniso)):
        good = v <= b
        ok &= good
        print(f"{name}: {v:.3e} (bound {b:.1e}){'' if good else '  FAIL'}")
    print("hydro_limit:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
