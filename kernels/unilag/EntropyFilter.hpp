/*! \file EntropyFilter.hpp
 *  \brief The entropy filter (scene key scheme.entropy_filter = C; docs/gpr-model.md 2.7): after each step, an
 *  exchange of internal energy between face neighbours that removes the mesh-scale part of the specific internal
 *  energy eps and leaves its linear part alone,
 *     m_i E_i += dt sum_f C rho_f a_f s_f R_f,
 *     R_f = minmod( (eps_j - eps_i) - 1/2 (grad eps_i + grad eps_j) . (x_j - x_i),  eps_j - eps_i ),
 *  over the interior faces f = (i, j) where neither cell is shocked; rho_f the mean density, a_f the larger sound
 *  speed, s_f the face area, x the centroids, grad eps the least-squares gradient over the face neighbours
 *  (epsGradientFromFaces: mirror images at slip walls and symmetry planes, the minimum-norm fit where they span
 *  fewer than D directions).
 *  Why: a strong shock crossing triangles (tetrahedra) leaves cells of the two orientations between two rows of
 *  nodes with different entropies, at equal pressure, and nothing in the scheme exchanges entropy afterwards
 *  (docs/sedov.md, sessions 7-16): a density scatter of 5-15% behind the shock that order 2 keeps more of than order
 *  1. The filter damps it within a few steps of its birth, like a heat conduction of mesh-scale modes only.
 *   - Linear eps fields give R_f = 0 (away from slip walls, where the mirror images assume a zero normal gradient):
 *     second order in smooth flows. The face stencil, not 2.5's node stencil: it takes a third off the filter's cost
 *     (session 22), and each face's residual needs only the fit along its own direction, which it makes exact.
 *   - The minmod keeps R_f between 0 and the jump: heat flows from the hotter cell to the colder one only, no more
 *     than the jump, so that eps stays within its neighbours' range (a cold gas stays at eps >= 0) for
 *     C dt sum_f rho_f a_f s_f <= m_i, which the CFL step gives for C <= 0.25 (equilateral triangle: 4 C cfl).
 *   - Shocked cells, s_i > (1 + kappa) a_i with s the nodal solver's signal speed a + Gamma_D |dv| (Aux::signal),
 *     kappa = 0.5, neither give nor take: at the front the hotter cell of a pair is the one that ends up colder
 *     (docs/sedov.md, session 14), so a conduction there makes the scatter larger.
 *   - Conservative to round-off: R_f, rho_f, a_f and the antisymmetrised area vector (sharedFaceArea, as the
 *     heat fluxes') are exact negatives from either side of a face; each cell adds only its own faces' fluxes (no
 *     atomics), so the result is independent of the partition and the thread count, bit for bit.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"

namespace unilag
{
namespace entropy_filter
{

//! Shock sensor: cells whose nodal signal speed exceeds (1 + kappa) times their sound speed are left alone.
constexpr double kShockKappa = 0.5;
//! Largest coefficient C the scene accepts: eps stays within its neighbours' range for C <= 0.25 at CFL 1.
constexpr double kMaxCoefficient = 0.25;

//! Directions of the gradient's fit whose part off the span of the earlier ones is below this share of their length
//! add nothing (a corner cell's mirror images can be nearly parallel to a neighbour's direction).
constexpr double kMinSine = 0.05;

/*! Whether the first D directions u each stand off the span of the earlier ones by a sine above kMinSine: then
 *  fitInSpan's Gram-Schmidt keeps every direction, and the fit is that of the plain normal equations. */
template <int D>
KOKKOS_INLINE_FUNCTION bool spansWell(const Vec<D>* u)
{
    constexpr double s2 = kMinSine * kMinSine;
    const double u00 = dot(u[0], u[0]), u11 = dot(u[1], u[1]), u01 = dot(u[0], u[1]);
    const double area2 = u00 * u11 - u01 * u01; // |u0 x u1|^2 (Lagrange's identity), also for D = 2
    if (!(area2 > s2 * u00 * u11))
        return false;
    if constexpr (D == 3)
    {
        const Vec<3> n{{u[0][1] * u[1][2] - u[0][2] * u[1][1], u[0][2] * u[1][0] - u[0][0] * u[1][2],
                        u[0][0] * u[1][1] - u[0][1] * u[1][0]}};
        const double off = dot(u[2], n); // |u2| |u0 x u1| times the sine of u2 off the plane of u0, u1
        return off * off > s2 * dot(u[2], u[2]) * area2;
    }
    return true;
}

/*! The gradient g of the least-squares fit of g . u_s = w_s (weights 1/|u_s|^2) over n <= D + 1 directions u, made
 *  in their span when they span fewer than D dimensions (the minimum-norm fit). A direction close to the span of
 *  the earlier ones, but not in it, is left out while the span is not full (it would make the fit ill-conditioned).
 *  For w from a linear field, g . u_s = w_s exactly for every direction in the span of those fitted. A cell whose
 *  first D directions span well (nearly all) takes the normal equations directly: the same fit, a third of the cost
 *  of the filter's gradient without the Gram-Schmidt basis (session 25). */
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> fitInSpanGramSchmidt(const Vec<D>* u, const double* w, int n);

template <int D>
KOKKOS_FORCEINLINE_FUNCTION Vec<D> fitInSpan(const Vec<D>* u, const double* w, int n)
{
    if (!(n >= D && spansWell<D>(u)))
        return fitInSpanGramSchmidt<D>(u, w, n);
    Mat<D> M = Mat<D>::zero();
    Vec<D> b = Vec<D>::zero();
    for (int s = 0; s < n; ++s)
    {
        const double weight = 1.0 / dot(u[s], u[s]);
        M.addOuter(weight, u[s]);
        b = b + (weight * w[s]) * u[s];
    }
    return solve<D>(M, b);
}

//! fitInSpan for the cells whose directions do not span well: the fit in the Gram-Schmidt basis of their span.
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> fitInSpanGramSchmidt(const Vec<D>* u, const double* w, int n)
{
    Vec<D> Q[D]; // orthonormal basis of the span, Gram-Schmidt in order
    bool fitted[D + 1];
    int nq = 0;
    for (int s = 0; s < n; ++s)
    {
        fitted[s] = nq == D;
        if (nq == D)
            continue;
        Vec<D> v = u[s];
        for (int a = 0; a < nq; ++a)
            v = v - dot(v, Q[a]) * Q[a];
        const double len = norm(v);
        fitted[s] = len > kMinSine * norm(u[s]);
        if (fitted[s])
            Q[nq++] = (1.0 / len) * v;
    }
    Mat<D> M = Mat<D>::zero(); // normal equations in the basis: M y = b, leading nq x nq block
    Vec<D> b = Vec<D>::zero();
    for (int s = 0; s < n; ++s)
    {
        if (!fitted[s])
            continue;
        Vec<D> c = Vec<D>::zero();
        const double weight = 1.0 / dot(u[s], u[s]);
        for (int a = 0; a < nq; ++a)
            c[a] = dot(u[s], Q[a]);
        M.addOuter(weight, c);
        for (int a = 0; a < nq; ++a)
            b[a] += weight * w[s] * c[a];
    }
    double y[D] = {};
    if (nq == D)
    {
        const Vec<D> full = solve<D>(M, b);
        for (int a = 0; a < D; ++a)
            y[a] = full[a];
    }
    else if (nq == 2) // D == 3: a tetrahedron with two faces of no neighbour and no mirror
    {
        Mat<2> M2;
        for (int a = 0; a < 2; ++a)
            for (int c = 0; c < 2; ++c)
                M2.a[a][c] = M.a[a][c];
        const Vec<2> y2 = solve<2>(M2, Vec<2>{{b[0], b[1]}});
        y[0] = y2[0];
        y[1] = y2[1];
    }
    else if (nq == 1)
        y[0] = b[0] / M.a[0][0];
    Vec<D> g = Vec<D>::zero();
    for (int a = 0; a < nq; ++a)
        g = g + y[a] * Q[a];
    return g;
}

//! minmod(r, jump): r clipped to [0, jump] (or [jump, 0]); 0 where r points against the jump. Odd in (r, jump).
//! Comparisons, not fmin / fmax: those are calls into libm on the host (NaN handling), a tenth of the filter.
KOKKOS_INLINE_FUNCTION double clipToJump(double r, double jump)
{
    if (r * jump <= 0.0)
        return 0.0;
    return jump > 0.0 ? (r < jump ? r : jump) : (r > jump ? r : jump);
}

} // namespace entropy_filter

/*! grad eps of the owned cells for the filter's residual: the fit of entropy_filter::fitInSpan over the face
 *  neighbours' centroids and, across a slip wall or symmetry face, over the cell's mirror image (eps unchanged);
 *  other boundary faces add nothing. Needs aux (Aux::eps) and geom on the cell and its face neighbours. */
template <int D>
void epsGradientFromFaces(const MeshView<D>& mesh, const ConstField& aux, const CellGeometry& geom,
                          const ConstField& x, const BoundaryView& bc, const Field& grad)
{
    constexpr int NV = D + 1;
    auto centroid = geom.centroid;
    auto corner = geom.corner;
    const bool hasBc = bc.type.extent(0) > 0;
    Kokkos::parallel_for(
        "unilag::epsGradientFromFaces", Kokkos::RangePolicy<ExecSpace>(0, mesh.nOwnedCells),
        KOKKOS_LAMBDA(const LO i) {
            Vec<D> u[NV];
            double w[NV];
            int n = 0;
            for (int k = 0; k < NV; ++k)
            {
                const LO j = mesh.cellNeighbour(i, k);
                if (j >= 0)
                {
                    for (int a = 0; a < D; ++a)
                        u[n][a] = centroid(j, a) - centroid(i, a);
                    w[n++] = aux(j, Aux::eps) - aux(i, Aux::eps);
                    continue;
                }
                const int g = mesh.cellFaceGroup(i, k);
                if (!hasBc || g < 0 || bc.type(g) != BcSlipWall)
                    continue;
                // face k's outward normal is -c_k; the mirror image lies twice the centroid's distance beyond it
                Vec<D> normal, toFace;
                const LO r = mesh.cellNodes(i, (k + 1) % NV);
                for (int a = 0; a < D; ++a)
                {
                    normal[a] = -corner(i, k * D + a);
                    toFace[a] = x(r, a) - centroid(i, a);
                }
                normal = (1.0 / norm(normal)) * normal;
                u[n] = (2.0 * dot(toFace, normal)) * normal;
                w[n++] = 0.0;
            }
            const Vec<D> g = entropy_filter::fitInSpan<D>(u, w, n);
            for (int a = 0; a < D; ++a)
                grad(i, a) = g[a];
        });
}

/*! Adds the entropy filter's exchange over dt to the total energy of the owned cells (file comment). Needs aux
 *  (Aux::eps, sound, signal), state (omega), geom (centroid, corner) and gradEps (one column per direction) on every
 *  local cell, ghosts included; writes only the energy column of the owned cells. */
template <int D, class P>
void filterEntropy(const MeshView<D>& mesh, const Field& state, const ConstField& aux, const CellGeometry& geom,
                   const View<const double*>& mass, const ConstField& gradEps, double dt, double coefficient)
{
    using S = StateLayout<D, P>;
    constexpr int NV = D + 1;
    auto centroid = geom.centroid;
    auto corner = geom.corner;
    Kokkos::parallel_for(
        "unilag::filterEntropy", Kokkos::RangePolicy<ExecSpace>(0, mesh.nOwnedCells), KOKKOS_LAMBDA(const LO i) {
            constexpr double shockRatio = 1.0 + entropy_filter::kShockKappa;
            const double soundI = aux(i, Aux::sound), epsI = aux(i, Aux::eps), rhoI = 1.0 / state(i, S::omega);
            if (aux(i, Aux::signal) > shockRatio * soundI)
                return;
            double sum = 0.0;
            for (int k = 0; k < NV; ++k)
            {
                const LO j = mesh.cellNeighbour(i, k);
                if (j < 0 || aux(j, Aux::signal) > shockRatio * aux(j, Aux::sound)) // boundary, shocked
                    continue;
                const double jump = aux(j, Aux::eps) - epsI;
                double residual = jump;
                for (int a = 0; a < D; ++a)
                    residual -= 0.5 * (gradEps(i, a) + gradEps(j, a)) * (centroid(j, a) - centroid(i, a));
                const Vec<D> area = sharedFaceArea<D>(mesh, corner, i, k, j);
                const double rho = 0.5 * (rhoI + 1.0 / state(j, S::omega));
                const double soundJ = aux(j, Aux::sound);
                const double sound = soundI < soundJ ? soundJ : soundI;
                sum += rho * sound * norm(area) * entropy_filter::clipToJump(residual, jump);
            }
            state(i, S::energy) += dt * coefficient * sum / mass(i);
        });
}

} // namespace unilag
