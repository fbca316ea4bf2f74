#include "tube/TubeTimeRun.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>

#include <Kokkos_Core.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "io/OutputFolder.hpp"
#include "core/Mpi.hpp"
#include "io/XdmfWriter.hpp"
#include "solver/Summary.hpp"
#include "solver/TimeLoop.hpp"
#include "tube/GrowthFit.hpp"
#include "tube/LinearStability.hpp"
#include "tube/PhysicalRod.hpp"
#include "tube/TubeDynamics.hpp"
#include "tube/RankZero.hpp"
#include "tube/SerialLoop.hpp"

namespace unilag
{
namespace
{

using namespace tube;
constexpr double kPi = 3.14159265358979323846;
//! --check's bound on the energy change of a run with nothing pumped in (the splitting's error is bounded, O(dt^2)).
constexpr double kEnergyTolerance = 1e-5;

//! The linear model of the same tube, for u_cf and the linear growth rate at the run's speed.
LinearStability linearModel(const TubeScene& scene)
{
    return LinearStability(sceneDiscretisation(scene), scene.physical.massRatio());
}

//! The perturbation's shape along the tube, 1 at its largest: a tip-load deflection when the right end is free.
double perturbationShape(const TubeScene& scene, double s)
{
    const double x = s / scene.physical.length;
    return scene.right == EndCondition::Free ? 0.5 * x * x * (3.0 - x) : std::sin(kPi * x);
}

//! d(shape)/ds.
double perturbationSlope(const TubeScene& scene, double s)
{
    const double L = scene.physical.length, x = s / L;
    return scene.right == EndCondition::Free ? 1.5 * x * (2.0 - x) / L : kPi / L * std::cos(kPi * x);
}

/*! The initial perturbation: node velocities tipVelocity x shape(s), and the sections' spins that turn each with
 *  its tangent (omega = e1 x v', the tube being straight along e1), so that no shear rate is imposed: a velocity
 *  field without those spins would excite the stiff shear-rotation modes. */
void perturb(TubeDynamics& rod, const TubeScene& scene)
{
    const std::array<double, 3> a = scene.dynamics.tipVelocity;
    rod.setVelocity([&](double s) {
        const double w = perturbationShape(scene, s);
        return std::array<double, 3>{a[0] * w, a[1] * w, a[2] * w};
    });
    rod.setSpin([&](double s) {
        const double dw = perturbationSlope(scene, s);
        return std::array<double, 3>{0.0, -a[2] * dw, a[1] * dw};
    });
}

struct TipSeries
{
    std::vector<double> t, x, y, z, distance;
    void add(double time, const std::array<double, 3>& tip)
    {
        t.push_back(time);
        x.push_back(tip[0]);
        y.push_back(tip[1]);
        z.push_back(tip[2]);
        distance.push_back(std::hypot(tip[1], tip[2]));
    }
};

/*! The tube as a TimeSystem. A loop step is kSubsteps rod steps of the splitting with their half kicks merged
 *  (TubeDynamics::run: one load evaluation per rod step instead of two); the tip is sampled once per loop step,
 *  thousands of times per period of the lowest modes. An explicit step has no retry: a non-finite state stops the
 *  run with a diagnosis. */
class TubeTimeSystem : public TimeSystem
{
  public:
    TubeTimeSystem(TubeDynamics& rod, const DynamicsSettings& d, const std::string& dir)
        : rod_(rod), step_(loopStep(rod, d)), writer_(MPI_COMM_SELF, dir, "tube", io::CellType::Polyline)
    {
        std::vector<long long> segments;
        for (int j = 0; j + 1 < rod.nodes(); ++j)
            segments.insert(segments.end(), {j, j + 1});
        writer_.setTopology(rod.nodes(), rod.nodes() - 1, segments);
        tip.add(0.0, rod.tip());
    }
    static int substeps() { return kSubsteps; }
    double prepareStep(double, long) override { return step_; }
    double loopStep() const { return step_; }
    void beginAttempts() override {}
    bool attemptStep(double, double dt, int, int& iterations) override
    {
        iterations = 0;
        rod_.run(dt / kSubsteps, kSubsteps);
        return rod_.finite();
    }
    std::string failure(double t, double dt, int) override
    {
        return "the tube's state is not finite after the step from t = " + jsonNumber(t) + " s with dt = " +
               jsonNumber(dt) + " s (stable step " + jsonNumber(rod_.stableStep()) +
               " s): the amplitude grew beyond what the rod can carry, or step_factor is too large";
    }
    void acceptStep(double t, double dt, int) override { tip.add(t + dt, rod_.tip()); }
    std::string collapse(double t, double dt, long step) override
    {
        return "the stable step fell to " + jsonNumber(dt) + " s at t = " + jsonNumber(t) + " s (step " +
               std::to_string(step) + ")";
    }
    void write(int index, double t) override
    {
        const RodFields f = rod_.fields();
        writer_.writeStep(index, t, f.position, {},
                          {{"velocity", 3, f.velocity.data()},
                           {"curvature", 1, f.curvature.data()},
                           {"fluid_velocity", 1, f.fluidVelocity.data()},
                           {"pressure", 1, f.pressure.data()},
                           {"area", 1, f.area.data()}});
    }
    std::vector<double> totals() override
    {
        const auto p = rod_.linearMomentum(), l = rod_.angularMomentum();
        return {rod_.energy(), p[0], p[1], p[2], l[0], l[1], l[2]};
    }

    TipSeries tip;

  private:
    static constexpr int kSubsteps = 16;
    /*! One fixed step that divides the output interval: a symplectic splitting keeps its energy error bounded at a
     *  fixed step, and every change of step (an output time clipping it) shifts that error a little. */
    static double loopStep(const TubeDynamics& rod, const DynamicsSettings& d)
    {
        const double stable = kSubsteps * d.stepFactor * rod.stableStep();
        const double interval = d.outputInterval > 0.0 ? std::min(d.outputInterval, d.endTime) : d.endTime;
        return interval / std::ceil(interval / stable);
    }
    TubeDynamics& rod_;
    double step_;
    io::XdmfWriter writer_;
};

void writeTipCsv(const TipSeries& s, int maxRows, const std::string& file)
{
    std::ofstream out(file);
    out << "t,x,y,z,distance\n" << std::setprecision(10);
    const std::size_t n = s.t.size(), stride = std::max<std::size_t>(1, (n + maxRows - 1) / maxRows);
    for (std::size_t i = 0; i < n; i += stride)
        out << s.t[i] << ',' << s.x[i] << ',' << s.y[i] << ',' << s.z[i] << ',' << s.distance[i] << '\n';
    io::finishOutput(out, file);
}

//! Everything the summary reports beyond the loop's own entries.
struct RunFigures
{
    double flowSpeed = 0, uDimensionless = 0, uCritical = NAN, linearGrowth = NAN, linearFrequency = NAN;
    GrowthFit fit;
    double outOfPlane = 0, orthogonality = 0, wall = 0, nodeStepsPerSecond = 0;
    long rodSteps = 0;          //!< steps of the splitting (the loop's steps times its substeps)
    std::vector<Mode> spectrum; //!< the linear model's at the run's speed
    double finalAmplitude = 0;  //!< the tip's largest distance from the axis over the last tenth of the run
};

/*! The fit of the tip's motion: a planar run (one transverse component under a tenth of the other) on its signed
 *  displacement, a 3D run on its distance from the axis. */
GrowthFit fitTip(const TipSeries& tip, double from, double below, double& outOfPlane)
{
    double maxY = 0.0, maxZ = 0.0;
    for (std::size_t i = 0; i < tip.t.size(); ++i)
    {
        maxY = std::max(maxY, std::abs(tip.y[i]));
        maxZ = std::max(maxZ, std::abs(tip.z[i]));
    }
    outOfPlane = maxY + maxZ > 0.0 ? maxZ / std::max(maxY, maxZ) : 0.0;
    if (maxZ <= 0.1 * maxY)
        return fitGrowthSigned(tip.t, tip.y, from, below);
    if (maxY <= 0.1 * maxZ)
        return fitGrowthSigned(tip.t, tip.z, from, below);
    return fitGrowth(tip.t, tip.distance, from, below);
}

//! The tip's largest distance from the axis over the last tenth of the run (the limit cycle's amplitude, if any).
double lastTenthAmplitude(const TipSeries& tip)
{
    double amplitude = 0.0;
    const double from = 0.9 * tip.t.back();
    for (std::size_t i = 0; i < tip.t.size(); ++i)
        if (tip.t[i] >= from)
            amplitude = std::max(amplitude, tip.distance[i]);
    return amplitude;
}

/*! The linear mode the tip shows: the one nearest the fitted frequency (below u_cf the largest growth rate is an
 *  undamped axial mode's 0, not the bending modes' decay), or the fastest growing one without a frequency. */
void pickLinearMode(const std::vector<Mode>& spectrum, double fittedFrequency, RunFigures& f)
{
    double best = INFINITY;
    f.linearGrowth = -INFINITY;
    for (const Mode& m : spectrum)
    {
        const double distance = fittedFrequency > 0.0 ? std::abs(std::abs(m.frequency()) - fittedFrequency) : -m.growth();
        if (distance < best)
        {
            best = distance;
            f.linearGrowth = m.growth();
            f.linearFrequency = std::abs(m.frequency());
        }
    }
}

void writeSummary(const TubeScene& scene, const LoopResult& loop, const RunFigures& f, int nodes, int threads,
                  const std::string& file)
{
    const PhysicalTube& p = scene.physical;
    const double T = p.timeScale();
    Summary s = runSummary(scene.file, scene.name, loop, 3, nodes - 1, nodes, 1, threads);
    s.text("solver", "tube dynamics").text("model", "geometric rod (Cosserat, SE(3)), constant cross-section");
    s.object("ends", {{"left", "\"" + std::string(endName(scene.left)) + "\""},
                      {"right", "\"" + std::string(endName(scene.right)) + "\""}});
    s.integer("segments", scene.dynamics.segments).number("beta", p.massRatio());
    s.number("flow_speed", f.flowSpeed).number("u", f.uDimensionless).number("u_cf_linear", f.uCritical);
    s.number("u_over_u_cf", f.uDimensionless / f.uCritical);
    s.text("growth_rate_units", "1/s; *_dimensionless: per tau = t sqrt(EI/(M+m))/L^2 (tube.md 2.1)");
    s.number("growth_rate", f.fit.ok ? f.fit.growthRate : NAN);
    s.number("growth_rate_dimensionless", f.fit.ok ? f.fit.growthRate * T : NAN);
    s.number("linear_growth_rate_dimensionless", f.linearGrowth);
    s.number("frequency_dimensionless", f.fit.ok ? f.fit.frequency * T : NAN);
    s.number("linear_frequency_dimensionless", f.linearFrequency);
    s.integer("tip_peaks_fitted", f.fit.peaks).number("tip_amplitude", f.finalAmplitude);
    s.number("out_of_plane_ratio", f.outOfPlane);
    if (loop.initialTotals.size() == 7 && loop.finalTotals.size() == 7)
    {
        const double e0 = loop.initialTotals[0], e1 = loop.finalTotals[0];
        s.number("energy_initial", e0).number("energy_final", e1);
        s.number("energy_relative_change", e0 != 0.0 ? (e1 - e0) / std::abs(e0) : 0.0);
    }
    s.number("orthogonality_defect", f.orthogonality);
    s.integer("rod_steps", f.rodSteps).number("wall_seconds", f.wall).number("node_steps_per_second", f.nodeStepsPerSecond);
    s.write(file);
}

//! U from the scene: m/s, or a fraction of the linear u_cf; fills the linear figures at that speed.
void resolveFlow(const TubeScene& scene, RunFigures& f)
{
    const PhysicalTube& p = scene.physical;
    const LinearStability linear = linearModel(scene);
    const StabilityStudy& st = scene.stability;
    const Onset onset = linear.firstInstability({st.speedMax, st.speedStep, st.tolerance});
    f.uCritical = onset.found ? onset.speed : NAN;
    const DynamicsSettings& d = scene.dynamics;
    f.flowSpeed = std::isnan(d.criticalFraction) ? d.flowSpeed : d.criticalFraction * f.uCritical * p.velocityScale();
    f.uDimensionless = f.flowSpeed / p.velocityScale();
    if (!std::isfinite(f.flowSpeed))
        throw InputError(scene.file + ": key 'dynamics.flow.critical_fraction': the tube has no critical speed below "
                                      "stability.speed_max = " + jsonNumber(st.speedMax));
    f.spectrum = linear.spectrum(f.uDimensionless);
}

/*! --check of a time run: rotations orthogonal to round-off; with no flow nothing pumps energy in, so the energy
 *  must stay within the splitting's bounded error, relative to the initial energy (so only without gravity: a tube
 *  released straight under gravity starts with no energy and sags). */
int checkRun(const TubeScene& scene, const LoopResult& loop, const RunFigures& f)
{
    std::vector<std::string> fails;
    if (!(f.orthogonality <= 1e-12))
        fails.push_back("rotations drift from orthogonal: max |Lambda^T Lambda - I| = " + jsonNumber(f.orthogonality) +
                        " > 1e-12");
    const auto& g = scene.dynamics.gravity;
    const bool conservative = f.flowSpeed == 0.0 && g[0] == 0.0 && g[1] == 0.0 && g[2] == 0.0;
    const double e0 = loop.initialTotals[0], e1 = loop.finalTotals[0];
    const double change = e0 != 0.0 ? std::abs(e1 - e0) / std::abs(e0) : 0.0;
    if (conservative && !(change <= kEnergyTolerance))
        fails.push_back("energy changed by " + jsonNumber(change) + " (relative) with no flow and no gravity (> " +
                        jsonNumber(kEnergyTolerance) + "): lower dynamics.step_factor");
    return reportCheck(fails);
}

//! Rank 0's run; returns the exit code.
int runOnRankZero(const TubeScene& scene, bool check)
{
    const DynamicsSettings& d = scene.dynamics;
    RunFigures f;
    resolveFlow(scene, f);
    RodSetup setup;
    setup.segments = d.segments;
    setup.left = scene.left;
    setup.right = scene.right;
    setup.flowSpeed = f.flowSpeed;
    TubeDynamics rod(rodConstants(scene.physical, d.gravity), setup);
    perturb(rod, scene);
    const std::string dir = scene.outputDirectory;
    std::filesystem::create_directories(dir);
    writeTubeScene(scene, dir + "/scene.yaml");
    TubeTimeSystem system(rod, d, dir);
    TimeControl control;
    control.stepsCsv = std::getenv("UNILAG_TUBE_STEPS") ? dir + "/steps.csv" : "";
    const TimedLoop run = runTubeLoop(system, d.endTime, d.outputInterval, system.loopStep(), scene.progress, control); // fixed step
    const LoopResult& loop = run.loop;
    f.wall = run.wall;
    f.rodSteps = loop.state.steps * TubeTimeSystem::substeps();
    f.nodeStepsPerSecond = loop.wallSeconds > 0 ? double(f.rodSteps) * rod.nodes() / loop.wallSeconds : 0.0;
    f.fit = fitTip(system.tip, d.fitFrom * d.endTime, d.fitBelow * scene.physical.length, f.outOfPlane);
    f.finalAmplitude = lastTenthAmplitude(system.tip);
    pickLinearMode(f.spectrum, f.fit.ok ? f.fit.frequency * scene.physical.timeScale() : 0.0, f);
    f.orthogonality = rod.orthogonalityDefect();
    writeTipCsv(system.tip, d.tipRows, dir + "/tip.csv");
    writeSummary(scene, loop, f, rod.nodes(), Kokkos::DefaultExecutionSpace().concurrency(), dir + "/summary.json");
    if (!loop.failure.empty())
    {
        std::fprintf(stderr, "unilag: error: %s: %s\n", scene.file.c_str(), loop.failure.c_str());
        return ExitUnstable;
    }
    char growth[160];
    if (f.fit.ok)
        std::snprintf(growth, sizeof growth, "growth rate %.4g (linear %.4g) per tau",
                      f.fit.growthRate * scene.physical.timeScale(), f.linearGrowth);
    else // too few tip peaks in the window: a held tip, a run too short, or a tip above fit_below from the start
        std::snprintf(growth, sizeof growth, "no growth rate fitted: %d tip peaks below fit_below after fit_from "
                      "(linear %.4g per tau)", f.fit.peaks, f.linearGrowth);
    std::printf("unilag: %s: tube dynamics, %d segments, U = %.4g m/s (u/u_cf = %.4g), %ld steps in %.3g s, "
                "%s; output in %s\n", scene.name.c_str(), d.segments, f.flowSpeed, f.uDimensionless / f.uCritical,
                f.rodSteps, f.wall, growth, dir.c_str());
    if (!check)
        return ExitOk;
    return checkRun(scene, loop, f);
}

} // namespace

int runTubeDynamics(const TubeScene& scene, bool check, MPI_Comm comm)
{
    return tube::onRankZero(comm, [&] { return runOnRankZero(scene, check); });
}

} // namespace unilag
