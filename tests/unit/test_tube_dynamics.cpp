// The nonlinear tube (src/tube/TubeDynamics.cpp, kernels/unilag/TubeRod.hpp): exact gradients against finite
// differences, cantilever bending frequencies against Euler-Bernoulli, energy and orthogonality over 1e5 steps,
// momenta of a free-free tube, and flutter at beta = 0.2 against the linear stability (LinearStability).
// Units: L = 1, EI = 1, M + m = 1 (time in L^2 sqrt((M + m)/EI)). Measured (docs/tube-dynamics.md has more):
//   cantilever omega_k/lambda_k^2 - 1: -9.6e-4, -8.3e-4, -5.0e-4 (N = 30, 50, 70); pinned-pinned -2.2e-4
//   1e5 steps: max |dE/E| 9.1e-8, drift 3e-9, orthogonality defect 5.2e-14
//   free-free: |dP|/|P| 6.4e-15, |dL|/|L| 1.7e-15 after 2e4 steps
//   flutter, beta 0.2, growth at 1.02 u_cf / linear: 1.120 (this test's N = 20 tube), 1.002 (N = 80, stiff tube)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <random>
#include <vector>

#include "tube/LinearStability.hpp"
#include "tube/TubeDynamics.hpp"

namespace
{

using namespace unilag::tube;
using Vec = std::array<double, 3>;
using Frame = std::array<double, 9>;

Frame expFrame(const Vec& th) // Rodrigues, row-major
{
    const double t = std::sqrt(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]);
    const double a = std::sin(t) / t, b = (1 - std::cos(t)) / (t * t);
    const double K[9] = {0, -th[2], th[1], th[2], 0, -th[0], -th[1], th[0], 0};
    Frame r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            double k2 = 0;
            for (int l = 0; l < 3; ++l)
                k2 += K[3 * i + l] * K[3 * l + j];
            r[3 * i + j] = (i == j) + a * K[3 * i + j] + b * k2;
        }
    return r;
}

Frame times(const Frame& x, const Frame& y)
{
    Frame r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int l = 0; l < 3; ++l)
                r[3 * i + j] += x[3 * i + l] * y[3 * l + j];
    return r;
}

Frame perturbed(const Frame& f, int axis, double eps) // f exp(eps e_axis^)
{
    Vec th{0, 0, 0};
    th[axis] = eps;
    return times(f, expFrame(th));
}

RodConstants unitTube(double lambdaSq, double rotary = 0)
{
    // Shear and rotary-inertia corrections to the Euler-Bernoulli frequency ~ lambda^2 EI/(2 kGA) and
    // lambda^2 rho I/2 (relative): 2.5e-4 each at this scaling.
    RodConstants c;
    c.bending = 1.0;
    c.torsion = 1.0 / 1.3;
    c.extension = c.shear = lambdaSq / 5e-4;
    c.wallRotary = rotary > 0 ? rotary : 5e-4 / lambdaSq;
    c.wallMass = 0.8;
    c.fluidMass = 0.2;
    return c;
}

double cantileverMode(double lambda, double s)
{
    const double sigma = (std::sinh(lambda) - std::sin(lambda)) / (std::cosh(lambda) + std::cos(lambda));
    return std::cosh(lambda * s) - std::cos(lambda * s) - sigma * (std::sinh(lambda * s) - std::sin(lambda * s));
}

double modeSlope(double lambda, double s)
{
    const double sigma = (std::sinh(lambda) - std::sin(lambda)) / (std::cosh(lambda) + std::cos(lambda));
    return lambda * (std::sinh(lambda * s) + std::sin(lambda * s) - sigma * (std::cosh(lambda * s) - std::cos(lambda * s)));
}

//! Times where the series crosses zero (linear interpolation between samples).
std::vector<double> zeroCrossings(const std::vector<double>& t, const std::vector<double>& y)
{
    std::vector<double> z;
    for (std::size_t k = 1; k < y.size(); ++k)
        if ((y[k - 1] < 0) != (y[k] < 0))
            z.push_back(t[k - 1] + (t[k] - t[k - 1]) * y[k - 1] / (y[k - 1] - y[k]));
    return z;
}

//! Angular frequency from equally spaced zero crossings (least-squares slope = half period).
double frequencyFromCrossings(const std::vector<double>& z)
{
    const int n = static_cast<int>(z.size());
    double sk = 0, st = 0, skk = 0, skt = 0;
    for (int k = 0; k < n; ++k)
    {
        sk += k;
        st += z[k];
        skk += double(k) * k;
        skt += k * z[k];
    }
    const double halfPeriod = (n * skt - sk * st) / (n * skk - sk * sk);
    return M_PI / halfPeriod;
}

//! The cantilever's mode `lambda` (modal coordinate: the y displacement projected on the mode shape).
double measuredFrequency(double lambda, int segments, double periods)
{
    RodSetup setup;
    setup.segments = segments;
    TubeDynamics tube(unitTube(lambda * lambda), setup);
    const double amp = 1e-4;
    tube.displace([&](double s) { return Vec{0, amp * cantileverMode(lambda, s) / cantileverMode(lambda, 1), 0}; });
    const double period = 2 * M_PI / (lambda * lambda);
    const double dt = tube.stableStep();
    const int sampleEvery = std::max(1, int(period / (100 * dt)));
    const int steps = int(periods * period / dt);
    std::vector<double> t, q;
    const double h = tube.spacing();
    for (int k = 0; k <= steps; k += sampleEvery)
    {
        const RodFields f = tube.fields();
        double proj = 0;
        for (int j = 0; j < tube.nodes(); ++j)
            proj += (j == 0 || j == tube.nodes() - 1 ? 0.5 : 1.0) * f.position[3 * j + 1] * cantileverMode(lambda, j * h);
        t.push_back(tube.time());
        q.push_back(proj);
        tube.run(dt, sampleEvery);
    }
    EXPECT_TRUE(tube.finite());
    return frequencyFromCrossings(zeroCrossings(t, q));
}

TEST(TubeDynamicsGradient, ForcesAndTorquesAreExactGradients)
{
    RodConstants c;
    c.extension = 3.0;
    c.shear = 2.0;
    c.bending = 0.7;
    c.torsion = 0.5;
    c.restCurvature = {0.3, -0.2, 0.5};
    const double h = 0.1;
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int trial = 0; trial < 5; ++trial)
    {
        const Frame A = expFrame({U(gen), U(gen), U(gen)});
        const Frame B = times(A, expFrame({0.3 * U(gen), 0.3 * U(gen), 0.3 * U(gen)}));
        const Vec ra{U(gen), U(gen), U(gen)};
        Vec rb = ra;
        for (int a = 0; a < 3; ++a)
            rb[a] += h * (A[3 * a] + 0.2 * U(gen)); // along A's axis 1, stretched and sheared
        const SegmentGradient g = segmentGradient(c, h, A, B, ra, rb);
        const double eps = 1e-6;
        double scale = 0;
        for (int a = 0; a < 3; ++a)
            scale = std::max({scale, std::abs(g.forceOnLeft[a]), std::abs(g.torqueLeft[a]), std::abs(g.torqueRight[a])});
        for (int a = 0; a < 3; ++a)
        {
            Vec p = rb, m = rb;
            p[a] += eps;
            m[a] -= eps;
            const double dVdrb = (segmentGradient(c, h, A, B, ra, p).energy - segmentGradient(c, h, A, B, ra, m).energy) / (2 * eps);
            EXPECT_NEAR(dVdrb, g.forceOnLeft[a], 1e-6 * scale) << "dV/dr_{j+1}, axis " << a;
            p = ra;
            m = ra;
            p[a] += eps;
            m[a] -= eps;
            const double dVdra = (segmentGradient(c, h, A, B, p, rb).energy - segmentGradient(c, h, A, B, m, rb).energy) / (2 * eps);
            EXPECT_NEAR(dVdra, -g.forceOnLeft[a], 1e-6 * scale) << "dV/dr_j, axis " << a;
            const double dVdA = (segmentGradient(c, h, perturbed(A, a, eps), B, ra, rb).energy -
                                 segmentGradient(c, h, perturbed(A, a, -eps), B, ra, rb).energy) / (2 * eps);
            EXPECT_NEAR(-dVdA, g.torqueLeft[a], 1e-6 * scale) << "torque on node j, axis " << a;
            const double dVdB = (segmentGradient(c, h, A, perturbed(B, a, eps), ra, rb).energy -
                                 segmentGradient(c, h, A, perturbed(B, a, -eps), ra, rb).energy) / (2 * eps);
            EXPECT_NEAR(-dVdB, g.torqueRight[a], 1e-6 * scale) << "torque on node j+1, axis " << a;
        }
    }
}

TEST(TubeDynamicsModes, CantileverFrequenciesMatchEulerBernoulli)
{
    const double lambdas[3] = {1.8751040687, 4.6940911330, 7.8547574382};
    const int segments[3] = {30, 50, 70};
    for (int k = 0; k < 3; ++k)
    {
        const double exact = lambdas[k] * lambdas[k];
        const double measured = measuredFrequency(lambdas[k], segments[k], 1.6);
        std::printf("mode %d: N = %d, omega = %.6f, Euler-Bernoulli %.6f, relative %.2e\n", k + 1, segments[k],
                    measured, exact, measured / exact - 1);
        EXPECT_NEAR(measured / exact, 1.0, 5e-3) << "mode " << k + 1;
    }
}

TEST(TubeDynamicsConservation, EnergyAndOrthogonalityOver1e5Steps)
{
    RodSetup setup;
    setup.segments = 20;
    TubeDynamics tube(unitTube(1.8751 * 1.8751), setup);
    // Started straight with the first mode's velocity and the matching spins (the tangent turns, no shear
    // rate), so the stiff axial and shear modes stay quiet and the energy error is the bending mode's.
    const double ay = 0.05, az = 0.02, lambda = 1.8751;
    tube.setVelocity([&](double s) { return Vec{0, ay * cantileverMode(lambda, s), az * cantileverMode(lambda, s)}; });
    tube.setSpin([&](double s) { return Vec{0, -az * modeSlope(lambda, s), ay * modeSlope(lambda, s)}; });
    const double dt = tube.stableStep(), e0 = tube.energy();
    double worst = 0, firstMean = 0, lastMean = 0;
    const int blocks = 100, perBlock = 1000;
    for (int b = 0; b < blocks; ++b)
    {
        tube.run(dt, perBlock);
        const double err = tube.energy() / e0 - 1;
        worst = std::max(worst, std::abs(err));
        if (b < 10)
            firstMean += err / 10;
        if (b >= blocks - 10)
            lastMean += err / 10;
    }
    std::printf("1e5 steps, dt = %.3e: max |dE/E| = %.2e, drift (last - first 10%%) = %.2e, defect = %.2e\n", dt,
                worst, lastMean - firstMean, tube.orthogonalityDefect());
    EXPECT_LT(worst, 1e-5);
    EXPECT_LT(std::abs(lastMean - firstMean), 1e-6);
    EXPECT_LT(tube.orthogonalityDefect(), 1e-13);
}

double relativeChange(const Vec& a, const Vec& b)
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])) /
           std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

TEST(TubeDynamicsConservation, FreeFreeMomentaAndRestHelix)
{
    RodConstants c = unitTube(10.0);
    c.restCurvature = {1.0, 2.0, -1.0};
    RodSetup setup;
    setup.segments = 30;
    setup.left = setup.right = EndCondition::Free;
    TubeDynamics tube(c, setup);
    EXPECT_LT(tube.energy(), 1e-20) << "the rest helix is stress free";
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<Vec> v(tube.nodes()), w(tube.nodes());
    for (int j = 0; j < tube.nodes(); ++j)
    {
        v[j] = {0.1 * U(gen), 0.1 * U(gen), 0.1 * U(gen)};
        w[j] = {2 * U(gen), 2 * U(gen), 2 * U(gen)};
    }
    const double h = tube.spacing();
    tube.setVelocity([&](double s) { return v[std::lround(s / h)]; });
    tube.setSpin([&](double s) { return w[std::lround(s / h)]; });
    const Vec p0 = tube.linearMomentum(), l0 = tube.angularMomentum();
    const double e0 = tube.energy();
    tube.run(tube.stableStep(), 20000);
    const double dp = relativeChange(p0, tube.linearMomentum()), dl = relativeChange(l0, tube.angularMomentum());
    std::printf("free-free, 2e4 steps: |dP|/|P| = %.2e, |dL|/|L| = %.2e, dE/E = %.2e, defect = %.2e\n", dp, dl,
                tube.energy() / e0 - 1, tube.orthogonalityDefect());
    EXPECT_TRUE(tube.finite());
    EXPECT_LT(dp, 1e-12);
    EXPECT_LT(dl, 1e-12);
    EXPECT_LT(tube.orthogonalityDefect(), 1e-13);
}

TEST(TubeDynamicsModes, PinnedPinnedFrequency)
{
    // Simply supported: positions held, rotations (moments) free; omega_1 = pi^2 sqrt(EI/((M + m) L^4)).
    RodSetup setup;
    setup.segments = 40;
    setup.left = setup.right = EndCondition::Pinned;
    TubeDynamics tube(unitTube(M_PI * M_PI), setup);
    tube.displace([](double s) { return Vec{0, 0, 1e-4 * std::sin(M_PI * s)}; });
    const double dt = tube.stableStep();
    const int every = std::max(1, int(2 * M_PI / (M_PI * M_PI) / (100 * dt)));
    std::vector<double> t, z;
    while (tube.time() < 2.5 * 2 * M_PI / (M_PI * M_PI))
    {
        t.push_back(tube.time());
        z.push_back(tube.position(20)[2]);
        tube.run(dt, every);
    }
    const double measured = frequencyFromCrossings(zeroCrossings(t, z));
    std::printf("pinned-pinned, N = 40: omega = %.6f, pi^2 = %.6f, relative %.2e\n", measured, M_PI * M_PI,
                measured / (M_PI * M_PI) - 1);
    EXPECT_NEAR(measured / (M_PI * M_PI), 1.0, 5e-3);
    EXPECT_LT(std::abs(tube.position(0)[2]) + std::abs(tube.position(40)[2]), 1e-15) << "the pins hold";
}

TEST(TubeDynamicsConservation, GravityGivesTheExactMomentumRate)
{
    // Free-free under gravity: the internal loads cancel pairwise, so dP/dt = (M + m) L g step by step.
    RodConstants c = unitTube(10.0);
    c.gravity = {0.0, -9.81, 1.0};
    RodSetup setup;
    setup.segments = 20;
    setup.left = setup.right = EndCondition::Free;
    TubeDynamics tube(c, setup);
    tube.setVelocity([](double s) { return Vec{0.1 * s, 0.0, -0.2 * s * s}; });
    const Vec p0 = tube.linearMomentum();
    const double dt = tube.stableStep();
    tube.run(dt, 2000);
    const Vec p = tube.linearMomentum();
    for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(p[a], p0[a] + c.gravity[a] * 2000 * dt, 1e-12 * 9.81 * 2000 * dt) << "axis " << a;
}

//! Least-squares slope of log|y| at the series' extrema (parabola through the three samples around each) after tStart.
double growthFromExtrema(const std::vector<double>& t, const std::vector<double>& y, double tStart)
{
    std::vector<double> tp, lp;
    for (std::size_t k = 1; k + 1 < y.size(); ++k)
    {
        const double a = std::abs(y[k - 1]), b = std::abs(y[k]), c = std::abs(y[k + 1]);
        if (t[k] < tStart || !(b >= a && b > c) || (y[k - 1] < 0) != (y[k + 1] < 0))
            continue;
        const double curv = a - 2 * b + c, shift = 0.5 * (a - c) / curv; // in samples
        tp.push_back(t[k] + shift * (t[k + 1] - t[k]));
        lp.push_back(std::log(b - 0.25 * (a - c) * shift));
    }
    const double n = double(tp.size());
    double st = 0, sl = 0, stt = 0, stl = 0;
    for (std::size_t k = 0; k < tp.size(); ++k)
    {
        st += tp[k];
        sl += lp[k];
        stt += tp[k] * tp[k];
        stl += tp[k] * lp[k];
    }
    return (n * stl - st * sl) / (n * stt - st * st);
}

/*! Growth rate of the tip's transverse motion of the cantilever conveying fluid at beta = 0.2, flow speed
 *  u = U L sqrt(M/EI), started from a small displacement in the second mode's shape. Units: L = EI = M + m = 1. */
double measuredGrowth(double u, int segments, double stiffness, double rotary, double duration)
{
    RodConstants c = unitTube(stiffness, rotary);
    RodSetup setup;
    setup.segments = segments;
    setup.flowSpeed = u / std::sqrt(c.fluidMass);
    TubeDynamics tube(c, setup);
    const double lambda = 4.6940911330;
    tube.displace([&](double s) { return Vec{0, 1e-4 * cantileverMode(lambda, s) / cantileverMode(lambda, 1), 0}; });
    const double dt = tube.stableStep(), sample = 0.46 / 60; // about 60 samples per flutter period
    const int every = std::max(1, int(sample / dt));
    std::vector<double> t, y;
    while (tube.time() < duration)
    {
        t.push_back(tube.time());
        y.push_back(tube.tip()[1]);
        tube.run(dt, every);
    }
    EXPECT_TRUE(tube.finite());
    return growthFromExtrema(t, y, 2.0);
}

double linearUcf()
{
    TubeDiscretisation d; // 40 elements, 16 modes: u_cf within 1e-5 of the converged one (test_tube_stability)
    ScanOptions scan;
    scan.speedMax = 10;
    scan.speedStep = 0.05;
    return criticalFlutterSpeed(d, 0.2, scan).speed;
}

TEST(TubeDynamicsFlow, CantileverFluttersAboveTheLinearCriticalSpeed)
{
    const double ucf = linearUcf();
    // A cheap tube (N = 20, EA = kGA = 1e4, rho I = 2e-4, 4 time units): the accurate figures come from the test below.
    const double below = measuredGrowth(0.98 * ucf, 20, 5.0, 2e-4, 4.0);
    const double above = measuredGrowth(1.02 * ucf, 20, 5.0, 2e-4, 4.0);
    const double linear = LinearStability(TubeDiscretisation{}, 0.2).growthRate(1.02 * ucf);
    std::printf("beta 0.2, u_cf = %.5f, N = 20: growth at 0.98 u_cf %.4f, at 1.02 u_cf %.4f (linear %.4f, ratio %.3f)\n",
                ucf, below, above, linear, above / linear);
    EXPECT_LT(below, 0.0);
    EXPECT_GT(above, 0.0);
}

// The accurate comparison (minutes): --gtest_also_run_disabled_tests --gtest_filter='*AccurateGrowth*'
TEST(TubeDynamicsFlow, DISABLED_AccurateGrowthRate)
{
    const double ucf = linearUcf();
    const double linear = LinearStability(TubeDiscretisation{}, 0.2).growthRate(1.02 * ucf);
    for (int n : {40, 80})
        for (double stiffness : {10.0, 100.0})
        {
            const double g = measuredGrowth(1.02 * ucf, n, stiffness, 0.0, 10.0);
            std::printf("N = %d, EA = kGA = %.0f, rho I = %.1e: growth at 1.02 u_cf %.5f, linear %.5f, ratio %.4f\n",
                        n, stiffness / 5e-4, 5e-4 / stiffness, g, linear, g / linear);
        }
}

} // namespace

namespace
{

//! finite() is the time run's stop test: one NaN or infinity anywhere in the state, on either execution space,
//! must make it false, and a finite state true.
TEST(TubeDynamicsState, FiniteFindsOneBadNode)
{
    for (int serialBelow : {1024, 0}) // Kokkos::Serial and the default execution space
        for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
        {
            RodSetup setup;
            setup.segments = 20;
            setup.serialBelow = serialBelow;
            TubeDynamics rod(unitTube(10.0), setup);
            rod.setVelocity([](double s) { return Vec{0.0, 0.01 * s, 0.0}; });
            EXPECT_TRUE(rod.finite());
            rod.setVelocity([bad](double s) { return Vec{0.0, std::abs(s - 0.5) < 1e-9 ? bad : 0.0, 0.0}; });
            EXPECT_FALSE(rod.finite()) << "serialBelow " << serialBelow << ", value " << bad;
        }
}

} // namespace
