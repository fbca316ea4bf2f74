/*! \file Sym3Fixture.hpp
 *  \brief Helpers of the GPR point-wise tests (test_gpr_kernels.cpp, test_gpr_relaxation.cpp): full 3x3 matrices of
 *  symmetric tensors, random rotations and SPD tensors with given eigenvalues, bitwise and relative comparisons. */
#pragma once

#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include "unilag/Gpr.hpp"

namespace unilag_test
{

using namespace unilag::gpr;
using M3 = std::array<std::array<double, 3>, 3>;

inline M3 full(const Sym3& a)
{
    M3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m[i][j] = a(i, j);
    return m;
}

inline M3 mul(const M3& a, const M3& b)
{
    M3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                r[i][j] += a[i][k] * b[k][j];
    return r;
}

inline double maxAbs(const Sym3& a)
{
    double m = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m = std::max(m, std::fabs(a(i, j)));
    return m;
}

inline double maxDiff(const Sym3& a, const Sym3& b)
{
    return maxAbs(a - b);
}

inline bool bitwiseEqual(const Sym3& a, const Sym3& b)
{
    return std::memcmp(&a, &b, sizeof(Sym3)) == 0;
}

//! Random rotation (orthonormal columns) from Gram-Schmidt of a Gaussian matrix.
inline M3 randomRotation(std::mt19937& rng)
{
    std::normal_distribution<double> n(0.0, 1.0);
    M3 q;
    for (int k = 0; k < 3; ++k)
    {
        double v[3] = {n(rng), n(rng), n(rng)};
        for (int p = 0; p < k; ++p)
        {
            const double d = v[0] * q[0][p] + v[1] * q[1][p] + v[2] * q[2][p];
            for (int i = 0; i < 3; ++i)
                v[i] -= d * q[i][p];
        }
        const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int i = 0; i < 3; ++i)
            q[i][k] = v[i] / l;
    }
    return q;
}

inline Sym3 withEigen(const M3& q, double l0, double l1, double l2)
{
    const double lam[3] = {l0, l1, l2};
    double vec[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            vec[i][k] = q[i][k];
    return fromEigen(lam, vec);
}

//! Random SPD tensor A^T A with A = I + scale * N(0,1).
inline Sym3 randomSpd(std::mt19937& rng, double scale)
{
    std::normal_distribution<double> n(0.0, 1.0);
    M3 a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[i][j] = (i == j ? 1.0 : 0.0) + scale * n(rng);
    M3 g{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                g[i][j] += a[k][i] * a[k][j];
    return Sym3{g[0][0], g[1][1], g[2][2], g[0][1], g[0][2], g[1][2]};
}

} // namespace unilag_test
