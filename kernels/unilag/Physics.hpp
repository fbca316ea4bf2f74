/*! \file Physics.hpp
 *  \brief What the kernels are compiled for: the physics variant of a scene, the material data, the column
 *  layouts of the cell state and of the derived (auxiliary) cell quantities, and the boundary tables.
 *
 *  A scene pays only for what it uses (docs/gpr-model.md 1): the kernels are templates on a Physics tag, chosen once
 *  per run from the materials,
 *   - strain:  some material has shear stiffness (c_sh > 0): the state carries G_e, the nodal solver the stress
 *              sigma, and the Picard loop iterates it;
 *   - plastic: some material relaxes G_e with the power law tau1(sigma_bar);
 *   - heat:    some material conducts heat: the state carries J, and the Rusanov heat fluxes run.
 *  The hydrodynamic variant (all false) has exactly the columns and the work of the Euler solver.
 */
#pragma once

#include "unilag/Gpr.hpp"
#include "unilag/Types.hpp"

namespace unilag
{

template <bool Strain, bool Plastic, bool Heat>
struct Physics
{
    static_assert(Strain || !Plastic, "plasticity needs the strain (G_e) equations");
    static constexpr bool strain = Strain;
    static constexpr bool plastic = Plastic;
    static constexpr bool heat = Heat;
};
using PhysicsHydro = Physics<false, false, false>;

//! Column indices of the cell state (a Tpetra MultiVector on the overlapping cell map).
template <int D, class P = PhysicsHydro>
struct StateLayout
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        omega = 0,                     //!< specific volume 1/rho
        vel = 1,                       //!< velocity, D columns
        energy = 1 + D,                //!< specific total energy E = eps + |v|^2/2 + E_e(G) + alpha^2 |J|^2/2
        G = 2 + D,                     //!< G_e as Sym3 (xx, yy, zz, xy, xz, yz), 6 columns (strain only)
        J = G + (P::strain ? 6 : 0),   //!< thermal impulse, D columns (heat only)
        ncomp = J + (P::heat ? D : 0),
    };
};

//! The hydrodynamic state: the first 2 + D columns of every layout.
template <int D>
using HydroState = StateLayout<D, PhysicsHydro>;

//! Column indices of per-cell quantities derived from the state (EOS, temperature, stress).
struct Aux
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        pressure = 0,    //!< EOS pressure p(rho, eps)
        sound = 1,       //!< signal speed a = sqrt(c0^2 + 4/3 c_sh^2 + c_h^2) (docs/gpr-model.md 1.5)
        impedance = 2,   //!< z = rho s of the nodal solver, s the signal column (nodalImpedance)
        eps = 3,         //!< specific internal energy eps = E - kinetic - elastic - thermal
        theta = 4,       //!< temperature (heat only; 0 otherwise)
        signal = 5,      //!< s = a_eff + Gamma_D |dv|: the nodal solver's and the time step's speed
        compression = 6, //!< the shock term Gamma_D |dv| of s (nodalImpedance)
        stress = 7,      //!< shear stress sigma as Sym3, 6 columns (strain only)
    };
    template <class P>
    static constexpr int ncomp()
    {
        return P::strain ? stress + 6 : stress;
    }
};

enum StrainLaw : int
{
    StrainNone = 0,     //!< ideal fluid: no shear stress, G_e not evolved for this material
    StrainConstant = 1, //!< fixed tau1 (viscous fluid, hydro limit 1e-14, elastic +inf)
    StrainPlastic = 2   //!< tau1 = tau10 (sigma_Y / sigma_bar)^n
};

//! Material parameters (plain data, one entry per material, read inside kernels).
struct Material
{
    gpr::EosParams eos;          //!< docs/gpr-model.md 1.3
    double csh = 0.0;            //!< shear sound speed c_sh
    double rho0 = 1.0;           //!< reference density: G_e = (rho/rho0)^{2/3} I at rest; heat relaxation
    int strainLaw = StrainNone;  //!< StrainLaw
    double tau1 = 0.0;           //!< StrainConstant: relaxation time (+inf: elastic)
    double tau10 = 0.0, sigmaY = 0.0, exponent = 0.0; //!< StrainPlastic
    int heat = 0;                //!< 1: conducts heat
    double alpha = 0.0, tau2 = 0.0, theta0 = 1.0;      //!< heat: alpha, relaxation time, reference temperature
    //! Negative specific internal energies above -epsRoundoff are round-off of a cold gas, not instability: the
    //! problem's mean specific energy times 1e-14 (set by the initial state; docs/cold-gas.md).
    double epsRoundoff = 0.0;
};

//! Material of an ideal fluid with the given EOS (no shear, no heat): the Euler equations.
KOKKOS_INLINE_FUNCTION Material fluidMaterial(const gpr::EosParams& eos)
{
    Material m;
    m.eos = eos;
    return m;
}

enum BcType : int
{
    BcFree = 0,     //!< zero traction
    BcSlipWall = 1, //!< v . n = 0 (also symmetry planes)
    BcVelocity = 2, //!< imposed velocity vector (piston, clamped)
    BcPressure = 3, //!< imposed pressure: normal traction -p n (free surface when p = 0)
    BcTraction = 4  //!< imposed traction vector T n
};

enum ThermalBc : int
{
    ThermalAdiabatic = 0, //!< q . n = 0
    ThermalIsothermal = 1 //!< imposed wall temperature
};

//! The most planes one slip-wall group may span and keep fixed normals (a box's six walls as one group).
constexpr int MaxWallPlanes = 6;

//! Boundary conditions by boundary group id (the group of a face is MeshView::cellFaceGroup).
struct BoundaryView
{
    View<const int*> type;                           //!< group -> BcType
    Kokkos::View<const double* [3], MemSpace> value; //!< group -> imposed velocity or traction, or pressure in 0
    View<const int*> thermal;                        //!< group -> ThermalBc (heat variants only)
    View<const double*> temperature;                 //!< group -> isothermal wall temperature
    /*! group -> outward unit normals of the planes a slip wall or symmetry group spans (the mesh as built), zero
     *  rows after the last; all zero if curved. May be empty. */
    Kokkos::View<const double* [MaxWallPlanes][3], MemSpace> plane;
};

/*! The outward normal a slip wall imposes at a face of group g whose current outward area vector is `area`: the
 *  normal of the group's plane the face lies in (the one closest to `area`), scaled to |area|, where the group is
 *  made of planes, else `area`. Normals from the moving faces let a plane's round-off kinks grow: a node sliding
 *  along its tilted faces leaves the plane further, each step (docs/gpr-model.md 3.3). */
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> wallNormal(const BoundaryView& bc, int g, const Vec<D>& area)
{
    if (g >= int(bc.plane.extent(0)))
        return area;
    double a2 = 0.0;
    for (int d = 0; d < D; ++d)
        a2 += area[d] * area[d];
    const double a = Kokkos::Experimental::sqrt(a2);
    // a face tilts off its plane by round-off; 0.9 keeps planes at right angles (or 25 degrees) apart
    int best = -1;
    double bestCos = 0.9;
    for (int p = 0; p < MaxWallPlanes; ++p)
    {
        double c = 0.0;
        for (int d = 0; d < D; ++d)
            c += bc.plane(g, p, d) * area[d];
        if (c > bestCos * a)
        {
            bestCos = c / a;
            best = p;
        }
    }
    if (best < 0)
        return area;
    Vec<D> n;
    for (int d = 0; d < D; ++d)
        n[d] = a * bc.plane(g, best, d);
    return n;
}

//! A Sym3 from six consecutive columns (xx, yy, zz, xy, xz, yz) of a field row.
template <class F>
KOKKOS_INLINE_FUNCTION gpr::Sym3 loadSym3(const F& field, LO i, int col)
{
    return gpr::Sym3{field(i, col), field(i, col + 1), field(i, col + 2),
                     field(i, col + 3), field(i, col + 4), field(i, col + 5)};
}

//! Store a Sym3 into six consecutive columns (xx, yy, zz, xy, xz, yz) of a field row.
template <class F>
KOKKOS_INLINE_FUNCTION void storeSym3(const F& field, LO i, int col, const gpr::Sym3& g)
{
    field(i, col) = g.xx;
    field(i, col + 1) = g.yy;
    field(i, col + 2) = g.zz;
    field(i, col + 3) = g.xy;
    field(i, col + 4) = g.xz;
    field(i, col + 5) = g.yz;
}

} // namespace unilag
