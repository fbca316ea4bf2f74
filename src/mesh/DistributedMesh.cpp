#include "mesh/DistributedMesh.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>

#include <Tpetra_Map_decl.hpp>
#include <Zoltan2_PartitioningProblem.hpp>
#include <Zoltan2_XpetraMultiVectorAdapter.hpp>

#include "core/Mpi.hpp"
#include "mesh/FaceKey.hpp"

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

Teuchos::RCP<const Map> mapOf(const std::vector<GO>& gids, const Teuchos::RCP<const Comm>& comm)
{
    const auto INV = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    return Teuchos::rcp(new Map(INV, Teuchos::ArrayView<const GO>(gids.data(), gids.size()), 0, comm));
}

} // namespace

std::shared_ptr<DistributedMesh> DistributedMesh::distribute(const GlobalMesh& root, Teuchos::RCP<const Comm> comm)
{
    auto mesh = std::make_shared<DistributedMesh>();
    mesh->comm = comm;
    MPI_Comm raw = mpi::rawComm(comm);
    const int rank = comm->getRank();
    const bool isRoot = rank == 0;

    long long header[3] = {root.dim, (long long)root.nCells(), (long long)root.nNodes()};
    MPI_Bcast(header, 3, MPI_LONG_LONG, 0, raw);
    mesh->dim = int(header[0]);
    mesh->nv = mesh->dim + 1;
    mesh->nGlobalCells = header[1];
    mesh->nGlobalNodes = header[2];
    mesh->regionNames = root.regionNames;
    mesh->boundaryNames = root.boundaryNames;
    broadcastNames(mesh->regionNames, raw);
    broadcastNames(mesh->boundaryNames, raw);
    const int nv = mesh->nv, dim = mesh->dim;

    // Everything starts on rank 0.
    auto rootCells = Teuchos::rcp(new Map(mesh->nGlobalCells, isRoot ? mesh->nGlobalCells : 0, 0, comm));
    auto rootNodes = Teuchos::rcp(new Map(mesh->nGlobalNodes, isRoot ? mesh->nGlobalNodes : 0, 0, comm));
    MV records(rootCells, 1 + 2 * nv);
    MV coords(rootNodes, 3);
    MV centroids(rootCells, dim);
    if (isRoot)
    {
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

    // Zoltan2 multijagged on cell centroids.
    Teuchos::RCP<const Map> owned = rootCells;
    if (comm->getSize() > 1)
    {
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
        owned = mapOf(gids, comm);
    }
    MV mine(owned, 1 + 2 * nv);
    mine.doImport(records, Importer(rootCells, owned), Tpetra::INSERT);

    OwnedCells oc;
    {
        auto r = mine.getLocalViewHost(Tpetra::Access::ReadOnly);
        const LO n = LO(owned->getNodeNumElements());
        for (LO i = 0; i < n; ++i)
        {
            oc.gid.push_back(owned->getGlobalElement(i));
            oc.region.push_back(int(r(i, 0)));
            for (int k = 0; k < nv; ++k)
            {
                oc.nodes.push_back(GO(r(i, 1 + k)));
                oc.groups.push_back(int(r(i, 1 + nv + k)));
            }
        }
    }
    mesh->buildFromOwnedCells(oc, coords);
    return mesh;
}

void DistributedMesh::buildFromOwnedCells(const OwnedCells& oc, const MV& rootCoords)
{
    MPI_Comm raw = mpi::rawComm(comm);
    const int nranks = comm->getSize();
    const LO nOwn = LO(oc.gid.size());
    cellMap = mapOf(oc.gid, comm);

    // Node ownership: one rank among those owning a cell around the node.
    std::vector<GO> touched(oc.nodes);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    auto ownedNodesMap = Tpetra::createOneToOne(mapOf(touched, comm));
    std::vector<GO> ownedNodes(ownedNodesMap->getNodeElementList().begin(), ownedNodesMap->getNodeElementList().end());
    std::sort(ownedNodes.begin(), ownedNodes.end());
    nodeMap = mapOf(ownedNodes, comm);

    // Ghosts: send every (node, cell record) to the node's owner, which then knows all cells around it.
    std::vector<int> owner(oc.nodes.size());
    {
        // query each distinct node once (the directory lookup does not like repeated ids)
        Teuchos::Array<int> pids(touched.size());
        nodeMap->getRemoteIndexList(Teuchos::ArrayView<const GO>(touched.data(), touched.size()), pids());
        for (std::size_t q = 0; q < oc.nodes.size(); ++q)
            owner[q] = pids[std::lower_bound(touched.begin(), touched.end(), oc.nodes[q]) - touched.begin()];
    }
    const int L = 3 + 2 * nv; // node, cell gid, region, nodes, groups
    std::vector<int> sendCount(nranks, 0), recvCount(nranks), sdispl(nranks + 1, 0), rdispl(nranks + 1, 0);
    for (std::size_t q = 0; q < oc.nodes.size(); ++q)
        sendCount[owner[q]] += L;
    for (int p = 0; p < nranks; ++p)
        sdispl[p + 1] = sdispl[p] + sendCount[p];
    std::vector<long long> sendBuf(sdispl[nranks]);
    {
        std::vector<int> pos(sdispl.begin(), sdispl.end() - 1);
        for (LO i = 0; i < nOwn; ++i)
            for (int k = 0; k < nv; ++k)
            {
                const std::size_t q = std::size_t(nv) * i + k;
                long long* rec = &sendBuf[pos[owner[q]]];
                pos[owner[q]] += L;
                rec[0] = oc.nodes[q];
                rec[1] = oc.gid[i];
                rec[2] = oc.region[i];
                for (int j = 0; j < nv; ++j)
                {
                    rec[3 + j] = oc.nodes[std::size_t(nv) * i + j];
                    rec[3 + nv + j] = oc.groups[std::size_t(nv) * i + j];
                }
            }
    }
    MPI_Alltoall(sendCount.data(), 1, MPI_INT, recvCount.data(), 1, MPI_INT, raw);
    for (int p = 0; p < nranks; ++p)
        rdispl[p + 1] = rdispl[p] + recvCount[p];
    std::vector<long long> recvBuf(rdispl[nranks]);
    MPI_Alltoallv(sendBuf.data(), sendCount.data(), sdispl.data(), MPI_LONG_LONG, recvBuf.data(), recvCount.data(),
                  rdispl.data(), MPI_LONG_LONG, raw);

    // The node owner now holds every cell around its owned nodes (from the records of phase 1). Phase 2: it
    // sends back, to each other rank that touches the node, the cells around the node that rank does not own;
    // so every rank receives every cell that shares a node with one of its owned cells.
    const int me = comm->getRank();
    std::vector<int> recvRank(recvBuf.size() / L);
    for (int p = 0; p < nranks; ++p)
        for (int off = rdispl[p]; off < rdispl[p + 1]; off += L)
            recvRank[off / L] = p;
    std::vector<int> send2Count(nranks, 0), recv2Count(nranks), s2displ(nranks + 1, 0), r2displ(nranks + 1, 0);
    std::vector<std::vector<long long>> send2(nranks);
    {
        // records grouped by node
        std::vector<std::pair<GO, std::size_t>> byNode;
        byNode.reserve(recvBuf.size() / L);
        for (std::size_t off = 0; off < recvBuf.size(); off += L)
            byNode.emplace_back(recvBuf[off], off);
        std::sort(byNode.begin(), byNode.end());
        std::vector<char> touches(nranks);
        std::vector<std::unordered_set<GO>> sent(nranks); // each cell once per destination
        for (std::size_t a = 0, b; a < byNode.size(); a = b)
        {
            for (b = a; b < byNode.size() && byNode[b].first == byNode[a].first;)
                ++b;
            std::fill(touches.begin(), touches.end(), 0);
            for (std::size_t q = a; q < b; ++q)
                touches[recvRank[byNode[q].second / L]] = 1;
            for (int p = 0; p < nranks; ++p)
            {
                if (p == me || !touches[p])
                    continue;
                for (std::size_t q = a; q < b; ++q)
                {
                    const std::size_t off = byNode[q].second;
                    if (recvRank[off / L] != p && sent[p].insert(recvBuf[off + 1]).second)
                        send2[p].insert(send2[p].end(), recvBuf.begin() + off, recvBuf.begin() + off + L);
                }
            }
        }
    }
    for (int p = 0; p < nranks; ++p)
    {
        send2Count[p] = int(send2[p].size());
        s2displ[p + 1] = s2displ[p] + send2Count[p];
    }
    std::vector<long long> send2Buf(s2displ[nranks]);
    for (int p = 0; p < nranks; ++p)
        std::copy(send2[p].begin(), send2[p].end(), send2Buf.begin() + s2displ[p]);
    MPI_Alltoall(send2Count.data(), 1, MPI_INT, recv2Count.data(), 1, MPI_INT, raw);
    for (int p = 0; p < nranks; ++p)
        r2displ[p + 1] = r2displ[p] + recv2Count[p];
    std::vector<long long> recv2Buf(r2displ[nranks]);
    MPI_Alltoallv(send2Buf.data(), send2Count.data(), s2displ.data(), MPI_LONG_LONG, recv2Buf.data(),
                  recv2Count.data(), r2displ.data(), MPI_LONG_LONG, raw);

    // Ghosts: the cells of both phases that this rank does not own (records of one cell are identical).
    std::map<GO, const long long*> ghostRecord; // gid -> record
    {
        std::unordered_map<GO, LO> isOwned;
        for (LO i = 0; i < nOwn; ++i)
            isOwned[oc.gid[i]] = i;
        for (const auto* buf : {&recvBuf, &recv2Buf})
            for (std::size_t off = 0; off < buf->size(); off += L)
                if (!isOwned.count((*buf)[off + 1]))
                    ghostRecord.emplace((*buf)[off + 1], buf->data() + off);
    }

    // Local cells: owned (sorted) then ghosts (sorted).
    nOwnedCells = nOwn;
    nCells = nOwn + LO(ghostRecord.size());
    cellGid = oc.gid;
    cellRegion = oc.region;
    std::vector<GO> cellNodeGid(oc.nodes);
    cellFaceGroupHost = oc.groups;
    for (const auto& [gid, rec] : ghostRecord)
    {
        cellGid.push_back(gid);
        cellRegion.push_back(int(rec[2]));
        for (int j = 0; j < nv; ++j)
        {
            cellNodeGid.push_back(rec[3 + j]);
            cellFaceGroupHost.push_back(int(rec[3 + nv + j]));
        }
    }
    cellMapOverlap = mapOf(cellGid, comm);

    // Local nodes: owned (sorted) then the other nodes of local cells (sorted).
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
    nodeMapOverlap = mapOf(nodeGid, comm);
    cellImporter = Teuchos::rcp(new Importer(cellMap, cellMapOverlap));
    nodeImporter = Teuchos::rcp(new Importer(nodeMap, nodeMapOverlap));

    std::unordered_map<GO, LO> nodeLid;
    for (LO n = 0; n < nNodes; ++n)
        nodeLid[nodeGid[n]] = n;
    cellNodesHost.resize(cellNodeGid.size());
    for (std::size_t q = 0; q < cellNodeGid.size(); ++q)
        cellNodesHost[q] = nodeLid.at(cellNodeGid[q]);

    // Face neighbours: faces (opposite local node k) matched by their sorted local node ids.
    {
        static_assert(std::is_same_v<LO, int>, "FaceKey holds local node ids as int");
        cellNeighbourHost.assign(cellNodesHost.size(), -1);
        auto link = [this](const FaceRef& a, const FaceRef& b) {
            cellNeighbourHost[std::size_t(nv) * a.cell + a.k] = b.cell;
            cellNeighbourHost[std::size_t(nv) * b.cell + b.k] = a.cell;
        };
        if (matchFaces(cellNodesHost.data(), std::size_t(nCells), nv, link, [](const FaceRef&) {}))
            throw std::logic_error("DistributedMesh: a face is shared by more than two cells");
        // Owned cells see every face neighbour (the ghost layer holds all cells sharing a node with them), so
        // an owned face has a local neighbour exactly when it is not a boundary face.
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

    // Coordinates of all local nodes.
    {
        MV x(nodeMapOverlap, 3);
        x.doImport(rootCoords, Importer(rootCoords.getMap(), nodeMapOverlap), Tpetra::INSERT);
        auto xh = x.getLocalViewHost(Tpetra::Access::ReadOnly);
        coords0.resize(3 * std::size_t(nNodes));
        for (LO n = 0; n < nNodes; ++n)
            for (int d = 0; d < 3; ++d)
                coords0[3 * n + d] = xh(n, d);
    }

    // Node -> corner CSR, corners sorted by (global cell id, local node).
    std::vector<LO> offsets(nNodes + 1, 0);
    for (LO q = 0; q < LO(cellNodesHost.size()); ++q)
        ++offsets[cellNodesHost[q] + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<LO> corners(cellNodesHost.size());
    {
        std::vector<LO> pos(offsets.begin(), offsets.end() - 1);
        for (LO q = 0; q < LO(cellNodesHost.size()); ++q)
            corners[pos[cellNodesHost[q]]++] = q;
        for (LO n = 0; n < nNodes; ++n)
            std::sort(corners.begin() + offsets[n], corners.begin() + offsets[n + 1], [&](LO a, LO b) {
                return std::make_pair(cellGid[a / nv], a % nv) < std::make_pair(cellGid[b / nv], b % nv);
            });
    }

    // Device copies.
    cellNodes = Kokkos::View<LO**, Kokkos::LayoutLeft, MemSpace>("unilag::cellNodes", nCells, nv);
    cellFaceGroup = View<int**>("unilag::cellFaceGroup", nCells, nv);
    cellNeighbour = View<LO**>("unilag::cellNeighbour", nCells, nv);
    nodeCornerOffsets = View<LO*>("unilag::nodeCornerOffsets", nNodes + 1);
    nodeCorners = View<LO*>("unilag::nodeCorners", corners.size());
    {
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
        Kokkos::deep_copy(nodeCornerOffsets,
                          Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(offsets.data(), offsets.size()));
        Kokkos::deep_copy(nodeCorners,
                          Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(corners.data(), corners.size()));
    }

    // Output numbering: contiguous per rank for owned nodes, imported for the others.
    nodeOutputOffset = mpi::exclusiveOffset(raw, nOwnedNodes);
    {
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
}

} // namespace unilag
