// Shock Mach number against pressure ratio in a rigid straight tube (docs/tube-gas.md 4): the gas solver
// (src/tube/TubeGas.cpp) against the normal-shock relation of tube.md 3, a Sod profile against the exact Riemann
// solution, and the throughput of the gas step (cell-steps per second, threads from OMP_NUM_THREADS).
//   tube_shock_study [outdir=.] [benchCells=20000] [benchSteps=200]
// writes outdir/tube_shock_mach.csv and outdir/tube_sod_profile.csv; apps/tube_shock_study_plot.py draws them.
#include <Kokkos_Core.hpp>

#include "StudyArgs.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tube/RiemannExact.hpp"
#include "tube/TubeGas.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;

double slope(const std::vector<double>& x, const std::vector<double>& y)
{
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i)
        mx += x[i] / x.size(), my += y[i] / y.size();
    for (size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxy / sxx;
}

//! The shock's Mach number measured from its position at 8 times: the exact post-shock state flows in at the
//! left end (a piston) into gas at rest (rho, p) = (1, 1).
double measuredMach(double pressureRatio, int cells)
{
    const GasPrimitive ahead{1.0, 0.0, 1.0};
    const double a1 = std::sqrt(kGamma), mach = shockMachFromPressureRatio(pressureRatio, kGamma);
    const GasPrimitive behind = postShockState(ahead, mach, kGamma);
    GasSetup setup;
    setup.cells = cells;
    setup.left = GasEnd{GasEndType::FixedState, behind};
    setup.right = GasEnd{GasEndType::Transmissive, ahead};
    TubeGas gas(setup);
    gas.setState([&](double s) { return s < 0.1 ? behind : ahead; });
    const double tEnd = 0.8 / (mach * a1);
    std::vector<double> t, x;
    for (int k = 1; k <= 8; ++k)
    {
        gas.advanceTo(tEnd * k / 8.0);
        t.push_back(gas.time());
        x.push_back(leadingShockPosition(gas.fields(), 0.5 * (ahead.p + behind.p)));
    }
    return slope(t, x) / a1;
}

void machStudy(const std::string& dir)
{
    const std::string path = dir + "/tube_shock_mach.csv";
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f)
    {
        std::fprintf(stderr, "tube_shock_study: cannot write %s\n", path.c_str());
        std::exit(1);
    }
    std::fprintf(f, "pressure_ratio,mach_relation,mach_200,mach_400,rel_error_200,rel_error_400\n");
    std::printf("%8s %10s %10s %10s %10s\n", "p2/p1", "M_s(3)", "M 400", "err 200", "err 400");
    const double ratios[] = {1.1, 1.5, 2, 3, 5, 7, 10, 15, 20, 30, 50};
    for (double r : ratios)
    {
        const double m = shockMachFromPressureRatio(r, kGamma);
        const double m200 = measuredMach(r, 200), m400 = measuredMach(r, 400);
        std::fprintf(f, "%g,%.8f,%.8f,%.8f,%.3e,%.3e\n", r, m, m200, m400, m200 / m - 1, m400 / m - 1);
        std::printf("%8g %10.5f %10.5f %10.2e %10.2e\n", r, m, m400, m200 / m - 1, m400 / m - 1);
    }
    std::fclose(f);
}

void sodProfile(const std::string& dir)
{
    const GasPrimitive left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
    const RiemannExact exact(left, right, kGamma);
    GasSetup setup;
    setup.cells = 200;
    setup.left = GasEnd{GasEndType::Transmissive, left};
    setup.right = GasEnd{GasEndType::Transmissive, right};
    TubeGas gas(setup);
    gas.setState([&](double s) { return s < 0.5 ? left : right; });
    gas.advanceTo(0.2);
    const GasFields fl = gas.fields();
    const std::string path = dir + "/tube_sod_profile.csv";
    FILE* f = unilag::study::openOutput("unilag_tube_shock", path);
    std::fprintf(f, "s,rho,u,p,rho_exact,u_exact,p_exact\n");
    for (size_t j = 0; j < fl.s.size(); ++j)
    {
        const GasPrimitive e = exact.sample((fl.s[j] - 0.5) / 0.2);
        std::fprintf(f, "%.6f,%.8f,%.8f,%.8f,%.8f,%.8f,%.8f\n", fl.s[j], fl.rho[j], fl.u[j], fl.p[j], e.rho, e.u,
                     e.p);
    }
    std::fclose(f);
}

//! Cell-steps per second of TubeGas::step (two stages of 4 kernels each) on a closed tube with a shock.
void benchmark(int cells, int steps, bool serial)
{
    GasSetup setup;
    setup.cells = cells;
    setup.serialBelow = serial ? cells + 1 : 0; // the measurement chooses, not the size
    TubeGas gas(setup);
    gas.setState([](double s) { return s < 0.5 ? GasPrimitive{1.0, 0.0, 10.0} : GasPrimitive{0.125, 0.0, 0.1}; });
    const double dt = gas.stableStep();
    for (int i = 0; i < 10; ++i) // warm-up
        gas.step(dt);
    Kokkos::fence();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i)
        gas.step(dt);
    Kokkos::fence();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("bench_tube_gas threads=%d space=%s cells=%d steps=%d seconds=%.4f cell_steps_per_s=%.4e\n",
                Kokkos::DefaultExecutionSpace::concurrency(), serial ? "Serial" : Kokkos::DefaultExecutionSpace::name(),
                cells, steps, seconds, double(cells) * steps / seconds);
}

} // namespace

int main(int argc, char* argv[])
{
    Kokkos::ScopeGuard kokkos(argc, argv);
    const char* program = "unilag_tube_shock";
    const std::string dir = unilag::study::outputFolder(program, argc > 1 ? argv[1] : ".");
    const int cells = argc > 2 ? unilag::study::integerArg(program, "CELLS", argv[2], 2) : 20000;
    const int steps = argc > 3 ? unilag::study::integerArg(program, "STEPS", argv[3], 1) : 200;
    machStudy(dir);
    sodProfile(dir);
    for (bool serial : {false, true})
        benchmark(cells, steps, serial);
    return 0;
}
