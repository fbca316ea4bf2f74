/*! \file GprDiagnostics.hpp
 *  \brief What a run reports about its state: conserved totals, the diagnosis of a rejected step or a collapsed
 *  time step, boundary radii (shells), and errors against a radial exact solution (Sedov).
 */
#pragma once

#include <sstream>
#include <tuple>
#include <vector>

#include "physics/Exact.hpp"
#include "solver/GprModel.hpp"

namespace unilag
{

/*! The columns of totals(): mass, momentum, energy and sum m|v| (conservation), then what the angular momentum about
 *  the centre of mass is formed from (GprRun.hpp angularMomentum): about the origin (its z in 2D), sum m, sum m x,
 *  sum m |x|^2 and sum m |v|^2. */
template <int D> struct TotalsLayout
{
    enum : int
    {
        mass = 0,                        //!< sum |T_i| / omega_i (tests the GCL)
        momentum = 1,                    //!< D columns
        energy = 1 + D,                  //!< total energy
        speed = 2 + D,                   //!< sum m |v|, the momentum in play
        angular = 3 + D,                 //!< sum m x × v, NL columns
        NL = D == 2 ? 1 : 3,
        cellMass = angular + NL,         //!< sum m
        firstMoment = cellMass + 1,      //!< sum m x, D columns
        secondMoment = firstMoment + D,  //!< sum m |x|^2
        kinetic = secondMoment + 1,      //!< sum m |v|^2
        size = kinetic + 1,
    };
};

/*! Over owned cells, the TotalsLayout columns (x_i the centroid). The angular momentum is not conserved by the
 *  scheme, which dissipates the velocity jumps of a rotation (docs/gpr-model.md 3.11). Collective. */
template <int D, class P> void totals(const GprModel<D, P>& md, double (&out)[TotalsLayout<D>::size])
{
    using S = StateLayout<D, P>;
    using T = TotalsLayout<D>;
    auto s = md.fields["state"].getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto volume = md.geom.volume;
    auto centroid = md.geom.centroid;
    auto mass = md.mass();
    auto sum = KOKKOS_LAMBDA(const LO i, double(&acc)[T::size])
    {
        const double m = mass(i);
        acc[T::mass] += volume(i) / s(i, S::omega);
        double v2 = 0.0, x2 = 0.0, v[3] = {0.0, 0.0, 0.0}, x[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < D; ++d)
        {
            v[d] = s(i, S::vel + d);
            x[d] = centroid(i, d);
            acc[T::momentum + d] += m * v[d];
            acc[T::firstMoment + d] += m * x[d];
            v2 += v[d] * v[d];
            x2 += x[d] * x[d];
        }
        acc[T::energy] += m * s(i, S::energy);
        acc[T::speed] += m * Kokkos::Experimental::sqrt(v2);
        const double cross[3] = {x[1] * v[2] - x[2] * v[1], x[2] * v[0] - x[0] * v[2], x[0] * v[1] - x[1] * v[0]};
        for (int c = 0; c < T::NL; ++c)
            acc[T::angular + c] += m * cross[T::NL == 1 ? 2 : c];
        acc[T::cellMass] += m;
        acc[T::secondMoment] += m * x2;
        acc[T::kinetic] += m * v2;
    };
    sumReduce<T::size>("unilag::diagnostics::totals", md.m.nOwnedCells, sum, out);
    mpi::allSum(md.comm, out);
}

/*! The diagnosis of a rejected update: the bad cell with the lowest global id (each rank's check holds its bad
 *  cell of lowest local index, and owned cells are sorted by global id, so the text is the same on any number of
 *  ranks), where it is at t, and its state. Collective. */
template <int D, class P>
std::string diagnose(const GprModel<D, P>& md, const UpdateCheck& check, double t, double dt, int attempts)
{
    using S = StateLayout<D, P>;
    std::string local;
    const double gid = check.worstCell >= 0 ? double(md.mesh->cellGid[check.worstCell]) : 1e300;
    const int owner = mpi::argMinRank(md.comm, gid); // collective: every rank calls it
    if (check.worstCell >= 0 && owner == md.rank)
    {
        const auto& dm = *md.mesh;
        const LO i = check.worstCell;
        auto sn = md.fields["state_new"].getLocalViewHost(Tpetra::Access::ReadOnly);
        auto state0 = md.fields["state"].getLocalViewHost(Tpetra::Access::ReadOnly);
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
        auto volNew = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geomNew.volume);
        auto mats = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.materials);
        auto matOf = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.cellMaterial);
        const Material& m = mats(matOf(i));
        // The admissibility test of the update (CellUpdateApply.hpp), on this cell.
        Vec<D> v, J;
        gpr::Sym3 G;
        loadKinematics<D, P>(sn, i, v, G, J);
        const double rho = 1.0 / sn(i, S::omega);
        const double eps = internalEnergy<D, P>(m, sn(i, S::energy), v, G, J);
        const double c2 = gpr::soundSpeed2(m.eos, rho, gpr::pressure(m.eos, rho, eps));
        std::ostringstream os;
        os.precision(6);
        // where the cell is at t (the last dump shows it there), from the positions every rank agrees on
        auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::ReadOnly);
        double c[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k < D + 1; ++k)
            for (int d = 0; d < D; ++d)
                c[d] += xh(dm.cellNodesHost[(D + 1) * i + k], d) / (D + 1);
        os << "cell " << dm.cellGid[i] << " (centroid " << c[0] << ", " << c[1] << ", " << c[2]
           << ") at t = " << t << " after " << attempts << " halvings of dt (last dt " << dt << "): volume ratio "
           << volNew(i) / vol(i) << " (volume " << vol(i) << " -> " << volNew(i) << "), density " << rho
           << ", specific internal energy " << eps << " (total " << sn(i, S::energy) << ", kinetic "
           << 0.5 * dot(v, v) << ", before the step " << state0(i, S::energy) << "), squared sound speed " << c2;
        local = os.str();
    }
    return mpi::firstMessage(md.comm, local);
}

//! The time step has collapsed: report the smallest cell (the mesh is tangling there).
template <int D, class P> std::string collapse(const GprModel<D, P>& md, double t, double dt, long step)
{
    const auto& dm = *md.mesh;
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
    double smallest = 1e300;
    LO cell = -1;
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        if (vol(i) < smallest)
        {
            smallest = vol(i);
            cell = i;
        }
    const int owner = mpi::argMinRank(md.comm, smallest);
    std::string local;
    if (md.rank == owner && cell >= 0)
    {
        std::ostringstream os;
        os << "the time step collapsed to " << dt << " at t = " << t << " (step " << step << "); the smallest cell is "
           << dm.cellGid[cell] << " with volume " << vol(cell) << ": the mesh is tangling there";
        local = os.str();
    }
    return mpi::firstMessage(md.comm, local);
}

/*! What sets the stable step (TimeSystem::stepLimit): the cell with the smallest acoustic time h / s (s the nodal
 *  solver's signal speed), with the speed and length, so that a stalled run names the value behind it. */
template <int D, class P> std::string stepLimit(const GprModel<D, P>& md)
{
    using S = StateLayout<D, P>;
    const auto& dm = *md.mesh;
    auto aux = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.aux);
    auto length = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.length);
    auto time = [&](LO i) { return length(i) / std::max(aux(i, Aux::signal), 1e-300); };
    double shortest = 1e300;
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        shortest = std::min(shortest, time(i));
    shortest = mpi::allMin(md.comm, shortest);
    // of the cells at the shortest time, the lowest global id: the same cell on any number of ranks
    LO cell = -1;
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        if (time(i) == shortest && (cell < 0 || dm.cellGid[i] < dm.cellGid[cell]))
            cell = i;
    const double gid = mpi::allMin(md.comm, cell >= 0 ? double(dm.cellGid[cell]) : 1e300);
    std::string local;
    if (cell >= 0 && double(dm.cellGid[cell]) == gid)
    {
        auto sh = md.fields["state"].getLocalViewHost(Tpetra::Access::ReadOnly);
        std::ostringstream os;
        os.precision(6);
        os << "the shortest acoustic time is cell " << dm.cellGid[cell] << "'s: signal speed " << aux(cell, Aux::signal)
           << " over length " << length(cell) << " (density " << 1.0 / sh(cell, S::omega) << ", pressure "
           << aux(cell, Aux::pressure) << "): check the materials' values and time.cfl";
        local = os.str();
    }
    return mpi::firstMessage(md.comm, local);
}

/*! Per owned cell: position(centroid) (a radius, or x along a Riemann problem), density and volume, on the host.
 *  (Diagnostics at the end of a run and at outputs, not per step.) */
template <int D, class P, class Position>
std::tuple<std::vector<double>, std::vector<double>, std::vector<double>> cellSamples(const GprModel<D, P>& md,
                                                                                      Position position)
{
    using S = StateLayout<D, P>;
    const auto& dm = *md.mesh;
    auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto sh = md.fields["state"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
    std::vector<double> r(dm.nOwnedCells), rho(dm.nOwnedCells), v(dm.nOwnedCells);
    for (LO i = 0; i < dm.nOwnedCells; ++i)
    {
        double c[3] = {0, 0, 0};
        for (int k = 0; k < D + 1; ++k)
            for (int d = 0; d < D; ++d)
                c[d] += xh(dm.cellNodesHost[(D + 1) * i + k], d) / (D + 1);
        r[i] = position(c);
        rho[i] = 1.0 / sh(i, S::omega);
        v[i] = vol(i);
    }
    return {r, rho, v};
}

template <int D, class P>
std::tuple<std::vector<double>, std::vector<double>, std::vector<double>> cellRadii(const GprModel<D, P>& md)
{
    return cellSamples(md, [](const double(&c)[3]) { return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]); });
}

/*! Volume-weighted mean |rho - rho_exact(x, t)| over the domain for a Riemann problem along x (its discontinuity at
 *  x0 at t = 0), the exact solution sampled at the cells' centroids. */
template <int D, class P>
double riemannL1Density(const GprModel<D, P>& md, const tube::RiemannExact& exact, double x0, double t)
{
    auto [x, rho, vol] = cellSamples(md, [](const double(&c)[3]) { return c[0]; });
    double acc[2] = {0.0, 0.0};
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        const double exactRho = t > 0.0 ? exact.sample((x[i] - x0) / t).rho
                                        : (x[i] < x0 ? md.scene.riemannLeft.density : md.scene.riemannRight.density);
        acc[0] += vol[i] * std::abs(rho[i] - exactRho);
        acc[1] += vol[i];
    }
    mpi::allSum(md.comm, acc);
    return acc[0] / acc[1];
}

//! Mean distance from the origin of the nodes of each boundary group (shell radii: Kidder, beryllium shell).
template <int D, class P> std::vector<double> boundaryRadii(const GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    const int ng = int(dm.boundaryNames.size()), nv = D + 1;
    std::vector<std::vector<char>> on(ng, std::vector<char>(dm.nOwnedNodes, 0));
    for (LO i = 0; i < dm.nCells; ++i)
        for (int j = 0; j < nv; ++j)
        {
            const int g = dm.cellFaceGroupHost[nv * i + j];
            if (g < 0)
                continue;
            for (int k = 0; k < nv; ++k)
            {
                const LO r = dm.cellNodesHost[nv * i + k];
                if (k != j && r < dm.nOwnedNodes)
                    on[g][r] = 1;
            }
        }
    auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<double> acc(2 * std::size_t(ng), 0.0);
    for (int g = 0; g < ng; ++g)
        for (LO r = 0; r < dm.nOwnedNodes; ++r)
            if (on[g][r])
            {
                double r2 = 0.0;
                for (int d = 0; d < D; ++d)
                    r2 += xh(r, d) * xh(r, d);
                acc[2 * g] += std::sqrt(r2);
                acc[2 * g + 1] += 1.0;
            }
    MPI_Allreduce(MPI_IN_PLACE, acc.data(), 2 * ng, MPI_DOUBLE, MPI_SUM, md.comm);
    std::vector<double> radii(ng);
    for (int g = 0; g < ng; ++g)
        radii[g] = acc[2 * g + 1] > 0 ? acc[2 * g] / acc[2 * g + 1] : 0.0;
    return radii;
}

//! Volume-weighted mean |rho - rho_exact(|centroid|)| over the domain.
template <int D, class P>
double radialL1Density(const GprModel<D, P>& md, const RadialProfile& exact, double radiusScale)
{
    auto [r, rho, vol] = cellRadii(md);
    double acc[2] = {0.0, 0.0};
    for (std::size_t i = 0; i < r.size(); ++i)
    {
        acc[0] += vol[i] * std::abs(rho[i] - exact.density(radiusScale * r[i]));
        acc[1] += vol[i];
    }
    mpi::allSum(md.comm, acc);
    return acc[0] / acc[1];
}

//! Radius where the shell-averaged density falls to half-way between its peak and the ambient value.
template <int D, class P> double shockRadius(const GprModel<D, P>& md, const RadialProfile& exact)
{
    auto [r, rho, vol] = cellRadii(md);
    double hsum[2] = {0.0, double(r.size())};
    {
        auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.length);
        for (LO i = 0; i < md.m.nOwnedCells; ++i)
            hsum[0] += len(i);
    }
    mpi::allSum(md.comm, hsum);
    const double width = 2.0 * hsum[0] / hsum[1];
    double rmax = 0.0;
    for (double x : r)
        rmax = std::max(rmax, x);
    rmax = -mpi::allMin(md.comm, -rmax);
    const int nb = int(rmax / width) + 1;
    std::vector<double> bins(2 * nb, 0.0);
    for (std::size_t i = 0; i < r.size(); ++i)
    {
        const int b = std::min(nb - 1, int(r[i] / width));
        bins[2 * b] += vol[i] * rho[i];
        bins[2 * b + 1] += vol[i];
    }
    MPI_Allreduce(MPI_IN_PLACE, bins.data(), 2 * nb, MPI_DOUBLE, MPI_SUM, md.comm);
    std::vector<double> mean(nb, -1.0);
    int peak = 0;
    for (int b = 0; b < nb; ++b)
        if (bins[2 * b + 1] > 0.0)
        {
            mean[b] = bins[2 * b] / bins[2 * b + 1];
            if (mean[b] > mean[peak])
                peak = b;
        }
    const double ambient = exact.ambientDensity();
    const double level = ambient + 0.5 * (mean[peak] - ambient);
    for (int b = peak + 1; b < nb; ++b)
        if (mean[b] >= 0.0 && mean[b] < level)
        {
            int a = b - 1;
            while (a > peak && mean[a] < 0.0)
                --a;
            const double ra = (a + 0.5) * width, rb = (b + 0.5) * width;
            return ra + (rb - ra) * (mean[a] - level) / (mean[a] - mean[b]);
        }
    return (peak + 0.5) * width;
}

} // namespace unilag
