/*! \file RiemannExact.hpp
 *  \brief The exact Riemann solver of the 1D Euler equations for an ideal gas (Toro, ch. 4), on the host, for
 *  reference solutions (Sod, shock tubes) and the normal-shock relations of tube.md 3.
 */
#pragma once

namespace unilag::tube
{

struct GasPrimitive
{
    double rho = 1, u = 0, p = 1;
};

class RiemannExact
{
  public:
    //! Solves for the star region; throws std::runtime_error if the data create a vacuum.
    RiemannExact(const GasPrimitive& left, const GasPrimitive& right, double gamma);
    double starPressure() const { return pStar_; }
    double starVelocity() const { return uStar_; }
    //! The self-similar solution at x / t (the discontinuity initially at x = 0).
    GasPrimitive sample(double xOverT) const;

  private:
    //! Pressure function f_K(p) of one side and its derivative (shock for p > p_K, rarefaction otherwise).
    void side(double p, const GasPrimitive& w, double& f, double& df) const;
    GasPrimitive sampleSide(double x, const GasPrimitive& w, double sign) const;
    GasPrimitive l_, r_;
    double g_, pStar_ = 0, uStar_ = 0;
};

//! Normal shock into gas at rest (tube.md 3): Mach number c/a1 from the pressure ratio p2/p1.
double shockMachFromPressureRatio(double pressureRatio, double gamma);
//! The post-shock state (rho2, u2, p2) behind a shock of Mach number machNumber into `ahead` (at rest).
GasPrimitive postShockState(const GasPrimitive& ahead, double machNumber, double gamma);

} // namespace unilag::tube
