#include "tube/GasScene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "config/Walker.hpp"
#include "tube/TubeScene.hpp"

namespace unilag::tube
{
namespace
{

using config::ConfigNode;
using config::num;
using config::refuseTooManyDumps;
constexpr double pi_ = 3.14159265358979323846;

//! A state {density, velocity, pressure}: density and pressure positive (an ideal gas has no vacuum state).
GasPrimitive readState(ConfigNode& parent, const std::string& key)
{
    ConfigNode s = parent.sub(key, true);
    GasPrimitive w;
    w.rho = s.positive("density", 1.0, true);
    w.u = s.number("velocity", 0.0);
    w.p = s.positive("pressure", 1.0, true);
    s.rejectUnknown();
    return w;
}

/*! One end: {type: wall | transmissive | fixed_state | pressure_outlet | subsonic_inflow} and the state that type
 *  needs (fixed_state: density, velocity, pressure; pressure_outlet: pressure; subsonic_inflow: the reservoir's
 *  density and pressure). */
GasEnd readEnd(ConfigNode& ends, const std::string& key)
{
    ConfigNode e = ends.sub(key);
    GasEnd end;
    end.type = e.option<GasEndType>("type", "wall",
                                    {{"wall", GasEndType::Wall},
                                     {"transmissive", GasEndType::Transmissive},
                                     {"fixed_state", GasEndType::FixedState},
                                     {"pressure_outlet", GasEndType::PressureOutlet},
                                     {"subsonic_inflow", GasEndType::SubsonicInflow}});
    const bool needsDensity = end.type == GasEndType::FixedState || end.type == GasEndType::SubsonicInflow;
    const bool needsPressure = needsDensity || end.type == GasEndType::PressureOutlet;
    for (const char* k : {"density", "velocity", "pressure"})
    {
        const bool wanted = std::string(k) == "density"    ? needsDensity
                            : std::string(k) == "velocity" ? end.type == GasEndType::FixedState
                                                           : needsPressure;
        if (e.has(k) && !wanted)
            e.fail(k, std::string("a ") + gasEndName(end.type) + " end takes no " + k);
    }
    if (needsDensity)
        end.state.rho = e.positive("density", 1.0, true);
    if (end.type == GasEndType::FixedState)
        end.state.u = e.number("velocity", 0.0, true);
    if (needsPressure)
        end.state.p = e.positive("pressure", 1.0, true);
    e.rejectUnknown();
    return end;
}

//! initial: a Riemann problem (position, left, right) or a uniform state (uniform), not both.
void readInitial(ConfigNode& g, GasSettings& s)
{
    ConfigNode i = g.sub("initial", true);
    if (i.has("uniform") && (i.has("left") || i.has("right") || i.has("position")))
        i.fail("uniform", "give a uniform state or left/right states about a position, not both");
    if (i.has("uniform"))
    {
        s.left = s.right = readState(i, "uniform");
        i.rejectUnknown();
        return;
    }
    s.riemann = true;
    s.position = i.number("position", 0.5 * s.setup.length, true);
    if (!(s.position > 0.0 && s.position < s.setup.length))
        i.fail("position", "must be inside the tube (0, " + num(s.setup.length) + "), found " + num(s.position));
    s.left = readState(i, "left");
    s.right = readState(i, "right");
    try
    {
        RiemannExact(s.left, s.right, s.setup.gamma); // the exact reference must exist (no vacuum)
    }
    catch (const std::runtime_error& e)
    {
        i.fail("right", std::string("the left and right states create a vacuum: ") + e.what());
    }
    i.rejectUnknown();
}

/*! wall: the material (young_modulus, thickness, density, rest_radius required; poisson in [0, 0.5], viscosity,
 *  axial_tension >= 0), outside_pressure (required) and ramp (the width of the initial blend, >= 0). The wall
 *  starts on the quasi-static law of the initial pressure, which must exist (below the bulge limit). */
GasWallSettings readWall(ConfigNode& g, const GasSettings& s)
{
    ConfigNode w = g.sub("wall");
    GasWallSettings wall;
    wall.enabled = true;
    WallMaterial& m = wall.material;
    m.youngModulus = w.positive("young_modulus", m.youngModulus, true);
    m.poisson = w.number("poisson", m.poisson);
    if (!(m.poisson >= 0.0 && m.poisson <= 0.5))
        w.fail("poisson", "must be in [0, 0.5], found " + num(m.poisson));
    m.thickness = w.positive("thickness", m.thickness, true);
    m.density = w.positive("density", m.density, true);
    m.restRadius = w.positive("rest_radius", m.restRadius, true);
    m.viscosity = w.nonNegative("viscosity", m.viscosity);
    m.axialTension = w.nonNegative("axial_tension", m.axialTension);
    wall.outsidePressure = w.number("outside_pressure", 0.0, true);
    if (!(wall.outsidePressure >= 0.0) || !std::isfinite(wall.outsidePressure))
        w.fail("outside_pressure", "must be a non-negative number, found " + num(wall.outsidePressure));
    wall.ramp = w.nonNegative("ramp", wall.ramp);
    if (wall.ramp > 0.0 && !s.riemann)
        w.fail("ramp", "blends the left and right initial states: a uniform gas has none");
    const WallCoefficients c = wall.coefficients();
    const double limit = c.b / (2.0 * pi_) + wall.outsidePressure;
    for (const double p : {s.left.p, s.right.p})
        if (!(p < limit))
            w.fail("young_modulus", "the initial pressure " + num(p) +
                                        " is past the wall's bulge limit p_ext + b/(2 pi) = " + num(limit) +
                                        ": no equilibrium radius (stiffen the wall or lower the pressure)");
    w.rejectUnknown();
    return wall;
}

/*! perturbation.velocity: the transverse velocity's amplitude [0, vy, vz] (the tube lies along x; an axial part
 *  would only translate or stretch it). */
void readRodPerturbation(ConfigNode& r, GasRodSettings& rod)
{
    ConfigNode p = r.sub("perturbation");
    if (p.has("velocity"))
    {
        const std::vector<double> v = p.vector("velocity", true);
        for (std::size_t i = 0; i < v.size(); ++i)
            rod.velocity[i] = v[i];
        for (const double x : rod.velocity)
            if (!std::isfinite(x))
                p.fail("velocity", "must be finite numbers");
        if (rod.velocity[0] != 0.0)
            p.fail("velocity", "is transverse: [0, vy, vz] (the tube lies along x), found vx = " + num(rod.velocity[0]));
    }
    p.rejectUnknown();
}

/*! rod: the tube's material with the tube scene's keys (outer_radius, inner_radius or wall_thickness,
 *  youngs_modulus, density required; poisson_ratio in (-1, 0.5], shear_coefficient in (0, 1]), its ends (free,
 *  clamped, pinned), outside_pressure (>= 0), perturbation and rod_step_factor in (0, 1]. The gas's ends must stay
 *  walls (the end caps move with the rod); gravity is not coupled to it (nor an expandable wall: readGas). */
GasRodSettings readRod(ConfigNode& g, const GasSettings& s)
{
    for (const auto& [key, end] : {std::pair{"left", s.setup.left}, std::pair{"right", s.setup.right}})
        if (end.type != GasEndType::Wall)
            g.fail(std::string("ends.") + key + ".type",
                   std::string("a free tube (gas.rod) closes its gas with end caps that move with it: both gas ends "
                               "must be walls, found ") + gasEndName(end.type));
    ConfigNode r = g.sub("rod");
    if (r.has("gravity"))
        r.fail("gravity", "the gas's weight is not coupled to the rod (GasRodCoupling): a free tube runs without gravity");
    GasRodSettings rod;
    rod.enabled = true;
    readTubeRadii(r, true, rod.outerRadius, rod.innerRadius);
    rod.youngsModulus = r.positive("youngs_modulus", 0.0, true);
    rod.density = r.positive("density", 0.0, true);
    rod.poissonRatio = r.number("poisson_ratio", rod.poissonRatio);
    if (!(rod.poissonRatio > -1.0 && rod.poissonRatio <= 0.5))
        r.fail("poisson_ratio", "must be in (-1, 0.5], found " + num(rod.poissonRatio));
    rod.shearCoefficient = r.number("shear_coefficient", rod.shearCoefficient);
    if (!(rod.shearCoefficient > 0.0 && rod.shearCoefficient <= 1.0))
        r.fail("shear_coefficient", "must be in (0, 1], found " + num(rod.shearCoefficient));
    ConfigNode e = r.sub("ends");
    const std::vector<std::pair<std::string, EndCondition>> names = {
        {"free", EndCondition::Free}, {"clamped", EndCondition::Clamped}, {"pinned", EndCondition::Pinned}};
    rod.left = e.option("left", "free", names);
    rod.right = e.option("right", "free", names);
    e.rejectUnknown();
    rod.outsidePressure = r.nonNegative("outside_pressure", rod.outsidePressure);
    readRodPerturbation(r, rod);
    rod.rodStepFactor = r.positive("rod_step_factor", rod.rodStepFactor);
    if (rod.rodStepFactor > 1.0)
        r.fail("rod_step_factor", "must be in (0, 1] (of the rod's stable step), found " + num(rod.rodStepFactor));
    r.rejectUnknown();
    return rod;
}

/*! check: l1_density (a rigid tube's Riemann problem or inflow only) and energy (a free tube's bound on the
 *  coupled integrator's energy error, max |E/E0 - 1|; mass and energy of the other runs are held to 1e-10). */
void readCheck(ConfigNode& g, GasSettings& s)
{
    ConfigNode c = g.sub("check");
    if (c.has("l1_density") && (s.wall.enabled || s.rod.enabled))
        c.fail("l1_density", std::string("an ") + (s.wall.enabled ? "expandable tube (gas.wall)" : "free tube (gas.rod)") +
                                 " has no exact solution to compare with");
    if (c.has("l1_density") && !s.hasReference())
        c.fail("l1_density", "only a Riemann problem (initial.left/right) or a uniform gas fed by a fixed_state left "
                             "end has an exact solution to compare with");
    if (c.has("l1_density"))
        s.l1Bound = c.positive("l1_density", 1.0);
    if (c.has("energy") && !s.rod.enabled)
        c.fail("energy", "bounds a free tube's (gas.rod) integrator error; the rigid and expandable tubes conserve "
                         "energy to 1e-10");
    s.rod.energyBound = c.positive("energy", s.rod.energyBound);
    c.rejectUnknown();
}

} // namespace

GasPrimitive GasSettings::initialState(double s) const
{
    if (!riemann)
        return left;
    if (!(wall.ramp > 0.0))
        return s < position ? left : right;
    const double wl = 0.5 * (1.0 - std::tanh((s - position) / wall.ramp)), wr = 1.0 - wl;
    return GasPrimitive{wl * left.rho + wr * right.rho, wl * left.u + wr * right.u, wl * left.p + wr * right.p};
}

const char* gasEndName(GasEndType type)
{
    switch (type)
    {
    case GasEndType::Wall:
        return "wall";
    case GasEndType::Transmissive:
        return "transmissive";
    case GasEndType::FixedState:
        return "fixed_state";
    case GasEndType::PressureOutlet:
        return "pressure_outlet";
    case GasEndType::SubsonicInflow:
        return "subsonic_inflow";
    }
    return "?";
}

GasSettings readGas(ConfigNode& g)
{
    GasSettings s;
    GasSetup& setup = s.setup;
    setup.length = g.positive("length", setup.length, true);
    setup.cells = int(g.integer("cells", setup.cells, 4, 10000000));
    setup.gamma = g.number("gamma", setup.gamma);
    if (!(setup.gamma > 1.0 && setup.gamma <= 5.0))
        g.fail("gamma", "must be in (1, 5], found " + num(setup.gamma));
    setup.cfl = g.positive("cfl", setup.cfl);
    if (setup.cfl > 1.0)
        g.fail("cfl", "must be at most 1 (SSP-RK2 with MUSCL), found " + num(setup.cfl));
    setup.limiter = g.option<GasLimiter>("limiter", "van_leer",
                                         {{"van_leer", GasLimiter::VanLeer}, {"minmod", GasLimiter::MinMod}});
    ConfigNode ends = g.sub("ends");
    setup.left = readEnd(ends, "left");
    setup.right = readEnd(ends, "right");
    ends.rejectUnknown();
    readInitial(g, s);
    s.endTime = g.positive("end_time", s.endTime, true);
    s.outputInterval = g.nonNegative("output_interval", s.outputInterval);
    refuseTooManyDumps(g, "output_interval", s.outputInterval, s.endTime);
    if (g.has("wall") && g.has("rod"))
        g.fail("rod", "a free tube (gas.rod) has a rigid radius: give gas.wall or gas.rod, not both");
    if (g.has("wall"))
        s.wall = readWall(g, s);
    if (g.has("rod"))
        s.rod = readRod(g, s);
    readCheck(g, s);
    g.rejectUnknown();
    return s;
}

} // namespace unilag::tube
