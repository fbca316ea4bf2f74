#include "mesh/CellRecords.hpp"

#include <algorithm>
#include <numeric>

#include <Tpetra_Distributor.hpp>

namespace unilag
{
namespace
{

//! The gids each rank is sent: a Distributor plan from the destinations, gids grouped by destination rank.
std::vector<GO> receivedGids(const std::vector<GO>& gids, const std::vector<int>& destination,
                             const Teuchos::RCP<const Comm>& comm)
{
    // the plan wants exports grouped by rank (else it copies, or complains with efficiency warnings on)
    std::vector<std::size_t> order(gids.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return destination[a] < destination[b]; });
    std::vector<int> toRank(order.size());
    std::vector<GO> sent(order.size());
    for (std::size_t q = 0; q < order.size(); ++q)
    {
        toRank[q] = destination[order[q]];
        sent[q] = gids[order[q]];
    }
    Tpetra::Distributor plan(comm);
    const std::size_t nReceived = plan.createFromSends(Teuchos::ArrayView<const int>(toRank));
    std::vector<GO> received(nReceived);
    plan.doPostsAndWaits(Teuchos::ArrayView<const GO>(sent), 1, Teuchos::ArrayView<GO>(received));
    std::sort(received.begin(), received.end());
    return received;
}

} // namespace

Teuchos::RCP<const Map> mapOfGids(const std::vector<GO>& gids, const Teuchos::RCP<const Comm>& comm)
{
    const auto INV = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    return Teuchos::rcp(new Map(INV, Teuchos::ArrayView<const GO>(gids.data(), gids.size()), 0, comm));
}

void writeRecordRows(const CellRecords& cells, MV& rows)
{
    const int nv = cells.nv;
    auto r = rows.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < cells.size(); ++i)
    {
        r(i, 0) = cells.region[i];
        for (int k = 0; k < nv; ++k)
        {
            r(i, 1 + k) = double(cells.nodes[nv * i + k]);
            r(i, 1 + nv + k) = cells.groups[nv * i + k];
        }
    }
}

CellRecords readRecordRows(const MV& rows, int nv)
{
    CellRecords cells;
    cells.nv = nv;
    auto r = rows.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& map = *rows.getMap();
    const LO n = LO(map.getNodeNumElements());
    std::vector<GO> nodes(nv);
    std::vector<int> groups(nv);
    for (LO i = 0; i < n; ++i)
    {
        for (int k = 0; k < nv; ++k)
        {
            nodes[k] = GO(r(i, 1 + k));
            groups[k] = int(r(i, 1 + nv + k));
        }
        cells.append(map.getGlobalElement(i), int(r(i, 0)), nodes.data(), groups.data());
    }
    return cells;
}

CellRecords migrateRecords(const CellRecords& cells, const std::vector<int>& newOwner,
                           const Teuchos::RCP<const Map>& cellMap)
{
    auto newMap = mapOfGids(receivedGids(cells.gid, newOwner, cellMap->getComm()), cellMap->getComm());
    MV from(cellMap, recordColumns(cells.nv)), to(newMap, recordColumns(cells.nv));
    writeRecordRows(cells, from);
    to.doImport(from, Importer(cellMap, newMap), Tpetra::INSERT);
    return readRecordRows(to, cells.nv);
}

} // namespace unilag
