#include "tube/GasRun.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <Kokkos_Core.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Mpi.hpp"
#include "io/XdmfWriter.hpp"
#include "solver/Summary.hpp"
#include "solver/TimeLoop.hpp"
#include "tube/GasRodRun.hpp"
#include "tube/GasWallCoupling.hpp"
#include "tube/RankZero.hpp"
#include "tube/SerialLoop.hpp"

namespace unilag
{
namespace
{

using namespace tube;
//! --check's bound on the relative change of mass and energy between two walls (the fluxes telescope).
constexpr double kConservationTolerance = 1e-10;

//! The Riemann problem the run is compared with: the scene's, or (a fixed_state inflow) the inflow against the gas.
struct ReferenceProblem
{
    GasPrimitive left, right;
    double position = 0.0;
};

ReferenceProblem referenceProblem(const GasSettings& g)
{
    if (g.riemann)
        return {g.left, g.right, g.position};
    return {g.setup.left.state, g.left, 0.0};
}

/*! The exact solution of the reference problem, when the scene has one. The shock is found where p falls
 *  through (p_R + p*) / 2. */
ExactReference exactReference(const GasSettings& g)
{
    if (!g.hasReference())
        return ExactReference{};
    const ReferenceProblem rp = referenceProblem(g);
    return riemannShock(rp.left, rp.right, g.setup.gamma);
}

/*! An expandable tube has no exact solution; a Riemann problem with p_L > p_R drives a right-running front, located
 *  where p falls through the rigid tube's level (p_R + p*)/2. The wall lowers the front's speed and raises p2 above
 *  the rigid p* (docs/tube-wall.md 4), so that level lies inside the front; the speed is only measured. */
ExactReference wallShockReference(const GasSettings& g)
{
    ExactReference r;
    if (!g.riemann || !(g.left.p > g.right.p * (1.0 + 1e-3)))
        return r;
    const double pStar = RiemannExact(g.left, g.right, g.setup.gamma).starPressure();
    r.shock = pStar > g.right.p * (1.0 + 1e-3);
    r.shockLevel = 0.5 * (g.right.p + pStar);
    return r;
}

/*! The rigid gas or the gas with its wall behind one face for the time loop. energy(): the gas's, or gas + wall +
 *  the wall's viscous loss so far (what the coupled step conserves). */
struct GasStepper
{
    std::unique_ptr<TubeGas> rigid;
    std::unique_ptr<GasWallCoupling> coupled;
    const TubeGas& gas() const { return coupled ? coupled->gas() : *rigid; }
    double stableStep() const { return coupled ? coupled->stableStep() : rigid->stableStep(); }
    void step(double dt) { coupled ? coupled->step(dt) : rigid->step(dt); }
    double energy() const
    {
        if (!coupled)
            return rigid->energy();
        const CoupledEnergy e = coupled->energy();
        return e.total() + e.wall.dissipated;
    }
    //! Per cell: the wall radius and speed (a rigid tube: (A/pi)^(1/2) and 0).
    WallFields wall(const GasFields& f) const
    {
        if (coupled)
            return coupled->wall().fields();
        WallFields w;
        for (const double a : f.area)
            w.radius.push_back(std::sqrt(a / 3.14159265358979323846));
        w.speed.assign(f.area.size(), 0.0);
        return w;
    }
};

/*! The gas as a TimeSystem: one loop step is one SSP-RK2 step at the CFL step (with a wall: one Strang step). An
 *  explicit step has no retry: a non-finite state stops the run with a diagnosis. Where there is a shock, its
 *  position is sampled after every step, for the speed measured from the run. */
class GasTimeSystem : public TimeSystem
{
  public:
    GasTimeSystem(GasStepper& gas, const ExactReference& ref, const std::string& dir)
        : gas_(gas), ref_(ref), writer_(MPI_COMM_SELF, dir, "tube", io::CellType::Polyline)
    {
        const int n = gas.gas().cells();
        std::vector<long long> segments;
        for (int j = 0; j < n; ++j)
            segments.insert(segments.end(), {j, j + 1});
        writer_.setTopology(n + 1, n, segments);
        coords_.assign(3 * std::size_t(n + 1), 0.0);
        for (int f = 0; f <= n; ++f)
            coords_[3 * std::size_t(f)] = f * gas.gas().spacing();
    }
    double prepareStep(double, long) override { return gas_.stableStep(); }
    void beginAttempts() override {}
    bool attemptStep(double, double dt, int, int& iterations) override
    {
        iterations = 0;
        gas_.step(dt);
        return gas_.gas().finite(); // a non-finite wall makes the gas's energy non-finite in the exchange
    }
    std::string failure(double t, double dt, int) override
    {
        return "the gas state is not finite after the step from t = " + jsonNumber(t) + " with dt = " +
               jsonNumber(dt) + ": lower gas.cfl, or an end state drives a vacuum";
    }
    void acceptStep(double t, double dt, int) override
    {
        if (!ref_.shock)
            return;
        const double x = gas_.gas().shockPosition(ref_.shockLevel);
        if (x >= 0.0)
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
    void write(int index, double t) override
    {
        const GasFields f = gas_.gas().fields();
        const WallFields w = gas_.wall(f);
        std::vector<double> mach(f.rho.size());
        for (std::size_t i = 0; i < mach.size(); ++i)
            mach[i] = std::abs(f.u[i]) / std::sqrt(gamma() * f.p[i] / f.rho[i]);
        writer_.writeStep(index, t, coords_,
                          {{"density", 1, f.rho.data()},
                           {"pressure", 1, f.p.data()},
                           {"velocity", 1, f.u.data()},
                           {"mach", 1, mach.data()},
                           {"area", 1, f.area.data()},
                           {"radius", 1, w.radius.data()},
                           {"wall_speed", 1, w.speed.data()}});
    }
    std::vector<double> totals() override { return {gas_.gas().mass(), gas_.energy()}; }
    void setGamma(double g) { gamma_ = g; }

    std::vector<double> shockTime, shockPosition;

  private:
    double gamma() const { return gamma_; }
    GasStepper& gas_;
    ExactReference ref_;
    io::XdmfWriter writer_;
    std::vector<double> coords_;
    double gamma_ = 1.4;
};

//! L1(density) = sum |rho - rho_exact| h against the exact solution at time t (waves not yet at the ends).
double densityL1(const GasSettings& g, const GasFields& f, double t)
{
    const ReferenceProblem rp = referenceProblem(g);
    const RiemannExact exact(rp.left, rp.right, g.setup.gamma);
    const double h = g.setup.length / g.setup.cells;
    double sum = 0.0;
    for (std::size_t i = 0; i < f.rho.size(); ++i)
        sum += std::abs(f.rho[i] - exact.sample((f.s[i] - rp.position) / t).rho) * h;
    return sum;
}

struct GasFigures
{
    ExactReference ref;
    double shockPosition = NAN, shockSpeed = NAN, l1 = NAN, wall = 0;
    CoupledEnergy energy;         //!< with a wall: the final energy parts
    double radiusLeftEnd = NAN;   //!< with a wall: the final radius of the first cell
    double pressureLeftEnd = NAN; //!< and its gas pressure
};

double relativeChange(const std::vector<double>& a, const std::vector<double>& b, std::size_t i)
{
    return a[i] != 0.0 ? (b[i] - a[i]) / std::abs(a[i]) : 0.0;
}

/*! The wall's coefficients, the final energy parts, the linear speeds of the right state (gas a1, compliant c1 on
 *  the quasi-static law, tube.md 3) and the measured front's speed in both units. */
void writeWallSummary(Summary& s, const GasSettings& g, const GasFigures& f)
{
    const WallCoefficients c = g.wall.coefficients();
    s.object("wall", {{"a", jsonNumber(c.a)},
                      {"b", jsonNumber(c.b)},
                      {"c", jsonNumber(c.c)},
                      {"as", jsonNumber(c.as)},
                      {"outside_pressure", jsonNumber(c.pExt)},
                      {"bulge_limit_pressure", jsonNumber(c.pExt + c.b / (2.0 * 3.14159265358979323846))}});
    s.object("energy_final_parts", {{"gas", jsonNumber(f.energy.gas)},
                                    {"wall_kinetic", jsonNumber(f.energy.wall.kinetic)},
                                    {"wall_elastic", jsonNumber(f.energy.wall.elastic)},
                                    {"wall_tension", jsonNumber(f.energy.wall.tension)},
                                    {"outside", jsonNumber(f.energy.wall.outside)},
                                    {"dissipated", jsonNumber(f.energy.wall.dissipated)}});
    const GasPrimitive& r = g.right;
    const double a1 = std::sqrt(g.setup.gamma * r.p / r.rho), c1 = compliantSpeed(c, r.rho, r.p, g.setup.gamma);
    s.number("sound_speed_right", a1).number("compliant_speed_right", c1);
    s.number("wall_rest_radius", c.restRadius).number("radius_final_left_end", f.radiusLeftEnd);
    s.number("pressure_final_left_end", f.pressureLeftEnd);
    if (f.ref.shock)
    {
        s.number("shock_level_pressure", f.ref.shockLevel);
        s.number("shock_position", f.shockPosition).number("shock_speed", f.shockSpeed);
        s.number("shock_mach_gas", f.shockSpeed / a1).number("shock_mach_compliant", f.shockSpeed / c1);
    }
}

void writeSummary(const TubeScene& scene, const LoopResult& loop, const GasFigures& f, int threads,
                  const std::string& file)
{
    const GasSettings& g = scene.gas;
    Summary s = runSummary(scene.file, scene.name, loop, 1, g.setup.cells, g.setup.cells + 1, 1, threads);
    if (g.wall.enabled)
        s.text("solver", "tube gas + wall").text("model", "ideal gas in an expandable tube (docs/tube-wall.md)");
    else
        s.text("solver", "tube gas").text("model", "ideal gas in a rigid tube (HLLC, MUSCL, SSP-RK2)");
    s.object("ends", {{"left", "\"" + std::string(gasEndName(g.setup.left.type)) + "\""},
                      {"right", "\"" + std::string(gasEndName(g.setup.right.type)) + "\""}});
    s.number("gamma", g.setup.gamma).number("cfl", g.setup.cfl);
    const auto &a = loop.initialTotals, &b = loop.finalTotals;
    if (a.size() == 2 && b.size() == 2)
    {
        s.number("mass_initial", a[0]).number("mass_final", b[0]).number("mass_relative_change", relativeChange(a, b, 0));
        s.number("energy_initial", a[1]).number("energy_final", b[1]);
        s.number("energy_relative_change", relativeChange(a, b, 1));
    }
    const bool exact = g.hasReference();
    s.text("exact_reference", !exact ? "none" : g.riemann ? "riemann problem" : "fixed_state inflow into the gas");
    if (g.wall.enabled)
        writeWallSummary(s, g, f);
    else if (f.ref.shock)
    {
        s.number("shock_level_pressure", f.ref.shockLevel);
        s.number("shock_position", f.shockPosition).number("shock_speed", f.shockSpeed);
        s.number("shock_speed_exact", f.ref.shockSpeed);
        s.number("shock_position_exact", referenceProblem(g).position + f.ref.shockSpeed * loop.state.t);
    }
    if (g.hasReference())
        s.number("l1_density", f.l1).number("l1_density_bound", g.l1Bound);
    s.number("wall_seconds", f.wall);
    s.write(file);
}

int checkRun(const GasSettings& g, const LoopResult& loop, const GasFigures& f)
{
    std::vector<std::string> fails;
    for (std::size_t i = 0; g.closed() && i < 2; ++i)
    {
        const double change = std::abs(relativeChange(loop.initialTotals, loop.finalTotals, i));
        if (!(change <= kConservationTolerance))
            fails.push_back(std::string(i == 0 ? "mass" : "energy") + " changed by " + jsonNumber(change) +
                            " (relative) between two walls (> " + jsonNumber(kConservationTolerance) + ")");
    }
    if (!std::isnan(g.l1Bound) && !(f.l1 <= g.l1Bound))
        fails.push_back("L1(density) against the exact solution " + jsonNumber(f.l1) + " > gas.check.l1_density = " +
                        jsonNumber(g.l1Bound));
    return reportCheck(fails);
}

int runOnRankZero(const TubeScene& scene, bool check)
{
    const GasSettings& g = scene.gas;
    GasStepper gas;
    if (g.wall.enabled)
    {
        const WallCoefficients w = g.wall.coefficients();
        gas.coupled = std::make_unique<GasWallCoupling>(g.setup, w);
        // the wall starts on the quasi-static law of the local pressure (readWall checked that it exists)
        gas.coupled->setState([&](double s) { return equilibriumRadius(w, g.initialState(s).p); },
                              [&](double s) { return g.initialState(s); });
    }
    else
    {
        gas.rigid = std::make_unique<TubeGas>(g.setup);
        gas.rigid->setState([&](double s) { return g.initialState(s); });
    }
    const std::string dir = scene.outputDirectory;
    std::filesystem::create_directories(dir);
    writeTubeScene(scene, dir + "/scene.yaml");
    GasFigures f;
    f.ref = g.wall.enabled ? wallShockReference(g) : exactReference(g);
    GasTimeSystem system(gas, f.ref, dir);
    system.setGamma(g.setup.gamma);
    const TimedLoop run = runTubeLoop(system, g.endTime, g.outputInterval, gas.stableStep(), scene.progress); // CFL step: stable
    const LoopResult& loop = run.loop;
    f.wall = run.wall;
    if (!system.shockPosition.empty())
    {
        f.shockPosition = system.shockPosition.back();
        f.shockSpeed = secondHalfSpeed(system.shockTime, system.shockPosition, loop.state.t);
    }
    if (g.hasReference())
        f.l1 = densityL1(g, gas.gas().fields(), loop.state.t);
    if (gas.coupled)
    {
        f.energy = gas.coupled->energy();
        f.radiusLeftEnd = gas.coupled->wall().fields().radius.front();
        f.pressureLeftEnd = gas.coupled->gas().fields().p.front();
    }
    writeSummary(scene, loop, f, Kokkos::DefaultExecutionSpace().concurrency(), dir + "/summary.json");
    if (!loop.failure.empty())
    {
        std::fprintf(stderr, "unilag: error: %s: %s\n", scene.file.c_str(), loop.failure.c_str());
        return ExitUnstable;
    }
    if (g.wall.enabled)
        std::printf("unilag: %s: tube gas + wall, %d cells, %ld steps in %.3g s, energy change %.3g, %s; output in "
                    "%s\n",
                    scene.name.c_str(), g.setup.cells, loop.state.steps, f.wall,
                    relativeChange(loop.initialTotals, loop.finalTotals, 1),
                    shockSpeedText(f.shockSpeed, std::nan("")).c_str(), dir.c_str());
    else
        std::printf("unilag: %s: tube gas, %d cells, %ld steps in %.3g s, L1(rho) %.4g, %s; output in %s\n",
                    scene.name.c_str(), g.setup.cells, loop.state.steps, f.wall, f.l1,
                    shockSpeedText(f.shockSpeed, f.ref.shockSpeed).c_str(), dir.c_str());
    return check ? checkRun(g, loop, f) : ExitOk;
}

} // namespace

namespace tube
{

/*! The exact solution's right wave is a shock when p* > p_R; its speed is u_R + a_R sqrt((g+1)/(2g) p* / p_R +
 *  (g-1)/(2g)) (Toro 4.59). */
ExactReference riemannShock(const GasPrimitive& left, const GasPrimitive& right, double gamma)
{
    ExactReference r;
    r.exists = true;
    const double pStar = RiemannExact(left, right, gamma).starPressure(), pR = right.p;
    r.shock = pStar > pR * (1.0 + 1e-3);
    if (!r.shock)
        return r;
    r.shockLevel = 0.5 * (pR + pStar);
    const double aR = std::sqrt(gamma * pR / right.rho);
    r.shockSpeed = right.u + aR * std::sqrt((gamma + 1) / (2 * gamma) * pStar / pR + (gamma - 1) / (2 * gamma));
    return r;
}

double secondHalfSpeed(const std::vector<double>& t, const std::vector<double>& x, double endTime)
{
    double n = 0, st = 0, sx = 0, stt = 0, stx = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= 0.5 * endTime)
        {
            n += 1;
            st += t[i];
            sx += x[i];
            stt += t[i] * t[i];
            stx += t[i] * x[i];
        }
    const double det = n * stt - st * st;
    return n >= 2 && det > 0 ? (n * stx - st * sx) / det : NAN;
}

} // namespace tube

int runTubeGas(const TubeScene& scene, bool check, MPI_Comm comm)
{
    if (scene.gas.rod.enabled)
        return runTubeGasRod(scene, check, comm);
    return tube::onRankZero(comm, [&] { return runOnRankZero(scene, check); });
}

} // namespace unilag
