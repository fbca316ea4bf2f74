// Scene input (src/io/Scene.cpp) and mesh loading (src/mesh/GlobalMesh.cpp): a valid scene reads with the
// expected values, --set overrides apply, and bad input of every kind raises InputError naming the file and
// the key (or the element), never anything else.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "io/Scene.hpp"
#include "mesh/GlobalMesh.hpp"

namespace
{

namespace fs = std::filesystem;

const std::string kSource = UNILAG_SOURCE_DIR;
const std::string kGeometry = kSource + "/inputs/geometry/quadrant2d.geo";
const std::string kTable = kSource + "/inputs/exact/sedov_cyl_gamma1.4_E0.244816quadrant_t1.csv";

//! text with the single occurrence of `from` replaced by `to` (fails the test if `from` is not there once).
std::string replaced(const std::string& text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos)
    {
        ADD_FAILURE() << "'" << from << "' does not occur exactly once in the scene";
        return text;
    }
    return text.substr(0, at) + to + text.substr(at + from.size());
}

//! inputs/sedov2d.yaml with absolute paths to the geometry and the exact table.
std::string sedovScene()
{
    const std::string text = R"(%YAML 1.1
---
unilag:
  title: sedov2d
  mesh:
    geometry: @GEOMETRY@
    size: 0.0144
  materials:
    gas: { eos: ideal_gas, gamma: 1.4 }
  regions:
    gas: { material: gas, density: 1.0, velocity: [0.0, 0.0], pressure: 1.0e-6 }
  energy_deposit: { position: [0.0, 0.0], energy: 0.244816 }
  boundaries:
    axis_x: { type: symmetry }
    axis_y: { type: symmetry }
    outer: { type: slip_wall }
  time: { end: 1.0, cfl: 0.5 }
  output: { directory: output/sedov2d, interval: 0.1 }
  exact:
    solution: sedov
    table: @TABLE@
    shock_radius: 0.9988
    shock_radius_tolerance: 0.03
...
)";
    return replaced(replaced(text, "@GEOMETRY@", kGeometry), "@TABLE@", kTable);
}

//! A fresh directory under the system temp folder for the current test, removed afterwards.
class TempDir
{
  public:
    TempDir()
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("unilag_unit_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir()
    {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string write(const std::string& name, const std::string& text) const
    {
        const fs::path p = path_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

//! The message of the InputError that f throws ("" and a test failure if it throws nothing or something else).
template <class F> std::string inputError(F&& f)
{
    try
    {
        f();
    }
    catch (const unilag::InputError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "expected unilag::InputError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected unilag::InputError, nothing was thrown";
    return {};
}

//! Writes the scene text and returns readScene's InputError message; checks it names the file and the key.
std::string sceneError(const TempDir& dir, const std::string& text, const std::string& key,
                       const std::vector<std::string>& overrides = {})
{
    const std::string file = dir.write("scene.yaml", text);
    const std::string msg = inputError([&] { unilag::readScene(file, overrides); });
    EXPECT_PRED2(contains, msg, file);
    EXPECT_PRED2(contains, msg, "'" + key + "'");
    return msg;
}

} // namespace

// ---- valid scenes ----

TEST(Scene, ReadsSedovScene)
{
    TempDir dir;
    const std::string file = dir.write("sedov.yaml", sedovScene());
    const unilag::Scene s = unilag::readScene(file, {});

    EXPECT_EQ(s.file, file);
    EXPECT_EQ(fs::path(s.directory), dir.path());
    EXPECT_EQ(s.name, "sedov2d");
    EXPECT_EQ(s.geometry, fs::path(kGeometry).lexically_normal().string());
    EXPECT_TRUE(s.meshFile.empty());
    EXPECT_DOUBLE_EQ(s.meshSize, 0.0144);

    ASSERT_EQ(s.materials.size(), 1u);
    const auto& gas = s.materials.at("gas");
    EXPECT_EQ(gas.eos, "ideal_gas");
    EXPECT_DOUBLE_EQ(gas.gamma, 1.4);
    EXPECT_DOUBLE_EQ(gas.cv, 1.0); // default

    ASSERT_EQ(s.regions.size(), 1u);
    const auto& region = s.regions.at("gas");
    EXPECT_EQ(region.material, "gas");
    EXPECT_TRUE(region.density.isConstant());
    EXPECT_DOUBLE_EQ(region.density.value, 1.0);
    EXPECT_TRUE(region.hasPressure);
    EXPECT_DOUBLE_EQ(region.pressure.value, 1.0e-6);
    EXPECT_EQ(region.velocityComponents, 2);
    EXPECT_DOUBLE_EQ(region.velocity[0].value, 0.0);
    EXPECT_DOUBLE_EQ(region.velocity[1].value, 0.0);

    EXPECT_TRUE(s.hasDeposit);
    EXPECT_DOUBLE_EQ(s.depositPosition[0], 0.0);
    EXPECT_DOUBLE_EQ(s.depositPosition[1], 0.0);
    EXPECT_DOUBLE_EQ(s.depositEnergy, 0.244816);

    ASSERT_EQ(s.boundaries.size(), 3u);
    EXPECT_EQ(s.boundaries.at("axis_x").type, "symmetry");
    EXPECT_EQ(s.boundaries.at("axis_y").type, "symmetry");
    EXPECT_EQ(s.boundaries.at("outer").type, "slip_wall");

    EXPECT_DOUBLE_EQ(s.endTime, 1.0);
    EXPECT_DOUBLE_EQ(s.cfl, 0.5);
    EXPECT_DOUBLE_EQ(s.maxVolumeChange, 0.1); // defaults
    EXPECT_DOUBLE_EQ(s.maxGrowth, 1.1);
    EXPECT_DOUBLE_EQ(s.initialTimeStep, 0.0);

    EXPECT_EQ(s.outputDirectory, "output/sedov2d");
    EXPECT_DOUBLE_EQ(s.outputInterval, 0.1);
    EXPECT_TRUE(s.writeOutput);

    EXPECT_EQ(s.exactSolution, "sedov");
    EXPECT_EQ(s.exactTable, fs::path(kTable).lexically_normal().string());
    EXPECT_DOUBLE_EQ(s.exactShockRadius, 0.9988);
    EXPECT_DOUBLE_EQ(s.exactTime, 1.0); // default
    EXPECT_DOUBLE_EQ(s.shockRadiusTolerance, 0.03);
    EXPECT_DOUBLE_EQ(s.maxL1Density, 0.0);
}

TEST(Scene, ExpressionsAndVelocityBoundaries)
{
    TempDir dir;
    std::string text = replaced(sedovScene(), "pressure: 1.0e-6", "pressure: \"1 + 0.5 * x\"");
    text = replaced(text, "outer: { type: slip_wall }", "outer: { type: velocity, velocity: [0.5, -1.0] }");
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", text), {});
    const auto& p = s.regions.at("gas").pressure;
    EXPECT_FALSE(p.isConstant());
    EXPECT_EQ(p.text, "1 + 0.5 * x");
    EXPECT_DOUBLE_EQ(p.value, 1.0); // the value at the origin
    const auto& outer = s.boundaries.at("outer");
    EXPECT_EQ(outer.type, "velocity");
    EXPECT_DOUBLE_EQ(outer.velocity[0], 0.5);
    EXPECT_DOUBLE_EQ(outer.velocity[1], -1.0);
    EXPECT_DOUBLE_EQ(outer.velocity[2], 0.0);
}

TEST(Scene, SetOverridesValues)
{
    TempDir dir;
    const std::string file = dir.write("scene.yaml", sedovScene());
    const unilag::Scene s = unilag::readScene(file, {"time.end=0.5", "mesh.size=0.05"});
    EXPECT_DOUBLE_EQ(s.endTime, 0.5);
    EXPECT_DOUBLE_EQ(s.meshSize, 0.05);
    EXPECT_DOUBLE_EQ(s.cfl, 0.5); // untouched

    // an override is validated like the file: a misspelt key or a bad value names the key
    const std::string bad = inputError([&] { unilag::readScene(file, {"time.ennd=0.5"}); });
    EXPECT_PRED2(contains, bad, file);
    EXPECT_PRED2(contains, bad, "time.ennd");
    const std::string range = inputError([&] { unilag::readScene(file, {"time.cfl=2.0"}); });
    EXPECT_PRED2(contains, range, "time.cfl");
}

// ---- invalid scenes: InputError naming the file and the key ----

TEST(SceneErrors, UnknownTopLevelKey)
{
    TempDir dir;
    const std::string text = replaced(sedovScene(), "  title: sedov2d\n", "  title: sedov2d\n  tme: 1.0\n");
    const std::string msg = sceneError(dir, text, "tme");
    EXPECT_PRED2(contains, msg, "unknown key");
}

TEST(SceneErrors, MisspeltNestedKey)
{
    TempDir dir;
    // a misspelt optional key: the unknown key and a suggestion
    std::string msg = sceneError(dir, replaced(sedovScene(), "cfl: 0.5", "cffl: 0.5"), "time.cffl");
    EXPECT_PRED2(contains, msg, "did you mean 'time.cfl'");
    // a misspelt required key: the missing key and the misspelling are named
    msg = sceneError(dir, replaced(sedovScene(), "end: 1.0", "ennd: 1.0"), "time.ennd");
    EXPECT_PRED2(contains, msg, "did you mean 'time.end'");
}

TEST(SceneErrors, WrongType)
{
    TempDir dir;
    const std::string msg = sceneError(dir, replaced(sedovScene(), "end: 1.0", "end: \"soon\""), "time.end");
    EXPECT_PRED2(contains, msg, "soon");
}

TEST(SceneErrors, OutOfRange)
{
    TempDir dir;
    sceneError(dir, replaced(sedovScene(), "cfl: 0.5", "cfl: 1.5"), "time.cfl");
    sceneError(dir, replaced(sedovScene(), "density: 1.0", "density: -1.0"), "regions.gas.density");
    sceneError(dir, replaced(sedovScene(), "gamma: 1.4", "gamma: 1.0"), "materials.gas.gamma");
    sceneError(dir, replaced(sedovScene(), "size: 0.0144", "size: 0.0"), "mesh.size");
}

TEST(SceneErrors, UnknownEos)
{
    TempDir dir;
    const std::string msg =
        sceneError(dir, replaced(sedovScene(), "eos: ideal_gas", "eos: stiff"), "materials.gas.eos");
    EXPECT_PRED2(contains, msg, "stiff");
}

TEST(SceneErrors, UnknownBoundaryType)
{
    TempDir dir;
    const std::string msg =
        sceneError(dir, replaced(sedovScene(), "type: slip_wall", "type: sticky"), "boundaries.outer.type");
    EXPECT_PRED2(contains, msg, "sticky");
}

TEST(SceneErrors, BadExpression)
{
    TempDir dir;
    sceneError(dir, replaced(sedovScene(), "pressure: 1.0e-6", "pressure: \"1 + * x\""), "regions.gas.pressure");
}

TEST(SceneErrors, MalformedYaml)
{
    TempDir dir;
    const std::string file = dir.write("broken.yaml", "%YAML 1.1\n---\nunilag:\n  mesh: { a: [1, 2 }\n...\n");
    const std::string msg = inputError([&] { unilag::readScene(file, {}); });
    EXPECT_PRED2(contains, msg, file);
    EXPECT_PRED2(contains, msg, "malformed YAML");
}

TEST(SceneErrors, MissingFile)
{
    TempDir dir;
    const std::string file = (dir.path() / "nowhere.yaml").string();
    const std::string msg = inputError([&] { unilag::readScene(file, {}); });
    EXPECT_PRED2(contains, msg, file);
    EXPECT_PRED2(contains, msg, "not found");
}

// ---- meshes (.msh, gmsh ASCII 2.2) ----

namespace
{

/*! The unit square as two triangles 5 (nodes 1 2 3) and 6 (nodes 1 3 4), both counter-clockwise unless
 *  given otherwise, with its four edges in the boundary group "wall" (unless `lines` drops some). */
std::string squareMsh(const std::string& triangle5 = "1 2 3", const std::string& triangle6 = "1 3 4",
                      const std::vector<std::string>& lines = {"1 2", "2 3", "3 4", "4 1"},
                      const std::vector<std::string>& extraNodes = {},
                      const std::vector<std::string>& extraTriangles = {})
{
    std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                    "$PhysicalNames\n2\n1 1 \"wall\"\n2 2 \"gas\"\n$EndPhysicalNames\n";
    s += "$Nodes\n" + std::to_string(4 + extraNodes.size()) + "\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n";
    for (const auto& n : extraNodes)
        s += n + "\n";
    s += "$EndNodes\n$Elements\n" + std::to_string(lines.size() + 2 + extraTriangles.size()) + "\n";
    // element: tag, type (1 line, 2 triangle), 2 tags (physical group, elementary entity), nodes
    int tag = 1;
    for (std::size_t l = 0; l < lines.size(); ++l)
        s += std::to_string(tag++) + " 1 2 1 " + std::to_string(l + 1) + " " + lines[l] + "\n";
    tag = 5;
    for (const auto& t : std::vector<std::string>{triangle5, triangle6})
        s += std::to_string(tag++) + " 2 2 2 1 " + t + "\n";
    for (const auto& t : extraTriangles)
        s += std::to_string(tag++) + " 2 2 2 1 " + t + "\n";
    return s + "$EndElements\n";
}

unilag::Scene meshScene(const std::string& msh)
{
    unilag::Scene s;
    s.meshFile = msh;
    return s;
}

//! loadMesh's InputError message for the mesh text; checks it names the file.
std::string meshError(const TempDir& dir, const std::string& text)
{
    const std::string file = dir.write("mesh.msh", text);
    const std::string msg = inputError([&] { unilag::loadMesh(meshScene(file)); });
    EXPECT_PRED2(contains, msg, file);
    return msg;
}

double signedArea(const unilag::GlobalMesh& m, std::size_t c)
{
    const double* a = &m.coords[3 * m.cells[3 * c]];
    const double* b = &m.coords[3 * m.cells[3 * c + 1]];
    const double* d = &m.coords[3 * m.cells[3 * c + 2]];
    return 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
}

void expectSquare(const unilag::GlobalMesh& m)
{
    EXPECT_EQ(m.dim, 2);
    ASSERT_EQ(m.nCells(), 2u);
    EXPECT_EQ(m.nNodes(), 4u);
    ASSERT_EQ(m.regionNames, std::vector<std::string>{"gas"});
    ASSERT_EQ(m.boundaryNames, std::vector<std::string>{"wall"});
    ASSERT_EQ(m.cellFaceGroup.size(), 6u);
    int boundary = 0, interior = 0;
    for (int g : m.cellFaceGroup)
        (g == 0 ? boundary : interior) += 1;
    EXPECT_EQ(boundary, 4); // the four edges
    EXPECT_EQ(interior, 2); // the diagonal, seen from both triangles
    for (std::size_t c = 0; c < 2; ++c)
        EXPECT_NEAR(signedArea(m, c), 0.5, 1e-15) << "cell " << c;
}

} // namespace

TEST(MeshLoad, ConsistentSquareLoads)
{
    TempDir dir;
    const auto m = unilag::loadMesh(meshScene(dir.write("square.msh", squareMsh())));
    expectSquare(m);
    EXPECT_EQ(m.cellTag, (std::vector<std::size_t>{5, 6}));
}

TEST(MeshLoad, ClockwiseSquareIsReoriented)
{
    TempDir dir;
    const auto m = unilag::loadMesh(meshScene(dir.write("square.msh", squareMsh("1 3 2", "1 4 3"))));
    expectSquare(m);
}

TEST(MeshLoad, InvertedElementIsRejected)
{
    TempDir dir;
    const std::string msg = meshError(dir, squareMsh("1 2 3", "1 4 3"));
    EXPECT_PRED2(contains, msg, "element 6 ");
    EXPECT_PRED2(contains, msg, "inverted");
}

TEST(MeshLoad, DegenerateElementIsRejected)
{
    TempDir dir;
    // node 5 on the edge 1-2: triangle 7 (1 5 2) has zero area
    const std::string msg =
        meshError(dir, squareMsh("1 2 3", "1 3 4", {"1 2", "2 3", "3 4", "4 1"}, {"5 0.5 0 0"}, {"1 5 2"}));
    EXPECT_PRED2(contains, msg, "element 7 ");
    EXPECT_PRED2(contains, msg, "degenerate");
}

TEST(MeshLoad, BoundaryWithoutGroupIsRejected)
{
    TempDir dir;
    const std::string msg = meshError(dir, squareMsh("1 2 3", "1 3 4", {"1 2", "2 3", "3 4"}));
    EXPECT_PRED2(contains, msg, "no boundary physical group");
    EXPECT_PRED2(contains, msg, "element 6"); // the edge 4-1 belongs to triangle 6
}
