/*! \file CellRecords.hpp
 *  \brief The records that define a set of cells of the distributed mesh (global id, region, node global ids,
 *  face groups), how they travel between ranks as rows of a Tpetra MultiVector, and their migration to new
 *  owners. A rank's owned records are all DistributedMesh needs to build its part (ghosts come from them too).
 */
#pragma once

#include <cstddef>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "core/Types.hpp"

namespace unilag
{

struct CellRecords
{
    int nv = 0;              //!< nodes per cell
    std::vector<GO> gid;     //!< increasing
    std::vector<int> region; //!< one per cell
    std::vector<GO> nodes;   //!< nv node gids per cell
    std::vector<int> groups; //!< nv per cell: group of the face opposite node k, or -1

    std::size_t size() const { return gid.size(); }
    //! Appends one cell: nv node gids and nv face groups, each of type convertible to theirs.
    template <class N, class G>
    void append(GO cellGid, int cellRegion, const N* cellNodes, const G* cellGroups)
    {
        gid.push_back(cellGid);
        region.push_back(cellRegion);
        for (int k = 0; k < nv; ++k)
        {
            nodes.push_back(GO(cellNodes[k]));
            groups.push_back(int(cellGroups[k]));
        }
    }
};

/*! Columns of a record row: region, then nv node gids, then nv face groups. Gids below 2^53 travel exactly as
 *  doubles, and a MultiVector row is what a Tpetra Import moves. */
inline int recordColumns(int nv)
{
    return 1 + 2 * nv;
}

//! Writes record i of cells into row i of rows (rows: local rows in the order of cells, recordColumns(nv) columns).
void writeRecordRows(const CellRecords& cells, MV& rows);

//! The records held as rows of a MultiVector, their gids from its map (which must list them in increasing order).
CellRecords readRecordRows(const MV& rows, int nv);

/*! \brief Moves each record of cells to rank newOwner[i] with a Tpetra Import; returns the records this rank
 *  receives, sorted by gid. Collective. \p cellMap is the map of cells' gids (one-to-one over the ranks). */
CellRecords migrateRecords(const CellRecords& cells, const std::vector<int>& newOwner,
                           const Teuchos::RCP<const Map>& cellMap);

//! The map of these gids on comm (global size computed).
Teuchos::RCP<const Map> mapOfGids(const std::vector<GO>& gids, const Teuchos::RCP<const Comm>& comm);

} // namespace unilag
