#include "mesh/LatticeMesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

#include <gmsh.h>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "mesh/GlobalMesh.hpp"

namespace unilag
{
namespace
{

struct Box
{
    double lo[3], hi[3];
};

Box boundingBox(int dim, int tag)
{
    Box b{};
    gmsh::model::getBoundingBox(dim, tag, b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]);
    return b;
}

const char* entityName(int dim) { return dim == 1 ? "curve" : dim == 2 ? "surface" : "volume"; }

/*! The side's plane: the axis a < dim along which the entity's bounding box is flat (within tol), and its coordinate
 *  there (the box's middle: OpenCASCADE pads its boxes by its tolerance, 1e-7); axis -1 if none. */
std::pair<int, double> sidePlane(const Box& e, int dim, double tol)
{
    for (int a = 0; a < dim; ++a)
        if (e.hi[a] - e.lo[a] <= 2.0 * tol)
            return {a, 0.5 * (e.lo[a] + e.hi[a])};
    return {-1, 0.0};
}

/*! The model's one entity of dimension dim, checked to be an axis-aligned rectangle (2D) or box (3D): each of its
 *  boundary entities flat, on the lo or hi side of its bounding box along that axis. The box returned is the sides'
 *  planes (not the padded bounding box). */
int boxEntity(const std::string& source, int dim, Box& box, double& tol)
{
    const std::string shape = dim == 2 ? "rectangle" : "box";
    gmsh::vectorpair top;
    gmsh::model::getEntities(top, dim);
    if (top.size() != 1)
        throw InputError(source + ": mesh.mesher lattice meshes one axis-aligned " + shape + "; the geometry has " +
                         std::to_string(top.size()) + " " + entityName(dim) + "s");
    const Box padded = boundingBox(dim, top[0].second);
    double extent = 0.0;
    for (int a = 0; a < dim; ++a)
        extent = std::max(extent, padded.hi[a] - padded.lo[a]);
    tol = 1e-6 * extent + 1e-7; // + OpenCASCADE's padding, absolute
    box = padded;
    gmsh::vectorpair sides;
    gmsh::model::getBoundary(top, sides, false, false, false);
    for (const auto& [d, tag] : sides)
    {
        const auto [a, x] = sidePlane(boundingBox(d, std::abs(tag)), dim, tol);
        const bool low = a >= 0 && std::abs(x - padded.lo[a]) <= 2.0 * tol;
        if (a < 0 || (!low && std::abs(x - padded.hi[a]) > 2.0 * tol))
            throw InputError(source + ": mesh.mesher lattice meshes an axis-aligned " + shape + "; " + entityName(d) +
                             " " + std::to_string(std::abs(tag)) + " is not on a side of its bounding box");
        (low ? box.lo[a] : box.hi[a]) = x;
    }
    return top[0].second;
}

struct Lattice
{
    std::vector<double> xyz;          //!< 3 per node
    std::vector<std::size_t> cells;   //!< dim + 1 node tags (index + 1) each, positively oriented
    std::vector<std::size_t> facets;  //!< dim node tags each: the boundary lines (2D) or triangles (3D)
};

//! Node index + 1: gmsh's node tags.
std::size_t tagOf(int n) { return std::size_t(n) + 1; }

/*! 2D: the rows of nodes (row j at y0 + j h), node indices by x in each; odd rows but the first have their
 *  half-cell nodes moved onto the sides. */
std::vector<std::vector<int>> latticeRows(Lattice& l, const Box& r, double size)
{
    const double width = r.hi[0] - r.lo[0], height = r.hi[1] - r.lo[1];
    const int nx = std::max(2, int(std::lround(width / size)));
    const int ny = std::max(2, int(std::lround(height / (size * std::sqrt(3.0) / 2.0))));
    const double base = width / nx, h = height / ny;
    std::vector<std::vector<int>> rows;
    for (int j = 0; j <= ny; ++j)
    {
        std::vector<double> xs;
        if (j % 2 == 0)
            for (int i = 0; i <= nx; ++i)
                xs.push_back(i * base);
        else
        {
            xs.push_back(0.0);
            for (int i = j == 1 ? 0 : 1; i < (j == 1 ? nx : nx - 1); ++i)
                xs.push_back((i + 0.5) * base);
            xs.push_back(width);
        }
        std::vector<int> row;
        for (double x : xs)
        {
            row.push_back(int(l.xyz.size() / 3));
            l.xyz.insert(l.xyz.end(), {r.lo[0] + x, r.lo[1] + j * h, 0.0});
        }
        rows.push_back(row);
    }
    return rows;
}

/*! 2D: triangles between two rows, advancing along whichever row's next edge has its midpoint further left: the
 *  strip is cut into triangles with no crossing edge whatever the two rows' node counts. */
void zipRows(Lattice& l, const std::vector<int>& lower, const std::vector<int>& upper)
{
    auto x = [&l](int n) { return l.xyz[3 * std::size_t(n)]; };
    std::size_t i = 0, k = 0;
    while (i + 1 < lower.size() || k + 1 < upper.size())
    {
        const bool takeLower = k + 1 == upper.size() ||
                               (i + 1 < lower.size() && x(lower[i]) + x(lower[i + 1]) < x(upper[k]) + x(upper[k + 1]));
        const int third = takeLower ? lower[++i] : upper[++k];
        const int a = takeLower ? lower[i - 1] : lower[i], c = takeLower ? upper[k] : upper[k - 1];
        l.cells.insert(l.cells.end(), {tagOf(a), tagOf(third), tagOf(c)});
    }
}

Lattice triangleLattice(const Box& r, double size)
{
    Lattice l;
    const auto rows = latticeRows(l, r, size);
    for (std::size_t j = 0; j + 1 < rows.size(); ++j)
        zipRows(l, rows[j], rows[j + 1]);
    auto edge = [&l](int a, int b) { l.facets.insert(l.facets.end(), {tagOf(a), tagOf(b)}); };
    for (const auto* row : {&rows.front(), &rows.back()})
        for (std::size_t i = 0; i + 1 < row->size(); ++i)
            edge((*row)[i], (*row)[i + 1]);
    for (std::size_t j = 0; j + 1 < rows.size(); ++j)
    {
        edge(rows[j].front(), rows[j + 1].front());
        edge(rows[j].back(), rows[j + 1].back());
    }
    return l;
}

/*! 3D: the body-centred cubic lattice of n[0] x n[1] x n[2] cells: corners and cell centres as nodes, and for each
 *  face between two cells four tetrahedra (the two centres and one edge of the face each), all of volume |cell| / 12
 *  (congruent where the cells are cubes): no small cell anywhere. A face on the boundary is cut into two triangles by the diagonal
 *  through its corner of even i + j + k (the same choice around every corner, so the octant's corner is symmetric
 *  in its three planes), each a tetrahedron with its cell's centre, of the same volume. */
class BccBuilder
{
  public:
    BccBuilder(const Box& b, double size)
    {
        for (int a = 0; a < 3; ++a)
        {
            n_[a] = std::max(1, int(std::lround((b.hi[a] - b.lo[a]) / size)));
            h_[a] = (b.hi[a] - b.lo[a]) / n_[a];
        }
        for (int k = 0; k <= n_[2]; ++k)
            for (int j = 0; j <= n_[1]; ++j)
                for (int i = 0; i <= n_[0]; ++i)
                    l_.xyz.insert(l_.xyz.end(), {b.lo[0] + i * h_[0], b.lo[1] + j * h_[1], b.lo[2] + k * h_[2]});
        for (int k = 0; k < n_[2]; ++k)
            for (int j = 0; j < n_[1]; ++j)
                for (int i = 0; i < n_[0]; ++i)
                    l_.xyz.insert(l_.xyz.end(), {b.lo[0] + (i + 0.5) * h_[0], b.lo[1] + (j + 0.5) * h_[1],
                                                 b.lo[2] + (k + 0.5) * h_[2]});
    }

    Lattice build()
    {
        for (int a = 0; a < 3; ++a)
        {
            int hi[3] = {n_[0], n_[1], n_[2]};
            hi[a] += 1; // faces normal to a: n[a] + 1 planes of them
            for (int k = 0; k < hi[2]; ++k)
                for (int j = 0; j < hi[1]; ++j)
                    for (int i = 0; i < hi[0]; ++i)
                        face(a, {i, j, k});
        }
        return l_;
    }

  private:
    using Index = std::array<int, 3>;

    int corner(const Index& c) const { return c[0] + (n_[0] + 1) * (c[1] + (n_[1] + 1) * c[2]); }
    int centre(const Index& c) const
    {
        const int corners = (n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1);
        return corners + c[0] + n_[0] * (c[1] + n_[1] * c[2]);
    }
    bool inside(const Index& c) const
    {
        return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < n_[0] && c[1] < n_[1] && c[2] < n_[2];
    }

    //! The face normal to axis a with lowest corner f: its corners in cyclic order, then its tetrahedra.
    void face(int a, const Index& f)
    {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        std::array<Index, 4> cs{f, f, f, f};
        cs[1][u] += 1;
        cs[2][u] += 1;
        cs[2][v] += 1;
        cs[3][v] += 1;
        Index below = f;
        below[a] -= 1;
        if (inside(below) && inside(f))
        {
            for (int q = 0; q < 4; ++q)
                tet(centre(below), centre(f), corner(cs[q]), corner(cs[(q + 1) % 4]));
            return;
        }
        const int cell = centre(inside(f) ? f : below);
        int even = 0;
        while ((cs[even][0] + cs[even][1] + cs[even][2]) % 2 != 0)
            ++even;
        int p[4];
        for (int q = 0; q < 4; ++q)
            p[q] = corner(cs[(even + q) % 4]);
        for (const auto& tri : {std::array<int, 3>{p[0], p[1], p[2]}, std::array<int, 3>{p[0], p[2], p[3]}})
        {
            tet(cell, tri[0], tri[1], tri[2]);
            l_.facets.insert(l_.facets.end(), {tagOf(tri[0]), tagOf(tri[1]), tagOf(tri[2])});
        }
    }

    //! A tetrahedron, its last two nodes swapped if needed for a positive volume.
    void tet(int a, int b, int c, int d)
    {
        const double* x = l_.xyz.data();
        if (signedMeasure(3, x + 3 * a, x + 3 * b, x + 3 * c, x + 3 * d) < 0.0)
            std::swap(c, d);
        l_.cells.insert(l_.cells.end(), {tagOf(a), tagOf(b), tagOf(c), tagOf(d)});
    }

    int n_[3] = {1, 1, 1};
    double h_[3] = {0.0, 0.0, 0.0};
    Lattice l_;
};

/*! Each boundary facet on the side entity whose bounding box holds its centroid, as gmsh elements (lines in 2D,
 *  triangles in 3D) of that entity, so that the .geo's physical groups name them. */
void addBoundaryElements(const std::string& source, const Lattice& l, int dim, std::size_t firstTag, double tol)
{
    gmsh::vectorpair sides;
    gmsh::model::getEntities(sides, dim - 1);
    std::vector<Box> boxes;
    for (const auto& s : sides)
        boxes.push_back(boundingBox(s.first, s.second));
    std::map<int, std::vector<std::size_t>> nodesOfSide;
    for (std::size_t f = 0; f < l.facets.size(); f += dim)
    {
        double c[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k < dim; ++k)
            for (int a = 0; a < 3; ++a)
                c[a] += l.xyz[3 * (l.facets[f + k] - 1) + a] / dim;
        auto holds = [&](const Box& b) {
            for (int a = 0; a < 3; ++a)
                if (c[a] < b.lo[a] - tol || c[a] > b.hi[a] + tol)
                    return false;
            return true;
        };
        const auto it = std::find_if(boxes.begin(), boxes.end(), holds);
        if (it == boxes.end())
            throw InputError(source + ": mesh.mesher lattice: no " + entityName(dim - 1) +
                             " holds the boundary point (" + jsonNumber(c[0]) + ", " + jsonNumber(c[1]) + ", " +
                             jsonNumber(c[2]) + ")");
        auto& nodes = nodesOfSide[sides[std::size_t(it - boxes.begin())].second];
        nodes.insert(nodes.end(), l.facets.begin() + long(f), l.facets.begin() + long(f) + dim);
    }
    std::size_t tag = firstTag;
    for (const auto& [side, nodes] : nodesOfSide)
    {
        std::vector<std::size_t> tags(nodes.size() / std::size_t(dim));
        for (auto& t : tags)
            t = tag++;
        gmsh::model::mesh::addElementsByType(side, dim == 2 ? 1 : 2, tags, nodes);
    }
}

} // namespace

void meshAsLattice(const std::string& source, double size)
{
    const int dim = gmsh::model::getDimension();
    Box box{};
    double tol = 0.0;
    const int entity = boxEntity(source, dim, box, tol);
    const Lattice l = dim == 2 ? triangleLattice(box, size) : BccBuilder(box, size).build();
    std::vector<std::size_t> nodeTags(l.xyz.size() / 3);
    for (std::size_t n = 0; n < nodeTags.size(); ++n)
        nodeTags[n] = n + 1;
    gmsh::model::mesh::addNodes(dim, entity, nodeTags, l.xyz);
    std::vector<std::size_t> cellTags(l.cells.size() / std::size_t(dim + 1));
    for (std::size_t t = 0; t < cellTags.size(); ++t)
        cellTags[t] = t + 1;
    gmsh::model::mesh::addElementsByType(entity, dim == 2 ? 2 : 4, cellTags, l.cells);
    addBoundaryElements(source, l, dim, cellTags.size() + 1, tol);
}

} // namespace unilag
