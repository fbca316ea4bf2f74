/*! \file GprRun.hpp
 *  \brief One GPR run from a distributed mesh to an exit code: set-up, the time loop, then conservation, errors
 *  against the exact solution, summary.json, the one-line summary and the self-check (--check).
 */
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/OutputFolder.hpp"
#include "solver/GprSetup.hpp"
#include "solver/GprStationary.hpp"
#include "solver/GprSystem.hpp"
#include "solver/RunOptions.hpp"
#include "solver/Summary.hpp"

namespace unilag
{

/*! The angular momentum about the centre of mass, L = sum m (x - x_c) × (v - v_c) = L_0 - M x_c × v_c (its z in 2D),
 *  and sqrt(I K) with I = sum m |x - x_c|^2, K = sum m |v - v_c|^2, which bounds |L| (Cauchy-Schwarz) and equals it
 *  for a rigid rotation: the angular momentum in play. From the sums of totals(). */
template <int D> struct AngularMomentum
{
    double L[3] = {0.0, 0.0, 0.0};
    double scale = 0.0;
};

template <int D> AngularMomentum<D> angularMomentum(const std::vector<double>& t)
{
    using T = TotalsLayout<D>;
    AngularMomentum<D> a;
    const double M = std::max(t[T::cellMass], 1e-300);
    double xc[3] = {0.0, 0.0, 0.0}, vc[3] = {0.0, 0.0, 0.0}, x2 = 0.0, v2 = 0.0;
    for (int d = 0; d < D; ++d)
    {
        xc[d] = t[T::firstMoment + d] / M;
        vc[d] = t[T::momentum + d] / M;
        x2 += xc[d] * xc[d];
        v2 += vc[d] * vc[d];
    }
    const double cross[3] = {xc[1] * vc[2] - xc[2] * vc[1], xc[2] * vc[0] - xc[0] * vc[2],
                             xc[0] * vc[1] - xc[1] * vc[0]};
    for (int k = 0; k < T::NL; ++k)
        a.L[k] = t[T::angular + k] - M * cross[T::NL == 1 ? 2 : k];
    a.scale = std::sqrt(std::max(0.0, t[T::secondMoment] - M * x2) * std::max(0.0, t[T::kinetic] - M * v2));
    return a;
}

//! Conservation over a run: mass from the geometry (GCL), momentum and energy net of boundary impulse and work.
struct Conservation
{
    double mass = 0.0, momentum = 0.0, energy = 0.0;
    double energyScale = 0.0; //!< the largest energy in play, what the energy defects are relative to
    //! |L_final - L_initial| / the larger sqrt(I K) (about the centre of mass; boundary torques not subtracted)
    double angularMomentum = 0.0;
};

template <int D>
Conservation conservation(const std::vector<double>& initial, const std::vector<double>& final_,
                          const BoundaryBalance<D>& boundary)
{
    using T = TotalsLayout<D>;
    const double(&impulse)[D] = boundary.impulse;
    const double work = boundary.work + boundary.heat; // the energy the boundaries gave
    Conservation c;
    c.mass = std::abs(final_[T::mass] - initial[T::mass]) / initial[T::mass];
    double dp = 0.0;
    for (int d = 0; d < D; ++d)
        dp += std::pow(final_[T::momentum + d] - initial[T::momentum + d] - impulse[d], 2);
    // relative to the momentum in play: sum m|v|, or for a body nearly at rest sqrt(2 M E), the momentum its
    // energy could give it (the forces whose round-off this measures scale with it)
    const double momentumScale = std::max(final_[T::speed] + initial[T::speed],
                                          std::sqrt(2.0 * initial[T::mass] * std::abs(initial[T::energy])));
    c.momentum = std::sqrt(dp) / std::max(momentumScale, 1e-300);
    // relative to the largest energy in play (a body at rest hit by a piston starts with none)
    c.energyScale = std::max({std::abs(initial[T::energy]), std::abs(final_[T::energy]), std::abs(work), 1e-300});
    c.energy = std::abs(final_[T::energy] - initial[T::energy] - work) / c.energyScale;
    const AngularMomentum<D> a0 = angularMomentum<D>(initial), a1 = angularMomentum<D>(final_);
    double dl = 0.0;
    for (int k = 0; k < T::NL; ++k)
        dl += std::pow(a1.L[k] - a0.L[k], 2);
    c.angularMomentum = std::sqrt(dl) / std::max({a0.scale, a1.scale, 1e-300});
    return c;
}

//! Errors against the scene's exact solution (Sedov: self-similar radial profile); -1 where there is none.
struct ExactErrors
{
    double l1 = -1.0, shock = -1.0, exactShock = 0.0;
    StationaryErrors stationary; //!< exact.solution: stationary (L2 errors; -1 otherwise)
};

template <int D, class P> ExactErrors exactErrors(const GprModel<D, P>& md, double t)
{
    ExactErrors e;
    e.exactShock = md.scene.exactShockRadius;
    if (md.scene.exactSolution == ExactSolution::Stationary)
        e.stationary = stationaryErrors(md);
    if (md.scene.exactSolution == ExactSolution::Riemann)
        e.l1 = riemannL1Density(md, riemannSolution(md.scene), md.scene.riemannPosition, t);
    if (md.scene.exactSolution != ExactSolution::Sedov)
        return e;
    // R(t) = R(t_table) (t / t_table)^alpha, alpha = 2 / (d + 2) (planar energy release in d dimensions); the
    // profile is a function of r / R(t).
    const RadialProfile exact(md.scene.exactTable);
    const double scale = std::pow(t / md.scene.exactTime, 2.0 / (D + 2.0));
    e.l1 = radialL1Density(md, exact, 1.0 / scale);
    e.shock = shockRadius(md, exact);
    e.exactShock *= scale;
    return e;
}

/*! The cells tile the domain: |sum_i |T_i| - (1/D) sum_f x_f . A_f| / sum_i |T_i| over the boundary faces f (centroid
 *  x_f, outward area vector A_f = -D c_k of the face opposite corner k). Exact for simplices up to round-off (the
 *  divergence theorem per cell; interior faces cancel), so a node moved differently by two cells or two ranks shows.
 *  Mass needs no such check: m_i is constant and omega_i = |T_i| / m_i by construction. Collective. */
template <int D, class P> double volumeIdentityDefect(const GprModel<D, P>& md)
{
    constexpr int NV = D + 1;
    const MeshView<D> mesh = md.m;
    auto x = md.read("x");
    auto corner = md.geom.corner;
    auto volume = md.geom.volume;
    auto sum = KOKKOS_LAMBDA(const LO i, double(&acc)[2])
    {
        acc[0] += volume(i);
        for (int k = 0; k < NV; ++k)
        {
            if (mesh.cellFaceGroup(i, k) < 0)
                continue;
            for (int j = 0; j < NV; ++j)
                if (j != k)
                    for (int d = 0; d < D; ++d) // (1/D) x_f . A_f with x_f the mean of the face's D nodes
                        acc[1] -= x(mesh.cellNodes(i, j), d) * corner(i, k * D + d) / D;
        }
    };
    double v[2];
    sumReduce<2>("unilag::check::volume_identity", mesh.nOwnedCells, sum, v);
    mpi::allSum(md.comm, v);
    return std::abs(v[0] - v[1]) / v[0];
}

//! --check: conservation to round-off and the scene's error bounds; prints what failed (rank 0).
template <int D, class P>
int selfCheck(const GprModel<D, P>& md, const GprSystem<D, P>& sys, const Conservation& c, const ExactErrors& x,
              const std::vector<double>& radii)
{
    std::vector<std::string> fails;
    auto bound = [&](const std::string& what, double value, double limit)
    {
        if (!(value <= limit))
        {
            std::ostringstream os;
            os << what << " = " << value << " exceeds " << limit;
            fails.push_back(os.str());
        }
    };
    // Round-off bounds: everything is conservative by construction. Worst measured over the 110 --check runs of the
    // test suite: momentum 7.5e-15, energy 1.1e-15, GCL 6.1e-14, node imbalance 2.9e-15, volume 1.5e-16. The
    // accumulated sums keep 1e-12, room for runs 100x longer than the tests' (round-off grows with the steps).
    bound("mass relative change", c.mass, 1e-12);
    bound("momentum relative change", c.momentum, 1e-12);
    bound("energy relative change", c.energy, 1e-12);
    bound("GCL defect |m omega - |T|| / |T|", sys.maxGclDefect(), 1e-12);
    bound("volume identity |sum |T_i| - boundary integral of x.n / D| / sum |T_i|", volumeIdentityDefect(md), 1e-13);
    // The nodal solver's balance, from the forces the updates applied (NodeBalance.hpp): zero net force at
    // interior nodes, the imposed traction at free, pressure and traction nodes, no work by walls.
    const BoundaryBalance<D>& b = sys.balance();
    bound("force imbalance at node " + std::to_string(b.worstNode) + " (t = " + jsonNumber(b.worstTime) +
              ") relative to the forces on it",
          b.maxImbalance, 1e-13);
    bound("work of slip walls, symmetry planes and free surfaces relative to the energy",
          std::abs(b.passiveWork) / c.energyScale, 1e-13);
    const Scene& scene = md.scene;
    if (scene.maxL1Density > 0.0)
        bound("L1(density) error", x.l1, scene.maxL1Density);
    const DensityPeak peak = sys.largestDensity(); // collective: every rank
    if (scene.maxDensity > 0.0)
        bound("largest cell density over the run (cell " + std::to_string(peak.cell) + ", t = " +
                  jsonNumber(peak.t) + ")",
              peak.value, scene.maxDensity);
    const char* l2Names[3] = {"L2 error of the specific volume", "L2 error of the velocity",
                              "L2 error of the total energy"};
    const double l2[3] = {x.stationary.specificVolume, x.stationary.velocity, x.stationary.energy};
    for (int k = 0; k < 3; ++k)
        if (scene.maxL2[k] > 0.0)
            bound(l2Names[k], l2[k], scene.maxL2[k]);
    if (scene.shockRadiusTolerance > 0.0)
        bound("relative shock radius error", std::abs(x.shock - x.exactShock) / x.exactShock,
              scene.shockRadiusTolerance);
    if (scene.radiusTolerance > 0.0)
        for (const auto& [group, exact] : scene.boundaryRadius)
        {
            const auto& names = md.mesh->boundaryNames;
            const auto it = std::find(names.begin(), names.end(), group);
            const double r = it == names.end() ? -1.0 : radii[it - names.begin()];
            bound("relative error of the mean radius of '" + group + "'", std::abs(r - exact) / exact,
                  scene.radiusTolerance);
        }
    return reportCheck(fails, md.rank == 0);
}

//! The smallest shapeQuality over the cells of every rank, on the current positions. Collective.
template <int D, class P> double minShapeQuality(const GprModel<D, P>& md)
{
    const MeshView<D> mesh = md.m;
    auto x = md.read("x");
    auto length = md.geom.length;
    auto quality = KOKKOS_LAMBDA(const LO i, double(&acc)[1])
    {
        Vec<D> xi[D + 1];
        gatherNodes<D>(mesh, x, i, xi);
        const double q = shapeQuality<D>(xi, length(i));
        acc[0] = q < acc[0] ? q : acc[0];
    };
    double q[1];
    minReduce<1>("unilag::check::shape_quality", mesh.nOwnedCells, quality, q);
    return mpi::allMin(md.comm, q[0]);
}

//! The angular momentum about the centre of mass of totals() as JSON: its z component in 2D, [x, y, z] in 3D.
template <int D> std::string angularText(const std::vector<double>& totals)
{
    const AngularMomentum<D> a = angularMomentum<D>(totals);
    if constexpr (D == 2)
        return jsonNumber(a.L[0]);
    else
        return "[" + jsonNumber(a.L[0]) + ", " + jsonNumber(a.L[1]) + ", " + jsonNumber(a.L[2]) + "]";
}

template <int D, class P>
void writeSummary(const GprModel<D, P>& md, const GprSystem<D, P>& sys, const RunOptions& options, const LoopResult& r,
                  const Conservation& c, const ExactErrors& x, const std::vector<double>& radii, const LoopState& from)
{
    const auto& dm = *md.mesh;
    // the rate of this process's steps (a restart's wall time is its own, its steps counted from the checkpoint)
    const double cellSteps =
        double(dm.nGlobalCells) * double(r.state.steps - from.steps) / std::max(r.wallSeconds, 1e-300);
    const double initialQuality = sys.initialQuality();
    const double picardMean = r.state.steps > 0 ? double(sys.picardTotal()) / r.state.steps : 0.0;
    Summary s =
        runSummary(md.scene.file, md.scene.name, r, D, dm.nGlobalCells, dm.nGlobalNodes, md.size, options.threads);
    s.object("physics", {{"strain", P::strain ? "true" : "false"},
                         {"plastic", P::plastic ? "true" : "false"},
                         {"heat", P::heat ? "true" : "false"}});
    s.object("picard_iterations", {{"mean", jsonNumber(picardMean)}, {"max", std::to_string(sys.picardMax())}});
    s.integer("first_order_fallback_cells", sys.fallbackCells());
    if (sys.usesArs222())
        s.integer("midpoint_steps", sys.midpointSteps());
    s.number("t_final", r.state.t).number("wall_seconds", r.wallSeconds).number("cell_steps_per_second", cellSteps);
    if (!options.restart.empty())
        s.object("restarted_from", {{"step", std::to_string(from.steps)}, {"t", jsonNumber(from.t)}});
    s.number("mass_relative_change", c.mass).number("momentum_relative_change", c.momentum);
    s.number("energy_relative_change", c.energy).number("max_gcl_defect", sys.maxGclDefect());
    s.object("angular_momentum", {{"initial", angularText<D>(r.initialTotals)},
                                  {"final", angularText<D>(r.finalTotals)},
                                  {"relative_change", jsonNumber(c.angularMomentum)}});
    const BoundaryBalance<D>& b = sys.balance();
    std::vector<std::pair<std::string, std::string>> impulse;
    for (int d = 0; d < D; ++d)
        impulse.emplace_back(std::string(1, char('x' + d)), jsonNumber(b.impulse[d]));
    s.object("boundary_impulse", impulse);
    s.number("boundary_work", b.work).number("wall_work", b.passiveWork).number("boundary_heat", b.heat);
    s.number("max_node_force_imbalance", b.maxImbalance).number("volume_identity_defect", volumeIdentityDefect(md));
    const double finalQuality = minShapeQuality(md);
    const DensityPeak peak = sys.largestDensity();
    std::string at = "[" + jsonNumber(peak.centroid[0]);
    for (int d = 1; d < D; ++d)
        at += ", " + jsonNumber(peak.centroid[d]);
    s.object("largest_density", {{"value", jsonNumber(peak.value)},
                                 {"t", jsonNumber(peak.t)},
                                 {"cell", std::to_string(peak.cell)},
                                 {"centroid", at + "]"}});
    s.object("min_shape_quality", {{"initial", jsonNumber(initialQuality)}, {"final", jsonNumber(finalQuality)}});
    if (x.l1 >= 0.0)
        s.number("l1_density_error", x.l1);
    if (x.shock >= 0.0)
        s.number("shock_radius", x.shock).number("exact_shock_radius", x.exactShock);
    if (x.stationary.specificVolume >= 0.0)
        s.object("l2_error", {{"specific_volume", jsonNumber(x.stationary.specificVolume)},
                              {"velocity", jsonNumber(x.stationary.velocity)},
                              {"energy", jsonNumber(x.stationary.energy)},
                              {"h_final", jsonNumber(x.stationary.h)}});
    std::vector<std::pair<std::string, std::string>> mean;
    for (std::size_t g = 0; g < radii.size(); ++g)
        mean.emplace_back(dm.boundaryNames[g], jsonNumber(radii[g]));
    s.object("boundary_mean_radius", mean);
    s.timeShares(md.timers, r.wallSeconds);
    if (!r.failure.empty())
        s.text("failure", r.failure);
    s.text("output", sys.writer() ? sys.writer()->collectionPath() : std::string());
    if (md.rank != 0)
        return;
    s.write((std::filesystem::path(md.scene.outputDirectory) / "summary.json").string());
    std::printf("unilag: %s %dD, %lld cells, %d rank(s) x %d thread(s): %ld steps to t = %.6g in %.3g s "
                "(%.3g cell-steps/s); mass %.1e, momentum %.1e, energy %.1e",
                md.scene.name.c_str(), D, (long long)dm.nGlobalCells, md.size, options.threads, r.state.steps,
                r.state.t, r.wallSeconds, cellSteps, c.mass, c.momentum, c.energy);
    if (P::strain)
        std::printf("; Picard %.2f mean, %d max", picardMean, sys.picardMax());
    if (x.l1 >= 0.0)
        std::printf("; L1(density) %.4g", x.l1);
    if (x.shock >= 0.0)
        std::printf(", shock radius %.4g", x.shock);
    if (x.stationary.specificVolume >= 0.0)
        std::printf("; L2 omega %.4g, v %.4g, E %.4g (h %.3g)", x.stationary.specificVolume, x.stationary.velocity,
                    x.stationary.energy, x.stationary.h);
    std::printf("\nunilag: output in %s\n",
                (sys.writer() ? sys.writer()->collectionPath() : md.scene.outputDirectory).c_str());
}

//! Runs the scene on the distributed mesh; returns an ExitCode. Collective.
template <int D, class P>
int runGpr(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options)
{
    GprModel<D, P> md(scene, mesh);
    const std::string error = initialize(md);
    if (!error.empty())
    {
        if (md.rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    GprSystem<D, P> sys(md, options.check);
    const bool restart = !options.restart.empty();
    LoopState from; // a new run starts at t = 0; a restart where its checkpoint stopped (InputError if it cannot)
    if (restart)
        from = sys.restore(options.restart);
    if (restart && !(scene.endTime > from.t)) // nothing to continue: not a finished run's summary
        throw InputError(scene.file + ": key 'time.end': " + jsonNumber(scene.endTime) +
                         " is not after the checkpoint's time " + jsonNumber(from.t));
    // Only now, with the input fully validated, does anything get written.
    if (md.rank == 0)
    {
        std::filesystem::create_directories(scene.outputDirectory);
        // the previous run's own outputs (by name; nothing else), so that no dump of a longer run survives; a
        // restart continues them
        if (!restart)
            io::removeRunOutputs(scene.outputDirectory);
        writeScene(scene, (std::filesystem::path(scene.outputDirectory) / "scene.yaml").string());
    }
    MPI_Barrier(md.comm);
    if (scene.writeOutput)
        sys.openOutput(scene.outputDirectory, from.dumps);
    if (!restart)
    {
        sys.start();
        sys.setInitialQuality(minShapeQuality(md));
    }
    const LoopResult r = runTimeLoop(sys, timeControl(scene, options), md.comm, from);
    const Conservation c = conservation<D>(r.initialTotals, r.finalTotals, sys.balance());
    const ExactErrors x = r.failure.empty() ? exactErrors(md, r.state.t) : ExactErrors{};
    const std::vector<double> radii = boundaryRadii(md);
    writeSummary(md, sys, options, r, c, x, radii, from);
    if (!r.failure.empty())
    {
        if (md.rank == 0)
            std::fprintf(stderr, "unilag: error: the run went unstable: %s\n", r.failure.c_str());
        return ExitUnstable;
    }
    if (r.signal != 0)
    {
        if (md.rank == 0)
            std::fprintf(stderr, "unilag: stopped by signal %d at t = %.6g; checkpoint %s (continue with --restart)\n",
                         r.signal, r.state.t, sys.checkpointPath().c_str());
        return ExitInterrupted;
    }
    if (r.stepCapped)
    {
        if (md.rank == 0)
            std::fprintf(stderr, "unilag: stopped: time.max_steps = %ld reached at t = %.6g, before the end time %.6g\n",
                         scene.maxSteps, r.state.t, scene.endTime);
        return ExitMaxSteps;
    }
    return options.check ? selfCheck(md, sys, c, x, radii) : ExitOk;
}

} // namespace unilag
