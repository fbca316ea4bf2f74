// DistributedMesh::rebuild (src/mesh/DistributedMesh.cpp) on hand-built meshes (HostMesh.hpp): rebuilding with the
// same owners reproduces the mesh exactly, and moving cells keeps every cell owned once, with its record, its ghost
// layer and the current coordinates of its nodes. The tests hold on any number of ranks: `unit` runs them on one,
// unit_mesh_np2 and unit_mesh_np3 (tests/CMakeLists.txt) on more, where cells really move.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include <Tpetra_Core.hpp>

#include "HostMesh.hpp"
#include "core/Mpi.hpp"
#include "mesh/DistributedMesh.hpp"

namespace
{

using unilag::DistributedMesh;
using unilag::GlobalMesh;
using unilag::GO;
using unilag::LO;
using unilag::MV;

//! A HostMesh as the loader would give it: two regions (left and right of x = 0.5), walls as boundary groups.
template <int D> GlobalMesh globalMeshOf(unilag_test::HostMesh<D> h)
{
    unilag_test::connect<D>(h, unilag_test::wallGroup);
    std::vector<std::string> walls;
    for (int w = 0; w < 2 * D; ++w)
        walls.push_back("wall" + std::to_string(w));
    GlobalMesh g = unilag_test::globalMesh<D>(h, walls);
    for (LO i = 0; i < h.nCells(); ++i)
    {
        double x = 0.0;
        for (int k = 0; k < D + 1; ++k)
            x += h.x[D * h.cells[(D + 1) * i + k]] / (D + 1);
        g.cellRegion[i] = x < 0.5 ? 0 : 1;
    }
    g.regionNames = {"left", "right"};
    return g;
}

GlobalMesh square()
{
    return globalMeshOf<2>(unilag_test::squareMesh(6, 0.2, 7));
}

GlobalMesh cube()
{
    return globalMeshOf<3>(unilag_test::cubeMesh(2, 0.2, 11));
}

//! Node coordinates a moving mesh could have: the mesh file's, displaced by an amount unique to each node.
double movedCoordinate(const GlobalMesh& g, GO node, int d)
{
    return g.coords[3 * node + d] + 1e-3 * double(node + 1) * (d + 1);
}

//! The owned rows of coords0 (or moved ones) as a vector on the mesh's owned or local node map.
MV nodeCoordinates(const DistributedMesh& dm, bool overlap, const GlobalMesh* moveLike = nullptr)
{
    MV x(overlap ? dm.nodeMapOverlap : dm.nodeMap, 3);
    auto h = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO n = 0; n < LO(h.extent(0)); ++n)
        for (int d = 0; d < 3; ++d)
            h(n, d) = moveLike ? movedCoordinate(*moveLike, dm.nodeGid[n], d) : dm.coords0[3 * n + d];
    return x;
}

std::vector<LO> onHost(const unilag::View<LO*>& v)
{
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
    return std::vector<LO>(h.data(), h.data() + h.extent(0));
}

void expectSameMesh(const DistributedMesh& a, const DistributedMesh& b)
{
    EXPECT_EQ(a.nOwnedCells, b.nOwnedCells);
    EXPECT_EQ(a.nCells, b.nCells);
    EXPECT_EQ(a.nOwnedNodes, b.nOwnedNodes);
    EXPECT_EQ(a.nNodes, b.nNodes);
    EXPECT_TRUE(a.cellMap->isSameAs(*b.cellMap));
    EXPECT_TRUE(a.cellMapOverlap->isSameAs(*b.cellMapOverlap));
    EXPECT_TRUE(a.nodeMap->isSameAs(*b.nodeMap));
    EXPECT_TRUE(a.nodeMapOverlap->isSameAs(*b.nodeMapOverlap));
    EXPECT_EQ(a.cellGid, b.cellGid);
    EXPECT_EQ(a.nodeGid, b.nodeGid);
    EXPECT_EQ(a.cellRegion, b.cellRegion);
    EXPECT_EQ(a.cellNodesHost, b.cellNodesHost);
    EXPECT_EQ(a.cellFaceGroupHost, b.cellFaceGroupHost);
    EXPECT_EQ(a.cellNeighbourHost, b.cellNeighbourHost);
    EXPECT_EQ(onHost(a.nodeCornerOffsets), onHost(b.nodeCornerOffsets));
    EXPECT_EQ(onHost(a.nodeCorners), onHost(b.nodeCorners));
    EXPECT_EQ(a.nodeOutputOffset, b.nodeOutputOffset);
    EXPECT_EQ(a.nodeOutputId, b.nodeOutputId);
    EXPECT_EQ(a.coords0, b.coords0);
}

//! Every local cell carries the loader's record (region, nodes, face groups) under its global ids.
void expectRecordsOf(const GlobalMesh& g, const DistributedMesh& dm)
{
    const int nv = dm.nv;
    for (LO i = 0; i < dm.nCells; ++i)
    {
        const GO c = dm.cellGid[i];
        EXPECT_EQ(dm.cellRegion[i], g.cellRegion[c]) << "cell " << c;
        for (int k = 0; k < nv; ++k)
        {
            EXPECT_EQ(dm.nodeGid[dm.cellNodesHost[nv * i + k]], g.cells[nv * c + k]) << "cell " << c << " node " << k;
            EXPECT_EQ(dm.cellFaceGroupHost[nv * i + k], g.cellFaceGroup[nv * c + k]) << "cell " << c << " face " << k;
        }
    }
}

//! The local cells are the owned ones and exactly those sharing a node with them.
void expectGhostLayer(const GlobalMesh& g, const DistributedMesh& dm)
{
    const int nv = dm.nv;
    std::set<GO> ownedNodes, expected;
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        for (int k = 0; k < nv; ++k)
            ownedNodes.insert(g.cells[nv * dm.cellGid[i] + k]);
    for (std::size_t c = 0; c < g.nCells(); ++c)
        for (int k = 0; k < nv; ++k)
            if (ownedNodes.count(g.cells[nv * c + k]))
                expected.insert(GO(c));
    EXPECT_EQ(std::set<GO>(dm.cellGid.begin(), dm.cellGid.end()), expected);
}

//! Every cell is owned by exactly one rank, the one newOwner (on the old mesh) sent it to.
void expectOwnedOnce(const DistributedMesh& old, const std::vector<int>& newOwner, const DistributedMesh& dm)
{
    EXPECT_TRUE(dm.cellMap->isOneToOne());
    EXPECT_EQ(GO(dm.cellMap->getGlobalNumElements()), dm.nGlobalCells);
    double owned[1] = {double(dm.nOwnedCells)};
    unilag::mpi::allSum(unilag::mpi::rawComm(dm.comm), owned);
    EXPECT_EQ(owned[0], double(dm.nGlobalCells));
    MV sentTo(old.cellMap, 1), ownerHere(dm.cellMap, 1);
    {
        auto h = sentTo.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO i = 0; i < old.nOwnedCells; ++i)
            h(i, 0) = newOwner[i];
    }
    ownerHere.doImport(sentTo, unilag::Importer(old.cellMap, dm.cellMap), Tpetra::INSERT);
    auto h = ownerHere.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        EXPECT_EQ(int(h(i, 0)), dm.comm->getRank()) << "cell " << dm.cellGid[i];
}

void checkSameOwners(const GlobalMesh& g)
{
    auto dm = DistributedMesh::distribute(g, Tpetra::getDefaultComm());
    const std::vector<int> stay(dm->nOwnedCells, dm->comm->getRank());
    for (bool overlap : {false, true})
    {
        SCOPED_TRACE(overlap ? "coordinates on nodeMapOverlap" : "coordinates on nodeMap");
        auto again = DistributedMesh::rebuild(*dm, stay, nodeCoordinates(*dm, overlap));
        expectSameMesh(*dm, *again);
    }
}

void checkMovedCells(const GlobalMesh& g)
{
    auto dm = DistributedMesh::distribute(g, Tpetra::getDefaultComm());
    const int rank = dm->comm->getRank(), size = dm->comm->getSize();
    std::vector<int> newOwner(dm->nOwnedCells);
    for (LO i = 0; i < dm->nOwnedCells; ++i)
        newOwner[i] = dm->cellGid[i] % 3 == 0 ? (rank + 1) % size : rank;
    auto moved = DistributedMesh::rebuild(*dm, newOwner, nodeCoordinates(*dm, false, &g));

    expectOwnedOnce(*dm, newOwner, *moved);
    expectRecordsOf(g, *moved);
    expectGhostLayer(g, *moved);
    EXPECT_TRUE(moved->nodeMap->isOneToOne());
    EXPECT_EQ(GO(moved->nodeMap->getGlobalNumElements()), moved->nGlobalNodes);
    for (LO n = 0; n < moved->nNodes; ++n)
        for (int d = 0; d < 3; ++d)
            EXPECT_EQ(moved->coords0[3 * n + d], movedCoordinate(g, moved->nodeGid[n], d)) << "node " << moved->nodeGid[n];
    for (LO n = 0; n < moved->nOwnedNodes; ++n)
        EXPECT_EQ(moved->nodeOutputId[n], moved->nodeOutputOffset + n);
}

} // namespace

TEST(DistributedMeshRebuild, SameOwnersGiveTheSameMesh2D)
{
    checkSameOwners(square());
}

TEST(DistributedMeshRebuild, SameOwnersGiveTheSameMesh3D)
{
    checkSameOwners(cube());
}

TEST(DistributedMeshRebuild, MovedCellsKeepRecordsGhostsAndCoordinates2D)
{
    checkMovedCells(square());
}

TEST(DistributedMeshRebuild, MovedCellsKeepRecordsGhostsAndCoordinates3D)
{
    checkMovedCells(cube());
}

TEST(DistributedMeshRebuild, BadInputOnOneRankThrowsOnAll)
{
    const GlobalMesh g = square();
    auto dm = DistributedMesh::distribute(g, Tpetra::getDefaultComm());
    const int rank = dm->comm->getRank();
    std::vector<int> newOwner(dm->nOwnedCells + (rank == 0 ? 1 : 0), rank);
    EXPECT_THROW(DistributedMesh::rebuild(*dm, newOwner, nodeCoordinates(*dm, false)), std::invalid_argument);
    newOwner.assign(dm->nOwnedCells, rank == 0 ? dm->comm->getSize() : rank);
    EXPECT_THROW(DistributedMesh::rebuild(*dm, newOwner, nodeCoordinates(*dm, false)), std::invalid_argument);
    MV wrongMap(dm->cellMap, 3);
    EXPECT_THROW(DistributedMesh::rebuild(*dm, std::vector<int>(dm->nOwnedCells, rank), wrongMap),
                 std::invalid_argument);
}
