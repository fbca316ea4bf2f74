#include "mesh/CellRecords.hpp"

namespace unilag
{

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

} // namespace unilag
