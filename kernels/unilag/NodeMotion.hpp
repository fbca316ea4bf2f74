/*! \file NodeMotion.hpp
 *  \brief Node kernels outside the nodal solve: the trajectories x^{n+1} = x^n + dt v_r (moveNodes) and the node
 *  velocities before the first solve (meanCellVelocityAtNodes). Included by Hydro.hpp.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"

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

/*! \brief The mean velocity of the cells around each owned node, into vnode: the lagged node velocities of the first
 *  step's impedance (nodalImpedance), before any nodal solve (zeros gave a moving gas a spurious shock term there:
 *  docs/ars222.md). */
template <int D, class P = PhysicsHydro>
void meanCellVelocityAtNodes(const MeshView<D>& mesh, const ConstField& state, const Field& vnode)
{
    auto mean = KOKKOS_LAMBDA(const LO r)
    {
        const LO first = mesh.nodeCornerOffsets(r), last = mesh.nodeCornerOffsets(r + 1);
        for (int d = 0; d < D; ++d)
        {
            double v = 0.0;
            for (LO q = first; q < last; ++q)
                v += state(mesh.nodeCorners(q) / (D + 1), StateLayout<D, P>::vel + d);
            vnode(r, d) = last > first ? v / double(last - first) : 0.0;
        }
    };
    Kokkos::parallel_for("unilag::gpr::mean_cell_velocity_at_nodes", range(mesh.nOwnedNodes), mean);
}

} // namespace unilag
