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

//! The element of a model (only Euler-Bernoulli so far; the geometric model's element is docs/tube-model.md 7).
std::unique_ptr<TubeElement> makeElement(TubeModel model);

} // namespace unilag::tube
