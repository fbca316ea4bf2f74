// Bad scenes (src/config/Scene.cpp): every kind raises InputError naming the file and the key, never anything
// else. Valid scenes and meshes: test_scene.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "SceneFixture.hpp"
#include "config/ListWords.hpp"
#include "config/Scene.hpp"

using namespace unilag_test;

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

// ---- invalid GPR input ----

TEST(SceneErrors, BadEosParameters)
{
    TempDir dir;
    std::string msg = sceneError(dir, replaced(sedovScene(), "gamma: 1.4", "gamma: 0.9"), "materials.gas.gamma");
    EXPECT_PRED2(contains, msg, "gamma > 1");
    msg = sceneError(dir, replaced(sedovScene(), "gamma: 1.4", "gamma: 1.4, rho0: 0"), "materials.gas.rho0");
    EXPECT_PRED2(contains, msg, "positive");
    msg = sceneError(dir, replaced(withMaterial(kPlastic), "rho0: 1845", "rho0: -1845"), "materials.gas.rho0");
    EXPECT_PRED2(contains, msg, "positive");
    // a misspelt eos: the allowed values and the nearest one
    msg = sceneError(dir, replaced(sedovScene(), "eos: ideal_gas", "eos: mie_grunesen"), "materials.gas.eos");
    EXPECT_PRED2(contains, msg, "ideal_gas, mie_gruneisen, neo_hookean");
    EXPECT_PRED2(contains, msg, "did you mean 'mie_gruneisen'");
}

TEST(SceneErrors, ShearSoundSpeed)
{
    TempDir dir;
    std::string msg = sceneError(dir, replaced(withMaterial(kPlastic), "shear_sound_speed: 9070", "shear_sound_speed: -1"),
                                 "materials.gas.shear_sound_speed");
    EXPECT_PRED2(contains, msg, "non-negative");
    // a law with shear stress needs c_sh > 0
    msg = sceneError(dir, replaced(withMaterial(kPlastic), "      shear_sound_speed: 9070\n", ""),
                     "materials.gas.shear_sound_speed");
    EXPECT_PRED2(contains, msg, "'plastic' needs a shear sound speed > 0");
    // an ideal fluid has none: the message points to the hydrodynamic limit
    msg = sceneError(dir, replaced(sedovScene(), "gamma: 1.4", "gamma: 1.4, shear_sound_speed: 1.0"),
                     "materials.gas.shear_sound_speed");
    EXPECT_PRED2(contains, msg, "no shear stiffness");
    EXPECT_PRED2(contains, msg, "law: constant, tau1: 1e-14");
    msg = sceneError(dir, replaced(withMaterial(kHeat), "law: constant, tau1: 1e-14", "law: fluid"),
                     "materials.gas.shear_sound_speed");
    EXPECT_PRED2(contains, msg, "no shear stiffness");
}

TEST(SceneErrors, StrainRelaxationValues)
{
    TempDir dir;
    const std::string prefix = "materials.gas.strain_relaxation.";
    const std::string heat = withMaterial(kHeat), plastic = withMaterial(kPlastic);
    for (const auto* bad : {"tau1: -1e-14", "tau1: 0"})
    {
        const std::string msg = sceneError(dir, replaced(heat, "tau1: 1e-14", bad), prefix + "tau1");
        EXPECT_PRED2(contains, msg, "must be a positive number");
    }
    sceneError(dir, replaced(plastic, "tau10: 1.0", "tau10: 0"), prefix + "tau10");
    sceneError(dir, replaced(plastic, "yield_stress: 3.3e8", "yield_stress: -3.3e8"), prefix + "yield_stress");
    sceneError(dir, replaced(plastic, "exponent: 20", "exponent: -2"), prefix + "exponent");
    const std::string viscous = replaced(heat, "law: constant, tau1: 1e-14", "law: viscous, viscosity: -0.1");
    std::string msg = sceneError(dir, viscous, prefix + "viscosity");
    EXPECT_PRED2(contains, msg, "must be a positive number, found -0.1");
}

TEST(SceneErrors, StrainRelaxationKeys)
{
    TempDir dir;
    const std::string prefix = "materials.gas.strain_relaxation.";
    const std::string heat = withMaterial(kHeat), plastic = withMaterial(kPlastic);
    // unknown law: the allowed values and the nearest one
    std::string msg = sceneError(dir, replaced(plastic, "law: plastic", "law: plastik"), prefix + "law");
    EXPECT_PRED2(contains, msg, "fluid, viscous, elastic, constant, plastic");
    EXPECT_PRED2(contains, msg, "did you mean 'plastic'");
    // missing law, missing parameters
    msg = sceneError(dir, replaced(plastic, "        law: plastic\n", ""), prefix + "law");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(plastic, "        yield_stress: 3.3e8\n", ""), prefix + "yield_stress");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(heat, "law: constant, tau1: 1e-14", "law: constant"), prefix + "tau1");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(heat, "law: constant, tau1: 1e-14", "law: viscous"), prefix + "viscosity");
    EXPECT_PRED2(contains, msg, "missing");
    // a parameter of another law
    msg = sceneError(dir, replaced(plastic, "exponent: 20", "exponent: 20\n        viscosity: 0.1"), prefix + "viscosity");
    EXPECT_PRED2(contains, msg, "belongs to law 'viscous', not to law 'plastic'");
    msg = sceneError(dir, replaced(heat, "law: constant, tau1: 1e-14", "law: elastic, tau1: 1e14"), prefix + "tau1");
    EXPECT_PRED2(contains, msg, "belongs to law 'constant'");
    // a misspelt key
    msg = sceneError(dir, replaced(plastic, "tau10: 1.0", "tau10: 1.0\n        exponnent: 2"), prefix + "exponnent");
    EXPECT_PRED2(contains, msg, "did you mean");
    // not a section
    sceneError(dir, replaced(heat, "strain_relaxation: { law: constant, tau1: 1e-14 }", "strain_relaxation: plastic"),
               "materials.gas.strain_relaxation");
}

TEST(SceneErrors, HeatConduction)
{
    TempDir dir;
    const std::string prefix = "materials.gas.heat_conduction.";
    const std::string heat = withMaterial(kHeat);
    sceneError(dir, replaced(heat, "alpha: 2.0", "alpha: 0"), prefix + "alpha");
    sceneError(dir, replaced(heat, "alpha: 2.0", "alpha: -2.0"), prefix + "alpha");
    sceneError(dir, replaced(heat, "kappa: 1e-2", "kappa: -1e-2"), prefix + "kappa");
    sceneError(dir, replaced(heat, "kappa: 1e-2", "tau2: 0"), prefix + "tau2");
    sceneError(dir, replaced(heat, "reference_temperature: 1", "reference_temperature: 0"),
               prefix + "reference_temperature");
    std::string msg = sceneError(dir, replaced(heat, "        alpha: 2.0\n", ""), prefix + "alpha");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(heat, "        reference_temperature: 1\n", ""), prefix + "reference_temperature");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(heat, "        kappa: 1e-2\n", ""), prefix + "kappa");
    EXPECT_PRED2(contains, msg, "exactly one of 'kappa'");
    msg = sceneError(dir, replaced(heat, "kappa: 1e-2", "kappa: 1e-2\n        tau2: 1e-3"), prefix + "kappa");
    EXPECT_PRED2(contains, msg, "exactly one of 'kappa'");
    msg = sceneError(dir, replaced(heat, "cv: 2.5", "cv: 0"), "materials.gas.cv");
    EXPECT_PRED2(contains, msg, "positive");
}

TEST(SceneErrors, TractionAndThermalBoundaries)
{
    TempDir dir;
    const std::string prefix = "boundaries.outer.";
    const std::string traction = replaced(sedovScene(), "outer: { type: slip_wall }", "outer: { type: traction }");
    std::string msg = sceneError(dir, traction, prefix + "traction");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(traction, "type: traction", "type: traction, traction: [1.0]"), prefix + "traction");
    EXPECT_PRED2(contains, msg, "2 or 3 numbers");
    msg = sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", "outer: { type: slip_wall, traction: [0, 1] }"),
                     prefix + "traction");
    EXPECT_PRED2(contains, msg, "only a boundary of type 'traction'");
    msg = sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", "outer: { type: tracton }"), prefix + "type");
    EXPECT_PRED2(contains, msg, "did you mean 'traction'");

    const std::string iso = "outer: { type: slip_wall, thermal: isothermal, temperature: 300 }";
    sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", replaced(iso, "300", "-300")),
               prefix + "temperature");
    msg = sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", replaced(iso, ", temperature: 300", "")),
                     prefix + "temperature");
    EXPECT_PRED2(contains, msg, "missing");
    msg = sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", replaced(iso, "isothermal", "adiabatic")),
                     prefix + "temperature");
    EXPECT_PRED2(contains, msg, "only an isothermal boundary");
    msg = sceneError(dir, replaced(sedovScene(), "outer: { type: slip_wall }", replaced(iso, "isothermal", "hot")),
                     prefix + "thermal");
    EXPECT_PRED2(contains, msg, "adiabatic, isothermal");
}

TEST(SceneErrors, SchemeSection)
{
    TempDir dir;
    const std::string scheme =
        replaced(sedovScene(), "  time: {", "  scheme: { picard_tolerance: 1e-10, picard_max_iterations: 50 }\n  time: {");
    sceneError(dir, replaced(scheme, "picard_tolerance: 1e-10", "picard_tolerance: 0"), "scheme.picard_tolerance");
    sceneError(dir, replaced(scheme, "picard_max_iterations: 50", "picard_max_iterations: 0"),
               "scheme.picard_max_iterations");
    sceneError(dir, replaced(scheme, "picard_max_iterations: 50", "picard_max_iterations: 2.5"),
               "scheme.picard_max_iterations");
    const std::string msg =
        sceneError(dir, replaced(scheme, "picard_tolerance: 1e-10", "picard_tolerence: 1e-10"), "scheme.picard_tolerence");
    EXPECT_PRED2(contains, msg, "did you mean 'scheme.picard_tolerance'");
    // scheme.integrator: midpoint or ars222, and ars222 only at order 2
    const std::string o2 = replaced(scheme, "picard_max_iterations: 50", "picard_max_iterations: 50, order: 2");
    EXPECT_PRED2(contains, sceneError(dir, replaced(o2, "order: 2", "order: 2, integrator: rk2"), "scheme.integrator"),
                 "midpoint, ars222");
    EXPECT_PRED2(contains, sceneError(dir, replaced(scheme, "picard_max_iterations: 50", "integrator: ars222"),
                                      "scheme.integrator"),
                 "needs scheme.order: 2");
    EXPECT_EQ(unilag::readScene(dir.write("scene.yaml", o2), {"scheme.integrator=ars222"}).integrator,
              unilag::Integrator::Ars222);
    EXPECT_EQ(unilag::readScene(dir.write("scene.yaml", o2), {}).integrator, unilag::Integrator::Midpoint);
}

TEST(SceneErrors, ParallelSection)
{
    TempDir dir;
    const unilag::Scene d = unilag::readScene(dir.write("scene.yaml", sedovScene()), {});
    EXPECT_EQ(d.balanceInterval, 50); // the defaults: measure every 50 steps, repartition above 1.1
    EXPECT_DOUBLE_EQ(d.imbalanceThreshold, 1.1);
    EXPECT_TRUE(d.repartition);
    EXPECT_EQ(d.partitioner, "multijagged");
    const std::string parallel = replaced(
        sedovScene(), "  time: {",
        "  parallel: { check_interval: 20, imbalance_threshold: 1.2, repartition: false, partitioner: sfc }\n  time: {");
    const unilag::Scene s = unilag::readScene(dir.write("scene.yaml", parallel), {});
    EXPECT_EQ(s.balanceInterval, 20);
    EXPECT_DOUBLE_EQ(s.imbalanceThreshold, 1.2);
    EXPECT_FALSE(s.repartition);
    EXPECT_EQ(s.partitioner, "sfc");
    EXPECT_EQ(unilag::readScene(dir.write("scene.yaml", parallel), {"parallel.partitioner=rcb"}).partitioner, "rcb");
    EXPECT_PRED2(contains, sceneError(dir, replaced(parallel, "partitioner: sfc", "partitioner: metis"),
                                      "parallel.partitioner"),
                 "multijagged, rcb, sfc");
    sceneError(dir, replaced(parallel, "check_interval: 20", "check_interval: -1"), "parallel.check_interval");
    sceneError(dir, replaced(parallel, "imbalance_threshold: 1.2", "imbalance_threshold: -1"),
               "parallel.imbalance_threshold");
    sceneError(dir, replaced(parallel, "repartition: false", "repartition: maybe"), "parallel.repartition");
    sceneError(dir, replaced(parallel, "check_interval: 20", "check_every: 20"), "parallel.check_every");
}

// Teuchos types a list by its numbers and reads every item as one: [true, 0.0] was [0, 0], silently.
TEST(SceneErrors, TrueFalseInAList)
{
    TempDir dir;
    auto error = [&](const std::string& list) {
        const std::string file = dir.write("scene.yaml", replaced(sedovScene(), "velocity: [0.0, 0.0]", list));
        return inputError([&] { unilag::readScene(file, {}); });
    };
    EXPECT_PRED2(contains, error("velocity: [true, 0.0]"), "scene.yaml: line 11: 'true' in a list");
    EXPECT_PRED2(contains, error("velocity: [0.0,\n        No]"), "scene.yaml: line 12: 'No' in a list");
}

// --set kept a scalar's quotes: 'output.directory=""' made a folder named "" instead of the file's empty string.
TEST(SceneErrors, QuotedOverrideIsTheStringInside)
{
    TempDir dir;
    const std::string msg = sceneError(dir, sedovScene(), "output.directory", {"output.directory=\"\""});
    EXPECT_PRED2(contains, msg, "must not be empty");
    const std::string file = dir.write("scene.yaml", sedovScene());
    EXPECT_EQ(unilag::readScene(file, {"output.directory='out dir'"}).outputDirectory, "out dir");
}

TEST(SceneErrors, ListWordsScanSkipsQuotesAndComments)
{
    using unilag::config::rejectWordsInLists;
    EXPECT_NO_THROW(rejectWordsInLists("f", "a: [\"true\", 'no']  # [yes]\nb: \"[false]\"\nc: [1, 2]\n"));
    EXPECT_NO_THROW(rejectWordsInLists("f", "title: Kidder's [shell]\nd: [notrue, yesno]\n"));
    EXPECT_THROW(rejectWordsInLists("f", "a:\n  - 1.0\n  - yes\n"), unilag::InputError);
    EXPECT_THROW(rejectWordsInLists("f", "a: [1, [2, FALSE]]\n"), unilag::InputError);
}
