/*! \file GprPicard.hpp
 *  \brief The implicit coupling of the stress (2.4), member functions of GprOperator for the strain variants:
 *  the first iterate, the damped Picard loop over nodal solve -> trajectories -> G_e transport and stiff relaxation
 *  -> stress, and its diagnosis. Included by GprOperator.hpp.
 */
#pragma once

#include "core/Format.hpp"

namespace unilag
{

/*! First Picard iterate of a step, by linear extrapolation in time of the previous fixed points (the steps grow by at
 *  most 10%), which saves one or two iterations; the fixed point does not depend on it. Kept in sigma0 for a retry.
 *  On all local cells, so ghosts need no exchange.
 *   - first order: sigma^0 = 2 sigma^n - sigma^{n-1} (sigma holds sigma^n, from computeAux);
 *   - second order, the predictor: sigma^0 = 2 s^{n-1/2} - s^{n-3/2} with s the previous predictors' fixed points
 *     (notePredictorStress). Extrapolating sigma^n instead starts about 1e-4 rho a^2 away on the Be shell (the
 *     first-order predictor and the second-order state differ by the scheme's truncation error), which cost
 *     8-18 iterations instead of 2. */
template <int D, class P> void GprOperator<D, P>::startPicard(long step)
{
    auto sigma = md_.write("sigma");
    auto prev = md_.write("sigma_prev");
    if (md_.order2)
    {
        if (step >= 1)
        {
            auto prev2 = md_.read("sigma_prev2");
            const bool extrapolate = step >= 2;
            auto start = KOKKOS_LAMBDA(const LO i)
            {
                for (int c = 0; c < 6; ++c)
                    sigma(i, c) = extrapolate ? 2.0 * prev(i, c) - prev2(i, c) : prev(i, c);
            };
            Kokkos::parallel_for("unilag::gpr::picard_start", range(md_.m.nCells), start);
        }
    }
    else
    {
        const bool extrapolate = step > 0;
        auto start = KOKKOS_LAMBDA(const LO i)
        {
            for (int c = 0; c < 6; ++c)
            {
                const double s = sigma(i, c);
                if (extrapolate)
                    sigma(i, c) = 2.0 * s - prev(i, c);
                prev(i, c) = s;
            }
        };
        Kokkos::parallel_for("unilag::gpr::picard_start", range(md_.m.nCells), start);
    }
    md_.fields.copy("sigma", "sigma0");
}

//! Second order: keep the accepted predictor's fixed point (sigma) and the one before, for startPicard.
template <int D, class P> void GprOperator<D, P>::notePredictorStress()
{
    md_.fields.swap("sigma_prev2", "sigma_prev");
    md_.fields.copy("sigma", "sigma_prev");
}

//! The message for a cell whose volume or G_e became inadmissible (on the rank that has it; collective).
template <int D, class P> std::string GprOperator<D, P>::inadmissible(LO badCell, const std::string& where, double dt)
{
    std::string local;
    if (badCell >= 0)
    {
        local = "cell " + std::to_string(md_.mesh->cellGid[badCell]) +
                " became inadmissible (inverted, or G_e not positive definite) " + where + " with dt " + jsonNumber(dt);
    }
    return mpi::firstMessage(md_.comm, local);
}

/*! One Picard iteration's G_e update (strainUpdate) from the node velocities of the last nodal solve: moves the nodes
 *  to x_new, writes G^{l+1} into state_new and sigma^{l+1} into sigma_next (and, for ARS(2,2,2)'s stage 1, the
 *  transport increment into ars_strain_increment: the last iteration's is the converged one's). */
template <int D, class P> PicardCheck GprOperator<D, P>::strainStep(double dt, bool midpoint)
{
    ScopedTimer timer(md_.timers, Phase::StrainUpdate);
    auto v = md_.read("v_node");
    auto xn = md_.write("x_new");
    moveNodes(md_.read("x"), v, dt, xn, md_.m.nNodes, D);
    if (midpoint)
        return strainUpdate<D, P>(md_.m, md_.read("state"), md_.aux, md_.geom, md_.mass(), md_.cellMaterial,
                                  md_.materials, xn, v, dt, md_.sigmaMid, md_.write("sigma_next"),
                                  md_.write("state_new"), md_.plasticHint(true), md_.read("state_mid"), md_.geomMid,
                                  Field(), md_.plasticWork());
    return strainUpdate<D, P>(md_.m, md_.read("state"), md_.aux, md_.geom, md_.mass(), md_.cellMaterial, md_.materials,
                              xn, v, dt, md_.read("sigma"), md_.write("sigma_next"), md_.write("state_new"),
                              md_.plasticHint(false), ConstField(), CellGeometry(),
                              keepIncrement_ ? md_.write("ars_strain_increment") : Field(), md_.plasticWork());
}

/*! Picard loop of 2.4 for a step dt: v_node holds the nodal solution for sigma = sigma^0. Each iteration moves the
 *  nodes, updates G_e implicitly (G^{l+1} into state_new) and, unless the stress has converged, solves the nodes
 *  again with sigma^{l+1}. On success v_node and sigma are the consistent pair the cell update needs (the forces at
 *  each node then balance exactly). Collective. */
template <int D, class P> bool GprOperator<D, P>::picard(double dt, int& iterations, std::string& failure)
{
    const Scene& scene = md_.scene;
    double change = 0.0, prevChange = 0.0, omega = 1.0;
    for (int l = 0; l < scene.picardMaxIterations; ++l)
    {
        iterations = l + 1;
        const PicardCheck pc = strainStep(dt, false);
        double ext[3] = {pc.maxChange, -pc.minVolumeRatio, pc.badCell >= 0 ? 1.0 : 0.0};
        mpi::allMax(md_.comm, ext, 3);
        change = ext[0];
        if (ext[2] > 0.0 || !(-ext[1] > 0.0))
        {
            failure = inadmissible(pc.badCell, "in Picard iteration " + std::to_string(l + 1), dt);
            return false;
        }
        if (change <= scene.picardTolerance)
            return true;
        if (l + 1 == scene.picardMaxIterations)
            break;
        // Damping. The iteration map sigma -> v(sigma) -> sigma' has the Jacobian -K C^T M^{-1} C (K the stiffness
        // dt rho c_sh^2, C the corner vectors, M the nodal impedance matrices): real eigenvalues in [-kappa, 0],
        // kappa ~ CFL (c_sh / a)^2 times a mesh factor, which can exceed 1 on fine meshes. Plain Picard then
        // diverges; sigma <- sigma + omega (sigma' - sigma) with omega = 2 / (2 + kappa) contracts by
        // kappa / (2 + kappa) < 1 for any kappa. kappa is estimated from the observed contraction of the residual.
        if (l >= 1 && change > 0.5 * prevChange)
        {
            const double r = change / prevChange;
            const double kappa = omega == 1.0 ? r : (r + 1.0) / omega - 1.0;
            omega = std::max(0.2, std::min(omega, 2.0 / (2.0 + std::max(kappa, 0.0))));
        }
        prevChange = change;
        if (omega < 1.0)
        {
            auto so = md_.read("sigma");
            auto snext = md_.write("sigma_next");
            const double w = omega;
            auto damp = KOKKOS_LAMBDA(const LO i)
            {
                for (int c = 0; c < 6; ++c)
                    snext(i, c) = so(i, c) + w * (snext(i, c) - so(i, c));
            };
            Kokkos::parallel_for("unilag::gpr::picard_damping", range(md_.m.nOwnedCells), damp);
        }
        md_.fields.swap("sigma", "sigma_next");
        halo("sigma");
        solveNodes();
    }
    failure = "the Picard loop did not converge in " + std::to_string(scene.picardMaxIterations) +
              " iterations (relative stress change " + jsonNumber(change) + " > tolerance " +
              jsonNumber(scene.picardTolerance) + ", last dt " + jsonNumber(dt) + ")";
    return false;
}

} // namespace unilag
