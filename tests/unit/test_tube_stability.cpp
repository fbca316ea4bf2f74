// Linear stability of the Euler-Bernoulli tube conveying fluid (src/tube/LinearStability.cpp) against the
// classical results of tube.md 2.1: the cantilever's critical flow speeds and the jumps of u_cf(beta), the
// divergence of supported tubes, the natural frequencies without flow and the infinite tube's dispersion relation.
//
// Measured u_cf (scan step 0.05, bisection to 1e-6; N elements, K modes of the Galerkin projection):
//   beta | N=20,K=10 | N=40,K=16 | N=80,K=24 | N=40, all 80 dofs | reference (tube.md 2.1)
//   0.0  | 4.477792  | 4.477819  | 4.477827  | 4.477829          | 4.478 (Beck, u^2 = 20.05)
//   0.2  | 5.591758  | 5.591459  | 5.591415  | 5.591406          | 5.59
//   0.5  | 9.322855  | 9.322398  | 9.322404  | 9.322436          | 9.32
// The two resolutions tested here (first two columns) agree to 6e-5 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tube/LinearStability.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kPi = 3.14159265358979323846;

TubeDiscretisation cantilever(int elements, int modes)
{
    TubeDiscretisation d;
    d.elements = elements;
    d.modes = modes;
    return d;
}

TubeDiscretisation supported(EndCondition left, EndCondition right)
{
    TubeDiscretisation d = cantilever(40, 16);
    d.left = left;
    d.right = right;
    return d;
}

ScanOptions scanTo(double speedMax)
{
    ScanOptions s;
    s.speedMax = speedMax;
    s.speedStep = 0.05;
    return s;
}

double ucf(const TubeDiscretisation& d, double beta, double speedMax)
{
    const Onset o = criticalFlutterSpeed(d, beta, scanTo(speedMax));
    EXPECT_TRUE(o.found) << "beta " << beta;
    return o.speed;
}

TEST(TubeStability, CantileverCriticalSpeedsConverged)
{
    const double beta[] = {0.0, 0.2, 0.5}, reference[] = {4.478, 5.59, 9.32};
    for (int i = 0; i < 3; ++i)
    {
        const double coarse = ucf(cantilever(20, 10), beta[i], 12.0);
        const double fine = ucf(cantilever(40, 16), beta[i], 12.0);
        EXPECT_NEAR(fine, reference[i], 0.005 * reference[i]) << "beta " << beta[i];
        EXPECT_NEAR(coarse, fine, 1e-4 * fine) << "beta " << beta[i] << ": not converged in the discretisation";
    }
}

TEST(TubeStability, CantileverFlutterIsHopfWithImOmegaNegativeAbove)
{
    const TubeDiscretisation d = cantilever(20, 10);
    const Onset o = criticalFlutterSpeed(d, 0.2, scanTo(12.0));
    EXPECT_FALSE(o.divergence);
    EXPECT_NEAR(o.frequency, 13.714, 0.01); // Re(omega) at onset (N=40,K=16: 13.7144)
    const LinearStability s(d, 0.2);
    double minImOmega = 1e300;
    for (const Mode& m : s.spectrum(0.98 * o.speed))
        minImOmega = std::min(minImOmega, m.omega().imag());
    EXPECT_GT(minImOmega, 0.0) << "below u_cf every mode decays (Coriolis damping at beta > 0)";
    minImOmega = 1e300;
    for (const Mode& m : s.spectrum(1.02 * o.speed))
        minImOmega = std::min(minImOmega, m.omega().imag());
    EXPECT_LT(minImOmega, 0.0) << "above u_cf a mode grows: Im(omega) < 0";
    // the second no-flow mode (omega 22.03 at u = 0) is the one that flutters, at omega 13.71 (Paidoussis 3.5)
    EXPECT_EQ(unstableMode(s, o), 2);
}

/*! The beta in [lo, hi] where u_cf jumps, by bisection on which half holds the larger change of u_cf.
 *  Measured (N=40, K=16, beta step 0.01): u_cf 7.04 -> 8.27 between beta 0.29 and 0.30, 10.93 -> 12.77 between
 *  0.69 and 0.70, 14.65 -> 17.44 between 0.92 and 0.93. Located here (N=20, K=10, scan step 0.05): jumps of 0.81,
 *  1.63, 2.61 at beta 0.2973, 0.6955, 0.9236. */
double locateJump(const TubeDiscretisation& d, double lo, double hi, double speedMax, double& jump)
{
    double uLo = ucf(d, lo, speedMax), uHi = ucf(d, hi, speedMax);
    for (int i = 0; i < 5; ++i)
    {
        const double mid = 0.5 * (lo + hi), uMid = ucf(d, mid, speedMax);
        if (uMid - uLo > uHi - uMid)
            hi = mid, uHi = uMid;
        else
            lo = mid, uLo = uMid;
    }
    jump = uHi - uLo;
    return 0.5 * (lo + hi);
}

TEST(TubeStability, CriticalSpeedJumpsNearPaidoussisValues)
{
    const TubeDiscretisation d = cantilever(20, 10);
    struct Window
    {
        double lo, hi, expected, speedMax;
    };
    for (const Window w :
         {Window{0.28, 0.31, 0.30, 9.0}, Window{0.68, 0.71, 0.69, 13.5}, Window{0.91, 0.94, 0.92, 18.5}})
    {
        double jump = 0.0;
        const double at = locateJump(d, w.lo, w.hi, w.speedMax, jump);
        std::printf("u_cf jumps by %.3f at beta %.4f\n", jump, at);
        EXPECT_NEAR(at, w.expected, 0.01) << "jump near " << w.expected;
        // over the final bracket (0.03 / 32) the steepest continuous stretch (slope ~30) changes u_cf by ~0.03
        EXPECT_GT(jump, 0.5) << "u_cf must jump (not turn steeply) near beta " << w.expected;
    }
}

/*! Measured (40 elements, 16 modes; beta 0.1 and 0.5 alike): pinned-pinned 3.1415927 (K_b x = u^2 K_f x) and
 *  3.1415928 (scan + bisection), clamped-clamped 6.2832007 / 6.2832005 (2.5e-6 above 2 pi), clamped-pinned 4.493411. */
TEST(TubeStability, DivergenceOfSupportedTubes)
{
    struct Case
    {
        EndCondition left, right;
        double expected;
    };
    for (const Case c : {Case{EndCondition::Pinned, EndCondition::Pinned, kPi},
                         Case{EndCondition::Clamped, EndCondition::Clamped, 2 * kPi}})
        for (double beta : {0.1, 0.5})
        {
            const LinearStability s(supported(c.left, c.right), beta);
            EXPECT_NEAR(s.divergenceSpeed(), c.expected, 1e-3 * c.expected);
            const Onset o = s.firstInstability(scanTo(7.0));
            EXPECT_TRUE(o.divergence) << "a supported tube first buckles (beta " << beta << ")";
            EXPECT_NEAR(o.speed, c.expected, 1e-3 * c.expected);
            // the first mode buckles: omega_1 reaches 0 there (pinned: omega_1^2 = pi^4 - u^2 pi^2)
            EXPECT_EQ(unstableMode(s, o), 1) << "beta " << beta;
        }
    // a clamped-pinned tube buckles at 4.493 (tube.md 2.1); a cantilever never diverges
    EXPECT_NEAR(LinearStability(supported(EndCondition::Clamped, EndCondition::Pinned), 0.3).divergenceSpeed(), 4.4934,
                1e-3);
    EXPECT_TRUE(std::isinf(LinearStability(cantilever(40, 16), 0.3).divergenceSpeed()));
}

//! Measured sqrt(omega) (20 elements, 10 modes): 1.875104, 4.694096, 7.854822 (40, 16: 1.875104, 4.694091, 7.854761).
TEST(TubeStability, CantileverNaturalFrequenciesWithoutFlow)
{
    const double lambda[] = {1.8751, 4.6941, 7.8548}; // omega = lambda^2 (units of sqrt(EI/(M+m))/L^2)
    for (double beta : {0.0, 0.5})
    {
        const std::vector<Mode> modes = LinearStability(cantilever(20, 10), beta).lowestModes(0.0, 3);
        ASSERT_EQ(modes.size(), 3u);
        for (int i = 0; i < 3; ++i)
        {
            EXPECT_NEAR(modes[i].omega().real(), lambda[i] * lambda[i], 1e-3 * lambda[i] * lambda[i]);
            EXPECT_NEAR(modes[i].omega().imag(), 0.0, 1e-9);
        }
    }
}

/*! Without Coriolis coupling (beta = 0) the pinned tube's modes are sin(n pi xi), exact waves of the infinite
 *  tube with k = n pi: the FEM spectrum must be the dispersion relation at those k, below and above divergence. */
TEST(TubeStability, DispersionRelationAgainstPinnedTube)
{
    const LinearStability s(supported(EndCondition::Pinned, EndCondition::Pinned), 0.0);
    for (double u : {2.0, 4.0})
    {
        const std::vector<Mode> fem = s.spectrum(u);
        for (int n = 1; n <= 4; ++n)
        {
            const auto omega = dispersionOmega(n * kPi, u, 0.0);
            for (const auto& w : omega)
            {
                double nearest = 1e300;
                for (const Mode& m : fem)
                    nearest = std::min(nearest, std::abs(m.omega() - w));
                EXPECT_LT(nearest, 1e-5 * std::abs(w)) << "u " << u << " k = " << n << " pi, omega " << w;
            }
        }
    }
    // long waves are unstable on the infinite tube: Im(omega) < 0 for k^2 < (1 - beta) u^2
    EXPECT_LT(std::min(dispersionOmega(1.0, 2.0, 0.3)[0].imag(), dispersionOmega(1.0, 2.0, 0.3)[1].imag()), 0.0);
    EXPECT_DOUBLE_EQ(dispersionOmega(2.0, 2.0, 0.3)[0].imag(), 0.0);
}

} // namespace
