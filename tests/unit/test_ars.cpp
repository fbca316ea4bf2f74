// IMEX ARS(2,2,2) kernels (kernels/unilag/Ars.hpp): the backward-Euler strain relaxation G = B - c G dev(G) solves
// its equation from c = 0 (elastic: B bit for bit) to c = 1e30, keeps the Navier-Stokes deviator dev B / (c m) to
// full relative accuracy in the stiff limit, and is continuous where it switches between its two forms (c m = 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "unilag/Ars.hpp"

namespace
{

using namespace unilag::gpr;

double fro(const Sym3& a)
{
    return std::sqrt(norm2(a));
}

Sym3 randomSpd(std::mt19937& rng, double scale)
{
    std::normal_distribution<double> n(0.0, 1.0);
    double a[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[i][j] = (i == j ? 1.0 : 0.0) + scale * n(rng);
    double g[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                g[i][j] += a[k][i] * a[k][j];
    return Sym3{g[0][0], g[1][1], g[2][2], g[0][1], g[0][2], g[1][2]};
}

TEST(ArsImplicitRelax, BetaIsOneMinusHalfSqrt2)
{
    EXPECT_NEAR(unilag::arsBeta, 1.0 - std::sqrt(2.0) / 2.0, 1e-16);
}

TEST(ArsImplicitRelax, ElasticLimitIsIdentityMap)
{
    std::mt19937 rng(3);
    for (int t = 0; t < 20; ++t)
    {
        const Sym3 B = randomSpd(rng, 0.3);
        const Sym3 G = implicitStrainRelax(B, 0.0);
        EXPECT_EQ(G.xx, B.xx);
        EXPECT_EQ(G.yz, B.yz);
        const Sym3 Ginf = implicitStrainRelax(B, strainRelaxationRate(B, infinity()) * 0.1);
        EXPECT_EQ(std::memcmp(&Ginf, &B, sizeof(Sym3)), 0);
    }
}

TEST(ArsImplicitRelax, SolvesBackwardEulerForAnyStiffness)
{
    std::mt19937 rng(7);
    for (double scale : {1e-4, 0.05, 0.3})
        for (double c : {1e-12, 1e-6, 1e-3, 0.1, 0.9, 1.1, 10.0, 1e3, 1e6, 1e13, 1e30})
            for (int t = 0; t < 10; ++t)
            {
                const Sym3 B = randomSpd(rng, scale);
                const Sym3 G = implicitStrainRelax(B, c);
                ASSERT_GT(det(G), 0.0);
                // the equation, relative to its largest terms: |G - B + c G dev G| vs |dev B|; dev G formed from
                // G's entries carries their round-off eps |G|, which c multiplies (the stiff cases: see below)
                const Sym3 res = G - B + c * symProduct(G, dev(G));
                EXPECT_LE(fro(res), 1e-13 * (fro(B) + 1.0) + 1e-12 * fro(dev(B)) + 8e-16 * c * norm2(G))
                    << "c " << c << " scale " << scale;
                // the deviator relaxes (never grows), trace(G) <= trace(B)
                EXPECT_LE(fro(dev(G)), fro(dev(B)) * (1.0 + 1e-12));
                EXPECT_LE(trace(G), trace(B) * (1.0 + 1e-15));
            }
}

TEST(ArsImplicitRelax, NavierStokesDeviatorKeepsItsDigits)
{
    std::mt19937 rng(11);
    for (double c : {1e4, 1e8, 1e13, 1e20, 1e30})
        for (double scale : {1e-6, 1e-2})
        {
            const Sym3 B = randomSpd(rng, scale);
            const Sym3 G = implicitStrainRelax(B, c);
            const double m = trace(G) / 3.0, cm = c * m;
            // dev G = dev B / (c m) (1 + O(|dev B| / (c m^2))): what G's entries can hold of it, i.e. up to their
            // round-off eps m (the increment form B - c G dev G would leave an error eps |dev B|, far above it)
            const double tol = 1e-3 * fro(dev(B)) / cm + 8e-16 * m;
            EXPECT_LE(fro(dev(G) - (1.0 / cm) * dev(B)), tol) << "c " << c << " scale " << scale;
            EXPECT_NEAR(m, trace(B) / 3.0, 1e-15 * trace(B) + norm2(dev(B)) / c);
        }
}

TEST(ArsImplicitRelax, ContinuousAcrossItsTwoForms)
{
    std::mt19937 rng(5);
    for (int t = 0; t < 5; ++t)
    {
        const Sym3 B = randomSpd(rng, 0.2);
        // the form switches at c m = 1 (m slightly below mean(b)); |dG/d ln c| <= |dev B|, so steps of 1e-3 in
        // ln c may change G by about 1e-3 |dev B| at most: a jump between the forms would show
        const double c0 = 3.0 / trace(B);
        Sym3 prev = implicitStrainRelax(B, 0.5 * c0);
        for (int j = 1; j <= 1400; ++j)
        {
            const Sym3 G = implicitStrainRelax(B, 0.5 * c0 * std::exp(1e-3 * j));
            ASSERT_LE(fro(G - prev), 1.01e-3 * fro(dev(B))) << j;
            prev = G;
        }
    }
}

} // namespace
