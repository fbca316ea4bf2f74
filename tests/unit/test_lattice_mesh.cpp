// mesh.mesher: lattice (src/mesh/LatticeMesh.cpp): the quadrant of inputs/geometry/quadrant2d.geo as an equilateral
// lattice whose only cells smaller than the lattice's own lie at the two bottom corners, the octant of octant3d.geo as
// a body-centred cubic lattice of tetrahedra all of one volume, the .geo's groups naming boundary and cells; geometry
// that is not one axis-aligned rectangle or box is refused, naming the file and the entity.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <string>
#include <vector>

#include "SceneFixture.hpp"
#include "config/Scene.hpp"
#include "mesh/GlobalMesh.hpp"

using namespace unilag_test;

namespace
{

unilag::Scene latticeScene(const std::string& geometry, double size)
{
    unilag::Scene s;
    s.geometry = geometry;
    s.meshSize = size;
    s.meshLattice = true;
    return s;
}

double centroidY(const unilag::GlobalMesh& m, std::size_t c)
{
    double y = 0.0;
    for (int k = 0; k < 3; ++k)
        y += m.coords[3 * m.cells[3 * c + k] + 1] / 3.0;
    return y;
}

} // namespace

TEST(LatticeMesh, QuadrantHasNoSmallCellAlongItsPlanesButAtTheCorners)
{
    const double size = 0.0577; // 21 cells along x, 24 rows of height 0.05
    const auto m = unilag::loadMesh(latticeScene(kGeometry, size));
    EXPECT_EQ(m.regionNames, std::vector<std::string>{"gas"});
    EXPECT_EQ(m.boundaryNames, (std::vector<std::string>{"axis_x", "axis_y", "outer"}));
    const double full = 0.5 * (1.2 / 21) * 0.05;
    double total = 0.0;
    int small = 0;
    for (std::size_t c = 0; c < m.nCells(); ++c)
    {
        const double a = unilag::signedMeasure(m, c);
        ASSERT_GT(a, 0.0) << "cell " << c << " is not counter-clockwise";
        total += a;
        if (a < 0.99 * full)
        {
            ++small;
            EXPECT_LT(centroidY(m, c), 0.1) << "a small cell above the two bottom rows, cell " << c;
            EXPECT_NEAR(a, 0.5 * full, 1e-12) << "cell " << c;
        }
        EXPECT_LT(a, 1.5 * full + 1e-12) << "cell " << c;
    }
    EXPECT_NEAR(total, 1.44, 1e-12);
    EXPECT_EQ(small, 4); // a half cell at each end of rows 0-1 and 1-2
    // boundary edges per group: 21 along y = 0, 24 along x = 0, 24 + 21 on the outer sides
    std::vector<int> edges(3, 0);
    for (int g : m.cellFaceGroup)
        if (g >= 0)
            ++edges[g];
    EXPECT_EQ(edges, (std::vector<int>{21, 24, 45}));
}

TEST(LatticeMesh, RefusesANonRectangle)
{
    const std::string geo = kSource + "/inputs/geometry/quarter_annulus2d.geo";
    const std::string msg = inputError([&] { unilag::loadMesh(latticeScene(geo, 0.05)); });
    EXPECT_PRED2(contains, msg, geo);
    EXPECT_PRED2(contains, msg, "axis-aligned rectangle; curve ");
    EXPECT_PRED2(contains, msg, "is not on a side of its bounding box");
}

TEST(LatticeMesh, OctantTetrahedraAreAllOfOneVolume)
{
    const std::string geo = kSource + "/inputs/geometry/octant3d.geo";
    const auto m = unilag::loadMesh(latticeScene(geo, 0.3)); // 4 cubic cells a side, h = 0.3
    EXPECT_EQ(m.dim, 3);
    EXPECT_EQ(m.regionNames, std::vector<std::string>{"gas"});
    ASSERT_EQ(m.nCells(), 12u * 64u);
    EXPECT_EQ(m.nNodes(), 125u + 64u);
    const double each = 0.3 * 0.3 * 0.3 / 12.0;
    double total = 0.0;
    for (std::size_t c = 0; c < m.nCells(); ++c)
    {
        const double v = unilag::signedMeasure(m, c);
        EXPECT_NEAR(v, each, 1e-14) << "cell " << c;
        total += v;
    }
    EXPECT_NEAR(total, 1.2 * 1.2 * 1.2, 1e-12);
    // two triangles per boundary face of a cubic cell: 32 on each side, 96 on the three outer sides together
    std::map<std::string, int> faces;
    for (int g : m.cellFaceGroup)
        if (g >= 0)
            ++faces[m.boundaryNames[g]];
    EXPECT_EQ(faces, (std::map<std::string, int>{{"outer", 96}, {"symmetry_x", 32}, {"symmetry_y", 32},
                                                  {"symmetry_z", 32}}));
}

TEST(LatticeMesh, RefusesAVolumeThatIsNotABox)
{
    TempDir dir;
    const std::string geo = dir.write("cylinder.geo", "SetFactory(\"OpenCASCADE\");\nCylinder(1) = {0, 0, 0, 0, 0, 1, "
                                                      "0.5};\nPhysical Volume(\"gas\") = {1};\n");
    const std::string msg = inputError([&] { unilag::loadMesh(latticeScene(geo, 0.2)); });
    EXPECT_PRED2(contains, msg, geo);
    EXPECT_PRED2(contains, msg, "axis-aligned box; surface ");
}

TEST(LatticeMesh, RefusesTwoSurfaces)
{
    const std::string geo = kSource + "/tests/meshes/mixed_tri_quad.geo";
    const std::string msg = inputError([&] { unilag::loadMesh(latticeScene(geo, 0.1)); });
    EXPECT_PRED2(contains, msg, "one axis-aligned rectangle; the geometry has 2 surfaces");
}
