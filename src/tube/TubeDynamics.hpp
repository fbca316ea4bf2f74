/*! \file TubeDynamics.hpp
 *  \brief The nonlinear tube conveying fluid: a Cosserat rod on SE(3) (tube.md 1.3, K = 0, constant
 *  cross-section) with incompressible plug flow, integrated by an explicit, symplectic, time-reversible Lie-group
 *  splitting (kick / exact drift / kick). Kernels in kernels/unilag/TubeRod.hpp; docs/tube-dynamics.md.
 *
 *  Units are the caller's; the rod starts straight along x from the origin, at rest (or in its rest helix when
 *  restCurvature != 0 and both ends are free, or with RodSetup::screwPeriodic). The fluid enters at the left end
 *  with relative speed U along the tangent and leaves at the right end, tangentially, with p = 0.
 */
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "tube/TubeScene.hpp"

namespace unilag::rod
{
struct RodViews; // kernels/unilag/TubeRod.hpp
}

namespace unilag::tube
{

struct RodConstants
{
    double length = 1.0;
    double extension = 0, shear = 0, bending = 0, torsion = 0; //!< EA, kGA, EI, GJ
    double wallMass = 0;                                       //!< rho_w A_w per length
    double wallRotary = 0; //!< rho_w I per length about a bending axis (torsion: twice); must be > 0
    double fluidMass = 0;  //!< M = rho_f A_i per length
    double fluidArea = 0;  //!< A_i, only to report p (fields().pressure holds p A_i when 0)
    std::array<double, 3> restCurvature{0, 0, 0}; //!< Omega_rest, body frame
    std::array<double, 3> gravity{0, 0, 0};
};

struct RodSetup
{
    int segments = 100;
    EndCondition left = EndCondition::Clamped, right = EndCondition::Free;
    double flowSpeed = 0; //!< U, the fluid's speed relative to the tube, along the tangent
    /*! Rods with fewer nodes run their kernels on Kokkos::Serial when the backend is on the host: a step of a
     *  small rod is tens of microseconds of work, less than the fork/join of its 3 (8 with flow) OpenMP launches,
     *  and far less when the cores are oversubscribed. 0: always the default execution space. */
    int serialBelow = 1024;
    /*! Screw-periodic ends (left, right ignored; no flow): N segments, the last joining node N-1 to node N :=
     *  g(node 0), g = (R_g, d_g) the rest helix's own screw motion (its frame and position at s = L, node 0 at
     *  the identity): Lambda_N = R_g Lambda_0, r_N = R_g r_0 + d_g. The rod starts in its rest helix; node N is
     *  kept as that image (it is not a degree of freedom). Admits the wavenumbers k = 2 pi n / L in the body
     *  frame (docs/tube-helix.md 6, docs/tube-dynamics.md). */
    bool screwPeriodic = false;
};

//! Host copies, per node: position (3), velocity (3), curvature |Omega| (1), fluid speed U (1),
//! pressure p (or p A_i, see RodConstants::fluidArea) (1), area A_i (1); node-major.
struct RodFields
{
    std::vector<double> position, velocity, curvature, fluidVelocity, pressure, area;
};

//! Exact segment energy and gradient on host, for tests: frames A, B (row-major 3x3), positions ra, rb.
struct SegmentGradient
{
    double energy;
    std::array<double, 3> forceOnLeft, torqueLeft, torqueRight; //!< node j+1 gets -forceOnLeft
};
SegmentGradient segmentGradient(const RodConstants& c, double h, const std::array<double, 9>& A,
                                const std::array<double, 9>& B, const std::array<double, 3>& ra,
                                const std::array<double, 3>& rb);

class TubeDynamics
{
  public:
    TubeDynamics(const RodConstants& constants, const RodSetup& setup);
    ~TubeDynamics();
    TubeDynamics(TubeDynamics&&) noexcept;
    TubeDynamics& operator=(TubeDynamics&&) noexcept;

    int nodes() const;
    double spacing() const; //!< h = L / N
    //! Initial node velocities (fixed nodes keep 0).
    void setVelocity(const std::function<std::array<double, 3>(double s)>& v);
    //! Initial body angular velocities omega (pi = I omega), nodes whose rotation is free.
    void setSpin(const std::function<std::array<double, 3>(double s)>& omega);
    //! Small displacements; each free rotation turns (minimally) so that its axis 1 follows the new tangent.
    void displace(const std::function<std::array<double, 3>(double s)>& dr);
    /*! Body-frame perturbation (Sigma, Psi) (s) (docs/tube-helix.md's): r_j += Lambda_j Psi, Lambda_j <-
     *  Lambda_j exp(Sigma^), nodes whose position / rotation is free. */
    void perturbBody(const std::function<std::array<double, 6>(double s)>& sigmaPsi);
    //! A safe explicit step: 0.9 x 2/omega_max, omega_max bounded element by element (axial, shear,
    //! bending, torsion, shear-rotation).
    double stableStep() const;
    //! kick(dt/2) drift(dt) kick(dt/2).
    void step(double dt);
    //! `steps` steps, the half kicks between steps merged (one load evaluation per step).
    void run(double dt, int steps);
    double time() const;

    //! Kinetic (translational with M + m, rotary) + elastic + gravity potential. The fluid's kinetic energy
    //! relative to the tube (M U^2/2 per length, constant) is not included.
    double energy() const;
    std::array<double, 3> linearMomentum() const;
    std::array<double, 3> angularMomentum() const; //!< about the origin, spatial frame
    double orthogonalityDefect() const;            //!< max_j |Lambda_j^T Lambda_j - I| (max entry)
    std::array<double, 3> tip() const;             //!< position of the last node
    std::array<double, 3> position(int node) const;
    std::array<double, 9> frame(int node) const; //!< Lambda_j, row-major
    bool screwPeriodic() const;                  //!< node N is the image of node 0 (RodSetup::screwPeriodic)
    bool finite() const;
    RodFields fields() const;

    //! For a coupled stepper that owns the kicks (GasRodCoupling): the device views, the elastic load into
    //! them (no kick, no flow), and the exact drift of the kinetic energy by tau.
    rod::RodViews deviceViews() const;
    void storeElasticLoads();
    void driftBy(double tau);

  private:
    struct State;
    void kick(double tau);  //!< loads at the current positions, then v, pi += tau (load)
    void drift(double tau); //!< exact flow of the kinetic energy
    void closeScrew();      //!< node N := g(node 0) (screw-periodic rods)
    std::unique_ptr<State> s_;
};

} // namespace unilag::tube
