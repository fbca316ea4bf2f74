#include "mesh/LatticeMesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

#include <gmsh.h>

#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace unilag
{
namespace
{

struct Box
{
    double x0, y0, x1, y1;
};

Box boundingBox(int dim, int tag)
{
    double lo[3], hi[3];
    gmsh::model::getBoundingBox(dim, tag, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    return {lo[0], lo[1], hi[0], hi[1]};
}

//! The curve lies on one side of the rectangle r (within tol).
bool onSide(const Box& c, const Box& r, double tol)
{
    auto near = [tol](double a, double b) { return std::abs(a - b) <= tol; };
    const bool vertical = near(c.x0, c.x1) && (near(c.x0, r.x0) || near(c.x0, r.x1));
    const bool horizontal = near(c.y0, c.y1) && (near(c.y0, r.y0) || near(c.y0, r.y1));
    return vertical || horizontal;
}

//! The model's one surface, checked to be a rectangle: its boundary curves all on the sides of its bounding box.
int rectangleSurface(const std::string& source, Box& rect)
{
    gmsh::vectorpair surfaces, volumes;
    gmsh::model::getEntities(surfaces, 2);
    gmsh::model::getEntities(volumes, 3);
    if (surfaces.size() != 1 || !volumes.empty())
        throw InputError(source + ": mesh.mesher lattice meshes one plane rectangle; the geometry has " +
                         std::to_string(surfaces.size()) + " surfaces and " + std::to_string(volumes.size()) +
                         " volumes");
    const int surface = surfaces[0].second;
    rect = boundingBox(2, surface);
    const double tol = 1e-9 * std::max(rect.x1 - rect.x0, rect.y1 - rect.y0);
    gmsh::vectorpair curves;
    gmsh::model::getBoundary(surfaces, curves, false, false, false);
    for (const auto& [dim, tag] : curves)
        if (!onSide(boundingBox(dim, std::abs(tag)), rect, tol))
            throw InputError(source + ": mesh.mesher lattice meshes an axis-aligned rectangle; curve " +
                             std::to_string(std::abs(tag)) + " is not on a side of the surface's bounding box");
    return surface;
}

struct Lattice
{
    std::vector<double> xyz;              //!< 3 per node
    std::vector<std::vector<int>> rows;   //!< node indices of each row, by x
    std::vector<std::size_t> triangles;   //!< 3 node tags (index + 1) each, counter-clockwise
};

//! The rows of nodes (row j at y0 + j h); odd rows but the first have the half-cell nodes moved onto the sides.
Lattice latticeNodes(const Box& r, double size)
{
    const double width = r.x1 - r.x0, height = r.y1 - r.y0;
    const int nx = std::max(2, int(std::lround(width / size)));
    const int ny = std::max(2, int(std::lround(height / (size * std::sqrt(3.0) / 2.0))));
    const double base = width / nx, h = height / ny;
    Lattice l;
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
            l.xyz.insert(l.xyz.end(), {r.x0 + x, r.y0 + j * h, 0.0});
        }
        l.rows.push_back(row);
    }
    return l;
}

/*! Triangles between two rows, advancing along whichever row's next edge has its midpoint further left: the strip
 *  is cut into triangles with no crossing edge whatever the two rows' node counts. */
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
        l.triangles.insert(l.triangles.end(), {std::size_t(a) + 1, std::size_t(third) + 1, std::size_t(c) + 1});
    }
}

//! The boundary edges (pairs of node indices) around the lattice.
std::vector<std::pair<int, int>> boundaryEdges(const Lattice& l)
{
    std::vector<std::pair<int, int>> edges;
    for (const auto* row : {&l.rows.front(), &l.rows.back()})
        for (std::size_t i = 0; i + 1 < row->size(); ++i)
            edges.emplace_back((*row)[i], (*row)[i + 1]);
    for (std::size_t j = 0; j + 1 < l.rows.size(); ++j)
    {
        edges.emplace_back(l.rows[j].front(), l.rows[j + 1].front());
        edges.emplace_back(l.rows[j].back(), l.rows[j + 1].back());
    }
    return edges;
}

/*! Each boundary edge on the curve whose bounding box holds its midpoint, as gmsh line elements of that curve. */
void addBoundaryLines(const std::string& source, const Lattice& l, std::size_t firstTag, double tol)
{
    gmsh::vectorpair curves;
    gmsh::model::getEntities(curves, 1);
    std::map<int, std::vector<std::size_t>> nodesOfCurve;
    for (const auto& [a, b] : boundaryEdges(l))
    {
        const double mx = 0.5 * (l.xyz[3 * a] + l.xyz[3 * b]), my = 0.5 * (l.xyz[3 * a + 1] + l.xyz[3 * b + 1]);
        auto holds = [&](const std::pair<int, int>& curve) {
            const Box c = boundingBox(1, curve.second);
            return c.x0 - tol <= mx && mx <= c.x1 + tol && c.y0 - tol <= my && my <= c.y1 + tol;
        };
        const auto it = std::find_if(curves.begin(), curves.end(), holds);
        if (it == curves.end())
            throw InputError(source + ": mesh.mesher lattice: no curve holds the boundary point (" + jsonNumber(mx) +
                             ", " + jsonNumber(my) + ")");
        nodesOfCurve[it->second].insert(nodesOfCurve[it->second].end(), {std::size_t(a) + 1, std::size_t(b) + 1});
    }
    std::size_t tag = firstTag;
    for (const auto& [curve, nodes] : nodesOfCurve)
    {
        std::vector<std::size_t> tags(nodes.size() / 2);
        for (auto& t : tags)
            t = tag++;
        gmsh::model::mesh::addElementsByType(curve, 1, tags, nodes);
    }
}

} // namespace

void meshAsLattice(const std::string& source, double size)
{
    Box rect{};
    const int surface = rectangleSurface(source, rect);
    Lattice l = latticeNodes(rect, size);
    for (std::size_t j = 0; j + 1 < l.rows.size(); ++j)
        zipRows(l, l.rows[j], l.rows[j + 1]);
    std::vector<std::size_t> nodeTags(l.xyz.size() / 3);
    for (std::size_t n = 0; n < nodeTags.size(); ++n)
        nodeTags[n] = n + 1;
    gmsh::model::mesh::addNodes(2, surface, nodeTags, l.xyz);
    std::vector<std::size_t> triangleTags(l.triangles.size() / 3);
    for (std::size_t t = 0; t < triangleTags.size(); ++t)
        triangleTags[t] = t + 1;
    gmsh::model::mesh::addElementsByType(surface, 2, triangleTags, l.triangles);
    const double tol = 1e-9 * std::max(rect.x1 - rect.x0, rect.y1 - rect.y0);
    addBoundaryLines(source, l, triangleTags.size() + 1, tol);
}

} // namespace unilag
