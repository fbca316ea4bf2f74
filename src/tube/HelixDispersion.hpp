/*! \file HelixDispersion.hpp
 *  \brief The dispersion relation of a helical (or straight) tube conveying fluid, from the linearisation of the
 *  geometric model (tube.md 1.3-1.4, constant cross-section) about a helical base state. docs/tube-helix.md.
 *
 *  Base state (body frame, constant in s and t): Omega_0 = K pi (cos kappa, sin kappa, 0) / L (component 1 is the
 *  twist about the tangent), Gamma_0 = chi = e1, gamma_0 = omega_0 = 0, fluid speed U, multiplier mu0; the rest
 *  curvature is Omega_0 (an intrinsically helical, stress-free tube). Perturbations in the body frame,
 *  Sigma = (Lambda^-1 delta Lambda)^vee, Psi = Lambda^-1 delta r, delta u, delta mu (and, inextensible, the
 *  constraint force), all ~ exp(i (omega t - k s)): the repository's convention (LinearStability.hpp), a mode is
 *  unstable when Im(omega) < 0. By the SE(3) symmetry the linearised system has constant coefficients; at each k
 *  it is the quadratic eigenproblem (omega^2 M2 + omega M1 + M0) x = 0, solved by companion linearisation (zggev).
 *
 *  Units: any consistent set. HelixParameters::dimensionless uses tube.md 2.1's: L = 1, EI = 1, M + m = 1, so
 *  omega is in units sqrt(EI / (M + m)) / L^2, k in 1 / L, u = U L sqrt(M / EI), beta = M / (M + m).
 */
#pragma once

#include <array>
#include <complex>
#include <vector>

namespace unilag::tube
{

/*! The tube, the flow and the helix. mu0 is the multiplier times the lumen area, A mu0 (a force): with the pressure
 *  p0, mu0 = 1/2 M U^2 - p0 A (the fluid momentum equation is Euler's with p = 1/2 rho u^2 - mu). The base internal
 *  (stress) force is axialForce() e1 = (3/2 M U^2 - mu0) e1 = (M U^2 + p0 A) e1, the fluid's momentum flux plus its
 *  pressure. */
struct HelixParameters
{
    double bendingStiffness = 1.0;   //!< EI
    double torsionalStiffness = 1.0; //!< G J_p
    double axialStiffness = 1.0;     //!< EA (wall)
    double shearStiffness = 1.0;     //!< kappa_s G A (wall)
    double wallMass = 0.5;           //!< m = rho_w A_w, per length
    double fluidMass = 0.5;          //!< M = rho_f A, per length
    double bendingInertia = 0.0;     //!< rho_w I, rotary inertia of the section about a diameter, per length
    double torsionalInertia = 0.0;   //!< rho_w J_p, about the tangent, per length
    double flowSpeed = 0.0;          //!< U (relative to the tube)
    double mu0 = 0.0;                //!< A mu0 (a force); zeroPressureMu0() gives p0 = 0
    double length = 1.0;             //!< L of Omega_0 = K pi (cos kappa, sin kappa, 0) / L
    double helixK = 0.0;             //!< K: K = 0 is the straight tube
    double helixAngle = 0.0;         //!< kappa: 0 a twisted straight rod, pi/2 a ring-like plane curve
    bool inextensible = false;       //!< Gamma = chi enforced by a multiplier (EA, kGA unused)
    bool noRotaryInertia = false;    //!< bendingInertia = torsionalInertia = 0
    //! Refuse a base state that is not an equilibrium (see equilibriumResidual); false: linearise anyway.
    bool requireEquilibrium = true;

    /*! tube.md 2.1's units (L = EI = M + m = 1), M = beta, m = 1 - beta, U = u / sqrt(beta), for a thin circular
     *  tube of slenderness L / r_g (r_g the wall's radius of gyration): EA = EI (L/r_g)^2, G J_p = EI / (1 + nu),
     *  kGA = shearCoefficient EA / (2 (1 + nu)), rho_w I = m / (L/r_g)^2, rho_w J_p = 2 rho_w I. mu0: p0 = 0.
     *  beta = 0 (u = 0) is the rod without fluid. */
    static HelixParameters dimensionless(double beta, double u, double slenderness = 50.0, double poisson = 0.3,
                                         double shearCoefficient = 0.5);

    std::array<double, 3> curvature() const;      //!< Omega_0 (= the rest curvature)
    double zeroPressureMu0() const;               //!< 1/2 M U^2: p0 = 0
    double equilibriumMu0() const;                //!< 3/2 M U^2: p0 A = -M U^2, no base force
    double axialForce() const;                    //!< f0 = 3/2 M U^2 - mu0 = M U^2 + p0 A
    double equilibriumResidual() const;           //!< |Omega_0 x f0 e1| = f0 |Omega_0| |sin kappa|
    bool isEquilibrium(double tolerance = 1e-12) const; //!< residual <= tolerance (|f0| + M U^2 + EI) / L
};

//! The unknowns of one mode, in this order: Sigma (3), Psi (3), delta u, A delta mu, then (inextensible) the
//! constraint force (3).
constexpr int kHelixFields = 8;

/*! One root omega(k) and its amplitude vector x (order: see kHelixFields), scaled so that (Sigma, Psi) has unit
 *  2-norm and its largest entry is real and positive. The perturbation is Re(x exp(i (omega t - k s))):
 *  delta r = Lambda_0 Psi, delta Lambda = Lambda_0 Sigma^ (to first order). */
struct HelixMode
{
    std::complex<double> omega;
    std::vector<std::complex<double>> shape;
};

/*! The coefficient matrices of (omega^2 M2 + omega M1 + M0) x = 0 at wavenumber k (n x n, row-major, complex;
 *  n = 8, or 11 inextensible). Rows: angular momentum (3), linear momentum (3), fluid momentum, fluid mass
 *  (then the constraint delta Gamma = 0). */
struct HelixPencil
{
    int n = 0;
    std::array<std::vector<std::complex<double>>, 3> m; //!< m[d]: coefficient of omega^d
    std::complex<double> operator()(int d, int i, int j) const { return m[d][std::size_t(i) * n + j]; }
};

HelixPencil helixPencil(const HelixParameters& p, double k);

/*! Every finite root omega of det(omega^2 M2 + omega M1 + M0) = 0 at wavenumber k, sorted by Re, then Im.
 *  Throws std::invalid_argument for a base state that is not an equilibrium (unless requireEquilibrium = false).
 *  At k = 0 the pencil can be singular (a uniform pressure); such pairs are left out. */
std::vector<std::complex<double>> helixDispersion(const HelixParameters& p, double k);

//! The same roots with their amplitude vectors.
std::vector<HelixMode> helixModes(const HelixParameters& p, double k);

/*! The straight Euler-Bernoulli tube under an axial force f0 (tube.md 2.1, p0 != 0), in its units:
 *  omega^2 - 2 sqrt(beta) u k omega - (k^4 - fhat k^2) = 0, fhat = f0 L^2 / EI = u^2 + p0 A L^2 / EI.
 *  fhat = u^2 is dispersionOmega (p0 = 0). */
std::array<std::complex<double>, 2> straightPipeOmega(double k, double u, double beta, double fhat);

} // namespace unilag::tube
