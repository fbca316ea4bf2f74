/*! \file Gpr.hpp
 *  \brief Point-wise physics of the Godunov-Peshkov-Romenski (GPR) model: symmetric 3x3 tensors with a Jacobi
 *  eigen-solver, the three equations of state, the elastic stress and energy, the strain (G_e) and heat (J)
 *  relaxation sources and the plastic relaxation.
 *
 *  Section numbers cite docs/gpr-model.md, the model and scheme of Boscheri, Chiocchetti & Peshkov (JCP 2022).
 *  Everything is header-only and device-callable (Kokkos core only, Kokkos math functions, no std:: math).
 *  G_e is always a full 3x3 tensor, also in 2D (plane strain keeps G_zz).
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{
namespace gpr
{

namespace kmath = Kokkos::Experimental;

//! +infinity (tau1 of an elastic solid, tau2 without heat relaxation).
KOKKOS_INLINE_FUNCTION constexpr double infinity()
{
    return Kokkos::Experimental::infinity<double>::value;
}

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

// ------------------------------------------------------------------------------------------------------------
// Equations of state, eps(rho, p) (docs/gpr-model.md 1.3)
// ------------------------------------------------------------------------------------------------------------

/*! \brief EOS parameters (plain data, usable in kernels). Only the fields of the chosen type are read:
 *   - IdealGas:     gamma, cv
 *   - MieGruneisen: rho0, c0, Gamma0, s, cv
 *   - NeoHookean:   rho0, csh (modulus G = rho0 csh^2), cv
 *  The neo-Hookean modulus uses the EOS's own csh: docs/gpr-model.md 1.3 uses the shear speed (bulk modulus
 *  K0 = G then); to impose another small-strain bulk modulus K, set csh = sqrt(K / rho0) here. */
struct EosParams
{
    static constexpr int IdealGas = 0;
    static constexpr int MieGruneisen = 1;
    static constexpr int NeoHookean = 2;

    int type;
    double gamma, cv, rho0, c0, Gamma0, s, csh;
};

//! \brief Ideal-gas parameters (docs/gpr-model.md 1.3).
KOKKOS_INLINE_FUNCTION EosParams idealGasEos(double gamma, double cv)
{
    return EosParams{EosParams::IdealGas, gamma, cv, 0.0, 0.0, 0.0, 0.0, 0.0};
}
//! \brief Mie-Grueneisen parameters (docs/gpr-model.md 1.3).
KOKKOS_INLINE_FUNCTION EosParams mieGruneisenEos(double rho0, double c0, double Gamma0, double s, double cv)
{
    return EosParams{EosParams::MieGruneisen, 0.0, cv, rho0, c0, Gamma0, s, 0.0};
}
//! \brief Neo-Hookean parameters, modulus rho0 csh^2 (docs/gpr-model.md 1.3).
KOKKOS_INLINE_FUNCTION EosParams neoHookeanEos(double rho0, double csh, double cv)
{
    return EosParams{EosParams::NeoHookean, 0.0, cv, rho0, 0.0, 0.0, 0.0, csh};
}

namespace detail
{
/*! Mie-Grueneisen reference curve f(eta) = (eta-1)(eta - Gamma0/2 (eta-1)) / (eta - s(eta-1))^2 and its
 *  derivative df/deta, eta = rho/rho0 (docs/gpr-model.md 1.3). Valid for eta < s/(s-1) (denominator > 0). */
KOKKOS_INLINE_FUNCTION void mgCurve(const EosParams& e, double eta, double& f, double& df)
{
    const double x = eta - 1.0;
    const double n = x * (eta - 0.5 * e.Gamma0 * x);
    const double dn = (eta - 0.5 * e.Gamma0 * x) + x * (1.0 - 0.5 * e.Gamma0);
    const double d = eta - e.s * x;
    const double dd = 1.0 - e.s;
    f = n / (d * d);
    df = (dn * d - 2.0 * n * dd) / (d * d * d);
}

/*! Neo-Hookean volume ratio J = rho0/rho: jm1 = J - 1 and lnJ = ln J, both without cancellation near J = 1. */
KOKKOS_INLINE_FUNCTION void nhStrain(const EosParams& e, double rho, double& J, double& jm1, double& lnJ)
{
    jm1 = (e.rho0 - rho) / rho;
    J = e.rho0 / rho;
    lnJ = kmath::log1p(jm1);
}
} // namespace detail

/*! \brief Pressure p(rho, eps) (docs/gpr-model.md 1.3).
 *   - ideal gas: p = (gamma - 1) rho eps;
 *   - Mie-Grueneisen: p = rho0 c0^2 f(eta) + rho0 Gamma0 eps, eta = rho/rho0;
 *   - neo-Hookean (barotropic, eps ignored): p = -(G/2)(J - 1 + ln(J)/J) with J = rho0/rho.
 *
 *  Neo-Hookean sign/variable: written in eta = rho/rho0, p = -(G/2)(eta - 1 + ln(eta)/eta) and
 *  eps = G/(4 rho0)((eta-1)^2 + (ln eta)^2) would give a NEGATIVE p in compression (eta > 1), and p would not be
 *  rho^2 d eps/d rho. In the volume ratio J = det F = rho0/rho = 1/eta (docs/gpr-model.md 1.3),
 *  both formulas are exactly consistent: p = rho^2 d eps/d rho = -rho0 d eps/dJ, p > 0 in compression (J < 1),
 *  p(rho0) = 0, dp/drho = (csh^2/2)(J^2 + 1 - ln J) > 0 for every J > 0 (since ln J <= J - 1 < J^2 + 1). So the
 *  slip is the variable, not the sign; a bare sign flip would agree only to first order in the strain. */
KOKKOS_INLINE_FUNCTION double pressure(const EosParams& e, double rho, double eps)
{
    switch (e.type)
    {
    case EosParams::MieGruneisen:
    {
        double f, df;
        detail::mgCurve(e, rho / e.rho0, f, df);
        return e.rho0 * e.c0 * e.c0 * f + e.rho0 * e.Gamma0 * eps;
    }
    case EosParams::NeoHookean:
    {
        double J, jm1, lnJ;
        detail::nhStrain(e, rho, J, jm1, lnJ);
        const double G = e.rho0 * e.csh * e.csh;
        return -0.5 * G * (jm1 + lnJ / J);
    }
    default:
        return (e.gamma - 1.0) * rho * eps;
    }
}

/*! \brief Specific internal energy eps(rho, p), the inverse of pressure() in eps (docs/gpr-model.md 1.3).
 *  Neo-Hookean is barotropic: the result is eps(rho) = (csh^2/4)((J-1)^2 + (ln J)^2), J = rho0/rho, whatever p. */
KOKKOS_INLINE_FUNCTION double internalEnergy(const EosParams& e, double rho, double p)
{
    switch (e.type)
    {
    case EosParams::MieGruneisen:
    {
        double f, df;
        detail::mgCurve(e, rho / e.rho0, f, df);
        return (p - e.rho0 * e.c0 * e.c0 * f) / (e.rho0 * e.Gamma0);
    }
    case EosParams::NeoHookean:
    {
        double J, jm1, lnJ;
        detail::nhStrain(e, rho, J, jm1, lnJ);
        return 0.25 * e.csh * e.csh * (jm1 * jm1 + lnJ * lnJ); // G/(4 rho0) = csh^2/4
    }
    default:
        return p / ((e.gamma - 1.0) * rho);
    }
}

/*! \brief Squared bulk sound speed c0^2 = dp/drho|_s = dp/drho|_eps + (p/rho^2) dp/deps|_rho (docs/gpr-model.md 1.3),
 *  analytic:
 *   - ideal gas: gamma p / rho;
 *   - Mie-Grueneisen: c0^2 f'(eta) + p Gamma0 rho0 / rho^2 (equals c0^2 at eta = 1, p = 0);
 *   - neo-Hookean: dp/drho = (csh^2/2)(J^2 + 1 - ln J), J = rho0/rho (p is not used). */
KOKKOS_INLINE_FUNCTION double soundSpeed2(const EosParams& e, double rho, double p)
{
    switch (e.type)
    {
    case EosParams::MieGruneisen:
    {
        double f, df;
        detail::mgCurve(e, rho / e.rho0, f, df);
        return e.c0 * e.c0 * df + p * e.Gamma0 * e.rho0 / (rho * rho);
    }
    case EosParams::NeoHookean:
    {
        double J, jm1, lnJ;
        detail::nhStrain(e, rho, J, jm1, lnJ);
        return 0.5 * e.csh * e.csh * (J * J + 1.0 - lnJ);
    }
    default:
        return e.gamma * p / rho;
    }
}

/*! \brief Temperature theta(rho, eps) = eps / cv for every EOS (docs/gpr-model.md 1.2). Exact for the ideal gas; for
 *  the solids the paper gives no temperature law and eps/cv is our choice (heat conduction is only exercised with the
 *  ideal gas). */
KOKKOS_INLINE_FUNCTION double temperature(const EosParams& e, double rho, double eps)
{
    (void)rho;
    return eps / e.cv;
}

// ------------------------------------------------------------------------------------------------------------
// Elasticity (docs/gpr-model.md 1.2). The signal speed (1.5) is formed in computeEos (Hydro.hpp), the heat
// speed in Heat.hpp: each with its own operation order, which the results are bitwise tied to.
// ------------------------------------------------------------------------------------------------------------

/*! \brief Shear (elastic) stress sigma = -rho csh^2 G dev(G) (docs/gpr-model.md 1.2). G and dev G commute, so G dev G
 *  is symmetric; it is formed as the symmetric product. Its trace is not zero (it scales like |dev G|^2). */
KOKKOS_INLINE_FUNCTION Sym3 shearStress(double rho, double csh, const Sym3& G)
{
    return (-rho * csh * csh) * symProduct(G, dev(G));
}

//! \brief Elastic specific energy E_e = (csh^2/4) |dev G|^2 (docs/gpr-model.md 1.2).
KOKKOS_INLINE_FUNCTION double elasticEnergy(double csh, const Sym3& G)
{
    return 0.25 * csh * csh * norm2(dev(G));
}

// ------------------------------------------------------------------------------------------------------------
// Strain relaxation (docs/gpr-model.md 1.4, 2.4)
// ------------------------------------------------------------------------------------------------------------

//! \brief Viscous fluid: tau1 = 6 mu / (rho0 csh^2) (docs/gpr-model.md 1.4), in the scene reader's operation order.
KOKKOS_INLINE_FUNCTION double tau1FromViscosity(double mu, double rho0, double csh)
{
    return 6.0 * mu / (rho0 * csh * csh);
}

//! \brief Von Mises equivalent stress sigma_bar = sqrt(3/2 tr(dev(sigma)^2)) (docs/gpr-model.md 1.4).
KOKKOS_INLINE_FUNCTION double vonMises(const Sym3& sigma)
{
    return kmath::sqrt(1.5 * norm2(dev(sigma)));
}

/*! \brief Relaxation rate k = 6 det(G)^{5/6} / tau1 of dG/dt = -k G dev(G) (docs/gpr-model.md 1.4, source of (1e)).
 *  tau1 = +inf gives 0, tau1 = 0 gives +inf. */
KOKKOS_INLINE_FUNCTION double strainRelaxationRate(const Sym3& G, double tau1)
{
    return 6.0 * kmath::pow(det(G), 5.0 / 6.0) / tau1;
}

namespace detail
{
//! Integrand w(s) = c / cbrt(prod_j (rho_j + q_j e^{-s})) of the relaxation quadrature (see relaxStrainKdt).
KOKKOS_INLINE_FUNCTION double relaxIntegrand(const double (&rho)[3], const double (&q)[3], double c, double s)
{
    const double y = kmath::exp(-s);
    return c / kmath::cbrt((rho[0] + q[0] * y) * (rho[1] + q[1] * y) * (rho[2] + q[2] * y));
}

//! 8-point Gauss-Legendre integral of relaxIntegrand over [a, b].
KOKKOS_INLINE_FUNCTION double relaxQuadrature(const double (&rho)[3], const double (&q)[3], double c, double a,
                                              double b)
{
    const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    const double m = 0.5 * (a + b), h = 0.5 * (b - a);
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
        sum += w[i] * (relaxIntegrand(rho, q, c, m - h * x[i]) + relaxIntegrand(rho, q, c, m + h * x[i]));
    return h * sum;
}
} // namespace detail

/*! \brief Exact solution over one step of the strain-relaxation ODE dG/dt = -k G dev(G) with frozen k
 *  (docs/gpr-model.md 1.4, 2.4); kdt = k dt >= 0.
 *
 *  Method (derived here, exact up to a quadrature of ~1e-13 accuracy). With m = tr(G)/3,
 *    d(G^{-1})/dt = -G^{-1} G' G^{-1} = k (I - m G^{-1}),
 *  which is linear in G^{-1} with scalar coefficients, so G^{-1}(t) = a(t) G^{-1}(0) + b(t) I: the eigenvectors
 *  are fixed and, because det G is invariant, one scalar carries the whole evolution. In the eigenbasis
 *  (lambda_1 <= lambda_2 <= lambda_3, g = det^{1/3}, rho_j = lambda_j/lambda_3, q_j = 1 - rho_j, y = e^{-s}):
 *    ln lambda_i(s) - ln lambda_i(0) = mean_j D_j - D_i,   D_j = ln(rho_j + q_j y),
 *    k g t = integral_0^s w(s') ds',   w(s) = c / cbrt(prod_j (rho_j + q_j e^{-s})),  c = g / lambda_3.
 *  The log-eigenvalue increments have zero mean by construction, so det G is preserved to round-off; s = 0 is
 *  the identity and s = inf gives lambda_i = g (G = det(G)^{1/3} I). The integrand rises monotonically from c to
 *  1 and is analytic in the strip |Im s| < pi, so 8-point Gauss-Legendre panels of width 2 integrate it to
 *  ~1e-13; the end point s is found by Newton in the last panel, started from the right (monotone: w increases).
 *  Since w <= 1, s >= k g dt: once s exceeds S = ln(lambda_3/lambda_1) + 40 the state equals det^{1/3} I to
 *  double precision (for a well-conditioned G this is decided from tr and det before the eigen-solver, so the
 *  hydrodynamic limit costs ~20 ns). Past r_max e^{-s} <= 1e-8 the integral has a closed form to O(1e-16), so at
 *  most (ln(lambda_3/lambda_1) + 19)/2 panels are integrated. Measured on one CPU core: ~0.9-1.3 us per call for
 *  k g dt <= 3, ~2 us near k g dt = 30 (eigen-solver ~0.26 us included).
 *  The update is applied as an increment G + V diag(dlambda) V^T, so a tiny k dt changes G by ~k dt only
 *  (eigen-decomposition round-off does not touch G itself). kdt <= 0 or NaN returns G bit-for-bit. G must be
 *  SPD (a G whose smallest eigenvalue is <= 0 is returned unchanged). */
KOKKOS_INLINE_FUNCTION Sym3 relaxStrainKdt(const Sym3& G, double kdt)
{
    if (!(kdt > 0.0))
        return G;
    // Hydrodynamic limit without the eigen-solver, for a well-conditioned G (tr^3/det <= 100, where det is
    // accurate to ~100 eps): lambda_max/lambda_min <= tr^3/det and s >= k g dt.
    const double detG = det(G), trG = trace(G);
    const double ratio = trG * trG * trG / detG;
    if (detG > 0.0 && ratio <= 100.0 && kdt * kmath::cbrt(detG) >= kmath::log(ratio) + 40.0)
        return identity(kmath::cbrt(detG));

    const Eigen3 e = eigen(G);
    const double lmin = e.value[0], lmax = e.value[2];
    if (!(lmin > 0.0) || lmin == lmax)
        return G; // not SPD, or already isotropic
    double rho[3], q[3];
    for (int j = 0; j < 3; ++j)
    {
        rho[j] = e.value[j] / lmax;
        q[j] = (lmax - e.value[j]) / lmax;
    }
    const double c = kmath::cbrt(rho[0] * rho[1] * rho[2]); // g / lambda_max
    const double tau = kdt * lmax * c;                      // k g dt
    const double rmax = q[0] / rho[0];                      // lambda_max / lambda_min - 1
    const double rmean = (q[0] / rho[0] + q[1] / rho[1]) / 3.0;
    const double sSat = kmath::log(lmax / lmin) + 40.0; // beyond: r_max e^{-s} < e^{-40}, equilibrium
    const double g = lmax * c; // det^{1/3} from the eigenvalues: ~eps cond, where the cofactor det has eps cond^2
    if (!(tau < sSat))
        return identity(g);

    // March panels of width 2 to the one holding the end point s. a + (tau - acc)/w(a) is an upper bound of s
    // (w increases), which detects the panel without integrating it. Once r_max e^{-a} <= 1e-8 the tail has a
    // closed form: w = 1 - rmean e^{-s} + O(r_max^2 e^{-2s}) with rmean = mean_j r_j, r_j = 1/rho_j - 1.
    constexpr double H = 2.0;
    double a = 0.0, acc = 0.0, s = 0.0;
    bool newton = false;
    while (true)
    {
        if (!(a < sSat))
            return identity(g); // fully relaxed
        const double ya = kmath::exp(-a);
        if (rmax * ya <= 1e-8)
        {
            // tau - acc = x - rmean ya (1 - e^{-x}), x = s - a: fixed point with contraction <= 1e-8
            const double d = tau - acc;
            double x = d;
            for (int it = 0; it < 2; ++it)
                x = d - rmean * ya * kmath::expm1(-x);
            s = a + x;
            break;
        }
        const double sUp = a + (tau - acc) / detail::relaxIntegrand(rho, q, c, a);
        if (sUp <= a + H)
        {
            s = sUp;
            newton = true;
            break;
        }
        const double p = detail::relaxQuadrature(rho, q, c, a, a + H);
        if (acc + p >= tau)
        {
            s = a + H;
            newton = true;
            break;
        }
        acc += p;
        a += H;
    }

    // Newton on F(s) = acc + int_a^s w - tau: F is convex increasing, so from a point right of the root the
    // iterates decrease monotonically (quadratic convergence; 1-2 iterations for small k dt).
    if (newton)
        for (int it = 0; it < 30; ++it)
        {
            const double F = acc + detail::relaxQuadrature(rho, q, c, a, s) - tau;
            const double ds = F / detail::relaxIntegrand(rho, q, c, s);
            s -= ds;
            if (!(kmath::fabs(ds) > 1e-15 * s))
                break;
        }

    const double y = kmath::exp(-s), em = -kmath::expm1(-s); // em = 1 - y, accurate for small s
    double D[3];
    for (int j = 0; j < 3; ++j)
    {
        const double arg = rho[j] + q[j] * y;
        // log1p form is exact for small s; the log form avoids cancellation when arg -> rho_j << 1
        D[j] = arg < 0.5 ? kmath::log(arg) : kmath::log1p(-q[j] * em);
    }
    const double mean = (D[0] + D[1] + D[2]) / 3.0;
    double dl[3];
    for (int i = 0; i < 3; ++i)
        dl[i] = e.value[i] * kmath::expm1(mean - D[i]);
    return G + fromEigen(dl, e.vector);
}

/*! \brief Strain relaxation of G_e over dt with frozen tau1 (docs/gpr-model.md 1.4, 2.4): exact solution of
 *  dG/dt = -k G dev(G), k = 6 det(G)^{5/6} / tau1 (relaxStrainKdt). Robust for any tau1 and dt:
 *  tau1 = +inf (elastic) returns G bit-for-bit, tau1 -> 0 (or 0) gives det(G)^{1/3} I, and det G is preserved
 *  to round-off in between. For a plastic tau1(sigma_bar), freeze tau1 at the current iterate. */
KOKKOS_INLINE_FUNCTION Sym3 relaxStrain(const Sym3& G, double dt, double tau1)
{
    return relaxStrainKdt(G, strainRelaxationRate(G, tau1) * dt);
}

/*! \brief G_e over one step of dG/dt = -(G L + L^T G) - k G dev G with a fixed tau1, given the transport increment
 *  dT = -dt (G L + L^T G) at G0 (docs/gpr-model.md 2.4: the exponential integrator).
 *
 *  Splitting (transport, then the exact relaxation over dt) loses the Navier-Stokes limit: for k dt >> 1 it relaxes
 *  away the deviator that the stretching rebuilds during the step, so the viscous stress vanishes instead of
 *  tending to -(tau1/3) dev D rho c_sh^2 (docs/gpr-model.md 1.4, Navier-Stokes limit). Near equilibrium G = g (I + X)
 *  the deviator obeys X' = -a X + F, a = k g, F = dev(dT)/(g dt), whose exact (exponential) solution is
 *  X(dt) = e^{-a dt} X0 + phi1(a dt) dt F, phi1(z) = (1 - e^{-z}) / z. Hence
 *    G = R(G0 + tr(dT)/3 I, k dt) + phi1(k g dt) dev(dT),
 *  with R the exact det-preserving relaxation (relaxStrainKdt): the volumetric transport is never relaxed, the
 *  initial deviator decays exactly, and the stretching enters with the exponential weight. Limits: tau1 = inf gives
 *  G0 + dT (pure transport); k dt -> inf gives det^{1/3} I + dev(dT) / (k g dt), the discrete Navier-Stokes
 *  stress; for k dt -> 0 it agrees with the splitting to O(k dt^2). */
KOKKOS_INLINE_FUNCTION Sym3 transportAndRelax(const Sym3& G0, const Sym3& dT, double dt, double tau1)
{
    if (!(tau1 < infinity()))
        return G0 + dT; // elastic: no relaxation to evaluate
    const Sym3 Gi = G0 + identity(trace(dT) / 3.0);
    const double kdt = strainRelaxationRate(Gi, tau1) * dt;
    if (!(kdt > 0.0))
        return G0 + dT;
    const double z = kdt * kmath::cbrt(det(Gi));
    const double phi1 = z < 1e-8 ? 1.0 - 0.5 * z : -kmath::expm1(-z) / z;
    return relaxStrainKdt(Gi, kdt) + phi1 * dev(dT);
}

/*! \brief Plastic strain relaxation over dt with tau1 consistent with the relaxed state (docs/gpr-model.md 1.4, 2.4):
 *  G = R(G*, kdt), kdt = dt 6 det(G*)^{5/6} / tau1(sigma_bar(rho, G)), tau1 = tau10 (sigma_Y / sigma_bar)^n, where R
 *  is the exact relaxation of relaxStrainKdt. Freezing tau1 at a previous iterate instead makes a Picard loop flip
 *  between over- and under-relaxation for large n (sigma_bar crosses sigma_Y each time).
 *
 *  Method: the relaxed states form a one-parameter family G(s) with the eigenvectors of G* (relaxStrainKdt), with
 *  closed-form eigenvalues and kdt(s) = (1/g) int_0^s w. So the scalar equation is solved in y = ln s:
 *    Phi(y) = ln int_0^s w - ln g - ln(6 dt det^{5/6} / tau10) - n ln(sigma_bar(s) / sigma_Y) = 0,
 *  increasing in y (relaxation lowers sigma_bar) with slope >= about 1, by Newton with analytic derivatives inside a
 *  bisection bracket: one eigen-decomposition and a few one-panel quadratures per call. Negligible flow
 *  (kdt < 1e-8 even at sigma_bar(G*), i.e. well below the yield stress) costs only the von Mises stress of G*.
 *  det G is preserved to round-off (to O(kdt^2) ~ 1e-16 on the negligible-flow path). */
KOKKOS_INLINE_FUNCTION Sym3 relaxPlasticStrain(const Sym3& Gs, double rho, double csh, double dt, double tau10,
                                               double sigmaY, double n, double* hint = nullptr)
{
    const double mu = rho * csh * csh;
    const double detG = det(Gs);
    if (!(detG > 0.0) || !(dt > 0.0))
        return Gs;
    const double lnPre = kmath::log(6.0 * dt / tau10) + (5.0 / 6.0) * kmath::log(detG);
    const double sbar0 = vonMises(shearStress(rho, csh, Gs));
    if (!(sbar0 > 0.0))
        return Gs;
    const double lnKdt0 = lnPre + n * kmath::log(sbar0 / sigmaY); // kdt if tau1 stayed at its value for G*
    if (lnKdt0 < -18.4)
    {
        // kdt0 < 1e-8 (well inside the elastic range): the consistent kdt differs from kdt0 by a relative
        // O(n kdt0 |dev G|), and one explicit step of dG/dt = -k G dev G with kdt0 is exact to O(n kdt0^2) ~ 1e-14
        return Gs - kmath::exp(lnKdt0) * symProduct(Gs, dev(Gs));
    }
    const Eigen3 e = eigen(Gs);
    const double lmin = e.value[0], lmax = e.value[2];
    if (!(lmin > 0.0) || lmin == lmax)
        return Gs;
    double rh[3], q[3];
    for (int j = 0; j < 3; ++j)
    {
        rh[j] = e.value[j] / lmax;
        q[j] = (lmax - e.value[j]) / lmax;
    }
    const double c = kmath::cbrt(rh[0] * rh[1] * rh[2]);
    const double g = lmax * c;
    const double lnG = kmath::log(g);
    const double rmax = q[0] / rh[0];
    const double rmean = (q[0] / rh[0] + q[1] / rh[1]) / 3.0;
    const double sSat = kmath::log(lmax / lmin) + 40.0;

    // log-eigenvalue increments D and their s-derivatives at s
    auto logs = [&](double s, double (&D)[3], double (&dD)[3]) {
        const double y = kmath::exp(-s), em = -kmath::expm1(-s);
        for (int j = 0; j < 3; ++j)
        {
            const double arg = rh[j] + q[j] * y;
            D[j] = arg < 0.5 ? kmath::log(arg) : kmath::log1p(-q[j] * em);
            dD[j] = -q[j] * y / arg;
        }
    };
    // int_0^s w: panels of width 2, closed-form tail once r_max e^{-a} <= 1e-8 (as in relaxStrainKdt)
    auto integral = [&](double s) {
        double a = 0.0, acc = 0.0;
        while (s - a > 2.0)
        {
            if (rmax * kmath::exp(-a) <= 1e-8)
                return acc + (s - a) + rmean * kmath::exp(-a) * kmath::expm1(-(s - a));
            acc += detail::relaxQuadrature(rh, q, c, a, a + 2.0);
            a += 2.0;
        }
        return acc + detail::relaxQuadrature(rh, q, c, a, s);
    };
    // Phi(y) and dPhi/dy
    auto phi = [&](double yv, double& dphi) {
        const double s = kmath::exp(yv);
        double D[3], dD[3];
        logs(s, D, dD);
        const double mD = (D[0] + D[1] + D[2]) / 3.0, mdD = (dD[0] + dD[1] + dD[2]) / 3.0;
        double lam[3], dlam[3];
        for (int i = 0; i < 3; ++i)
        {
            lam[i] = e.value[i] * kmath::exp(mD - D[i]);
            dlam[i] = lam[i] * (mdD - dD[i]);
        }
        const double m = (lam[0] + lam[1] + lam[2]) / 3.0, dm = (dlam[0] + dlam[1] + dlam[2]) / 3.0;
        double sg[3], dsg[3];
        for (int i = 0; i < 3; ++i)
        {
            sg[i] = -mu * lam[i] * (lam[i] - m);
            dsg[i] = -mu * (dlam[i] * (lam[i] - m) + lam[i] * (dlam[i] - dm));
        }
        const double sm = (sg[0] + sg[1] + sg[2]) / 3.0, dsm = (dsg[0] + dsg[1] + dsg[2]) / 3.0;
        double s2 = 0.0, ds2 = 0.0;
        for (int i = 0; i < 3; ++i)
        {
            s2 += (sg[i] - sm) * (sg[i] - sm);
            ds2 += 2.0 * (sg[i] - sm) * (dsg[i] - dsm);
        }
        const double I = integral(s);
        const double w = detail::relaxIntegrand(rh, q, c, s);
        // ln sigma_bar = 0.5 ln(1.5 s2)
        const double lnSbar = 0.5 * kmath::log(1.5 * s2);
        dphi = s * (w / I - n * 0.5 * ds2 / s2);
        return kmath::log(I) - lnG - lnPre - n * (lnSbar - kmath::log(sigmaY));
    };
    // bracket: kdt* <= kdt0 and int_0^s w >= c s, so s* <= g kdt0 / c; below, 50 e-folds less
    // (Phi > 0 there by construction, unless clipped at saturation); Newton starts from sigma_bar = sigma_Y, where
    // kdt = exp(lnPre) and s ~ g kdt (w(0) = 1): Phi is nearly linear in y, so 4-7 evaluations.
    double yb = lnKdt0 + lnG - kmath::log(c), d;
    if (yb > kmath::log(sSat))
    {
        yb = kmath::log(sSat);
        if (!(phi(yb, d) > 0.0))
            return identity(g); // relaxed to equilibrium within the step
    }
    double ya = yb - 50.0;
    double yv = ya; // if Phi(ya) >= 0 the flow is negligible (50 e-folds below its bound): take ya
    // A hint (the solution of the previous Picard iterate or step) inside the bracket replaces the cold start and
    // the check of the lower end: then typically two evaluations.
    const bool warm = hint && *hint > ya && *hint < yb;
    if (warm || phi(ya, d) < 0.0)
    {
        yv = warm ? *hint : kmath::fmin(kmath::fmax(lnPre + lnG, ya), yb);
        double fy = phi(yv, d);
        if (fy > 0.0)
            yb = yv;
        else
            ya = yv;
        for (int it = 0; it < 60; ++it)
        {
            double next = yv - fy / d;
            if (!(next > ya && next < yb))
                next = 0.5 * (ya + yb);
            const double step = kmath::fabs(next - yv);
            yv = next;
            if (step < 1e-7 && next > ya && next < yb)
                break; // quadratic convergence: the error of this Newton update is O(step^2) ~ 1e-14
            fy = phi(yv, d);
            if (fy > 0.0)
                yb = yv;
            else
                ya = yv;
            // Phi has a round-off floor of ~1e-12 (it is a sum of logarithms of size ~n); |Phi| < 1e-11 is kdt to
            // 1e-11 relative
            if (!(step > 1e-12) || kmath::fabs(fy) < 1e-11)
                break;
        }
    }
    if (hint)
        *hint = yv;
    double D[3], dD[3];
    logs(kmath::exp(yv), D, dD);
    const double mD = (D[0] + D[1] + D[2]) / 3.0;
    double dl[3];
    for (int i = 0; i < 3; ++i)
        dl[i] = e.value[i] * kmath::expm1(mD - D[i]);
    return Gs + fromEigen(dl, e.vector);
}

// ------------------------------------------------------------------------------------------------------------
// Heat conduction (docs/gpr-model.md 1.2, 1.4, 2.3)
// ------------------------------------------------------------------------------------------------------------

/*! \brief Implicit heat-relaxation factor: J^{n+1} = relaxHeatFactor(...) J*, i.e.
 *  1 / (1 + dt rho0 theta / (tau2 rho theta0)) (docs/gpr-model.md 2.3), theta frozen at t^n and rho at t^{n+1}.
 *  tau2 -> 0 gives 0 (Fourier limit), tau2 = +inf gives 1; dt <= 0 gives 1. */
KOKKOS_INLINE_FUNCTION double relaxHeatFactor(double dt, double tau2, double rho, double rho0, double theta,
                                              double theta0)
{
    if (!(dt > 0.0))
        return 1.0;
    return 1.0 / (1.0 + dt * rho0 * theta / (tau2 * rho * theta0));
}

/*! \brief Fourier conductivity of the relaxation time: kappa = tau2 alpha^2 theta0 / rho0 (docs/gpr-model.md 1.2).
 *  Formed as tau2 times the scale alpha^2 theta0 / rho0, the scene reader's operation order, so that the reader
 *  can call this and keep its bits. */
KOKKOS_INLINE_FUNCTION double kappaFromTau2(double tau2, double alpha, double theta0, double rho0)
{
    return tau2 * (alpha * alpha * theta0 / rho0);
}

//! \brief Inverse of kappaFromTau2: tau2 = kappa / (alpha^2 theta0 / rho0) (docs/gpr-model.md 1.2), same scale.
KOKKOS_INLINE_FUNCTION double tau2FromKappa(double kappa, double alpha, double theta0, double rho0)
{
    return kappa / (alpha * alpha * theta0 / rho0);
}

} // namespace gpr
} // namespace unilag
