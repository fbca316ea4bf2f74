/*! \file TubeWall.hpp
 *  \brief Kernels of the expandable tube wall R(s, t) and of its energy exchange with the gas
 *  (docs/tube-wall.md). Per cell j (the rod's segments): radius R_j, wall speed V_j = dR_j/dt.
 *
 *  Wall energy per unit length (tube.md 1.3, a_s = 0):  a V^2/2 + b (R - R0)^2/2 + p_ext pi R^2,
 *  the last term the work against the outside pressure (the -p_ext Q of the Lagrangian). The exchange step
 *  freezes the gas transport: in each cell xi, m and the entropy are fixed, so the gas internal energy per
 *  length is U(A) = U_n (A_n / A)^(g-1) and the cell is a one-degree-of-freedom Hamiltonian system
 *  H = a V^2/2 + W(R),  W = U(pi R^2) + b (R - R0)^2/2 + p_ext pi R^2  (dW/dR = -(p - p_ext) 2 pi R + b (R - R0)),
 *  plus a viscous wall force -c V. It is advanced by the discrete-gradient (average vector field) rule
 *    R1 - R0 = dt (V0 + V1)/2,   a (V1 - V0) = -dt (W(R1) - W(R0))/(R1 - R0) - c dt (V0 + V1)/2,
 *  which gives exactly  [a V^2/2 + W]_0^1 = -c dt ((V0 + V1)/2)^2: energy moves between gas and wall with no
 *  error but that of the scalar Newton solve and round-off. Kokkos core only, no atomics.
 */
#pragma once

#include <Kokkos_Core.hpp>

#include "unilag/TubeGas.hpp"

namespace unilag::wall
{

using gas::ScalarView;
using gas::StateView;

constexpr double pi = 3.14159265358979323846;

//! Per unit length: a wall mass, b hoop stiffness, c viscous coefficient; rest radius, outside pressure.
struct WallParams
{
    double a, b, c, restRadius, pExt;
};

/*! parallel_for / parallel_reduce on the default execution space, or on Kokkos::Serial for small tubes on a
 *  host backend (GasSetup::serialBelow: a few microseconds of work per launch lose to an OpenMP fork/join, by
 *  100 times on the loaded 2-core box). Host-side helpers. */
template <class Functor> void forEach(const char* name, int n, bool serial, const Functor& f)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (Kokkos::SpaceAccessibility<Kokkos::Serial, gas::MemSpace>::accessible)
        if (serial)
        {
            Kokkos::parallel_for(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f);
            return;
        }
#endif
    (void)serial;
    Kokkos::parallel_for(name, Kokkos::RangePolicy<gas::ExecSpace>(0, n), f);
}

template <class Functor, class Result>
void reduce(const char* name, int n, bool serial, const Functor& f, Result&& result)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (Kokkos::SpaceAccessibility<Kokkos::Serial, gas::MemSpace>::accessible)
        if (serial)
        {
            Kokkos::parallel_reduce(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f, result);
            return;
        }
#endif
    (void)serial;
    Kokkos::parallel_reduce(name, Kokkos::RangePolicy<gas::ExecSpace>(0, n), f, result);
}

//! The wall state per cell on the device: R, dR/dt, energy taken by the viscous force so far.
struct WallViews
{
    ScalarView radius, speed, dissipated;
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

/*! Cells: the exchange step over dt (docs/tube-wall.md 2). Solves F(d) = a (2 d/dt - 2 V0) + dt DW(d) + c d = 0
 *  for d = R1 - R0 by Newton (slope 2a/dt + c + dt W''(R0 + d/2)/2, exact for a quadratic W), then
 *  V1 = 2 d/dt - V0, E += U1 - U0, A = pi R1^2; the dissipated c dt ((V0 + V1)/2)^2 is summed per cell so
 *  that the energy balance can be checked with damping too. */
struct WallExchange
{
    StateView q;
    ScalarView areaCell, radius, speed, dissipated;
    WallParams w;
    double gamma, dt;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double r0 = radius(j), v0 = speed(j);
        const double u0 = q(j, 2) - 0.5 * q(j, 1) * q(j, 1) / q(j, 0); // gas internal energy per length
        double d = dt * v0;
        for (int it = 0; it < 40; ++it)
        {
            const double f = w.a * (2.0 * d / dt - 2.0 * v0) + dt * potentialSlope(w, u0, r0, d, gamma) + w.c * d;
            const double rm = r0 + 0.5 * d;
            const double um = u0 * Kokkos::Experimental::pow(r0 / rm, 2.0 * (gamma - 1.0));
            const double slope = 2.0 * w.a / dt + w.c + 0.5 * dt * potentialCurvature(w, um, rm, gamma);
            const double step = f / slope;
            d -= step;
            if (Kokkos::Experimental::fabs(step) <= 1e-16 * r0)
                break;
        }
        const double v1 = 2.0 * d / dt - v0, vm = 0.5 * (v0 + v1);
        q(j, 2) += adiabaticEnergyChange(u0, r0, d, gamma);
        radius(j) = r0 + d;
        speed(j) = v1;
        areaCell(j) = pi * (r0 + d) * (r0 + d);
        dissipated(j) += w.c * dt * vm * vm;
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

//! max over cells of the wall frequency (W''/a)^(1/2), which bounds the exchange step for accuracy.
struct MaxWallFrequency
{
    StateView q;
    ScalarView radius;
    WallParams w;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& m) const
    {
        const double u = q(j, 2) - 0.5 * q(j, 1) * q(j, 1) / q(j, 0);
        const double omega = Kokkos::Experimental::sqrt(potentialCurvature(w, u, radius(j), gamma) / w.a);
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
