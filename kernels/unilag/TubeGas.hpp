/*! \file TubeGas.hpp
 *  \brief Kernels of the compressible gas in a tube (docs/tube-gas.md): quasi-1D Euler equations per unit
 *  length of the rod's s-grid, finite volumes, HLLC flux, MUSCL on primitive variables, SSP-RK2.
 *
 *  Cells are the rod's segments j = 0..N-1, faces are its nodes f = 0..N (face f between cells f-1 and f).
 *  The tube may be stretched and moving (tube.md 1.8): the gas sees the centreline r(s, t) only through the
 *  metric (c, g, k) = (|r'|^2, r'.r_t, |r_t|^2) (|Gamma|^2, Gamma.gamma, |gamma|^2), frozen during a gas step.
 *  With Q = A sqrt(c), v = u sqrt(c) the gas speed relative to the tube (physical), w = g / sqrt(c) the tube's
 *  own tangential speed, the conserved quantities per unit s are
 *    xi = rho Q,   m = xi (g + u c)  (= xi Gamma.(gamma + u Gamma)),   E = xi (e + v^2/2 - k/2),
 *  and with the metric frozen (docs/tube-gas.md 5)
 *    d_t xi + d_s(xi u) = 0,
 *    d_t m + d_s(u m + p Q) = xi (k'/2 + u g' + u^2 c'/2) + p Q'        (tube.md 1.8 momentum),
 *    d_t E + d_s(xi u (e + p/rho + v^2/2 - k/2)) = 0                     (the frozen tube's energy).
 *  A rigid straight tube at rest is c = 1, g = k = 0: Q = A and the classical quasi-1D Euler equations.
 *  Fluxes are HLLC in the tube's frame on (rho, v, p), Galilean-shifted by w. Primitive arrays carry two ghost
 *  cells on each side (storage index c = j + 2), so that the face kernel reconstructs both sides of every face
 *  with no branch on the position. Kokkos core only, no atomics: every kernel writes only its own cell or face
 *  and gathers its neighbours.
 */
#pragma once

#include <Kokkos_Core.hpp>

namespace unilag::gas
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using StateView = Kokkos::View<double* [3], MemSpace>; //!< (xi, m, E) per cell, or (rho, u, p) with ghosts
using ScalarView = Kokkos::View<double*, MemSpace>;
//! The tube's metric (c, g, k) = (|r'|^2, r'.r_t, |r_t|^2) per cell or face (see the file comment).
using MetricView = Kokkos::View<double* [3], MemSpace>;

constexpr int ghosts = 2;

//! The device state a coupled stepper (src/tube/GasWallCoupling.cpp) reads and writes between gas steps:
//! the conserved (xi, m, E) per cell and the areas, which a moving wall rewrites (docs/tube-wall.md), and the
//! metric of the centreline, which a moving rod rewrites (docs/tube-gas.md 5).
struct GasViews
{
    StateView q;
    ScalarView areaFace, areaCell;
    MetricView metricFace, metricCell;
};

//! Primitive state: density (per volume), velocity along the tangent relative to the tube (physical), pressure.
struct Prim
{
    double rho, u, p;
};
//! A flux per unit area (mass, momentum, energy) of the 1D Euler equations.
struct Flux
{
    double f[3];
};

//! Kinds of tube ends (ghost-cell recipes, see ghostState).
struct End
{
    static constexpr int Wall = 0;           //!< closed end: mirror state, no mass or energy through the face
    static constexpr int Transmissive = 1;   //!< zero gradient: supersonic outflow, or waves leaving
    static constexpr int FixedState = 2;     //!< (rho, u, p) given: supersonic inflow
    static constexpr int PressureOutlet = 3; //!< subsonic outflow at given p: entropy, outgoing invariant kept
    static constexpr int SubsonicInflow = 4; //!< from a reservoir at rest (rho0, p0): entropy, enthalpy kept
};
struct EndParams
{
    int type;
    double rho, u, p;
};

struct Limiter
{
    static constexpr int MinMod = 0;
    static constexpr int VanLeer = 1;
};

KOKKOS_INLINE_FUNCTION double soundSpeed(const Prim& w, double gamma)
{
    return Kokkos::Experimental::sqrt(gamma * w.p / w.rho);
}

//! Limited slope from the two one-sided differences (both limiters are TVD and keep edges between neighbours,
//! so rho and p stay positive at the faces).
KOKKOS_INLINE_FUNCTION double limitedSlope(double dl, double dr, int limiter)
{
    if (dl * dr <= 0.0)
        return 0.0;
    if (limiter == Limiter::VanLeer)
        return 2.0 * dl * dr / (dl + dr);
    return dl > 0.0 ? Kokkos::Experimental::fmin(dl, dr) : Kokkos::Experimental::fmax(dl, dr);
}

//! HLLC flux per unit area (Toro 10.4), Davis wave speeds. The star factor (S - u)/(S - S*) is formed first:
//! for two states at rest with equal p it is exactly 1 and S* exactly 0, so the flux is exactly (0, p, 0)
//! (the well balance of docs/tube-gas.md 2 rests on this).
KOKKOS_INLINE_FUNCTION Flux hllc(const Prim& l, const Prim& r, double gamma)
{
    const double al = soundSpeed(l, gamma), ar = soundSpeed(r, gamma);
    const double sl = Kokkos::Experimental::fmin(l.u - al, r.u - ar),
                 sr = Kokkos::Experimental::fmax(l.u + al, r.u + ar);
    const double el = l.p / (gamma - 1.0) + 0.5 * l.rho * l.u * l.u; // energy per volume
    const double er = r.p / (gamma - 1.0) + 0.5 * r.rho * r.u * r.u;
    Flux f;
    if (sl >= 0.0)
    {
        f.f[0] = l.rho * l.u, f.f[1] = l.rho * l.u * l.u + l.p, f.f[2] = l.u * (el + l.p);
        return f;
    }
    if (sr <= 0.0)
    {
        f.f[0] = r.rho * r.u, f.f[1] = r.rho * r.u * r.u + r.p, f.f[2] = r.u * (er + r.p);
        return f;
    }
    const double ml = l.rho * (sl - l.u), mr = r.rho * (sr - r.u);
    const double ss = (r.p - l.p + l.u * ml - r.u * mr) / (ml - mr);
    const Prim& w = ss >= 0.0 ? l : r;
    const double s = ss >= 0.0 ? sl : sr, e = ss >= 0.0 ? el : er;
    const double c = (s - w.u) / (s - ss);
    const double rs = w.rho * c; // star density
    const double es = c * (e + (ss - w.u) * (w.rho * ss + w.p / (s - w.u)));
    const double u0 = w.rho, u1 = w.rho * w.u;
    f.f[0] = u1 + s * (rs - u0);
    f.f[1] = u1 * w.u + w.p + s * (rs * ss - u1);
    f.f[2] = w.u * (e + w.p) + s * (es - e);
    return f;
}

/*! Subsonic inflow from a reservoir at rest (b.rho, b.p): the entropy and the total enthalpy a0^2/(g-1) of the
 *  reservoir and the outgoing invariant of the interior fix the inflow state. (Imposing rho and u instead is
 *  the textbook choice, but a fixed-velocity inlet with mean flow Mach M reflects acoustic energy with gain
 *  ((1 + M)/(1 - M))^2: against a pressure outlet, the nozzle of docs/tube-gas.md grew instead of settling.)
 *  Works in the inward frame v = -sign u; if the interior pulls outward, v = 0 (the reservoir closes). */
KOKKOS_INLINE_FUNCTION Prim reservoirInflow(const EndParams& b, const Prim& in, double sign, double gamma)
{
    const double g1 = gamma - 1.0;
    const double a0 = Kokkos::Experimental::sqrt(gamma * b.p / b.rho);
    const double jv = -sign * in.u - 2.0 * soundSpeed(in, gamma) / g1; // v - 2a/(g-1), leaving the tube
    // a = (g-1)/2 (v - jv) and a^2/(g-1) + v^2/2 = a0^2/(g-1): a quadratic c2 v^2 + c1 v + c0 = 0
    const double c2 = 0.25 * (g1 + 2.0), c1 = -0.5 * g1 * jv, c0 = 0.25 * g1 * jv * jv - a0 * a0 / g1;
    const double disc = Kokkos::Experimental::fmax(c1 * c1 - 4.0 * c2 * c0, 0.0);
    const double v = Kokkos::Experimental::fmax((-c1 + Kokkos::Experimental::sqrt(disc)) / (2.0 * c2), 0.0);
    const double a = Kokkos::Experimental::fmin(0.5 * g1 * (v - jv), a0);
    const double ratio = a / a0;
    return Prim{b.rho * Kokkos::Experimental::pow(ratio, 2.0 / g1), -sign * v,
                b.p * Kokkos::Experimental::pow(ratio, 2.0 * gamma / g1)};
}

//! Ghost state beyond an end, from the adjacent interior state `in`; `left` says which end (the outgoing
//! characteristic is u + a at the right end, u - a at the left end).
KOKKOS_INLINE_FUNCTION Prim ghostState(const EndParams& b, const Prim& in, bool left, double gamma)
{
    const double g1 = gamma - 1.0;
    const double sign = left ? -1.0 : 1.0;
    switch (b.type)
    {
    case End::Wall:
        return Prim{in.rho, -in.u, in.p};
    case End::FixedState:
        return Prim{b.rho, b.u, b.p};
    case End::PressureOutlet:
    {
        // isentropic from the interior (entropy leaves with u), outgoing invariant u +- 2a/(g-1) kept
        const double rho = in.rho * Kokkos::Experimental::pow(b.p / in.p, 1.0 / gamma);
        const double ai = soundSpeed(in, gamma), ab = Kokkos::Experimental::sqrt(gamma * b.p / rho);
        return Prim{rho, in.u + sign * 2.0 * (ai - ab) / g1, b.p};
    }
    case End::SubsonicInflow:
        return reservoirInflow(b, in, sign, gamma);
    default: // Transmissive
        return in;
    }
}

KOKKOS_INLINE_FUNCTION Prim loadPrim(const StateView& w, int c) { return Prim{w(c, 0), w(c, 1), w(c, 2)}; }

//! Edge value of cell storage c on its right (side = +1) or left (side = -1) face.
KOKKOS_INLINE_FUNCTION Prim edgeValue(const StateView& w, int c, double side, int limiter)
{
    Prim e;
    double* out[3] = {&e.rho, &e.u, &e.p};
    for (int k = 0; k < 3; ++k)
    {
        const double slope = limitedSlope(w(c, k) - w(c - 1, k), w(c + 1, k) - w(c, k), limiter);
        *out[k] = w(c, k) + 0.5 * side * slope;
    }
    return e;
}

//! Cells: (xi, m, E), the cell area and metric -> (rho, v, p) at storage j + ghosts (v relative to the tube).
struct ToPrimitive
{
    StateView q, w;
    ScalarView areaCell;
    MetricView metric;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double c = metric(j, 0), g = metric(j, 1), k = metric(j, 2);
        const double root = Kokkos::Experimental::sqrt(c);
        const double volume = areaCell(j) * root; // Q
        const double rho = q(j, 0) / volume, u = (q(j, 1) / q(j, 0) - g) / c, v = u * root;
        w(j + ghosts, 0) = rho;
        w(j + ghosts, 1) = v;
        w(j + ghosts, 2) = (gamma - 1.0) * ((q(j, 2) + 0.5 * k * q(j, 0)) / volume - 0.5 * rho * v * v);
    }
};

//! The 2 x 2 ghost cells: k = 0, 1 left (storage 1 - k mirrors/extends storage ghosts + k), k = 2, 3 right.
struct FillGhosts
{
    StateView w;
    EndParams left, right;
    int n;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        const bool isLeft = k < 2;
        const int depth = k % 2; // 0: next to the end
        const int ghost = isLeft ? ghosts - 1 - depth : n + ghosts + depth;
        const EndParams& b = isLeft ? left : right;
        // a wall mirrors cell by cell; the other ends extend the state next to the end
        const int mirrorDepth = b.type == End::Wall ? depth : 0;
        const int inner = isLeft ? ghosts + mirrorDepth : n + ghosts - 1 - mirrorDepth;
        const Prim g = ghostState(b, loadPrim(w, inner), isLeft, gamma);
        w(ghost, 0) = g.rho;
        w(ghost, 1) = g.u;
        w(ghost, 2) = g.p;
    }
};

/*! Faces f = 0..N: the tube frame's HLLC flux (per area: mass F0, momentum F1, energy F2), shifted to the
 *  conserved quantities per unit s: flux(f, 0) = A_f F0 (xi u), flux(f, 2) = A_f (F2 - k_f F0 / 2), and
 *  flux(f, 1) = F1 + w_f F0, the momentum flux per unit Q: the cell update multiplies it by Q_f after subtracting
 *  the cell's own pressure, which keeps a gas at rest at rest in any tube. At a wall no mass or energy passes
 *  (the end cap moves with the tube). */
struct FaceFlux
{
    StateView w, flux;
    ScalarView areaFace;
    MetricView metric;
    int n, limiter;
    bool wallLeft, wallRight;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int f) const
    {
        const int cl = f + ghosts - 1, cr = f + ghosts; // storage of the cells left and right of face f
        const Prim l = edgeValue(w, cl, 1.0, limiter), r = edgeValue(w, cr, -1.0, limiter);
        const Flux h = hllc(l, r, gamma);
        const bool wall = (f == 0 && wallLeft) || (f == n && wallRight);
        const double a = areaFace(f), c = metric(f, 0), k = metric(f, 2);
        const double tubeSpeed = metric(f, 1) / Kokkos::Experimental::sqrt(c); // w
        flux(f, 0) = wall ? 0.0 : a * h.f[0];
        flux(f, 1) = h.f[1] + tubeSpeed * h.f[0];
        flux(f, 2) = wall ? 0.0 : a * (h.f[2] - 0.5 * k * h.f[0]);
    }
};

/*! Cells: out = alpha base + beta (cur + dt L(cur)), L the semi-discrete right-hand side. SSP-RK2 is
 *  (alpha, beta) = (0, 1) then (1/2, 1/2). out may alias base or cur: each cell reads only its own entry.
 *  Momentum: -(Q_R (F_R - p_j) - Q_L (F_L - p_j))/h = -(Q_R F_R - Q_L F_L)/h + p_j (Q_R - Q_L)/h, the pressure
 *  source p dQ/ds with the cell-centre p (second order), written so that F = p_j gives exactly zero; plus the
 *  moving tube's xi (k'/2 + u g' + u^2 c'/2) from the face metrics (zero for a uniform metric). */
struct CellUpdate
{
    StateView out, base, cur, w, flux;
    ScalarView areaFace;
    MetricView metricFace, metricCell;
    double alpha, beta, dt, h;
    KOKKOS_INLINE_FUNCTION double inertialSource(int j) const
    {
        const double u = w(j + ghosts, 1) / Kokkos::Experimental::sqrt(metricCell(j, 0));
        const double dc = metricFace(j + 1, 0) - metricFace(j, 0), dg = metricFace(j + 1, 1) - metricFace(j, 1),
                     dk = metricFace(j + 1, 2) - metricFace(j, 2);
        return cur(j, 0) * (0.5 * dk + u * dg + 0.5 * u * u * dc) / h;
    }
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double p = w(j + ghosts, 2);
        const double ql = areaFace(j) * Kokkos::Experimental::sqrt(metricFace(j, 0)),
                     qr = areaFace(j + 1) * Kokkos::Experimental::sqrt(metricFace(j + 1, 0));
        const double dm = -(qr * (flux(j + 1, 1) - p) - ql * (flux(j, 1) - p)) / h + inertialSource(j);
        const double d[3] = {-(flux(j + 1, 0) - flux(j, 0)) / h, dm, -(flux(j + 1, 2) - flux(j, 2)) / h};
        for (int k = 0; k < 3; ++k)
            out(j, k) = alpha * base(j, k) + beta * (cur(j, k) + dt * d[k]);
    }
};

//! max over cells of (|v| + a) / sqrt(c), the signal speed in s per time, for the CFL step (storage j + ghosts).
struct MaxSignalSpeed
{
    StateView w;
    MetricView metric;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& m) const
    {
        const Prim p = loadPrim(w, j + ghosts);
        const double s =
            (Kokkos::Experimental::fabs(p.u) + soundSpeed(p, gamma)) / Kokkos::Experimental::sqrt(metric(j, 0));
        m = s > m ? s : m;
    }
};

//! Sum over cells of component k of q, times h (mass for k = 0, energy for k = 2).
struct Integral
{
    StateView q;
    int k;
    double h;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& sum) const { sum += h * q(j, k); }
};

//! Counts the cells whose conserved state is not finite: the run's stop test, one integer to the host.
struct NonFiniteCells
{
    StateView q;
    KOKKOS_INLINE_FUNCTION void operator()(int j, int& bad) const
    {
        const bool ok = Kokkos::Experimental::isfinite(q(j, 0)) && Kokkos::Experimental::isfinite(q(j, 1)) &&
                        Kokkos::Experimental::isfinite(q(j, 2));
        bad += ok ? 0 : 1;
    }
};

/*! The last face f = i + 1 (i = 0 .. n - 2) where the pressure (primitives w, with ghosts) falls through `level`
 *  from cell f - 1 to cell f: a max-reduction, so a run tracks its shock without copying the state to the host. */
struct LastPressureCrossing
{
    StateView w;
    double level;
    KOKKOS_INLINE_FUNCTION void operator()(int i, int& last) const
    {
        const int f = i + 1;
        if (w(f - 1 + ghosts, 2) >= level && w(f + ghosts, 2) < level && f > last)
            last = f;
    }
};

} // namespace unilag::gas
