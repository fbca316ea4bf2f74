/*! \file TubeArtery.hpp
 *  \brief Kernels of the 1D arterial model (tube.md 4.2, docs/tube-artery.md): incompressible flow in a tube
 *  with stretchable walls, quasi-static wall law.
 *
 *    d_t A + d_s Q = 0,
 *    d_t Q + d_s(alpha Q^2/A + beta/(3 rho sqrt(A0)) A^{3/2}) = -K_r Q/A,     p = beta (sqrt(A/A0) - 1),
 *
 *  the flux form of (A/rho) d_s p for uniform A0 and beta. Finite volumes on N cells: MC-limited MUSCL slopes,
 *  HLL face fluxes, SSP-RK2 (Heun) in time. One kernel per stage: cell i recomputes both its face fluxes (each
 *  interior face is evaluated twice) so that there is no flux array, no second launch and no atomics. The two
 *  end faces take their flux from a boundary state solved from the outgoing Riemann invariant W = u +- 4c; the
 *  thread of the end cell is the only writer of that end's boundary record (Windkessel pressure, volume that has
 *  crossed the face), which is advanced by the same RK weights as the cells, so volume balances to round-off.
 */
#pragma once

#include <Kokkos_Core.hpp>

namespace unilag::artery
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using StateView = Kokkos::View<double* [2], MemSpace>; //!< (A, Q) per cell
using BoundaryView = Kokkos::View<double[8], MemSpace>;

//! Slots of the boundary record.
enum BoundarySlot : int
{
    kWindkesselPressure = 0, //!< p_C, pressure on the Windkessel capacitor
    kVolumeIn = 1,           //!< integral of the inlet face's volume flux
    kVolumeOut = 2,          //!< integral of the outlet face's volume flux
    kInletArea = 3,          //!< boundary states of the last stage (for output)
    kInletFlow = 4,
    kOutletArea = 5,
    kOutletFlow = 6,
};

enum class InletKind : int
{
    Closed = 0,
    Flux = 1, //!< prescribed Q_in(t)
};
enum class OutletKind : int
{
    Closed = 0,
    Reflection = 1, //!< W2 - W2_0 = -R_t (W1 - W1_0); R_t = 0 is non-reflecting
    Windkessel = 2, //!< RCR: p = p_C + R1 Q, C dp_C/dt = Q - p_C/R2 (venous pressure 0)
};

//! Everything a cell kernel needs, by value (trivially copyable to the device).
struct ArteryConstants
{
    double rho = 1060, A0 = 0, beta = 0, alpha = 1, frictionK = 0, dx = 0;
    InletKind inlet = InletKind::Closed;
    OutletKind outlet = OutletKind::Reflection;
    double reflection = 0;
    double R1 = 0, R2 = 0, C = 0;
};

KOKKOS_INLINE_FUNCTION double pressure(const ArteryConstants& k, double A)
{
    return k.beta * (Kokkos::Experimental::sqrt(A / k.A0) - 1.0);
}
//! c^2 = (A/rho) dp/dA = beta sqrt(A/A0) / (2 rho); at A0 this is Moens-Korteweg, beta/(2 rho).
KOKKOS_INLINE_FUNCTION double waveSpeed(const ArteryConstants& k, double A)
{
    return Kokkos::Experimental::sqrt(k.beta * Kokkos::Experimental::sqrt(A / k.A0) / (2.0 * k.rho));
}
//! Inverse of waveSpeed.
KOKKOS_INLINE_FUNCTION double areaFromSpeed(const ArteryConstants& k, double c)
{
    const double ratio = 2.0 * k.rho * c * c / k.beta; // sqrt(A/A0)
    return k.A0 * ratio * ratio;
}
KOKKOS_INLINE_FUNCTION void physicalFlux(const ArteryConstants& k, double A, double Q, double F[2])
{
    F[0] = Q;
    F[1] = k.alpha * Q * Q / A + k.beta / (3.0 * k.rho * Kokkos::Experimental::sqrt(k.A0)) * A * Kokkos::Experimental::sqrt(A);
}
//! The two characteristic speeds alpha u -+ sqrt(c^2 + alpha (alpha - 1) u^2) (exact for the alpha != 1 flux).
KOKKOS_INLINE_FUNCTION void characteristicSpeeds(const ArteryConstants& k, double A, double Q, double& lo,
                                                 double& hi)
{
    const double u = Q / A, c = waveSpeed(k, A);
    const double root = Kokkos::Experimental::sqrt(c * c + k.alpha * (k.alpha - 1.0) * u * u);
    lo = k.alpha * u - root;
    hi = k.alpha * u + root;
}

//! Monotonised-central limiter: second order where smooth, clips less than minmod at a pulse's crest.
KOKKOS_INLINE_FUNCTION double limitedSlope(double left, double right)
{
    if (left * right <= 0.0)
        return 0.0;
    const double s = left > 0 ? 1.0 : -1.0;
    const double m = Kokkos::Experimental::fmin(Kokkos::Experimental::fmin(2.0 * Kokkos::Experimental::fabs(left), 2.0 * Kokkos::Experimental::fabs(right)),
                                  0.5 * Kokkos::Experimental::fabs(left + right));
    return s * m;
}

KOKKOS_INLINE_FUNCTION void hllFlux(const ArteryConstants& k, const double L[2], const double R[2], double F[2])
{
    double loL, hiL, loR, hiR, FL[2], FR[2];
    characteristicSpeeds(k, L[0], L[1], loL, hiL);
    characteristicSpeeds(k, R[0], R[1], loR, hiR);
    physicalFlux(k, L[0], L[1], FL);
    physicalFlux(k, R[0], R[1], FR);
    const double sL = Kokkos::Experimental::fmin(loL, loR), sR = Kokkos::Experimental::fmax(hiL, hiR);
    for (int m = 0; m < 2; ++m)
    {
        if (sL >= 0)
            F[m] = FL[m];
        else if (sR <= 0)
            F[m] = FR[m];
        else
            F[m] = (sR * FL[m] - sL * FR[m] + sL * sR * (R[m] - L[m])) / (sR - sL);
    }
}

/*! Area on the inlet face with prescribed flux Q that carries the outgoing invariant W2 = Q/A - 4c(A).
 *  Newton from the interior area; f is monotone in A for subcritical flow, so a few steps suffice. */
KOKKOS_INLINE_FUNCTION double inletArea(const ArteryConstants& k, double Q, double W2, double Aguess)
{
    double A = Aguess;
    for (int it = 0; it < 20; ++it)
    {
        const double c = waveSpeed(k, A);
        const double f = Q / A - 4.0 * c - W2;
        const double df = -Q / (A * A) - c / A;
        const double step = f / df;
        A = Kokkos::Experimental::fmax(A - step, 0.25 * A);
        if (Kokkos::Experimental::fabs(step) < 1e-14 * A)
            break;
    }
    return A;
}

/*! Area on an RCR outlet face: p(A) = p_C + R1 A (W1 - 4 c(A)), with the outgoing W1 = u + 4c. */
KOKKOS_INLINE_FUNCTION double windkesselArea(const ArteryConstants& k, double W1, double pC, double Aguess)
{
    double A = Aguess;
    for (int it = 0; it < 30; ++it)
    {
        const double c = waveSpeed(k, A);
        const double f = pressure(k, A) - pC - k.R1 * A * (W1 - 4.0 * c);
        const double df = k.beta / (2.0 * Kokkos::Experimental::sqrt(A * k.A0)) - k.R1 * (W1 - 4.0 * c) + k.R1 * c;
        const double step = f / df;
        A = Kokkos::Experimental::fmax(A - step, 0.25 * A);
        if (Kokkos::Experimental::fabs(step) < 1e-14 * A)
            break;
    }
    return A;
}

/*! One SSP-RK2 stage on cell i: out = a base + b (in + dt L(in)), with (a, b) = (0, 1) then (1/2, 1/2).
 *  `out` may alias `base` (cell i reads base(i) before writing out(i)); `in` must not alias `out`. */
struct ArteryStage
{
    ArteryConstants k;
    StateView in, base, out;
    BoundaryView bcIn, bcBase, bcOut;
    double dt, a, b;
    double inletQ; //!< Q_in at this stage's time
    int n;

    KOKKOS_INLINE_FUNCTION double slope(int i, int m) const
    {
        if (i == 0 || i == n - 1)
            return 0.0; // first order in the two end cells: their outer neighbour is the boundary state
        return limitedSlope(in(i, m) - in(i - 1, m), in(i + 1, m) - in(i, m));
    }
    //! HLL flux on interior face f (between cells f - 1 and f), 1 <= f <= n - 1.
    KOKKOS_INLINE_FUNCTION void interiorFlux(int f, double F[2]) const
    {
        double L[2], R[2];
        for (int m = 0; m < 2; ++m)
        {
            L[m] = in(f - 1, m) + 0.5 * slope(f - 1, m);
            R[m] = in(f, m) - 0.5 * slope(f, m);
        }
        hllFlux(k, L, R, F);
    }
    KOKKOS_INLINE_FUNCTION void inletFlux(double F[2], double& A, double& Q) const
    {
        const double Ai = in(0, 0), Qi = in(0, 1);
        if (k.inlet == InletKind::Closed)
        {
            // u = 0 on the face: W2 = -4c, and the outgoing W2 = u - 4c of the cell fixes c.
            Q = 0.0;
            A = areaFromSpeed(k, waveSpeed(k, Ai) - 0.25 * Qi / Ai);
        }
        else
        {
            Q = inletQ;
            A = inletArea(k, Q, Qi / Ai - 4.0 * waveSpeed(k, Ai), Ai);
        }
        physicalFlux(k, A, Q, F);
        F[0] = Q; // exactly the imposed flux, so that volume balances to round-off
    }
    KOKKOS_INLINE_FUNCTION void outletFlux(double F[2], double& A, double& Q) const
    {
        const double Ai = in(n - 1, 0), Qi = in(n - 1, 1);
        const double W1 = Qi / Ai + 4.0 * waveSpeed(k, Ai);
        const double c0 = waveSpeed(k, k.A0);
        if (k.outlet == OutletKind::Closed)
        {
            Q = 0.0;
            A = areaFromSpeed(k, 0.25 * W1);
        }
        else if (k.outlet == OutletKind::Reflection)
        {
            const double W2 = -4.0 * c0 - k.reflection * (W1 - 4.0 * c0);
            A = areaFromSpeed(k, (W1 - W2) / 8.0);
            Q = A * 0.5 * (W1 + W2);
        }
        else
        {
            A = windkesselArea(k, W1, bcIn(kWindkesselPressure), Ai);
            Q = A * (W1 - 4.0 * waveSpeed(k, A));
        }
        physicalFlux(k, A, Q, F);
        F[0] = Q;
    }
    //! out = a base + b (in + dt rate) for one boundary slot.
    KOKKOS_INLINE_FUNCTION void advanceSlot(int s, double rate) const
    {
        bcOut(s) = a * bcBase(s) + b * (bcIn(s) + dt * rate);
    }

    KOKKOS_INLINE_FUNCTION void operator()(const int i) const
    {
        double FL[2], FR[2], Ab, Qb;
        if (i == 0)
        {
            inletFlux(FL, Ab, Qb);
            advanceSlot(kVolumeIn, FL[0]);
            bcOut(kInletArea) = Ab;
            bcOut(kInletFlow) = Qb;
        }
        else
            interiorFlux(i, FL);
        if (i == n - 1)
        {
            outletFlux(FR, Ab, Qb);
            advanceSlot(kVolumeOut, FR[0]);
            const double pC = bcIn(kWindkesselPressure);
            const double dpC = k.outlet == OutletKind::Windkessel ? (Qb - pC / k.R2) / k.C : 0.0;
            advanceSlot(kWindkesselPressure, dpC);
            bcOut(kOutletArea) = Ab;
            bcOut(kOutletFlow) = Qb;
        }
        else
            interiorFlux(i + 1, FR);
        const double A = in(i, 0), Q = in(i, 1);
        const double rateA = -(FR[0] - FL[0]) / k.dx;
        const double rateQ = -(FR[1] - FL[1]) / k.dx - k.frictionK * Q / A;
        const double newA = a * base(i, 0) + b * (A + dt * rateA);
        const double newQ = a * base(i, 1) + b * (Q + dt * rateQ);
        out(i, 0) = newA;
        out(i, 1) = newQ;
    }
};

//! Largest |characteristic speed| over the cells (for the CFL time step).
struct ArteryMaxSpeed
{
    ArteryConstants k;
    StateView U;
    KOKKOS_INLINE_FUNCTION void operator()(const int i, double& acc) const
    {
        double lo, hi;
        characteristicSpeeds(k, U(i, 0), U(i, 1), lo, hi);
        acc = Kokkos::Experimental::fmax(acc, Kokkos::Experimental::fmax(Kokkos::Experimental::fabs(lo), Kokkos::Experimental::fabs(hi)));
    }
};

//! Sum of A dx (volume of the vessel).
struct ArteryVolume
{
    StateView U;
    double dx;
    KOKKOS_INLINE_FUNCTION void operator()(const int i, double& acc) const { acc += U(i, 0) * dx; }
};

} // namespace unilag::artery
