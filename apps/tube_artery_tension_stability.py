#!/usr/bin/env python3
"""Von Neumann analysis of the artery scheme with the Pedley-Luo tension (docs/tube-artery.md 2).

The linearised scheme about (A0, 0), without friction, in units h = dx = 1, c0 = 1: MUSCL with central slopes
(the MC limiter's choice where the data are smooth), HLL (Rusanov with +-c0 when linear), and the tension source
mu^2 D3 a in q's rate, D3 the centred five-point third difference, mu = sqrt(A0 T / rho) / (c0 dx). For each mu it
prints the largest stable dt c0 / dx of Heun (SSP-RK2) and SSP-RK3, and dt mu = dt sqrt(A0 T / rho) / dx^2, the
figure the code's step limit dt = cfl dx / (c0 + 1.5 sqrt(A T / rho) / dx) must stay inside. Plain Python.
"""
import cmath
import math


def rate_matrix(theta, mu):
    """2x2 symbol of L on (a, q) for the Fourier mode exp(i j theta)."""
    e = cmath.exp(1j * theta)
    left = 1 + 0.5j * math.sin(theta)  # u_j + slope/2, central slope (u_{j+1} - u_{j-1}) / 2
    right = e * (1 - 0.5j * math.sin(theta))
    mean, jump = (left + right) / 2, (right - left) / 2
    d = 1 - 1 / e  # F_{j+1/2} - F_{j-1/2}
    d3 = 1j * (math.sin(2 * theta) - 2 * math.sin(theta))
    # Rusanov face flux F = (F_L + F_R)/2 - (c0/2)(U_R - U_L): F_a = mean q - jump a, F_q = mean a - jump q
    return [[d * jump, -d * mean], [-d * mean + mu * mu * d3, d * jump]]


def amplification(m, dt, order):
    z = [[dt * m[i][j] for j in range(2)] for i in range(2)]
    mul = lambda x, y: [[sum(x[i][k] * y[k][j] for k in range(2)) for j in range(2)] for i in range(2)]
    terms, power, factorial = [z], z, 1
    for n in range(2, order + 1):
        power, factorial = mul(power, z), factorial * n
        terms.append([[v / factorial for v in row] for row in power])
    return [[(1 if i == j else 0) + sum(t[i][j] for t in terms) for j in range(2)] for i in range(2)]


def spectral_radius(g):
    tr, det = g[0][0] + g[1][1], g[0][0] * g[1][1] - g[0][1] * g[1][0]
    root = cmath.sqrt(tr * tr - 4 * det)
    return max(abs((tr + root) / 2), abs((tr - root) / 2))


def largest_dt(mu, order, modes=800):
    stable = lambda dt: all(
        spectral_radius(amplification(rate_matrix(math.pi * (k + 0.5) / modes, mu), dt, order)) <= 1 + 1e-12
        for k in range(modes))
    lo, hi = 0.0, 3.0
    for _ in range(40):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if stable(mid) else (lo, mid)
    return lo


if __name__ == "__main__":
    print("mu, Heun dt c0/dx, RK3 dt c0/dx, RK3 dt mu, code's dt c0/dx at cfl 1 (1 / (1 + 1.5 mu))")
    for mu in [0, 0.3, 1, 3, 10, 30, 100, 1000]:
        d2, d3 = largest_dt(mu, 2), largest_dt(mu, 3)
        print(f"{mu:7.1f} {d2:9.5f} {d3:9.5f} {d3 * mu:7.4f} {1 / (1 + 1.5 * mu):9.5f}")
