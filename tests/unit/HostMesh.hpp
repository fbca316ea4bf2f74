/*! \file HostMesh.hpp
 *  \brief Hand-built distorted simplex meshes of the unit square and cube on the host, for the kernel unit tests
 *  (hydro, heat): structured grids with randomly moved interior nodes, split into triangles or Kuhn tetrahedra, with
 *  face neighbours and boundary groups. */
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/GlobalMesh.hpp"
#include "unilag/Geometry.hpp"

namespace unilag_test
{

using unilag::LO;

//! A simplex mesh: coordinates, cells, per face (opposite local node k) its boundary group or -1, and the
//! neighbour across it (or -1). wall[r] has bit 2d set if node r lies on x_d = 0 and bit 2d+1 if on x_d = 1.
template <int D> struct HostMesh
{
    static constexpr int NV = D + 1;
    std::vector<double> x;
    std::vector<LO> cells;
    std::vector<int> faceGroup;
    std::vector<LO> neighbour;
    std::vector<int> wall;
    LO nNodes() const { return LO(x.size() / D); }
    LO nCells() const { return LO(cells.size() / NV); }
};

//! Structured node grid of [0,1]^D with n cells a side; interior nodes moved by up to amp * h per coordinate.
template <int D> HostMesh<D> gridNodes(int n, double amp, unsigned seed)
{
    HostMesh<D> m;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amp / n, amp / n);
    const int nn = D == 2 ? (n + 1) * (n + 1) : (n + 1) * (n + 1) * (n + 1);
    for (int r = 0; r < nn; ++r)
    {
        int idx[3] = {r % (n + 1), (r / (n + 1)) % (n + 1), r / ((n + 1) * (n + 1))};
        bool interior = true;
        int wall = 0;
        for (int d = 0; d < D; ++d)
        {
            interior = interior && idx[d] > 0 && idx[d] < n;
            wall |= (idx[d] == 0 ? 1 : 0) << (2 * d);
            wall |= (idx[d] == n ? 1 : 0) << (2 * d + 1);
        }
        for (int d = 0; d < D; ++d)
            m.x.push_back(double(idx[d]) / n + (interior ? u(rng) : 0.0));
        m.wall.push_back(wall);
    }
    return m;
}

//! n x n squares, each split into two triangles, counter-clockwise; diagonals alternate unless uniform.
inline HostMesh<2> squareMesh(int n, double amp, unsigned seed, bool uniform = false)
{
    HostMesh<2> m = gridNodes<2>(n, amp, seed);
    auto id = [n](int i, int j) { return LO(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const LO a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            const std::array<LO, 6> t = (uniform || (i + j) % 2 == 0) ? std::array<LO, 6>{a, b, c, a, c, d}
                                                                      : std::array<LO, 6>{a, b, d, b, c, d};
            m.cells.insert(m.cells.end(), t.begin(), t.end());
        }
    return m;
}

//! n^3 cubes, each split into the 6 Kuhn tetrahedra along its main diagonal, positively oriented.
inline HostMesh<3> cubeMesh(int n, double amp, unsigned seed)
{
    HostMesh<3> m = gridNodes<3>(n, amp, seed);
    auto id = [n](int i, int j, int k) { return LO((k * (n + 1) + j) * (n + 1) + i); };
    int perm[3] = {0, 1, 2};
    std::vector<std::array<int, 3>> perms;
    do
        perms.push_back({perm[0], perm[1], perm[2]});
    while (std::next_permutation(perm, perm + 3));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& p : perms)
                {
                    int c[3] = {i, j, k};
                    LO tet[4];
                    tet[0] = id(c[0], c[1], c[2]);
                    for (int s = 0; s < 3; ++s)
                    {
                        ++c[p[s]];
                        tet[s + 1] = id(c[0], c[1], c[2]);
                    }
                    // odd permutations give negatively oriented tets
                    const int inversions = (p[0] > p[1]) + (p[0] > p[2]) + (p[1] > p[2]);
                    if (inversions % 2 == 1)
                        std::swap(tet[0], tet[1]);
                    m.cells.insert(m.cells.end(), tet, tet + 4);
                }
    return m;
}

//! The sorted nodes of face k (opposite local node k) of cell i: equal for the two cells sharing the face.
template <int D> std::array<LO, D> faceKey(const HostMesh<D>& m, LO i, int k)
{
    std::array<LO, D> key;
    int n = 0;
    for (int j = 0; j < D + 1; ++j)
        if (j != k)
            key[n++] = m.cells[(D + 1) * i + j];
    std::sort(key.begin(), key.end());
    return key;
}

/*! Face neighbours by matching sorted node lists; unmatched faces are boundary faces, whose group is
 *  groupOf(wall bits common to the face's nodes). */
template <int D> void connect(HostMesh<D>& m, const std::function<int(int)>& groupOf)
{
    constexpr int NV = D + 1;
    std::vector<std::tuple<std::array<LO, D>, LO, int>> faces;
    for (LO i = 0; i < m.nCells(); ++i)
        for (int k = 0; k < NV; ++k)
            faces.emplace_back(faceKey<D>(m, i, k), i, k);
    std::sort(faces.begin(), faces.end());
    m.neighbour.assign(m.cells.size(), -1);
    m.faceGroup.assign(m.cells.size(), -1);
    for (std::size_t a = 0, b; a < faces.size(); a = b)
    {
        for (b = a + 1; b < faces.size() && std::get<0>(faces[b]) == std::get<0>(faces[a]);)
            ++b;
        ASSERT_LE(b - a, 2u);
        const auto& [key, i, k] = faces[a];
        if (b - a == 2)
        {
            const auto& [key2, i2, k2] = faces[a + 1];
            m.neighbour[NV * i + k] = i2;
            m.neighbour[NV * i2 + k2] = i;
        }
        else
        {
            int common = ~0;
            for (LO r : key)
                common &= m.wall[r];
            ASSERT_NE(common, 0) << "boundary face off the walls: the mesh is not conforming";
            m.faceGroup[NV * i + k] = groupOf(common);
        }
    }
}

//! Wall index 0 .. 2D-1 (x=0, x=1, y=0, ...) of a face from its common wall bits.
inline int wallGroup(int common)
{
    int g = 0;
    while (!(common & (1 << g)))
        ++g;
    return g;
}

//! The kernels' mesh maps of h on the device, on one rank (the node -> corner CSR included); h's node positions into x.
template <int D> unilag::MeshView<D> deviceMesh(const HostMesh<D>& h, const unilag::Field& x)
{
    constexpr int NV = D + 1;
    const LO nCells = h.nCells(), nNodes = h.nNodes();
    Kokkos::View<LO**, Kokkos::LayoutLeft, unilag::MemSpace> cellNodes("cellNodes", nCells, NV);
    unilag::View<LO*> offsets("offsets", nNodes + 1), corners("corners", nCells * NV);
    unilag::View<int**> faceGroup("faceGroup", nCells, NV);
    unilag::View<LO**> neighbour("neighbour", nCells, NV);
    auto cn = Kokkos::create_mirror_view(cellNodes);
    auto fg = Kokkos::create_mirror_view(faceGroup);
    auto nb = Kokkos::create_mirror_view(neighbour);
    auto off = Kokkos::create_mirror_view(offsets);
    auto cor = Kokkos::create_mirror_view(corners);
    // node -> corner CSR; filling cell by cell keeps each node's corners sorted by cell id
    for (LO i = 0; i < nCells; ++i)
        for (int k = 0; k < NV; ++k)
        {
            cn(i, k) = h.cells[NV * i + k];
            fg(i, k) = h.faceGroup[NV * i + k];
            nb(i, k) = h.neighbour[NV * i + k];
            ++off(cn(i, k) + 1);
        }
    for (LO r = 0; r < nNodes; ++r)
        off(r + 1) += off(r);
    std::vector<LO> fill(off.data(), off.data() + nNodes);
    for (LO i = 0; i < nCells; ++i)
        for (int k = 0; k < NV; ++k)
            cor(fill[cn(i, k)]++) = i * NV + k;
    Kokkos::deep_copy(cellNodes, cn);
    Kokkos::deep_copy(faceGroup, fg);
    Kokkos::deep_copy(neighbour, nb);
    Kokkos::deep_copy(offsets, off);
    Kokkos::deep_copy(corners, cor);
    auto xh = Kokkos::create_mirror_view(x);
    for (LO r = 0; r < nNodes; ++r)
        for (int d = 0; d < D; ++d)
            xh(r, d) = h.x[D * r + d];
    Kokkos::deep_copy(x, xh);

    unilag::MeshView<D> mesh;
    mesh.cellNodes = cellNodes;
    mesh.nodeCornerOffsets = offsets;
    mesh.nodeCorners = corners;
    mesh.cellFaceGroup = faceGroup;
    mesh.cellNeighbour = neighbour;
    mesh.nOwnedCells = mesh.nCells = nCells;
    mesh.nOwnedNodes = mesh.nNodes = nNodes;
    return mesh;
}

/*! The connected HostMesh h as a mesh on rank 0: one region "gas", HostMesh face group g named boundaryNames[g].
 *  Cell and node ids are the HostMesh indices, so after distribute the local row i is HostMesh entity gid[i]. */
template <int D> unilag::GlobalMesh globalMesh(const HostMesh<D>& h, std::vector<std::string> boundaryNames)
{
    unilag::GlobalMesh g;
    g.dim = D;
    for (LO r = 0; r < h.nNodes(); ++r)
        for (int d = 0; d < 3; ++d)
            g.coords.push_back(d < D ? h.x[D * r + d] : 0.0);
    g.cells.assign(h.cells.begin(), h.cells.end());
    g.cellFaceGroup = h.faceGroup;
    g.cellRegion.assign(h.nCells(), 0);
    g.cellTag.resize(h.nCells());
    for (LO i = 0; i < h.nCells(); ++i)
        g.cellTag[i] = i + 1;
    g.regionNames = {"gas"};
    g.boundaryNames = std::move(boundaryNames);
    return g;
}

} // namespace unilag_test
