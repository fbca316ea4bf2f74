/*! \file EntropyFilter.hpp
 *  \brief The entropy filter (scene key scheme.entropy_filter = C; docs/gpr-model.md 2.7): after each step, an
 *  exchange of internal energy between face neighbours that removes the mesh-scale part of the specific internal
 *  energy eps and leaves its linear part alone,
 *     m_i E_i += dt sum_f C rho_f a_f s_f R_f,
 *     R_f = minmod( (eps_j - eps_i) - 1/2 (grad eps_i + grad eps_j) . (x_j - x_i),  eps_j - eps_i ),
 *  over the interior faces f = (i, j) where neither cell is shocked; rho_f the mean density, a_f the larger sound
 *  speed, s_f the face area, x the centroids, grad eps the unlimited least-squares gradient (limitedGradientsOf with
 *  EpsQuantity: node-neighbour stencil, mirrored at slip walls and symmetry planes).
 *  Why: a strong shock crossing triangles (tetrahedra) leaves cells of the two orientations between two rows of
 *  nodes with different entropies, at equal pressure, and nothing in the scheme exchanges entropy afterwards
 *  (docs/sedov.md, sessions 7-16): a density scatter of 5-15% behind the shock that order 2 keeps more of than order
 *  1. The filter damps it within a few steps of its birth, like a heat conduction of mesh-scale modes only.
 *   - Linear eps fields give R_f = 0 (and quadratic ones on a symmetric stencil): second order in smooth flows.
 *   - The minmod keeps R_f between 0 and the jump: heat flows from the hotter cell to the colder one only, no more
 *     than the jump, so that eps stays within its neighbours' range (a cold gas stays at eps >= 0) for
 *     C dt sum_f rho_f a_f s_f <= m_i, which the CFL step gives for C <= 0.25 (equilateral triangle: 4 C cfl).
 *   - Shocked cells, s_i > (1 + kappa) a_i with s the nodal solver's signal speed a + Gamma_D |dv| (Aux::signal),
 *     kappa = 0.5, neither give nor take: at the front the hotter cell of a pair is the one that ends up colder
 *     (docs/sedov.md, session 14), so a conduction there makes the scatter larger.
 *   - Conservative to round-off: R_f, rho_f, a_f and the antisymmetrised area vector (as the heat fluxes',
 *     Heat.hpp) are exact negatives from either side of a face; each cell adds only its own faces' fluxes (no
 *     atomics), so the result is independent of the partition and the thread count, bit for bit.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"
#include "unilag/Reconstruction.hpp"

namespace unilag
{
namespace entropy_filter
{

//! Shock sensor: cells whose nodal signal speed exceeds (1 + kappa) times their sound speed are left alone.
constexpr double kShockKappa = 0.5;
//! Largest coefficient C the scene accepts: eps stays within its neighbours' range for C <= 0.25 at CFL 1.
constexpr double kMaxCoefficient = 0.25;

//! eps as the Q of limitedGradientsOf: one quantity, unlimited, mirrored (unchanged) at slip walls and planes.
template <int D>
struct EpsQuantity
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        nq = 1,
        bdata = 0,
    };
    static constexpr bool atFaces = false;
    ConstField aux;
    BoundaryView bc;

    KOKKOS_INLINE_FUNCTION void values(LO j, double (&w)[1]) const { w[0] = aux(j, Aux::eps); }
    KOKKOS_INLINE_FUNCTION Bounds bounds(Limiter, int) const { return Bounds::Unlimited; }
    KOKKOS_INLINE_FUNCTION bool mirrors(int g) const { return bc.type(g) == BcSlipWall; }
    KOKKOS_INLINE_FUNCTION void mirror(const Vec<D>&, double (&)[1]) const {}
    KOKKOS_INLINE_FUNCTION bool boundaryValue(int, double&) const { return false; }
};

//! minmod(r, jump): r clipped to [0, jump] (or [jump, 0]); 0 where r points against the jump. Odd in (r, jump).
KOKKOS_INLINE_FUNCTION double clipToJump(double r, double jump)
{
    if (r * jump <= 0.0)
        return 0.0;
    return jump > 0.0 ? Kokkos::Experimental::fmin(r, jump) : Kokkos::Experimental::fmax(r, jump);
}

} // namespace entropy_filter

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
            using Kokkos::Experimental::fmax;
            constexpr double shockRatio = 1.0 + entropy_filter::kShockKappa;
            if (aux(i, Aux::signal) > shockRatio * aux(i, Aux::sound))
                return;
            double sum = 0.0;
            for (int k = 0; k < NV; ++k)
            {
                const LO j = mesh.cellNeighbour(i, k);
                if (j < 0 || aux(j, Aux::signal) > shockRatio * aux(j, Aux::sound)) // boundary, shocked
                    continue;
                const double jump = aux(j, Aux::eps) - aux(i, Aux::eps);
                double residual = jump;
                for (int a = 0; a < D; ++a)
                    residual -= 0.5 * (gradEps(i, a) + gradEps(j, a)) * (centroid(j, a) - centroid(i, a));
                // the face's area vector antisymmetrised, (A_i - A_j)/2, m the face of j facing i (as Heat.hpp)
                Vec<D> area = Vec<D>::zero();
                for (int m = 0; m < NV; ++m)
                    if (mesh.cellNeighbour(j, m) == i)
                        for (int a = 0; a < D; ++a)
                            area[a] = (0.5 * D) * (corner(j, m * D + a) - corner(i, k * D + a));
                const double rho = 0.5 * (1.0 / state(i, S::omega) + 1.0 / state(j, S::omega));
                const double sound = fmax(aux(i, Aux::sound), aux(j, Aux::sound));
                sum += rho * sound * norm(area) * entropy_filter::clipToJump(residual, jump);
            }
            state(i, S::energy) += dt * coefficient * sum / mass(i);
        });
}

} // namespace unilag
