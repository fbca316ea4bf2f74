// Tube scenes (src/tube/TubeScene.cpp) and the tube run (src/tube/TubeRun.cpp): a valid scene reads with its
// values, `--set` replaces the list of mass ratios, and bad input raises InputError naming the file and the key;
// runTube then exits 2 and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/Errors.hpp"
#include "tube/TubeRun.hpp"
#include "tube/TubeScene.hpp"

namespace
{

namespace fs = std::filesystem;
using namespace unilag::tube;

const std::string kScene = std::string(UNILAG_SOURCE_DIR) + "/inputs/tube_stability.yaml";

//! A scratch folder per test process (tests may run in parallel).
fs::path scratch()
{
    const fs::path dir = fs::temp_directory_path() / ("unilag_tube_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir;
}

//! The physical tube of tube.md 2.2 case (A): Ro = 5 mm, Ri = 3 mm, E = 1e7 Pa, water in a rubber wall.
std::string physicalScene()
{
    const std::string text = R"(%YAML 1.1
---
unilag:
  tube:
    model: euler_bernoulli
    length: 1.0
    outer_radius: 0.005
    inner_radius: 0.003
    youngs_modulus: 1.0e7
    poisson_ratio: 0.45
    density: 1000.0
  fluid: { density: 1000.0 }
  ends: { left: clamped, right: free }
  stability: { elements: 10, modes: 8, speed_max: 12.0, speed_step: 0.05 }
  output: { directory: out, plot: false }
)";
    const fs::path file = scratch() / "physical.yaml";
    std::ofstream(file) << text;
    return file.string();
}

//! The InputError message of reading `file` with overrides ("" if it reads).
std::string errorOf(const std::string& file, const std::vector<std::string>& overrides)
{
    try
    {
        readTubeScene(file, overrides);
    }
    catch (const unilag::InputError& e)
    {
        return e.what();
    }
    return "";
}

TEST(TubeScene, ReadsTheStabilityScene)
{
    const TubeScene s = readTubeScene(kScene, {});
    EXPECT_EQ(s.model, TubeModel::EulerBernoulli);
    EXPECT_EQ(s.left, EndCondition::Clamped);
    EXPECT_EQ(s.right, EndCondition::Free);
    EXPECT_EQ(s.stability.beta, (std::vector<double>{0.0, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9}));
    EXPECT_FALSE(s.hasPhysical);
}

TEST(TubeScene, SetReplacesTheListOfMassRatios)
{
    EXPECT_EQ(readTubeScene(kScene, {"stability.beta=[0.1,0.3]"}).stability.beta, (std::vector<double>{0.1, 0.3}));
    EXPECT_EQ(readTubeScene(kScene, {"stability.beta=[0.25]"}).stability.beta, (std::vector<double>{0.25}));
    EXPECT_EQ(readTubeScene(kScene, {"stability.beta=0.4"}).stability.beta, (std::vector<double>{0.4}));
}

TEST(TubeScene, PhysicalTubeGivesItsMassRatio)
{
    const TubeScene s = readTubeScene(physicalScene(), {});
    ASSERT_TRUE(s.hasPhysical);
    // tube.md 2.2 (A): EI = 4.27e-3 N m^2, M = 0.0283, m = 0.0503 kg/m, beta = 0.36
    EXPECT_NEAR(s.physical.bendingStiffness(), 4.273e-3, 1e-6);
    EXPECT_NEAR(s.physical.fluidMassPerLength(), 0.02827, 1e-5);
    EXPECT_NEAR(s.physical.wallMassPerLength(), 0.05027, 1e-5);
    ASSERT_EQ(s.stability.beta.size(), 1u);
    EXPECT_NEAR(s.stability.beta[0], 0.36, 0.001);
}

TEST(TubeScene, BadInputNamesFileAndKey)
{
    const std::string phys = physicalScene();
    struct Case
    {
        std::string file, set, expected;
    };
    const std::vector<Case> cases = {
        {phys, "tube.length=-1.0", "key 'tube.length': must be a positive number"},
        {phys, "tube.youngs_modulus=-2.0e7", "key 'tube.youngs_modulus': must be a positive number"},
        {phys, "tube.inner_radius=0.005", "key 'tube.inner_radius': must be less than outer_radius"},
        {phys, "tube.inner_radius=0.006", "key 'tube.inner_radius': must be less than outer_radius"},
        {phys, "fluid.densty=1.0", "key 'fluid.densty': unknown key (did you mean 'fluid.density'?)"},
        {kScene, "stability.beta=[0.2,1.0]", "key 'stability.beta': mass ratio must be in [0, 1), found 1"},
        {kScene, "stability.beta=[-0.1]", "key 'stability.beta': mass ratio must be in [0, 1)"},
        {kScene, "ends.left=clampd",
         "key 'ends.left': 'clampd' is not one of: clamped, pinned, free (did you mean "
         "'clamped'?)"},
        {kScene, "tube.length=-1.0", "key 'tube.length': must be a positive number"},
        {kScene, "tube.model=timoshenko", "key 'tube.model': 'timoshenko' is not one of"},
        {kScene, "stability.elements=1", "key 'stability.elements': must be in [2, 1000]"},
    };
    for (const Case& c : cases)
    {
        const std::string msg = errorOf(c.file, {c.set});
        EXPECT_NE(msg.find(c.file + ": " + c.expected), std::string::npos) << c.set << " gave: " << msg;
    }
}

const std::string kGeometric = std::string(UNILAG_SOURCE_DIR) + "/inputs/tube_rubber_geometric.yaml";

TEST(TubeScene, ReadsTheGeometricScene)
{
    const TubeScene s = readTubeScene(kGeometric, {});
    EXPECT_EQ(s.model, TubeModel::Geometric);
    ASSERT_TRUE(s.hasPhysical);
    EXPECT_DOUBLE_EQ(s.physical.areaChange, 2.5e-6);
    EXPECT_EQ(s.physical.areaPressure, AreaPressure::Dynamic);
    EXPECT_DOUBLE_EQ(s.physical.shearCoefficient, 0.5);
    EXPECT_NEAR(s.stability.beta.at(0), 0.36, 0.001);
    // K / (A_i L^2) = 2.5e-6 / (pi 9e-6)
    EXPECT_NEAR(s.physical.geometricParameters().areaChange, 2.5e-6 / (3.14159265358979 * 9e-6), 1e-9);
    EXPECT_EQ(readTubeScene(kGeometric, {"tube.area_change_pressure=static"}).physical.areaPressure,
              AreaPressure::Static);
}

TEST(TubeScene, GeometricBadInputNamesFileAndKey)
{
    struct Case
    {
        std::string file;
        std::vector<std::string> set;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {kGeometric, {"tube.area_change=-1.0e-6"}, "key 'tube.area_change': must be a non-negative number"},
        {kGeometric, {"tube.area_change_pressure=total"}, "key 'tube.area_change_pressure': 'total' is not one of"},
        {kGeometric, {"stability.beta=[0.2]"}, "key 'stability.beta': the geometric model takes its mass ratio"},
        {kGeometric, {"tube.model=euler_bernoulli"}, "key 'tube.area_change': only the geometric model has"},
        {kScene,
         {"tube.model=geometric", "stability.beta=[0.2]"},
         "key 'tube.length': missing (the geometric model needs"},
    };
    for (const Case& c : cases)
    {
        const std::string msg = errorOf(c.file, c.set);
        EXPECT_NE(msg.find(c.file + ": " + c.expected), std::string::npos) << c.set[0] << " gave: " << msg;
    }
}

TEST(TubeRun, BadInputExitsTwoAndWritesNothing)
{
    const fs::path out = scratch() / "bad";
    fs::remove_all(out);
    EXPECT_EQ(unilag::runTube(kScene, {"stability.beta=[0.5,1.5]"}, out.string(), false, true, MPI_COMM_WORLD),
              unilag::ExitInput);
    EXPECT_FALSE(fs::exists(out));
}

TEST(TubeRun, WritesTheStabilityTable)
{
    const fs::path out = scratch() / "ok";
    fs::remove_all(out);
    ASSERT_EQ(unilag::runTube(physicalScene(), {}, out.string(), false, true, MPI_COMM_WORLD), unilag::ExitOk);
    std::ifstream csv(out / "stability.csv");
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_EQ(header, "beta,u_cf,omega_cf,instability,u_cd,U_cf_m_per_s,f_cf_hz,mode");
    // tube.md 2.2 (A): u_cf = 8.59, U = 8.59 x 0.389 = 3.3 m/s
    const double ucf = std::stod(row.substr(row.find(',') + 1));
    EXPECT_NEAR(ucf, 8.59, 0.01);
    EXPECT_NE(row.find(",flutter,nan,3.3"), std::string::npos) << row;
    EXPECT_TRUE(fs::exists(out / "summary.json"));
    EXPECT_TRUE(fs::exists(out / "stability_loci.csv"));
    EXPECT_TRUE(fs::exists(out / "scene.yaml"));
    fs::remove_all(scratch());
}

} // namespace
