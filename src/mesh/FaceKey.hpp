/*! \file FaceKey.hpp
 *  \brief Faces of simplex cells named by their sorted node indices, and the matching of all faces of a set of
 *  cells into shared (interior) and single (boundary) faces. The mesh loader and the distributed mesh both use
 *  it, so a face is the same key in both.
 */
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace unilag
{

//! A face by its node indices in increasing order; the third is -1 for the 2-node faces of triangles.
using FaceKey = std::array<int, 3>;

//! The key of the face with the n (2 or 3) given nodes.
inline FaceKey faceKey(const int* nodes, int n)
{
    // sorting network for 2 or 3 entries
    FaceKey key{nodes[0], nodes[1], n == 3 ? nodes[2] : -1};
    if (key[0] > key[1])
        std::swap(key[0], key[1]);
    if (n == 3)
    {
        if (key[1] > key[2])
            std::swap(key[1], key[2]);
        if (key[0] > key[1])
            std::swap(key[0], key[1]);
    }
    return key;
}

//! The key of face k of a simplex cell of nv (3 or 4) nodes: the face opposite its local node k.
inline FaceKey oppositeFaceKey(const int* cellNodes, int nv, int k)
{
    int nodes[3] = {-1, -1, -1}, n = 0;
    for (int j = 0; j < nv; ++j)
        if (j != k)
            nodes[n++] = cellNodes[j];
    return faceKey(nodes, n);
}

//! Face k of a cell, with its key.
struct FaceRef
{
    FaceKey key;
    int cell, k;
};

//! Every face of nCells cells (nv node indices each, row-major), sorted by (key, cell, k): equal keys are adjacent.
inline std::vector<FaceRef> sortedFaces(const int* cells, std::size_t nCells, int nv)
{
    std::vector<FaceRef> faces;
    faces.reserve(nCells * nv);
    for (std::size_t c = 0; c < nCells; ++c)
        for (int k = 0; k < nv; ++k)
            faces.push_back({oppositeFaceKey(cells + nv * c, nv, k), int(c), k});
    std::sort(faces.begin(), faces.end(), [](const FaceRef& a, const FaceRef& b) {
        return std::tie(a.key, a.cell, a.k) < std::tie(b.key, b.cell, b.k);
    });
    return faces;
}

/*! \brief Matches the faces of nCells cells (nv node indices each, row-major) by key, in increasing key order:
 *  onInterior(a, b) for a face of two cells (a.cell <= b.cell), onBoundary(a) for a face of one cell.
 *  \return the first face that more than two cells share (matching stops there; the mesh is broken), or nothing.
 */
template <class OnInterior, class OnBoundary>
std::optional<FaceRef> matchFaces(const int* cells, std::size_t nCells, int nv, OnInterior onInterior,
                                  OnBoundary onBoundary)
{
    const std::vector<FaceRef> faces = sortedFaces(cells, nCells, nv);
    for (std::size_t a = 0, b; a < faces.size(); a = b)
    {
        for (b = a + 1; b < faces.size() && faces[b].key == faces[a].key;)
            ++b;
        if (b - a > 2)
            return faces[a];
        if (b - a == 2)
            onInterior(faces[a], faces[a + 1]);
        else
            onBoundary(faces[a]);
    }
    return std::nullopt;
}

} // namespace unilag
