#include "tube/TubeScene.hpp"

#include <cmath>
#include <filesystem>

#include <Teuchos_YamlParameterListHelpers.hpp>

#include "config/Walker.hpp"
#include "tube/LinearStability.hpp"

namespace unilag::tube
{
namespace
{

namespace fs = std::filesystem;
using config::ConfigNode;
using config::num;

constexpr double kPi = 3.14159265358979323846;

//! A positive number if the key is given, NaN if not (so that the caller can tell which keys are missing).
double positiveIfGiven(ConfigNode& node, const std::string& key)
{
    return node.has(key) ? node.positive(key, 0.0, true) : std::nan("");
}

/*! tube.area_change (K of A = A0 - K |Omega|^2 / 2, m^2, >= 0) and tube.area_change_pressure (what loads it,
 *  docs/tube-model.md 7.3): only the geometric model has an area change. */
void readAreaChange(ConfigNode& t, TubeScene& s)
{
    const bool geometric = s.model == TubeModel::Geometric;
    for (const char* key : {"area_change", "area_change_pressure"})
        if (t.has(key) && !geometric)
            t.fail(key, "only the geometric model has an area change; set tube.model: geometric");
    if (!geometric)
        return;
    s.physical.areaChange = t.nonNegative("area_change", 0.0);
    s.physical.areaPressure = t.option<AreaPressure>(
        "area_change_pressure", "dynamic", {{"dynamic", AreaPressure::Dynamic}, {"static", AreaPressure::Static}});
}

//! tube: the model and, optionally, the physical tube (then every physical key is required).
void readTube(ConfigNode& root, TubeScene& s)
{
    ConfigNode t = root.sub("tube");
    s.model =
        t.option<TubeModel>("model", "euler_bernoulli",
                            {{"euler_bernoulli", TubeModel::EulerBernoulli}, {"geometric", TubeModel::Geometric}});
    PhysicalTube& p = s.physical;
    p.length = positiveIfGiven(t, "length");
    readTubeRadii(t, false, p.outerRadius, p.innerRadius);
    p.youngsModulus = positiveIfGiven(t, "youngs_modulus");
    p.wallDensity = positiveIfGiven(t, "density");
    p.poissonRatio = t.number("poisson_ratio", 0.3);
    if (!(p.poissonRatio > -1.0 && p.poissonRatio <= 0.5))
        t.fail("poisson_ratio", "must be in (-1, 0.5], found " + num(p.poissonRatio));
    p.shearCoefficient = t.number("shear_coefficient", 0.5);
    if (!(p.shearCoefficient > 0.0 && p.shearCoefficient <= 1.0))
        t.fail("shear_coefficient", "must be in (0, 1], found " + num(p.shearCoefficient));
    readAreaChange(t, s);

    ConfigNode f = root.sub("fluid");
    p.fluidDensity = positiveIfGiven(f, "density");
    f.rejectUnknown();

    const std::vector<std::pair<std::string, double>> required = {{"length", p.length},
                                                                  {"outer_radius", p.outerRadius},
                                                                  {"inner_radius", p.innerRadius},
                                                                  {"youngs_modulus", p.youngsModulus},
                                                                  {"density", p.wallDensity}};
    bool anyGiven = !std::isnan(p.fluidDensity);
    for (const auto& [key, v] : required)
        anyGiven = anyGiven || !std::isnan(v);
    s.hasPhysical = anyGiven;
    if (s.model == TubeModel::Geometric && !anyGiven)
        t.missing("length", "(the geometric model needs the physical tube: length, outer_radius, inner_radius or "
                            "wall_thickness, youngs_modulus, density and fluid.density)");
    if (anyGiven)
    {
        for (const auto& [key, v] : required)
            if (std::isnan(v))
                t.missing(key, "(a physical tube needs length, outer_radius, inner_radius or wall_thickness, "
                               "youngs_modulus, density and fluid.density)");
        if (std::isnan(p.fluidDensity))
            f.missing("density", "(a physical tube needs the fluid's density)");
    }
    t.rejectUnknown();
}

//! ends: left (where the fluid enters) and right, each clamped, pinned or free.
void readEnds(ConfigNode& root, TubeScene& s)
{
    ConfigNode e = root.sub("ends");
    const std::vector<std::pair<std::string, EndCondition>> names = {
        {"clamped", EndCondition::Clamped}, {"pinned", EndCondition::Pinned}, {"free", EndCondition::Free}};
    s.left = e.option("left", "clamped", names);
    s.right = e.option("right", "free", names);
    if (s.left == EndCondition::Free && s.right == EndCondition::Free)
        e.fail("right", "a tube free at both ends has rigid-body modes; hold at least one end");
    // The fluid leaves at a free end in this model (Paidoussis' discharging tube); entering there (an aspirating
    // tube) it predicts flutter at vanishing flow speed, an artefact of the model (Paidoussis, JFS 13, 1999).
    if (s.left == EndCondition::Free)
        e.fail("left", "the fluid enters at the left end, and a free inlet (an aspirating tube) is outside the "
                       "model: it would flutter at vanishing flow speed; free the right end (the outlet) instead");
    if (s.left != EndCondition::Clamped && s.right != EndCondition::Clamped &&
        (s.left == EndCondition::Free || s.right == EndCondition::Free))
        e.fail("right", "a pinned-free tube has a rigid-body mode; clamp one end");
    e.rejectUnknown();
}

//! stability: the mass ratios and the numerical parameters of the study.
void readStability(ConfigNode& root, TubeScene& s)
{
    ConfigNode st = root.sub("stability");
    StabilityStudy& study = s.stability;
    if (st.has("beta") && s.model == TubeModel::Geometric)
        st.fail("beta", "the geometric model takes its mass ratio (and its other ratios) from the physical tube; "
                        "remove stability.beta");
    if (st.has("beta") || !s.hasPhysical)
        study.beta = st.numbers("beta", true);
    else
        study.beta = {s.physical.massRatio()};
    for (double b : study.beta)
        if (!(b >= 0.0 && b < 1.0))
            st.fail("beta", "mass ratio must be in [0, 1), found " + num(b));
    study.elements = int(st.integer("elements", study.elements, 2, 1000));
    study.modes = int(st.integer("modes", study.modes, 0, 10000));
    study.speedMax = st.positive("speed_max", study.speedMax);
    study.speedStep = st.positive("speed_step", study.speedStep);
    if (study.speedStep >= study.speedMax)
        st.fail("speed_step", "must be less than speed_max (" + num(study.speedMax) + ")");
    // 1e-320 scanned nothing and reported no instability; a bisection to 1e-320 never ended
    if (study.speedMax / study.speedStep > 1e7)
        st.fail("speed_step", num(study.speedStep) + " makes " + num(std::floor(study.speedMax / study.speedStep)) +
                                  " scan points to speed_max " + num(study.speedMax) + ": at most 1e7");
    study.tolerance = st.positive("tolerance", study.tolerance);
    if (!(study.tolerance >= 1e-12 * study.speedMax && study.tolerance < study.speedStep))
        st.fail("tolerance", "must be in [1e-12 speed_max, speed_step) = [" + num(1e-12 * study.speedMax) + ", " +
                                 num(study.speedStep) + "), found " + num(study.tolerance));
    study.locusModes = int(st.integer("locus_modes", study.locusModes, 1, 50));
    study.locusPoints = int(st.integer("locus_points", study.locusPoints, 2, 100000));
    study.locusSpeedFactor = st.positive("locus_speed_factor", study.locusSpeedFactor);
    // more modes than the elements have dofs kept them all, silently; the loci's extra columns were nan
    const int dofs = freeDofCount(sceneDiscretisation(s)), kept = study.modes > 0 ? study.modes : dofs;
    if (study.modes > dofs)
        st.fail("modes", "at most the " + std::to_string(dofs) + " degrees of freedom of " +
                             std::to_string(study.elements) + " elements with these ends, found " +
                             std::to_string(study.modes) + " (0 keeps them all)");
    if (study.locusModes > kept)
        st.fail("locus_modes", "at most the study's " + std::to_string(kept) + " modes, found " +
                                   std::to_string(study.locusModes));
    st.rejectUnknown();
}

//! dynamics: a time run of the physical tube (its stiffnesses and masses come from tube: and fluid:).
void readDynamicsSection(ConfigNode& root, TubeScene& s)
{
    if (!root.has("dynamics"))
        return;
    ConfigNode d = root.sub("dynamics");
    if (!s.hasPhysical)
        d.fail("end_time", "a time run needs the physical tube (tube.length, radii, youngs_modulus, density and "
                           "fluid.density)");
    if (s.physical.areaChange > 0.0)
        d.fail("end_time", "the nonlinear rod has a constant cross-section; set tube.area_change to 0 for a time run "
                           "(the area change is in the linear study, docs/tube-model.md 7)");
    s.dynamics = readDynamics(d);
    s.hasDynamics = true;
}

/*! gas: or artery: (one of them): a module with its own vessel, ends and time settings, so that the rod's sections
 *  (tube, fluid, ends, stability, dynamics) do not apply and are refused rather than silently ignored. */
void readFlowModule(ConfigNode& root, TubeScene& s)
{
    const char* module = root.has("gas") ? "gas" : "artery";
    if (root.has("gas") && root.has("artery"))
        root.fail("artery", "a scene runs the gas or the artery, not both");
    for (const char* key : {"tube", "fluid", "ends", "stability", "dynamics"})
        if (root.has(key))
            root.fail(key, std::string("a ") + module + " scene takes its vessel and ends from `" + module + ":`");
    ConfigNode m = root.sub(module, true);
    if (root.has("gas"))
    {
        s.gas = readGas(m);
        s.hasGas = true;
    }
    else
    {
        s.artery = readArtery(m);
        s.hasArtery = true;
    }
}

void readOutput(ConfigNode& root, TubeScene& s)
{
    ConfigNode o = root.sub("output");
    s.outputDirectory = o.text("directory", "output/" + s.name);
    if (s.outputDirectory.empty())
        o.fail("directory", "must not be empty");
    s.plot = o.boolean("plot", true);
    o.rejectUnknown();
}

} // namespace

void readTubeRadii(ConfigNode& node, bool required, double& outer, double& inner)
{
    auto read = [&](const std::string& key)
    { return required ? node.positive(key, 0.0, true) : positiveIfGiven(node, key); };
    outer = read("outer_radius");
    if (node.has("inner_radius") && node.has("wall_thickness"))
        node.fail("wall_thickness", "give inner_radius or wall_thickness, not both");
    if (node.has("wall_thickness"))
    {
        const double h = node.positive("wall_thickness", 0.0, true);
        if (h >= outer)
            node.fail("wall_thickness", "must be less than outer_radius (" + num(outer) + "), found " + num(h));
        inner = outer - h;
        return;
    }
    inner = read("inner_radius");
    if (inner >= outer)
        node.fail("inner_radius", "must be less than outer_radius (" + num(outer) + "), found " + num(inner));
}

const char* endName(EndCondition e)
{
    switch (e)
    {
    case EndCondition::Clamped:
        return "clamped";
    case EndCondition::Pinned:
        return "pinned";
    case EndCondition::Free:
        return "free";
    }
    return "?";
}

double PhysicalTube::wallArea() const
{
    return kPi * (outerRadius * outerRadius - innerRadius * innerRadius);
}
double PhysicalTube::secondMoment() const
{
    return kPi * (std::pow(outerRadius, 4) - std::pow(innerRadius, 4)) / 4.0;
}
double PhysicalTube::radiusOfGyration() const
{
    return std::sqrt(secondMoment() / wallArea());
}
double PhysicalTube::slenderness() const
{
    return length / radiusOfGyration();
}
double PhysicalTube::shearModulus() const
{
    return youngsModulus / (2.0 * (1.0 + poissonRatio));
}
double PhysicalTube::bendingStiffness() const
{
    return youngsModulus * secondMoment();
}
double PhysicalTube::fluidMassPerLength() const
{
    return fluidDensity * kPi * innerRadius * innerRadius;
}
double PhysicalTube::wallMassPerLength() const
{
    return wallDensity * kPi * (outerRadius * outerRadius - innerRadius * innerRadius);
}
double PhysicalTube::massRatio() const
{
    return fluidMassPerLength() / (fluidMassPerLength() + wallMassPerLength());
}
double PhysicalTube::velocityScale() const
{
    return std::sqrt(bendingStiffness() / fluidMassPerLength()) / length;
}
double PhysicalTube::timeScale() const
{
    return length * length * std::sqrt((fluidMassPerLength() + wallMassPerLength()) / bendingStiffness());
}

GeometricParameters PhysicalTube::geometricParameters() const
{
    const double l2 = length * length, ei = bendingStiffness();
    GeometricParameters g;
    g.shear = ei / (shearCoefficient * shearModulus() * wallArea() * l2);
    g.extension = ei / (youngsModulus * wallArea() * l2);
    g.rotary = wallDensity * secondMoment() / ((fluidMassPerLength() + wallMassPerLength()) * l2);
    g.areaChange = areaChange / (kPi * innerRadius * innerRadius * l2);
    g.pressure = areaPressure;
    return g;
}

bool isTubeScene(const std::string& file)
{
    try
    {
        const auto top = config::readYaml(file, "unilag", {});
        return top->isSublist("tube") || top->isSublist("gas") || top->isSublist("artery");
    }
    catch (const InputError&)
    {
        return false;
    }
}

TubeScene readTubeScene(const std::string& file, const std::vector<std::string>& overrides)
{
    const Teuchos::RCP<Teuchos::ParameterList> top = config::readYaml(file, "unilag", overrides);
    TubeScene s;
    s.file = file;
    s.name = fs::path(file).stem().string();
    ConfigNode root(file, "", *top);
    s.name = root.text("title", s.name);
    if (root.has("gas") || root.has("artery"))
        readFlowModule(root, s);
    else
    {
        readTube(root, s);
        readEnds(root, s);
        readStability(root, s);
        readDynamicsSection(root, s);
    }
    readOutput(root, s);
    root.rejectUnknown();
    s.resolved = std::make_shared<Teuchos::ParameterList>(*top);
    return s;
}

void writeTubeScene(const TubeScene& scene, const std::string& file)
{
    Teuchos::writeParameterListToYamlFile(*scene.resolved, file);
}

} // namespace unilag::tube
