/*! \file TubeWall.hpp
 *  \brief Kernels of the expandable tube wall R(s, t) and of its energy exchange with the gas
 *  (docs/tube-wall.md). Per cell j (the rod's segments): radius R_j, wall speed V_j = dR_j/dt.
 *
 *  Wall energy per unit length (tube.md 1.3):  a V^2/2 + b (R - R0)^2/2 + a_s R'^2/2 + p_ext pi R^2, the last
 *  term the work against the outside pressure (the -p_ext Q of the Lagrangian). a_s = 2 pi R0 N_x, N_x an axial
 *  membrane pre-tension (N/m): a generator of length ds tilted by R' is longer by R'^2 ds/2, and N_x on the
 *  circumference 2 pi R0 does that work. On the grid: sum over interior faces of a_s/2 ((R_{j+1} - R_j)/h)^2 h
 *  (zero slope at the ends), whose gradient per length is -a_s (L R)_j, L the Neumann second difference.
 *  The exchange step freezes the gas transport: in each cell xi, m and the entropy are fixed, so the gas internal
 *  energy per length is U(A) = U_n (A_n / A)^(g-1) and (a_s = 0) the cell is a one-degree-of-freedom system
 *  H = a V^2/2 + W(R),  W = U(pi R^2) + b (R - R0)^2/2 + p_ext pi R^2  (dW/dR = -(p - p_ext) 2 pi R + b (R - R0)),
 *  plus a viscous wall force -c V. It is advanced by the discrete-gradient (average vector field) rule
 *    R1 - R0 = dt (V0 + V1)/2,   a (V1 - V0) = -dt (W(R1) - W(R0))/(R1 - R0) - c dt (V0 + V1)/2,
 *  which gives exactly  [a V^2/2 + W]_0^1 = -c dt ((V0 + V1)/2)^2: energy moves between gas and wall with no
 *  error but that of the scalar Newton solve and round-off (a_s > 0: WallExchangeTension). Kokkos core only, no
 *  atomics.
 */
#pragma once

#include <Kokkos_Core.hpp>

#include "unilag/TubeGas.hpp"

namespace unilag::wall
{

using gas::ScalarView;
using gas::StateView;

constexpr double pi = 3.14159265358979323846;

//! Per unit length: a wall mass, b hoop stiffness, c viscous coefficient; rest radius, outside pressure; as the
//! axial tension coefficient (energy a_s R'^2/2).
struct WallParams
{
    double a, b, c, restRadius, pExt, as;
};

//! The wall state per cell on the device: R, dR/dt, energy taken by the viscous force so far; scratch for the
//! exchange with axial tension (its Newton step and Thomas sweep; allocated only when a_s > 0).
struct WallViews
{
    ScalarView radius, speed, dissipated;
    ScalarView step, cPrime, rPrime;
};

//! Gas internal energy change U(A1) - U(A0) for an adiabatic change of the cell area from pi R0^2 to
//! pi (R0 + d)^2 at fixed xi and entropy, written with log1p/expm1 so that it stays accurate for tiny d.
KOKKOS_INLINE_FUNCTION double adiabaticEnergyChange(double u0, double r0, double d, double gamma)
{
    const double relativeArea = d * (2.0 * r0 + d) / (r0 * r0); // (A1 - A0)/A0
    return u0 * Kokkos::Experimental::expm1(-(gamma - 1.0) * Kokkos::Experimental::log1p(relativeArea));
}

//! Discrete gradient (W(R0 + d) - W(R0))/d of the cell potential; its d -> 0 limit at d == 0.
KOKKOS_INLINE_FUNCTION double potentialSlope(const WallParams& w, double u0, double r0, double d, double gamma)
{
    const double elastic = w.b * (r0 + 0.5 * d - w.restRadius); // exact quotient of a quadratic
    const double outside = w.pExt * pi * (2.0 * r0 + d);
    const double gasPart = d != 0.0 ? adiabaticEnergyChange(u0, r0, d, gamma) / d : -2.0 * (gamma - 1.0) * u0 / r0;
    return elastic + outside + gasPart;
}

//! d^2W/dR^2 at R (the Newton slope, and the wall frequency (W''/a)^(1/2)); u the gas energy at R.
KOKKOS_INLINE_FUNCTION double potentialCurvature(const WallParams& w, double u, double r, double gamma)
{
    return w.b + 2.0 * pi * w.pExt + 2.0 * (gamma - 1.0) * (2.0 * gamma - 1.0) * u / (r * r);
}

//! Gas internal energy per length of cell j.
KOKKOS_INLINE_FUNCTION double internalEnergy(const StateView& q, int j)
{
    return q(j, 2) - 0.5 * q(j, 1) * q(j, 1) / q(j, 0);
}

/*! One cell's exchange equation for d = R1 - R0 without the tension: F(d) = a (2 d/dt - 2 V0) + dt DW(d) + c d,
 *  and its Newton slope 2a/dt + c + dt W''(R0 + d/2)/2 (exact for a quadratic W). */
struct CellExchange
{
    WallParams w;
    double u0, r0, v0, gamma, dt;
    KOKKOS_INLINE_FUNCTION double residual(double d) const
    {
        return w.a * (2.0 * d / dt - 2.0 * v0) + dt * potentialSlope(w, u0, r0, d, gamma) + w.c * d;
    }
    KOKKOS_INLINE_FUNCTION double slope(double d) const
    {
        const double rm = r0 + 0.5 * d;
        const double um = u0 * Kokkos::Experimental::pow(r0 / rm, 2.0 * (gamma - 1.0));
        return 2.0 * w.a / dt + w.c + 0.5 * dt * potentialCurvature(w, um, rm, gamma);
    }
};

//! d = R1 - R0 from F(d) = 0 by Newton, from the free flight d = dt V0.
KOKKOS_INLINE_FUNCTION double solveExchange(const CellExchange& x)
{
    double d = x.dt * x.v0;
    for (int it = 0; it < 40; ++it)
    {
        const double step = x.residual(d) / x.slope(d);
        d -= step;
        if (Kokkos::Experimental::fabs(step) <= 1e-16 * x.r0)
            break;
    }
    return d;
}

//! The state after cell j's exchange by d: V1 = 2 d/dt - V0, E += U1 - U0, A = pi R1^2, the viscous loss summed.
KOKKOS_INLINE_FUNCTION void finishExchange(const StateView& q, const ScalarView& areaCell, const ScalarView& radius,
                                           const ScalarView& speed, const ScalarView& dissipated, const CellExchange& x,
                                           int j, double d)
{
    const double v1 = 2.0 * d / x.dt - x.v0, vm = 0.5 * (x.v0 + v1);
    q(j, 2) += adiabaticEnergyChange(x.u0, x.r0, d, x.gamma);
    radius(j) = x.r0 + d;
    speed(j) = v1;
    areaCell(j) = pi * (x.r0 + d) * (x.r0 + d);
    dissipated(j) += x.w.c * x.dt * vm * vm;
}

/*! Cells: the exchange step over dt without axial tension (docs/tube-wall.md 2): each cell alone, F(d) = 0 by
 *  Newton, then finishExchange; the dissipated c dt ((V0 + V1)/2)^2 is summed per cell so that the energy
 *  balance can be checked with damping too. */
struct WallExchange
{
    StateView q;
    ScalarView areaCell, radius, speed, dissipated;
    WallParams w;
    double gamma, dt;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const CellExchange x{w, internalEnergy(q, j), radius(j), speed(j), gamma, dt};
        finishExchange(q, areaCell, radius, speed, dissipated, x, j, solveExchange(x));
    }
};

/*! The exchange step with axial tension a_s > 0: the cells are coupled by the tension force a_s (L R)_j, taken at
 *  the midpoint (R0 + R1)/2. That is the average-vector-field discrete gradient of the quadratic tension energy,
 *  so [kinetic + W + tension]_0^1 = -viscous loss exactly, as without tension. Newton on the whole tube: each
 *  iteration solves the tridiagonal Jacobian (cell slopes + dt a_s/(2 h^2) per neighbour on the diagonal,
 *  -dt a_s/(2 h^2) off it) by a Thomas sweep. The sweep is sequential, hence ONE work item (RangePolicy(0, 1));
 *  the tubes are small (10^2-10^4 cells) so it costs about what the per-cell kernel does on a host backend; a
 *  GPU version would use cyclic reduction. Scratch: d (the step R1 - R0), and the sweep's c' and r'.
 *  Why not a separate split part d2R/dt2 = (a_s/a) R_ss for the wall alone: both it and the exchange would advance
 *  R by V dt, counting the wall velocity twice; a tension kick (R frozen) is not energy-exact. */
struct WallExchangeTension
{
    StateView q;
    ScalarView areaCell, radius, speed, dissipated, d, cPrime, rPrime;
    WallParams w;
    double gamma, dt, h;
    int n;
    KOKKOS_INLINE_FUNCTION CellExchange cell(int j) const
    {
        return CellExchange{w, internalEnergy(q, j), radius(j), speed(j), gamma, dt};
    }
    //! Midpoint R of cell j (R0 + d/2), the Neumann ends replacing a missing neighbour by the cell itself.
    KOKKOS_INLINE_FUNCTION double mid(int j) const { return radius(j) + 0.5 * d(j); }
    //! dt a_s (L R_mid)_j, the tension impulse on cell j.
    KOKKOS_INLINE_FUNCTION double tension(int j) const
    {
        const double left = j > 0 ? mid(j - 1) - mid(j) : 0.0, right = j < n - 1 ? mid(j + 1) - mid(j) : 0.0;
        return dt * w.as * (left + right) / (h * h);
    }
    //! One Newton iteration (Thomas sweep on the Jacobian); returns max |delta_j| / R0_j.
    KOKKOS_INLINE_FUNCTION double newtonStep() const
    {
        const double off = -0.5 * dt * w.as / (h * h);
        double previousC = 0.0, previousR = 0.0;
        for (int j = 0; j < n; ++j) // forward: c'_j = off / m, r'_j = (F_j - off r'_{j-1}) / m
        {
            const CellExchange x = cell(j);
            const double neighbours = (j > 0 ? 1.0 : 0.0) + (j < n - 1 ? 1.0 : 0.0);
            const double diagonal = x.slope(d(j)) - neighbours * off;
            const double m = diagonal - off * previousC;
            previousC = off / m;
            previousR = (x.residual(d(j)) - tension(j) - off * previousR) / m;
            cPrime(j) = previousC;
            rPrime(j) = previousR;
        }
        double worst = 0.0, delta = 0.0;
        for (int j = n - 1; j >= 0; --j) // backward: delta_j = r'_j - c'_j delta_{j+1}
        {
            delta = rPrime(j) - (j < n - 1 ? cPrime(j) * delta : 0.0);
            rPrime(j) = delta;
            const double relative = Kokkos::Experimental::fabs(delta) / radius(j);
            worst = relative > worst ? relative : worst;
        }
        for (int j = 0; j < n; ++j) // after the sweep: the residuals above all used the old d
            d(j) -= rPrime(j);
        return worst;
    }
    KOKKOS_INLINE_FUNCTION void operator()(int) const
    {
        for (int j = 0; j < n; ++j)
            d(j) = dt * speed(j);
        for (int it = 0; it < 40; ++it)
            if (newtonStep() <= 1e-16)
                break;
        for (int j = 0; j < n; ++j)
            finishExchange(q, areaCell, radius, speed, dissipated, cell(j), j, d(j));
    }
};

//! Cells: A = pi R^2 (the initial areas; the exchange step keeps them so).
struct CellAreasFromRadius
{
    ScalarView areaCell, radius;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const { areaCell(j) = pi * radius(j) * radius(j); }
};

//! Faces f = 0..N: mean of the two cells' areas; an end face takes its cell's (a closed end has no flux,
//! and the momentum source there is p_j (A_R - A_L) with the same A on both sides of the end cell's face).
struct FaceAreasFromCells
{
    ScalarView areaFace, areaCell;
    int n;
    KOKKOS_INLINE_FUNCTION void operator()(int f) const
    {
        const int l = f > 0 ? f - 1 : 0, r = f < n ? f : n - 1;
        areaFace(f) = 0.5 * (areaCell(l) + areaCell(r));
    }
};

//! One wall energy part summed over cells times h: part 0 kinetic a V^2/2, 1 elastic b (R - R0)^2/2,
//! 2 outside p_ext pi R^2.
struct WallEnergyPart
{
    ScalarView radius, speed;
    WallParams w;
    double h;
    int part;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& sum) const
    {
        const double r = radius(j), v = speed(j);
        if (part == 0)
            sum += h * 0.5 * w.a * v * v;
        else if (part == 1)
            sum += h * 0.5 * w.b * (r - w.restRadius) * (r - w.restRadius);
        else
            sum += h * w.pExt * pi * r * r;
    }
};

//! Interior faces f = 0..N-2: the tension energy a_s/2 ((R_{f+1} - R_f)/h)^2 h (zero slope at the ends).
struct WallTensionEnergy
{
    ScalarView radius;
    double as, h;
    KOKKOS_INLINE_FUNCTION void operator()(int f, double& sum) const
    {
        const double slope = (radius(f + 1) - radius(f)) / h;
        sum += h * 0.5 * as * slope * slope;
    }
};

/*! max over cells of the wall frequency ((W'' + 4 a_s/h^2)/a)^(1/2), which bounds the exchange step for accuracy:
 *  4 a_s/h^2 bounds the tension's stiffness (the largest eigenvalue of -a_s L), the grid's shortest wave. */
struct MaxWallFrequency
{
    StateView q;
    ScalarView radius;
    WallParams w;
    double gamma, h;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& m) const
    {
        const double stiffness = potentialCurvature(w, internalEnergy(q, j), radius(j), gamma) + 4.0 * w.as / (h * h);
        const double omega = Kokkos::Experimental::sqrt(stiffness / w.a);
        m = omega > m ? omega : m;
    }
};

//! Sum over cells of v(j) times h (the dissipated energy).
struct SumTimesH
{
    ScalarView v;
    double h;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& sum) const { sum += h * v(j); }
};

} // namespace unilag::wall
