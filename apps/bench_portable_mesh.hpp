/*! \file bench_portable_mesh.hpp
 *  \brief The generated meshes of apps/bench_portable.cpp: the unit square cut into N x N squares of two triangles
 *  each (diagonals alternating), or the unit cube into N^3 cubes of six tetrahedra (Kuhn's subdivision), interior
 *  nodes moved by up to 15% of the spacing (a fixed hash, the same on every machine), optionally numbered at random;
 *  and their device copies as the kernels' MeshView, built as src/mesh/DistributedMesh.cpp builds them on one rank.
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include <Kokkos_Core.hpp>

#include "mesh/FaceKey.hpp"
#include "unilag/Geometry.hpp"

namespace unilag::portable
{

//! A simplex mesh on the host: cell -> nodes (row-major, positively oriented), node coordinates.
struct HostMesh
{
    int dim = 2, nv = 3;
    std::vector<int> cells;
    std::vector<double> coords; //!< dim per node
    int nCells() const { return int(cells.size()) / nv; }
    int nNodes() const { return int(coords.size()) / dim; }
};

//! A fixed hash of the node index in [-1, 1]: the same perturbation on every backend and machine.
inline double hashUnit(std::uint64_t n, int salt)
{
    std::uint64_t z = n * 0x9E3779B97F4A7C15ull + std::uint64_t(salt) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) / double(1ull << 52) - 1.0;
}

//! Signed measure of cell c (twice the area in 2D, six times the volume in 3D): only its sign is used.
inline double orientation(const HostMesh& m, int c)
{
    const int* n = &m.cells[std::size_t(m.nv) * c];
    auto x = [&](int k, int d) {
        return m.coords[std::size_t(m.dim) * n[k] + d] - m.coords[std::size_t(m.dim) * n[0] + d];
    };
    if (m.dim == 2)
        return x(1, 0) * x(2, 1) - x(1, 1) * x(2, 0);
    return x(1, 0) * (x(2, 1) * x(3, 2) - x(2, 2) * x(3, 1)) - x(1, 1) * (x(2, 0) * x(3, 2) - x(2, 2) * x(3, 0)) +
           x(1, 2) * (x(2, 0) * x(3, 1) - x(2, 1) * x(3, 0));
}

inline HostMesh generateMesh(int dim, int n, bool shuffle)
{
    HostMesh m;
    m.dim = dim;
    m.nv = dim + 1;
    const int np = n + 1;
    const int nodes = dim == 2 ? np * np : np * np * np;
    auto id = [&](int i, int j, int k) { return i + np * (j + np * k); };
    m.coords.resize(std::size_t(dim) * nodes);
    for (int q = 0; q < nodes; ++q)
    {
        const int ijk[3] = {q % np, (q / np) % np, q / (np * np)};
        for (int d = 0; d < dim; ++d)
        {
            const bool interior = ijk[d] > 0 && ijk[d] < n;
            m.coords[std::size_t(dim) * q + d] = (ijk[d] + (interior ? 0.15 * hashUnit(q, d) : 0.0)) / n;
        }
    }
    if (dim == 2)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
            {
                const int a = id(i, j, 0), b = id(i + 1, j, 0), c = id(i + 1, j + 1, 0), d = id(i, j + 1, 0);
                const bool flip = (i + j) % 2 != 0;
                const int t[6] = {a, b, flip ? d : c, flip ? b : a, c, d};
                m.cells.insert(m.cells.end(), t, t + 6);
            }
    else
    {
        const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    for (const auto& p : perms) // the path from corner (0,0,0) to (1,1,1) along the axes p
                    {
                        int c[3] = {i, j, k};
                        m.cells.push_back(id(c[0], c[1], c[2]));
                        for (int s = 0; s < 3; ++s)
                        {
                            ++c[p[s]];
                            m.cells.push_back(id(c[0], c[1], c[2]));
                        }
                    }
    }
    if (shuffle)
    {
        std::mt19937 rng(12345);
        std::vector<int> cellOrder(m.nCells()), nodeOrder(nodes);
        std::iota(cellOrder.begin(), cellOrder.end(), 0);
        std::iota(nodeOrder.begin(), nodeOrder.end(), 0);
        std::shuffle(cellOrder.begin(), cellOrder.end(), rng);
        std::shuffle(nodeOrder.begin(), nodeOrder.end(), rng); // old node -> new node
        HostMesh s = m;
        for (int c = 0; c < m.nCells(); ++c)
            for (int k = 0; k < m.nv; ++k)
                s.cells[std::size_t(m.nv) * c + k] = nodeOrder[m.cells[std::size_t(m.nv) * cellOrder[c] + k]];
        for (int q = 0; q < nodes; ++q)
            for (int d = 0; d < dim; ++d)
                s.coords[std::size_t(dim) * nodeOrder[q] + d] = m.coords[std::size_t(dim) * q + d];
        m = std::move(s);
    }
    for (int c = 0; c < m.nCells(); ++c)
        if (orientation(m, c) < 0.0)
            std::swap(m.cells[std::size_t(m.nv) * c], m.cells[std::size_t(m.nv) * c + 1]);
    return m;
}

//! Device copies of a host mesh as the kernels' MeshView: face neighbours, boundary faces (group 0) and the
//! node -> corner lists (by cell, then corner), as src/mesh/DistributedMesh.cpp builds them on one rank.
template <int D>
MeshView<D> deviceMesh(const HostMesh& h)
{
    constexpr int NV = D + 1;
    const int nc = h.nCells(), nn = h.nNodes();
    Kokkos::View<LO**, Kokkos::LayoutLeft, MemSpace> cellNodes("portable::cellNodes", nc, NV);
    View<int**> faceGroup("portable::cellFaceGroup", nc, NV);
    View<LO**> neighbour("portable::cellNeighbour", nc, NV);
    View<int*> nodeBoundary("portable::nodeBoundary", nn);
    auto cn = Kokkos::create_mirror_view(cellNodes);
    auto fg = Kokkos::create_mirror_view(faceGroup);
    auto nb = Kokkos::create_mirror_view(neighbour);
    auto bn = Kokkos::create_mirror_view(nodeBoundary);
    Kokkos::deep_copy(fg, 0);
    Kokkos::deep_copy(nb, -1);
    Kokkos::deep_copy(bn, 0);
    for (int c = 0; c < nc; ++c)
        for (int k = 0; k < NV; ++k)
            cn(c, k) = h.cells[std::size_t(NV) * c + k];
    auto interior = [&](const FaceRef& a, const FaceRef& b) {
        nb(a.cell, a.k) = b.cell;
        nb(b.cell, b.k) = a.cell;
        fg(a.cell, a.k) = fg(b.cell, b.k) = -1;
    };
    auto boundary = [&](const FaceRef& a) {
        for (int k = 0; k < NV; ++k)
            if (k != a.k)
                bn(cn(a.cell, k)) = 1;
    };
    if (matchFaces(h.cells.data(), std::size_t(nc), NV, interior, boundary))
        throw std::logic_error("generated mesh: a face of more than two cells");
    std::vector<LO> offsets(nn + 1, 0), corners(std::size_t(nc) * NV);
    for (int q : h.cells)
        ++offsets[q + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<LO> pos(offsets.begin(), offsets.end() - 1);
    for (LO q = 0; q < LO(h.cells.size()); ++q) // corners in increasing cell order: sorted as required
        corners[pos[h.cells[q]]++] = q;
    using HostArray = Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
    View<LO*> nodeCornerOffsets("portable::nodeCornerOffsets", nn + 1);
    View<LO*> nodeCorners("portable::nodeCorners", corners.size());
    Kokkos::deep_copy(nodeCornerOffsets, HostArray(offsets.data(), offsets.size()));
    Kokkos::deep_copy(nodeCorners, HostArray(corners.data(), corners.size()));
    Kokkos::deep_copy(cellNodes, cn);
    Kokkos::deep_copy(faceGroup, fg);
    Kokkos::deep_copy(neighbour, nb);
    Kokkos::deep_copy(nodeBoundary, bn);
    MeshView<D> m;
    m.cellNodes = cellNodes;
    m.nodeCornerOffsets = nodeCornerOffsets;
    m.nodeCorners = nodeCorners;
    m.cellFaceGroup = faceGroup;
    m.cellNeighbour = neighbour;
    m.nodeBoundary = nodeBoundary;
    m.nOwnedCells = m.nCells = nc;
    m.nOwnedNodes = m.nNodes = nn;
    return m;
}

} // namespace unilag::portable
