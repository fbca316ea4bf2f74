/*! \file TubeRod.hpp
 *  \brief Kernels of the nonlinear tube: a Cosserat rod on SE(3) conveying fluid (docs/tube-dynamics.md).
 *
 *  Nodes j = 0..N carry a rotation Lambda_j (body axis 1 = tangent) and a position r_j; segment j joins nodes
 *  j and j+1. The discrete strains are objective and second order:
 *    Omega_j = cay^{-1}(Lambda_j^T Lambda_{j+1}) / h,   Gamma_j = (Lambda_j + Lambda_{j+1})^T (r_{j+1} - r_j) / (2h),
 *  and every force and torque here is the exact gradient of the discrete elastic energy, so that the split
 *  integrator conserves momenta to round-off and energy without drift. Segment kernels compute the stresses;
 *  node kernels gather the two adjacent segments (no atomics). Kokkos core only, no host calls in kernels.
 */
#pragma once

#include <Kokkos_Core.hpp>

namespace unilag::rod
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using Vec3View = Kokkos::View<double* [3], MemSpace>;
using Mat3View = Kokkos::View<double* [3][3], MemSpace>;
using ScalarView = Kokkos::View<double*, MemSpace>;

struct V3
{
    double x[3];
    KOKKOS_INLINE_FUNCTION double& operator[](int i) { return x[i]; }
    KOKKOS_INLINE_FUNCTION double operator[](int i) const { return x[i]; }
};
struct M3
{
    double a[3][3];
};

KOKKOS_INLINE_FUNCTION V3 v3(double a, double b, double c) { return V3{{a, b, c}}; }
KOKKOS_INLINE_FUNCTION V3 operator+(const V3& a, const V3& b) { return v3(a[0] + b[0], a[1] + b[1], a[2] + b[2]); }
KOKKOS_INLINE_FUNCTION V3 operator-(const V3& a, const V3& b) { return v3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
KOKKOS_INLINE_FUNCTION V3 operator*(double s, const V3& a) { return v3(s * a[0], s * a[1], s * a[2]); }
KOKKOS_INLINE_FUNCTION double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
KOKKOS_INLINE_FUNCTION V3 cross(const V3& a, const V3& b)
{
    return v3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
KOKKOS_INLINE_FUNCTION V3 mul(const M3& m, const V3& v) //!< m v
{
    V3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = m.a[i][0] * v[0] + m.a[i][1] * v[1] + m.a[i][2] * v[2];
    return r;
}
KOKKOS_INLINE_FUNCTION V3 mulT(const M3& m, const V3& v) //!< m^T v
{
    V3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = m.a[0][i] * v[0] + m.a[1][i] * v[1] + m.a[2][i] * v[2];
    return r;
}
KOKKOS_INLINE_FUNCTION M3 mul(const M3& a, const M3& b) //!< a b
{
    M3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.a[i][j] = a.a[i][0] * b.a[0][j] + a.a[i][1] * b.a[1][j] + a.a[i][2] * b.a[2][j];
    return r;
}
KOKKOS_INLINE_FUNCTION M3 mulTN(const M3& a, const M3& b) //!< a^T b
{
    M3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.a[i][j] = a.a[0][i] * b.a[0][j] + a.a[1][i] * b.a[1][j] + a.a[2][i] * b.a[2][j];
    return r;
}

/*! exp(theta^) - I by Rodrigues' formula, a theta^ + b theta^2, with coefficients accurate down to theta = 0
 *  ((1 - cos)/theta^2 is written 2 sin^2(theta/2)/theta^2). The identity is left out on purpose: the update
 *  Lambda + Lambda (exp - I) then rounds only the (pseudo-random) last bit of Lambda, whereas Lambda exp(..)
 *  would round exp's diagonal 1 - O(theta^2) the same way every step and drift off orthogonality linearly. */
KOKKOS_INLINE_FUNCTION M3 expSO3MinusI(const V3& th)
{
    const double t2 = dot(th, th);
    const double t = Kokkos::Experimental::sqrt(t2);
    double a, b; // sin(t)/t, (1 - cos t)/t^2
    if (t < 1e-4)
    {
        a = 1.0 - t2 / 6.0 * (1.0 - t2 / 20.0);
        b = 0.5 - t2 / 24.0 * (1.0 - t2 / 30.0);
    }
    else
    {
        const double sh = Kokkos::Experimental::sin(0.5 * t) / t;
        a = Kokkos::Experimental::sin(t) / t;
        b = 2.0 * sh * sh;
    }
    M3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.a[i][j] = b * (th[i] * th[j] - (i == j ? t2 : 0.0));
    r.a[0][1] -= a * th[2];
    r.a[1][0] += a * th[2];
    r.a[0][2] += a * th[1];
    r.a[2][0] -= a * th[1];
    r.a[1][2] -= a * th[0];
    r.a[2][1] += a * th[0];
    return r;
}

//! cay^{-1}(R) = 2 vee(R - R^T) / (1 + tr R): the rotation vector of the Cayley map (R = cay(x)).
KOKKOS_INLINE_FUNCTION V3 cayleyLog(const M3& R)
{
    const double s = 2.0 / (1.0 + R.a[0][0] + R.a[1][1] + R.a[2][2]);
    return v3(s * (R.a[2][1] - R.a[1][2]), s * (R.a[0][2] - R.a[2][0]), s * (R.a[1][0] - R.a[0][1]));
}

//! cay(x) = (I - x^/2)^{-1} (I + x^/2) = I + 4/(4 + |x|^2) (x^ + x^2/2): exactly orthogonal in exact arithmetic.
KOKKOS_INLINE_FUNCTION M3 cayley(const V3& x)
{
    const double c = 4.0 / (4.0 + dot(x, x));
    M3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.a[i][j] = (i == j ? 1.0 : 0.0) + 0.5 * c * (x[i] * x[j] - (i == j ? dot(x, x) : 0.0));
    r.a[0][1] -= c * x[2];
    r.a[1][0] += c * x[2];
    r.a[0][2] += c * x[1];
    r.a[2][0] -= c * x[1];
    r.a[1][2] -= c * x[0];
    r.a[2][1] += c * x[0];
    return r;
}

//! Segment constants: spacing h, J = diag(GJ, EI, EI), L = diag(EA, kGA, kGA), rest curvature (body).
struct RodParams
{
    double h;
    double J[3], L[3], rest[3];
};

//! The exact gradient of one segment's energy: the force on node j (node j+1 gets its opposite, spatial
//! frame) and the body torques on nodes j and j+1 (minus dV/dSigma for Lambda -> Lambda (I + Sigma^)).
struct SegmentLoad
{
    V3 force, torqueLeft, torqueRight;
    double energy;
};

KOKKOS_INLINE_FUNCTION M3 loadM3(const Mat3View& v, int j)
{
    M3 m;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            m.a[a][b] = v(j, a, b);
    return m;
}
KOKKOS_INLINE_FUNCTION V3 loadV3(const Vec3View& v, int j) { return v3(v(j, 0), v(j, 1), v(j, 2)); }
KOKKOS_INLINE_FUNCTION void storeV3(const Vec3View& v, int j, const V3& x)
{
    for (int a = 0; a < 3; ++a)
        v(j, a) = x[a];
}

/*! Strains, stresses, energy and exact gradient of a segment from its end frames A, B and positions ra, rb.
 *  With R = A^T B, d = 1 + tr R, x = cay^{-1}(R): a right perturbation B -> B (I + Sigma^) moves x by
 *  B_r Sigma = [2 (tr R I - R^T)/d + x x^T/2] Sigma, one of A by -B_l Sigma = -[2 (tr R I - R)/d + x x^T/2] Sigma
 *  (from R S^ + S^ R^T = ((tr R) I - R^T) S)^ and tr(R S^) = -vee(R - R^T).S);
 *  Gamma's body vectors a = A^T (rb - ra)/h move by a x Sigma. */
KOKKOS_INLINE_FUNCTION SegmentLoad segmentLoad(const M3& A, const M3& B, const V3& ra, const V3& rb,
                                               const RodParams& p)
{
    const M3 R = mulTN(A, B);
    const double tr = R.a[0][0] + R.a[1][1] + R.a[2][2];
    const double den = 1.0 + tr;
    const V3 x = cayleyLog(R);
    const V3 chord = (1.0 / p.h) * (rb - ra);
    const V3 a = mulT(A, chord), b = mulT(B, chord);
    V3 gammaStrain = 0.5 * (a + b);
    gammaStrain[0] -= 1.0;
    V3 m, n;
    double energy = 0.0;
    for (int i = 0; i < 3; ++i)
    {
        const double kappa = x[i] / p.h - p.rest[i];
        m[i] = p.J[i] * kappa;
        n[i] = p.L[i] * gammaStrain[i];
        energy += 0.5 * p.h * (m[i] * kappa + n[i] * gammaStrain[i]);
    }
    SegmentLoad s;
    s.energy = energy;
    s.force = 0.5 * (mul(A, n) + mul(B, n)); // = dV/d r_{j+1} = -dV/d r_j
    // dV/dSigma_B = B_r^T m + (h/2) n x b ; dV/dSigma_A = -B_l^T m + (h/2) n x a
    const double xm = 0.5 * dot(x, m);
    const V3 brm = (2.0 / den) * (tr * m - mul(R, m)) + xm * x;
    const V3 blm = (2.0 / den) * (tr * m - mulT(R, m)) + xm * x;
    s.torqueRight = (-1.0) * (brm + (0.5 * p.h) * cross(n, b));
    s.torqueLeft = blm - (0.5 * p.h) * cross(n, a);
    return s;
}

//! Segment pass: each segment's load, stored for the node gather.
struct SegmentStress
{
    Mat3View lam;
    Vec3View r, force, torqueLeft, torqueRight;
    RodParams p;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const SegmentLoad s = segmentLoad(loadM3(lam, j), loadM3(lam, j + 1), loadV3(r, j), loadV3(r, j + 1), p);
        storeV3(force, j, s.force);
        storeV3(torqueLeft, j, s.torqueLeft);
        storeV3(torqueRight, j, s.torqueRight);
    }
};

/*! The rod's device state, for a coupled stepper that kicks the nodes itself (src/tube/GasRodCoupling.cpp):
 *  positions, velocities, body spins pi, frames, the elastic load stored by the last node gather, the lumped
 *  masses and rotary inertias (I2) per node, the end flags and the segment length h. */
struct RodViews
{
    Vec3View position, velocity, spin, force, torque;
    Mat3View lam;
    ScalarView mass, rotary;
    int leftFlags, rightFlags, segments;
    double h;
};

//! Which motions an end condition fixes; node flags: bit 1 position fixed, bit 2 rotation fixed.
KOKKOS_INLINE_FUNCTION bool positionFixed(int flags) { return flags & 1; }
KOKKOS_INLINE_FUNCTION bool rotationFixed(int flags) { return flags & 2; }

//! Kick of node j: v += tau F / m, pi += tau T (body torque; Lambda does not move during a kick).
KOKKOS_INLINE_FUNCTION void kickNode(int j, int flags, double tau, const V3& f, const V3& t, const ScalarView& mass,
                                     const Vec3View& velocity, const Vec3View& spin)
{
    for (int a = 0; a < 3; ++a)
    {
        if (!positionFixed(flags))
            velocity(j, a) += tau * f[a] / mass(j);
        if (!rotationFixed(flags))
            spin(j, a) += tau * t[a];
    }
}

/*! Node pass: the two adjacent segments' loads plus gravity (no atomics: each node reads, nobody adds),
 *  stored, and (kick) applied at once when nothing else (the fluid) needs the stored load first.
 *  Screw-periodic rods (`screw`): nodes 0..N-1 are launched; the last segment ends at node N, the image
 *  (R_g Lambda_0, R_g r_0 + d_g) of node 0, so node 0 also takes that segment's right load: the force pulled
 *  back, -R_g^T F_{N-1} (delta r_N = R_g delta r_0), the body torque as it is (Lambda_N = R_g Lambda_0 moves by the
 *  same right perturbation as Lambda_0). */
struct NodeGather
{
    Vec3View segForce, segTorqueLeft, segTorqueRight, force, torque, velocity, spin;
    ScalarView mass;
    double gravity[3];
    int leftFlags, rightFlags, segments;
    double tau;
    bool kick;
    bool screw = false;
    M3 screwRotation = M3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; //!< R_g
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        V3 f, t;
        for (int a = 0; a < 3; ++a)
        {
            f[a] = mass(j) * gravity[a];
            t[a] = 0.0;
            if (j < segments)
            {
                f[a] += segForce(j, a);
                t[a] += segTorqueLeft(j, a);
            }
            if (j > 0)
            {
                f[a] -= segForce(j - 1, a);
                t[a] += segTorqueRight(j - 1, a);
            }
        }
        if (screw && j == 0)
        {
            f = f - mulT(screwRotation, loadV3(segForce, segments - 1));
            t = t + loadV3(segTorqueRight, segments - 1);
        }
        storeV3(force, j, f);
        storeV3(torque, j, t);
        if (kick)
            kickNode(j, j == 0 ? leftFlags : (j == segments ? rightFlags : 0), tau, f, t, mass, velocity, spin);
    }
};

/*! Fluid pass over segments (plug flow at relative speed U, mass M per length): the chord tangent and the
 *  segment's increment of p A from d_l(p A) = -M t.(a + U d_l v), the tube accelerations a taken from the
 *  elastic load. */
struct FluidSegment
{
    Vec3View r, v, force, tangent;
    ScalarView mass, pressureStep;
    double fluidMass, speed;
    int leftFlags, rightFlags, segments;
    //! the node's acceleration under the elastic load (0 where the position is held)
    KOKKOS_INLINE_FUNCTION V3 acceleration(int j) const
    {
        const int flags = j == 0 ? leftFlags : (j == segments ? rightFlags : 0);
        return (flags & 1) ? v3(0, 0, 0) : (1.0 / mass(j)) * loadV3(force, j);
    }
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const V3 d = loadV3(r, j + 1) - loadV3(r, j);
        const double len = Kokkos::Experimental::sqrt(dot(d, d));
        const V3 t = (1.0 / len) * d;
        const V3 dv = loadV3(v, j + 1) - loadV3(v, j);
        const V3 acc = 0.5 * (acceleration(j) + acceleration(j + 1));
        storeV3(tangent, j, t);
        pressureStep(j) = fluidMass * (len * dot(t, acc) + speed * dot(t, dv));
    }
};

//! p A at node k = sum of the increments of segments k..N-1 (p = 0 where the fluid leaves, node N).
struct PressureScan
{
    using value_type = double;
    ScalarView pressureStep, pressure;
    int segments;
    KOKKOS_INLINE_FUNCTION void operator()(int i, double& sum, bool final) const
    {
        const int k = segments - 1 - i;
        sum += pressureStep(k);
        if (final)
            pressure(k) = sum;
    }
};

/*! The kick with the fluid's forces, finite volume over each node's cell: the centrifugal and pressure force
 *  -(M U^2 + p A)(t_j - t_{j-1}), zero at the end nodes (the fluid enters and leaves along the end segment's
 *  tangent), and the Coriolis force -2 M U (I - t t^T) d_l v, per node cell
 *  -M U [P_{j-1}(v_j - v_{j-1}) + P_j(v_{j+1} - v_j)], P = I - t t^T, taken at the kick's midpoint velocity
 *  (v_old + v_new)/2 (Crank-Nicolson: the skew gyroscopic operator then does no spurious work; a lagged explicit
 *  velocity makes the short waves grow at a rate proportional to dt). Solved by fixed-point sweeps (Jacobi,
 *  contraction tau M U/(m h) ~ 1e-2): sweep 0 takes v_old (explicit predictor), later sweeps the previous sweep's
 *  v_new. The last sweep also kicks the spins. */
struct CoriolisKick
{
    Vec3View force, torque, tangent, vOld, vIn, vOut, spin;
    ScalarView mass, pressure;
    double centrifugal, coriolis; // M U^2, M U
    int leftFlags, rightFlags, segments;
    double tau;
    bool predictor, last;
    KOKKOS_INLINE_FUNCTION V3 midVelocity(int k) const
    {
        return predictor ? loadV3(vOld, k) : 0.5 * (loadV3(vOld, k) + loadV3(vIn, k));
    }
    KOKKOS_INLINE_FUNCTION V3 projectedJump(int seg, const V3& dv) const // (I - t t^T) dv
    {
        const V3 t = loadV3(tangent, seg);
        return dv - dot(t, dv) * t;
    }
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const int flags = j == 0 ? leftFlags : (j == segments ? rightFlags : 0);
        const V3 vj = midVelocity(j);
        V3 f = loadV3(force, j);
        if (j > 0 && j < segments)
            f = f - (centrifugal + pressure(j)) * (loadV3(tangent, j) - loadV3(tangent, j - 1));
        if (j > 0)
            f = f - coriolis * projectedJump(j - 1, vj - midVelocity(j - 1));
        if (j < segments)
            f = f - coriolis * projectedJump(j, midVelocity(j + 1) - vj);
        const V3 v0 = loadV3(vOld, j);
        storeV3(vOut, j, positionFixed(flags) ? v0 : v0 + (tau / mass(j)) * f);
        if (last && !rotationFixed(flags))
            for (int a = 0; a < 3; ++a)
                spin(j, a) += tau * torque(j, a);
    }
};

/*! Counts the nodes whose position, velocity, spin or frame is not finite: the run's stop test, reduced on the
 *  device so that only one integer crosses to the host each step. */
struct NonFiniteNodes
{
    Vec3View position, velocity, spin;
    Mat3View lam;
    KOKKOS_INLINE_FUNCTION void operator()(int j, int& bad) const
    {
        bool ok = true;
        for (int a = 0; a < 3; ++a)
        {
            ok = ok && Kokkos::Experimental::isfinite(position(j, a)) && Kokkos::Experimental::isfinite(velocity(j, a)) &&
                 Kokkos::Experimental::isfinite(spin(j, a));
            for (int b = 0; b < 3; ++b)
                ok = ok && Kokkos::Experimental::isfinite(lam(j, a, b));
        }
        bad += ok ? 0 : 1;
    }
};

/*! Screw-periodic closure (one thread): node N becomes the image of node 0 under the helix's screw motion
 *  g = (R_g, d_g): Lambda_N = R_g Lambda_0, r_N = R_g r_0 + d_g, v_N = R_g v_0, pi_N = pi_0 (body). */
struct ScrewImage
{
    Mat3View lam;
    Vec3View position, velocity, spin;
    M3 rotation;
    V3 shift;
    int segments;
    KOKKOS_INLINE_FUNCTION void operator()(int) const
    {
        const int n = segments;
        const M3 image = mul(rotation, loadM3(lam, 0));
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                lam(n, a, b) = image.a[a][b];
        storeV3(position, n, mul(rotation, loadV3(position, 0)) + shift);
        storeV3(velocity, n, mul(rotation, loadV3(velocity, 0)));
        storeV3(spin, n, loadV3(spin, 0));
    }
};

/*! Drift: the exact flow of the kinetic energy. Translation r += tau v. Rotation of the axisymmetric node
 *  (inertia diag(I1, I2, I2), body momentum pi): T = |pi|^2/(2 I2) + pi1^2 (1/I1 - 1/I2)/2; the two flows
 *  commute and each is a rotation, Lambda <- Lambda exp(tau pi^/I2) exp(phi e1^), pi <- exp(-phi e1^) pi with
 *  phi = tau pi1 (1/I1 - 1/I2). Lambda stays orthogonal to round-off without renormalisation. */
struct Drift
{
    Vec3View position, velocity, spin;
    Mat3View lam;
    ScalarView rotary; // I2 per node; I1 = 2 I2 (axisymmetric tube)
    int leftFlags, rightFlags, segments;
    double tau;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const int flags = j == 0 ? leftFlags : (j == segments ? rightFlags : 0);
        if (!positionFixed(flags))
            for (int a = 0; a < 3; ++a)
                position(j, a) += tau * velocity(j, a);
        if (rotationFixed(flags))
            return;
        const double i2 = rotary(j);
        const V3 pi = loadV3(spin, j);
        // E = exp(tau pi^/I2) Rx(phi) - I = E1 + E2 + E1 E2, E2 = Rx(phi) - I (cos - 1 = -2 sin^2(phi/2))
        const M3 e1 = expSO3MinusI((tau / i2) * pi);
        const double phi = tau * pi[0] * (0.5 / i2 - 1.0 / i2);
        const double sh = Kokkos::Experimental::sin(0.5 * phi);
        const double cm = -2.0 * sh * sh, sn = Kokkos::Experimental::sin(phi);
        M3 e;
        for (int a = 0; a < 3; ++a)
        {
            e.a[a][0] = e1.a[a][0];
            e.a[a][1] = e1.a[a][1] + (a == 1 ? cm : (a == 2 ? sn : 0.0)) + e1.a[a][1] * cm + e1.a[a][2] * sn;
            e.a[a][2] = e1.a[a][2] + (a == 1 ? -sn : (a == 2 ? cm : 0.0)) - e1.a[a][1] * sn + e1.a[a][2] * cm;
        }
        const M3 old = loadM3(lam, j);
        const M3 inc = mul(old, e);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                lam(j, a, b) = old.a[a][b] + inc.a[a][b];
        spin(j, 1) = pi[1] + (cm * pi[1] + sn * pi[2]);
        spin(j, 2) = pi[2] + (cm * pi[2] - sn * pi[1]);
    }
};

} // namespace unilag::rod
