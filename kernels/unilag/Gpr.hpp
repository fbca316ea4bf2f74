/*! \file Gpr.hpp
 *  \brief Point-wise physics of the Godunov-Peshkov-Romenski (GPR) model (tensors: Sym3.hpp, EOS: Eos.hpp):
 *  the elastic stress and energy, the strain (G_e) and heat (J)
 *  relaxation sources and the plastic relaxation.
 *
 *  Section numbers cite docs/gpr-model.md, the model and scheme of Boscheri, Chiocchetti & Peshkov (JCP 2022).
 *  Everything is header-only and device-callable (Kokkos core only, Kokkos math functions, no std:: math).
 *  G_e is always a full 3x3 tensor, also in 2D (plane strain keeps G_zz).
 */
#pragma once

#include "unilag/Eos.hpp"
#include "unilag/Sym3.hpp"
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
 *  det G is preserved to round-off (to O(kdt^2) ~ 1e-16 on the negligible-flow path).
 *  work, if given, is incremented by the cell's cost above the negligible-flow path, which the load balance weighs
 *  (GprSystem::cellCosts): one for the eigen-decomposition, and per evaluation of Phi one plus its quadrature panels
 *  (1 to about 10: strongly relaxing cells take more). Counting evaluations alone left ranks 1.3x apart in time at
 *  equal counts on the impact scene (docs/parallel.md 4). */
KOKKOS_INLINE_FUNCTION Sym3 relaxPlasticStrain(const Sym3& Gs, double rho, double csh, double dt, double tau10,
                                               double sigmaY, double n, double* hint = nullptr, double* work = nullptr)
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
    double evaluations = 1.0; // the work counted (see above)
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
            evaluations += 1.0;
        }
        evaluations += 1.0;
        return acc + detail::relaxQuadrature(rh, q, c, a, s);
    };
    // Phi(y) and dPhi/dy
    auto phi = [&](double yv, double& dphi) {
        evaluations += 1.0;
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
        {
            if (work)
                *work += evaluations;
            return identity(g); // relaxed to equilibrium within the step
        }
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
    if (work)
        *work += evaluations;
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
 *  tau2 -> 0 gives 0 (Fourier limit), tau2 = +inf gives 1; dt <= 0 or theta <= 0 gives 1. */
KOKKOS_INLINE_FUNCTION double relaxHeatFactor(double dt, double tau2, double rho, double rho0, double theta,
                                              double theta0)
{
    if (!(dt > 0.0))
        return 1.0;
    // theta = eps / cv dips below 0 by round-off in a cold cell (updatedSound2 admits eps >= -epsRoundoff): there,
    // as at theta = 0, the relaxation time is infinite (factor 1, also for tau2 = 0), so J never grows
    if (!(theta > 0.0))
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
