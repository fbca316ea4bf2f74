#include "tube/GasRodRun.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <Kokkos_Core.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "io/XdmfWriter.hpp"
#include "solver/Summary.hpp"
#include "solver/TimeLoop.hpp"
#include "tube/GasRodCoupling.hpp"
#include "tube/GasRun.hpp"
#include "tube/PhysicalRod.hpp"
#include "tube/RankZero.hpp"
#include "tube/SerialLoop.hpp"

namespace unilag
{
namespace
{

using namespace tube;
constexpr double kPi = 3.14159265358979323846;
//! --check: mass and momentum are exchanged exactly (the fluxes and segment loads telescope): round-off only.
constexpr double kMassTolerance = 1e-12, kMomentumTolerance = 1e-12;

//! The tube scene's physical tube from gas.rod's material keys and gas.length (no fluid: the gas is coupled).
PhysicalTube physicalTube(const GasSettings& g)
{
    PhysicalTube p;
    p.length = g.setup.length;
    p.outerRadius = g.rod.outerRadius;
    p.innerRadius = g.rod.innerRadius;
    p.youngsModulus = g.rod.youngsModulus;
    p.poissonRatio = g.rod.poissonRatio;
    p.wallDensity = g.rod.density;
    p.shearCoefficient = g.rod.shearCoefficient;
    p.fluidDensity = 0.0;
    return p;
}

GasRodSetup couplingSetup(const GasSettings& g)
{
    GasRodSetup s;
    s.rod = rodConstants(physicalTube(g));
    s.rodSetup.segments = g.setup.cells;
    s.rodSetup.left = g.rod.left;
    s.rodSetup.right = g.rod.right;
    s.gas = g.setup;
    s.area = g.rod.area();
    s.outsidePressure = g.rod.outsidePressure;
    s.rodStepFactor = g.rod.rodStepFactor;
    return s;
}

/*! The initial transverse velocity a f(s): f = cos(2 pi s / L) on a free-free tube (no net momentum: it bends
 *  in its first free-free shape's sense), else sin(pi s / L) (0 at the held ends). The sections spin with their
 *  tangents (omega = e1 x a f'), so that no shear rate is imposed (as TubeTimeRun's perturbation). */
void perturb(TubeDynamics& rod, const GasSettings& g)
{
    const std::array<double, 3> a = g.rod.velocity;
    if (a[1] == 0.0 && a[2] == 0.0)
        return;
    const double L = g.setup.length;
    const bool freeFree = g.rod.left == EndCondition::Free && g.rod.right == EndCondition::Free;
    const double k = freeFree ? 2.0 * kPi / L : kPi / L;
    const auto shape = [&](double s) { return freeFree ? std::cos(k * s) : std::sin(k * s); };
    const auto slope = [&](double s) { return freeFree ? -k * std::sin(k * s) : k * std::cos(k * s); };
    rod.setVelocity([&](double s) { return std::array<double, 3>{0.0, a[1] * shape(s), a[2] * shape(s)}; });
    rod.setSpin([&](double s) { return std::array<double, 3>{0.0, -a[2] * slope(s), a[1] * slope(s)}; });
}

/*! The coupled tube as a TimeSystem: one loop step is one Strang step at the gas's CFL step. An explicit step has
 *  no retry: a non-finite gas or rod stops the run with a diagnosis before anything non-finite is written. The
 *  energy is summed after every step (its largest deviation is what --check bounds); the leading shock is sampled
 *  until it comes within five cells of the right end cap (after its reflection the level no longer marks it). */
class GasRodTimeSystem : public TimeSystem
{
  public:
    GasRodTimeSystem(GasRodCoupling& tube, const ExactReference& ref, double gamma, const std::string& dir)
        : tube_(tube), ref_(ref), writer_(MPI_COMM_SELF, dir, "tube", io::CellType::Polyline),
          energy0_(tube.totals().energy()), gamma_(gamma)
    {
        const int n = tube.gas().cells();
        std::vector<long long> segments;
        for (int j = 0; j < n; ++j)
            segments.insert(segments.end(), {j, j + 1});
        writer_.setTopology(n + 1, n, segments);
        sampling_ = ref.shock;
    }
    double prepareStep(double, long) override { return tube_.stableStep(); }
    void beginAttempts() override {}
    bool attemptStep(double, double dt, int, int& iterations) override
    {
        iterations = 0;
        tube_.step(dt);
        return tube_.gas().finite() && tube_.rod().finite();
    }
    std::string failure(double t, double dt, int) override
    {
        return "the free tube's state (gas or rod) is not finite after the step from t = " + jsonNumber(t) +
               " with dt = " + jsonNumber(dt) + ": lower gas.cfl or gas.rod.rod_step_factor";
    }
    void acceptStep(double t, double dt, int) override
    {
        maxEnergyChange = std::max(maxEnergyChange, std::abs(tube_.totals().energy() / energy0_ - 1.0));
        if (!sampling_)
            return;
        const double x = tube_.gas().shockPosition(ref_.shockLevel);
        const double edge = tube_.gas().cells() * tube_.gas().spacing() - 5.0 * tube_.gas().spacing();
        if (x >= edge)
            sampling_ = false; // it reaches the end cap: stop for good
        else if (x >= 0.0)
        {
            shockTime.push_back(t + dt);
            shockPosition.push_back(x);
        }
    }
    std::string collapse(double t, double dt, long step) override
    {
        return "the stable step fell to " + jsonNumber(dt) + " at t = " + jsonNumber(t) + " (step " +
               std::to_string(step) + ")";
    }
    void write(int index, double t) override;
    std::vector<double> totals() override
    {
        const GasRodTotals s = tube_.totals();
        return {s.mass, s.momentum[0], s.momentum[1], s.momentum[2], s.energy()};
    }

    std::vector<double> shockTime, shockPosition;
    double maxEnergyChange = 0.0; //!< max |E/E0 - 1| over the steps

  private:
    GasRodCoupling& tube_;
    ExactReference ref_;
    io::XdmfWriter writer_;
    double energy0_, gamma_;
    bool sampling_ = false;
};

/*! The rod's nodes as the polyline's points; per cell the gas (v relative to the tube, Mach |v| / a) and the
 *  radius sqrt(A / pi); per node the rod's velocity. */
void GasRodTimeSystem::write(int index, double t)
{
    const GasFields f = tube_.gas().fields();
    const RodFields r = tube_.rod().fields();
    std::vector<double> mach(f.rho.size()), radius(f.rho.size());
    for (std::size_t i = 0; i < mach.size(); ++i)
    {
        mach[i] = std::abs(f.u[i]) / std::sqrt(gamma_ * f.p[i] / f.rho[i]);
        radius[i] = std::sqrt(f.area[i] / kPi);
    }
    writer_.writeStep(index, t, r.position,
                      {{"density", 1, f.rho.data()},
                       {"pressure", 1, f.p.data()},
                       {"velocity", 1, f.u.data()},
                       {"mach", 1, mach.data()},
                       {"area", 1, f.area.data()},
                       {"radius", 1, radius.data()}},
                      {{"rod_velocity", 3, r.velocity.data()}});
}

struct RodFigures
{
    ExactReference ref;
    double shockTime = NAN, shockPosition = NAN, shockSpeed = NAN;
    double maxEnergyChange = 0.0, wall = 0.0;
    double momentumScale = 0.0, momentumChange = 0.0; //!< |P1 - P0| / scale
    double maxStretch = 0.0, maxTransverse = 0.0;     //!< max |Gamma| - 1, max distance of a node from the x axis
    GasRodTotals final;
};

std::string vectorJson(double x, double y, double z)
{
    return "[" + jsonNumber(x) + ", " + jsonNumber(y) + ", " + jsonNumber(z) + "]";
}

double relative(double a, double b)
{
    return a != 0.0 ? (b - a) / std::abs(a) : 0.0;
}

void writeRodSection(Summary& s, const GasSettings& g, const GasRodSetup& c, const RodFigures& f)
{
    s.object("rod", {{"left", "\"" + std::string(endName(g.rod.left)) + "\""},
                     {"right", "\"" + std::string(endName(g.rod.right)) + "\""},
                     {"extension_stiffness_EA", jsonNumber(c.rod.extension)},
                     {"shear_stiffness_kGA", jsonNumber(c.rod.shear)},
                     {"bending_stiffness_EI", jsonNumber(c.rod.bending)},
                     {"wall_mass_per_length", jsonNumber(c.rod.wallMass)},
                     {"gas_area", jsonNumber(c.area)},
                     {"axial_wave_speed", jsonNumber(std::sqrt(c.rod.extension / c.rod.wallMass))},
                     {"outside_pressure", jsonNumber(c.outsidePressure)},
                     {"rod_step_factor", jsonNumber(c.rodStepFactor)}});
    s.object("energy_final_parts", {{"rod", jsonNumber(f.final.rodEnergy)},
                                    {"gas_kinetic", jsonNumber(f.final.gasKinetic)},
                                    {"gas_internal", jsonNumber(f.final.gasInternal)},
                                    {"outside", jsonNumber(f.final.outside)}});
    s.number("max_stretch", f.maxStretch).number("max_transverse_displacement", f.maxTransverse);
}

void writeSummary(const TubeScene& scene, const LoopResult& loop, const GasRodSetup& c, const RodFigures& f,
                  const std::string& file)
{
    const GasSettings& g = scene.gas;
    const int threads = Kokkos::DefaultExecutionSpace().concurrency();
    Summary s = runSummary(scene.file, scene.name, loop, 3, g.setup.cells, g.setup.cells + 1, 1, threads);
    s.text("solver", "tube gas + free rod")
        .text("model", "ideal gas in a free Cosserat rod, momentum exchanged exactly (docs/tube-gas-rod.md)");
    s.object("ends", {{"left", "\"wall\""}, {"right", "\"wall\""}});
    s.number("gamma", g.setup.gamma).number("cfl", g.setup.cfl);
    writeRodSection(s, g, c, f);
    const auto &a = loop.initialTotals, &b = loop.finalTotals;
    if (a.size() == 5 && b.size() == 5)
    {
        s.number("mass_initial", a[0]).number("mass_final", b[0]).number("mass_relative_change", relative(a[0], b[0]));
        s.raw("momentum_initial", vectorJson(a[1], a[2], a[3])).raw("momentum_final", vectorJson(b[1], b[2], b[3]));
        s.number("momentum_scale", f.momentumScale).number("momentum_change_over_scale", f.momentumChange);
        s.number("energy_initial", a[4]).number("energy_final", b[4]).number("energy_relative_change", relative(a[4], b[4]));
    }
    s.number("energy_max_relative_change", f.maxEnergyChange).number("energy_bound", g.rod.energyBound);
    if (f.ref.shock)
    {
        s.number("shock_level_pressure", f.ref.shockLevel).number("shock_time", f.shockTime);
        s.number("shock_position", f.shockPosition).number("shock_speed", f.shockSpeed);
        s.number("shock_speed_rigid_exact", f.ref.shockSpeed);
        s.number("shock_mach", f.shockSpeed / std::sqrt(g.setup.gamma * g.right.p / g.right.rho));
    }
    s.number("wall_seconds", f.wall);
    s.write(file);
}

/*! mass to round-off; total momentum to round-off of sqrt(2 E0 (wall + gas mass)) (the momentum that energy
 *  would carry) when nothing holds the tube; the energy's largest deviation within gas.check.energy. */
int checkRun(const GasSettings& g, const LoopResult& loop, const RodFigures& f)
{
    std::vector<std::string> fails;
    const double dm = std::abs(relative(loop.initialTotals[0], loop.finalTotals[0]));
    if (!(dm <= kMassTolerance))
        fails.push_back("mass changed by " + jsonNumber(dm) + " (relative, > " + jsonNumber(kMassTolerance) + ")");
    const bool freeFree = g.rod.left == EndCondition::Free && g.rod.right == EndCondition::Free;
    if (freeFree && !(f.momentumChange <= kMomentumTolerance))
        fails.push_back("total momentum changed by " + jsonNumber(f.momentumChange) + " of its scale (> " +
                        jsonNumber(kMomentumTolerance) + ") with both rod ends free");
    if (!(f.maxEnergyChange <= g.rod.energyBound))
        fails.push_back("energy (rod + gas) deviated by " + jsonNumber(f.maxEnergyChange) +
                        " (relative) > gas.check.energy = " + jsonNumber(g.rod.energyBound) +
                        ": lower gas.cfl and gas.rod.rod_step_factor");
    return reportCheck(fails);
}

//! Conservation and shape figures of the run's end.
void finalFigures(const GasRodCoupling& tube, const GasRodSetup& c, const LoopResult& loop, RodFigures& f)
{
    f.final = tube.totals();
    const auto &a = loop.initialTotals, &b = loop.finalTotals;
    f.momentumScale = std::sqrt(2.0 * std::abs(a[4]) * (c.rod.wallMass * c.rod.length + a[0]));
    f.momentumChange = std::hypot(b[1] - a[1], b[2] - a[2], b[3] - a[3]) / f.momentumScale;
    for (const auto& m : tube.cellMetric())
        f.maxStretch = std::max(f.maxStretch, std::abs(std::sqrt(m[0]) - 1.0));
    const RodFields r = tube.rod().fields();
    for (std::size_t k = 0; 3 * k + 2 < r.position.size(); ++k)
        f.maxTransverse = std::max(f.maxTransverse, std::hypot(r.position[3 * k + 1], r.position[3 * k + 2]));
}

int runOnRankZero(const TubeScene& scene, bool check)
{
    const GasSettings& g = scene.gas;
    const GasRodSetup setup = couplingSetup(g);
    GasRodCoupling tube(setup);
    perturb(tube.rod(), g);
    tube.setGas([&](double s) { return g.initialState(s); });
    const std::string dir = scene.outputDirectory;
    std::filesystem::create_directories(dir);
    writeTubeScene(scene, dir + "/scene.yaml");
    RodFigures f;
    // the rigid tube's Riemann data place the level: the stiff wall changes the shock's strength only slightly
    if (g.riemann)
        f.ref = riemannShock(g.left, g.right, g.setup.gamma);
    GasRodTimeSystem system(tube, f.ref, g.setup.gamma, dir);
    const TimedLoop run = runTubeLoop(system, g.endTime, g.outputInterval, tube.stableStep(), scene.progress); // CFL step: stable
    const LoopResult& loop = run.loop;
    f.wall = run.wall;
    f.maxEnergyChange = system.maxEnergyChange;
    if (!system.shockTime.empty())
    {
        f.shockTime = system.shockTime.back();
        f.shockPosition = system.shockPosition.back();
        f.shockSpeed = secondHalfSpeed(system.shockTime, system.shockPosition, f.shockTime);
    }
    if (loop.failure.empty())
        finalFigures(tube, setup, loop, f);
    writeSummary(scene, loop, setup, f, dir + "/summary.json");
    if (!loop.failure.empty())
    {
        std::fprintf(stderr, "unilag: error: %s: %s\n", scene.file.c_str(), loop.failure.c_str());
        return ExitUnstable;
    }
    std::printf("unilag: %s: tube gas + free rod, %d segments, %ld steps in %.3g s, mass change %.3g, momentum "
                "change %.3g of its scale, max energy change %.3g, %s; output in %s\n",
                scene.name.c_str(), g.setup.cells, loop.state.steps, f.wall,
                relative(loop.initialTotals[0], loop.finalTotals[0]), f.momentumChange, f.maxEnergyChange,
                shockSpeedText(f.shockSpeed, f.ref.shockSpeed, "rigid exact").c_str(), dir.c_str());
    return check ? checkRun(g, loop, f) : ExitOk;
}

} // namespace

int runTubeGasRod(const TubeScene& scene, bool check, MPI_Comm comm)
{
    return tube::onRankZero(comm, [&] { return runOnRankZero(scene, check); });
}

} // namespace unilag
