/*! \file GprBalance.hpp
 *  \brief The force balance at the nodes of each update (NodeBalance.hpp, GprNodeBalance.hpp), and what
 *  the run accumulates from it: the boundary impulse and work the conservation check subtracts, the work of walls
 *  and free surfaces (zero), heat through isothermal walls, and the worst node imbalance.
 */
#pragma once

#include "core/Types.hpp"

namespace unilag
{

//! One update's balance, global over the ranks: rates (per unit time) and the worst relative node imbalance.
template <int D> struct BalanceRates
{
    double impulse[D] = {};    //!< sum over boundary nodes of F_r
    double work = 0.0;         //!< sum over boundary nodes of F_r . v_r
    double passiveWork = 0.0;  //!< of walls, symmetry planes and free surfaces (zero up to round-off)
    double heat = 0.0;         //!< through isothermal walls
    double maxImbalance = 0.0; //!< NodeBalanceRates::maxImbalance, over all ranks
    GO worstNode = -1;         //!< its global node id

    //! this += w * other (rates of weighted stages); the imbalance is the worst of both.
    void add(const BalanceRates& other, double w)
    {
        for (int d = 0; d < D; ++d)
            impulse[d] += w * other.impulse[d];
        work += w * other.work;
        passiveWork += w * other.passiveWork;
        heat += w * other.heat;
        if (other.maxImbalance > maxImbalance || worstNode < 0)
        {
            maxImbalance = other.maxImbalance;
            worstNode = other.worstNode;
        }
    }
};

//! The run's boundary impulse and work (time integrals of BalanceRates), for the conservation check.
template <int D> struct BoundaryBalance
{
    double impulse[D] = {};
    double work = 0.0, passiveWork = 0.0, heat = 0.0;
    double maxImbalance = 0.0;
    GO worstNode = -1;
    double worstTime = 0.0;

    void accumulate(const BalanceRates<D>& r, double t, double dt)
    {
        for (int d = 0; d < D; ++d)
            impulse[d] += dt * r.impulse[d];
        work += dt * r.work;
        passiveWork += dt * r.passiveWork;
        heat += dt * r.heat;
        if (r.maxImbalance > maxImbalance)
        {
            maxImbalance = r.maxImbalance;
            worstNode = r.worstNode;
            worstTime = t;
        }
    }
};

} // namespace unilag
