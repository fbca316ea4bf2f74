/*! \file NodeMotion.hpp
 *  \brief Node kernels outside the nodal solve: the trajectories x^{n+1} = x^n + dt v_r (moveNodes) and the node
 *  velocities before the first solve (meanCellVelocityAtNodes). Included by Hydro.hpp.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"
#include "unilag/Reconstruction.hpp"

namespace unilag
{

//! Moves nodes [0, n): xNew = x + dt v.
inline void moveNodes(const ConstField& x, const ConstField& vnode, double dt, const Field& xNew, LO n, int dim)
{
    auto move = KOKKOS_LAMBDA(const LO r)
    {
        for (int d = 0; d < dim; ++d)
            xNew(r, d) = x(r, d) + dt * vnode(r, d);
    };
    Kokkos::parallel_for("unilag::hydro::move_nodes", range(n), move);
}

//! The slip walls and symmetry planes of a BoundaryView, as the groups addMirrorPlanes asks about.
struct SlipWallGroups
{
    BoundaryView bc;
    KOKKOS_INLINE_FUNCTION bool mirrors(int g) const { return bc.type(g) == BcSlipWall; }
};

/*! \brief The mean velocity of the cells around each owned node, into vnode: the lagged node velocities of the first
 *  step's impedance (nodalImpedance), before any nodal solve (zeros gave a moving gas a spurious shock term there:
 *  docs/ars222.md). At a node on slip walls or symmetry planes (bc given) the components normal to them are removed:
 *  the mean over the cells of the mirrored mesh, so that the first step is the mirror problem's too. */
template <int D, class P = PhysicsHydro>
void meanCellVelocityAtNodes(const MeshView<D>& mesh, const ConstField& state, const ConstField& x, const Field& vnode,
                             const BoundaryView& bc = BoundaryView())
{
    const bool hasBc = bc.type.extent(0) > 0;
    auto mean = KOKKOS_LAMBDA(const LO r)
    {
        const LO first = mesh.nodeCornerOffsets(r), last = mesh.nodeCornerOffsets(r + 1);
        Vec<D> v = Vec<D>::zero();
        for (LO q = first; q < last; ++q)
            for (int d = 0; d < D; ++d)
                v[d] += state(mesh.nodeCorners(q) / (D + 1), StateLayout<D, P>::vel + d);
        if (last > first)
            v = (1.0 / double(last - first)) * v;
        Vec<D> plane[D];
        int nPlanes = 0;
        if (hasBc && mesh.mayBeOnBoundary(r))
            for (LO q = first; q < last; ++q)
                addMirrorPlanes<D>(mesh, SlipWallGroups{bc}, x, mesh.nodeCorners(q) / (D + 1),
                                   mesh.nodeCorners(q) % (D + 1), plane, nPlanes);
        Vec<D> Q[D]; // orthonormalised as the nodal solver does, so that non-orthogonal planes leave no normal part
        const int nq = orthonormalBasis<D>(plane, nPlanes, Q);
        for (int a = 0; a < nq; ++a)
            v = v - dot(v, Q[a]) * Q[a];
        for (int d = 0; d < D; ++d)
            vnode(r, d) = v[d];
    };
    Kokkos::parallel_for("unilag::gpr::mean_cell_velocity_at_nodes", range(mesh.nOwnedNodes), mean);
}

} // namespace unilag
