#include "mesh/Repartition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <Zoltan2_PartitioningProblem.hpp>
#include <Zoltan2_XpetraMultiVectorAdapter.hpp>

#include "core/Mpi.hpp"

namespace unilag
{

namespace
{

/*! Ranges of the global ids of equal cost: the ids follow a Morton curve of the initial cells (GlobalMesh.cpp), so
 *  the parts are compact. The costs travel by id to a contiguous map (rank p holds a range of ids, in order), where
 *  a prefix sum over the ranks places each cell; the parts come back with an Import. Each cell goes to the part
 *  that holds the midpoint of its cost interval. */
std::vector<int> curveOwners(const DistributedMesh& mesh, const std::vector<double>& cost)
{
    const int parts = mesh.comm->getSize();
    const MPI_Comm comm = mpi::rawComm(mesh.comm);
    auto line = Teuchos::rcp(new Map(mesh.nGlobalCells, 0, mesh.comm));
    MV owned(mesh.cellMap, 1), byId(line, 1);
    {
        auto o = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO i = 0; i < mesh.nOwnedCells; ++i)
            o(i, 0) = cost[i];
    }
    const Importer toLine(mesh.cellMap, line); // both maps one-to-one: the reverse mode brings the parts back
    byId.doImport(owned, toLine, Tpetra::INSERT);
    {
        auto c = byId.getLocalViewHost(Tpetra::Access::ReadWrite);
        double local = 0.0;
        for (std::size_t k = 0; k < c.extent(0); ++k)
            local += c(k, 0);
        double before = 0.0, total[1] = {local};
        MPI_Exscan(&local, &before, 1, MPI_DOUBLE, MPI_SUM, comm);
        if (mpi::rank(comm) == 0)
            before = 0.0;
        mpi::allSum(comm, total);
        const double share = total[0] / parts;
        for (std::size_t k = 0; k < c.extent(0); ++k)
        {
            const double mid = before + 0.5 * c(k, 0);
            before += c(k, 0);
            c(k, 0) = std::min(double(parts - 1), std::floor(mid / share));
        }
    }
    owned.doExport(byId, toLine, Tpetra::INSERT);
    auto o = owned.getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<int> owner(mesh.nOwnedCells);
    for (LO i = 0; i < mesh.nOwnedCells; ++i)
        owner[i] = int(o(i, 0));
    return owner;
}

} // namespace

std::vector<int> balancedOwners(const DistributedMesh& mesh, const MV& coords, const std::vector<double>& cost,
                                const std::string& algorithm)
{
    if (cost.size() != std::size_t(mesh.nOwnedCells))
        throw std::invalid_argument("balancedOwners: one cost per owned cell");
    const int rank = mesh.comm->getRank();
    if (mesh.comm->getSize() == 1)
        return std::vector<int>(mesh.nOwnedCells, rank);
    if (algorithm == "sfc")
        return curveOwners(mesh, cost);
    // centroids of the owned cells at the current positions (the cells have moved since the last partition)
    MV centroids(mesh.cellMap, mesh.dim);
    {
        auto x = coords.getLocalViewHost(Tpetra::Access::ReadOnly);
        auto c = centroids.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO i = 0; i < mesh.nOwnedCells; ++i)
            for (int d = 0; d < mesh.dim; ++d)
            {
                double sum = 0.0;
                for (int k = 0; k < mesh.nv; ++k)
                    sum += x(mesh.cellNodesHost[std::size_t(mesh.nv) * i + k], d);
                c(i, d) = sum / mesh.nv;
            }
    }
    using Adapter = Zoltan2::XpetraMultiVectorAdapter<MV>;
    std::vector<const double*> weights = {cost.data()};
    std::vector<int> strides = {1};
    Adapter adapter(Teuchos::rcpFromRef(std::as_const(centroids)), weights, strides);
    Teuchos::ParameterList zp("zoltan2");
    zp.set("algorithm", algorithm);
    zp.set("imbalance_tolerance", 1.05);
    zp.set("num_global_parts", mesh.comm->getSize());
    // rcb runs Zoltan (1), whose default DEBUG_LEVEL 1 printed its ~40 parameters on every rank at each repartition
    zp.sublist("zoltan_parameters").set("DEBUG_LEVEL", std::string("0"));
    Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &zp, mesh.comm);
    problem.solve();
    const auto* parts = problem.getSolution().getPartListView();
    return std::vector<int>(parts, parts + mesh.nOwnedCells);
}

double costImbalance(const DistributedMesh& mesh, const std::vector<double>& cost)
{
    const double mine = std::accumulate(cost.begin(), cost.end(), 0.0);
    double total[1] = {mine};
    mpi::allSum(mpi::rawComm(mesh.comm), total);
    const double largest = mpi::allMax(mpi::rawComm(mesh.comm), mine);
    return total[0] > 0.0 ? largest * mesh.comm->getSize() / total[0] : 1.0;
}

} // namespace unilag
