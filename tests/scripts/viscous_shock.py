#!/usr/bin/env python3
"""Viscous Mach-2 shock (docs/gpr-model.md 3.4, DPRZ16 set-up) against the exact Becker profile, on three meshes: the L1
error of the density near the shock must decrease with the mesh size, and every run must conserve (--check).

Scene (inputs/viscous_shock2d.yaml): ideal gas gamma = 1.4, rho0 = 1, p0 = 1/gamma (c0 = 1), mu = 2e-2, Pr = 3/4;
the Rankine-Hugoniot jump at x = XJ drives a shock right at Ms c0 = 2 into gas at rest, pushed by a piston at the
post-shock velocity. For Pr = 3/4 (and constant mu, kappa) the Navier-Stokes-Fourier shock structure is Becker's:
with Re = rho0 c0 Ms / mu, a = 2/(Ms^2 (gamma+1)) + (gamma-1)/(gamma+1) and xi = x - x_shock,
    (1 - v)/(v - a)^a = ((1 - a)/2)^(1 - a) exp(-(3/4) Re (Ms^2 - 1)/(gamma Ms^2) xi),   rho = rho0 / v,
(gas at rest ahead, on the right). It is the travelling wave of the first-order Chapman-Enskog limit of GPR,
which this set-up only approaches: tau1 = 4.8e-3 and tau2 = 5.2e-3 are about a third of the time the gas takes to
cross the shock (width ~0.03 at speed 2), and c_sh tau1 = 0.024 is about the width. So GPR's structure differs from
Becker's by a model error that no mesh removes: order 2's L1 levels off (an independent review, window [0.17, 0.40]
with the position from mass conservation: 3.61e-3 at size 0.01, 2.82e-3 at 0.005, largest at the shock's centre),
while order 1's numerical viscosity dominates (3.2e-2, 1.9e-2). The test asserts order 1's decrease.
The shock forms from the jump, which shifts its position: x_shock = XJ + Ms c0 t + delta, with delta fitted
(minimum L1 error; |delta| is printed and must stay below 0.02). The formation also leaves an entropy spot on the
particles that were at XJ (they move at the piston speed); the error window [x_shock - 0.08, x_shock + 0.15]
excludes it (it lies ~0.19 behind the shock at t = 0.25, spread by conduction over ~0.05).

The exact profile is solved by bisection (numpy only); `viscous_shock.py --selftest` checks it: the end states
against Rankine-Hugoniot and Becker's ODE (4/3)(mu/(rho0 U)) v' = ((gamma+1)/(2 gamma)) (1 - v)(v - a)/v.

usage: viscous_shock.py UNILAG SCENE WORKDIR [--max-fine-l1 X] [--set KEY=VALUE ...]
       viscous_shock.py --selftest
"""
import glob
import math
import os
import re
import subprocess
import sys

import numpy as np

GAMMA, MS, RHO0 = 1.4, 2.0, 1.0
P0 = 1.0 / GAMMA
MU = 2.0e-2
C0 = math.sqrt(GAMMA * P0 / RHO0)
XJ = -0.25              # initial position of the jump (scene)
SIZES = [0.02, 0.01, 0.0067]
BEHIND, AHEAD = 0.08, 0.15  # error window around the shock
MAX_SHIFT = 0.02

RE = RHO0 * C0 * MS / MU
A = 2.0 / (MS**2 * (GAMMA + 1.0)) + (GAMMA - 1.0) / (GAMMA + 1.0)
K = 0.75 * RE * (MS**2 - 1.0) / (GAMMA * MS**2)


def vbar(xi):
    """Becker profile: v = u_shockframe / U_upstream in (a, 1) at distances xi from the centre (gas ahead at xi > 0)."""
    xi = np.atleast_1d(np.asarray(xi, dtype=float))
    # ln(1 - v) - a ln(v - a) = (1 - a) ln((1 - a)/2) - K xi; the left side decreases with v on (a, 1)
    rhs = (1.0 - A) * math.log((1.0 - A) / 2.0) - K * xi
    lo, hi = np.full_like(xi, A), np.ones_like(xi)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        with np.errstate(divide="ignore"):
            f = np.log(1.0 - mid) - A * np.log(mid - A) - rhs
        lo, hi = np.where(f > 0, mid, lo), np.where(f > 0, hi, mid)
    return 0.5 * (lo + hi)


def exact(xi):
    """Density, pressure and velocity (fluid ahead at rest) of the Becker shock at xi = x - x_shock."""
    v = vbar(xi)
    rho = RHO0 / v
    p = (P0 / v) * (1.0 + 0.5 * (GAMMA - 1.0) * MS**2 * (1.0 - v**2))
    u = MS * C0 * (1.0 - v)
    return rho, p, u


def selftest():
    ok = True
    # Rankine-Hugoniot state behind a Mach-Ms shock
    r1 = (GAMMA + 1.0) * MS**2 / ((GAMMA - 1.0) * MS**2 + 2.0) * RHO0
    p1 = P0 * (1.0 + 2.0 * GAMMA / (GAMMA + 1.0) * (MS**2 - 1.0))
    u1 = MS * C0 * (1.0 - RHO0 / r1)
    rho, p, u = exact(np.array([-1.0, 1.0]))
    for name, got, want in (("rho behind", rho[0], r1), ("p behind", p[0], p1), ("u behind", u[0], u1),
                            ("rho ahead", rho[1], RHO0), ("p ahead", p[1], P0), ("u ahead", u[1], 0.0)):
        err = abs(got - want) / max(abs(want), 1.0)
        print(f"{name}: {got:.12g} (Rankine-Hugoniot {want:.12g})")
        ok &= err < 1e-10
    # Becker's ODE, by centred differences
    xi = np.linspace(-0.08, 0.12, 41)
    d = 1e-6
    v = vbar(xi)
    dv = (vbar(xi + d) - vbar(xi - d)) / (2 * d)
    lhs = (4.0 / 3.0) * MU / (RHO0 * MS * C0) * dv
    rhs = (GAMMA + 1.0) / (2.0 * GAMMA) * (1.0 - v) * (v - A) / v
    res = np.max(np.abs(lhs - rhs)) / np.max(np.abs(rhs))
    print(f"Becker ODE residual: {res:.2e}")
    ok &= res < 1e-6
    print("viscous_shock selftest:", "PASS" if ok else "FAIL")
    return ok


def last_dump(out):
    h5s = sorted(glob.glob(f"{out}/unilag_*.h5"))
    with open(h5s[-1][:-3] + ".xmf") as f:
        t = float(re.search(r'<Time Value="([^"]+)"', f.read()).group(1))
    import h5py
    with h5py.File(h5s[-1], "r") as f:
        xyz, conn = f["coordinates"][...], f["connectivity"][...]
        rho, vol = f["density"][:, 0], f["volume"][:, 0]
    return t, xyz, conn, rho, vol


def l1_error(xc, rho, vol, height, x_shock):
    win = (xc > x_shock - BEHIND) & (xc < x_shock + AHEAD)
    rex, _, _ = exact(xc[win] - x_shock)
    return np.sum(np.abs(rho[win] - rex) * vol[win]) / height


def fit_shift(xc, rho, vol, height, x_nominal):
    """delta minimising the L1 error: a scan, then golden-section refinement."""
    ds = np.linspace(-0.05, 0.05, 201)
    errs = [l1_error(xc, rho, vol, height, x_nominal + d) for d in ds]
    i = int(np.argmin(errs))
    lo, hi = ds[max(i - 1, 0)], ds[min(i + 1, len(ds) - 1)]
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(60):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if l1_error(xc, rho, vol, height, x_nominal + a) < l1_error(xc, rho, vol, height, x_nominal + b):
            hi = b
        else:
            lo = a
    d = 0.5 * (lo + hi)
    return d, l1_error(xc, rho, vol, height, x_nominal + d)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--selftest":
        sys.exit(0 if selftest() else 1)
    unilag, scene, work = sys.argv[1:4]
    extra = sys.argv[4:]  # more --set options for every run (e.g. --set scheme.order=2)
    max_fine = None  # --max-fine-l1 X: bound on the finest mesh's L1 error
    if "--max-fine-l1" in extra:
        k = extra.index("--max-fine-l1")
        max_fine = float(extra[k + 1])
        del extra[k:k + 2]
    if not selftest():
        sys.exit(1)
    rows = []
    for h in SIZES:
        out = os.path.join(work, f"viscous_shock_h{h}")
        subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", f"mesh.size={h}", "--set",
                        "output.interval=0", "--output", out] + extra, check=True)
        t, xyz, conn, rho, vol = last_dump(out)
        xc = xyz[conn][:, :, 0].mean(axis=1)
        height = xyz[:, 1].max() - xyz[:, 1].min()
        x_nominal = XJ + MS * C0 * t
        d, err = fit_shift(xc, rho, vol, height, x_nominal)
        rows.append((h, len(rho), d, err))
        print(f"h={h:<6} cells={len(rho):<6} t={t:.4g} shock at {x_nominal + d:.4f} (shift {d:+.4f}) "
              f"L1(rho) = {err:.4e}")
    ok = True
    for a, b in zip(rows, rows[1:]):
        order = math.log(a[3] / b[3]) / math.log(a[0] / b[0])
        print(f"L1 order {a[1]} -> {b[1]} cells: {order:.2f}")
        ok &= b[3] < a[3]
    for r in rows:
        if abs(r[2]) > MAX_SHIFT:
            print(f"FAIL: shock shifted by {r[2]:+.4f} from XJ + Ms c0 t on {r[1]} cells (> {MAX_SHIFT})")
            ok = False
    if max_fine is not None:
        fine = rows[-1][3]
        print(f"finest mesh: L1(rho) = {fine:.4e} (bound {max_fine:.4e})")
        if not fine <= max_fine:
            print("FAIL: the finest mesh's L1 error exceeds the bound")
            ok = False
    print("viscous_shock:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
