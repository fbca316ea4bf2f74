/*! \file instantiate_kernels.cpp
 *  \brief The GPU compile check of kernels/ (scripts/cuda-check.sh): every kernel launcher instantiated for the
 *  default execution space of a CUDA build of Kokkos, for 2D and 3D and for each physics variant the solver runs
 *  (src/solver/RunVariant.hpp), so that nvcc compiles each KOKKOS_LAMBDA and each device function it calls.
 *
 *  Taking a launcher's address instantiates its body without a call, so this file needs no mesh and no GPU.
 */
#include <type_traits>
#include <vector>

#include <Kokkos_Core.hpp>

#include "unilag/Ars.hpp"
#include "unilag/CellUpdate.hpp"
#include "unilag/CellUpdateApply.hpp"
#include "unilag/EntropyFilter.hpp"
#include "unilag/Geometry.hpp"
#include "unilag/Heat.hpp"
#include "unilag/Hydro.hpp"
#include "unilag/NodeBalance.hpp"
#include "unilag/NodeMotion.hpp"
#include "unilag/Reconstruction.hpp"
#include "unilag/Reduce.hpp"

static_assert(std::is_same_v<unilag::ExecSpace, Kokkos::Cuda>,
              "the GPU compile check needs Kokkos built with CUDA as its default execution space");

namespace
{

using Launchers = std::vector<const void*>;

template <class F> void keep(Launchers& out, F* f)
{
    out.push_back(reinterpret_cast<const void*>(f));
}

//! The launchers every variant runs: geometry, EOS, impedance, nodal solve, update, reconstruction, balances.
template <int D, class P> void mechanics(Launchers& out)
{
    using namespace unilag;
    keep(out, &computeGeometry<D>);
    keep(out, &computeEos<D, P>);
    keep(out, &nodalImpedance<D, P>);
    keep(out, &renewImpedance<D, P>);
    keep(out, &nodalSolve<D, P>);
    keep(out, &stableTimeStep<D>);
    keep(out, &meanCellVelocityAtNodes<D, P>);
    keep(out, &subcellForces<D, P>);
    keep(out, &storeRates<D, P>);
    keep(out, &nodeBalance<D, P>);
    keep(out, &worstImbalance<D>);
    keep(out, &updateCells<D, P>);
    keep(out, &updateCellsFromStages<D, P, 1>);
    keep(out, &updateCellsFromStages<D, P, 2>);
    keep(out, &updateCellsFromStages<D, P, 3>);
    keep(out, &flagInadmissible<D, P>);
    keep(out, &flagAll);
    keep(out, &limitedGradients<D, P>);
    keep(out, &filterEntropy<D, P>);
    keep(out, &epsGradientFromFaces<D>);
    if constexpr (P::strain)
    {
        keep(out, &strainUpdate<D, P>);
        keep(out, &arsFinalStrain<D, P>);
    }
    if constexpr (P::heat)
    {
        keep(out, &heatFluxes<D, P>);
        keep(out, &boundaryHeatRate<D, P>);
        keep(out, &limitedGradientsOf<D, heat::Quantities<D, P>>);
    }
}

template <int D> void dimension(Launchers& out)
{
    using unilag::Physics;
    mechanics<D, Physics<false, false, false>>(out);
    mechanics<D, Physics<false, false, true>>(out);
    mechanics<D, Physics<true, false, false>>(out);
    mechanics<D, Physics<true, false, true>>(out);
    mechanics<D, Physics<true, true, false>>(out);
    mechanics<D, Physics<true, true, true>>(out);
}

} // namespace

//! Every launcher's address, so that the compiler keeps each instantiation.
Launchers unilagCudaKernels();
Launchers unilagCudaKernels()
{
    Launchers out;
    dimension<2>(out);
    dimension<3>(out);
    keep(out, &unilag::combineNodeVelocities);
    keep(out, &unilag::moveNodes);
    keep(out, &unilag::dropFlaggedGradients);
    return out;
}
