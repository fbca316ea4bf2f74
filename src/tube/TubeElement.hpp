/*! \file TubeElement.hpp
 *  \brief Finite elements of the planar linearised tube: each returns the element matrices of the quadratic
 *  forms (energy densities) of the linearised Lagrangian, so the assembly never knows which element it holds.
 *
 *  For the dimensionless Euler-Bernoulli pipe (docs/tube-model.md 1; tube.md 2.1)
 *      eta'''' + u^2 eta'' + 2 sqrt(beta) u eta_t' + eta_tt = 0,
 *  the weak form with a test function v is
 *      (v'', eta'') - u^2 (v', eta') + u^2 [v eta']_0^1 + 2 sqrt(beta) u (v, eta_t') + (v, eta_tt) = 0,
 *  one matrix per density: bending (v'', eta''), centrifugal (v', eta'), Coriolis (v, eta'), inertia (v, eta), and
 *  the end term [v eta'] that the centrifugal density leaves at an end where v is free. The centrifugal term is
 *  integrated by parts (instead of using (v, eta'') directly) so that a C0 element (Timoshenko: w, psi) can
 *  supply the same five matrices; the end term is what makes a free end a follower end (non-conservative).
 */
#pragma once

#include <memory>
#include <vector>

#include "tube/TubeScene.hpp"

namespace unilag::tube
{

//! Element matrices, row-major nd x nd (nd = 2 x dofs per node), in the element's local dof order.
struct ElementMatrices
{
    int size = 0;
    std::vector<double> inertia;     //!< (v, eta)
    std::vector<double> bending;     //!< elastic energy: (v'', eta'') for Euler-Bernoulli
    std::vector<double> centrifugal; //!< (v', eta'): the fluid's u^2 w'^2 density
    std::vector<double> coriolis;    //!< (v, eta'): the fluid's 2 sqrt(beta) u w_t w' density (not symmetric)
    //! per u^2, the stiffening of psi'^2 by the area change (docs/tube-model.md 7.3); empty: none
    std::vector<double> areaStiffening;
    double& at(std::vector<double>& m, int i, int j) const { return m[i * size + j]; }
};

class TubeElement
{
  public:
    virtual ~TubeElement() = default;
    virtual int dofsPerNode() const = 0;
    //! The matrices of one element of length h.
    virtual ElementMatrices matrices(double h) const = 0;
    /*! The end term v eta' at the element's left (atRight = false) or right end, as a matrix over the
     *  element's dofs (row: v's dof, column: eta's dof). */
    virtual std::vector<double> endTerm(double h, bool atRight) const = 0;
    //! The node dof components an end condition holds at zero (clamped: w and slope; pinned: w).
    virtual std::vector<int> constrained(EndCondition end) const = 0;
};

/*! Hermite cubic Euler-Bernoulli element: dofs (w, w') at each node, C1 across nodes; its matrices are
 *  integrated by 4-point Gauss quadrature, exact for these polynomial degrees (<= 6). */
class HermiteBeamElement : public TubeElement
{
  public:
    int dofsPerNode() const override { return 2; }
    ElementMatrices matrices(double h) const override;
    std::vector<double> endTerm(double h, bool atRight) const override;
    std::vector<int> constrained(EndCondition end) const override;
};

/*! \brief The geometric model's planar element about the straight state (docs/tube-model.md 7): dofs (x, w, psi)
 *  per node (axial and transverse displacement, section rotation), C0, with the strains Gamma1 - 1 = x',
 *  Gamma2 = w' - psi, Omega3 = psi'. Dimensionless densities (GeometricParameters):
 *      elastic   psi'^2 + (w' - psi)^2 / shear + x'^2 / extension
 *      inertia   w_t^2 + x_t^2 + rotary psi_t^2
 *      fluid     on the centreline slope w', as for Euler-Bernoulli (centrifugal, Coriolis, end term)
 *      area      areaStiffening() u^2 psi'^2
 *  w and psi use Reddy's interdependent interpolation: the exact static solution of the Timoshenko beam (psi
 *  quadratic, w cubic, w' - psi = -2 shear psi'' constant over the element), so the element does not lock as
 *  shear -> 0 and is the Hermite cubic at shear = 0; x is linear. */
class GeometricElement : public TubeElement
{
  public:
    explicit GeometricElement(const GeometricParameters& p) : p_(p) {}
    int dofsPerNode() const override { return 3; }
    ElementMatrices matrices(double h) const override;
    std::vector<double> endTerm(double h, bool atRight) const override;
    std::vector<int> constrained(EndCondition end) const override;

  private:
    GeometricParameters p_;
};

//! The element of a model; the Euler-Bernoulli element ignores the geometric parameters.
std::unique_ptr<TubeElement> makeElement(TubeModel model, const GeometricParameters& geometric = {});

} // namespace unilag::tube
