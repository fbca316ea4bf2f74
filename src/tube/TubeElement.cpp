#include "tube/TubeElement.hpp"

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

std::unique_ptr<TubeElement> makeElement(TubeModel model)
{
    if (model != TubeModel::EulerBernoulli)
        throw std::logic_error("only the Euler-Bernoulli element exists (docs/tube-model.md 7)");
    return std::make_unique<HermiteBeamElement>();
}

} // namespace unilag::tube
