/*! \file bench_material.hpp
 *  \brief The material and state of the kernel benchmarks' physics variants (apps/bench_kernels.cpp,
 *  apps/bench_portable.cpp): an ideal gas (gamma 1.4, cv 1) with the variant's constitutive laws, and the G_e and J
 *  its cells start from.
 */
#pragma once

#include <cmath>

#include "unilag/Physics.hpp"

namespace unilag::bench
{

template <class P>
Material variantMaterial()
{
    Material mat = fluidMaterial(gpr::idealGasEos(1.4, 1.0));
    if constexpr (P::strain)
    {
        mat.csh = 0.5;
        mat.strainLaw = P::plastic ? StrainPlastic : StrainConstant;
        mat.tau1 = gpr::infinity(); // elastic
        mat.tau10 = 1.0; // kdt ~ 6 dt (sigma_bar / sigma_Y)^10: a few percent of relaxation per step where it yields
        mat.sigmaY = 2e-3; // about the median von Mises stress of the perturbed G
        mat.exponent = 10.0;
    }
    if constexpr (P::heat)
    {
        mat.heat = 1;
        mat.alpha = 1.0;
        mat.tau2 = 1e-3;
        mat.theta0 = 1.0;
    }
    return mat;
}

/*! G_e and J of a variant's cell at centroid c with density rho into its state row `cell` (columns S::G, S::J):
 *  G_e = rho^{2/3} I with a smooth 1% anisotropic perturbation (sigma != 0; the plastic variant yields in about half
 *  the cells), J = 0.01 cos(2 c). */
template <int D, class P, class Row>
void setVariantState(Row&& cell, double rho, const double* c)
{
    using S = StateLayout<D, P>;
    if constexpr (P::strain)
    {
        const double g = std::cbrt(rho * rho), e = 0.01 * std::sin(4.0 * c[0] + 3.0 * c[1]);
        const double G[6] = {g * (1 + e), g * (1 - 0.5 * e), g * (1 - 0.5 * e), 0.5 * g * e, 0.0, 0.0};
        for (int k = 0; k < 6; ++k)
            cell(S::G + k) = G[k];
    }
    if constexpr (P::heat)
        for (int d = 0; d < D; ++d)
            cell(S::J + d) = 0.01 * std::cos(2.0 * c[d]);
}

} // namespace unilag::bench
