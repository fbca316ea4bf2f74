// Throughput of the nonlinear tube's step (src/tube/TubeDynamics.cpp): node-steps per second of a cantilever
// conveying fluid, without and with flow, on the default execution space (threads from OMP_NUM_THREADS on the
// OpenMP backend) and on Kokkos::Serial (RodSetup::serialBelow), one line per run.
//   OMP_NUM_THREADS=1 build/release/apps/bench_tube_step [segments=200] [steps=4000]
#include <Kokkos_Core.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tube/TubeDynamics.hpp"

namespace
{

using unilag::tube::RodConstants;
using unilag::tube::RodSetup;
using unilag::tube::TubeDynamics;

//! Seconds for `steps` steps of a tube (L = EI = M + m = 1, beta = 0.2) started from a small tip deflection.
double timeSteps(int segments, int steps, double flowSpeed, bool serial)
{
    RodConstants c;
    c.bending = 1.0;
    c.torsion = 1.0 / 1.3;
    c.extension = c.shear = 2e4;
    c.wallRotary = 1e-4;
    c.wallMass = 0.8;
    c.fluidMass = 0.2;
    RodSetup setup;
    setup.segments = segments;
    setup.flowSpeed = flowSpeed;
    setup.serialBelow = serial ? segments + 2 : 0; // the measurement chooses, not the size
    TubeDynamics tube(c, setup);
    tube.displace([](double s) { return std::array<double, 3>{0, 1e-3 * s * s, 0}; });
    const double dt = tube.stableStep();
    tube.run(dt, 10); // warm-up
    const auto start = std::chrono::steady_clock::now();
    tube.run(dt, steps);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!tube.finite())
        std::fprintf(stderr, "bench_tube_step: the state went non-finite\n");
    return seconds;
}

} // namespace

int main(int argc, char* argv[])
{
    Kokkos::ScopeGuard kokkos(argc, argv);
    const int segments = argc > 1 ? std::atoi(argv[1]) : 200;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 4000;
    const int threads = Kokkos::DefaultExecutionSpace::concurrency();
    for (bool serial : {false, true})
        for (double u : {0.0, 5.6})
        {
            const double seconds = timeSteps(segments, steps, u / std::sqrt(0.2), serial);
            std::printf("bench_tube_step threads=%d space=%s segments=%d steps=%d flow_u=%.1f seconds=%.4f "
                        "node_steps_per_s=%.4e\n",
                        serial ? 1 : threads, serial ? "Serial" : "default", segments, steps, u, seconds,
                        double(segments + 1) * steps / seconds);
        }
    return 0;
}
