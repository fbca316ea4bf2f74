// GPR point-wise physics (kernels/unilag/Gpr.hpp), continued from test_gpr_kernels.cpp: the elastic stress, the
// exact strain relaxation (det, limits, eigenvectors, monotone decay, agreement with RK4 of the matrix ODE), the
// plastic relaxation, the heat relaxation, and a device (parallel_for / parallel_reduce) run.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "unilag/Gpr.hpp"
#include "Sym3Fixture.hpp"

namespace
{

using namespace unilag::gpr;
using namespace unilag_test;

// ---- elastic stress and energy ----

TEST(GprStress, IsotropicIsZero)
{
    for (double a : {0.3, 1.0, 1.7})
    {
        EXPECT_EQ(maxAbs(shearStress(2.0, 3.0, identity(a))), 0.0);
        EXPECT_EQ(elasticEnergy(3.0, identity(a)), 0.0);
    }
}

TEST(GprStress, SimpleShear)
{
    const double rho = 1.7, csh = 2.3, mu = rho * csh * csh;
    for (double gam : {1e-6, 1e-3, 0.1, 0.5})
    {
        // F = I + gam e_x e_y, A = F^{-1} = I - gam e_x e_y, G = A^T A
        const Sym3 G{1.0, 1.0 + gam * gam, 1.0, -gam, 0.0, 0.0};
        const Sym3 s = shearStress(rho, csh, G);
        EXPECT_NEAR(s.xy, mu * gam * (1.0 + 2.0 * gam * gam / 3.0), 1e-15 * mu); // linear limit: mu gamma
        EXPECT_EQ(s.xz, 0.0);
        EXPECT_EQ(s.yz, 0.0);
        // full-matrix reference -rho csh^2 (G G - tr(G)/3 G)
        const M3 g = full(G), gg = mul(g, g);
        const double t3 = trace(G) / 3.0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(s(i, j), -mu * (gg[i][j] - t3 * g[i][j]), 1e-14 * mu);
        EXPECT_NEAR(elasticEnergy(csh, G), 0.25 * csh * csh * norm2(dev(G)), 1e-15);
    }
    // random G: the symmetric product equals the full product G dev(G) (they commute)
    std::mt19937 rng(9);
    for (int t = 0; t < 100; ++t)
    {
        const Sym3 G = randomSpd(rng, 0.4);
        const Sym3 s = shearStress(rho, csh, G);
        const M3 g = full(G), d = full(dev(G)), gd = mul(g, d);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(s(i, j), -mu * gd[i][j], 1e-13 * mu * maxAbs(G) * maxAbs(G));
    }
}

TEST(GprStrain, Tau1FromViscosity)
{
    EXPECT_DOUBLE_EQ(tau1FromViscosity(1e-2, 1.0, 5.0), 6.0 * 1e-2 / 25.0);
    // the scene reader's operation order, bit for bit
    const double mu = 0.0173, rho0 = 1.37, csh = 2.91;
    EXPECT_EQ(tau1FromViscosity(mu, rho0, csh), 6.0 * mu / (rho0 * csh * csh));
}

// ---- strain relaxation ----

//! Reference: RK4 of the matrix ODE dG/dt = -k G dev(G) with frozen k over unit time, n steps (kdt = k dt).
Sym3 rk4Relax(Sym3 G, double kdt, int n)
{
    const double h = 1.0 / n;
    auto f = [&](const Sym3& g) { return (-kdt) * symProduct(g, dev(g)); };
    for (int i = 0; i < n; ++i)
    {
        const Sym3 k1 = f(G), k2 = f(G + (0.5 * h) * k1), k3 = f(G + (0.5 * h) * k2), k4 = f(G + h * k3);
        G = G + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    return G;
}

std::vector<Sym3> relaxSamples()
{
    std::vector<Sym3> gs;
    std::mt19937 rng(21);
    for (int t = 0; t < 6; ++t)
        gs.push_back(randomSpd(rng, 0.35));
    gs.push_back(Sym3{1.0, 1.25, 1.0, -0.5, 0.0, 0.0});                // simple shear 0.5
    gs.push_back(withEigen(randomRotation(rng), 0.02, 1.0, 30.0));     // strongly anisotropic
    gs.push_back(0.3 * withEigen(randomRotation(rng), 0.5, 0.5, 2.0)); // double eigenvalue, det != 1
    return gs;
}

TEST(RelaxStrain, DeterminantPreserved)
{
    // det of an SPD tensor stored in doubles is only defined to ~cond(G) * eps (rounding G's entries alone, or
    // rebuilding it from its own eigenpairs, moves det that much), so the bound is 1e-13 up to cond = 100 and
    // grows with cond beyond (the strongly anisotropic sample has cond = 1500).
    double worst = 0.0;
    for (const Sym3& G : relaxSamples())
    {
        const Eigen3 e = eigen(G);
        const double tol = 1e-13 * std::max(1.0, e.value[2] / e.value[0] / 100.0);
        for (double tau1 : {1e-14, 1e-6, 1e-2, 1.0, 1e14})
            for (double dt : {1e-8, 1e-4, 1.0})
            {
                const Sym3 R = relaxStrain(G, dt, tau1);
                const double rel = std::fabs(det(R) / det(G) - 1.0);
                EXPECT_LE(rel, tol) << "tau1 " << tau1 << " dt " << dt;
                worst = std::max(worst, rel);
            }
    }
    std::printf("[ info     ] relaxStrain: max relative det change %.2e\n", worst);
}

TEST(RelaxStrain, HydrodynamicLimit)
{
    for (const Sym3& G : relaxSamples())
        for (double dt : {1e-8, 1e-4, 1.0})
        {
            const Sym3 R = relaxStrain(G, dt, 1e-14);
            const double g = std::cbrt(det(G));
            EXPECT_LE(maxDiff(R, identity(g)), 1e-12 * g);
        }
    // tau1 = 0 (ideal fluid) is instantaneous; dt = 0 does nothing
    const Sym3 G = relaxSamples()[0];
    EXPECT_LE(maxDiff(relaxStrain(G, 1e-3, 0.0), identity(std::cbrt(det(G)))), 1e-15);
    EXPECT_TRUE(bitwiseEqual(relaxStrain(G, 0.0, 0.0), G));
}

TEST(RelaxStrain, ElasticLimit)
{
    for (const Sym3& G : relaxSamples())
    {
        // +inf and k dt = 0: bit-for-bit
        EXPECT_TRUE(bitwiseEqual(relaxStrain(G, 1.0, infinity()), G));
        EXPECT_TRUE(bitwiseEqual(relaxStrainKdt(G, 0.0), G));
        const double scale = maxAbs(G);
        for (double dt : {1e-8, 1e-4})
            EXPECT_LE(maxDiff(relaxStrain(G, dt, 1e14), G), 1e-15 * scale) << dt;
        // dt = 1: the exact change -k dt G dev G is ~1e-14 |G| (not below 1e-15): compare with first order
        const double kdt = strainRelaxationRate(G, 1e14) * 1.0;
        const Sym3 first = G - kdt * symProduct(G, dev(G));
        EXPECT_LE(maxDiff(relaxStrain(G, 1.0, 1e14), first), 1e-15 * scale);
    }
}

TEST(RelaxStrain, EigenvectorsPreservedAndMonotoneDecay)
{
    for (const Sym3& G : relaxSamples())
    {
        const Eigen3 e = eigen(G);
        double prev = std::sqrt(norm2(dev(G)));
        for (int k = -6; k <= 3; ++k)
        {
            const double dt = std::pow(10.0, k);
            const Sym3 R = relaxStrain(G, dt, 1.0);
            // V^T R V is diagonal
            double off = 0.0;
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                {
                    if (a == b)
                        continue;
                    double s = 0.0;
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            s += e.vector[i][a] * R(i, j) * e.vector[j][b];
                    off = std::max(off, std::fabs(s));
                }
            EXPECT_LE(off, 1e-14 * maxAbs(G));
            const double nd = std::sqrt(norm2(dev(R)));
            EXPECT_LE(nd, prev * (1.0 + 1e-14)) << dt;
            prev = nd;
        }
    }
}

TEST(RelaxStrain, MatchesRk4Reference)
{
    double worst = 0.0;
    for (const Sym3& G : relaxSamples())
        for (double kgdt : {0.1, 1.0, 5.0, 20.0}) // 20: past the closed-form tail switch for most samples
        {
            // k g dt (g = det^{1/3}) is the dimensionless relaxation time of the deviations near equilibrium
            const double g = std::cbrt(det(G));
            const double kdt = kgdt / g;
            const Eigen3 e = eigen(G);
            const int n = int(std::ceil(kdt * e.value[2] / 1e-3)) + 100; // h k lambda_max <= 1e-3
            const Sym3 ref = rk4Relax(G, kdt, n);
            const Sym3 R = relaxStrainKdt(G, kdt);
            const double err = maxDiff(R, ref) / maxAbs(G);
            EXPECT_LE(err, 1e-10) << "k g dt " << kgdt;
            worst = std::max(worst, err);
        }
    std::printf("[ info     ] relaxStrain vs RK4 (k g dt = 0.1, 1, 5, 20): max rel diff %.2e\n", worst);
}

TEST(RelaxStrain, SemigroupProperty)
{
    // exactness: relaxing by a then by a equals relaxing by 2a
    double worst = 0.0;
    for (const Sym3& G : relaxSamples())
        for (double a : {1e-3, 0.2, 1.5, 20.0})
        {
            const Sym3 one = relaxStrainKdt(G, 2.0 * a);
            const Sym3 two = relaxStrainKdt(relaxStrainKdt(G, a), a);
            const double err = maxDiff(one, two) / maxAbs(G);
            EXPECT_LE(err, 1e-12) << a;
            worst = std::max(worst, err);
        }
    std::printf("[ info     ] relaxStrain semigroup defect: %.2e\n", worst);
}

// ---- plasticity ----

TEST(GprPlastic, VonMises)
{
    EXPECT_NEAR(vonMises(Sym3{-3.0, 0.0, 0.0, 0.0, 0.0, 0.0}), 3.0, 1e-15);
    EXPECT_NEAR(vonMises(Sym3{0.0, 0.0, 0.0, 2.0, 0.0, 0.0}), 2.0 * std::sqrt(3.0), 1e-14);
    EXPECT_EQ(vonMises(identity(-5.0)), 0.0);
    const Sym3 s{1.0, -2.0, 0.5, 0.3, -0.2, 0.7};
    EXPECT_NEAR(vonMises(s + identity(100.0)), vonMises(s), 1e-12); // pressure does not change it
}

//! No deviatoric stress, no plastic flow: the power law's tau1 is infinite and G comes back bit-for-bit.
TEST(GprPlastic, IsotropicStateDoesNotFlow)
{
    const double rho = 1845.0, csh = 9047.0, dt = 1e-7, tau10 = 1e-6, sY = 3.3e8, n = 20.0;
    for (double g : {0.8, 1.0, 1.3})
        EXPECT_TRUE(bitwiseEqual(relaxPlasticStrain(identity(g), rho, csh, dt, tau10, sY, n), identity(g)));
}

/* Plastic relaxation with tau1 consistent with the relaxed state: G = R(G*, kdt) where
 * kdt = dt 6 det^{5/6} / tau1(sigma_bar(G)). Checked by recomputing kdt from the result and relaxing G* with it. */
TEST(GprPlastic, ConsistentRelaxation)
{
    const double rho = 1845.0, csh = 9047.0, sY = 3.3e8, tau10 = 1e-6;
    int plastic = 0;
    for (const Sym3& G : relaxSamples())
        for (double dt : {1e-9, 1e-8, 1e-7, 1e-5})
            for (double n : {2.0, 20.0, 100.0})
            {
                // scale the sample towards isotropy so that sigma_bar spans the yield stress
                for (double eps : {1e-4, 1e-3, 1e-2})
                {
                    const double g = std::cbrt(det(G));
                    const Sym3 Gs = identity(g) + (eps / std::max(1e-300, std::sqrt(norm2(dev(G))))) * dev(G);
                    const Sym3 R = relaxPlasticStrain(Gs, rho, csh, dt, tau10, sY, n);
                    EXPECT_NEAR(det(R), det(Gs), 1e-13 * det(Gs));
                    const double sbar = vonMises(shearStress(rho, csh, R));
                    // the power law tau1 = tau10 (sigma_Y / sigma_bar)^n, which relaxPlasticStrain solves in logs
                    const double kdt = strainRelaxationRate(Gs, tau10 * std::pow(sY / sbar, n)) * dt;
                    const Sym3 check = relaxStrainKdt(Gs, kdt);
                    EXPECT_LE(std::sqrt(norm2(check - R)), 1e-10 * std::sqrt(norm2(Gs))) << dt << " " << n << " " << eps;
                    EXPECT_LE(std::sqrt(norm2(dev(R))), std::sqrt(norm2(dev(Gs))) * (1 + 1e-14));
                    plastic += kdt > 1e-6;
                }
            }
    EXPECT_GT(plastic, 20); // the samples do exercise strong plastic flow
}

TEST(GprPlastic, CostPerCall)
{
    // beryllium, a state 30% past the yield stress, a typical explicit step: reported, not asserted
    const double rho = 1845.0, csh = 9047.0, sY = 3.3e8;
    const Sym3 G0 = relaxSamples()[0];
    const Sym3 Gs = identity(std::cbrt(det(G0))) + (0.0037 / std::sqrt(norm2(dev(G0)))) * dev(G0);
    const double ratio = vonMises(shearStress(rho, csh, Gs)) / sY;
    double sink = 0.0;
    const int calls = 20000;
    const auto t0 = std::chrono::steady_clock::now();
    for (int c = 0; c < calls; ++c)
        sink += relaxPlasticStrain(Gs, rho, csh, 1e-8 * (1.0 + 1e-6 * c), 1e-6, sY, 20.0).xx;
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / calls;
    // warm start, as in a Picard loop: the hint of the previous call (slightly different dt) gives the same answer
    double hint = std::nan("");
    const Sym3 cold = relaxPlasticStrain(Gs, rho, csh, 1e-8, 1e-6, sY, 20.0);
    relaxPlasticStrain(Gs, rho, csh, 1.01e-8, 1e-6, sY, 20.0, &hint);
    const Sym3 warm = relaxPlasticStrain(Gs, rho, csh, 1e-8, 1e-6, sY, 20.0, &hint);
    EXPECT_LE(std::sqrt(norm2(warm - cold)), 1e-13 * std::sqrt(norm2(Gs)));
    const auto t1 = std::chrono::steady_clock::now();
    for (int c = 0; c < calls; ++c)
        sink += relaxPlasticStrain(Gs, rho, csh, 1e-8 * (1.0 + 1e-6 * c), 1e-6, sY, 20.0, &hint).xx;
    const double usWarm = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t1).count() / calls;
    std::printf("[ info     ] relaxPlasticStrain: %.2f us per call cold, %.2f warm (sigma_bar/sigma_Y = %.2f) %g\n", us,
                usWarm, ratio, sink * 0);
    EXPECT_GT(ratio, 1.0);
}

// Transport and relaxation together (exponential integrator): elastic, Navier-Stokes and splitting limits.
TEST(GprStrain, TransportAndRelaxLimits)
{
    const Sym3 G0 = relaxSamples()[6]; // simple shear 0.5
    const Sym3 D{0.3, -0.1, -0.2, 0.25, 0.05, -0.15}; // a traceless rate of deformation
    const double dt = 1e-3;
    const Sym3 dT = (-2.0 * dt) * D; // -dt (G L + L^T G) for G = I, L = D
    // elastic: pure transport
    EXPECT_LE(std::sqrt(norm2(transportAndRelax(G0, dT, dt, infinity()) - (G0 + dT))), 1e-15);
    // Navier-Stokes: k dt = 6 dt / tau1 >> 1 from G = I: dev G -> -(tau1 / 3) dev D (first order in tau1 / dt)
    for (double tau1 : {1e-6, 1e-9, 1e-12})
    {
        const Sym3 G = transportAndRelax(identity(1.0), dT, dt, tau1);
        const Sym3 expect = (-tau1 / 3.0) * dev(D);
        EXPECT_LE(std::sqrt(norm2(dev(G) - expect)), 1e-3 * std::sqrt(norm2(expect))) << tau1;
    }
    // the hydrodynamic limit: the deviator is negligible
    EXPECT_LE(std::sqrt(norm2(dev(transportAndRelax(G0, dT, dt, 1e-14)))), 1e-10);
    // small k dt: agrees with transport-then-relax to O(k dt^2)
    for (double tau1 : {1.0, 10.0})
    {
        const double kdt = strainRelaxationRate(G0, tau1) * dt;
        const Sym3 split = relaxStrain(G0 + dT, dt, tau1);
        EXPECT_LE(std::sqrt(norm2(transportAndRelax(G0, dT, dt, tau1) - split)), 2.0 * kdt * std::sqrt(norm2(dT))) << tau1;
    }
}

// ---- heat ----

TEST(GprHeat, RelaxationFactorLimits)
{
    const double dt = 1e-3, rho = 1.2, rho0 = 1.0, th = 0.7, th0 = 0.5;
    EXPECT_EQ(relaxHeatFactor(dt, 0.0, rho, rho0, th, th0), 0.0);
    EXPECT_LT(relaxHeatFactor(dt, 1e-14, rho, rho0, th, th0), 1e-10);
    EXPECT_EQ(relaxHeatFactor(dt, infinity(), rho, rho0, th, th0), 1.0);
    EXPECT_NEAR(relaxHeatFactor(dt, 1e14, rho, rho0, th, th0), 1.0, 1e-16);
    EXPECT_EQ(relaxHeatFactor(0.0, 0.0, rho, rho0, th, th0), 1.0);
    const double x = dt * rho0 * th / (0.01 * rho * th0);
    EXPECT_DOUBLE_EQ(relaxHeatFactor(dt, 0.01, rho, rho0, th, th0), 1.0 / (1.0 + x));
    // a cold cell (theta at or a round-off below 0) does not relax J, and never amplifies it (it did: 1 / (1 - ...))
    for (const double tau2 : {0.0, 1e-14, 0.01})
    {
        EXPECT_EQ(relaxHeatFactor(dt, tau2, rho, rho0, 0.0, th0), 1.0) << tau2;
        EXPECT_EQ(relaxHeatFactor(dt, tau2, rho, rho0, -1e-18, th0), 1.0) << tau2;
    }
    // kappa <-> tau2
    const double alpha = 2.0, kappa = 1e-2;
    const double tau2 = tau2FromKappa(kappa, alpha, th0, rho0);
    EXPECT_NEAR(kappaFromTau2(tau2, alpha, th0, rho0), kappa, 1e-18);
    EXPECT_DOUBLE_EQ(kappaFromTau2(0.3, alpha, th0, rho0), 0.3 * alpha * alpha * th0 / rho0);
    // the scene reader's operation order, bit for bit: tau2 and kappa through the scale alpha^2 theta0 / rho0
    // (data for which the textbook orders round differently)
    const double a = 2.729, t0 = 1.404, r0 = 2.129, scale = a * a * t0 / r0;
    EXPECT_EQ(kappaFromTau2(0.7889, a, t0, r0), 0.7889 * scale);
    EXPECT_EQ(tau2FromKappa(0.7889, a, t0, r0), 0.7889 / scale);
}

// ---- device-callability ----

//! Pseudo-random SPD tensor of index i (device-side, no RNG state).
KOKKOS_INLINE_FUNCTION Sym3 indexedSpd(int i)
{
    const double t = 0.37 * i;
    const double a = 0.3 * Kokkos::Experimental::sin(t), b = 0.25 * Kokkos::Experimental::cos(1.3 * t),
                 c = 0.2 * Kokkos::Experimental::sin(2.1 * t + 0.4);
    return Sym3{1.0 + a, 1.1 - b, 0.9 + c, 0.5 * b, -0.4 * c, 0.3 * a};
}

KOKKOS_INLINE_FUNCTION double indexedTau1(int i)
{
    return 1e-3 * (1 + i % 7);
}

struct DeviceResults
{
    double eigenErr, detErr, eosErr;
};

//! Kernels through parallel_for / parallel_reduce (a free function: CUDA extended lambdas cannot live in TEST
//! bodies).
DeviceResults runOnDevice(int n, const Kokkos::View<double* [6], unilag::MemSpace>& out)
{
    using unilag::range;
    Kokkos::parallel_for(
        "gpr_test::relax", range(n), KOKKOS_LAMBDA(const int i) {
            const Sym3 R = relaxStrain(indexedSpd(i), 1e-3, indexedTau1(i));
            out(i, 0) = R.xx;
            out(i, 1) = R.yy;
            out(i, 2) = R.zz;
            out(i, 3) = R.xy;
            out(i, 4) = R.xz;
            out(i, 5) = R.yz;
        });
    DeviceResults r{0.0, 0.0, 0.0};
    Kokkos::parallel_reduce(
        "gpr_test::eigen", range(n),
        KOKKOS_LAMBDA(const int i, double& err) {
            const Sym3 G = indexedSpd(i);
            const Sym3 d = fromEigen(eigen(G)) - G;
            err = Kokkos::Experimental::fmax(err, Kokkos::Experimental::sqrt(norm2(d)));
        },
        Kokkos::Max<double>(r.eigenErr));
    Kokkos::parallel_reduce(
        "gpr_test::relax_det", range(n),
        KOKKOS_LAMBDA(const int i, double& err) {
            const Sym3 G = indexedSpd(i);
            const Sym3 R = relaxStrain(G, 1e-3, indexedTau1(i));
            err = Kokkos::Experimental::fmax(err, Kokkos::Experimental::fabs(det(R) / det(G) - 1.0));
        },
        Kokkos::Max<double>(r.detErr));
    Kokkos::parallel_reduce(
        "gpr_test::eos", range(n),
        KOKKOS_LAMBDA(const int i, double& err) {
            const EosParams eos = mieGruneisenEos(8930.0, 3939.0, 2.0, 1.5, 390.0);
            const double rho = 8930.0 * (0.9 + 0.001 * (i % 300)), eps = 1e3 * (i % 11);
            const double p = pressure(eos, rho, eps);
            const double scale = eps + Kokkos::Experimental::fabs(p) / (8930.0 * 2.0);
            err =
                Kokkos::Experimental::fmax(err, Kokkos::Experimental::fabs(internalEnergy(eos, rho, p) - eps) / scale);
        },
        Kokkos::Max<double>(r.eosErr));
    return r;
}

TEST(GprDevice, KernelsRunInParallel)
{
    const int n = 4096;
    Kokkos::View<double* [6], unilag::MemSpace> out("relaxed", n);
    const DeviceResults r = runOnDevice(n, out);
    EXPECT_LE(r.eigenErr, 1e-14);
    EXPECT_LE(r.detErr, 1e-13);
    EXPECT_LE(r.eosErr, 1e-15);
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
    for (int i = 0; i < n; i += 97)
    {
        const Sym3 R = relaxStrain(indexedSpd(i), 1e-3, indexedTau1(i));
        const double v[6] = {R.xx, R.yy, R.zz, R.xy, R.xz, R.yz};
        for (int c = 0; c < 6; ++c)
            EXPECT_EQ(h(i, c), v[c]); // same code on the host and in the kernel
    }
}

} // namespace
