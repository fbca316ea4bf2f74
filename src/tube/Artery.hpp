/*! \file Artery.hpp
 *  \brief A single 1D artery (tube.md 4.2; docs/tube-artery.md): incompressible flow in a tube with
 *  stretchable walls, the quasi-static limit of the talk's wall Lagrangian. Kernels in kernels/unilag/TubeArtery.hpp.
 *
 *  SI units. The vessel is uniform (A0, beta constant along s); it starts at rest at A = A0, p = p_ext = 0
 *  unless setState() says otherwise. The inlet is s = 0, the outlet s = length.
 */
#pragma once

#include <functional>
#include <vector>

#include "unilag/TubeArtery.hpp"

namespace unilag::tube
{

struct ArteryConfig
{
    double length = 0.126;
    double radius = 2.6485e-3; //!< R0, unloaded lumen radius
    double wall = 0.24e-3;     //!< h0
    double young = 700e3;      //!< E
    double poisson = 0.5;      //!< nu (incompressible wall, as openBF)
    double density = 1060;     //!< rho of blood
    double viscosity = 4e-3;   //!< mu; 0 switches friction off
    double gammaProfile = 2;   //!< velocity profile order gamma_p
    int cells = 64;
    double cfl = 0.9;
    int serialBelow = 512; //!< fewer cells run on Kokkos::Serial where the views are host-accessible
    artery::InletKind inlet = artery::InletKind::Closed;
    std::function<double(double)> inletFlux; //!< Q_in(t), m^3/s, for InletKind::Flux
    artery::OutletKind outlet = artery::OutletKind::Reflection;
    double reflection = 0;        //!< R_t for OutletKind::Reflection
    double R1 = 0, R2 = 0, C = 0; //!< RCR Windkessel
    double tension = 0;           //!< F_z, axial pre-tension force of the wall (N); 0: no Pedley-Luo term
};

//! Wall stiffness beta = sqrt(pi/A0) h E / (1 - nu^2) (Pa) and the Moens-Korteweg speed from E, h, R0 directly.
double arteryBeta(const ArteryConfig& cfg);
double moensKortewegSpeed(const ArteryConfig& cfg);  //!< sqrt(E h / (2 rho R0 (1 - nu^2)))
double frictionCoefficient(const ArteryConfig& cfg); //!< K_r = 2 (gamma_p + 2) pi mu / rho
//! T = F_z / (4 pi A0) (Pa), the coefficient of p = ... - T d_ss A (TubeArtery.hpp: membrane with axial force F_z).
double tensionCoefficient(const ArteryConfig& cfg);

class Artery
{
  public:
    explicit Artery(const ArteryConfig& cfg);

    //! Host state (A, Q per cell, size cells each); also resets the boundary record (p_C, volumes).
    void setState(const std::vector<double>& area, const std::vector<double>& flow, double windkesselPressure = 0);
    //! One SSP-RK2 step (SSP-RK3 with tension) with dt = min(cfl dx / max|lambda|, dtMax); returns the dt taken.
    //! With tension, lambda includes the dispersive speed (TubeArtery.hpp, kTensionStepFactor).
    double step(double dtMax = 1e30);
    //! Steps until time() == t exactly (the last step is shortened).
    void advanceTo(double t);

    double time() const { return time_; }
    double dx() const { return constants_.dx; }
    double area0() const { return constants_.A0; }
    const artery::ArteryConstants& constants() const { return constants_; }
    long long cellSteps() const { return cellSteps_; }

    double volume() const;    //!< sum A dx
    double volumeIn() const;  //!< integral of the inlet face's volume flux since setState
    double volumeOut() const; //!< same on the outlet face
    double windkesselPressure() const;
    void hostState(std::vector<double>& area, std::vector<double>& flow) const;
    double pressure(double area) const { return artery::pressure(constants_, area); } //!< the elastic part, Phi(A)
    //! -T d_ss A in cell i of a host area field, with the kernels' mirror ends (0 without tension).
    double tensionPressure(const std::vector<double>& area, int i) const;
    //! Per-cell wall-law pressure Phi(A) - T d_ss A (exactly Phi(A) without tension).
    std::vector<double> wallPressure(const std::vector<double>& area) const;
    //! (A, Q) on the inlet and outlet faces from the last stage.
    void boundaryStates(double& Ain, double& Qin, double& Aout, double& Qout) const;

  private:
    void runStage(artery::StateView in, artery::StateView base, artery::StateView out, artery::BoundaryView bcIn,
                  artery::BoundaryView bcBase, artery::BoundaryView bcOut, double dt, double weight, double t,
                  bool record = true);
    double maxSpeed() const;
    void stepHeun(double dt);
    void stepRK3(double dt);
    double boundarySlot(int s) const;

    ArteryConfig cfg_;
    artery::ArteryConstants constants_;
    artery::StateView U_, U1_, U2_, flux_; //!< flux_: faces 0..cells; U2_ only with tension (RK3)
    artery::BoundaryView bc_, bc1_, bc2_;
    bool serial_ = false;
    double time_ = 0;
    long long cellSteps_ = 0;
};

} // namespace unilag::tube
