/*! \file bench_material.hpp
 *  \brief The material of the kernel benchmarks' physics variants (apps/bench_kernels.cpp, apps/bench_portable.cpp):
 *  an ideal gas (gamma 1.4, cv 1) with the variant's constitutive laws, sized for the benchmarks' perturbed G_e.
 */
#pragma once

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

} // namespace unilag::bench
