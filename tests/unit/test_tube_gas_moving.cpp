// The gas in a stretched, moving tube (kernels/unilag/TubeGas.hpp with a metric, docs/tube-gas.md 5): computed
// shocks satisfy the talk's three Rankine-Hugoniot relations with Gamma, gamma of the tube (tube.md 1.8), move at
// the exact speed of the tube frame's Riemann problem and raise the entropy; a gas in a spinning tube holds its
// centrifugal equilibrium to second order and conserves mass and the frozen tube's energy to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tube/RankineHugoniot.hpp"
#include "tube/RiemannExact.hpp"
#include "tube/TubeGas.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;

//! The tube as the gas sees it, from Gamma (tangent r', stretched) and gamma (velocity r_t), both uniform.
struct Tube
{
    std::array<double, 3> Gamma, gamma;
    std::array<double, 3> metric() const
    {
        const auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b)
        { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        return {dot(Gamma, Gamma), dot(Gamma, gamma), dot(gamma, gamma)};
    }
};

} // namespace

TEST(TubeGasMovingTube, ShocksSatisfyTheTalksRankineHugoniotRelations)
{
    const double d = std::sqrt(0.75);
    const Tube tubes[] = {
        {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},      // rigid straight tube: classical Euler
        {{1.2 * d, 0.6, 0.0}, {0.3, -0.5, 0.2}}, // stretched 20%, moving obliquely
        {{0.8, 0.0, 0.0}, {0.7, 0.0, 0.0}},      // compressed 20%, sliding along its axis
        {{0.0, 1.1, 0.0}, {-0.4, 0.9, 0.0}},     // stretched 10%, moving against the gas and across
    };
    const GasPrimitive left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1}; // Sod, at rest relative to the tube
    const RiemannExact exact(left, right, kGamma);
    const double pStar = exact.starPressure(), aRight = std::sqrt(kGamma * right.p / right.rho);
    const double relativeShockSpeed = right.u + aRight * std::sqrt((kGamma + 1.0) / (2.0 * kGamma) * pStar / right.p +
                                                                   (kGamma - 1.0) / (2.0 * kGamma));
    for (const Tube& tube : tubes)
    {
        const std::array<double, 3> m = tube.metric();
        GasSetup setup;
        setup.cells = 800;
        TubeGas gas(setup);
        gas.setMetric(m);
        gas.setState([&](double s) { return s < 0.3 ? left : right; });
        const double level = 0.5 * (pStar + right.p), t1 = 0.12, t2 = 0.2;
        gas.advanceTo(t1);
        const double s1 = gas.shockPosition(level);
        gas.advanceTo(t2);
        const double s2 = gas.shockPosition(level);
        const double cs = (s2 - s1) / (t2 - t1), csExact = relativeShockSpeed / std::sqrt(m[0]);
        const GasFields f = gas.fields();
        const std::vector<std::array<double, 3>> metric(f.s.size(), m);
        const ShockSide behind = shockSide(f, metric, s2 - 0.07, s2 - 0.02, s2, kGamma),
                        ahead = shockSide(f, metric, s2 + 0.02, s2 + 0.07, s2, kGamma);
        const std::array<double, 3> defect = rankineHugoniotDefects(behind, ahead, cs, m);
        std::printf("tube |G|^2 %.3f G.g %+.3f |g|^2 %.3f: shock speed %.5f (exact %.5f), RH defects %.1e %.1e %.1e, "
                    "entropy jump %.4f\n",
                    m[0], m[1], m[2], cs, csExact, defect[0], defect[1], defect[2],
                    behind.entropy(kGamma) - ahead.entropy(kGamma));
        EXPECT_NEAR(cs / csExact, 1.0, 5e-3);
        for (double r : defect)
            EXPECT_LT(r, 0.01);
        EXPECT_GT(behind.entropy(kGamma) - ahead.entropy(kGamma), 0.0);
    }
}

namespace
{

/*! A tube spinning at rate omega about an axis through s = -s0, perpendicular to it: frozen metric (1, 0, k),
 *  k = omega^2 (s + s0)^2. The isentropic equilibrium of the rotating frame has enthalpy h = h0 + k/2. */
struct SpinningTube
{
    double omega = 2.0, s0 = 0.5, rho0 = 1.0, p0 = 1.0;
    double k(double s) const { return omega * omega * (s + s0) * (s + s0); }
    GasPrimitive equilibrium(double s) const
    {
        const double h0 = kGamma / (kGamma - 1.0) * p0 / rho0, ratio = 1.0 + 0.5 * k(s) / h0; // h / h0
        const double rho = rho0 * std::pow(ratio, 1.0 / (kGamma - 1.0));
        return GasPrimitive{rho, 0.0, p0 * std::pow(rho / rho0, kGamma)};
    }
};

} // namespace

TEST(TubeGasMovingTube, SpinningTubeHoldsItsCentrifugalEquilibrium)
{
    const SpinningTube spin;
    double previous = 0;
    for (int cells : {50, 100, 200})
    {
        GasSetup setup;
        setup.cells = cells;
        TubeGas gas(setup);
        gas.setMetric({}, [&](double s) { return std::array<double, 3>{1.0, 0.0, spin.k(s)}; });
        gas.setState([&](double s) { return spin.equilibrium(s); });
        const double m0 = gas.mass(), e0 = gas.energy();
        gas.advanceTo(1.0); // about 1.3 sound crossings
        const GasFields f = gas.fields();
        // L1 |v|: the wall cells' mirror ghosts miss the equilibrium's pressure slope (first order there, in two
        // cells), so the maximum falls as h and the L1 norm as h^2
        double vmax = 0, l1 = 0;
        for (double v : f.u)
            vmax = std::max(vmax, std::abs(v)), l1 += std::abs(v) / cells;
        const double dm = gas.mass() / m0 - 1.0, de = gas.energy() / e0 - 1.0;
        std::printf("spinning tube, %d cells: L1 |v| %.3e (ratio %.2f), max |v| %.2e, dM/M %.1e, dE/E %.1e\n", cells,
                    l1, previous / l1, vmax, dm, de);
        EXPECT_LT(std::abs(dm), 1e-13);
        EXPECT_LT(std::abs(de), 1e-12);
        EXPECT_LT(vmax, 0.04); // the sound speed is about 1.2: a wrong centrifugal term drives v of O(0.3)
        if (previous > 0)
        {
            EXPECT_GT(previous / l1, 3.0); // second order: 4 in the limit
        }
        previous = l1;
    }
}
