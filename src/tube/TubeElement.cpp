#include "tube/TubeElement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace unilag::tube
{
namespace
{

//! Hermite cubic shape functions on [0, h] at t = x / h and their first two x-derivatives.
struct HermiteValues
{
    std::array<double, 4> n, d1, d2;
};

HermiteValues hermite(double t, double h)
{
    HermiteValues v;
    v.n = {1 - 3 * t * t + 2 * t * t * t, h * (t - 2 * t * t + t * t * t), 3 * t * t - 2 * t * t * t,
           h * (-t * t + t * t * t)};
    v.d1 = {(-6 * t + 6 * t * t) / h, 1 - 4 * t + 3 * t * t, (6 * t - 6 * t * t) / h, -2 * t + 3 * t * t};
    v.d2 = {(-6 + 12 * t) / (h * h), (-4 + 6 * t) / h, (6 - 12 * t) / (h * h), (-2 + 6 * t) / h};
    return v;
}

// 4-point Gauss-Legendre on [0, 1]
constexpr double kGaussT[4] = {0.5 - 0.4305681557970263, 0.5 - 0.1699905217924281, 0.5 + 0.1699905217924281,
                               0.5 + 0.4305681557970263};
constexpr double kGaussW[4] = {0.3478548451374538 / 2, 0.6521451548625461 / 2, 0.6521451548625461 / 2,
                               0.3478548451374538 / 2};

/*! The interdependent (Timoshenko) interpolation of (w, psi) on [0, h] for shear compliance S: the static solution
 *  psi = b0 + b1 x + b2 x^2, w = c + b0 x + b1 x^2 / 2 + b2 (x^3 / 3 - 2 S x), whose shear strain w' - psi = -2 S b2
 *  is constant. basis[i] = (c, b0, b1, b2) of the function with nodal values (w1, psi1, w2, psi2) = e_i. */
struct TimoshenkoBasis
{
    std::array<std::array<double, 4>, 4> basis;
    double shear;

    TimoshenkoBasis(double h, double shear) : shear(shear)
    {
        const double d = h * h * h * h / 6.0 + 2.0 * shear * h * h, a = h * h * h / 3.0 - 2.0 * shear * h;
        for (int i = 0; i < 4; ++i)
        {
            const double w1 = i == 0, psi1 = i == 1, w2 = i == 2, psi2 = i == 3;
            const double r1 = w2 - w1 - psi1 * h, r2 = psi2 - psi1; // w(h), psi(h) less the c, b0 parts
            basis[i] = {w1, psi1, (r1 * h * h - a * r2) / d, (0.5 * h * h * r2 - h * r1) / d};
        }
    }
    double w(int i, double x) const
    {
        const auto& q = basis[i];
        return q[0] + q[1] * x + q[2] * x * x / 2 + q[3] * (x * x * x / 3 - 2 * shear * x);
    }
    double dw(int i, double x) const { return psi(i, x) + shearStrain(i); }
    double psi(int i, double x) const { return basis[i][1] + basis[i][2] * x + basis[i][3] * x * x; }
    double dpsi(int i, double x) const { return basis[i][2] + 2 * basis[i][3] * x; }
    double shearStrain(int i) const { return -2.0 * shear * basis[i][3]; }
    //! (w' - psi)_i (w' - psi)_j / S = 4 S b2_i b2_j: written without 1/S so that S = 0 is the Euler-Bernoulli limit
    double shearEnergy(int i, int j) const { return 4.0 * shear * basis[i][3] * basis[j][3]; }
};

// local dofs of the geometric element: node-major (x, w, psi)
constexpr int kX[2] = {0, 3};
//! The element dof of the Timoshenko basis function i (w1, psi1, w2, psi2).
constexpr int kWPsi[4] = {1, 2, 4, 5};

} // namespace

ElementMatrices HermiteBeamElement::matrices(double h) const
{
    ElementMatrices e;
    e.size = 4;
    for (auto* m : {&e.inertia, &e.bending, &e.centrifugal, &e.coriolis})
        m->assign(16, 0.0);
    for (int q = 0; q < 4; ++q)
    {
        const HermiteValues v = hermite(kGaussT[q], h);
        const double w = kGaussW[q] * h;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
            {
                e.at(e.inertia, i, j) += w * v.n[i] * v.n[j];
                e.at(e.bending, i, j) += w * v.d2[i] * v.d2[j];
                e.at(e.centrifugal, i, j) += w * v.d1[i] * v.d1[j];
                e.at(e.coriolis, i, j) += w * v.n[i] * v.d1[j];
            }
    }
    return e;
}

std::vector<double> HermiteBeamElement::endTerm(double h, bool atRight) const
{
    const HermiteValues v = hermite(atRight ? 1.0 : 0.0, h);
    std::vector<double> m(16);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            m[i * 4 + j] = v.n[i] * v.d1[j];
    return m;
}

std::vector<int> HermiteBeamElement::constrained(EndCondition end) const
{
    switch (end)
    {
    case EndCondition::Clamped:
        return {0, 1};
    case EndCondition::Pinned:
        return {0};
    case EndCondition::Free:
        return {};
    }
    return {};
}

ElementMatrices GeometricElement::matrices(double h) const
{
    ElementMatrices e;
    e.size = 6;
    for (auto* m : {&e.inertia, &e.bending, &e.centrifugal, &e.coriolis, &e.areaStiffening})
        m->assign(36, 0.0);
    const TimoshenkoBasis b(h, p_.shear);
    const double stiffening = p_.areaStiffening();
    for (int q = 0; q < 4; ++q)
    {
        const double x = kGaussT[q] * h, wq = kGaussW[q] * h;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
            {
                const int r = kWPsi[i], c = kWPsi[j];
                e.at(e.inertia, r, c) += wq * (b.w(i, x) * b.w(j, x) + p_.rotary * b.psi(i, x) * b.psi(j, x));
                e.at(e.bending, r, c) += wq * (b.dpsi(i, x) * b.dpsi(j, x) + b.shearEnergy(i, j));
                e.at(e.centrifugal, r, c) += wq * b.dw(i, x) * b.dw(j, x);
                e.at(e.coriolis, r, c) += wq * b.w(i, x) * b.dw(j, x);
                e.at(e.areaStiffening, r, c) += wq * stiffening * b.dpsi(i, x) * b.dpsi(j, x);
            }
    }
    /* axial: linear x, inertia h/6 [2 1; 1 2], stiffness [1 -1; -1 1] / (h extension). x decouples from (w, psi)
     * about the straight state; extension 0 (inextensible) is floored at 1e-9 so that the no-flow eigenproblem
     * keeps the bending eigenvalues to ~1e-6 (its absolute error scales with the largest entry). */
    const double axial = 1.0 / (h * std::max(p_.extension, 1e-9));
    for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c)
        {
            e.at(e.inertia, kX[a], kX[c]) = h * (a == c ? 2.0 : 1.0) / 6.0;
            e.at(e.bending, kX[a], kX[c]) = a == c ? axial : -axial;
        }
    return e;
}

std::vector<double> GeometricElement::endTerm(double h, bool atRight) const
{
    const TimoshenkoBasis b(h, p_.shear);
    const double x = atRight ? h : 0.0;
    std::vector<double> m(36, 0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            m[kWPsi[i] * 6 + kWPsi[j]] = b.w(i, x) * b.dw(j, x);
    return m;
}

std::vector<int> GeometricElement::constrained(EndCondition end) const
{
    switch (end)
    {
    case EndCondition::Clamped:
        return {0, 1, 2};
    case EndCondition::Pinned:
        return {0, 1};
    case EndCondition::Free:
        return {};
    }
    return {};
}

std::unique_ptr<TubeElement> makeElement(TubeModel model, const GeometricParameters& geometric)
{
    if (model == TubeModel::Geometric)
        return std::make_unique<GeometricElement>(geometric);
    return std::make_unique<HermiteBeamElement>();
}

} // namespace unilag::tube
