/*! \file GprOperator.hpp
 *  \brief The GPR operator: what one configuration and state give, independent of how stages are combined.
 *
 *  - derived quantities at t^n: geometry, EOS, speeds, temperature, shear stress (computeAux);
 *  - the nodal solve: node velocities and subcell forces for a stress iterate (solveNodes), or for a reconstructed
 *    midpoint state (solveNodesAt);
 *  - the implicit coupling of the stress: the Picard loop (2.4) over trajectories, GCL volume and the G_e
 *    transport + stiff relaxation (picard, in GprPicard.hpp);
 *  - the explicit rates: heat fluxes (heatFluxes), and the conservative update of v, E, omega (and J) from the
 *    forces of a given flux state (updateCells);
 *  - the stable time step, the boundary impulse and work.
 *  The integrators (Integrators.hpp) call these in the order of their stages; the time loop knows neither.
 */
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "solver/GprBalance.hpp"
#include "solver/GprModel.hpp"
#include "unilag/Ars.hpp"
#include "unilag/EntropyFilter.hpp"
#include "unilag/Heat.hpp"
#include "unilag/NodeBalance.hpp"

namespace unilag
{

template <int D, class P> class GprOperator
{
    using S = StateLayout<D, P>;

  public:
    explicit GprOperator(GprModel<D, P>& model) : md_(model) {}
    GprModel<D, P>& model() { return md_; }

    /*! EOS, signal speeds, temperature and sigma^n (into the field sigma) for all local cells; the impedance's shock
     *  term against the node velocities in the field lagged. */
    void computeAux(const char* lagged = "v_node")
    {
        ScopedTimer timer(md_.timers, Phase::Eos);
        // z from the last nodal solve's node velocities (the previous step's): Dukowicz's shock term
        nodalImpedance<D, P>(md_.m, computeEosOfState(), md_.cellMaterial, md_.materials, md_.geom, md_.read(lagged),
                             md_.aux, md_.m.nCells);
    }

    /*! computeAux after a change of the cells' internal energy alone (the entropy filter): the EOS again, the
     *  impedance from the shock term computeAux stored (renewImpedance: the same bits, no loop over corners). */
    void renewAux()
    {
        ScopedTimer timer(md_.timers, Phase::Eos);
        renewImpedance<D, P>(computeEosOfState(), md_.cellMaterial, md_.materials, md_.geom, md_.aux, md_.m.nCells);
    }

    //! Before the first step: the lagged node velocities of the first impedance (meanCellVelocityAtNodes). Collective.
    void initialNodeVelocities()
    {
        meanCellVelocityAtNodes<D, P>(md_.m, md_.read("state"), md_.read("x"), md_.write("v_node"), md_.bc);
        halo("v_node");
    }

    //! Geometry of local cells [first, nCells) at the current positions.
    void refreshGeometry(LO first = 0)
    {
        ScopedTimer t(md_.timers, Phase::Geometry);
        computeGeometry<D>(md_.m, md_.read("x"), md_.geom, md_.m.nCells, first);
    }

    //! Imposed boundary pressures at time t (scene expressions of t).
    void setBoundaryTime(double t)
    {
        if (md_.pressureLaws.empty())
            return;
        for (auto& [g, law] : md_.pressureLaws)
            md_.bcValueHost(g, 0) = (*law)(0.0, 0.0, 0.0, t);
        Kokkos::deep_copy(md_.bcValue, md_.bcValueHost);
    }

    /*! Nodal solve at owned nodes with T = -p^n I + sigma (strain: the stress iterate), then node velocities to all
     *  local nodes. At second order with the limited reconstruction of the state at t^n (reconstructStart), so that
     *  the predictor of the midpoint step is second order in space too. */
    void solveNodes()
    {
        {
            ScopedTimer timer(md_.timers, Phase::NodalSolve);
            nodalSolve<D, P>(md_.m, md_.bc, md_.read("state"), md_.aux, md_.geom, md_.write("v_node"), md_.fnode,
                             stressIterate(), recStart_);
        }
        halo("v_node");
    }

    /*! Order 2: the limited gradients of the state at t^n, for the predictor's nodal solves and forces. With
     *  first-order predictor fluxes the midpoint step is only first order in time: their O(h) error enters the
     *  midpoint state, and the vortex's velocity error at CFL 0.5 stays at 2.6x its small-dt value (docs/gpr-model.md
     *  3.1). Once per step, with the first stress iterate: each Picard iterate adds these gradients to its own cell
     *  values, so that the Picard loop costs no extra reconstruction. Collective. */
    void reconstructStart()
    {
        {
            ScopedTimer timer(md_.timers, Phase::Reconstruction);
            limitedGradients<D, P>(md_.m, md_.read("state"), md_.aux, stressIterate(), md_.geom, md_.read("x"),
                                   md_.write("gradients_n"), md_.bc, md_.limiter,
                                   md_.reconstruct, md_.pressureLimiter, &md_.gradientSums);
            if (fallbackMarked_)
                dropFlaggedGradients(md_.write("gradients_n"), md_.read("first_order"), md_.m.nOwnedCells);
        }
        halo("gradients_n");
        recStart_ = Reconstruction<D>{md_.read("gradients_n"), md_.read("x"), md_.geom.centroid,
                                       md_.geom.volume, md_.consistentLoad};
    }

    /*! Explicit heat fluxes of the state at t^n (2.3): independent of dt. Order 2: from theta, eps, J reconstructed
     *  at the faces, as the midpoint's (with first-order fluxes here the self-convergence of the heat-conduction
     *  scene stays at order 1.06). Collective at order 2. */
    void heatFluxes()
    {
        heatRecStart_ = md_.order2 ? reconstructHeat(md_.read("state"), md_.aux, md_.geom, md_.read("x"),
                                                     "heat_gradients_n")
                                   : Reconstruction<D>();
        ScopedTimer timer(md_.timers, Phase::HeatFluxes);
        unilag::heatFluxes<D, P>(md_.m, md_.bc, md_.read("state"), md_.aux, md_.geom, md_.cellMaterial, md_.materials,
                                 md_.heatRate, heatRecStart_);
    }

    //! The largest stable step over all ranks: CFL and the volume-change bound. Collective.
    double stableTimeStep()
    {
        ScopedTimer timer(md_.timers, Phase::TimeStep);
        return mpi::allMin(md_.comm, unilag::stableTimeStep<D>(md_.m, md_.aux, md_.geom, md_.read("v_node"),
                                                               md_.scene.cfl, md_.scene.maxVolumeChange));
    }

    /*! Order 2, the a posteriori first-order fallback (docs/gpr-model.md 2.5): a new step starts with no cell
     *  marked. Steps without a fallback (nearly all) pay neither this fill nor the gradient drops. */
    void clearFallback()
    {
        if (fallbackMarked_)
            Kokkos::deep_copy(md_.write("first_order"), 0.0);
        fallbackMarked_ = false;
    }

    /*! Marks the cells that the last update left inadmissible (state_new, geomNew) for first order in the rest of
     *  this step, with their ghosts; returns how many were marked, over all ranks. Collective. */
    long markFallback()
    {
        const LO local = flagInadmissible<D, P>(md_.m, md_.read("state_new"), md_.geomNew, md_.cellMaterial,
                                                md_.materials, md_.write("first_order"));
        halo("first_order");
        double count[1] = {double(local)};
        mpi::allSum(md_.comm, count);
        fallbackMarked_ = fallbackMarked_ || count[0] > 0.0;
        return long(count[0]);
    }

    /*! The fallback's last resort: every cell first order for the rest of this step, which then fails only where a
     *  first-order step would. Returns how many cells were not marked yet, over all ranks. Collective. */
    long markAllFallback()
    {
        double count[1] = {double(flagAll(md_.write("first_order"), md_.m.nOwnedCells))};
        mpi::allSum(md_.comm, count);
        fallbackMarked_ = true;
        return long(count[0]);
    }

    void halo(const std::string& field)
    {
        ScopedTimer timer(md_.timers, Phase::Halo);
        md_.fields.halo(field);
    }

    /*! First-order update of the owned cells over dt from the forces of the state at t^n (2b, 2c) and the Simpson
     *  GCL (2a), into state_new, x_new, geomNew. Strain variants: the converged Picard iterate has moved the nodes
     *  and left G^{n+1} in state_new. Returns the global validity extrema. Collective. */
    UpdateCheck updateCells(double dt)
    {
        auto x = md_.read("x");
        auto v = md_.read("v_node");
        auto xn = md_.write("x_new");
        if constexpr (!P::strain)
            moveNodes(x, v, dt, xn, md_.m.nNodes, D);
        const ConstField sigma = stressIterate();
        const CellFlux<D> flux{md_.read("state"), md_.aux, sigma, md_.geom, recStart_};
        UpdateCheck check;
        {
            ScopedTimer timer(md_.timers, Phase::CellUpdate);
            check = reduceCheck(unilag::updateCells<D, P>(md_.m, md_.read("state"), md_.aux, md_.geom, md_.mass(),
                                                  md_.cellMaterial, md_.materials, x, xn, v, dt, md_.write("state_new"),
                                                  sigma, md_.heatRate, md_.geomNew, flux));
        }
        balance_ = balanceOf(subcellForces<D, P>(md_.m, md_.read("state"), md_.aux, sigma, md_.geom, v, flux),
                             heatRecStart_);
        return check;
    }

    /*! The nodes whose force balance each update evaluates: every owned node (everyNode: --check, which asserts the
     *  interior balance) or only those on a boundary (enough for the impulse and work). */
    void selectBalanceNodes(bool everyNode);
    //! After a repartition: no cell is marked for the fallback, and first_order is refilled at the next mark.
    void onNewMesh() { fallbackMarked_ = true; }
    //! The force balance (and boundary heat) of the last update's forces, global over the ranks.
    const BalanceRates<D>& lastBalance() const { return balance_; }

    /*! The new state becomes the state: its ghosts are exchanged, positions and the owned cells' geometry taken
     *  over from the update, the ghosts' geometry and every cell's EOS recomputed. Collective. */
    void advance(const char* lagged = "v_node")
    {
        halo("state_new");
        md_.fields.swap("state", "state_new");
        md_.fields.swap("x", "x_new");
        std::swap(md_.geom, md_.geomNew); // owned cells: written by the update; ghosts are computed here
        refreshGeometry(md_.m.nOwnedCells);
        computeAux(lagged);
    }

    /*! The entropy filter over dt (scheme.entropy_filter; EntropyFilter.hpp, docs/gpr-model.md 2.7) on the state
     *  that advance() left, with its ghosts, EOS and impedance renewed (renewAux). Collective; no-op at C = 0. */
    void filterEntropy(double dt)
    {
        if (!(md_.scene.entropyFilter > 0.0))
            return;
        {
            ScopedTimer timer(md_.timers, Phase::EntropyFilter);
            epsGradientFromFaces<D>(md_.m, md_.aux, md_.geom, md_.read("x"), md_.bc, md_.write("eps_gradient"));
        }
        halo("eps_gradient");
        {
            ScopedTimer timer(md_.timers, Phase::EntropyFilter);
            unilag::filterEntropy<D, P>(md_.m, md_.write("state"), md_.aux, md_.geom, md_.mass(),
                                        md_.read("eps_gradient"), dt, md_.scene.entropyFilter);
        }
        halo("state");
        renewAux();
    }

    //! The global extrema of a cell update's checks. Collective.
    UpdateCheck reduceCheck(UpdateCheck check)
    {
        double ext[3] = {-check.minVolumeRatio, -check.minSound2, check.maxGclDefect};
        mpi::allMax(md_.comm, ext, 3);
        check.minVolumeRatio = -ext[0];
        check.minSound2 = -ext[1];
        check.maxGclDefect = ext[2];
        return check;
    }

    // Strain variants: the Picard coupling (GprPicard.hpp).
    void startPicard(long step);
    void notePredictorStress();
    bool picard(double dt, int& iterations, std::string& failure);
    std::string inadmissible(LO badCell, const std::string& where, double dt);

    // Stored stages, for integrators that combine several (GprStages.hpp).
    void storeStageRates(const std::string& name, bool stage = false);
    UpdateCheck updateFromStages(double dt, const std::vector<std::pair<std::string, double>>& stages);

    // Second order: the corrector's pieces (GprCorrector.hpp).
    void midpointState(double t, double dt);
    void stageState(double tStage);
    bool correctorUpdate(double dt, UpdateCheck& check, std::string& failure);

    // IMEX ARS(2,2,2) (GprArs.hpp).
    void keepStrainIncrement(bool keep);
    void storeStageVelocity(const std::string& name);
    bool arsFinal(double dt, UpdateCheck& check, std::string& failure);

  private:
    //! computeEos of the state (and sigma^n, strain variants) for all local cells; returns the state it read.
    ConstField computeEosOfState()
    {
        auto s = md_.read("state");
        Field sigma;
        if constexpr (P::strain)
            sigma = md_.overwrite("sigma");
        computeEos<D, P>(s, md_.cellMaterial, md_.materials, md_.aux, md_.m.nCells, sigma);
        return s;
    }

    //! The stress iterate sigma (strain variants; none for the hydrodynamic variants).
    ConstField stressIterate()
    {
        if constexpr (P::strain)
            return md_.read("sigma");
        return ConstField();
    }

    //! Order 2, heat: the limited gradients of theta, eps, J of (state, aux) on (geom, x), into the field name and
    //! exchanged. Collective.
    Reconstruction<D> reconstructHeat(const ConstField& state, const ConstField& aux, const CellGeometry& geom,
                                      const ConstField& x, const char* name)
    {
        {
            ScopedTimer timer(md_.timers, Phase::Reconstruction);
            limitedGradientsOf<D>(md_.m, heat::Quantities<D, P>{state, aux, md_.bc}, geom, x, md_.write(name), md_.bc,
                                  md_.limiter, &md_.gradientSums);
        }
        halo(name);
        return Reconstruction<D>{md_.read(name), x, geom.centroid, geom.volume, false};
    }

    PicardCheck strainStep(double dt, bool midpoint);
    //! heatRec: the heat fluxes' reconstruction of the forces' state (the stage state's heatRec_; none at t^n)
    BalanceRates<D> balanceOf(const SubcellForces<D, P>& forces, const Reconstruction<D>& heatRec = {});
    GprModel<D, P>& md_;
    Reconstruction<D> recStart_; //!< order 2: the limited gradients of the state at t^n (predictor)
    bool fallbackMarked_ = true; //!< some cell is marked in first_order (true at first: the field is not filled)
    Reconstruction<D> rec_;      //!< order 2: the midpoint state's limited gradients
    Reconstruction<D> heatRec_;  //!< order 2, heat: the midpoint state's theta, eps, J gradients
    Reconstruction<D> heatRecStart_; //!< order 2, heat: those of the state at t^n
    bool keepIncrement_ = false; //!< ARS(2,2,2) stage 1: strainStep keeps dT in the field ars_strain_increment
    View<LO*> balanceNodes_; //!< owned nodes whose balance is evaluated (selectBalanceNodes)
    Field balanceScratch_;   //!< per node: NodeBalanceLayout
    BalanceRates<D> balance_;
    std::map<std::string, BalanceRates<D>> stageBalance_; //!< stored stages' balances, by stage name
};

} // namespace unilag

#include "solver/GprArs.hpp"
#include "solver/GprCorrector.hpp"
#include "solver/GprNodeBalance.hpp"
#include "solver/GprPicard.hpp"
#include "solver/GprStages.hpp"
