/*! \file Sym3.hpp
 *  \brief Symmetric 3x3 tensors for the GPR kernels: algebra, deviator, transport rate G L + L^T G, and a Jacobi
 *  eigen-decomposition (G_e, stress).
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{
namespace gpr
{

namespace kmath = Kokkos::Experimental;

// ------------------------------------------------------------------------------------------------------------
// Symmetric 3x3 tensors
// ------------------------------------------------------------------------------------------------------------

//! Symmetric 3x3 tensor (six independent entries).
struct Sym3
{
    double xx, yy, zz, xy, xz, yz;

    //! Entry (i, j), i, j in {0, 1, 2}.
    KOKKOS_INLINE_FUNCTION double operator()(int i, int j) const
    {
        if (i == j)
            return i == 0 ? xx : (i == 1 ? yy : zz);
        const int s = i + j; // 1: xy, 2: xz, 3: yz
        return s == 1 ? xy : (s == 2 ? xz : yz);
    }
};

//! a I.
KOKKOS_INLINE_FUNCTION Sym3 identity(double a = 1.0)
{
    return Sym3{a, a, a, 0.0, 0.0, 0.0};
}

//! \brief Entry-wise sum.
KOKKOS_INLINE_FUNCTION Sym3 operator+(const Sym3& a, const Sym3& b)
{
    return Sym3{a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.xz + b.xz, a.yz + b.yz};
}
//! \brief Entry-wise difference.
KOKKOS_INLINE_FUNCTION Sym3 operator-(const Sym3& a, const Sym3& b)
{
    return Sym3{a.xx - b.xx, a.yy - b.yy, a.zz - b.zz, a.xy - b.xy, a.xz - b.xz, a.yz - b.yz};
}
//! \brief Scalar multiple.
KOKKOS_INLINE_FUNCTION Sym3 operator*(double s, const Sym3& a)
{
    return Sym3{s * a.xx, s * a.yy, s * a.zz, s * a.xy, s * a.xz, s * a.yz};
}

//! \brief tr A.
KOKKOS_INLINE_FUNCTION double trace(const Sym3& a)
{
    return a.xx + a.yy + a.zz;
}

/*! \brief det A by cofactors (relative accuracy ~eps lambda_max^3/|det|; det G_e = (rho/rho0)^2 without
 *  relaxation, docs/gpr-model.md 1.1). */
KOKKOS_INLINE_FUNCTION double det(const Sym3& a)
{
    return a.xx * (a.yy * a.zz - a.yz * a.yz) - a.xy * (a.xy * a.zz - a.yz * a.xz) + a.xz * (a.xy * a.yz - a.yy * a.xz);
}

/*! \brief Deviator dev A = A - tr(A)/3 I (docs/gpr-model.md 1.2). The diagonal is formed as (2 a - b - c)/3 so that an
 *  isotropic tensor has an exactly zero deviator. */
KOKKOS_INLINE_FUNCTION Sym3 dev(const Sym3& a)
{
    const double third = 1.0 / 3.0;
    return Sym3{third * (2.0 * a.xx - a.yy - a.zz),
                third * (2.0 * a.yy - a.xx - a.zz),
                third * (2.0 * a.zz - a.xx - a.yy),
                a.xy,
                a.xz,
                a.yz};
}

//! Double contraction A : B = tr(A B).
KOKKOS_INLINE_FUNCTION double ddot(const Sym3& a, const Sym3& b)
{
    return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + 2.0 * (a.xy * b.xy + a.xz * b.xz + a.yz * b.yz);
}

//! Squared Frobenius norm |A|^2 = A : A.
KOKKOS_INLINE_FUNCTION double norm2(const Sym3& a)
{
    return ddot(a, a);
}

//! Symmetric part of the product, (A B + B A)/2 (equal to A B when A and B commute, e.g. G and dev G).
KOKKOS_INLINE_FUNCTION Sym3 symProduct(const Sym3& a, const Sym3& b)
{
    Sym3 r;
    r.xx = a.xx * b.xx + a.xy * b.xy + a.xz * b.xz;
    r.yy = a.xy * b.xy + a.yy * b.yy + a.yz * b.yz;
    r.zz = a.xz * b.xz + a.yz * b.yz + a.zz * b.zz;
    // (AB)_ij = sum_k a_ik b_kj, averaged with (BA)_ij = (AB)_ji
    r.xy = 0.5 * ((a.xx * b.xy + a.xy * b.yy + a.xz * b.yz) + (a.xy * b.xx + a.yy * b.xy + a.yz * b.xz));
    r.xz = 0.5 * ((a.xx * b.xz + a.xy * b.yz + a.xz * b.zz) + (a.xz * b.xx + a.yz * b.xy + a.zz * b.xz));
    r.yz = 0.5 * ((a.xy * b.xz + a.yy * b.yz + a.yz * b.zz) + (a.xz * b.xy + a.yz * b.yy + a.zz * b.yz));
    return r;
}

//! A^2 (symmetric).
KOKKOS_INLINE_FUNCTION Sym3 square(const Sym3& a)
{
    return symProduct(a, a);
}

/*! \brief Transport rate G L + L^T G of the G_e equation (docs/gpr-model.md 1.1 (1e), 2.2 (2e)); L(i, j) = dv_i/dx_j
 *  (in 2D pass L with a zero third row and column). */
KOKKOS_INLINE_FUNCTION Sym3 transportRate(const Sym3& g, const Mat<3>& L)
{
    double x[3][3]; // X = G L; the result is X + X^T
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            x[i][j] = g(i, 0) * L.a[0][j] + g(i, 1) * L.a[1][j] + g(i, 2) * L.a[2][j];
    return Sym3{2.0 * x[0][0], 2.0 * x[1][1], 2.0 * x[2][2], x[0][1] + x[1][0], x[0][2] + x[2][0], x[1][2] + x[2][1]};
}

//! Eigen-decomposition A = sum_k value[k] v_k v_k^T, ascending values; vector[i][k] is component i of v_k.
struct Eigen3
{
    double value[3];
    double vector[3][3];
};

/*! \brief Eigen-decomposition of a symmetric 3x3 tensor by cyclic Jacobi rotations (at most 32 sweeps; a 3x3
 *  matrix converges quadratically in 4-6). Rotations use the stable tangent formula, and an off-diagonal entry
 *  is set to zero once it no longer changes the diagonal in floating point, so the loop ends with an exactly
 *  diagonal matrix. Eigenvectors are orthonormal to round-off; the values are sorted ascending. */
KOKKOS_INLINE_FUNCTION Eigen3 eigen(const Sym3& A)
{
    double a[3][3] = {{A.xx, A.xy, A.xz}, {A.xy, A.yy, A.yz}, {A.xz, A.yz, A.zz}};
    double v[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    constexpr int maxSweeps = 32;
    for (int sweep = 0; sweep < maxSweeps; ++sweep)
    {
        if (a[0][1] == 0.0 && a[0][2] == 0.0 && a[1][2] == 0.0)
            break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q)
            {
                const double apq = a[p][q];
                if (apq == 0.0)
                    continue;
                const double g = 100.0 * kmath::fabs(apq);
                const double app = kmath::fabs(a[p][p]), aqq = kmath::fabs(a[q][q]);
                if (app + g == app && aqq + g == aqq)
                {
                    a[p][q] = a[q][p] = 0.0; // negligible (< 1e-18 of both diagonal entries): drop it
                    continue;
                }
                const double theta = 0.5 * (a[q][q] - a[p][p]) / apq;
                double t;
                if (kmath::fabs(theta) > 1e150)
                    t = 0.5 / theta; // theta^2 would overflow; t ~ 1/(2 theta)
                else
                    t = 1.0 / (kmath::fabs(theta) + kmath::sqrt(theta * theta + 1.0));
                if (theta < 0.0)
                    t = -t;
                const double c = 1.0 / kmath::sqrt(t * t + 1.0);
                const double s = t * c;
                a[p][p] -= t * apq;
                a[q][q] += t * apq;
                a[p][q] = a[q][p] = 0.0;
                const int r = 3 - p - q; // the remaining index
                const double arp = a[r][p], arq = a[r][q];
                a[r][p] = a[p][r] = c * arp - s * arq;
                a[r][q] = a[q][r] = s * arp + c * arq;
                for (int i = 0; i < 3; ++i)
                {
                    const double vip = v[i][p], viq = v[i][q];
                    v[i][p] = c * vip - s * viq;
                    v[i][q] = s * vip + c * viq;
                }
            }
    }
    Eigen3 e;
    int idx[3] = {0, 1, 2};
    // sort ascending (three elements: insertion sort)
    for (int i = 1; i < 3; ++i)
        for (int j = i; j > 0 && a[idx[j]][idx[j]] < a[idx[j - 1]][idx[j - 1]]; --j)
        {
            const int tmp = idx[j];
            idx[j] = idx[j - 1];
            idx[j - 1] = tmp;
        }
    for (int k = 0; k < 3; ++k)
    {
        e.value[k] = a[idx[k]][idx[k]];
        for (int i = 0; i < 3; ++i)
            e.vector[i][k] = v[i][idx[k]];
    }
    return e;
}

//! sum_k lam[k] v_k v_k^T with v_k the columns of vec (reconstruction from eigenpairs).
KOKKOS_INLINE_FUNCTION Sym3 fromEigen(const double (&lam)[3], const double (&vec)[3][3])
{
    Sym3 r{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < 3; ++k)
    {
        const double x = vec[0][k], y = vec[1][k], z = vec[2][k], l = lam[k];
        r.xx += l * x * x;
        r.yy += l * y * y;
        r.zz += l * z * z;
        r.xy += l * x * y;
        r.xz += l * x * z;
        r.yz += l * y * z;
    }
    return r;
}

//! \brief Reconstruction from an Eigen3.
KOKKOS_INLINE_FUNCTION Sym3 fromEigen(const Eigen3& e)
{
    return fromEigen(e.value, e.vector);
}

} // namespace gpr
} // namespace unilag
