// GPR point-wise physics (kernels/unilag/Gpr.hpp): symmetric tensors and the Jacobi eigen-solver, the three
// equations of state (inverse, isentropic sound speed, limits, the neo-Hookean sign). The elastic stress and the
// strain, plastic and heat relaxations: test_gpr_relaxation.cpp.
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

// ---- symmetric tensors and the eigen-solver ----

TEST(GprSym3, HelpersMatchFullMatrices)
{
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0.0, 1.0);
    for (int t = 0; t < 50; ++t)
    {
        const Sym3 a = randomSpd(rng, 0.7), b = randomSpd(rng, 0.7);
        const M3 A = full(a), B = full(b), AB = mul(A, B), BA = mul(B, A);
        EXPECT_DOUBLE_EQ(trace(a), A[0][0] + A[1][1] + A[2][2]);
        const double detRef = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                              A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                              A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
        EXPECT_NEAR(det(a), detRef, 1e-13 * std::fabs(detRef));
        EXPECT_NEAR(trace(dev(a)), 0.0, 1e-14 * trace(a));
        EXPECT_NEAR(ddot(a, b), AB[0][0] + AB[1][1] + AB[2][2], 1e-13 * std::sqrt(norm2(a) * norm2(b)));
        const Sym3 s = symProduct(a, b);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(s(i, j), 0.5 * (AB[i][j] + BA[i][j]), 1e-13 * maxAbs(a) * maxAbs(b));
        // transport rate G L + L^T G with a general L
        unilag::Mat<3> L;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                L.a[i][j] = n(rng);
        const Sym3 r = transportRate(a, L);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
            {
                double ref = 0.0;
                for (int k = 0; k < 3; ++k)
                    ref += A[i][k] * L.a[k][j] + L.a[k][i] * A[k][j];
                EXPECT_NEAR(r(i, j), ref, 1e-12 * maxAbs(a));
            }
    }
    EXPECT_EQ(maxAbs(dev(identity(0.7))), 0.0); // exactly zero for an isotropic tensor
}

void checkEigen(const Sym3& a, double tolRec, double tolOrth)
{
    const Eigen3 e = eigen(a);
    const double scale = maxAbs(a); // not the Frobenius norm: it underflows for the 1e-300 case
    EXPECT_LE(maxDiff(fromEigen(e), a), tolRec * scale);
    EXPECT_LE(e.value[0], e.value[1]);
    EXPECT_LE(e.value[1], e.value[2]);
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
        {
            double d = 0.0;
            for (int i = 0; i < 3; ++i)
                d += e.vector[i][k] * e.vector[i][l];
            EXPECT_NEAR(d, k == l ? 1.0 : 0.0, tolOrth);
        }
}

TEST(GprSym3, EigenRandomSpd)
{
    std::mt19937 rng(11);
    for (int t = 0; t < 2000; ++t)
        checkEigen(randomSpd(rng, t % 2 ? 0.3 : 2.0), 1e-13, 1e-14);
}

TEST(GprSym3, EigenHardCases)
{
    std::mt19937 rng(5);
    for (int t = 0; t < 200; ++t)
    {
        const M3 q = randomRotation(rng);
        checkEigen(withEigen(q, 1.0, 1.0, 2.0), 1e-13, 1e-14);          // double eigenvalue
        checkEigen(withEigen(q, 3.0, 3.0, 3.0 + 1e-12), 1e-13, 1e-14);  // nearly triple
        checkEigen(withEigen(q, 1e-6, 1.0, 1e6), 1e-13, 1e-14);         // ill-conditioned
        checkEigen(withEigen(q, -2.0, 0.5, 4.0), 1e-13, 1e-14);         // indefinite
        checkEigen(withEigen(q, 1e-300, 2e-300, 3e-300), 1e-13, 1e-14); // tiny
    }
    checkEigen(identity(2.0), 0.0, 0.0);
    checkEigen(Sym3{1.0, 2.0, 3.0, 0.0, 0.0, 0.0}, 0.0, 0.0);
    checkEigen(Sym3{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 0.0);
    checkEigen(Sym3{1.0, 1.0, 1.0, 1e-200, 0.0, 0.0}, 1e-15, 1e-15); // 45-degree rotation
}

// ---- equations of state ----

EosParams copper()
{
    return mieGruneisenEos(8930.0, 3939.0, 2.0, 1.5, 390.0);
}
EosParams rubber()
{
    return neoHookeanEos(1100.0, 73.0, 1000.0);
}

TEST(EosInverse, IdealGas)
{
    const EosParams e = idealGasEos(1.4, 2.5);
    for (double rho : {1e-3, 0.125, 1.0, 7.0, 1e3})
        for (double eps : {1e-8, 1e-2, 1.0, 2.5e3})
        {
            const double p = pressure(e, rho, eps);
            EXPECT_NEAR(internalEnergy(e, rho, p), eps, 4e-16 * eps);
            EXPECT_NEAR(pressure(e, rho, internalEnergy(e, rho, p)), p, 4e-16 * p);
            EXPECT_DOUBLE_EQ(temperature(e, rho, eps), eps / 2.5);
        }
}

TEST(EosInverse, MieGruneisen)
{
    const EosParams e = copper();
    for (double eta : {0.7, 0.9, 0.999, 1.0, 1.001, 1.1, 1.3, 1.8})
        for (double eps : {0.0, 1.0, 1e3, 1e5, 1e6})
        {
            const double rho = eta * e.rho0;
            const double p = pressure(e, rho, eps);
            // round-off scale: the cold-curve term rho0 c0^2 f cancels in eps = (p - rho0 c0^2 f)/(rho0 Gamma0)
            const double scale = std::fabs(eps) + std::fabs(p) / (e.rho0 * e.Gamma0);
            EXPECT_NEAR(internalEnergy(e, rho, p), eps, 1e-15 * scale) << eta << " " << eps;
            EXPECT_NEAR(pressure(e, rho, internalEnergy(e, rho, p)), p, 1e-15 * (std::fabs(p) + e.rho0 * e.c0 * e.c0));
        }
}

TEST(EosInverse, NeoHookeanBarotropic)
{
    const EosParams e = rubber();
    for (double eta : {0.3, 0.8, 0.99, 1.0, 1.01, 1.2, 2.0, 5.0})
    {
        const double rho = eta * e.rho0;
        const double epsB = internalEnergy(e, rho, 0.0); // barotrope energy, p ignored
        const double p = pressure(e, rho, epsB);
        EXPECT_EQ(pressure(e, rho, 123.0), p); // eps ignored
        EXPECT_EQ(internalEnergy(e, rho, p), epsB);
        EXPECT_GE(epsB, 0.0);
    }
}

//! Isentropic derivative by finite differences: integrate d eps = p / rho^2 d rho (RK4) to rho +- h.
double isentropicC2(const EosParams& e, double rho, double eps)
{
    const double h = 1e-4 * rho;
    auto f = [&](double r, double x) { return pressure(e, r, x) / (r * r); };
    auto integrate = [&](double target)
    {
        double r = rho, x = eps;
        const int n = 8;
        const double dr = (target - rho) / n;
        for (int i = 0; i < n; ++i)
        {
            const double k1 = f(r, x), k2 = f(r + 0.5 * dr, x + 0.5 * dr * k1), k3 = f(r + 0.5 * dr, x + 0.5 * dr * k2),
                         k4 = f(r + dr, x + dr * k3);
            x += dr / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            r += dr;
        }
        return pressure(e, target, x);
    };
    return (integrate(rho + h) - integrate(rho - h)) / (2.0 * h);
}

TEST(EosSoundSpeed, MatchesIsentropicDerivative)
{
    struct Case
    {
        EosParams e;
        std::vector<double> rho, eps;
    };
    const EosParams ig = idealGasEos(1.4, 2.5), mg = copper(), nh = rubber();
    const Case cases[] = {
        {ig, {1e-3, 0.5, 1.0, 6.0}, {1e-3, 1.0, 2.5e3}},
        {mg, {0.8 * mg.rho0, 0.97 * mg.rho0, mg.rho0, 1.05 * mg.rho0, 1.4 * mg.rho0}, {0.0, 1e4, 1e6}},
        {nh, {0.4 * nh.rho0, 0.9 * nh.rho0, nh.rho0, 1.1 * nh.rho0, 2.5 * nh.rho0}, {0.0}},
    };
    double worst = 0.0;
    for (const Case& c : cases)
        for (double rho : c.rho)
            for (double eps : c.eps)
            {
                const double p = pressure(c.e, rho, eps);
                const double c2 = soundSpeed2(c.e, rho, p);
                const double fd = isentropicC2(c.e, rho, eps);
                EXPECT_GT(c2, 0.0);
                EXPECT_NEAR(c2, fd, 1e-6 * c2) << "type " << c.e.type << " rho " << rho << " eps " << eps;
                worst = std::max(worst, std::fabs(c2 - fd) / c2);
            }
    std::printf("[ info     ] soundSpeed2 vs isentropic finite difference: max rel diff %.2e\n", worst);
}

TEST(EosMieGruneisen, LinearLimit)
{
    const EosParams e = copper();
    EXPECT_EQ(pressure(e, e.rho0, 0.0), 0.0);
    EXPECT_NEAR(soundSpeed2(e, e.rho0, 0.0), e.c0 * e.c0, 1e-15 * e.c0 * e.c0);
    // small compression: p ~ rho0 c0^2 (eta - 1)
    EXPECT_NEAR(pressure(e, (1.0 + 1e-7) * e.rho0, 0.0) / (e.rho0 * e.c0 * e.c0 * 1e-7), 1.0, 1e-6);
    // Grueneisen term: dp/deps|_rho = rho0 Gamma0
    EXPECT_NEAR(pressure(e, 1.2 * e.rho0, 10.0) - pressure(e, 1.2 * e.rho0, 0.0), 10.0 * e.rho0 * e.Gamma0,
                1e-6 * 10.0 * e.rho0 * e.Gamma0);
}

TEST(EosNeoHookean, SignAndConsistency)
{
    const EosParams e = rubber();
    const double G = e.rho0 * e.csh * e.csh;
    EXPECT_EQ(pressure(e, e.rho0, 0.0), 0.0);
    EXPECT_EQ(internalEnergy(e, e.rho0, 0.0), 0.0);
    EXPECT_NEAR(soundSpeed2(e, e.rho0, 0.0), e.csh * e.csh, 1e-15 * e.csh * e.csh);
    // p > 0 in compression, < 0 in tension, increasing in rho everywhere
    double prev = -1e300;
    for (int k = 0; k <= 400; ++k)
    {
        const double eta = 0.1 * std::pow(100.0, k / 400.0); // eta = rho/rho0 in [0.1, 10]
        const double rho = eta * e.rho0;
        const double p = pressure(e, rho, 0.0);
        if (eta > 1.0)
        {
            EXPECT_GT(p, 0.0);
        }
        else if (eta < 1.0)
        {
            EXPECT_LT(p, 0.0);
        }
        EXPECT_GT(p, prev);
        EXPECT_GT(soundSpeed2(e, rho, p), 0.0);
        prev = p;
        // thermodynamic consistency: d eps/d rho = p / rho^2 (central difference, O(h^2) ~ 1e-10 csh^2/rho0)
        const double h = 1e-5 * rho;
        const double dedr = (internalEnergy(e, rho + h, 0.0) - internalEnergy(e, rho - h, 0.0)) / (2.0 * h);
        EXPECT_NEAR(dedr, p / (rho * rho), 1e-7 * std::fabs(p / (rho * rho)) + 1e-9 * e.csh * e.csh / e.rho0) << eta;
    }
    // small strain: p ~ G (eta - 1), i.e. small-strain bulk modulus G
    EXPECT_NEAR(pressure(e, (1.0 + 1e-6) * e.rho0, 0.0) / (G * 1e-6), 1.0, 1e-5);
}

} // namespace
