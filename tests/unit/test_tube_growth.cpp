// The growth-rate fit of flutter runs (src/tube/GrowthFit.cpp) on series whose rate is known: a planar
// oscillation a e^(sigma t) |sin(omega t)|, growing and decaying, with a transient before the fit window, and a
// whirl (a distance from the axis without oscillation). The fit must return sigma and omega, not something near.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tube/GrowthFit.hpp"

namespace
{

using unilag::tube::fitGrowth;

struct Series
{
    std::vector<double> t, a;
};

//! |y| of y = e^(sigma t) sin(omega t) + transient e^(-5 t) sin(3.7 omega t), sampled every dt.
Series planar(double sigma, double omega, double end, double dt)
{
    Series s;
    for (double t = 0.0; t <= end; t += dt)
    {
        s.t.push_back(t);
        s.a.push_back(std::abs(std::exp(sigma * t) * std::sin(omega * t) + std::exp(-5.0 * t) * std::sin(3.7 * omega * t)));
    }
    return s;
}

TEST(TubeGrowthFit, PlanarGrowthAndFrequency)
{
    for (double sigma : {0.3, -0.2, 0.0})
    {
        const Series s = planar(sigma, 20.0, 6.0, 1e-4);
        const auto fit = fitGrowth(s.t, s.a, 2.0);
        ASSERT_TRUE(fit.ok);
        EXPECT_GT(fit.peaks, 20);
        // peaks of e^(sigma t)|sin(omega t)| sit at tan(omega t) = omega / sigma: equally spaced, so the fit is exact
        // up to the sampling of the peaks (dt = 1e-4 over a period of 0.31)
        EXPECT_NEAR(fit.growthRate, sigma, 1e-3) << "sigma " << sigma;
        EXPECT_NEAR(fit.frequency, 20.0, 20.0 * 1e-3);
    }
}

//! y = e^(sigma t) sin(omega t) + a ripple at 23 omega of 1/2000 of the first amplitude, which gives |y| many
//! spurious local maxima once the oscillation has decayed below the ripple's size near zero.
TEST(TubeGrowthFit, SignedFitIgnoresTheRipple)
{
    for (double sigma : {0.4, -0.4})
    {
        std::vector<double> t, y;
        for (double x = 0.0; x <= 8.0; x += 2e-5)
        {
            t.push_back(x);
            y.push_back(std::exp(sigma * x) * std::sin(20.0 * x) + 0.0005 * std::sin(460.0 * x));
        }
        const auto fit = unilag::tube::fitGrowthSigned(t, y, 1.0);
        ASSERT_TRUE(fit.ok);
        EXPECT_NEAR(fit.peaks, 2 * 20.0 * 7.0 / (2 * M_PI), 2.0); // two per period over t in [1, 8]
        EXPECT_NEAR(fit.growthRate, sigma, 0.01 * std::abs(sigma)) << "sigma " << sigma;
        EXPECT_NEAR(fit.frequency, 20.0, 0.02);
    }
}

//! A flutter that saturates into a limit cycle of amplitude 0.1: below 0.01 the fit sees the linear growth only.
TEST(TubeGrowthFit, SaturationIsLeftOutBelowTheCap)
{
    std::vector<double> t, y;
    for (double x = 0.0; x <= 20.0; x += 1e-4)
    {
        t.push_back(x);
        y.push_back(std::min(1e-4 * std::exp(0.5 * x), 0.1) * std::sin(20.0 * x));
    }
    const auto capped = unilag::tube::fitGrowthSigned(t, y, 0.5, 0.01);
    ASSERT_TRUE(capped.ok);
    EXPECT_NEAR(capped.growthRate, 0.5, 2e-3);
    const auto whole = unilag::tube::fitGrowthSigned(t, y, 0.5);
    EXPECT_LT(whole.growthRate, 0.4); // the plateau pulls an uncapped fit down
}

TEST(TubeGrowthFit, WhirlWithoutPeaks)
{
    Series s;
    for (double t = 0.0; t <= 4.0; t += 1e-3)
    {
        s.t.push_back(t);
        s.a.push_back(1e-3 * std::exp(0.25 * t));
    }
    const auto fit = fitGrowth(s.t, s.a, 1.0);
    ASSERT_TRUE(fit.ok);
    EXPECT_EQ(fit.peaks, 0);
    EXPECT_NEAR(fit.growthRate, 0.25, 1e-12);
}

TEST(TubeGrowthFit, UnderFourPeaksIsNotAnOscillationFit)
{
    const Series s = planar(0.1, 1.0, 3.0, 1e-2); // half a period after t = 1: one peak
    const auto fit = fitGrowth(s.t, s.a, 1.0);
    EXPECT_LT(fit.peaks, 4);
    EXPECT_EQ(fit.frequency, 0.0); // no frequency claimed from the log fit
}

} // namespace
