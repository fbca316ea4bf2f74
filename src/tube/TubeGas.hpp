/*! \file TubeGas.hpp
 *  \brief Compressible ideal gas in a tube of cross-section A(s) on the rod's s-grid (cells = the rod's segments,
 *  faces = its nodes), rigid and straight by default, or stretched and moving through the centreline's metric
 *  (setMetric): finite volumes with an HLLC flux, limited MUSCL on (rho, v, p), SSP-RK2 and a CFL step. Kernels
 *  in kernels/unilag/TubeGas.hpp; docs/tube-gas.md.
 */
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "tube/RiemannExact.hpp"

namespace unilag::gas
{
struct GasViews; // kernels/unilag/TubeGas.hpp
}

namespace unilag::tube
{

enum class GasEndType
{
    Wall,           //!< closed end
    Transmissive,   //!< zero gradient: supersonic outflow, or waves leaving
    FixedState,     //!< all of (rho, u, p) imposed: supersonic inflow
    PressureOutlet, //!< subsonic outflow at pressure p (characteristics)
    SubsonicInflow  //!< from a reservoir at rest: its entropy and total enthalpy, with the outgoing invariant
};

struct GasEnd
{
    GasEndType type = GasEndType::Wall;
    GasPrimitive state; //!< FixedState: all; PressureOutlet: p; SubsonicInflow: the reservoir (rho0, p0)
};

enum class GasLimiter
{
    MinMod,
    VanLeer
};

struct GasSetup
{
    double length = 1.0;
    int cells = 100;
    double gamma = 1.4;
    double cfl = 0.8; //!< of h / max(|u| + a); SSP-RK2 with MUSCL is stable up to 1
    GasLimiter limiter = GasLimiter::VanLeer;
    GasEnd left, right;
    /*! Tubes with fewer cells run their kernels on Kokkos::Serial when the backend is on the host (as
     *  RodSetup::serialBelow): a step is 8 launches of microseconds of work each, less than an OpenMP
     *  fork/join, and far less when the cores are oversubscribed. 0: always the default execution space. */
    int serialBelow = 1024;
};

//! Host copies, per cell: centre s, density, velocity relative to the tube (physical), pressure, area.
struct GasFields
{
    std::vector<double> s, rho, u, p, area;
};

//! Where p falls through `level` last, scanning from the right end (a right-running shock into lower
//! pressure), interpolated linearly between cell centres; -1 if it does not.
double leadingShockPosition(const GasFields& fields, double level);

class TubeGas
{
  public:
    explicit TubeGas(const GasSetup& setup);
    ~TubeGas();
    TubeGas(TubeGas&&) noexcept;
    TubeGas& operator=(TubeGas&&) noexcept;

    int cells() const;
    double spacing() const; //!< h = L / N
    //! Cross-section at the faces (nodes) s_f = f h; a cell's area is the mean of its faces'. Default 1.
    //! Call before setState (the conserved state is per unit length).
    void setArea(const std::function<double(double s)>& area);
    /*! The centreline's metric (c, g, k) = (|r'|^2, r'.r_t, |r_t|^2) at the faces s_f = f h: `at` if given, else
     *  `uniform` (a rigid tube at rest is (1, 0, 0), the default). A cell's is the mean of its faces'. Held
     *  fixed during a step (a coupled stepper rewrites deviceViews().metric*); call before setState. */
    void setMetric(const std::array<double, 3>& uniform,
                   const std::function<std::array<double, 3>(double s)>& at = nullptr);
    //! Primitive state at the cell centres (u: the speed relative to the tube, physical units).
    void setState(const std::function<GasPrimitive(double s)>& state);
    double stableStep() const; //!< cfl h / max(|u| + a)
    void step(double dt);      //!< one SSP-RK2 step
    //! Steps of stableStep() (the last one shortened) up to time tEnd; returns the number of steps.
    int advanceTo(double tEnd);
    double time() const;
    void setTime(double t); //!< for a coupled stepper that repeats a step from a saved state

    double mass() const;   //!< sum of xi h
    double energy() const; //!< sum of E h
    bool finite() const;   //!< every cell's conserved state is finite (one reduction on the device)
    //! leadingShockPosition(fields(), level), found on the device (a reduction and two values copied back).
    double shockPosition(double level) const;
    GasFields fields() const;
    /*! The device views (conserved state, face and cell areas) for a coupled stepper that changes the areas
     *  between steps (docs/tube-wall.md); step() treats the areas as frozen during the step. */
    gas::GasViews deviceViews() const;

  private:
    void residualUpdate(double alpha, double beta, double dt, bool toScratch);
    struct State;
    std::unique_ptr<State> s_;
};

} // namespace unilag::tube
