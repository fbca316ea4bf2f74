/*! \file GprOutput.hpp
 *  \brief HDF5/XDMF output of a GPR run: the owned cells' fields and the moving node coordinates, one dump per
 *  output time (open unilag.xmf in ParaView).
 */
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "io/XdmfWriter.hpp"
#include "solver/GprModel.hpp"

namespace unilag
{

//! The owned cells of the mesh as the writer's topology, in global output node ids (again after a repartition:
//! every dump holds its own connectivity, so the series follows the new one). Collective.
template <int D, class P> void setTopology(const GprModel<D, P>& md, io::XdmfWriter& writer)
{
    const auto& dm = *md.mesh;
    std::vector<long long> conn(std::size_t(dm.nOwnedCells) * (D + 1));
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        for (int k = 0; k < D + 1; ++k)
            conn[(D + 1) * i + k] = dm.nodeOutputId[dm.cellNodesHost[(D + 1) * i + k]];
    writer.setTopology(dm.nOwnedNodes, dm.nOwnedCells, conn);
}

//! A writer of the owned cells of the mesh. Collective.
template <int D, class P> std::unique_ptr<io::XdmfWriter> makeWriter(const GprModel<D, P>& md, const std::string& dir)
{
    auto writer = std::make_unique<io::XdmfWriter>(md.comm, dir, "unilag", D);
    setTopology(md, *writer);
    return writer;
}

//! Writes dump number index of the owned cells at time t. Collective.
template <int D, class P> void dump(GprModel<D, P>& md, io::XdmfWriter& writer, int index, double t)
{
    using S = StateLayout<D, P>;
    ScopedTimer timer(md.timers, Phase::Output);
    const auto& dm = *md.mesh;
    const LO n = dm.nOwnedCells;
    auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto sh = md.fields["state"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.aux);
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
    std::vector<double> coords(3 * std::size_t(dm.nOwnedNodes), 0.0);
    for (LO r = 0; r < dm.nOwnedNodes; ++r)
        for (int d = 0; d < D; ++d)
            coords[3 * r + d] = xh(r, d);
    std::vector<double> rho(n), p(n), vel(3 * std::size_t(n), 0.0), eps(n), volume(n), part(n, md.rank), gid(n);
    for (LO i = 0; i < n; ++i)
    {
        rho[i] = 1.0 / sh(i, S::omega);
        p[i] = ah(i, Aux::pressure);
        for (int d = 0; d < D; ++d)
            vel[3 * i + d] = sh(i, S::vel + d);
        // E less the kinetic, elastic and thermal energies (computeEos): what the EOS sees
        eps[i] = ah(i, Aux::eps);
        volume[i] = vol(i);
        gid[i] = double(dm.cellGid[i]);
    }
    std::vector<io::CellField> fields{{"density", 1, rho.data()},   {"pressure", 1, p.data()},
                                      {"velocity", 3, vel.data()},  {"specific_internal_energy", 1, eps.data()},
                                      {"volume", 1, volume.data()}, {"rank", 1, part.data()},
                                      {"global_id", 1, gid.data()}};
    std::vector<double> mises, gdet, gdev, gten, theta, jvec;
    if constexpr (P::strain)
    {
        // von Mises stress (plastic maps), det G_e and the G_e anisotropy |dev G| / tr G
        auto sg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(),
                                                      md.fields["sigma"].getLocalViewDevice(Tpetra::Access::ReadOnly));
        mises.resize(n);
        gdet.resize(n);
        gdev.resize(n);
        for (LO i = 0; i < n; ++i)
        {
            mises[i] = gpr::vonMises(loadSym3(sg, i, 0));
            const gpr::Sym3 G = loadSym3(sh, i, S::G);
            gdet[i] = gpr::det(G);
            gdev[i] = std::sqrt(gpr::norm2(gpr::dev(G))) / gpr::trace(G);
        }
        gten.resize(6 * std::size_t(n));
        for (LO i = 0; i < n; ++i)
        {
            // XDMF Tensor6 order: xx, yy, zz, xy, yz, xz
            const gpr::Sym3 G = loadSym3(sh, i, S::G);
            const double c[6] = {G.xx, G.yy, G.zz, G.xy, G.yz, G.xz};
            for (int k = 0; k < 6; ++k)
                gten[6 * i + k] = c[k];
        }
        fields.push_back({"G", 6, gten.data()});
        fields.push_back({"von_mises_stress", 1, mises.data()});
        fields.push_back({"G_det", 1, gdet.data()});
        fields.push_back({"G_anisotropy", 1, gdev.data()});
    }
    if constexpr (P::heat)
    {
        theta.resize(n);
        jvec.assign(3 * std::size_t(n), 0.0);
        for (LO i = 0; i < n; ++i)
        {
            theta[i] = ah(i, Aux::theta);
            for (int d = 0; d < D; ++d)
                jvec[3 * i + d] = sh(i, S::J + d);
        }
        fields.push_back({"temperature", 1, theta.data()});
        fields.push_back({"thermal_impulse", 3, jvec.data()});
    }
    writer.writeStep(index, t, coords, fields);
}

} // namespace unilag
