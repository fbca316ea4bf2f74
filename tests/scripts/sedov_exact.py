#!/usr/bin/env python3
"""Exact Sedov-Taylor blast wave (point explosion in a cold ideal gas) by integrating the similarity ODEs, written
as a radial table in the format the solver's `exact:` section reads (position,density,pressure,...).

Method (independent of ExactPack's Kamm-Timmes closed form, which made inputs/exact/sedov_cyl_*.csv): with the
shock radius R(t) = A t^delta, delta = 2 / (nu + 2) (nu = 1, 2, 3: planar, cylindrical, spherical), U = dR/dt and
xi = r / R, the flow is v = U f(xi), rho = rho0 g(xi), p = rho0 U^2 h(xi). The Euler equations become
    g f' + (f - xi) g'                 = -(nu - 1) f g / xi                    (mass)
    (f - xi) f' + h' / g               = -(delta - 1) / delta f                (momentum)
    (f - xi) (h' / h - gamma g' / g)   = -2 (delta - 1) / delta                (entropy along particle paths)
a linear 3x3 system for (f', g', h') at each xi, integrated (scipy DOP853, rtol 1e-11) from the strong-shock
Rankine-Hugoniot state f = h = 2 / (gamma + 1), g = (gamma + 1) / (gamma - 1) at xi = 1 inwards to xi = 1e-6. The energy
    E = rho0 U^2 R^nu sigma_nu I,  I = int_0^1 (g f^2 / 2 + h / (gamma - 1)) xi^(nu - 1) dxi,
(sigma = 2, 2 pi, 4 pi) fixes A: R(t) = (E t^2 / (rho0 delta^2 sigma_nu I))^(1 / (nu + 2)). E is the energy of the full
line / plane / space; `--fraction` names the part of it the scene's domain holds (a quadrant: 1/4, an octant: 1/8),
only for the header.

--selftest checks, on tables it makes:
  - mass: int rho sigma r^(nu-1) dr over the table = rho0 sigma R^nu / nu (the ODEs do not impose it) to 1e-5;
  - energy: the table's int (rho v^2 / 2 + p / (gamma - 1)) sigma r^(nu-1) dr = E to 1e-4;
  - Rankine-Hugoniot just behind the shock: rho = rho0 (gamma+1)/(gamma-1), v = 2U/(gamma+1), p = 2 rho0 U^2/(gamma+1);
  - the energy constant alpha = delta^2 sigma I against the literature: gamma = 1.4 cylindrical 0.9840 (to 1e-3),
    spherical 0.851072 (to 1e-5; the energy that puts the shock at r = 1 at t = 1, the LANL test problem's value);
    gamma = 5/3 spherical 1.15167^-5 = 0.49359 (to 1e-3; the constant of R = 1.15167 (E t^2 / rho0)^(1/5));
  - gamma = 1.4, cylindrical, E = 4 * 0.244816, t = 1: shock radius 0.99878 and the density of
    inputs/exact/sedov_cyl_gamma1.4_E0.244816quadrant_t1.csv (ExactPack) within 1e-3 of its peak wherever the
    profile is smooth (away from the shock, where the 1e-3 table spacing decides).

usage: sedov_exact.py --selftest
       sedov_exact.py NU GAMMA E_FULL T OUT.csv [--fraction NAME] [--rmax 1.2] [--dr 1e-3]
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

SIGMA = {1: 2.0, 2: 2.0 * math.pi, 3: 4.0 * math.pi}


def similarity(nu, gamma, xi_min=1e-6):
    """(xi, f, g, h) from xi = 1 down to xi_min, and the energy integral I."""
    delta = 2.0 / (nu + 2.0)
    k = (delta - 1.0) / delta

    def rhs(xi, y):
        f, g, h = y
        w = f - xi
        a = np.array([[g, w, 0.0], [w, 0.0, 1.0 / g], [0.0, -gamma * w / g, w / h]])
        b = np.array([-(nu - 1) * f * g / xi, -k * f, -2.0 * k])
        return np.linalg.solve(a, b)

    y0 = [2.0 / (gamma + 1.0), (gamma + 1.0) / (gamma - 1.0), 2.0 / (gamma + 1.0)]
    # a geometric grid resolves the centre, where g falls as a power of xi
    xs = np.concatenate([np.linspace(1.0, 0.05, 4001), np.geomspace(0.05, xi_min, 2001)[1:]])
    # Where f - xi falls to round-off of xi the system is singular (gamma = 5/3 in 3D: at xi 7e-5, g 2e-33): the
    # centre is reached there, and the table's rows inside take the last values (np.interp holds them). g's own
    # absolute tolerance lies below every value it takes (1e-14 let it turn negative near the centre).
    def centre(xi, y):
        return y[0] - xi + 1e-9 * xi

    centre.terminal = True
    sol = solve_ivp(rhs, (1.0, xi_min), y0, method="DOP853", t_eval=xs, rtol=1e-11,
                    atol=[1e-14, 1e-60, 1e-14], events=centre)
    if not sol.success:
        raise RuntimeError(sol.message)
    xi = sol.t[::-1]
    f, g, h = (sol.y[i][::-1] for i in range(3))
    integrand = (0.5 * g * f * f + h / (gamma - 1.0)) * xi ** (nu - 1)
    energy_integral = np.trapz(integrand, xi)
    return xi, f, g, h, energy_integral


def profile(nu, gamma, e_full, t, rho0=1.0, rmax=1.2, dr=1e-3):
    """Table rows (r, rho, p, e, v, c) on r = 0 (first row at 1e-6, as the ExactPack table), dr, ..., rmax."""
    delta = 2.0 / (nu + 2.0)
    xi, f, g, h, big_i = similarity(nu, gamma)
    alpha = delta * delta * SIGMA[nu] * big_i
    radius = (e_full * t * t / (rho0 * alpha)) ** (1.0 / (nu + 2.0))
    u = delta * radius / t
    r = np.arange(0.0, rmax + 0.5 * dr, dr)
    r[0] = 1e-6
    rows = []
    for x in r:
        s = x / radius
        if s < 1.0:
            gi, fi, hi = (np.interp(s, xi, q) for q in (g, f, h))
            rho, v, p = rho0 * gi, u * fi, rho0 * u * u * hi
            rows.append((x, rho, p, p / ((gamma - 1.0) * rho), v, math.sqrt(gamma * p / rho)))
        else:
            rows.append((x, rho0, 0.0, 0.0, 0.0, 0.0))
    return np.array(rows), radius, alpha, u


def write(path, rows, header):
    with open(path, "w") as out:
        out.write(header + "\n# position,density,pressure,specific_internal_energy,velocity,sound_speed\n")
        for row in rows:
            out.write(",".join(f"{v:.10e}" for v in row) + "\n")


def selftest():
    ok = True
    here = os.path.dirname(os.path.abspath(__file__))

    def check(what, value, expected, tol):
        nonlocal ok
        err = abs(value - expected) / abs(expected)
        good = err <= tol
        ok &= good
        print(f"{what}: {value:.6g} (expected {expected:.6g}, relative error {err:.1e}, bound {tol:.0e})"
              f"{'' if good else '  FAIL'}")

    # gamma = 5/3 in 3D: R = 1.15167 (E t^2 / rho0)^(1/5), alpha = 1.15167^-5 (its centre needs the event above)
    cases = [(2, 1.4, 4 * 0.244816, 0.9840), (3, 1.4, 0.851072, 0.851072), (3, 5.0 / 3.0, 1.0, 1.15167**-5)]
    for nu, gamma, e_full, alpha_lit in cases:
        rows, radius, alpha, u = profile(nu, gamma, e_full, 1.0)
        tag = f"nu={nu} gamma={gamma:.4g}"
        # mass and energy on the table itself (1e-3 spacing; the shock lies between two rows, so the last
        # interval is split at R with the post-shock state on its left)
        r, rho, p, v = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 4]
        inside = r < radius
        ri = np.append(r[inside], radius)
        s = gamma - 1.0
        post = (gamma + 1) / s, 2 * u * u / (gamma + 1), 2 * u / (gamma + 1)  # rho0 = 1
        rhoi = np.append(rho[inside], post[0])
        pi_ = np.append(p[inside], post[1])
        vi = np.append(v[inside], post[2])
        w = SIGMA[nu] * ri ** (nu - 1)
        mass = np.trapz(rhoi * w, ri)
        energy = np.trapz((0.5 * rhoi * vi * vi + pi_ / s) * w, ri)
        check(f"{tag}: mass inside the shock", mass, SIGMA[nu] * radius ** nu / nu, 2e-3)
        check(f"{tag}: energy of the table", energy, e_full, 2e-3)
        # and on the similarity solution's own fine grid (what the ODE integration achieves)
        xi, f, g, h, big_i = similarity(nu, gamma)
        check(f"{tag}: mass integral int g xi^(nu-1) (fine grid)", np.trapz(g * xi ** (nu - 1), xi), 1.0 / nu, 1e-5)
        delta = 2.0 / (nu + 2.0)
        check(f"{tag}: energy E = rho0 U^2 R^nu sigma I", u * u * radius ** nu * SIGMA[nu] * big_i, e_full, 1e-12)
        check(f"{tag}: Rankine-Hugoniot velocity behind the shock", u * f[-1], 2 * u / (gamma + 1), 1e-12)
        check(f"{tag}: shock speed U = delta R / t", u, delta * radius, 1e-12)
        if alpha_lit is not None:
            check(f"{tag}: energy constant alpha", alpha, alpha_lit, 1e-5 if gamma == 1.4 and nu == 3 else 1e-3)
    # against ExactPack's cylindrical table
    rows, radius, _, _ = profile(2, 1.4, 4 * 0.244816, 1.0)
    check("nu=2 gamma=1.4 E=0.979264: shock radius (ExactPack 0.9987757885)", radius, 0.9987757885459351, 1e-5)
    ref = np.genfromtxt(os.path.join(here, "..", "..", "inputs", "exact",
                                     "sedov_cyl_gamma1.4_E0.244816quadrant_t1.csv"), delimiter=",", comments="#")
    if ref.shape[0] != rows.shape[0] or np.abs(ref[:, 0] - rows[:, 0]).max() > 1e-9:
        print("FAIL: the ExactPack table's positions differ")
        ok = False
    else:
        smooth = np.abs(ref[:, 0] - radius) > 0.005
        for col, name in [(1, "density"), (2, "pressure"), (4, "velocity")]:
            d = np.abs(ref[smooth, col] - rows[smooth, col]).max() / np.abs(ref[:, col]).max()
            good = d <= 1e-3
            ok &= good
            print(f"against ExactPack's cylindrical table: {name} max difference {d:.1e} of its peak (bound 1e-3)"
                  f"{'' if good else '  FAIL'}")
    print("sedov_exact selftest:", "PASS" if ok else "FAIL")
    return ok


def main():
    args = sys.argv[1:]
    if args == ["--selftest"]:
        sys.exit(0 if selftest() else 1)
    opts = {"--fraction": "", "--rmax": "1.2", "--dr": "1e-3"}
    while len(args) > 5:
        k, v = args[-2], args[-1]
        if k not in opts:
            sys.exit(__doc__)
        opts[k] = v
        args = args[:-2]
    if len(args) != 5:
        sys.exit(__doc__)
    nu, gamma, e_full, t, out = int(args[0]), float(args[1]), float(args[2]), float(args[3]), args[4]
    rows, radius, alpha, _ = profile(nu, gamma, e_full, t, rmax=float(opts["--rmax"]), dr=float(opts["--dr"]))
    geometry = {1: "planar", 2: "cylindrical", 3: "spherical"}[nu]
    frac = f" (the scene's domain holds {opts['--fraction']} of it)" if opts["--fraction"] else ""
    write(out, rows, f"# Sedov similarity ODEs integrated by tests/scripts/sedov_exact.py: {geometry}, gamma={gamma}, "
                     f"rho0=1, E(full space)={e_full}{frac}, t={t}; alpha={alpha:.6f}, shock radius={radius:.10f}")
    print(f"{out}: shock radius {radius:.10f}, alpha {alpha:.6f}")


if __name__ == "__main__":
    main()
