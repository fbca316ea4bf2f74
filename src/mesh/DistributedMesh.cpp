#include "mesh/DistributedMesh.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>

#include <Tpetra_Map_decl.hpp>
#include <Zoltan2_PartitioningProblem.hpp>
#include <Zoltan2_XpetraMultiVectorAdapter.hpp>

#include "core/Mpi.hpp"
#include "mesh/FaceKey.hpp"
#include "mesh/GhostCells.hpp"

namespace unilag
{
namespace
{

void broadcastNames(std::vector<std::string>& names, MPI_Comm comm)
{
    std::string packed;
    for (const auto& n : names)
        packed += n + '\n';
    int len = int(packed.size());
    MPI_Bcast(&len, 1, MPI_INT, 0, comm);
    packed.resize(len);
    MPI_Bcast(packed.data(), len, MPI_CHAR, 0, comm);
    names.clear();
    std::size_t start = 0, nl;
    while ((nl = packed.find('\n', start)) != std::string::npos)
    {
        names.push_back(packed.substr(start, nl - start));
        start = nl + 1;
    }
}

//! Dimension, global counts and group names: rank 0's, on every rank.
void broadcastHeader(const GlobalMesh& root, DistributedMesh& mesh, MPI_Comm comm)
{
    long long header[3] = {root.dim, (long long)root.nCells(), (long long)root.nNodes()};
    MPI_Bcast(header, 3, MPI_LONG_LONG, 0, comm);
    mesh.dim = int(header[0]);
    mesh.nv = mesh.dim + 1;
    mesh.nGlobalCells = header[1];
    mesh.nGlobalNodes = header[2];
    mesh.regionNames = root.regionNames;
    mesh.boundaryNames = root.boundaryNames;
    broadcastNames(mesh.regionNames, comm);
    broadcastNames(mesh.boundaryNames, comm);
}

//! Rank 0's mesh as rows of MultiVectors on rank 0: cell records, node coordinates and cell centroids.
void writeRootRows(const GlobalMesh& root, MV& records, MV& coords, MV& centroids)
{
    const int nv = root.nv(), dim = root.dim;
    auto r = records.getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto x = coords.getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto c = centroids.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t n = 0; n < root.nNodes(); ++n)
        for (int d = 0; d < 3; ++d)
            x(n, d) = root.coords[3 * n + d];
    for (std::size_t i = 0; i < root.nCells(); ++i)
    {
        r(i, 0) = root.cellRegion[i];
        for (int k = 0; k < nv; ++k)
        {
            const int node = root.cells[nv * i + k];
            r(i, 1 + k) = node; // gids up to 2^53 travel exactly as doubles
            r(i, 1 + nv + k) = root.cellFaceGroup[nv * i + k];
            for (int d = 0; d < dim; ++d)
                c(i, d) += root.coords[3 * node + d] / nv;
        }
    }
}

//! The cells each rank owns: Zoltan2 multijagged on the cell centroids (all on rank 0 before), sorted by gid.
Teuchos::RCP<const Map> partitionCells(MV& centroids, const Teuchos::RCP<const Comm>& comm)
{
    if (comm->getSize() == 1)
        return centroids.getMap();
    using Adapter = Zoltan2::XpetraMultiVectorAdapter<MV>;
    auto xc = Teuchos::rcpFromRef(centroids);
    Adapter adapter(xc);
    Teuchos::ParameterList zp("zoltan2");
    zp.set("algorithm", "multijagged");
    zp.set("imbalance_tolerance", 1.05);
    zp.set("num_global_parts", comm->getSize());
    Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &zp, comm);
    problem.solve();
    Teuchos::RCP<MV> moved;
    adapter.applyPartitioningSolution(centroids, moved, problem.getSolution());
    auto list = moved->getMap()->getNodeElementList();
    std::vector<GO> gids(list.begin(), list.end());
    std::sort(gids.begin(), gids.end());
    return mapOfGids(gids, comm);
}

//! rebuild's input errors, the same on every rank ("" when all is well). Collective.
std::string rebuildInputError(const DistributedMesh& old, const std::vector<int>& newOwner, const MV& coords)
{
    const int nranks = old.comm->getSize();
    std::string error;
    if (newOwner.size() != std::size_t(old.nOwnedCells))
        error = "newOwner has " + std::to_string(newOwner.size()) + " entries for " +
                std::to_string(old.nOwnedCells) + " owned cells";
    else if (std::any_of(newOwner.begin(), newOwner.end(), [&](int p) { return p < 0 || p >= nranks; }))
        error = "newOwner names a rank outside [0, " + std::to_string(nranks) + ")";
    else if (coords.getNumVectors() != 3)
        error = "coords has " + std::to_string(coords.getNumVectors()) + " columns, not 3";
    // isSameAs is collective: every rank asks both
    const bool onOwned = coords.getMap()->isSameAs(*old.nodeMap);
    const bool onOverlap = coords.getMap()->isSameAs(*old.nodeMapOverlap);
    if (error.empty() && !onOwned && !onOverlap)
        error = "coords is on neither the old nodeMap nor nodeMapOverlap";
    error = mpi::firstMessage(mpi::rawComm(old.comm), error);
    return error.empty() ? error : "DistributedMesh::rebuild: " + error;
}

} // namespace

std::shared_ptr<DistributedMesh> DistributedMesh::distribute(const GlobalMesh& root, Teuchos::RCP<const Comm> comm)
{
    auto mesh = std::make_shared<DistributedMesh>();
    mesh->comm = comm;
    broadcastHeader(root, *mesh, mpi::rawComm(comm));
    const bool isRoot = comm->getRank() == 0;

    // Everything starts on rank 0.
    const GO nc = mesh->nGlobalCells, nn = mesh->nGlobalNodes;
    auto rootCells = Teuchos::rcp(new Map(nc, isRoot ? nc : 0, 0, comm));
    auto rootNodes = Teuchos::rcp(new Map(nn, isRoot ? nn : 0, 0, comm));
    MV records(rootCells, recordColumns(mesh->nv));
    MV coords(rootNodes, 3);
    MV centroids(rootCells, mesh->dim);
    if (isRoot)
        writeRootRows(root, records, coords, centroids);

    auto owned = partitionCells(centroids, comm);
    MV mine(owned, recordColumns(mesh->nv));
    mine.doImport(records, Importer(rootCells, owned), Tpetra::INSERT);
    mesh->buildFromOwnedCells(readRecordRows(mine, mesh->nv), coords);
    return mesh;
}

std::shared_ptr<DistributedMesh> DistributedMesh::rebuild(const DistributedMesh& old, const std::vector<int>& newOwner,
                                                          const MV& coords)
{
    const std::string error = rebuildInputError(old, newOwner, coords);
    if (!error.empty())
        throw std::invalid_argument(error);
    auto mesh = std::make_shared<DistributedMesh>();
    mesh->comm = old.comm;
    mesh->dim = old.dim;
    mesh->nv = old.nv;
    mesh->nGlobalCells = old.nGlobalCells;
    mesh->nGlobalNodes = old.nGlobalNodes;
    mesh->regionNames = old.regionNames;
    mesh->boundaryNames = old.boundaryNames;

    const CellRecords moved = migrateRecords(old.ownedRecords(), newOwner, old.cellMap);
    // the owned rows come first in nodeMapOverlap, so its first nOwnedNodes rows are a vector on nodeMap
    auto ownedCoords = coords.getMap()->isSameAs(*old.nodeMap) ? Teuchos::rcpFromRef(coords)
                                                               : coords.offsetView(old.nodeMap, 0);
    mesh->buildFromOwnedCells(moved, *ownedCoords);
    return mesh;
}

CellRecords DistributedMesh::ownedRecords() const
{
    CellRecords owned;
    owned.nv = nv;
    std::vector<GO> nodes(nv);
    for (LO i = 0; i < nOwnedCells; ++i)
    {
        for (int k = 0; k < nv; ++k)
            nodes[k] = nodeGid[cellNodesHost[std::size_t(nv) * i + k]];
        owned.append(cellGid[i], cellRegion[i], nodes.data(), &cellFaceGroupHost[std::size_t(nv) * i]);
    }
    return owned;
}

void DistributedMesh::buildFromOwnedCells(const CellRecords& owned, const MV& coords)
{
    cellMap = mapOfGids(owned.gid, comm);

    // Node ownership: one rank among those owning a cell around the node.
    std::vector<GO> touched(owned.nodes);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    auto ownedNodesMap = Tpetra::createOneToOne(mapOfGids(touched, comm));
    std::vector<GO> ownedNodes(ownedNodesMap->getNodeElementList().begin(), ownedNodesMap->getNodeElementList().end());
    std::sort(ownedNodes.begin(), ownedNodes.end());
    nodeMap = mapOfGids(ownedNodes, comm);

    const CellRecords ghosts = gatherGhostCells(owned, touched, *nodeMap, mpi::rawComm(comm));
    const std::vector<GO> cellNodeGid = setLocalCells(owned, ghosts);
    setLocalNodes(ownedNodes, cellNodeGid);
    findFaceNeighbours();
    importCoordinates(coords);
    buildDeviceViews();
    numberOutputNodes();
}

//! Local cells: owned (sorted by gid) then ghosts (sorted by gid). Returns their node gids, nv per cell.
std::vector<GO> DistributedMesh::setLocalCells(const CellRecords& owned, const CellRecords& ghosts)
{
    nOwnedCells = LO(owned.size());
    nCells = nOwnedCells + LO(ghosts.size());
    cellGid = owned.gid;
    cellGid.insert(cellGid.end(), ghosts.gid.begin(), ghosts.gid.end());
    cellRegion = owned.region;
    cellRegion.insert(cellRegion.end(), ghosts.region.begin(), ghosts.region.end());
    cellFaceGroupHost = owned.groups;
    cellFaceGroupHost.insert(cellFaceGroupHost.end(), ghosts.groups.begin(), ghosts.groups.end());
    cellMapOverlap = mapOfGids(cellGid, comm);
    std::vector<GO> cellNodeGid(owned.nodes);
    cellNodeGid.insert(cellNodeGid.end(), ghosts.nodes.begin(), ghosts.nodes.end());
    return cellNodeGid;
}

//! Local nodes: owned (sorted) then the other nodes of local cells (sorted); the importers and cellNodesHost.
void DistributedMesh::setLocalNodes(const std::vector<GO>& ownedNodes, const std::vector<GO>& cellNodeGid)
{
    std::vector<GO> others;
    {
        std::vector<GO> all(cellNodeGid);
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        std::set_difference(all.begin(), all.end(), ownedNodes.begin(), ownedNodes.end(), std::back_inserter(others));
    }
    nodeGid = ownedNodes;
    nodeGid.insert(nodeGid.end(), others.begin(), others.end());
    nOwnedNodes = LO(ownedNodes.size());
    nNodes = LO(nodeGid.size());
    nodeMapOverlap = mapOfGids(nodeGid, comm);
    cellImporter = Teuchos::rcp(new Importer(cellMap, cellMapOverlap));
    nodeImporter = Teuchos::rcp(new Importer(nodeMap, nodeMapOverlap));

    std::unordered_map<GO, LO> nodeLid;
    for (LO n = 0; n < nNodes; ++n)
        nodeLid[nodeGid[n]] = n;
    cellNodesHost.resize(cellNodeGid.size());
    for (std::size_t q = 0; q < cellNodeGid.size(); ++q)
        cellNodesHost[q] = nodeLid.at(cellNodeGid[q]);
}

//! Face neighbours: faces (opposite local node k) matched by their sorted local node ids.
void DistributedMesh::findFaceNeighbours()
{
    static_assert(std::is_same_v<LO, int>, "FaceKey holds local node ids as int");
    cellNeighbourHost.assign(cellNodesHost.size(), -1);
    auto link = [this](const FaceRef& a, const FaceRef& b) {
        cellNeighbourHost[std::size_t(nv) * a.cell + a.k] = b.cell;
        cellNeighbourHost[std::size_t(nv) * b.cell + b.k] = a.cell;
    };
    if (matchFaces(cellNodesHost.data(), std::size_t(nCells), nv, link, [](const FaceRef&) {}))
        throw std::logic_error("DistributedMesh: a face is shared by more than two cells");
    // Owned cells see every face neighbour (the ghost layer holds all cells sharing a node with them), so an
    // owned face has a local neighbour exactly when it is not a boundary face.
    for (LO i = 0; i < nOwnedCells; ++i)
        for (int k = 0; k < nv; ++k)
        {
            const std::size_t q = std::size_t(nv) * i + k;
            if ((cellFaceGroupHost[q] < 0) != (cellNeighbourHost[q] >= 0))
                throw std::logic_error("DistributedMesh: face " + std::to_string(k) + " of cell " +
                                       std::to_string(cellGid[i]) +
                                       (cellFaceGroupHost[q] < 0 ? " is interior but has no local neighbour"
                                                                 : " is a boundary face with a neighbour"));
        }
}

//! coords0 of all local nodes, imported from coords (3 columns on a one-to-one node map).
void DistributedMesh::importCoordinates(const MV& coords)
{
    MV x(nodeMapOverlap, 3);
    x.doImport(coords, Importer(coords.getMap(), nodeMapOverlap), Tpetra::INSERT);
    auto xh = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    coords0.resize(3 * std::size_t(nNodes));
    for (LO n = 0; n < nNodes; ++n)
        for (int d = 0; d < 3; ++d)
            coords0[3 * n + d] = xh(n, d);
}

/*! The node -> corner CSR (corner q = nv * cell + local node), each node's corners sorted by (global cell id,
 *  local node): node sums then add in the same order on any number of ranks. */
void DistributedMesh::nodeCornerLists(std::vector<LO>& offsets, std::vector<LO>& corners) const
{
    offsets.assign(nNodes + 1, 0);
    for (LO q = 0; q < LO(cellNodesHost.size()); ++q)
        ++offsets[cellNodesHost[q] + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    corners.resize(cellNodesHost.size());
    std::vector<LO> pos(offsets.begin(), offsets.end() - 1);
    for (LO q = 0; q < LO(cellNodesHost.size()); ++q)
        corners[pos[cellNodesHost[q]]++] = q;
    for (LO n = 0; n < nNodes; ++n)
        std::sort(corners.begin() + offsets[n], corners.begin() + offsets[n + 1], [&](LO a, LO b) {
            return std::make_pair(cellGid[a / nv], a % nv) < std::make_pair(cellGid[b / nv], b % nv);
        });
}

//! Device copies of the cell tables and of the node -> corner lists.
void DistributedMesh::buildDeviceViews()
{
    std::vector<LO> offsets, corners;
    nodeCornerLists(offsets, corners);
    cellNodes = Kokkos::View<LO**, Kokkos::LayoutLeft, MemSpace>("unilag::cellNodes", nCells, nv);
    cellFaceGroup = View<int**>("unilag::cellFaceGroup", nCells, nv);
    cellNeighbour = View<LO**>("unilag::cellNeighbour", nCells, nv);
    nodeCornerOffsets = View<LO*>("unilag::nodeCornerOffsets", nNodes + 1);
    nodeCorners = View<LO*>("unilag::nodeCorners", corners.size());
    auto cn = Kokkos::create_mirror_view(cellNodes);
    auto fg = Kokkos::create_mirror_view(cellFaceGroup);
    auto nb = Kokkos::create_mirror_view(cellNeighbour);
    for (LO i = 0; i < nCells; ++i)
        for (int k = 0; k < nv; ++k)
        {
            cn(i, k) = cellNodesHost[std::size_t(nv) * i + k];
            fg(i, k) = cellFaceGroupHost[std::size_t(nv) * i + k];
            nb(i, k) = cellNeighbourHost[std::size_t(nv) * i + k];
        }
    Kokkos::deep_copy(cellNodes, cn);
    Kokkos::deep_copy(cellFaceGroup, fg);
    Kokkos::deep_copy(cellNeighbour, nb);
    using HostArray = Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
    Kokkos::deep_copy(nodeCornerOffsets, HostArray(offsets.data(), offsets.size()));
    Kokkos::deep_copy(nodeCorners, HostArray(corners.data(), corners.size()));
    nodeBoundary = View<int*>("unilag::nodeBoundary", nNodes);
    auto onBoundary = Kokkos::create_mirror_view(nodeBoundary);
    for (LO i = 0; i < nCells; ++i)
        for (int f = 0; f < nv; ++f)
            if (fg(i, f) >= 0)
                for (int k = 0; k < nv; ++k)
                    if (k != f) // face f is opposite local node f
                        onBoundary(cn(i, k)) = 1;
    Kokkos::deep_copy(nodeBoundary, onBoundary);
}

//! Output numbering: contiguous per rank for owned nodes, imported for the others.
void DistributedMesh::numberOutputNodes()
{
    nodeOutputOffset = mpi::exclusiveOffset(mpi::rawComm(comm), nOwnedNodes);
    MV ids(nodeMap, 1), idsOv(nodeMapOverlap, 1);
    {
        auto h = ids.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO n = 0; n < nOwnedNodes; ++n)
            h(n, 0) = double(nodeOutputOffset + n);
    }
    idsOv.doImport(ids, *nodeImporter, Tpetra::INSERT);
    auto h = idsOv.getLocalViewHost(Tpetra::Access::ReadOnly);
    nodeOutputId.resize(nNodes);
    for (LO n = 0; n < nNodes; ++n)
        nodeOutputId[n] = (long long)h(n, 0);
}

} // namespace unilag
