/*! \file Eos.hpp
 *  \brief Equations of state eps(rho, p) of the GPR model (docs/gpr-model.md 1.3): ideal gas, Mie-Grueneisen,
 *  neo-Hookean; pressure, internal energy, sound speed and temperature.
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{
namespace gpr
{

namespace kmath = Kokkos::Experimental;

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

} // namespace gpr
} // namespace unilag
