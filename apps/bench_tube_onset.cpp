/*! \file bench_tube_onset.cpp
 *  \brief How long the linear stability takes to give u_cf at one mass ratio to 0.1%: for each discretisation
 *  (elements, Galerkin modes) and scan step, the median wall time of criticalFlutterSpeed over repeats, u_cf, and
 *  its error against a fine reference (80 elements, 32 modes, bisection to 1e-9). The cheapest row within 0.1% is
 *  the figure to report. Usage: `build/release/apps/unilag_bench_tube_onset [beta] [repeats]` (default 0.2, 5).
 */
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tube/LinearStability.hpp"

namespace
{

using namespace unilag::tube;

struct Config
{
    int elements, modes;
    double speedStep;
};

double medianSeconds(const Config& c, double beta, int repeats, double& ucf)
{
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r)
    {
        const auto start = std::chrono::steady_clock::now();
        TubeDiscretisation d;
        d.elements = c.elements;
        d.modes = c.modes;
        ucf = criticalFlutterSpeed(d, beta, {30.0, c.speedStep, 1e-6}).speed;
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    const double beta = argc > 1 ? std::atof(argv[1]) : 0.2;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
    TubeDiscretisation fine;
    fine.elements = 80;
    fine.modes = 32;
    const double reference = criticalFlutterSpeed(fine, beta, {30.0, 0.02, 1e-9}).speed;
    std::printf("beta %.3f: reference u_cf %.9f (80 elements, 32 modes)\n", beta, reference);
    std::printf("%8s %6s %10s %14s %12s %12s\n", "elements", "modes", "scan_step", "u_cf", "rel_error", "seconds");
    const std::vector<Config> configs = {{8, 6, 0.1},   {10, 8, 0.1},   {16, 8, 0.1},  {20, 10, 0.1},
                                         {20, 10, 0.02}, {40, 16, 0.1}, {40, 16, 0.02}};
    for (const Config& c : configs)
    {
        double ucf = 0.0;
        const double seconds = medianSeconds(c, beta, repeats, ucf);
        std::printf("%8d %6d %10.3g %14.9f %12.3e %12.4g\n", c.elements, c.modes, c.speedStep, ucf,
                    std::abs(ucf - reference) / reference, seconds);
    }
    return 0;
}
