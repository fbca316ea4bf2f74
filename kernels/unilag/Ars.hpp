/*! \file Ars.hpp
 *  \brief Kernels of the IMEX ARS(2,2,2) step (reference gpr.md 2.6, docs/gpr-model.md 2.6): the backward-Euler
 *  strain relaxation of its implicit stages, the final G_e of a step, and the combined node velocity.
 *  Tableaux (beta = 1 - sqrt(2)/2): explicit [[0,0,0],[beta,0,0],[beta-1,2-beta,0]],
 *  implicit [[0,0,0],[0,beta,0],[0,1-beta,beta]]; the trajectories use the explicit weights.
 */
#pragma once

#include "unilag/Hydro.hpp"

namespace unilag
{

//! ARS(2,2,2)'s gamma = beta = 1 - sqrt(2)/2 (gpr.md 2.6): stage 1 spans beta dt.
constexpr double arsBeta = 0.29289321881345247560;

namespace gpr
{
namespace detail
{
/*! Deviator eigenvalues x_i of the backward-Euler relaxation for a trial shift q = mean(b) - m (see
 *  implicitStrainRelax): the positive root of c x^2 + (1 + c m) x = d_i + q, in the form without cancellation, and
 *  dx_i/dq = (1 + c x_i) / sqrt(disc). Returns H(q) = q - (c/3) sum x_i^2 and writes H'(q). */
KOKKOS_INLINE_FUNCTION double implicitShift(const double (&d)[3], double mb, double c, double q, double (&x)[3],
                                            double& dH)
{
    const double m = mb - q, a = 1.0 + c * m;
    double sx2 = 0.0, sxdx = 0.0;
    for (int i = 0; i < 3; ++i)
    {
        const double r = d[i] + q; // b_i - m
        const double root = kmath::sqrt(kmath::fmax(a * a + 4.0 * c * r, 0.0));
        x[i] = 2.0 * r / (a + root);
        sx2 += x[i] * x[i];
        sxdx += x[i] * (1.0 + c * x[i]) / kmath::fmax(root, 1e-300);
    }
    dH = 1.0 - (2.0 / 3.0) * c * sxdx;
    return q - (c / 3.0) * sx2;
}
} // namespace detail

/*! \brief One backward-Euler stage of the strain relaxation, G = B - c G dev(G) with c = h k >= 0 (k frozen; gpr.md
 *  2.6, the implicit column of ARS(2,2,2)).
 *
 *  G shares the eigenvectors of B, and with m = mean(g), g_i = m + x_i each eigenvalue obeys g_i (1 + c x_i) = b_i,
 *  i.e. c x_i^2 + (1 + c m) x_i = d_i + (mean(b) - m), d_i the eigenvalues of dev B; summing gives
 *  q = mean(b) - m = (c/3) sum x_i^2, one scalar equation (Newton in a bisection bracket q in [0, mean(b))).
 *  Everything is in terms of the deviator so that no digit is lost in either limit:
 *   - c = 0 (tau1 = inf, elastic) returns B bit for bit;
 *   - c -> inf (tau1 = 1e-14): x_i -> (d_i + q)/(c m), the Navier-Stokes deviator dev B / (c m), formed directly
 *     (G = m I + V diag(x) V^T), not as the small difference of B and its relaxed part;
 *   - c m < 1: G = B - c V diag(g_i x_i) V^T, the increment form (round-off of the eigen-solver scales with it).
 *  B must be SPD (b_i > 0: every g_i is then positive); otherwise B is returned and the caller's check fails. */
KOKKOS_INLINE_FUNCTION Sym3 implicitStrainRelax(const Sym3& B, double c)
{
    if (!(c > 0.0))
        return B;
    const double mb = trace(B) / 3.0;
    if (!(c * mb < 1e250))
        return identity(mb); // the deviator ~ |dev B| / (c m) is below 1e-250 of G
    const Eigen3 e = eigen(dev(B));
    if (!(mb + e.value[0] > 0.0) || (e.value[0] == 0.0 && e.value[2] == 0.0))
        return B; // not SPD, or isotropic (G = B solves it)
    double x[3], dH, q = 0.0, lo = 0.0, hi = mb;
    for (int it = 0; it < 100; ++it)
    {
        const double H = detail::implicitShift(e.value, mb, c, q, x, dH);
        if (H == 0.0)
            break;
        (H < 0.0 ? lo : hi) = q;
        double qn = q - H / dH;
        if (!(qn > lo && qn < hi))
            qn = 0.5 * (lo + hi);
        const bool done = kmath::fabs(qn - q) <= 1e-16 * mb;
        q = qn;
        if (done)
            break;
    }
    detail::implicitShift(e.value, mb, c, q, x, dH); // the x_i of the final q
    const double m = mb - q;
    if (c * m >= 1.0)
        return identity(m) + fromEigen(x, e.vector);
    double gx[3];
    for (int i = 0; i < 3; ++i)
        gx[i] = -c * (m + x[i]) * x[i];
    return B + fromEigen(gx, e.vector);
}

} // namespace gpr

//! The combined node velocity of a step, v = w0 v0 + w1 v1, for all local nodes [0, n) (both halo-complete).
inline void combineNodeVelocities(const ConstField& v0, const ConstField& v1, double w0, double w1, const Field& v,
                                  LO n, int dim)
{
    auto combine = KOKKOS_LAMBDA(const LO r)
    {
        for (int d = 0; d < dim; ++d)
            v(r, d) = w0 * v0(r, d) + w1 * v1(r, d);
    };
    Kokkos::parallel_for("unilag::ars::combine_velocities", range(n), combine);
}

/*! \brief G_e^{n+1} of an ARS(2,2,2) step for the owned cells, into stateNew (gpr.md 2.6, final row):
 *    G^{n+1} = B + beta dt L_im(G^{n+1}),  B = G^n + dt [(beta-1) E(Q^n) + (2-beta) E(Q^1)] + (1-beta) dt I_1,
 *  with E = -(G L + L^T G) the transport rate and I_1 stage 1's stiff source.
 *   - dt E(Q^n) = dT0 / beta: stage 1's transport increment over beta dt (strainUpdate's increment, the converged
 *     Picard iterate's, with stage 1's node velocities v0 and the corner vectors at t^n);
 *   - E(Q^1) from G^1 (stage: the stage state) and L^1 = (1/|T^1|) sum_r v1_r (x) c_r^1 on the stage configuration
 *     (stageGeom) with its own node velocities v1;
 *   - I_1 = (G^1 - G^n - dT0) / (beta dt): the residual of stage 1, not (G^1 - G_eq)/tau1 re-evaluated, which loses
 *     every digit at tau1 = 1e-14. With G^n + dT0 formed as strainUpdate forms it, I_1 = 0 exactly where stage 1
 *     did not relax (tau1 = inf): the elastic step is then ARS's explicit transport exactly.
 *  Constant tau1: the backward-Euler solve implicitStrainRelax over beta dt with k = 6 det(B)^{5/6} / tau1 (frozen
 *  at B; k(G^{n+1}) differs by O(dt^2)). Plastic law: relaxPlasticStrain of B over beta dt, the exact relaxation with
 *  tau1(sigma_bar) consistent with the result, as in stage 1 (robust for large exponents, where a backward-Euler
 *  solve with tau1 depending on its own result has no safe bracket; it differs from backward Euler by
 *  O((beta dt k)^2), in the non-stiff range only). Returns the smallest volume ratio and a bad cell (G not SPD or
 *  an inverted cell; -1 if none); maxChange is unused (0). plasticWork: as strainUpdate's. */
template <int D, class P>
PicardCheck arsFinalStrain(const MeshView<D>& mesh, const ConstField& state, const ConstField& increment,
                           const ConstField& stage, const CellGeometry& stageGeom, const ConstField& v1,
                           const CellGeometry& geom, const View<const double*>& mass,
                           const View<const int*>& cellMaterial, const View<const Material*>& materials,
                           const ConstField& xNew, double dt, const Field& stateNew,
                           const View<double*>& plasticHint = View<double*>(),
                           const View<double*>& plasticWork = View<double*>())
{
    static_assert(P::strain, "arsFinalStrain is for the strain variants");
    const bool count = plasticWork.extent(0) > 0;
    using S = StateLayout<D, P>;
    constexpr double beta = arsBeta;
    auto corner = stageGeom.corner;
    auto stageVolume = stageGeom.volume;
    auto volume = geom.volume;
    auto update = KOKKOS_LAMBDA(const LO i, double(&ext)[2])
    {
        captureBeforeConstexpr(mass, plasticHint, plasticWork, count);
        const Material& m = materials(cellMaterial(i));
        const gpr::Sym3 G0 = loadSym3(state, i, S::G);
        const double newVolume = cellVolumeAt<D>(mesh, xNew, i);
        const double ratio = newVolume / volume(i);
        ext[0] = Kokkos::Experimental::fmin(ext[0], ratio);
        bool bad = !(ratio > 0.0);
        gpr::Sym3 G = G0;
        if (m.strainLaw != StrainNone && !bad)
        {
            const gpr::Sym3 dT0 = loadSym3(increment, i, 0);
            const gpr::Sym3 G1 = loadSym3(stage, i, S::G);
            const Mat<3> L = cellVelocityGradient<D>(mesh, v1, corner, i, 1.0 / stageVolume(i));
            const gpr::Sym3 dT1 = (-dt) * gpr::transportRate(G1, L);
            const gpr::Sym3 residual = G1 - (G0 + dT0); // beta dt I_1
            const gpr::Sym3 B = G0 + ((beta - 1.0) / beta) * dT0 + (2.0 - beta) * dT1 + ((1.0 - beta) / beta) * residual;
            if constexpr (P::plastic)
                if (m.strainLaw == StrainPlastic)
                    G = gpr::relaxPlasticStrain(B, mass(i) / newVolume, m.csh, beta * dt, m.tau10, m.sigmaY,
                                                m.exponent, &plasticHint(i), count ? &plasticWork(i) : nullptr);
            if (m.strainLaw == StrainConstant)
                G = gpr::implicitStrainRelax(B, beta * dt * gpr::strainRelaxationRate(B, m.tau1));
            bad = !(gpr::det(G) > 0.0) || !(gpr::trace(G) > 0.0) || !(gpr::norm2(G) == gpr::norm2(G));
        }
        storeSym3(stateNew, i, S::G, G);
        if (bad)
            ext[1] = Kokkos::Experimental::fmin(ext[1], double(i));
    };
    double ext[2];
    minReduce<2>("unilag::ars::final_strain", mesh.nOwnedCells, update, ext, P::plastic);
    const bool bad = ext[1] < double(mesh.nOwnedCells);
    return PicardCheck{0.0, ext[0], bad ? LO(ext[1]) : LO(-1)};
}

} // namespace unilag
