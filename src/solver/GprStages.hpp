/*! \file GprStages.hpp
 *  \brief Stored stages, member functions of GprOperator: a stage's rates (subcell forces and heat fluxes) kept in a
 *  field, and the update of the state at t^n from weighted stored stages, Q^{n+1} = Q^n + dt/m sum_k w_k R_k, with
 *  J relaxed implicitly after the combination. The interface an IMEX tableau (ARS(2,2,2)) is built on; the
 *  first-order and midpoint integrators use the fused single-stage update instead (one pass over the cells).
 *  Included by GprOperator.hpp.
 */
#pragma once

#include <stdexcept>

namespace unilag
{

/*! Stores the rates of the current stage for the owned cells in the scratch field name (RateLayout; created on first
 *  use): the subcell forces of the state at t^n (or, stage = true, of the stage state left by stageState: state_mid,
 *  its EOS, stress, corner vectors and reconstruction) with the stress and reconstruction of the last nodal solve and
 *  its node velocities, and the heat fluxes computed for that state. The reconstruction must be the nodal solve's
 *  (recStart_ at order 2, not none), or the stored forces no longer balance at the nodes. */
template <int D, class P> void GprOperator<D, P>::storeStageRates(const std::string& name, bool stage)
{
    if (!md_.fields.has(name))
        md_.fields.add(name, Entity::Cell, RateLayout<D, P>::ncomp, Lifetime::Scratch);
    ConstField sigma;
    if constexpr (P::strain)
        sigma = stage ? ConstField(md_.sigmaMid) : md_.read("sigma");
    const SubcellForces<D, P> forces{md_.m,
                                     stage ? md_.read("state_mid") : md_.read("state"),
                                     stage ? md_.auxMid : md_.aux,
                                     sigma,
                                     stage ? md_.geomMid.corner : md_.geom.corner,
                                     stage ? rec_ : recStart_,
                                     md_.read("v_node")};
    {
        ScopedTimer timer(md_.timers, Phase::CellUpdate);
        storeRates<D, P>(forces, stage ? md_.heatRateMid : md_.heatRate, md_.write(name));
    }
    stageBalance_[name] = balanceOf(forces, stage ? heatRec_ : heatRecStart_); // views overwritten next stage
}

/*! Updates the owned cells from stored stages (name, weight), at most three: v, E (and J, then relaxed) from
 *  Q^n + dt/m sum_k w_k R_k, positions x^{n+1} = x^n + dt v_node (v_node: the combined node velocity), volumes
 *  from the new geometry. Strain variants: G^{n+1} must already be in state_new. Collective. */
template <int D, class P>
UpdateCheck GprOperator<D, P>::updateFromStages(double dt, const std::vector<std::pair<std::string, double>>& stages)
{
    constexpr int K = 3;
    if (stages.empty() || stages.size() > std::size_t(K))
        throw std::logic_error("updateFromStages: 1 to 3 stages");
    StageSum<K> sum;
    balance_ = BalanceRates<D>();
    for (const auto& [name, weight] : stages)
    {
        sum.rate[sum.stages] = md_.read(name);
        sum.weight[sum.stages++] = weight;
        balance_.add(stageBalance_.at(name), weight);
    }
    ScopedTimer timer(md_.timers, Phase::CellUpdate);
    auto x = md_.read("x");
    auto v = md_.read("v_node");
    auto xn = md_.write("x_new");
    moveNodes(x, v, dt, xn, md_.m.nNodes, D);
    return reduceCheck(updateCellsFromStages<D, P, K>(md_.m, md_.read("state"), md_.aux, md_.geom, md_.mass(),
                                                      md_.cellMaterial, md_.materials, x, xn, v, dt,
                                                      md_.write("state_new"), sum, md_.geomNew));
}

} // namespace unilag
