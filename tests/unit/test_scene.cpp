// Scene input (src/config/Scene.cpp) and mesh loading (src/mesh/GlobalMesh.cpp): a valid scene reads with the
// expected values, --set overrides apply, and a mesh loads or is refused naming the element. Bad scenes:
// test_scene_errors.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "SceneFixture.hpp"
#include "config/Scene.hpp"
#include "mesh/GlobalMesh.hpp"

using namespace unilag_test;
namespace fs = std::filesystem;

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
    EXPECT_EQ(gas.eos, unilag::EosKind::IdealGas);
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
    EXPECT_EQ(s.boundaries.at("axis_x").type, unilag::BoundaryKind::Symmetry);
    EXPECT_EQ(s.boundaries.at("axis_y").type, unilag::BoundaryKind::Symmetry);
    EXPECT_EQ(s.boundaries.at("outer").type, unilag::BoundaryKind::SlipWall);

    EXPECT_DOUBLE_EQ(s.endTime, 1.0);
    EXPECT_DOUBLE_EQ(s.cfl, 0.5);
    EXPECT_DOUBLE_EQ(s.maxVolumeChange, 0.1); // defaults
    EXPECT_DOUBLE_EQ(s.maxGrowth, 1.1);
    EXPECT_DOUBLE_EQ(s.initialTimeStep, 0.0);

    EXPECT_EQ(s.outputDirectory, "output/sedov2d");
    EXPECT_DOUBLE_EQ(s.outputInterval, 0.1);
    EXPECT_TRUE(s.writeOutput);

    EXPECT_EQ(s.exactSolution, unilag::ExactSolution::Sedov);
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
    EXPECT_EQ(outer.type, unilag::BoundaryKind::Velocity);
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

TEST(Scene, SetTakesTheTypeOfItsValue)
{
    // `end: 1` and `interval: 0` are integers in the file; a fraction set over them must not be rounded (it was:
    // --set output.interval=0.002 over interval 0 gave 0, and time.end=0.4 over end 1 gave 0)
    TempDir dir;
    std::string text = replaced(sedovScene(), "time: { end: 1.0, cfl: 0.5 }", "time: { end: 1, cfl: 0.5 }");
    text = replaced(text, "interval: 0.1 }", "interval: 0 }");
    const std::string file = dir.write("scene.yaml", text);
    const unilag::Scene s = unilag::readScene(file, {"time.end=0.4", "output.interval=0.002", "scheme.order=2.0"});
    EXPECT_DOUBLE_EQ(s.endTime, 0.4);
    EXPECT_DOUBLE_EQ(s.outputInterval, 0.002);
    EXPECT_EQ(s.order, 2); // an integer key takes 2.0
    const std::string frac = inputError([&] { unilag::readScene(file, {"scheme.order=1.5"}); });
    EXPECT_PRED2(contains, frac, "scheme.order");

    // a list may hold expressions, as in the file; commas inside parentheses and quotes stay in their item
    const unilag::Scene v = unilag::readScene(file, {"regions.gas.velocity=[\"-x / max(r, 1e-12)\", 0.5]"});
    EXPECT_EQ(v.regions.at("gas").velocity[0].text, "-x / max(r, 1e-12)");
    EXPECT_DOUBLE_EQ(v.regions.at("gas").velocity[1].value, 0.5);
    const std::string word = inputError([&] { unilag::readScene(file, {"energy_deposit.position=[0, abc]"}); });
    EXPECT_PRED2(contains, word, "energy_deposit.position");
}

TEST(Scene, GprDefaultsAreAnIdealFluid)
{
    TempDir dir;
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", sedovScene()), {});
    const auto& gas = s.materials.at("gas");
    EXPECT_DOUBLE_EQ(gas.rho0, 1.0); // reference density of an ideal gas
    EXPECT_DOUBLE_EQ(gas.shearSpeed, 0.0);
    EXPECT_EQ(gas.strainLaw, unilag::RelaxationLaw::Fluid);
    EXPECT_DOUBLE_EQ(gas.tau1, 0.0);
    EXPECT_FALSE(gas.heatConduction);
    const auto& outer = s.boundaries.at("outer");
    EXPECT_EQ(outer.thermal, unilag::ThermalKind::Adiabatic);
    EXPECT_DOUBLE_EQ(outer.temperature, 0.0);
    EXPECT_DOUBLE_EQ(s.picardTolerance, 1e-10);
    EXPECT_EQ(s.picardMaxIterations, 50);
}

TEST(Scene, ReadsPlasticMaterial)
{
    TempDir dir;
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", withMaterial(kPlastic)), {});
    const auto& be = s.materials.at("gas");
    EXPECT_EQ(be.eos, unilag::EosKind::MieGruneisen);
    EXPECT_DOUBLE_EQ(be.rho0, 1845.0);
    EXPECT_DOUBLE_EQ(be.shearSpeed, 9070.0);
    EXPECT_EQ(be.strainLaw, unilag::RelaxationLaw::Plastic);
    EXPECT_DOUBLE_EQ(be.tau10, 1.0);
    EXPECT_DOUBLE_EQ(be.yieldStress, 3.3e8);
    EXPECT_DOUBLE_EQ(be.exponent, 20.0);
    EXPECT_FALSE(be.heatConduction);
}

TEST(Scene, StrainLawsGiveTau1)
{
    TempDir dir;
    const std::string solids = R"(      eos: ideal_gas
    water:
      eos: ideal_gas
      rho0: 1000
      shear_sound_speed: 10
      strain_relaxation: { law: viscous, viscosity: 0.02 }
    steel:
      eos: neo_hookean
      rho0: 7800
      csh: 3000
      shear_sound_speed: 3000
      strain_relaxation: { law: elastic }
    hydro:
      eos: ideal_gas
      shear_sound_speed: 1
      strain_relaxation: { law: constant, tau1: 1e-14 }
    stiff:
      eos: ideal_gas
      shear_sound_speed: 1
      strain_relaxation: { law: constant, tau1: 1e14 }
)";
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", withMaterial(solids)), {});
    const auto& water = s.materials.at("water");
    EXPECT_EQ(water.strainLaw, unilag::RelaxationLaw::Viscous);
    EXPECT_DOUBLE_EQ(water.viscosity, 0.02);
    EXPECT_DOUBLE_EQ(water.tau1, 6.0 * 0.02 / (1000.0 * 10.0 * 10.0)); // tau1 = 6 mu / (rho0 c_sh^2)
    const auto& steel = s.materials.at("steel");
    EXPECT_EQ(steel.strainLaw, unilag::RelaxationLaw::Elastic);
    EXPECT_TRUE(std::isinf(steel.tau1) && steel.tau1 > 0.0);
    EXPECT_DOUBLE_EQ(s.materials.at("hydro").tau1, 1e-14);
    EXPECT_DOUBLE_EQ(s.materials.at("stiff").tau1, 1e14);
    EXPECT_EQ(s.materials.at("gas").strainLaw, unilag::RelaxationLaw::Fluid);
}

TEST(Scene, HeatConductionKappaAndTau2)
{
    TempDir dir;
    // kappa given: tau2 = kappa rho0 / (alpha^2 theta0), rho0 = 1 by default for an ideal gas
    unilag::Scene s = unilag::readScene(dir.write("scene.yaml", withMaterial(kHeat)), {});
    const auto& gas = s.materials.at("gas");
    EXPECT_TRUE(gas.heatConduction);
    EXPECT_DOUBLE_EQ(gas.alpha, 2.0);
    EXPECT_DOUBLE_EQ(gas.theta0, 1.0);
    EXPECT_DOUBLE_EQ(gas.kappa, 1e-2);
    EXPECT_DOUBLE_EQ(gas.tau2, 1e-2 * 1.0 / (2.0 * 2.0 * 1.0));
    EXPECT_DOUBLE_EQ(gas.cv, 2.5);
    EXPECT_EQ(gas.strainLaw, unilag::RelaxationLaw::Constant);
    EXPECT_DOUBLE_EQ(gas.tau1, 1e-14);

    // tau2 given (and rho0, theta0 not 1): kappa = tau2 alpha^2 theta0 / rho0
    std::string text = replaced(withMaterial(kHeat), "kappa: 1e-2", "tau2: 0.5");
    text = replaced(text, "reference_temperature: 1", "reference_temperature: 300");
    text = replaced(text, "gamma: 1.4", "gamma: 1.4\n      rho0: 2.0");
    s = unilag::readScene(dir.write("scene.yaml", text), {});
    const auto& hot = s.materials.at("gas");
    EXPECT_DOUBLE_EQ(hot.rho0, 2.0);
    EXPECT_DOUBLE_EQ(hot.tau2, 0.5);
    EXPECT_DOUBLE_EQ(hot.kappa, 0.5 * 2.0 * 2.0 * 300.0 / 2.0);
}

TEST(Scene, TractionThermalBoundariesAndScheme)
{
    TempDir dir;
    std::string text = replaced(sedovScene(), "outer: { type: slip_wall }", "outer: { type: traction, traction: [0, -1e5] }");
    text = replaced(text, "axis_x: { type: symmetry }", "axis_x: { type: slip_wall, thermal: isothermal, temperature: 300 }");
    text = replaced(text, "  time: {", "  scheme: { picard_tolerance: 1e-8, picard_max_iterations: 20 }\n  time: {");
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", text), {});
    const auto& outer = s.boundaries.at("outer");
    EXPECT_EQ(outer.type, unilag::BoundaryKind::Traction);
    EXPECT_DOUBLE_EQ(outer.traction[0], 0.0);
    EXPECT_DOUBLE_EQ(outer.traction[1], -1e5);
    EXPECT_DOUBLE_EQ(outer.traction[2], 0.0);
    EXPECT_EQ(outer.thermal, unilag::ThermalKind::Adiabatic);
    const auto& wall = s.boundaries.at("axis_x");
    EXPECT_EQ(wall.type, unilag::BoundaryKind::SlipWall);
    EXPECT_EQ(wall.thermal, unilag::ThermalKind::Isothermal);
    EXPECT_DOUBLE_EQ(wall.temperature, 300.0);
    EXPECT_DOUBLE_EQ(s.picardTolerance, 1e-8);
    EXPECT_EQ(s.picardMaxIterations, 20);

    // --set reaches the new keys
    const unilag::Scene o = unilag::readScene(dir.write("scene.yaml", text), {"scheme.picard_max_iterations=7"});
    EXPECT_EQ(o.picardMaxIterations, 7);
}

TEST(Scene, ResolvedGprSceneReadsBack)
{
    TempDir dir;
    std::string text = withMaterial(kPlastic + "    air:\n" + kHeat);
    text = replaced(text, "outer: { type: slip_wall }", "outer: { type: traction, traction: [1.5, -1e5] }");
    text = replaced(text, "  time: {", "  scheme: { picard_max_iterations: 20 }\n  time: {");
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", text), {"scheme.picard_tolerance=1e-9"});
    const std::string resolved = (dir.path() / "resolved.yaml").string();
    unilag::writeScene(s, resolved);
    const unilag::Scene r = unilag::readScene(resolved, {});
    for (const auto* name : {"gas", "air"})
    {
        const auto& a = s.materials.at(name);
        const auto& b = r.materials.at(name);
        EXPECT_EQ(a.strainLaw, b.strainLaw) << name;
        EXPECT_DOUBLE_EQ(a.shearSpeed, b.shearSpeed) << name;
        EXPECT_DOUBLE_EQ(a.tau1, b.tau1) << name;
        EXPECT_DOUBLE_EQ(a.yieldStress, b.yieldStress) << name;
        EXPECT_EQ(a.heatConduction, b.heatConduction) << name;
        EXPECT_DOUBLE_EQ(a.tau2, b.tau2) << name;
    }
    EXPECT_DOUBLE_EQ(r.boundaries.at("outer").traction[1], -1e5);
    EXPECT_DOUBLE_EQ(r.picardTolerance, 1e-9);
    EXPECT_EQ(r.picardMaxIterations, 20);
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
        EXPECT_NEAR(unilag::signedMeasure(m, c), 0.5, 1e-15) << "cell " << c;
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
