/*! \file GprStationary.hpp
 *  \brief Errors against a stationary exact solution (`exact.solution: stationary`, the isentropic vortex of the
 *  paper's convergence tables, docs/gpr-model.md 3.1): the regions' initial expressions are the solution at all
 *  times, evaluated at each cell's CURRENT centroid (the mesh has moved with the flow). Included by GprRun.hpp.
 */
#pragma once

#include <cmath>

namespace unilag
{

//! L2 errors sqrt(sum_i |T_i| e_i^2) of the specific volume, the velocity (|v - v_exact|) and the total specific
//! energy (internal + kinetic; the elastic part is the model's, ~0 in the hydrodynamic limit), and the mean
//! characteristic cell length h on the final mesh (the paper's h(Omega(t_f))). Collective.
struct StationaryErrors
{
    double specificVolume = -1.0, velocity = -1.0, energy = -1.0, h = 0.0;
};

template <int D, class P> StationaryErrors stationaryErrors(const GprModel<D, P>& md)
{
    using S = StateLayout<D, P>;
    const auto& dm = *md.mesh;
    auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto sh = md.fields["state"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
    auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.length);
    auto mats = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.materials);
    auto matOf = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.cellMaterial);
    std::vector<std::unique_ptr<RegionFunctions>> regions;
    for (const auto& name : dm.regionNames)
        regions.push_back(std::make_unique<RegionFunctions>(md.scene.regions.at(name)));
    double acc[5] = {0, 0, 0, 0, 0}; // three squared errors, sum of h, cells
    for (LO i = 0; i < dm.nOwnedCells; ++i)
    {
        double c[3] = {0, 0, 0};
        for (int k = 0; k < D + 1; ++k)
            for (int d = 0; d < D; ++d)
                c[d] += xh(dm.cellNodesHost[(D + 1) * i + k], d) / (D + 1);
        const RegionFunctions& f = *regions[dm.cellRegion[i]];
        const RegionSpec& spec = f.spec;
        const double rho = f.eval(spec.density, f.rho, c);
        const double th = f.eval(spec.hasPressure ? spec.pressure : spec.internalEnergy, f.thermo, c);
        const double eps = spec.hasPressure ? gpr::internalEnergy(mats(matOf(i)).eos, rho, th) : th;
        double dv2 = 0.0, kin = 0.0;
        for (int d = 0; d < D; ++d)
        {
            const double v = d < spec.velocityComponents ? f.eval(spec.velocity[d], f.velocity[d], c) : 0.0;
            dv2 += (sh(i, S::vel + d) - v) * (sh(i, S::vel + d) - v);
            kin += 0.5 * v * v;
        }
        const double dOmega = sh(i, S::omega) - 1.0 / rho, dE = sh(i, S::energy) - (eps + kin);
        acc[0] += vol(i) * dOmega * dOmega;
        acc[1] += vol(i) * dv2;
        acc[2] += vol(i) * dE * dE;
        acc[3] += len(i);
        acc[4] += 1.0;
    }
    mpi::allSum(md.comm, acc);
    StationaryErrors e;
    e.specificVolume = std::sqrt(acc[0]);
    e.velocity = std::sqrt(acc[1]);
    e.energy = std::sqrt(acc[2]);
    e.h = acc[3] / std::max(acc[4], 1.0);
    return e;
}

} // namespace unilag
