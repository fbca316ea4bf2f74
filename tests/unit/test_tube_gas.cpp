// The compressible gas in a rigid tube (src/tube/TubeGas.cpp, kernels/unilag/TubeGas.hpp) and the exact Riemann
// solver (src/tube/RiemannExact.cpp): Sod against the exact solution with the observed order, shock Mach numbers
// against the normal-shock relation (tube.md 3), conservation with closed ends, a gas at rest in a varying tube,
// and the characteristic ends. Measured figures: docs/tube-gas.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <vector>

#include "tube/RiemannExact.hpp"
#include "tube/TubeGas.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;

GasEnd end(GasEndType type, GasPrimitive state = {}) { return GasEnd{type, state}; }

//! The reservoir at rest from which a flow w expands isentropically (SubsonicInflow's data).
GasPrimitive reservoirOf(const GasPrimitive& w)
{
    const double m2 = w.u * w.u * w.rho / (kGamma * w.p), f = 1.0 + 0.5 * (kGamma - 1.0) * m2;
    return GasPrimitive{w.rho * std::pow(f, 1.0 / (kGamma - 1.0)), 0.0, w.p * std::pow(f, kGamma / (kGamma - 1.0))};
}

//! A/A* of isentropic flow at Mach number m.
double areaRatio(double m)
{
    const double g = kGamma;
    return std::pow(2.0 / (g + 1.0) * (1.0 + 0.5 * (g - 1.0) * m * m), 0.5 * (g + 1.0) / (g - 1.0)) / m;
}

//! L1 norm of rho - exact over the tube, the exact Riemann solution centred at x0 at time t.
double densityErrorL1(const GasFields& f, const RiemannExact& exact, double x0, double t, double h)
{
    double sum = 0.0;
    for (size_t j = 0; j < f.s.size(); ++j)
        sum += h * std::abs(f.rho[j] - exact.sample((f.s[j] - x0) / t).rho);
    return sum;
}

double slopeLeastSquares(const std::vector<double>& x, const std::vector<double>& y)
{
    double mx = 0, my = 0;
    for (size_t i = 0; i < x.size(); ++i)
        mx += x[i] / x.size(), my += y[i] / y.size();
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxy / sxx;
}

} // namespace

TEST(TubeGasRiemann, ToroTestsAndShockRelations)
{
    // Toro, Riemann Solvers, table 4.2: tests 1 (Sod) and 3
    const RiemannExact sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, kGamma);
    EXPECT_NEAR(sod.starPressure(), 0.30313, 1e-5);
    EXPECT_NEAR(sod.starVelocity(), 0.92745, 1e-5);
    const RiemannExact strong({1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, kGamma);
    EXPECT_NEAR(strong.starPressure(), 460.894, 1e-3);
    EXPECT_NEAR(strong.starVelocity(), 19.5975, 1e-4);
    // tube.md 3: p2/p1 = 2, 5, 10 -> M_s = 1.363, 2.104, 2.952; the post-shock state solves the Riemann problem
    const double ratio[3] = {2, 5, 10}, mach[3] = {1.363, 2.104, 2.952};
    for (int i = 0; i < 3; ++i)
    {
        const double m = shockMachFromPressureRatio(ratio[i], kGamma);
        EXPECT_NEAR(m, mach[i], 5e-4);
        const GasPrimitive ahead{1.0, 0.0, 1.0}, behind = postShockState(ahead, m, kGamma);
        EXPECT_NEAR(behind.p, ratio[i], 1e-12);
        const RiemannExact r(behind, ahead, kGamma);
        EXPECT_NEAR(r.starPressure(), behind.p, 1e-10 * behind.p);
        EXPECT_NEAR(r.starVelocity(), behind.u, 1e-10);
    }
}

TEST(TubeGasSod, ConvergesToTheExactSolution)
{
    const GasPrimitive left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
    const RiemannExact exact(left, right, kGamma);
    double error[3];
    const int cells[3] = {100, 200, 400};
    for (int i = 0; i < 3; ++i)
    {
        GasSetup setup;
        setup.cells = cells[i];
        setup.left = end(GasEndType::Transmissive);
        setup.right = end(GasEndType::Transmissive);
        TubeGas gas(setup);
        gas.setState([&](double s) { return s < 0.5 ? left : right; });
        gas.advanceTo(0.2);
        error[i] = densityErrorL1(gas.fields(), exact, 0.5, 0.2, gas.spacing());
    }
    const double order1 = std::log2(error[0] / error[1]), order2 = std::log2(error[1] / error[2]);
    std::printf("Sod L1(rho): %.4e %.4e %.4e (100, 200, 400 cells), observed order %.3f %.3f\n", error[0],
                error[1], error[2], order1, order2);
    EXPECT_LT(error[2], error[1]);
    EXPECT_LT(error[1], error[0]);
    EXPECT_GT(order2, 0.6); // discontinuities cap the order at 1 (contact: 1/2 for a first-order scheme)
    EXPECT_LT(error[2], 4e-3);
}

TEST(TubeGasShock, MachNumberMatchesTheNormalShockRelation)
{
    const GasPrimitive ahead{1.0, 0.0, 1.0};
    const double a1 = std::sqrt(kGamma), ratio[3] = {2, 5, 10};
    for (double pr : ratio)
    {
        const double mach = shockMachFromPressureRatio(pr, kGamma);
        const GasPrimitive behind = postShockState(ahead, mach, kGamma);
        GasSetup setup;
        setup.cells = 400;
        setup.left = end(GasEndType::FixedState, behind); // the piston: the exact post-shock state flows in
        setup.right = end(GasEndType::Transmissive);
        TubeGas gas(setup);
        gas.setState([&](double s) { return s < 0.1 ? behind : ahead; });
        const double tEnd = 0.8 / (mach * a1); // the shock at s = 0.9
        std::vector<double> t, x;
        for (int k = 1; k <= 8; ++k)
        {
            gas.advanceTo(tEnd * k / 8.0);
            t.push_back(gas.time());
            const double level = 0.5 * (ahead.p + behind.p);
            x.push_back(leadingShockPosition(gas.fields(), level));
            EXPECT_DOUBLE_EQ(gas.shockPosition(level), x.back()); // the device search finds the same crossing
        }
        const double measured = slopeLeastSquares(t, x) / a1;
        std::printf("p2/p1 = %4.1f: M_s measured %.5f, relation %.5f, rel. error %.2e\n", pr, measured, mach,
                    measured / mach - 1.0);
        EXPECT_NEAR(measured / mach, 1.0, 5e-3);
    }
}

TEST(TubeGasConservation, ClosedEndsKeepMassAndEnergy)
{
    for (bool varyingArea : {false, true})
    {
        GasSetup setup;
        setup.cells = 200;
        TubeGas gas(setup); // walls at both ends
        if (varyingArea)
            gas.setArea([](double s) { return 1.0 + 0.5 * std::sin(2.0 * M_PI * s); });
        gas.setState([](double s) { return s < 0.3 ? GasPrimitive{1.0, 0.0, 10.0} : GasPrimitive{0.125, 0.0, 0.1}; });
        const double m0 = gas.mass(), e0 = gas.energy();
        const int steps = gas.advanceTo(2.0); // the shock crosses the tube about 5 times
        const double dm = gas.mass() / m0 - 1.0, de = gas.energy() / e0 - 1.0;
        std::printf("closed tube, %s area, %d steps: dM/M %.2e, dE/E %.2e\n", varyingArea ? "varying" : "constant",
                    steps, dm, de);
        EXPECT_LT(std::abs(dm), 1e-13);
        EXPECT_LT(std::abs(de), 1e-10);
    }
}

TEST(TubeGasConservation, DefaultSpaceMatchesSerial)
{
    // The other tests run on Kokkos::Serial (small tubes); the default space must give the same numbers.
    // Few steps: OpenMP launches cost milliseconds each when the cores are oversubscribed.
    GasFields f[2];
    for (int i = 0; i < 2; ++i)
    {
        GasSetup setup;
        setup.cells = 200;
        setup.serialBelow = i == 0 ? 0 : 1024;
        TubeGas gas(setup);
        gas.setArea([](double s) { return 1.0 + 0.5 * std::sin(2.0 * M_PI * s); });
        gas.setState([](double s) { return s < 0.3 ? GasPrimitive{1.0, 0.0, 10.0} : GasPrimitive{0.125, 0.0, 0.1}; });
        for (int k = 0; k < 40; ++k)
            gas.step(gas.stableStep());
        f[i] = gas.fields();
    }
    for (size_t j = 0; j < f[0].s.size(); ++j)
    {
        EXPECT_EQ(f[0].rho[j], f[1].rho[j]);
        EXPECT_EQ(f[0].u[j], f[1].u[j]);
        EXPECT_EQ(f[0].p[j], f[1].p[j]);
    }
}

TEST(TubeGasWellBalanced, GasAtRestInAVaryingTubeStaysAtRest)
{
    GasSetup setup;
    setup.cells = 200;
    TubeGas gas(setup);
    gas.setArea([](double s) { return 1.0 + 0.8 * std::sin(3.0 * M_PI * s) * std::sin(3.0 * M_PI * s); });
    gas.setState([](double s) { return GasPrimitive{1.0 + 0.5 * s + 0.2 * (s > 0.5), 0.0, 1.0}; });
    const int steps = gas.advanceTo(1.0);
    const GasFields f = gas.fields();
    double umax = 0, dpmax = 0;
    for (size_t j = 0; j < f.u.size(); ++j)
        umax = std::max(umax, std::abs(f.u[j])), dpmax = std::max(dpmax, std::abs(f.p[j] - 1.0));
    std::printf("gas at rest, varying tube, %d steps: max |u| %.2e, max |p - 1| %.2e\n", steps, umax, dpmax);
    EXPECT_LT(umax, 1e-13);
    EXPECT_LT(dpmax, 1e-13);
}

TEST(TubeGasEnds, UniformFlowsPassThroughTheOpenEnds)
{
    struct Case
    {
        GasEndType in, out;
        GasPrimitive w; //!< u < 0: the flow enters at the right end, the same recipes mirrored
    };
    const Case cases[3] = {{GasEndType::SubsonicInflow, GasEndType::PressureOutlet, {1.0, 0.3, 1.0}},
                           {GasEndType::SubsonicInflow, GasEndType::PressureOutlet, {1.0, -0.3, 1.0}},
                           {GasEndType::FixedState, GasEndType::Transmissive, {1.0, 2.5, 1.0}}};
    for (const Case& c : cases)
    {
        GasSetup setup;
        setup.cells = 50;
        const GasEnd in = end(c.in, c.in == GasEndType::SubsonicInflow ? reservoirOf(c.w) : c.w);
        const GasEnd out = end(c.out, c.w);
        setup.left = c.w.u > 0.0 ? in : out;
        setup.right = c.w.u > 0.0 ? out : in;
        TubeGas gas(setup);
        gas.setState([&](double) { return c.w; });
        gas.advanceTo(2.0);
        const GasFields f = gas.fields();
        for (size_t j = 0; j < f.u.size(); ++j)
        {
            EXPECT_NEAR(f.rho[j], c.w.rho, 1e-12);
            EXPECT_NEAR(f.u[j], c.w.u, 1e-12);
            EXPECT_NEAR(f.p[j], c.w.p, 1e-12);
        }
    }
}

TEST(TubeGasEnds, PressureOutletDrawsTheExactRarefaction)
{
    // Gas at rest, the right end opened to p = 0.5: the outlet state lies on the outgoing invariant and the
    // isentrope of the gas, so the exact solution is one rarefaction from s = 1 into that state.
    const GasPrimitive rest{1.0, 0.0, 1.0};
    const double pOut = 0.5, a0 = std::sqrt(kGamma);
    const double rhoOut = std::pow(pOut, 1.0 / kGamma), aOut = std::sqrt(kGamma * pOut / rhoOut);
    const GasPrimitive outlet{rhoOut, 2.0 * (a0 - aOut) / (kGamma - 1.0), pOut};
    GasSetup setup;
    setup.cells = 400;
    setup.left = end(GasEndType::Wall);
    setup.right = end(GasEndType::PressureOutlet, GasPrimitive{1.0, 0.0, pOut});
    TubeGas gas(setup);
    gas.setState([&](double) { return rest; });
    const double t = 0.5;
    gas.advanceTo(t);
    const RiemannExact exact(rest, outlet, kGamma);
    const GasFields f = gas.fields();
    double l1 = 0.0;
    for (size_t j = 0; j < f.p.size(); ++j)
        l1 += gas.spacing() * std::abs(f.p[j] - exact.sample((f.s[j] - 1.0) / t).p);
    std::printf("pressure outlet: L1(p - exact) %.2e, last cell p %.4f (outlet %.2f), u %.4f (exact %.4f)\n", l1,
                f.p.back(), pOut, f.u.back(), outlet.u);
    EXPECT_LT(l1, 2e-3);
    EXPECT_NEAR(f.p.back(), pOut, 0.02);
}

TEST(TubeGasEnds, NozzleFromAReservoirSettlesOnTheIsentropicSolution)
{
    // Reservoir (rho0, p0) = (1, 1) -> A = 1 - 0.3 sin^2(pi s) -> outlet at p = 0.9: subsonic, isentropic.
    const double pOut = 0.9, g = kGamma;
    const double machOut = std::sqrt(2.0 / (g - 1.0) * (std::pow(1.0 / pOut, (g - 1.0) / g) - 1.0));
    const double rhoOut = std::pow(pOut, 1.0 / g), fluxExact = rhoOut * machOut * std::sqrt(g * pOut / rhoOut);
    double lo = 1e-3, hi = 1.0; // the throat's Mach number: A_throat / A* = 0.7 A_out / A*, subsonic branch
    for (int it = 0; it < 60; ++it)
        (areaRatio(0.5 * (lo + hi)) > 0.7 * areaRatio(machOut) ? lo : hi) = 0.5 * (lo + hi);
    const double machThroat = 0.5 * (lo + hi);
    double spread[2];
    for (int i = 0; i < 2; ++i)
    {
        GasSetup setup;
        setup.cells = 100 << i;
        setup.left = end(GasEndType::SubsonicInflow, GasPrimitive{1.0, 0.0, 1.0});
        setup.right = end(GasEndType::PressureOutlet, GasPrimitive{1.0, 0.0, pOut});
        TubeGas gas(setup);
        gas.setArea([](double s) { return 1.0 - 0.3 * std::pow(std::sin(M_PI * s), 2); });
        gas.setState([](double) { return GasPrimitive{1.0, 0.0, 1.0}; });
        gas.advanceTo(40.0); // settled: t = 40 and 60 agree to the 5 digits printed
        const GasFields f = gas.fields();
        double qmin = 1e300, qmax = 0, machMax = 0;
        for (size_t j = 0; j < f.s.size(); ++j)
        {
            const double q = f.rho[j] * f.u[j] * f.area[j];
            qmin = std::min(qmin, q), qmax = std::max(qmax, q);
            machMax = std::max(machMax, f.u[j] / std::sqrt(g * f.p[j] / f.rho[j]));
        }
        const double mOut = f.u.back() / std::sqrt(g * f.p.back() / f.rho.back());
        spread[i] = qmax / qmin - 1.0;
        std::printf("nozzle, %d cells: rho u A spread %.2e, flux %.5f (exact %.5f), M throat %.5f (%.5f), "
                    "M outlet %.5f (%.5f)\n",
                    setup.cells, spread[i], qmax, fluxExact, machMax, machThroat, mOut, machOut);
        EXPECT_NEAR(qmax / fluxExact, 1.0, 1e-3);
        EXPECT_NEAR(machMax / machThroat, 1.0, 1e-3);
        EXPECT_NEAR(mOut / machOut, 1.0, 1e-3);
    }
    EXPECT_GT(spread[0] / spread[1], 3.0); // second order
}

TEST(TubeGasSmooth, AdvectedDensityBumpConvergesAtSecondOrder)
{
    // A smooth density bump carried by uniform u = 1, p = 1 (a contact wave: exact solution = the shifted bump)
    const auto bump = [](double s) {
        const double x = (s - 0.3) / 0.2;
        return std::abs(x) < 1.0 ? std::pow(std::cos(0.5 * M_PI * x), 4) : 0.0;
    };
    const double t = 0.4;
    double error[3];
    const int cells[3] = {100, 200, 400};
    for (int i = 0; i < 3; ++i)
    {
        GasSetup setup;
        setup.cells = cells[i];
        setup.left = end(GasEndType::FixedState, GasPrimitive{1.0, 1.0, 1.0});
        setup.right = end(GasEndType::Transmissive);
        TubeGas gas(setup);
        gas.setState([&](double s) { return GasPrimitive{1.0 + 0.5 * bump(s), 1.0, 1.0}; });
        gas.advanceTo(t);
        const GasFields f = gas.fields();
        error[i] = 0.0;
        for (size_t j = 0; j < f.s.size(); ++j)
            error[i] += gas.spacing() * std::abs(f.rho[j] - 1.0 - 0.5 * bump(f.s[j] - t));
    }
    const double order1 = std::log2(error[0] / error[1]), order2 = std::log2(error[1] / error[2]);
    std::printf("smooth bump L1(rho): %.3e %.3e %.3e (100, 200, 400 cells), observed order %.3f %.3f\n", error[0],
                error[1], error[2], order1, order2);
    EXPECT_GT(order2, 1.6); // van Leer clips the extremum, so a little under 2
}

//! finite() is the gas run's stop test: one non-finite cell, on either execution space, makes it false.
TEST(TubeGasState, FiniteFindsOneBadCell)
{
    for (int serialBelow : {1024, 0})
        for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
        {
            GasSetup setup;
            setup.cells = 50;
            setup.serialBelow = serialBelow;
            TubeGas gas(setup);
            gas.setState([](double) { return GasPrimitive{1.0, 0.0, 1.0}; });
            EXPECT_TRUE(gas.finite());
            gas.setState([bad](double s) { return GasPrimitive{1.0, std::abs(s - 0.51) < 0.005 ? bad : 0.0, 1.0}; });
            EXPECT_FALSE(gas.finite()) << "serialBelow " << serialBelow << ", value " << bad;
        }
}
