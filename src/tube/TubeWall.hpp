/*! \file TubeWall.hpp
 *  \brief The expandable wall of a straight tube, R(s, t) per cell of the rod's s-grid, held on the rod (rod
 *  rigid): its parameters from a wall material (thin elastic shell), its state and its energy. The coupled
 *  step with the gas is GasWallCoupling; kernels in kernels/unilag/TubeWall.hpp; docs/tube-wall.md.
 */
#pragma once

#include <functional>
#include <memory>
#include <vector>

namespace unilag::wall
{
struct WallViews; // kernels/unilag/TubeWall.hpp
}

namespace unilag::tube
{

/*! A thin elastic wall (docs/tube-wall.md 1). SI units or any consistent set. */
struct WallMaterial
{
    double youngModulus = 1.0e6; //!< E
    double poisson = 0.5;        //!< nu (0.5: rubber)
    double thickness = 1.0e-3;   //!< h
    double density = 1000.0;     //!< rho_w
    double restRadius = 5.0e-3;  //!< R0 (mid-surface radius of the unloaded wall = the gas radius at rest)
    double viscosity = 0.0;      //!< c: viscous wall force -c dR/dt per unit length (0: none)
    double axialTension = 0.0;   //!< N_x: axial membrane pre-tension, force per unit circumference (N/m; >= 0)
};

/*! Per unit length of tube: a V^2/2 kinetic, b (R - R0)^2/2 elastic, as R'^2/2 tension, viscous force -c V. */
struct WallCoefficients
{
    double a = 1.0;          //!< wall mass per length
    double b = 1.0;          //!< hoop stiffness per length
    double c = 0.0;          //!< viscous coefficient
    double restRadius = 1.0; //!< R0
    double pExt = 0.0;       //!< outside pressure
    double as = 0.0;         //!< axial tension coefficient (wall equation a R'' = ... + as R_ss)
};

//! a = rho_w 2 pi R0 h;  b = 2 pi E h / (R0 (1 - nu^2))  (hoop strain (R - R0)/R0 with the axial strain held
//! at zero by the rigid rod: plane-strain modulus E/(1 - nu^2)); c = the material's viscosity;
//! as = 2 pi R0 N_x (a generator tilted by R' is longer by R'^2/2 per length; N_x on the circumference 2 pi R0
//! does that work: energy N_x 2 pi R0 R'^2/2 per length).
WallCoefficients wallCoefficients(const WallMaterial& m, double pExt);

//! Quasi-static wall law (p - p_ext) 2 pi R = b (R - R0): the radius at pressure p (throws past the
//! bulge limit p - p_ext >= b / (2 pi), where no equilibrium exists).
double equilibriumRadius(const WallCoefficients& w, double p);
//! dA/dp of the quasi-static law at pressure p: 4 pi^2 R^3 / (b R0).
double compliance(const WallCoefficients& w, double p);
//! Linear speed of a compliant gas-filled tube, 1/c^2 = 1/a^2 + (rho/A) dA/dp (tube.md 3).
double compliantSpeed(const WallCoefficients& w, double rho, double p, double gamma);

//! Host copies per cell: radius and wall speed.
struct WallFields
{
    std::vector<double> radius, speed;
};

//! Parts of the wall energy (summed over cells times h).
struct WallEnergy
{
    double kinetic = 0, elastic = 0, outside = 0, tension = 0, dissipated = 0;
};

class TubeWall
{
  public:
    //! serial: run the kernels on Kokkos::Serial on host backends (small tubes, as GasSetup::serialBelow).
    TubeWall(const WallCoefficients& coefficients, int cells, double length, bool serial = false);
    ~TubeWall();
    TubeWall(TubeWall&&) noexcept;
    TubeWall& operator=(TubeWall&&) noexcept;

    const WallCoefficients& coefficients() const;
    int cells() const;
    //! Radius and wall speed at the cell centres (resets the dissipated energy).
    void setState(const std::function<double(double s)>& radius, const std::function<double(double s)>& speed);
    WallEnergy energy() const;
    WallFields fields() const;

    //! Radius, wall speed and dissipated energy per cell on the device, for GasWallCoupling.
    wall::WallViews deviceViews() const;

  private:
    struct State;
    std::unique_ptr<State> s_;
};

} // namespace unilag::tube
