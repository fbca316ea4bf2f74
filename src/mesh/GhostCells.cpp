#include "mesh/GhostCells.hpp"

#include <algorithm>
#include <map>
#include <unordered_set>
#include <utility>

namespace unilag
{
namespace
{

/*! A message of (node, cell record) entries: node gid, cell gid, region, nv node gids, nv face groups. The node
 *  says why the cell is sent: the sender owns a cell around that node (phase 1), or the receiver does (phase 2). */
int entryLength(int nv)
{
    return 3 + 2 * nv;
}

//! What an all-to-all exchange delivered: the entries of rank p in [displ[p], displ[p + 1]).
struct Received
{
    std::vector<long long> buf;
    std::vector<int> displ;
};

//! Sends outbox[p] to rank p and receives what every rank sent here. Collective.
Received allToAll(const std::vector<std::vector<long long>>& outbox, MPI_Comm comm)
{
    const int nranks = int(outbox.size());
    std::vector<int> sendCount(nranks), recvCount(nranks), sdispl(nranks + 1, 0);
    for (int p = 0; p < nranks; ++p)
    {
        sendCount[p] = int(outbox[p].size());
        sdispl[p + 1] = sdispl[p] + sendCount[p];
    }
    std::vector<long long> sendBuf(sdispl[nranks]);
    for (int p = 0; p < nranks; ++p)
        std::copy(outbox[p].begin(), outbox[p].end(), sendBuf.begin() + sdispl[p]);
    MPI_Alltoall(sendCount.data(), 1, MPI_INT, recvCount.data(), 1, MPI_INT, comm);
    Received in;
    in.displ.assign(nranks + 1, 0);
    for (int p = 0; p < nranks; ++p)
        in.displ[p + 1] = in.displ[p] + recvCount[p];
    in.buf.resize(in.displ[nranks]);
    MPI_Alltoallv(sendBuf.data(), sendCount.data(), sdispl.data(), MPI_LONG_LONG, in.buf.data(), recvCount.data(),
                  in.displ.data(), MPI_LONG_LONG, comm);
    return in;
}

//! The owning rank of each node of each owned cell (nv per cell).
std::vector<int> nodeOwners(const CellRecords& owned, const std::vector<GO>& touched, const Map& nodeMap)
{
    // query each distinct node once (the directory lookup does not like repeated ids)
    Teuchos::Array<int> pids(touched.size());
    nodeMap.getRemoteIndexList(Teuchos::ArrayView<const GO>(touched.data(), touched.size()), pids());
    std::vector<int> owner(owned.nodes.size());
    for (std::size_t q = 0; q < owned.nodes.size(); ++q)
        owner[q] = pids[std::lower_bound(touched.begin(), touched.end(), owned.nodes[q]) - touched.begin()];
    return owner;
}

//! Phase 1: every (node, owned cell) entry goes to the node's owner, which then knows all cells around its nodes.
Received sendToNodeOwners(const CellRecords& owned, const std::vector<int>& owner, int nranks, MPI_Comm comm)
{
    const int nv = owned.nv;
    std::vector<std::vector<long long>> outbox(nranks);
    for (std::size_t i = 0; i < owned.size(); ++i)
        for (int k = 0; k < nv; ++k)
        {
            const std::size_t q = std::size_t(nv) * i + k;
            auto& out = outbox[owner[q]];
            out.push_back(owned.nodes[q]);
            out.push_back(owned.gid[i]);
            out.push_back(owned.region[i]);
            out.insert(out.end(), owned.nodes.begin() + nv * i, owned.nodes.begin() + nv * (i + 1));
            out.insert(out.end(), owned.groups.begin() + nv * i, owned.groups.begin() + nv * (i + 1));
        }
    return allToAll(outbox, comm);
}

/*! Phase 2: the node owner sends back, to each other rank that touches the node, the cells around the node that
 *  rank does not own; so every rank receives every cell that shares a node with one of its owned cells. */
Received returnNodeNeighbours(const Received& atOwner, int nv, int me, MPI_Comm comm)
{
    const int L = entryLength(nv), nranks = int(atOwner.displ.size()) - 1;
    const std::vector<long long>& buf = atOwner.buf;
    std::vector<int> fromRank(buf.size() / L);
    for (int p = 0; p < nranks; ++p)
        for (int off = atOwner.displ[p]; off < atOwner.displ[p + 1]; off += L)
            fromRank[off / L] = p;
    // entries grouped by node
    std::vector<std::pair<GO, std::size_t>> byNode;
    byNode.reserve(buf.size() / L);
    for (std::size_t off = 0; off < buf.size(); off += L)
        byNode.emplace_back(buf[off], off);
    std::sort(byNode.begin(), byNode.end());
    std::vector<std::vector<long long>> outbox(nranks);
    std::vector<char> touches(nranks);
    std::vector<std::unordered_set<GO>> sent(nranks); // each cell once per destination
    for (std::size_t a = 0, b; a < byNode.size(); a = b)
    {
        for (b = a; b < byNode.size() && byNode[b].first == byNode[a].first;)
            ++b;
        std::fill(touches.begin(), touches.end(), 0);
        for (std::size_t q = a; q < b; ++q)
            touches[fromRank[byNode[q].second / L]] = 1;
        for (int p = 0; p < nranks; ++p)
        {
            if (p == me || !touches[p])
                continue;
            for (std::size_t q = a; q < b; ++q)
            {
                const std::size_t off = byNode[q].second;
                if (fromRank[off / L] != p && sent[p].insert(buf[off + 1]).second)
                    outbox[p].insert(outbox[p].end(), buf.begin() + off, buf.begin() + off + L);
            }
        }
    }
    return allToAll(outbox, comm);
}

} // namespace

CellRecords gatherGhostCells(const CellRecords& owned, const std::vector<GO>& touched, const Map& nodeMap,
                             MPI_Comm comm)
{
    const int nv = owned.nv, L = entryLength(nv), nranks = mpi::size(comm);
    const Received atOwner = sendToNodeOwners(owned, nodeOwners(owned, touched, nodeMap), nranks, comm);
    const Received returned = returnNodeNeighbours(atOwner, nv, mpi::rank(comm), comm);

    // Ghosts: the cells of both phases that this rank does not own (entries of one cell carry the same record).
    std::map<GO, const long long*> ghostEntry;
    for (const auto* buf : {&atOwner.buf, &returned.buf})
        for (std::size_t off = 0; off < buf->size(); off += L)
            if (!std::binary_search(owned.gid.begin(), owned.gid.end(), (*buf)[off + 1]))
                ghostEntry.emplace((*buf)[off + 1], buf->data() + off);
    CellRecords ghosts;
    ghosts.nv = nv;
    for (const auto& [gid, entry] : ghostEntry)
        ghosts.append(gid, int(entry[2]), entry + 3, entry + 3 + nv);
    return ghosts;
}

} // namespace unilag
