#!/usr/bin/env python3
"""Reference period of the first free-free bending mode of the beryllium plate of inputs/be_plate2d.yaml
(docs/gpr-model.md 3.9), for plate_period.py's EXPECTED_PERIOD.

The GPR model linearised about the reference state is isotropic linear elasticity with shear modulus
mu = rho0 c_sh^2 (from E_e = c_sh^2/4 |dev G|^2) and bulk modulus K = rho0 c0^2 (the Mie-Grueneisen EOS, f'(1) = 1);
the 2D run is plane strain. Three estimates are printed:
  - Euler-Bernoulli with the plane-strain modulus E' = E / (1 - nu^2): omega = (beta1 L)^2 / L^2 sqrt(E' I / (rho A));
  - Timoshenko (shear deformation and rotary inertia; shear coefficient k = 5/6): root of the free-free frequency
    equation, found by bisection on the determinant of the 4x4 boundary-condition system;
  - a plane-strain finite-element eigenvalue (biquadratic Q9 elements, full 3x3 Gauss, consistent mass) on two
    meshes: this is the reference (the plate is short, L/h = 6, and Euler-Bernoulli overestimates the frequency).
numpy only.

usage: plate_reference_period.py [NX NY]
"""
import math
import sys

import numpy as np

rho0, c0, csh = 1845.0, 7998.0, math.sqrt(151.9e9 / 1845.0)
L, h = 0.06, 0.01
mu = rho0 * csh**2
K = rho0 * c0**2
lam = K - 2.0 * mu / 3.0
E = 9.0 * K * mu / (3.0 * K + mu)
nu = (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu))
Ep = E / (1.0 - nu**2)  # plane strain
b1 = 4.730040744862704


def euler_bernoulli():
    return (b1 / L) ** 2 * math.sqrt(Ep * h**2 / (12.0 * rho0))


def timoshenko():
    """Free-free Timoshenko beam, plane strain (E', mu), k = 5/6: omega of the first bending mode."""
    A, I, k = h, h**3 / 12.0, 5.0 / 6.0
    kGA, EI, rA, rI = k * mu * A, Ep * I, rho0 * A, rho0 * I

    def det(w):
        # w(x) = sum C e^{s x}, phi(x) = sum D e^{s x}; characteristic: EI kGA s^4 + (...) s^2 + ... = 0
        a4 = EI * kGA
        a2 = (EI * rA + kGA * rI) * w**2
        a0 = rA * w**2 * (rI * w**2 - kGA)
        roots = np.roots([a4, 0.0, a2, 0.0, a0]).astype(complex)
        rows = []
        for x in (0.0, L):
            r1, r2 = [], []
            for s in roots:
                # kGA (w'' - phi') + rA w^2 w = 0 with w = e^{sx}, phi = P e^{sx}: P = (kGA s^2 + rA w^2) / (kGA s)
                P = (kGA * s**2 + rA * w**2) / (kGA * s)
                e = np.exp(s * (x - L / 2))
                r1.append(EI * s * P * e)          # moment EI phi' = 0
                r2.append(kGA * (s - P) * e)       # shear kGA (w' - phi) = 0
            rows += [r1, r2]
        M = np.array(rows)
        return np.linalg.det(M / np.abs(M).max(axis=0))

    w_eb = euler_bernoulli()
    ws = np.linspace(0.5 * w_eb, 1.05 * w_eb, 400)
    dd = np.array([det(w) for w in ws])
    # the determinant is real up to a phase that depends on the root ordering; use the phase-free |.| minimum
    mag = np.abs(dd)
    i = int(np.argmin(mag[1:-1])) + 1
    lo, hi = ws[i - 1], ws[i + 1]
    for _ in range(100):
        m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        if abs(det(m1)) < abs(det(m2)):
            hi = m2
        else:
            lo = m1
    return 0.5 * (lo + hi)


def fem(nx, ny):
    """Plane-strain Q9 eigenvalue problem; returns omega of the lowest non-rigid mode symmetric in x
    (the first bending mode; rigid modes have omega ~ 0)."""
    NX, NY = 2 * nx + 1, 2 * ny + 1
    xs = np.linspace(-L / 2, L / 2, NX)
    ys = np.linspace(-h / 2, h / 2, NY)
    nid = lambda i, j: j * NX + i
    ndof = 2 * NX * NY
    Kg = np.zeros((ndof, ndof))
    Mg = np.zeros((ndof, ndof))
    g = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
    wg = np.array([5.0, 8.0, 5.0]) / 9.0
    # 1D quadratic shape functions on [-1, 1] with nodes -1, 0, 1
    N1 = lambda t: np.array([0.5 * t * (t - 1), 1 - t * t, 0.5 * t * (t + 1)])
    dN1 = lambda t: np.array([t - 0.5, -2 * t, t + 0.5])
    D = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
    dx, dy = L / nx, h / ny
    Ke = np.zeros((18, 18))
    Me = np.zeros((18, 18))
    for a, ta in enumerate(g):
        for b, tb in enumerate(g):
            Nx, Ny, dNx, dNy = N1(ta), N1(tb), dN1(ta) * 2 / dx, dN1(tb) * 2 / dy
            N = np.outer(Ny, Nx).ravel()  # local node (j, i) -> j*3+i
            Gx = np.outer(Ny, dNx).ravel()
            Gy = np.outer(dNy, Nx).ravel()
            B = np.zeros((3, 18))
            B[0, 0::2] = Gx
            B[1, 1::2] = Gy
            B[2, 0::2] = Gy
            B[2, 1::2] = Gx
            wJ = wg[a] * wg[b] * dx * dy / 4
            Ke += wJ * B.T @ D @ B
            Nm = np.zeros((2, 18))
            Nm[0, 0::2] = N
            Nm[1, 1::2] = N
            Me += wJ * rho0 * Nm.T @ Nm
    for ej in range(ny):
        for ei in range(nx):
            nodes = [nid(2 * ei + i, 2 * ej + j) for j in range(3) for i in range(3)]
            dofs = np.array([[2 * n, 2 * n + 1] for n in nodes]).ravel()
            Kg[np.ix_(dofs, dofs)] += Ke
            Mg[np.ix_(dofs, dofs)] += Me
    # keep only modes with v_y even in x (u_x odd): restrict to that subspace by symmetric combination
    Lc = np.linalg.cholesky(Mg)
    Li = np.linalg.inv(Lc)
    A = Li @ Kg @ Li.T
    w2, V = np.linalg.eigh(0.5 * (A + A.T))
    modes = Li.T @ V
    X = np.tile(xs, NY)
    for k in range(len(w2)):
        if w2[k] <= 1e-9 * w2[-1]:  # rigid-body modes
            continue
        vy = modes[1::2, k]
        ux = modes[0::2, k]
        # first bending mode: v_y even in x with a dominant y-displacement
        even = np.allclose(vy, vy.reshape(NY, NX)[:, ::-1].ravel(), atol=1e-6 * np.abs(vy).max())
        if even and np.abs(vy).max() > np.abs(ux).max():
            return math.sqrt(w2[k])
    raise RuntimeError("no bending mode found")


print(f"Be: rho0 = {rho0}, mu = rho0 csh^2 = {mu:.4e} Pa, K = rho0 c0^2 = {K:.4e} Pa -> E = {E:.4e} Pa, nu = {nu:.4f};"
      f" plane strain E' = {Ep:.4e} Pa")
w = euler_bernoulli()
print(f"Euler-Bernoulli (plane strain): omega = {w:.5e} rad/s, period = {2 * math.pi / w * 1e6:.3f} us")
w = timoshenko()
print(f"Timoshenko (k = 5/6):           omega = {w:.5e} rad/s, period = {2 * math.pi / w * 1e6:.3f} us")
meshes = [(int(sys.argv[1]), int(sys.argv[2]))] if len(sys.argv) > 2 else [(12, 2), (24, 4)]
for nx, ny in meshes:
    w = fem(nx, ny)
    print(f"plane-strain FEM Q9 {nx}x{ny}:       omega = {w:.5e} rad/s, period = {2 * math.pi / w * 1e6:.3f} us")
