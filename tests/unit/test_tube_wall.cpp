// The expandable wall coupled to the gas (src/tube/TubeWall.cpp, src/tube/GasWallCoupling.cpp,
// kernels/unilag/TubeWall.hpp): wall coefficients and the quasi-static law, mass and total energy with closed
// ends (with and without wall viscosity), a gas at rest on an equilibrium wall, the compliant pulse speed; the
// axial tension a_s: total energy with a shock and closed ends, the dispersion of a linear wall wave.
// Measured figures: docs/tube-wall.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tube/GasWallCoupling.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;
constexpr double kPi = 3.14159265358979323846;

GasSetup closedTube(int cells)
{
    GasSetup g;
    g.cells = cells;
    g.gamma = kGamma;
    return g; // Wall ends by default
}

//! A nondimensional wall: R0 = 0.1, p_ext = 1, a = 0.01, b = 50 (bulge limit p - p_ext = 7.96).
WallCoefficients testWall(double viscosity = 0.0, double tension = 0.0)
{
    WallCoefficients w;
    w.a = 0.01;
    w.b = 50.0;
    w.c = viscosity;
    w.as = tension;
    w.restRadius = 0.1;
    w.pExt = 1.0;
    return w;
}

//! Pressure-weighted centroid of p - p0 over s > from.
double pulseCentroid(const GasFields& f, double p0, double from)
{
    double sw = 0, sws = 0;
    for (size_t j = 0; j < f.s.size(); ++j)
        if (f.s[j] > from)
            sw += f.p[j] - p0, sws += (f.p[j] - p0) * f.s[j];
    return sws / sw;
}

} // namespace

TEST(TubeWallCoefficients, MaterialFormulasAndQuasiStaticLaw)
{
    WallMaterial m; // latex-like: E 1 MPa, nu 0.5, h 1 mm, rho_w 1000, R0 5 mm
    const WallCoefficients w = wallCoefficients(m, 101325.0);
    EXPECT_NEAR(w.a, 1000.0 * 2 * kPi * 5e-3 * 1e-3, 1e-15);
    EXPECT_NEAR(w.b, 2 * kPi * 1e6 * 1e-3 / (5e-3 * 0.75), 1e-6);
    const double p = 101325.0 + 5e4, r = equilibriumRadius(w, p);
    EXPECT_NEAR((p - w.pExt) * 2 * kPi * r, w.b * (r - w.restRadius), 1e-9 * w.b * r);
    const double dp = 1.0, dadp = (kPi * std::pow(equilibriumRadius(w, p + dp), 2) -
                                   kPi * std::pow(equilibriumRadius(w, p - dp), 2)) /
                                  (2 * dp);
    EXPECT_NEAR(compliance(w, p), dadp, 1e-6 * dadp);
    EXPECT_THROW(equilibriumRadius(w, w.pExt + 1.001 * w.b / (2 * kPi)), std::domain_error);
    EXPECT_EQ(w.as, 0.0);
    m.axialTension = 80.0; // N/m
    EXPECT_NEAR(wallCoefficients(m, 101325.0).as, 2 * kPi * 5e-3 * 80.0, 1e-15);
    m.axialTension = -1.0;
    EXPECT_THROW(wallCoefficients(m, 101325.0), std::invalid_argument);
    // a rigid wall (b -> infinity) gives back the gas sound speed
    WallCoefficients rigid = w;
    rigid.b = 1e30;
    EXPECT_NEAR(compliantSpeed(rigid, 1.2, 101325.0, kGamma), std::sqrt(kGamma * 101325.0 / 1.2), 1e-9);
}

TEST(TubeWallConservation, ClosedEndsKeepMassAndTotalEnergy)
{
    for (double viscosity : {0.0, 0.05})
    {
        GasWallCoupling tube(closedTube(200), testWall(viscosity));
        // 4:1 pressure jump; the wall starts at R0 everywhere, out of equilibrium with both pressures
        tube.setState([](double) { return 0.1; },
                      [](double s) {
                          return s < 0.5 ? GasPrimitive{4.0, 0.0, 4.0} : GasPrimitive{1.0, 0.0, 1.0};
                      });
        const double m0 = tube.mass();
        const CoupledEnergy e0 = tube.energy();
        double maxWallEnergyChange = 0.0, maxDrift = 0.0;
        int steps = 0;
        for (int k = 1; k <= 8; ++k)
        {
            steps += tube.advanceTo(0.25 * k);
            const CoupledEnergy e = tube.energy();
            maxDrift = std::max(maxDrift, std::abs(e.total() + e.wall.dissipated - e0.total()) / e0.total());
            maxWallEnergyChange = std::max(maxWallEnergyChange, std::abs(e.gas - e0.gas) / e0.total());
        }
        const CoupledEnergy e = tube.energy();
        const double dm = std::abs(tube.mass() - m0) / m0;
        std::printf("closed tube, c = %.2f, %d steps to t = 2: dM/M %.2e, max |dE_total|/E %.2e, "
                    "max |dE_gas|/E %.2e, dissipated/E %.2e\n",
                    viscosity, steps, dm, maxDrift, maxWallEnergyChange, e.wall.dissipated / e0.total());
        EXPECT_LT(dm, 1e-13);
        EXPECT_LT(maxDrift, 1e-10);
        EXPECT_GT(maxWallEnergyChange, 1e-3); // the wall really takes up and gives back energy
        if (viscosity > 0.0)
        {
            EXPECT_GT(e.wall.dissipated / e0.total(), 1e-4);
        }
    }
}

TEST(TubeWallEquilibrium, GasAtRestOnAnEquilibriumWallStaysAtRest)
{
    const WallCoefficients w = testWall();
    const double p = 3.0, r = equilibriumRadius(w, p);
    GasWallCoupling tube(closedTube(100), w);
    tube.setState([r](double) { return r; }, [p](double s) { return GasPrimitive{1.0 + 0.5 * s, 0.0, p}; });
    tube.advanceTo(1.0);
    const GasFields f = tube.gas().fields();
    const WallFields wf = tube.wall().fields();
    double du = 0, dp = 0, dr = 0;
    for (size_t j = 0; j < f.s.size(); ++j)
    {
        du = std::max(du, std::abs(f.u[j]));
        dp = std::max(dp, std::abs(f.p[j] - p));
        dr = std::max(dr, std::abs(wf.radius[j] - r));
    }
    std::printf("gas at rest, R = %.6f: max |u| %.2e, max |p - p0| %.2e, max |R - R_eq| %.2e\n", r, du, dp, dr);
    EXPECT_LT(du, 1e-12);
    EXPECT_LT(dp, 1e-12);
    EXPECT_LT(dr, 1e-14);
}

TEST(TubeWallPulse, SmallPulseTravelsAtTheCompliantSpeed)
{
    // quasi-static, light, damped wall: b = 5.6 pi makes (rho/A) dA/dp = 4 pi / b = 1/a^2, so c = a / sqrt 2;
    // the wall frequency (W''/a)^(1/2) = 375 is 13 times k c = 28 of the pulse (width 0.03), and c = 0.08 is
    // a damping ratio 0.43. Undamped, the wall inertia makes the pulse 0.44% slow (docs/tube-wall.md 3).
    WallCoefficients w;
    w.a = 2.5e-4;
    w.b = 5.6 * kPi;
    w.c = 0.08;
    w.restRadius = 0.1;
    w.pExt = 1.0;
    const double rho = 1.0, p0 = 1.0, c = compliantSpeed(w, rho, p0, kGamma);
    const double a = std::sqrt(kGamma * p0 / rho);
    GasWallCoupling tube(closedTube(800), w);
    auto pressure = [p0](double s) { return p0 * (1.0 + 1e-4 * std::exp(-std::pow((s - 0.3) / 0.03, 2))); };
    // a right-running simple wave: u = (p - p0)/(rho c), rho - rho0 = (p - p0)/c^2, R on the quasi-static law
    tube.setState([&](double s) { return equilibriumRadius(w, pressure(s)); },
                  [&](double s)
                  {
                      const double dp = pressure(s) - p0;
                      return GasPrimitive{rho * std::pow(pressure(s) / p0, 1.0 / kGamma), dp / (rho * c), p0 + dp};
                  });
    tube.advanceTo(0.1);
    const double x1 = pulseCentroid(tube.gas().fields(), p0, 0.1);
    const int steps = tube.advanceTo(0.4);
    const double x2 = pulseCentroid(tube.gas().fields(), p0, 0.1);
    const double speed = (x2 - x1) / 0.3;
    std::printf("compliant pulse: a %.5f, c theory %.5f, measured %.5f (rel. %.2e), %d steps\n", a, c, speed,
                speed / c - 1.0, steps);
    EXPECT_NEAR(speed / c, 1.0, 0.01);
}

/*! Axial tension a_s = 0.02 (tension wave speed (a_s/a)^(1/2) = 1.41, the gas's 1.18-2.4): the 4:1 jump makes
 *  R' large at the driver edge. The exchange with tension is one tridiagonal Newton system; the total energy
 *  gas + wall (tension included) + viscous loss must still be conserved to round-off. */
TEST(TubeWallTension, ClosedEndsKeepTotalEnergyWithTension)
{
    for (double viscosity : {0.0, 0.05})
    {
        GasWallCoupling tube(closedTube(200), testWall(viscosity, 0.02));
        tube.setState([](double) { return 0.1; },
                      [](double s) {
                          return s < 0.5 ? GasPrimitive{4.0, 0.0, 4.0} : GasPrimitive{1.0, 0.0, 1.0};
                      });
        const double m0 = tube.mass();
        const CoupledEnergy e0 = tube.energy();
        double maxDrift = 0.0, maxTension = 0.0;
        int steps = 0;
        for (int k = 1; k <= 4; ++k) // to t = 1: the shock has been reflected at the right end
        {
            steps += tube.advanceTo(0.25 * k);
            const CoupledEnergy e = tube.energy();
            maxDrift = std::max(maxDrift, std::abs(e.total() + e.wall.dissipated - e0.total()) / e0.total());
            maxTension = std::max(maxTension, e.wall.tension / e0.total());
        }
        const double dm = std::abs(tube.mass() - m0) / m0;
        std::printf("closed tube with tension a_s = 0.02, c = %.2f, %d steps to t = 1: dM/M %.2e, "
                    "max |dE_total|/E %.2e, max tension energy/E %.2e\n",
                    viscosity, steps, dm, maxDrift, maxTension);
        EXPECT_LT(dm, 1e-13);
        EXPECT_LT(maxDrift, 1e-12);
        EXPECT_GT(maxTension, 1e-5); // the tension really holds energy
    }
}

/*! A standing wall wave R = R0 + eps cos(k s), k = 4 pi (L = 1, 100 cells: an exact eigenvector of the Neumann
 *  second difference at the cell centres), from rest, in a gas at p0 = p_ext = 1e-4, rho0 = 1. a_s k^2 = 2 b, so the
 *  tension carries two thirds of the stiffness. Linearised about that rest state (docs/tube-wall.md 3), the coupled
 *  dispersion is  a w^2 = b + a_s k^2 - 4 pi g p0 w^2 / (k^2 c^2 - w^2),  c^2 = g p0 / rho0;  its wall branch, with
 *  the grid's k_h^2 = (4/h^2) sin^2(k h/2) for the tension, is what cell 0 must oscillate at. The gas shifts
 *  w by 5.9e-6 (4 pi g p0 = 1.8e-3 against b + a_s k^2 = 150), the continuous k^2 by -4.3e-4. */
TEST(TubeWallTension, LinearWallWaveHasTheDiscreteDispersion)
{
    const int cells = 100;
    const double h = 1.0 / cells, k = 4.0 * kPi, p0 = 1e-4;
    WallCoefficients w = testWall(0.0, 2.0 * 50.0 / (k * k));
    w.pExt = p0;
    GasWallCoupling tube(closedTube(cells), w, 0.05);
    const double eps = 1e-6 * w.restRadius;
    tube.setState([&](double s) { return w.restRadius + eps * std::cos(k * s); },
                  [p0](double) {
                      return GasPrimitive{1.0, 0.0, p0};
                  });
    const double kh2 = 4.0 / (h * h) * std::pow(std::sin(0.5 * k * h), 2);
    const double stiffness = w.b + w.as * kh2, gasStiffness = 4.0 * kPi * kGamma * p0, kc2 = k * k * kGamma * p0;
    // the larger root X = w^2 of a X^2 - (a k^2 c^2 + stiffness + gasStiffness) X + stiffness k^2 c^2 = 0
    const double sum = w.a * kc2 + stiffness + gasStiffness;
    const double omegaCoupled = std::sqrt((sum + std::sqrt(sum * sum - 4.0 * w.a * stiffness * kc2)) / (2.0 * w.a));
    const double omegaWall = std::sqrt(stiffness / w.a), omegaContinuous = std::sqrt((w.b + w.as * k * k) / w.a);
    // zero crossings of R_0 - R0, interpolated linearly between steps, over about six periods
    std::vector<double> crossings;
    double previous = tube.wall().fields().radius[0] - w.restRadius, tPrevious = 0.0;
    const double tEnd = 6.2 * 2.0 * kPi / omegaWall;
    while (tube.time() < tEnd)
    {
        tube.step(tube.stableStep());
        const double now = tube.wall().fields().radius[0] - w.restRadius;
        if ((previous > 0.0) != (now > 0.0))
            crossings.push_back(tPrevious + (tube.time() - tPrevious) * previous / (previous - now));
        previous = now;
        tPrevious = tube.time();
    }
    ASSERT_GE(crossings.size(), 10u);
    const double omega = kPi * (crossings.size() - 1) / (crossings.back() - crossings.front());
    std::printf("wall wave k = 4 pi, a_s k^2 = 2 b: omega %.6f; coupled discrete %.6f (rel. %.2e), wall alone "
                "%.6f (rel. %.2e), continuous %.6f (rel. %.2e); %zu zero crossings\n",
                omega, omegaCoupled, omega / omegaCoupled - 1.0, omegaWall, omega / omegaWall - 1.0, omegaContinuous,
                omega / omegaContinuous - 1.0, crossings.size());
    EXPECT_NEAR(omega / omegaCoupled, 1.0, 2e-6);
}
