/*! \file GprArs.hpp
 *  \brief The IMEX ARS(2,2,2) step (reference gpr.md 2.6, docs/gpr-model.md 2.6), member functions of GprOperator:
 *  what stage 1 keeps, the stage velocities, and the final combination. The integrator (Integrators.hpp, Ars222)
 *  calls them in this order:
 *   1. stage 1 over beta dt: the first-order Picard stage from Q^n with the reconstruction at t^n, keeping its
 *      transport increment dT0 (keepStrainIncrement); its rates R0 (storeStageRates) and node velocities v0;
 *   2. the stage state Q^1 (stageState at t^n + beta dt): its own stress, reconstruction and nodal solve; R1, v1;
 *   3. arsFinal: x^{n+1} = x^n + dt [(beta-1) v0 + (2-beta) v1], G^{n+1} (arsFinalStrain: explicit transport of both
 *      stages, stage 1's stiff source, backward-Euler relaxation over beta dt), then v, E, omega (GCL from x^{n+1})
 *      and J from Q^n + dt/m [(beta-1) R0 + (2-beta) R1] (updateFromStages).
 *  Included by GprOperator.hpp.
 */
#pragma once

namespace unilag
{

//! Stage 1 of ARS(2,2,2): strainStep also keeps its transport increment dT (field ars_strain_increment, owned cells).
template <int D, class P> void GprOperator<D, P>::keepStrainIncrement(bool keep)
{
    if (keep && !md_.fields.has("ars_strain_increment"))
        md_.fields.add("ars_strain_increment", Entity::Cell, 6, Lifetime::Scratch);
    keepIncrement_ = keep;
}

//! Keeps the node velocities of the last nodal solve (all local nodes) in the scratch field name.
template <int D, class P> void GprOperator<D, P>::storeStageVelocity(const std::string& name)
{
    if (!md_.fields.has(name))
        md_.fields.add(name, Entity::Node, D, Lifetime::Scratch);
    md_.fields.copy("v_node", name);
}

/*! The final row of ARS(2,2,2) from the stored stages ars_rates0/ars_v0 (Q^n) and ars_rates1/ars_v1 (Q^1, in
 *  state_mid/geomMid): v_node becomes the combined velocity, x_new = x^n + dt v_node, G^{n+1} into state_new
 *  (strain variants), then the conservative update with the explicit weights (beta - 1, 2 - beta). The forces of
 *  each stage balance at every node with that stage's velocities, so the combination conserves momentum and energy
 *  exactly. Collective; false (with a message in failure) if G^{n+1} is inadmissible somewhere. */
template <int D, class P> bool GprOperator<D, P>::arsFinal(double dt, UpdateCheck& check, std::string& failure)
{
    constexpr double beta = arsBeta;
    auto& md = md_;
    combineNodeVelocities(md.read("ars_v0"), md.read("ars_v1"), beta - 1.0, 2.0 - beta, md.write("v_node"),
                          md.m.nNodes, D);
    if constexpr (P::strain)
    {
        ScopedTimer timer(md.timers, Phase::StrainUpdate);
        moveNodes(md.read("x"), md.read("v_node"), dt, md.write("x_new"), md.m.nNodes, D);
        const PicardCheck pc = arsFinalStrain<D, P>(
            md.m, md.read("state"), md.read("ars_strain_increment"), md.read("state_mid"), md.geomMid,
            md.read("ars_v1"), md.geom, md.mass(), md.cellMaterial, md.materials, md.read("x_new"), dt,
            md.write("state_new"), md.plasticHint(true), md.plasticWork());
        if (mpi::allMax(md.comm, pc.badCell >= 0 ? 1.0 : 0.0) > 0.0)
        {
            failure = inadmissible(pc.badCell, "in the final stage of ARS(2,2,2)", dt);
            return false;
        }
    }
    check = updateFromStages(dt, {{"ars_rates0", beta - 1.0}, {"ars_rates1", 2.0 - beta}});
    return true;
}

} // namespace unilag
