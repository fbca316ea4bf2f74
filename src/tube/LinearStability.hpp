/*! \file LinearStability.hpp
 *  \brief Linear stability of the straight tube conveying fluid (planar, about the straight state), by finite
 *  elements (TubeElement) and LAPACK: the spectrum against the flow speed, the first instability (flutter or
 *  divergence) and the dispersion relation of the infinite tube. docs/tube-model.md 1-4.
 *
 *  Sign convention (Paidoussis'): perturbations go as exp(i omega tau); the solver computes lambda = i omega
 *  (eta ~ exp(lambda tau)), so the growth rate is Re(lambda) = -Im(omega) and the frequency Im(lambda) = Re(omega).
 *  A mode is unstable when Im(omega) < 0.
 */
#pragma once

#include <array>
#include <complex>
#include <limits>
#include <vector>

#include "tube/Lapack.hpp"
#include "tube/TubeScene.hpp"

namespace unilag::tube
{

//! One eigenvalue of the linearised tube.
struct Mode
{
    std::complex<double> lambda;                                                        //!< eta ~ exp(lambda tau)
    std::complex<double> omega() const { return {lambda.imag(), 0.0 - lambda.real()}; } //!< -i lambda (no -0)
    double growth() const { return lambda.real(); }
    double frequency() const { return lambda.imag(); }
};

//! The first instability met as u grows from 0.
struct Onset
{
    bool found = false;                                          //!< false: stable up to the scan's end
    double speed = std::numeric_limits<double>::infinity();      //!< u at onset
    double frequency = std::numeric_limits<double>::quiet_NaN(); //!< Re(omega) of the mode going unstable there
    bool divergence = false; //!< the mode goes through 0 on the real axis (static buckling), not a Hopf pair
};

/*! The tube's discretisation: `elements` finite elements, then (modes > 0) a Galerkin projection on the
 *  `modes` lowest modes of the tube without flow, which keeps the eigenproblems of a scan small (tube.md 2.1's
 *  reference used 10 or more beam modes); modes = 0 keeps every finite-element dof. */
struct TubeDiscretisation
{
    TubeModel model = TubeModel::EulerBernoulli;
    EndCondition left = EndCondition::Clamped, right = EndCondition::Free;
    int elements = 40;
    int modes = 16;
    GeometricParameters geometric; //!< the geometric model's ratios (TubeModel::Geometric only)
};

/*! The geometric model of a physical tube (its ratios: PhysicalTube::geometricParameters), to be built as
 *  LinearStability(geometricDiscretisation(tube), tube.massRatio()); u and tau in the units of
 *  PhysicalTube::velocityScale and timeScale. The modes are more than for Euler-Bernoulli because the axial and
 *  shear modes of a stubby tube take places among the lowest. */
TubeDiscretisation geometricDiscretisation(const PhysicalTube& tube, int elements = 40, int modes = 24,
                                           EndCondition left = EndCondition::Clamped,
                                           EndCondition right = EndCondition::Free);

//! The discretisation a scene asks for (its model, ends, stability.elements and .modes, its physical tube's
//! geometric parameters).
TubeDiscretisation sceneDiscretisation(const TubeScene& scene);

//! The finite-element dofs the ends leave free (the most modes a Galerkin projection can keep).
int freeDofCount(const TubeDiscretisation& disc);

//! How the first crossing is searched: a scan in u, then bisection.
struct ScanOptions
{
    double speedMax = 30.0, speedStep = 0.02, tolerance = 1e-6;
};

/*! \brief The discretised linearised tube M eta_tt + C(u) eta_t + K(u) eta = 0 with
 *  C(u) = 2 sqrt(beta) u G and K(u) = K_b - u^2 K_f (K_f: centrifugal density minus its end terms, minus the area
 *  change's stiffening of the geometric model, docs/tube-model.md 7.3), reduced to the
 *  dofs the end conditions leave free, and its first-order form. */
class LinearStability
{
  public:
    LinearStability(const TubeDiscretisation& disc, double beta);

    int dofs() const { return mass_.n; }
    double beta() const { return beta_; }

    //! Every eigenvalue at flow speed u, sorted by frequency Re(omega), then growth.
    std::vector<Mode> spectrum(double u) const;
    //! The `count` lowest modes of non-negative frequency at u (one of each conjugate pair), by frequency.
    std::vector<Mode> lowestModes(double u, int count) const;
    /*! The largest growth rate max Re(lambda) at u, over the modes below frequencyCutoff(). For the geometric model
     *  it is 0 (round-off) below the onset: its axial modes are undamped. */
    double growthRate(double u) const;
    /*! The geometric model's thickness-shear cutoff 1 / sqrt(shear rotary) (inf for Euler-Bernoulli): the modes
     *  above it (Timoshenko's second spectrum) are left out of growthRate, unstable and firstInstability, because
     *  at beta > 0 the discrete system has instabilities there whose onset and frequency move with the mesh
     *  (docs/tube-model.md 7.5). */
    double frequencyCutoff() const { return frequencyCutoff_; }
    //! Some mode below the cutoff grows at u (Re lambda above round-off, relative to |lambda|).
    bool unstable(double u) const;
    //! The first u where the tube loses stability (scan, then bisection): tube.md 2.1's "first crossing".
    Onset firstInstability(const ScanOptions& scan) const;
    /*! The divergence speed: the least u > 0 where K(u) is singular (a real eigenvalue through 0), from the
     *  generalised eigenproblem K_b x = u^2 K_f x; independent of beta. +inf if there is none (a free end). */
    double divergenceSpeed() const;

  private:
    lapack::Matrix firstOrderMatrix(double u) const;
    void projectOnModes(int modes);

    //! The spectrum at u less the modes above the cutoff.
    std::vector<Mode> modesBelowCutoff(double u) const;

    double beta_;
    double frequencyCutoff_ = std::numeric_limits<double>::infinity();
    lapack::Matrix mass_, bending_, flow_, coriolis_;               //!< reduced M, K_b, K_f, G
    lapack::Matrix invMassBending_, invMassFlow_, invMassCoriolis_; //!< M^{-1} times each
};

/*! The `count` lowest modes at speeds[0] followed along the speeds: at each speed, each mode goes to the nearest
 *  unused eigenvalue of non-negative frequency (greedy), so that a locus stays one mode when modes cross in
 *  frequency or one becomes overdamped. Result[p][m]: mode m at speeds[p]. */
std::vector<std::vector<Mode>> trackModes(const LinearStability& stability, const std::vector<double>& speeds,
                                          int count);

/*! Which mode goes unstable at the onset: the `count` lowest modes without flow (1: lowest frequency) followed
 *  along u from 0 to just above onset.speed (trackModes, `points` speeds); the one whose eigenvalue there is
 *  nearest i omega_cf (0 at a divergence), or of two met there (a coalescence) the growing one. 0 if there is no
 *  onset or the unstable mode is not clearly among the `count` followed (nearer i omega_cf than half the rest). */
int unstableMode(const LinearStability& stability, const Onset& onset, int count = 6, int points = 301);

//! u_cf of the scene's tube at mass ratio beta (the first instability, flutter or divergence).
Onset criticalFlutterSpeed(const TubeDiscretisation& disc, double beta, const ScanOptions& scan);

/*! \brief The infinite straight tube's dispersion relation (tube.md 2.1), eta ~ exp(i(omega tau - k xi)):
 *  omega^2 - 2 sqrt(beta) u k omega - (k^4 - u^2 k^2) = 0, so omega = k (sqrt(beta) u +- sqrt(k^2 - (1 - beta) u^2)).
 *  Long waves, k^2 < (1 - beta) u^2, are unstable (a root with Im omega < 0). */
std::array<std::complex<double>, 2> dispersionOmega(double k, double u, double beta);

} // namespace unilag::tube
