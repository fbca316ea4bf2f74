#include "tube/ArteryRun.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <Kokkos_Core.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "io/OutputFolder.hpp"
#include "core/Mpi.hpp"
#include "io/XdmfWriter.hpp"
#include "solver/Summary.hpp"
#include "solver/TimeLoop.hpp"
#include "tube/RankZero.hpp"
#include "tube/SerialLoop.hpp"

namespace unilag
{
namespace
{

using namespace tube;
//! --check's bound on (V - V0 - V_in + V_out) / V0: the boundary records advance with the cells' RK weights
//! (docs/tube-artery.md, measured 4.6e-16 after 2000 steps).
constexpr double kVolumeTolerance = 1e-10;
constexpr int kProbeWidth = 6; //!< p and Q at inlet, middle, outlet

/*! The artery as a TimeSystem. One loop step is one probe sample interval (period / samples_per_cycle), which the
 *  artery covers with its own CFL steps (Artery::advanceTo), so that the probes fall on the same phase every cycle
 *  and the cycle-to-cycle change compares like with like. */
class ArteryTimeSystem : public TimeSystem
{
  public:
    ArteryTimeSystem(Artery& artery, double sampleInterval, const std::string& dir)
        : artery_(artery), sample_(sampleInterval), writer_(MPI_COMM_SELF, dir, "tube", io::CellType::Polyline)
    {
        std::vector<double> area, flow;
        artery.hostState(area, flow);
        cells_ = int(area.size());
        std::vector<long long> segments;
        for (int j = 0; j < cells_; ++j)
            segments.insert(segments.end(), {j, j + 1});
        writer_.setTopology(cells_ + 1, cells_, segments);
        coords_.assign(3 * std::size_t(cells_ + 1), 0.0);
        for (int f = 0; f <= cells_; ++f)
            coords_[3 * std::size_t(f)] = f * artery.dx();
    }
    double prepareStep(double, long) override { return sample_; }
    void beginAttempts() override {}
    bool attemptStep(double t, double dt, int, int& iterations) override
    {
        iterations = 0;
        artery_.advanceTo(t + dt);
        return std::isfinite(artery_.volume()) && std::isfinite(artery_.windkesselPressure());
    }
    std::string failure(double t, double dt, int) override
    {
        return "the artery's state is not finite after [" + jsonNumber(t) + ", " + jsonNumber(t + dt) +
               "] s: lower artery.cfl, or the inlet flow empties the vessel";
    }
    void acceptStep(double t, double dt, int) override
    {
        time.push_back(t + dt);
        const std::vector<double> p = probes();
        samples.insert(samples.end(), p.begin(), p.end());
    }
    std::string collapse(double t, double dt, long step) override
    {
        return "the step fell to " + jsonNumber(dt) + " s at t = " + jsonNumber(t) + " s (step " +
               std::to_string(step) + ")";
    }
    void write(int index, double t) override
    {
        std::vector<double> area, flow;
        artery_.hostState(area, flow);
        std::vector<double> pressure = artery_.wallPressure(area), velocity(area.size());
        for (std::size_t i = 0; i < area.size(); ++i)
            velocity[i] = flow[i] / area[i];
        writer_.writeStep(index, t, coords_,
                          {{"area", 1, area.data()},
                           {"flow", 1, flow.data()},
                           {"pressure", 1, pressure.data()},
                           {"velocity", 1, velocity.data()}});
    }
    std::vector<double> totals() override
    {
        return {artery_.volume(), artery_.volumeIn(), artery_.volumeOut()};
    }

    std::vector<double> time, samples; //!< samples: kProbeWidth per time

  private:
    /*! p and Q on the inlet face, mid-vessel (mean of the two middle cells) and the outlet face. Mid-vessel p is
     *  the wall law's, tension included; the end faces' is Phi(A_b), the pressure their boundary laws impose. */
    std::vector<double> probes() const
    {
        std::vector<double> A, Q;
        artery_.hostState(A, Q);
        double Ain, Qin, Aout, Qout;
        artery_.boundaryStates(Ain, Qin, Aout, Qout);
        const int m = int(A.size()) / 2;
        const bool odd = A.size() % 2;
        const double Amid = odd ? A[m] : 0.5 * (A[m - 1] + A[m]);
        const double Qmid = odd ? Q[m] : 0.5 * (Q[m - 1] + Q[m]);
        const double pT = odd ? artery_.tensionPressure(A, m)
                              : 0.5 * (artery_.tensionPressure(A, m - 1) + artery_.tensionPressure(A, m));
        return {artery_.pressure(Ain), Qin, artery_.pressure(Amid) + pT, Qmid, artery_.pressure(Aout), Qout};
    }
    Artery& artery_;
    double sample_;
    int cells_ = 0;
    io::XdmfWriter writer_;
    std::vector<double> coords_;
};

struct ArteryFigures
{
    int cyclesRun = 0, periodicAfter = -1; //!< the first cycle within the tolerance of the one before (-1: none)
    double changeP = NAN, changeQ = NAN;   //!< of the last cycle
    std::array<double, 3> meanPressure{NAN, NAN, NAN}; //!< inlet, middle, outlet over the last cycle
    double volumeDefect = NAN, wall = 0;
};

/*! Cycle-to-cycle change of cycle m against m - 1: max |x_m - x_{m-1}| / max |x_m| over probes and samples, of the
 *  pressures (parity 0) or flows (parity 1). */
double cycleChange(const std::vector<double>& s, int perCycle, int m, int parity)
{
    double diff = 0, scale = 0;
    const std::size_t now = std::size_t(m) * perCycle * kProbeWidth, before = now - std::size_t(perCycle) * kProbeWidth;
    for (std::size_t k = 0; k < std::size_t(perCycle) * kProbeWidth; ++k)
        if (int(k % 2) == parity)
        {
            diff = std::max(diff, std::abs(s[now + k] - s[before + k]));
            scale = std::max(scale, std::abs(s[now + k]));
        }
    return scale > 0 ? diff / scale : 0.0;
}

void measureCycles(const ArterySettings& a, const ArteryTimeSystem& sys, ArteryFigures& f)
{
    const int perCycle = a.samplesPerCycle;
    f.cyclesRun = int(sys.time.size()) / perCycle;
    for (int m = 1; m < f.cyclesRun; ++m)
    {
        f.changeP = cycleChange(sys.samples, perCycle, m, 0);
        f.changeQ = cycleChange(sys.samples, perCycle, m, 1);
        const bool periodic = f.changeP < a.periodicTolerance && f.changeQ < a.periodicTolerance;
        if (periodic && f.periodicAfter < 0)
            f.periodicAfter = m + 1;
        if (!periodic)
            f.periodicAfter = -1;
    }
    if (f.cyclesRun < 1)
        return;
    const std::size_t last = std::size_t(f.cyclesRun - 1) * perCycle;
    for (int j = 0; j < 3; ++j)
    {
        double sum = 0;
        for (int k = 0; k < perCycle; ++k)
            sum += sys.samples[(last + k) * kProbeWidth + 2 * j];
        f.meanPressure[j] = sum / perCycle;
    }
}

void writeWaveforms(const ArteryTimeSystem& sys, const std::string& file)
{
    std::ofstream out(file);
    out << "t_s,p_in_Pa,Q_in_m3s,p_mid_Pa,Q_mid_m3s,p_out_Pa,Q_out_m3s\n" << std::setprecision(10);
    for (std::size_t i = 0; i < sys.time.size(); ++i)
    {
        out << sys.time[i];
        for (int j = 0; j < kProbeWidth; ++j)
            out << ',' << sys.samples[i * kProbeWidth + j];
        out << '\n';
    }
    io::finishOutput(out, file);
}

void writeSummary(const TubeScene& scene, const Artery& artery, const LoopResult& loop, const ArteryFigures& f,
                  int threads, const std::string& file)
{
    const ArterySettings& a = scene.artery;
    const int cells = a.config.cells;
    Summary s = runSummary(scene.file, scene.name, loop, 1, cells, cells + 1, 1, threads);
    s.text("solver", "tube artery").text("model", "1D artery, stretchable walls (docs/tube-artery.md)");
    s.text("inlet", a.inlet.standIn ? "stand_in" : "harmonics");
    s.text("outlet", a.config.outlet == artery::OutletKind::Windkessel ? "rcr" : "reflection");
    s.number("period", a.inlet.period).number("wave_speed", moensKortewegSpeed(a.config));
    s.number("tension_N", a.config.tension).number("tension_coefficient_Pa", tensionCoefficient(a.config));
    s.integer("cycles", f.cyclesRun).integer("cycles_to_periodicity", f.periodicAfter);
    s.number("periodic_tolerance", a.periodicTolerance);
    s.number("last_cycle_change_pressure", f.changeP).number("last_cycle_change_flow", f.changeQ);
    s.object("mean_pressure_Pa", {{"inlet", jsonNumber(f.meanPressure[0])},
                                  {"middle", jsonNumber(f.meanPressure[1])},
                                  {"outlet", jsonNumber(f.meanPressure[2])}});
    s.number("volume_balance_defect", f.volumeDefect).integer("cell_steps", artery.cellSteps());
    s.number("wall_seconds", f.wall);
    s.write(file);
}

int checkRun(const ArterySettings& a, const ArteryFigures& f)
{
    std::vector<std::string> fails;
    if (!(std::abs(f.volumeDefect) <= kVolumeTolerance))
        fails.push_back("volume balance (V - V0 - V_in + V_out) / V0 = " + jsonNumber(f.volumeDefect) + " (> " +
                        jsonNumber(kVolumeTolerance) + ")");
    if (f.periodicAfter < 0)
        fails.push_back("not periodic after " + std::to_string(f.cyclesRun) + " cycles: the last change is " +
                        jsonNumber(f.changeP) + " (pressure), " + jsonNumber(f.changeQ) +
                        " (flow) >= artery.periodic_tolerance = " + jsonNumber(a.periodicTolerance) +
                        ": run more artery.cycles");
    return reportCheck(fails);
}

int runOnRankZero(const TubeScene& scene, bool check)
{
    const ArterySettings& a = scene.artery;
    ArteryConfig cfg = a.config;
    const InletWaveform inlet = a.inlet;
    cfg.inletFlux = [inlet](double t) { return inlet(t); };
    Artery artery(cfg);
    const std::string dir = scene.outputDirectory;
    std::filesystem::create_directories(dir);
    writeTubeScene(scene, dir + "/scene.yaml");
    const double sample = a.inlet.period / a.samplesPerCycle;
    ArteryTimeSystem system(artery, sample, dir);
    const TimedLoop run = runTubeLoop(system, a.cycles * a.inlet.period,
                                      a.dumpsPerCycle > 0 ? a.inlet.period / a.dumpsPerCycle : 0.0, sample, false);
    const LoopResult& loop = run.loop;
    ArteryFigures f;
    f.wall = run.wall;
    const auto &t0 = loop.initialTotals, &t1 = loop.finalTotals;
    f.volumeDefect = (t1[0] - t0[0] - (t1[1] - t0[1]) + (t1[2] - t0[2])) / t0[0];
    measureCycles(a, system, f);
    writeWaveforms(system, dir + "/waveforms.csv");
    writeSummary(scene, artery, loop, f, Kokkos::DefaultExecutionSpace().concurrency(), dir + "/summary.json");
    if (!loop.failure.empty())
    {
        std::fprintf(stderr, "unilag: error: %s: %s\n", scene.file.c_str(), loop.failure.c_str());
        return ExitUnstable;
    }
    // summary.json says -1 (no cycle within the tolerance of the one before); the line says it in words
    const std::string periodic =
        f.periodicAfter < 0 ? "not periodic yet" : "periodic after " + std::to_string(f.periodicAfter);
    std::printf("unilag: %s: artery, %d cells, %d cycles in %.3g s, %s, mean p in/mid/out %.5g %.5g %.5g Pa; "
                "output in %s\n",
                scene.name.c_str(), cfg.cells, f.cyclesRun, f.wall, periodic.c_str(), f.meanPressure[0],
                f.meanPressure[1], f.meanPressure[2], dir.c_str());
    return check ? checkRun(a, f) : ExitOk;
}

} // namespace

int runTubeArtery(const TubeScene& scene, bool check, MPI_Comm comm)
{
    return tube::onRankZero(comm, [&] { return runOnRankZero(scene, check); });
}

} // namespace unilag
