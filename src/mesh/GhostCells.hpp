/*! \file GhostCells.hpp
 *  \brief The ghost layer of the distributed mesh: every cell that shares a node with a cell this rank owns and
 *  is owned elsewhere, found with two all-to-all exchanges through the nodes' owners.
 */
#pragma once

#include <vector>

#include "core/Mpi.hpp"
#include "core/Types.hpp"
#include "mesh/CellRecords.hpp"

namespace unilag
{

/*! \brief The records of the cells that share a node with an owned cell and are not owned, sorted by gid.
 *  \param owned this rank's owned cells
 *  \param touched the distinct node gids of the owned cells, increasing
 *  \param nodeMap the one-to-one node map (each node owned by a rank that owns a cell around it)
 *  Collective over comm. */
CellRecords gatherGhostCells(const CellRecords& owned, const std::vector<GO>& touched, const Map& nodeMap,
                             MPI_Comm comm);

} // namespace unilag
