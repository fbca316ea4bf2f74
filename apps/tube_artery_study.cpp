// The common carotid artery (Boileau et al. 2015 benchmark 2, parameters as openBF encodes them; tube.md 4.3)
// run to a periodic state with src/tube/Artery. docs/tube-artery.md; apps/tube_artery_plot.py draws the CSVs.
//
//   tube_artery_study [--cells N] [--out DIR] [--prefill] [--throughput N] [--no-serial] [--tension F]
//   (Kokkos flags pass)
//
// The benchmark's inlet waveform (openBF's CCA inlet file) is not available here: the inlet flow is a stated
// stand-in, Q(t) = Qd + Qs g(t; 0.15 s, 0.06 s) + Qn g(t; 0.42 s, 0.04 s), g a unit Gaussian bump repeated with
// period T = 1.1 s (images at -T, 0, T make it smooth to round-off), Qs = 14, Qn = 3 ml/s and Qd chosen for a
// mean of 6 ml/s (systolic peak ~17.8 ml/s, a dicrotic bump, no backflow).
// Periodicity: pressure and flow at inlet, middle and outlet, sampled 200 times a cycle; the cycle-to-cycle change,
// max |x_m - x_{m-1}| / max |x_m| over probes and samples, must fall below 1e-3 for both.
// --prefill starts the Windkessel at p_C = mean Q R2 (openBF starts from rest, the default here too).
// --throughput N: times 2000 steps of an N-cell vessel instead (cell-steps per second, no output).
// --no-serial: run small vessels on the default execution space too (Artery runs < 512 cells on Kokkos::Serial).
// --tension F: the wall's axial force F_z (N), the Pedley-Luo term -T d_ss A with T = F_z / (4 pi A0) (0: none).
#include <Kokkos_Core.hpp>

#include "StudyArgs.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tube/Artery.hpp"

namespace
{

using namespace unilag::tube;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPeriod = 1.1, kMeanFlow = 6e-6;
constexpr double kSystole = 14e-6, kNotch = 3e-6;
constexpr int kSamples = 200;

double bump(double t, double centre, double width)
{
    const double tau = std::fmod(t, kPeriod);
    double sum = 0;
    for (int m = -1; m <= 1; ++m)
        sum += std::exp(-0.5 * std::pow((tau - centre - m * kPeriod) / width, 2));
    return sum;
}

double inletFlow(double t)
{
    const double root2pi = std::sqrt(2 * kPi);
    const double diastole = kMeanFlow - (kSystole * 0.06 + kNotch * 0.04) * root2pi / kPeriod;
    return diastole + kSystole * bump(t, 0.15, 0.06) + kNotch * bump(t, 0.42, 0.04);
}

ArteryConfig carotid(int cells, bool serial)
{
    ArteryConfig c; // L, R0, h0, E, nu, rho, mu, gamma_p: the CCA defaults of ArteryConfig
    c.cells = cells;
    if (!serial)
        c.serialBelow = 0;
    c.inlet = unilag::artery::InletKind::Flux;
    c.inletFlux = inletFlow;
    c.outlet = unilag::artery::OutletKind::Windkessel;
    c.R1 = 2.4875e8;
    c.R2 = 1.8697e9;
    c.C = 1.7529e-10;
    return c;
}

//! p and Q at inlet face, mid-vessel (mean of the two middle cells, even N) and outlet face.
std::vector<double> probes(const Artery& a)
{
    std::vector<double> A, Q;
    a.hostState(A, Q);
    double Ain, Qin, Aout, Qout;
    a.boundaryStates(Ain, Qin, Aout, Qout);
    const size_t m = A.size() / 2;
    const double Amid = 0.5 * (A[m - 1] + A[m]), Qmid = 0.5 * (Q[m - 1] + Q[m]);
    return {a.pressure(Ain), Qin, a.pressure(Amid), Qmid, a.pressure(Aout), Qout};
}

//! Relative cycle-to-cycle change of the pressures (even columns) or flows (odd columns).
double cycleChange(const std::vector<std::vector<double>>& now, const std::vector<std::vector<double>>& before,
                   int parity)
{
    double diff = 0, scale = 0;
    for (size_t k = 0; k < now.size(); ++k)
        for (size_t j = parity; j < now[k].size(); j += 2)
        {
            diff = std::fmax(diff, std::fabs(now[k][j] - before[k][j]));
            scale = std::fmax(scale, std::fabs(now[k][j]));
        }
    return diff / scale;
}

void writeWaveforms(const std::string& path, const std::vector<std::vector<double>>& cycle)
{
    FILE* f = unilag::study::openOutput("unilag_tube_artery", path);
    std::fprintf(f, "t_s,p_in_Pa,Q_in_m3s,p_mid_Pa,Q_mid_m3s,p_out_Pa,Q_out_m3s\n");
    for (size_t k = 0; k < cycle.size(); ++k)
    {
        std::fprintf(f, "%.6f", (k + 1) * kPeriod / kSamples);
        for (double v : cycle[k])
            std::fprintf(f, ",%.9g", v);
        std::fprintf(f, "\n");
    }
    std::fclose(f);
}

int throughput(int cells, bool serial, double tension)
{
    ArteryConfig cfg = carotid(cells, serial);
    cfg.tension = tension;
    Artery a(cfg);
    a.step();
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 2000; ++k)
        a.step();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("cells %d threads %d%s: %.3g cell-steps/s (%.3g s for 2000 steps)\n", cells,
                Kokkos::DefaultExecutionSpace::concurrency(), serial && cells < 512 ? " (Serial)" : "",
                2000.0 * cells / s, s);
    return 0;
}

struct Options
{
    int cells = 64, throughputCells = 0;
    bool prefill = false, serial = true;
    double tension = 0; //!< F_z, N
    std::string out = ".";
};

Options parse(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i)
    {
        const char* program = "unilag_tube_artery";
        if (!std::strcmp(argv[i], "--cells") && i + 1 < argc)
            o.cells = unilag::study::integerArg(program, "--cells", argv[++i], 2);
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            o.out = argv[++i];
        else if (!std::strcmp(argv[i], "--throughput") && i + 1 < argc)
            o.throughputCells = unilag::study::integerArg(program, "--throughput", argv[++i], 2);
        else if (!std::strcmp(argv[i], "--prefill"))
            o.prefill = true;
        else if (!std::strcmp(argv[i], "--tension") && i + 1 < argc)
            o.tension = unilag::study::positiveArg(program, "--tension", argv[++i], true);
        else if (!std::strcmp(argv[i], "--no-serial"))
            o.serial = false;
        else
            unilag::study::fail(program, std::string("unknown option '") + argv[i] +
                                     "' (options: --cells N, --out DIR, --throughput N, --prefill, --tension T, "
                                     "--no-serial)");
    }
    if (o.throughputCells == 0)
        unilag::study::outputFolder("unilag_tube_artery", o.out);
    return o;
}

int runCarotid(const Options& o)
{
    ArteryConfig cfg = carotid(o.cells, o.serial);
    cfg.tension = o.tension;
    Artery a(cfg);
    if (o.prefill)
        a.setState(std::vector<double>(o.cells, a.area0()), std::vector<double>(o.cells, 0.0), kMeanFlow * cfg.R2);
    FILE* log = unilag::study::openOutput("unilag_tube_artery", o.out + "/tube_artery_cycles.csv");
    std::fprintf(log, "cycle,change_p,change_Q,wall_s\n");
    std::vector<std::vector<double>> last, cycle(kSamples);
    const auto t0 = std::chrono::steady_clock::now();
    double wall = 0, changeP = 1, changeQ = 1;
    int m = 0;
    for (m = 1; m <= 40 && (changeP >= 1e-3 || changeQ >= 1e-3); ++m)
    {
        for (int k = 0; k < kSamples; ++k)
        {
            a.advanceTo((m - 1) * kPeriod + (k + 1) * kPeriod / kSamples);
            cycle[k] = probes(a);
        }
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!last.empty())
        {
            changeP = cycleChange(cycle, last, 0);
            changeQ = cycleChange(cycle, last, 1);
        }
        std::fprintf(log, "%d,%.6g,%.6g,%.6g\n", m, changeP, changeQ, wall);
        last = cycle;
    }
    std::fclose(log);
    writeWaveforms(o.out + "/tube_artery_waveforms.csv", cycle);
    double pMax = 0, pMin = 1e30;
    for (const auto& row : cycle)
        pMax = std::fmax(pMax, row[0]), pMin = std::fmin(pMin, row[0]);
    std::printf("cells %d threads %d%s: periodic after %d cycles (change p %.2e, Q %.2e), wall %.3f s, "
                "%lld cell-steps, %.3g cell-steps/s; inlet p %.1f/%.1f mmHg\n",
                o.cells, Kokkos::DefaultExecutionSpace::concurrency(), o.serial && o.cells < 512 ? " (Serial)" : "",
                m - 1, changeP, changeQ, wall, a.cellSteps(), a.cellSteps() / wall, pMax / 133.322, pMin / 133.322);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    Kokkos::ScopeGuard guard(argc, argv);
    const Options o = parse(argc, argv);
    return o.throughputCells > 0 ? throughput(o.throughputCells, o.serial, o.tension) : runCarotid(o);
}
