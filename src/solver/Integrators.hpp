/*! \file Integrators.hpp
 *  \brief The time integrators of the GPR system: short classes that call the operator's stages in order and know
 *  nothing of the physics (Laghos' ODE solvers, ARKODE's steppers). The rates at t^n (nodal solve with the first
 *  stress iterate, heat fluxes) are computed before the attempts, since they do not depend on dt.
 *   - ForwardEuler (scheme.order 1): the implicit Picard stage over dt, then the explicit update
 *     (docs/gpr-model.md 2.1-2.4).
 *   - Midpoint (scheme.order 2, scheme.integrator midpoint): the same over dt/2 as the predictor, then the
 *     corrector over dt with the reconstructed midpoint fluxes (docs/gpr-model.md 2.5).
 *   - Ars222 (scheme.order 2, scheme.integrator ars222): the paper's IMEX ARS(2,2,2) (reference gpr.md 2.6,
 *     docs/gpr-model.md 2.6), which combines stored stages (GprArs.hpp, storeStageRates, updateFromStages).
 */
#pragma once

#include <string>

#include "solver/GprOperator.hpp"

namespace unilag
{

//! Whether a cell update left every cell with a positive volume and a non-negative squared sound speed (0: cold).
inline bool admissible(const UpdateCheck& check)
{
    return check.minVolumeRatio > 0.0 && check.minSound2 >= 0.0;
}

//! The result of one attempt at a step, for the diagnosis if every attempt fails.
struct StageResult
{
    int iterations = 0;  //!< Picard iterations of the (last) implicit stage
    UpdateCheck check{}; //!< the last cell update's extrema
    std::string failure; //!< the implicit solve's or G_e update's failure, "" if none
};

//! First-order stage: Picard coupling of the stress (strain variants), then the update of the cells over dt.
template <int D, class P> bool eulerStage(GprOperator<D, P>& op, double dt, StageResult& r)
{
    bool ok = true;
    if constexpr (P::strain)
        ok = op.picard(dt, r.iterations, r.failure);
    if (ok)
        r.check = op.updateCells(dt);
    return ok && admissible(r.check);
}

template <int D, class P> class ForwardEuler
{
  public:
    explicit ForwardEuler(GprOperator<D, P>& op) : op_(op) {}
    bool step(double /*t*/, double dt, StageResult& r) { return eulerStage(op_, dt, r); }

  private:
    GprOperator<D, P>& op_;
};

template <int D, class P> class Midpoint
{
  public:
    explicit Midpoint(GprOperator<D, P>& op) : op_(op) {}
    bool step(double t, double dt, StageResult& r)
    {
        if (!eulerStage(op_, 0.5 * dt, r)) // predictor: Q^{n+1/2}
            return false;
        op_.midpointState(t, dt);
        return op_.correctorUpdate(dt, r.check, r.failure) && admissible(r.check);
    }

  private:
    GprOperator<D, P>& op_;
};

/*! IMEX ARS(2,2,2) (gpr.md 2.6): stage 1 is the first-order Picard stage over beta dt from Q^n (implicit in the
 *  stress and G_e, as the paper's "full nodal solve + Picard loop"), with the reconstruction at t^n; stage 2 is the
 *  nodal solve of Q^1 with its own stress; the final row combines both stages' rates with the explicit weights
 *  (beta - 1, 2 - beta) and relaxes G_e implicitly over beta dt (GprOperator::arsFinal). */
template <int D, class P> class Ars222
{
  public:
    explicit Ars222(GprOperator<D, P>& op) : op_(op) {}
    bool step(double t, double dt, StageResult& r)
    {
        op_.keepStrainIncrement(true);
        const bool ok = eulerStage(op_, arsBeta * dt, r); // Q^1 in state_new, x^1 in x_new
        op_.keepStrainIncrement(false);
        if (!ok)
            return false;
        op_.storeStageRates("ars_rates0"); // R0: forces of Q^n with the converged stress and v0
        op_.storeStageVelocity("ars_v0");
        op_.stageState(t + arsBeta * dt); // Q^1: geometry, EOS, stress, gradients, nodal solve -> v1
        op_.storeStageRates("ars_rates1", true);
        op_.storeStageVelocity("ars_v1");
        return op_.arsFinal(dt, r.check, r.failure) && admissible(r.check);
    }

  private:
    GprOperator<D, P>& op_;
};

} // namespace unilag
