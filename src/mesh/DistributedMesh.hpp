/*! \file DistributedMesh.hpp
 *  \brief The mesh distributed over MPI ranks on Tpetra maps, with one layer of node-neighbour ghost cells.
 *
 *  Ownership: Zoltan2 (multijagged, cell centroids) assigns cells to ranks; each node is owned by one rank
 *  that owns a cell around it (Tpetra::createOneToOne). Ghost cells are all cells that share a node with an
 *  owned cell (the node-neighbour layer of the owned cells) and are not owned. Hence the nodal solver at an
 *  owned node sees every cell of its corners locally, every face neighbour of an owned cell is local
 *  (cellNeighbour, for face fluxes), and so is the node-neighbour stencil of a second-order reconstruction.
 *  Local numbering is owned-first: cells [0, nOwnedCells) then ghosts, nodes [0, nOwnedNodes) then the other
 *  nodes of local cells, each part sorted by global id. Node->corner lists are sorted by global cell id, so
 *  every node sum adds the same numbers in the same order on any number of ranks and threads.
 *
 *  distribute() and rebuild() share one construction from the owned cell records (CellRecords.hpp): distribute
 *  moves them from rank 0 to Zoltan2's owners, rebuild from the current owners to new ones (repartitioning a
 *  moving mesh); then ghosts, maps, importers, face neighbours and node->corner lists follow from them.
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "core/Types.hpp"
#include "mesh/CellRecords.hpp"
#include "mesh/GlobalMesh.hpp"
#include "unilag/Geometry.hpp"

namespace unilag
{

class DistributedMesh
{
  public:
    /*! \brief Partition and distribute a mesh that lives on rank 0 (root is ignored on other ranks).
     *  Collective. */
    static std::shared_ptr<DistributedMesh> distribute(const GlobalMesh& root, Teuchos::RCP<const Comm> comm);

    /*! \brief The same mesh with its cells owned by new ranks, for repartitioning a moving mesh. Collective.
     *  \param old the mesh as it is distributed now
     *  \param newOwner for each owned cell of old (local index < old.nOwnedCells), the rank to own it next
     *  \param coords current node coordinates, 3 columns, on old.nodeMap or old.nodeMapOverlap (owned rows read)
     *  The owned cell records move to their new ranks with a Tpetra Import; the new mesh is then built exactly as
     *  distribute builds one, with coords0 = coords. Global cell and node ids are kept, so the caller moves its
     *  fields with Import(old.cellMap, mesh->cellMap) and Import(old.nodeMap, mesh->nodeMap). With every cell
     *  staying on its rank the result equals old: same maps, local numbering, corner lists and output ids.
     *  \throws std::invalid_argument on every rank if any rank passed a wrong size, rank or map. */
    static std::shared_ptr<DistributedMesh> rebuild(const DistributedMesh& old, const std::vector<int>& newOwner,
                                                    const MV& coords);

    int dim = 0, nv = 0;
    Teuchos::RCP<const Comm> comm;
    Teuchos::RCP<const Map> cellMap, cellMapOverlap, nodeMap, nodeMapOverlap;
    Teuchos::RCP<const Importer> cellImporter; //!< owned cells -> owned + ghost cells
    Teuchos::RCP<const Importer> nodeImporter; //!< owned nodes -> all local nodes

    LO nOwnedCells = 0, nCells = 0, nOwnedNodes = 0, nNodes = 0;
    GO nGlobalCells = 0, nGlobalNodes = 0;
    std::vector<std::string> regionNames, boundaryNames;

    // Host copies (local numbering).
    std::vector<GO> cellGid, nodeGid;
    std::vector<int> cellRegion;
    std::vector<LO> cellNodesHost;   //!< nv per cell
    std::vector<int> cellFaceGroupHost; //!< nv per cell
    std::vector<LO> cellNeighbourHost;  //!< nv per cell: local cell across face k, -1 if none is local
    std::vector<double> coords0;     //!< node coordinates when built (mesh file or rebuild's), 3 per local node

    // Device views for the kernels.
    Kokkos::View<LO**, Kokkos::LayoutLeft, MemSpace> cellNodes;
    View<int**> cellFaceGroup;
    View<LO**> cellNeighbour; //!< local cell across face k (opposite local node k), -1 on the boundary or not local
    View<LO*> nodeCornerOffsets, nodeCorners;
    View<int*> nodeBoundary; //!< 1 if a boundary face of a local cell holds the node (complete for owned cells' nodes)

    //! Output numbering: owned nodes get offset + local index; other local nodes that of their owner.
    long long nodeOutputOffset = 0;
    std::vector<long long> nodeOutputId;

    template <int D>
    MeshView<D> view() const
    {
        MeshView<D> m;
        m.cellNodes = cellNodes;
        m.nodeCornerOffsets = nodeCornerOffsets;
        m.nodeCorners = nodeCorners;
        m.cellFaceGroup = cellFaceGroup;
        m.cellNeighbour = cellNeighbour;
        m.nodeBoundary = nodeBoundary;
        m.nOwnedCells = nOwnedCells;
        m.nCells = nCells;
        m.nOwnedNodes = nOwnedNodes;
        m.nNodes = nNodes;
        return m;
    }

  private:
    void buildFromOwnedCells(const CellRecords& owned, const MV& coords);
    std::vector<GO> setLocalCells(const CellRecords& owned, const CellRecords& ghosts);
    void setLocalNodes(const std::vector<GO>& ownedNodes, const std::vector<GO>& cellNodeGid);
    void findFaceNeighbours();
    void importCoordinates(const MV& coords);
    void nodeCornerLists(std::vector<LO>& offsets, std::vector<LO>& corners) const;
    void buildDeviceViews();
    void numberOutputNodes();
    CellRecords ownedRecords() const;
};

} // namespace unilag
