// A free, soft tube filled with gas (src/tube/GasRodCoupling.cpp, docs/tube-gas-rod.md): the total energy of
// rod + gas against the step, and the talk's Rankine-Hugoniot relations (tube.md 1.8) on the shocks computed in
// the moving, stretched tube.
//   unilag_tube_gas_rod [outdir=.] [end_time=4]
// writes outdir/tube_gas_rod_energy.csv (the energy history at three steps) and outdir/tube_gas_rod_shocks.csv;
// apps/tube_gas_rod_study_plot.py draws tube_gas_rod_energy.png.
#include <Kokkos_Core.hpp>

#include "StudyArgs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "tube/GasRodCoupling.hpp"
#include "tube/RankineHugoniot.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;

//! The soft free-free tube of tests/unit/test_tube_gas_rod.cpp: length 1, gas cross-section 0.01 (mass 0.01
//! per length at rho = 1), wall mass `alpha`, EA `extension` (its axial waves outrun the gas's shocks).
GasRodSetup softTube(int segments, double cfl, double alpha, double extension)
{
    GasRodSetup s;
    s.rod.length = 1.0;
    s.rod.extension = extension;
    s.rod.shear = 0.5 * extension;
    s.rod.bending = 1e-3;
    s.rod.torsion = 7e-4;
    s.rod.wallMass = alpha;
    s.rod.wallRotary = 6e-5;
    s.rodSetup.segments = segments;
    s.rodSetup.left = EndCondition::Free;
    s.rodSetup.right = EndCondition::Free;
    s.gas.gamma = kGamma;
    s.gas.cfl = cfl;
    s.rodStepFactor = cfl / 0.8;
    s.area = 0.01;
    return s;
}

GasPrimitive sod(double s) { return s < 0.5 ? GasPrimitive{1.0, 0.0, 1.0} : GasPrimitive{0.125, 0.0, 0.1}; }
std::array<double, 3> bending(double s) { return {0.0, 0.05 * std::cos(2.0 * M_PI * s), 0.0}; }

FILE* openOrThrow(const std::string& path)
{
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f)
        throw std::runtime_error("cannot write " + path);
    return f;
}

void energyStudy(const std::string& dir, double endTime)
{
    FILE* csv = openOrThrow(dir + "/tube_gas_rod_energy.csv");
    std::fprintf(csv, "cfl,t,energy_error,momentum,mass_error\n");
    std::printf("energy of rod + gas, soft tube, 100 segments, Sod inside, t in [0, %g]\n", endTime);
    for (double cfl : {0.8, 0.4, 0.2})
    {
        GasRodCoupling tube(softTube(100, cfl, 0.05, 0.5));
        tube.rod().setVelocity(bending);
        tube.setGas(sod);
        const GasRodTotals t0 = tube.totals();
        double worst = 0;
        int steps = 0;
        const auto start = std::chrono::steady_clock::now();
        while (tube.time() < endTime * (1.0 - 1e-14))
        {
            tube.step(std::min(tube.stableStep(), endTime - tube.time()));
            if (++steps % 5 == 0)
            {
                const GasRodTotals t = tube.totals();
                const double de = t.energy() / t0.energy() - 1.0;
                worst = std::max(worst, std::abs(de));
                std::fprintf(csv, "%.2f,%.6f,%.6e,%.3e,%.3e\n", cfl, tube.time(), de,
                             std::hypot(t.momentum[0], t.momentum[1], t.momentum[2]), t.mass / t0.mass - 1.0);
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("  cfl %.1f: %5d steps, max |dE/E| %.3e, %.2f s (%.2f ms per step, with the energy sums)\n", cfl,
                    steps, worst, seconds, 1e3 * seconds / steps);
    }
    std::fclose(csv);
}

void shockStudy(const std::string& dir)
{
    FILE* csv = openOrThrow(dir + "/tube_gas_rod_shocks.csv");
    std::fprintf(csv, "t,s,speed,Gamma2,Gamma_gamma,gamma2,Gamma2_jump,defect_mass,defect_momentum,defect_energy,"
                      "entropy_jump\n");
    GasRodCoupling tube(softTube(400, 0.8, 0.02, 0.2));
    tube.rod().setVelocity(bending);
    tube.setGas(sod);
    std::printf("Rankine-Hugoniot on the computed shock (400 segments, alpha 0.02, EA 0.2):\n");
    for (double t0 : {0.12, 0.17, 0.22}) // the fits (t0 +- 0.02) must not overlap
    {
        const ShockJump j = measureShockJump([&](double t) { tube.advanceTo(t); },
                                             [&] { return tube.gas().shockPosition(0.2); },
                                             [&] { return std::make_pair(tube.gas().fields(), tube.cellMetric()); },
                                             t0, kGamma);
        const auto& m = j.metric;
        const auto& d = j.defects;
        std::fprintf(csv, "%.3f,%.5f,%.5f,%.6f,%.4e,%.4e,%.3e,%.3e,%.3e,%.3e,%.5f\n", t0, j.position, j.speed, m[0],
                     m[1], m[2], j.behind.metric[0] - j.ahead.metric[0], d[0], d[1], d[2], j.entropyJump);
        std::printf("  t %.2f: s %.4f, speed %.4f, |G|^2 %.5f, G.g %+.2e: defects %.1e %.1e %.1e, entropy jump "
                    "%.4f\n",
                    t0, j.position, j.speed, m[0], m[1], d[0], d[1], d[2], j.entropyJump);
    }
    std::fclose(csv);
}

} // namespace

int main(int argc, char* argv[])
{
    Kokkos::ScopeGuard guard(argc, argv);
    const char* program = "unilag_tube_gas_rod";
    const std::string dir = unilag::study::outputFolder(program, argc > 1 ? argv[1] : ".");
    const double endTime = argc > 2 ? unilag::study::positiveArg(program, "END_TIME", argv[2]) : 4.0;
    try
    {
        energyStudy(dir, endTime);
        shockStudy(dir);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "unilag_tube_gas_rod: %s\n", e.what());
        return 1;
    }
    return 0;
}
