#include "config/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

#include <Teuchos_YamlParameterListHelpers.hpp>

#include "unilag/EntropyFilter.hpp"
#include "unilag/Gpr.hpp"

#include "physics/Exact.hpp"
#include "physics/Expression.hpp"
#include "tube/RiemannExact.hpp"

namespace unilag
{
namespace
{

namespace fs = std::filesystem;
using config::ConfigNode;
using config::num;
using config::resolvePath;

//! Strain relaxation laws (docs/gpr-model.md 1.4) and the keys of strain_relaxation each one takes besides 'law'.
struct LawKeys
{
    std::string name;
    RelaxationLaw law;
    std::vector<std::string> keys;
};
const std::vector<LawKeys> kStrainLaws = {{"fluid", RelaxationLaw::Fluid, {}},
                                          {"viscous", RelaxationLaw::Viscous, {"viscosity"}},
                                          {"elastic", RelaxationLaw::Elastic, {}},
                                          {"constant", RelaxationLaw::Constant, {"tau1"}},
                                          {"plastic", RelaxationLaw::Plastic, {"tau10", "yield_stress", "exponent"}}};

/*! \brief strain_relaxation of a material (docs/gpr-model.md 1.4): the law, its parameters and tau1.
 *  Needs spec.rho0 and spec.shearSpeed. */
void readStrainRelaxation(ConfigNode& m, MaterialSpec& spec)
{
    const bool given = m.has("strain_relaxation");
    ConfigNode st = m.sub("strain_relaxation");
    std::vector<std::pair<std::string, RelaxationLaw>> laws;
    for (const auto& law : kStrainLaws)
        laws.emplace_back(law.name, law.law);
    spec.strainLaw = st.option("law", "fluid", laws, given);
    const std::string lawName = st.text("law", "fluid");
    // a parameter of another law is a mistake (e.g. viscosity with law plastic), not an unknown key
    for (const auto& law : kStrainLaws)
        for (const auto& k : law.keys)
            if (law.law != spec.strainLaw && st.has(k))
                st.fail(k, "belongs to law '" + law.name + "', not to law '" + lawName + "' (key '" + st.join("law") +
                               "')");

    if (spec.strainLaw == RelaxationLaw::Fluid)
    {
        if (spec.shearSpeed != 0.0)
            m.fail("shear_sound_speed",
                   "an ideal fluid (strain_relaxation law 'fluid', the default) has no shear stiffness, found " +
                       num(spec.shearSpeed) +
                       "; for the hydrodynamic limit of GPR give 'strain_relaxation: {law: constant, tau1: 1e-14}'");
        spec.tau1 = 0.0;
    }
    else if (!(spec.shearSpeed > 0.0))
        m.fail("shear_sound_speed",
               "strain relaxation law '" + lawName + "' needs a shear sound speed > 0, found " + num(spec.shearSpeed));

    if (spec.strainLaw == RelaxationLaw::Viscous)
    {
        spec.viscosity = st.positive("viscosity", 0.0, true);
        spec.tau1 = gpr::tau1FromViscosity(spec.viscosity, spec.rho0, spec.shearSpeed);
    }
    else if (spec.strainLaw == RelaxationLaw::Elastic)
        spec.tau1 = std::numeric_limits<double>::infinity();
    else if (spec.strainLaw == RelaxationLaw::Constant)
        spec.tau1 = st.positive("tau1", 0.0, true);
    else if (spec.strainLaw == RelaxationLaw::Plastic)
    {
        spec.tau10 = st.positive("tau10", 0.0, true);
        spec.yieldStress = st.positive("yield_stress", 0.0, true);
        spec.exponent = st.positive("exponent", 0.0, true);
    }
    st.rejectUnknown();
}

//! heat_conduction of a material (docs/gpr-model.md 1.2, 1.4): alpha, theta0 and one of kappa, tau2. Needs spec.rho0.
void readHeatConduction(ConfigNode& m, MaterialSpec& spec)
{
    spec.heatConduction = m.has("heat_conduction");
    ConfigNode h = m.sub("heat_conduction");
    if (!spec.heatConduction)
        return;
    spec.alpha = h.positive("alpha", 0.0, true);
    spec.theta0 = h.positive("reference_temperature", 0.0, true);
    const bool kappa = h.has("kappa"), tau2 = h.has("tau2");
    if (kappa == tau2)
        h.fail("kappa", std::string(kappa ? "given together with 'tau2'" : "missing") +
                            ": give exactly one of 'kappa' (Fourier conductivity) and 'tau2' (relaxation time)");
    if (kappa)
    {
        spec.kappa = h.positive("kappa", 0.0, true);
        spec.tau2 = gpr::tau2FromKappa(spec.kappa, spec.alpha, spec.theta0, spec.rho0);
    }
    else
    {
        spec.tau2 = h.positive("tau2", 0.0, true);
        spec.kappa = gpr::kappaFromTau2(spec.tau2, spec.alpha, spec.theta0, spec.rho0);
    }
    if (!(spec.tau2 > 0.0) || !std::isfinite(spec.tau2) || !(spec.kappa > 0.0) || !std::isfinite(spec.kappa))
        h.fail(kappa ? "kappa" : "tau2", "gives kappa = " + num(spec.kappa) + " and tau2 = " + num(spec.tau2) +
                                             ", both must be positive and finite");
    h.rejectUnknown();
}

//! One entry of 'materials'.
MaterialSpec readMaterial(ConfigNode& m)
{
    MaterialSpec spec;
    spec.eos = m.option<EosKind>("eos", "",
                                 {{"ideal_gas", EosKind::IdealGas},
                                  {"mie_gruneisen", EosKind::MieGruneisen},
                                  {"neo_hookean", EosKind::NeoHookean}},
                                 true);
    spec.cv = m.positive("cv", 1.0);
    if (spec.eos == EosKind::IdealGas)
    {
        spec.gamma = m.number("gamma", 1.4);
        if (!(spec.gamma > 1.0) || !std::isfinite(spec.gamma))
            m.fail("gamma", "an ideal gas needs gamma > 1, found " + num(spec.gamma));
        spec.rho0 = m.positive("rho0", 1.0);
    }
    else if (spec.eos == EosKind::MieGruneisen)
    {
        spec.rho0 = m.positive("rho0", 0.0, true);
        spec.c0 = m.positive("c0", 0.0, true);
        spec.Gamma0 = m.positive("Gamma0", 0.0, true);
        spec.s = m.nonNegative("s", 0.0);
    }
    else
    {
        spec.rho0 = m.positive("rho0", 0.0, true);
        spec.csh = m.positive("csh", 0.0, true);
    }
    spec.shearSpeed = m.nonNegative("shear_sound_speed", 0.0);
    readStrainRelaxation(m, spec);
    readHeatConduction(m, spec);
    m.rejectUnknown();
    return spec;
}

//! mesh: a .geo to mesh at a size (by gmsh, or as a lattice: mesher), or a .msh to read.
void readMeshSection(ConfigNode& root, Scene& s)
{
    ConfigNode mesh = root.sub("mesh", true);
    s.geometry = resolvePath(s.directory, mesh.text("geometry", ""));
    s.meshFile = resolvePath(s.directory, mesh.text("file", ""));
    if (s.geometry.empty() == s.meshFile.empty())
        mesh.fail("geometry", "give exactly one of 'geometry' (a .geo to mesh) and 'file' (a .msh to read)");
    if (!s.geometry.empty())
    {
        s.meshSize = mesh.positive("size", 0.0, true);
        s.meshLattice = mesh.choice("mesher", "gmsh", {"gmsh", "lattice"}) == "lattice";
        const std::string problem = config::inputFileProblem(s.geometry);
        if (!problem.empty())
            mesh.fail("geometry", problem + ": " + s.geometry);
    }
    else if (const std::string problem = config::inputFileProblem(s.meshFile); !problem.empty())
        mesh.fail("file", problem + ": " + s.meshFile);
    else if (mesh.has("mesher"))
        mesh.fail("mesher", "a .msh (mesh.file) is read as it is: mesher chooses how a mesh.geometry is meshed");
    mesh.rejectUnknown();
}

//! materials: at least one.
void readMaterials(ConfigNode& root, Scene& s)
{
    ConfigNode mats = root.sub("materials", true);
    for (const auto& name : mats.keys())
    {
        ConfigNode m = mats.sub(name);
        const MaterialSpec spec = readMaterial(m);
        s.materials[name] = spec;
    }
    if (s.materials.empty())
        root.fail("materials", "at least one material is required");
}

//! regions: the initial state of each gmsh physical group of cells.
void readRegions(ConfigNode& root, Scene& s)
{
    ConfigNode regions = root.sub("regions", true);
    for (const auto& name : regions.keys())
    {
        ConfigNode r = regions.sub(name);
        RegionSpec spec;
        spec.material = r.text("material", "", true);
        if (!s.materials.count(spec.material))
            r.fail("material", "unknown material '" + spec.material + "' (not in 'materials')");
        spec.density = r.expression("density", true);
        if (spec.density.isConstant() && !(spec.density.value > 0.0))
            r.fail("density", "must be positive, found " + num(spec.density.value));
        const bool p = r.has("pressure"), e = r.has("specific_internal_energy");
        if (p == e)
            r.fail("pressure", "give exactly one of 'pressure' and 'specific_internal_energy'");
        spec.hasPressure = p;
        if (p)
            spec.pressure = r.expression("pressure", true);
        else
            spec.internalEnergy = r.expression("specific_internal_energy", true);
        const Expr& th = p ? spec.pressure : spec.internalEnergy;
        if (th.isConstant() && !(th.value >= 0.0))
            r.fail(p ? "pressure" : "specific_internal_energy", "must be non-negative");
        if (r.has("velocity"))
        {
            auto v = r.expressions("velocity");
            spec.velocityComponents = int(v.size());
            for (std::size_t d = 0; d < v.size(); ++d)
                spec.velocity[d] = v[d];
        }
        spec.average = r.option<bool>("sampling", "centroid", {{"centroid", false}, {"average", true}});
        r.rejectUnknown();
        s.regions[name] = spec;
    }
    if (s.regions.empty())
        root.fail("regions", "at least one region (a gmsh physical group of cells) is required");
}

//! boundaries: the condition on each gmsh physical group of faces.
void readBoundaries(ConfigNode& root, Scene& s)
{
    ConfigNode bcs = root.sub("boundaries", true);
    for (const auto& name : bcs.keys())
    {
        ConfigNode b = bcs.sub(name);
        BoundarySpec spec;
        spec.type = b.option<BoundaryKind>("type", "",
                                           {{"free", BoundaryKind::Free},
                                            {"slip_wall", BoundaryKind::SlipWall},
                                            {"symmetry", BoundaryKind::Symmetry},
                                            {"velocity", BoundaryKind::Velocity},
                                            {"pressure", BoundaryKind::Pressure},
                                            {"traction", BoundaryKind::Traction}},
                                           true);
        const std::string typeName = b.text("type", "");
        // the value key of each type is its name; a value key of another type is a mistake
        for (const char* other : {"velocity", "pressure", "traction"})
            if (typeName != other && b.has(other))
                b.fail(other, std::string("only a boundary of type '") + other + "' takes '" + other +
                                  "', this one is '" + typeName + "'");
        if (spec.type == BoundaryKind::Velocity)
        {
            auto v = b.vector("velocity", true);
            for (std::size_t d = 0; d < v.size(); ++d)
                spec.velocity[d] = v[d];
        }
        if (spec.type == BoundaryKind::Pressure)
            spec.pressure = b.expression("pressure", true);
        if (spec.type == BoundaryKind::Traction)
        {
            auto v = b.vector("traction", true);
            if (v.size() < 2)
                b.fail("traction", "expected a traction vector of 2 or 3 numbers, found " + std::to_string(v.size()));
            for (std::size_t d = 0; d < v.size(); ++d)
                if (!std::isfinite(v[d]))
                    b.fail("traction", "must be finite");
            for (std::size_t d = 0; d < v.size(); ++d)
                spec.traction[d] = v[d];
        }
        spec.thermal = b.option<ThermalKind>(
            "thermal", "adiabatic", {{"adiabatic", ThermalKind::Adiabatic}, {"isothermal", ThermalKind::Isothermal}});
        if (spec.thermal == ThermalKind::Isothermal)
            spec.temperature = b.positive("temperature", 0.0, true);
        else if (b.has("temperature"))
            b.fail("temperature", "only an isothermal boundary takes a temperature (give 'thermal: isothermal')");
        b.rejectUnknown();
        s.boundaries[name] = spec;
    }
}

//! energy_deposit: a point release of energy.
void readDeposit(ConfigNode& root, Scene& s)
{
    ConfigNode dep = root.sub("energy_deposit");
    s.hasDeposit = true;
    auto pos = dep.vector("position", true);
    for (std::size_t d = 0; d < pos.size(); ++d)
        s.depositPosition[d] = pos[d];
    s.depositEnergy = dep.positive("energy", 0.0, true);
    dep.rejectUnknown();
}

//! time: end, CFL, step limits.
void readTime(ConfigNode& root, Scene& s)
{
    ConfigNode t = root.sub("time", true);
    s.endTime = t.positive("end", 0.0, true);
    s.cfl = t.positive("cfl", s.cfl);
    if (s.cfl > 1.0)
        t.fail("cfl", "must be in (0, 1], found " + num(s.cfl));
    s.maxVolumeChange = t.positive("max_volume_change", s.maxVolumeChange);
    s.initialTimeStep = t.nonNegative("initial_dt", 0.0);
    s.maxGrowth = t.positive("max_growth", s.maxGrowth);
    if (s.maxGrowth < 1.0)
        t.fail("max_growth", "must be >= 1");
    s.maxStepsGiven = t.has("max_steps");
    s.maxSteps = t.integer("max_steps", s.maxSteps, 1, 2000000000L);
    s.maxRetries = int(t.integer("max_retries", s.maxRetries, 0, 60));
    t.rejectUnknown();
}

//! scheme: order, limiter, what is reconstructed, Picard loop.
void readScheme(ConfigNode& root, Scene& s)
{
    ConfigNode sch = root.sub("scheme");
    s.picardTolerance = sch.positive("picard_tolerance", s.picardTolerance);
    s.picardMaxIterations = int(sch.integer("picard_max_iterations", s.picardMaxIterations, 1, 1000000));
    s.order = int(sch.integer("order", s.order, 1, 2));
    const std::vector<std::pair<std::string, Limiter>> limiters = {{"barth_jespersen", Limiter::BarthJespersen},
                                                                    {"vertex_based", Limiter::VertexBased},
                                                                    {"node_fit", Limiter::NodeFit},
                                                                    {"none", Limiter::None}};
    s.limiter = sch.option<Limiter>("limiter", "node_fit", limiters);
    if (sch.has("pressure_limiter"))
        s.pressureLimiter = sch.option<Limiter>("pressure_limiter", "", limiters);
    s.reconstruct = sch.option<Reconstructed>("reconstruct", "all",
                                              {{"all", Reconstructed::All}, {"velocity", Reconstructed::Velocity}});
    s.cornerLoad = sch.option<CornerLoad>("corner_load", "lumped",
                                          {{"lumped", CornerLoad::Lumped}, {"consistent", CornerLoad::Consistent}});
    s.integrator = sch.option<Integrator>("integrator", "midpoint",
                                          {{"midpoint", Integrator::Midpoint}, {"ars222", Integrator::Ars222}});
    s.entropyFilter = sch.nonNegative("entropy_filter", 0.0);
    if (s.entropyFilter > entropy_filter::kMaxCoefficient)
        sch.fail("entropy_filter", "must be in [0, " + num(entropy_filter::kMaxCoefficient) + "] (eps stays within " +
                                       "its neighbours' range up to there at CFL 1), found " + num(s.entropyFilter));
    if (s.pressureLimiter && s.reconstruct == Reconstructed::Velocity)
        sch.fail("pressure_limiter", "the pressure is not reconstructed with reconstruct: velocity");
    if (s.integrator == Integrator::Ars222 && s.order != 2)
        sch.fail("integrator", "ars222 is a second-order integrator: it needs scheme.order: 2");
    sch.rejectUnknown();
}

//! output: folder, interval.
void readOutput(ConfigNode& root, Scene& s)
{
    ConfigNode o = root.sub("output");
    s.outputDirectory = o.text("directory", "output/" + s.name);
    if (s.outputDirectory.empty())
        o.fail("directory", "must not be empty");
    s.outputSource = s.file + ": key 'output.directory'";
    s.outputInterval = o.nonNegative("interval", 0.0);
    s.checkpointInterval = o.nonNegative("checkpoint_interval", 0.0);
    refuseTooManyDumps(o, "checkpoint_interval", s.checkpointInterval, s.endTime, "checkpoints", "writes none");
    s.writeOutput = o.boolean("enabled", true);
    if (s.writeOutput)
        refuseTooManyDumps(o, "interval", s.outputInterval, s.endTime);
    o.rejectUnknown();
}

//! parallel: the load-balance checks and repartitioning.
void readParallel(ConfigNode& root, Scene& s)
{
    ConfigNode p = root.sub("parallel");
    s.balanceInterval = p.integer("check_interval", s.balanceInterval, 0, 2000000000L);
    s.earlyBalanceInterval = p.integer("early_check_interval", s.earlyChecks(), 1, 2000000000L);
    s.imbalanceThreshold = p.nonNegative("imbalance_threshold", s.imbalanceThreshold);
    s.repartition = p.boolean("repartition", s.repartition);
    s.rankSpeeds = p.boolean("rank_speeds", s.rankSpeeds);
    s.partitioner = p.option<std::string>("partitioner", s.partitioner,
                                          {{"multijagged", "multijagged"}, {"rcb", "rcb"}, {"sfc", "sfc"}});
    p.rejectUnknown();
}

//! exact.left / exact.right / exact.position of `solution: riemann`; every material an ideal gas of one gamma.
void readRiemann(ConfigNode& x, Scene& s)
{
    auto side = [&](const char* key)
    {
        ConfigNode w = x.sub(key);
        RiemannSide r;
        r.density = w.positive("density", 0.0, true);
        r.velocity = w.number("velocity", 0.0, true);
        r.pressure = w.positive("pressure", 0.0, true);
        w.rejectUnknown();
        return r;
    };
    s.riemannLeft = side("left");
    s.riemannRight = side("right");
    s.riemannPosition = x.number("position", 0.0);
    for (const auto& [name, m] : s.materials)
    {
        if (m.eos != EosKind::IdealGas || m.gamma != s.materials.begin()->second.gamma)
            x.fail("solution", "'riemann' is the exact solution of an ideal gas of one gamma; material '" + name +
                                   "' is not one");
        s.riemannGamma = m.gamma;
    }
    try
    {
        (void)riemannSolution(s);
    }
    catch (const std::runtime_error&)
    {
        x.fail("right", "the two states create a vacuum: no exact solution of this kind");
    }
}

//! exact: the exact solution and the --check bounds.
void readExact(ConfigNode& root, Scene& s)
{
    ConfigNode x = root.sub("exact");
    s.exactSolution =
        x.option<ExactSolution>("solution", "none",
                                {{"none", ExactSolution::None},
                                 {"sedov", ExactSolution::Sedov},
                                 {"stationary", ExactSolution::Stationary},
                                 {"riemann", ExactSolution::Riemann}});
    if (s.exactSolution == ExactSolution::Riemann)
        readRiemann(x, s);
    const bool sedov = s.exactSolution == ExactSolution::Sedov;
    s.exactTable = resolvePath(s.directory, x.text("table", "", sedov));
    if (const std::string problem = sedov ? config::inputFileProblem(s.exactTable) : ""; !problem.empty())
        x.fail("table", problem + ": " + s.exactTable);
    double tableEnd = 0.0;
    if (sedov)
    {
        try
        {
            tableEnd = RadialProfile(s.exactTable).lastPosition(); // read it now, not at the end of the run
        }
        catch (const InputError& e)
        {
            x.fail("table", e.what());
        }
    }
    s.exactShockRadius = x.positive("shock_radius", 1.0, sedov);
    // Beyond its last row the profile is that row's density: the ambient state only if the table passes the shock
    // (a truncated table gave an L1 of 0.995 on Sedov, silently).
    if (sedov && !(tableEnd > s.exactShockRadius))
        x.fail("table", s.exactTable + " ends at position " + std::to_string(tableEnd) +
                            ", not past the shock (shock_radius " + std::to_string(s.exactShockRadius) +
                            "): the profile beyond its last row is taken as that row's");
    s.exactTime = x.positive("time", 1.0);
    if (x.has("boundary_radius"))
    {
        ConfigNode radii = x.sub("boundary_radius");
        for (const auto& group : radii.keys())
            s.boundaryRadius[group] = radii.positive(group, 0.0, true);
        radii.rejectUnknown();
    }
    s.radiusTolerance = x.nonNegative("radius_tolerance", 0.0);
    s.maxL1Density = x.nonNegative("max_l1_density", 0.0);
    s.maxDensity = x.nonNegative("max_density", 0.0);
    s.shockRadiusTolerance = x.nonNegative("shock_radius_tolerance", 0.0);
    if (x.has("max_l2"))
    {
        if (s.exactSolution != ExactSolution::Stationary)
            x.fail("max_l2", "bounds L2 errors against a stationary solution: needs 'solution: stationary'");
        ConfigNode l2 = x.sub("max_l2");
        const char* keys[3] = {"specific_volume", "velocity", "energy"};
        for (int k = 0; k < 3; ++k)
            s.maxL2[k] = l2.nonNegative(keys[k], 0.0);
        l2.rejectUnknown();
    }
    x.rejectUnknown();
}

} // namespace

Scene readScene(const std::string& file, const std::vector<std::string>& overrides)
{
    const Teuchos::RCP<Teuchos::ParameterList> top = config::readYaml(file, "unilag", overrides);

    Scene s;
    s.file = file;
    s.directory = fs::path(file).parent_path().string();
    if (s.directory.empty())
        s.directory = ".";
    s.name = fs::path(file).stem().string();
    ConfigNode root(file, "", *top);
    s.name = root.text("title", s.name);

    readMeshSection(root, s);
    readMaterials(root, s);
    readRegions(root, s);
    readBoundaries(root, s);
    if (root.has("energy_deposit"))
        readDeposit(root, s);
    readTime(root, s);
    readScheme(root, s);
    readOutput(root, s);
    readParallel(root, s);
    if (root.has("exact"))
        readExact(root, s);
    root.rejectUnknown();
    s.resolved = *top;
    return s;
}

tube::RiemannExact riemannSolution(const Scene& scene)
{
    const RiemannSide &l = scene.riemannLeft, &r = scene.riemannRight;
    return tube::RiemannExact({l.density, l.velocity, l.pressure}, {r.density, r.velocity, r.pressure},
                              scene.riemannGamma);
}

void writeScene(const Scene& scene, const std::string& file)
{
    Teuchos::writeParameterListToYamlFile(scene.resolved, file);
}

} // namespace unilag
