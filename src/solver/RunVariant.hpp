/*! \file RunVariant.hpp
 *  \brief The dispatch of a scene to the solver compiled for its physics variant, in one dimension. Run2D.cpp and
 *  Run3D.cpp instantiate it, so the two dimensions compile in parallel.
 */
#pragma once

#include "solver/GprRun.hpp"
#include "solver/Run.hpp"

namespace unilag
{

/*! The physics variant a scene needs, from the materials its regions use (a declared but unused material costs
 *  nothing): G_e where some material has shear stiffness, the plasticity law where some material uses it, J where
 *  some material conducts heat. A scene pays only for the equations its materials need (Physics.hpp). */
template <int D> int runDim(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options)
{
    bool strain = false, plastic = false, heat = false;
    for (const auto& [region, regionSpec] : scene.regions)
    {
        const MaterialSpec& spec = scene.materials.at(regionSpec.material); // the reader checked it exists
        strain |= spec.strainLaw != RelaxationLaw::Fluid;
        plastic |= spec.strainLaw == RelaxationLaw::Plastic;
        heat |= spec.heatConduction;
    }
    if (plastic)
        return heat ? runGpr<D, Physics<true, true, true>>(scene, mesh, options)
                    : runGpr<D, Physics<true, true, false>>(scene, mesh, options);
    if (strain)
        return heat ? runGpr<D, Physics<true, false, true>>(scene, mesh, options)
                    : runGpr<D, Physics<true, false, false>>(scene, mesh, options);
    return heat ? runGpr<D, Physics<false, false, true>>(scene, mesh, options)
                : runGpr<D, PhysicsHydro>(scene, mesh, options);
}

} // namespace unilag
