/*! \file TubeArtery.hpp
 *  \brief Kernels of the 1D arterial model (tube.md 4.2, docs/tube-artery.md): incompressible flow in a tube
 *  with stretchable walls, quasi-static wall law.
 *
 *    d_t A + d_s Q = 0,
 *    d_t Q + d_s(alpha Q^2/A + beta/(3 rho sqrt(A0)) A^{3/2}) = -K_r Q/A,     p = beta (sqrt(A/A0) - 1),
 *
 *  the flux form of (A/rho) d_s p for uniform A0 and beta. Finite volumes on N cells: MC-limited MUSCL slopes,
 *  HLL face fluxes, SSP-RK2 (Heun) in time. Two kernels per stage: face fluxes (faces 0..N), then cells, so each
 *  flux is computed once and each cell only reads its two faces (no atomics). The two end faces take their flux
 *  from a boundary state solved from the outgoing Riemann invariant W = u +- 4c; the end face's thread is the only
 *  writer of that end's boundary record (Windkessel pressure, volume that has crossed the face), which advances
 *  with the same RK weights as the cells, so volume balances to round-off.
 *
 *  Longitudinal wall tension (Pedley & Luo 1998; tube.md 4.1): p = beta (sqrt(A/A0) - 1) - T d_ss A. An axial
 *  pre-tension force F_z (N) in a wall of small axial slope adds -N_z d_ss R to the Laplace law, N_z = F_z/(2 pi R0)
 *  per unit circumference; with d_ss R ~ d_ss A / (2 pi R0) near A0 this is T = F_z / (4 pi A0) (Pa). The momentum
 *  equation gains the source +(A/rho) T d_sss A, which is dispersive: linearised about (A0, 0) without friction,
 *  omega^2 = k^2 (c0^2 + A0 T k^2 / rho). It is the centred five-point third difference at cell centres, with
 *  mirror ghosts A_{-1-j} = A_j at both ends (clamped wall slope, d_s A = 0). T = 0 skips it and keeps Heun, bit
 *  for bit; T > 0 steps with SSP-RK3, whose stability region holds a segment of the imaginary axis, where the
 *  dispersive eigenvalues lie (Heun's only touches it at 0), with the step limit of kTensionStepFactor.
 */
#pragma once

#include <Kokkos_Core.hpp>

namespace unilag::artery
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using StateView = Kokkos::View<double* [2], MemSpace>; //!< (A, Q) per cell
using BoundaryView = Kokkos::View<double[8], MemSpace>;

/*! The tension's step limit: the dispersive eigenvalues reach omega ~ sqrt(A T / rho) / dx^2 (a fourth-order operator
 *  overall: mass flux d_s Q times the third difference). A von Neumann analysis of the linearised scheme (MUSCL with
 *  central slopes, HLL, SSP-RK3) gives the largest stable dt sqrt(A0 T / rho) / dx^2 as 0.93, 1.09, 0.88, 0.87 at
 *  mu = sqrt(A0 T / rho) / (c0 dx) = 1, 3, 100, 1000; 1.5 keeps cfl <= 1 inside it at every mu (0.77 of it at large
 *  mu with cfl = 1). */
constexpr double kTensionStepFactor = 1.5;

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

//! Everything a kernel needs, by value (trivially copyable to the device). setDerived() after filling.
struct ArteryConstants
{
    double rho = 1060, A0 = 0, beta = 0, alpha = 1, frictionK = 0, dx = 0;
    InletKind inlet = InletKind::Closed;
    OutletKind outlet = OutletKind::Reflection;
    double reflection = 0;
    double R1 = 0, R2 = 0, C = 0;
    double tension = 0; //!< T (Pa) of p = beta (sqrt(A/A0) - 1) - T d_ss A; 0 switches the term off
    int n = 0;          //!< cells
    // Derived, so that a face state costs three square roots: sqrt(A), c, and the alpha != 1 root.
    double sqrtA0 = 0, speedK = 0, fluxK = 0; //!< sqrt(A0), beta/(2 rho sqrt(A0)), beta/(3 rho sqrt(A0))
    double tensionK = 0, tensionSpeedK = 0;   //!< T/(2 rho dx^3); kTensionStepFactor sqrt(T/rho)/dx
    void setDerived()
    {
        sqrtA0 = Kokkos::Experimental::sqrt(A0);
        speedK = beta / (2.0 * rho * sqrtA0);
        fluxK = beta / (3.0 * rho * sqrtA0);
        tensionK = tension / (2.0 * rho * dx * dx * dx);
        tensionSpeedK = kTensionStepFactor * Kokkos::Experimental::sqrt(tension / rho) / dx;
    }
};

KOKKOS_INLINE_FUNCTION double pressure(const ArteryConstants& k, double A)
{
    return k.beta * (Kokkos::Experimental::sqrt(A) / k.sqrtA0 - 1.0);
}
//! c^2 = (A/rho) dp/dA = beta sqrt(A/A0) / (2 rho); at A0 this is Moens-Korteweg, beta/(2 rho).
KOKKOS_INLINE_FUNCTION double waveSpeed(const ArteryConstants& k, double A)
{
    return Kokkos::Experimental::sqrt(k.speedK * Kokkos::Experimental::sqrt(A));
}
//! Inverse of waveSpeed.
KOKKOS_INLINE_FUNCTION double areaFromSpeed(const ArteryConstants& k, double c)
{
    const double ratio = 2.0 * k.rho * c * c / k.beta; // sqrt(A/A0)
    return k.A0 * ratio * ratio;
}

//! A state with the flux and characteristic speeds alpha u -+ sqrt(c^2 + alpha (alpha - 1) u^2) it implies.
struct ArteryFaceState
{
    double U[2], F[2], lo, hi;
};

KOKKOS_INLINE_FUNCTION ArteryFaceState faceState(const ArteryConstants& k, double A, double Q)
{
    ArteryFaceState s;
    const double sqrtA = Kokkos::Experimental::sqrt(A), u = Q / A;
    const double c2 = k.speedK * sqrtA;
    const double root = Kokkos::Experimental::sqrt(c2 + k.alpha * (k.alpha - 1.0) * u * u);
    s.U[0] = A;
    s.U[1] = Q;
    s.F[0] = Q;
    s.F[1] = k.alpha * Q * u + k.fluxK * A * sqrtA; // (A/rho) d_s p = d_s(beta A^{3/2} / (3 rho sqrt(A0)))
    s.lo = k.alpha * u - root;
    s.hi = k.alpha * u + root;
    return s;
}

//! Monotonised-central limiter: second order where smooth, clips less than minmod at a pulse's crest.
KOKKOS_INLINE_FUNCTION double limitedSlope(double left, double right)
{
    if (left * right <= 0.0)
        return 0.0;
    const double s = left > 0 ? 1.0 : -1.0;
    const double m = Kokkos::Experimental::fmin(
        Kokkos::Experimental::fmin(2.0 * Kokkos::Experimental::fabs(left), 2.0 * Kokkos::Experimental::fabs(right)),
        0.5 * Kokkos::Experimental::fabs(left + right));
    return s * m;
}

KOKKOS_INLINE_FUNCTION void hllFlux(const ArteryFaceState& L, const ArteryFaceState& R, double F[2])
{
    const double sL = Kokkos::Experimental::fmin(L.lo, R.lo), sR = Kokkos::Experimental::fmax(L.hi, R.hi);
    for (int m = 0; m < 2; ++m)
    {
        if (sL >= 0)
            F[m] = L.F[m];
        else if (sR <= 0)
            F[m] = R.F[m];
        else
            F[m] = (sR * L.F[m] - sL * R.F[m] + sL * sR * (R.U[m] - L.U[m])) / (sR - sL);
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
        const double df = k.beta / (2.0 * Kokkos::Experimental::sqrt(A) * k.sqrtA0) - k.R1 * (W1 - 4.0 * c) + k.R1 * c;
        const double step = f / df;
        A = Kokkos::Experimental::fmax(A - step, 0.25 * A);
        if (Kokkos::Experimental::fabs(step) < 1e-14 * A)
            break;
    }
    return A;
}

/*! Face fluxes of one SSP-RK2 stage, faces f = 0..n (face f joins cells f - 1 and f). The end faces also advance
 *  the boundary record: bcOut = a bcBase + b (bcIn + dt rate), the same weights as the cells, so the volume that
 *  crossed a face is integrated exactly as the cells integrate it. `bcOut` may alias `bcBase`, not `bcIn`. */
struct ArteryFaceFlux
{
    ArteryConstants k;
    StateView in;
    Kokkos::View<double* [2], MemSpace> flux;
    BoundaryView bcIn, bcBase, bcOut;
    double dt, a, b;
    double inletQ; //!< Q_in at this stage's time
    int n;
    bool record = true; //!< write this stage's boundary states (output); false copies them from bcIn

    KOKKOS_INLINE_FUNCTION double slope(int i, int m) const
    {
        if (i == 0 || i == n - 1)
            return 0.0; // first order in the two end cells: their outer neighbour is the boundary state
        return limitedSlope(in(i, m) - in(i - 1, m), in(i + 1, m) - in(i, m));
    }
    KOKKOS_INLINE_FUNCTION void interiorFlux(int f) const
    {
        const ArteryFaceState L =
            faceState(k, in(f - 1, 0) + 0.5 * slope(f - 1, 0), in(f - 1, 1) + 0.5 * slope(f - 1, 1));
        const ArteryFaceState R = faceState(k, in(f, 0) - 0.5 * slope(f, 0), in(f, 1) - 0.5 * slope(f, 1));
        double F[2];
        hllFlux(L, R, F);
        flux(f, 0) = F[0];
        flux(f, 1) = F[1];
    }
    //! Boundary state (A, Q) on the inlet face from the outgoing invariant W2 = u - 4c of cell 0.
    KOKKOS_INLINE_FUNCTION void inletState(double& A, double& Q) const
    {
        const double Ai = in(0, 0), Qi = in(0, 1);
        const double W2 = Qi / Ai - 4.0 * waveSpeed(k, Ai);
        if (k.inlet == InletKind::Closed)
        {
            Q = 0.0;
            A = areaFromSpeed(k, -0.25 * W2); // u = 0 on the face: W2 = -4c
        }
        else
        {
            Q = inletQ;
            A = inletArea(k, Q, W2, Ai);
        }
    }
    //! Boundary state on the outlet face from the outgoing invariant W1 = u + 4c of cell n - 1.
    KOKKOS_INLINE_FUNCTION void outletState(double& A, double& Q) const
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
    }
    KOKKOS_INLINE_FUNCTION void advanceSlot(int s, double rate) const
    {
        bcOut(s) = a * bcBase(s) + b * (bcIn(s) + dt * rate);
    }
    KOKKOS_INLINE_FUNCTION void boundaryFlux(int f, double A, double Q) const
    {
        const ArteryFaceState s = faceState(k, A, Q);
        flux(f, 0) = Q; // exactly the imposed or solved flux (a closed end gets an exact zero)
        flux(f, 1) = s.F[1];
    }

    KOKKOS_INLINE_FUNCTION void operator()(const int f) const
    {
        double A, Q;
        if (f > 0 && f < n)
            interiorFlux(f);
        else if (f == 0)
        {
            inletState(A, Q);
            boundaryFlux(0, A, Q);
            advanceSlot(kVolumeIn, Q);
            bcOut(kInletArea) = record ? A : bcIn(kInletArea);
            bcOut(kInletFlow) = record ? Q : bcIn(kInletFlow);
        }
        else
        {
            outletState(A, Q);
            boundaryFlux(n, A, Q);
            advanceSlot(kVolumeOut, Q);
            const double pC = bcIn(kWindkesselPressure);
            advanceSlot(kWindkesselPressure, k.outlet == OutletKind::Windkessel ? (Q - pC / k.R2) / k.C : 0.0);
            bcOut(kOutletArea) = record ? A : bcIn(kOutletArea);
            bcOut(kOutletFlow) = record ? Q : bcIn(kOutletFlow);
        }
    }
};

/*! Cell update of one Runge-Kutta stage: out = a base + b (in + dt L(in)); SSP-RK2 (a, b) = (0, 1), (1/2, 1/2),
 *  SSP-RK3 (0, 1), (3/4, 1/4), (1/3, 2/3). L = flux difference plus the friction source -K_r Q/A and, for T > 0, the
 *  tension source (A/rho) T d_sss A. `out` may alias `base`, not `in`. */
struct ArteryCellUpdate
{
    ArteryConstants k;
    StateView in, base, out;
    Kokkos::View<double* [2], MemSpace> flux;
    double dt, a, b;

    //! Area of cell j, mirrored about the end faces for j < 0 or j >= n (d_s A = 0 there); n >= 2 keeps j in range.
    KOKKOS_INLINE_FUNCTION double mirroredArea(int j) const
    {
        if (j < 0)
            j = -1 - j;
        else if (j >= k.n)
            j = 2 * k.n - 1 - j;
        return in(j, 0);
    }
    //! (A/rho) T d_sss A with (A_{i+2} - 2 A_{i+1} + 2 A_{i-1} - A_{i-2}) / (2 dx^3): second order, and exact on the
    //! closed-end standing modes cos(n pi s / L), whose mirror images continue them.
    KOKKOS_INLINE_FUNCTION double tensionSource(int i, double A) const
    {
        const double d3 =
            mirroredArea(i + 2) - 2.0 * mirroredArea(i + 1) + 2.0 * mirroredArea(i - 1) - mirroredArea(i - 2);
        return k.tensionK * A * d3;
    }

    KOKKOS_INLINE_FUNCTION void operator()(const int i) const
    {
        const double A = in(i, 0), Q = in(i, 1);
        const double rateA = -(flux(i + 1, 0) - flux(i, 0)) / k.dx;
        double rateQ = -(flux(i + 1, 1) - flux(i, 1)) / k.dx - k.frictionK * Q / A;
        if (k.tension > 0)
            rateQ += tensionSource(i, A);
        const double newA = a * base(i, 0) + b * (A + dt * rateA);
        const double newQ = a * base(i, 1) + b * (Q + dt * rateQ);
        out(i, 0) = newA;
        out(i, 1) = newQ;
    }
};

/*! Largest |characteristic speed| over the cells (for the CFL time step); with T > 0 each cell adds its
 *  dispersive speed kTensionStepFactor sqrt(A T / rho) / dx, so that dt <= cfl dx^2 / (kTensionStepFactor ...). */
struct ArteryMaxSpeed
{
    ArteryConstants k;
    StateView U;
    KOKKOS_INLINE_FUNCTION void operator()(const int i, double& acc) const
    {
        const ArteryFaceState s = faceState(k, U(i, 0), U(i, 1));
        double speed = Kokkos::Experimental::fmax(-s.lo, s.hi);
        if (k.tension > 0)
            speed += k.tensionSpeedK * Kokkos::Experimental::sqrt(U(i, 0));
        acc = Kokkos::Experimental::fmax(acc, speed);
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
