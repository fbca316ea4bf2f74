/*! \file GprCorrector.hpp
 *  \brief Second order (2.5), member functions of GprOperator: the midpoint state of a predictor-corrector step
 *  with its limited reconstruction and nodal solve, and the update of the state at t^n over dt with the midpoint
 *  fluxes. Included by GprOperator.hpp.
 */
#pragma once

namespace unilag
{

//! The predictor's result Q^{n+1/2} becomes the midpoint state (stageState at t^n + dt/2). Collective.
template <int D, class P> void GprOperator<D, P>::midpointState(double t, double dt)
{
    stageState(t + 0.5 * dt);
}

/*! A first-order stage has left its state in state_new (owned cells), its positions in x_new (all local nodes) and
 *  the geometry of the owned cells in geomNew. These become the stage state (state_mid, x_mid, geomMid: the midpoint
 *  of a midpoint step, Q^1 of ARS(2,2,2)): its ghosts are completed, EOS and stress computed, its gradients
 *  reconstructed (limited, exchanged), and the nodes solved with its own stress and reconstructed values at time
 *  tStage (boundary pressures at that time). Heat variants: its Rusanov fluxes from theta, eps, J reconstructed at
 *  the faces (their own limited gradients, exchanged). Collective. */
template <int D, class P> void GprOperator<D, P>::stageState(double tStage)
{
    auto& md = md_;
    md.fields.swap("state_mid", "state_new");
    md.fields.swap("x_mid", "x_new");
    std::swap(md.geomMid, md.geomNew);
    halo("state_mid");
    auto xm = md.read("x_mid");
    auto sm = md.read("state_mid");
    {
        ScopedTimer timer(md.timers, Phase::Geometry);
        computeGeometry<D>(md.m, xm, md.geomMid, md.m.nCells, md.m.nOwnedCells);
    }
    {
        ScopedTimer timer(md.timers, Phase::Eos);
        computeEos<D, P>(sm, md.cellMaterial, md.materials, md.auxMid, md.m.nCells, md.sigmaMid);
        // z of the midpoint state against the predictor's node velocities (still in v_node)
        nodalImpedance<D, P>(md.m, sm, md.cellMaterial, md.materials, md.geomMid, md.read("v_node"), md.auxMid,
                             md.m.nCells);
    }
    setBoundaryTime(tStage);
    {
        ScopedTimer timer(md.timers, Phase::Reconstruction);
        limitedGradients<D, P>(md.m, sm, md.auxMid, md.sigmaMid, md.geomMid, xm, md.write("gradients"), md.bc,
                               md.limiter, md.reconstruct, md.pressureLimiter, &md.gradientSums);
        if (fallbackMarked_)
            dropFlaggedGradients(md.write("gradients"), md.read("first_order"), md.m.nOwnedCells);
    }
    halo("gradients");
    rec_ = Reconstruction<D>{md.read("gradients"), xm, md.geomMid.centroid, md.geomMid.volume,
                              md.consistentLoad};
    if constexpr (P::heat)
    {
        // second order in space: theta, eps, J reconstructed at the faces (as the predictor's, heatFluxes)
        heatRec_ = reconstructHeat(sm, md.auxMid, md.geomMid, xm, "heat_gradients");
        ScopedTimer timer(md.timers, Phase::HeatFluxes);
        unilag::heatFluxes<D, P>(md.m, md.bc, sm, md.auxMid, md.geomMid, md.cellMaterial, md.materials, md.heatRateMid,
                                 heatRec_);
    }
    {
        ScopedTimer timer(md.timers, Phase::NodalSolve);
        nodalSolve<D, P>(md.m, md.bc, sm, md.auxMid, md.geomMid, md.write("v_node"), md.fnode, md.sigmaMid, rec_);
    }
    halo("v_node");
}

/*! The corrector's update of Q^n over dt with the midpoint fluxes: x^{n+1} = x^n + dt v_r, G_e from G^n with the
 *  midpoint transport and an implicit relaxation over dt, v, E, omega (and J) from the midpoint forces and heat
 *  fluxes. The result is in state_new, x_new, geomNew as after a first-order step. Collective; false (with a message
 *  in failure) if the G_e update finds an inadmissible cell; check tells whether the update is admissible. */
template <int D, class P> bool GprOperator<D, P>::correctorUpdate(double dt, UpdateCheck& check, std::string& failure)
{
    auto& md = md_;
    auto x = md.read("x");
    auto v = md.read("v_node");
    auto sm = md.read("state_mid");
    if constexpr (P::strain)
    {
        const PicardCheck pc = strainStep(dt, true); // moves the nodes to x_new too
        if (mpi::allMax(md.comm, pc.badCell >= 0 ? 1.0 : 0.0) > 0.0)
        {
            failure = inadmissible(pc.badCell, "in the corrector", dt);
            return false;
        }
    }
    else
        moveNodes(x, v, dt, md.write("x_new"), md.m.nNodes, D);
    const CellFlux<D> midpoint{sm, md.auxMid, md.sigmaMid, md.geomMid, rec_};
    {
        ScopedTimer timer(md.timers, Phase::CellUpdate);
        check = reduceCheck(unilag::updateCells<D, P>(md.m, md.read("state"), md.aux, md.geom, md.mass(),
                                                      md.cellMaterial, md.materials, x, md.read("x_new"), v, dt,
                                                      md.write("state_new"), ConstField(), md.heatRateMid, md.geomNew,
                                                      midpoint));
    }
    balance_ = balanceOf(subcellForces<D, P>(md.m, sm, md.auxMid, md.sigmaMid, md.geomMid, v, midpoint), heatRec_);
    return true;
}

} // namespace unilag
