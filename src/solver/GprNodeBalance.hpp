/*! \file GprNodeBalance.hpp
 *  \brief Member functions of GprOperator: which nodes' force balance each update evaluates, and the balance of an
 *  update's forces over all ranks (BalanceRates, GprBalance.hpp). Included by GprOperator.hpp.
 */
#pragma once

#include <vector>

namespace unilag
{

template <int D, class P> void GprOperator<D, P>::selectBalanceNodes(bool everyNode)
{
    constexpr int NV = D + 1;
    const MeshView<D> mesh = md_.m;
    View<int*> flag("unilag::balance_flag", mesh.nOwnedNodes);
    auto mark = KOKKOS_LAMBDA(const LO r)
    {
        int onBoundary = everyNode ? 1 : 0;
        for (LO q = mesh.nodeCornerOffsets(r); q < mesh.nodeCornerOffsets(r + 1); ++q)
            for (int j = 0; j < NV; ++j)
                if (j != mesh.nodeCorners(q) % NV && mesh.cellFaceGroup(mesh.nodeCorners(q) / NV, j) >= 0)
                    onBoundary = 1;
        flag(r) = onBoundary;
    };
    Kokkos::parallel_for("unilag::check::balance_nodes", range(mesh.nOwnedNodes), mark);
    auto flagHost = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), flag);
    std::vector<LO> nodes;
    for (LO r = 0; r < mesh.nOwnedNodes; ++r)
        if (flagHost(r))
            nodes.push_back(r);
    balanceNodes_ = View<LO*>("unilag::balance_nodes", nodes.size());
    Kokkos::deep_copy(balanceNodes_, Kokkos::View<LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(nodes.data(),
                                                                                                   nodes.size()));
    balanceScratch_ = Field("unilag::balance_scratch", nodes.size(), NodeBalanceLayout<D>::ncomp);
}

//! The balance of the given forces at the selected nodes and the heat through isothermal walls. Collective.
template <int D, class P>
BalanceRates<D> GprOperator<D, P>::balanceOf(const SubcellForces<D, P>& forces, const Reconstruction<D>& heatRec)
{
    ScopedTimer timer(md_.timers, Phase::Check);
    NodeBalanceRates<D> local = nodeBalance<D, P>(forces, md_.bc, balanceNodes_, balanceScratch_);
    worstImbalance<D>(balanceNodes_, balanceScratch_, 1e-30 * mpi::allMax(md_.comm, local.maxForce), local);
    BalanceRates<D> r;
    double sums[D + 3];
    for (int d = 0; d < D; ++d)
        sums[d] = local.impulse[d];
    sums[D] = local.work;
    sums[D + 1] = local.passiveWork;
    sums[D + 2] = 0.0;
    if constexpr (P::heat)
        if (md_.isothermalWalls)
            sums[D + 2] = boundaryHeatRate<D, P>(heat::Faces<D, P>{md_.m, md_.bc, forces.state, forces.aux,
                                                                   forces.corner, md_.cellMaterial, md_.materials,
                                                                   heatRec});
    mpi::allSum(md_.comm, sums);
    for (int d = 0; d < D; ++d)
        r.impulse[d] = sums[d];
    r.work = sums[D];
    r.passiveWork = sums[D + 1];
    r.heat = sums[D + 2];
    r.maxImbalance = mpi::allMax(md_.comm, local.maxImbalance);
    // the worst node's global id, from the first rank that has the largest imbalance
    const int owner = mpi::argMinRank(md_.comm, -local.maxImbalance);
    double gid = local.worstNode >= 0 ? double(md_.mesh->nodeGid[local.worstNode]) : -1.0;
    MPI_Bcast(&gid, 1, MPI_DOUBLE, owner, md_.comm);
    r.worstNode = GO(gid);
    return r;
}

} // namespace unilag
