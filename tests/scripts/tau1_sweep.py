#!/usr/bin/env python3
"""Strain relaxation across the tau1 range (tests/scenes/tau1_sweep.yaml: a gas with c_sh = 1 in a shearing cellular
flow, law constant): every run must conserve (--check), and the elastic metric G from the last dump must obey the two
limits of docs/gpr-model.md 1.4:

  tau1 = 1e-14 (ideal fluid): G relaxes to isotropic within each step (the implicit relaxation is exact in the limit):
      max over cells of |dev G|_F / tr G <= ISO_BOUND = 1e-12. The physical deviator is ~ tau1 |grad v| ~ 1e-15; an
      unrelaxed G would sit at the flow's shear strain, ~1e-2 here.
  tau1 = 1e14 (elastic): no relaxation, so det G = (rho/rho0)^2 (G = A^T A, det A = rho/rho0). The discrete G
      transport G^{n+1} = G^n - dt (G^n L + L^T G^n) does not keep it exactly: per step
      det G^{n+1}/det G^n = det(I - dt L)^2 + O(dt^2 |L|^2), while the exact-GCL density gives
      (rho^{n+1}/rho^n)^2 = det(I + dt L)^-2. The mismatch is O(dt^2 |L|^2) per step, O(t dt |L|^2) in all: a
      first-order error in dt. The check is therefore that max |det G/(rho/rho0)^2 - 1| is small (<= DET_BOUND = 1e-3;
      t dt |L|^2 ~ 0.5 x 0.01 x 0.1 = 5e-4 at cfl 0.5) AND falls by at least 1.6 when the time step is halved
      (a second run at half the CFL number), which shows it is a time-discretisation error and not a transport bug.
      (A G update that keeps det G = (rho/rho0)^2 to round-off, <= 1e-12, passes without the ratio test.)
  tau1 = 1e-6 (viscous, Navier-Stokes limit; k dt = 6 dt/tau1 ~ 3e4): the first-order Chapman-Enskog balance
      of transport and relaxation, 0 = -(G L + L^T G) - (6/tau1) G dev G with G ~ I, gives
      dev G = -(tau1/3) dev D, D = (L + L^T)/2, i.e. the viscous stress 2 mu dev D with mu = rho0 tau1 c_sh^2/6
      (docs/gpr-model.md 1.4; the scheme is asymptotic preserving in this limit, docs/gpr-model.md 2.4). For the
      cellular flow D = 0.1 pi cos(pi x) cos(pi y) diag(1, -1, 0) times the flow's current amplitude (it decays, mostly
      by numerical dissipation: the amplitude is measured by projecting the cell velocities on the initial field). The
      check projects dev G on -(tau1/3) D: the ratio must be within CE_TOL = 0.15 of 1, the part of dev G off that shape
      below 0.2 of it. (A relaxation that lets dev G decay over the step instead of balancing it against the
      transport gives a ratio ~ 1/(k dt) ~ 0 here: the viscous stress is lost when dt >> tau1.)
  tau1 = 1 (k = 6, rate ~ 0.3): in between; conservation only.

usage: tau1_sweep.py UNILAG SCENE WORKDIR [--set KEY=VALUE ...]
The extra --set options go to every run (e.g. scheme.order=2 scheme.integrator=ars222).
"""
import glob
import os
import subprocess
import sys

import h5py
import numpy as np

RHO0 = 1.0
ISO_BOUND = 1e-12
DET_BOUND = 1e-3
CE_TOL = 0.15
TAUS = ["1e-14", "1e-6", "1", "1e14"]


def load_G(f):
    """G per cell as (n, 3, 3) from a dump: a 6-component field (xx, yy, zz, xy, xz, yz), a 9-component one, or
    the pair G_diag (xx, yy, zz) + G_offdiag (xy, xz, yz)."""
    if "G" in f:
        g = f["G"][...]
    else:
        g = np.hstack([f["G_diag"][...], f["G_offdiag"][...]])
    n = g.shape[0]
    if g.shape[1] == 9:
        return g.reshape(n, 3, 3)
    G = np.empty((n, 3, 3))
    for k, (i, j) in enumerate([(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]):
        G[:, i, j] = G[:, j, i] = g[:, k]
    return G


COMMON = []  # --set options of every run (command line)


def run(unilag, scene, work, tau, extra=()):
    out = os.path.join(work, f"tau1_{tau}" + ("_" + "_".join(e.split("=")[1] for e in extra[1::2]) if extra else ""))
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", f"materials.gas.strain_relaxation.tau1={tau}",
                    *COMMON, *extra, "--output", out], check=True)
    with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
        G = load_G(f)
        rho = f["density"][:, 0]
        vel = f["velocity"][...]
        xyz, conn = f["coordinates"][...], f["connectivity"][...]
    tr = np.trace(G, axis1=1, axis2=2)
    dev = G - tr[:, None, None] / 3.0 * np.eye(3)
    iso = np.linalg.norm(dev, axis=(1, 2)) / tr
    det = np.abs(np.linalg.det(G) / (rho / RHO0) ** 2 - 1.0)
    # Chapman-Enskog: dev G = -(tau1/3) amp D0 with D0 the initial field's strain rate at the cell centroids
    c = xyz[conn].mean(axis=1)
    x, y = c[:, 0], c[:, 1]
    u0 = 0.1 * np.sin(np.pi * x) * np.cos(np.pi * y)
    v0 = -0.1 * np.cos(np.pi * x) * np.sin(np.pi * y)
    amp = np.sum(vel[:, 0] * u0 + vel[:, 1] * v0) / np.sum(u0 * u0 + v0 * v0)
    P = np.zeros_like(G)
    d = 0.1 * np.pi * np.cos(np.pi * x) * np.cos(np.pi * y)
    P[:, 0, 0], P[:, 1, 1] = d, -d
    P *= -float(tau) / 3.0 * amp
    ratio = np.sum(dev * P) / np.sum(P * P)
    off = np.linalg.norm(dev - ratio * P) / max(np.linalg.norm(ratio * P), 1e-300)
    return iso, det, (amp, ratio, off)


def main():
    unilag, scene, work = sys.argv[1:4]
    COMMON.extend(sys.argv[4:])
    ok = True
    res = {}
    for tau in TAUS:
        iso, det, ce = run(unilag, scene, work, tau)
        res[tau] = (iso, det, ce)
        print(f"tau1 = {tau:<6}: |dev G|/tr G max {iso.max():.3e} mean {iso.mean():.3e};  "
              f"|det G/(rho/rho0)^2 - 1| max {det.max():.3e}" +
              (f";  dev G / Chapman-Enskog {ce[1]:.3g} (off-shape {ce[2]:.2g}, flow amplitude {ce[0]:.3f})"
               if tau == "1e-6" else ""))
    if not res["1e-14"][0].max() <= ISO_BOUND:
        print(f"FAIL: tau1 = 1e-14 leaves a deviatoric G above {ISO_BOUND:g}")
        ok = False
    amp, ratio, off = res["1e-6"][2]
    if not (abs(ratio - 1.0) <= CE_TOL and off <= 0.2):
        print(f"FAIL: tau1 = 1e-6: dev G is {ratio:.3g} x the Navier-Stokes value -(tau1/3) dev D "
              f"(off-shape part {off:.2g}); expected 1 within {CE_TOL}")
        ok = False
    d1 = res["1e14"][1].max()
    if not d1 <= DET_BOUND:
        print(f"FAIL: tau1 = 1e14: det G departs from (rho/rho0)^2 by more than {DET_BOUND:g}")
        ok = False
    _, det_half, _ = run(unilag, scene, work, "1e14", ("--set", "time.cfl=0.25"))
    ratio = d1 / max(det_half.max(), 1e-300)
    print(f"tau1 = 1e14 at half the time step: |det G/(rho/rho0)^2 - 1| max {det_half.max():.3e} (ratio {ratio:.2f})")
    if d1 > 1e-12 and not ratio >= 1.6:  # (a transport that keeps det G exactly passes outright)
        print("FAIL: the det G defect does not fall like the time step")
        ok = False
    print("tau1_sweep:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
