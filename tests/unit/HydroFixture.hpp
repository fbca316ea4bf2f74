/*! \file HydroFixture.hpp
 *  \brief The kernels' data of a hydrodynamic state on a HostMesh, for the reconstruction and limiter unit tests. */
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "HostMesh.hpp"
#include "unilag/CellUpdate.hpp"

namespace unilag_test
{

using unilag::Field;
using unilag::LO;
using unilag::MemSpace;

//! The kernels' data of a state on a HostMesh: what the reconstruction reads (state, EOS, geometry, boundary table).
template <int D> struct Hydro
{
    using S = unilag::HydroState<D>;
    static constexpr int NV = D + 1;

    LO nCells, nNodes;
    unilag::MeshView<D> mesh;
    unilag::BoundaryView bc;
    unilag::View<int*> cellMaterial;
    unilag::View<unilag::Material*> materials;
    Field x, state, aux;
    Field grad; //!< limited gradients (second order)
    unilag::CellGeometry geom;

    //! bcs: type and imposed velocity per boundary group.
    Hydro(const HostMesh<D>& h, double gamma, const std::vector<std::pair<int, std::array<double, 3>>>& bcs)
        : nCells(h.nCells()), nNodes(h.nNodes()), cellMaterial("cellMaterial", nCells), materials("materials", 1),
          x("x", nNodes, D), state("state", nCells, S::ncomp),
          aux("aux", nCells, unilag::Aux::ncomp<unilag::PhysicsHydro>()),
          grad("grad", nCells, unilag::ReconLayout<D, unilag::PhysicsHydro>::ncomp), geom(nCells, D)
    {
        mesh = unilag_test::deviceMesh<D>(h, x);

        unilag::View<int*> type("bcType", bcs.size());
        Kokkos::View<double* [3], MemSpace> value("bcValue", bcs.size());
        auto th = Kokkos::create_mirror_view(type);
        auto vh = Kokkos::create_mirror_view(value);
        for (std::size_t g = 0; g < bcs.size(); ++g)
        {
            th(g) = bcs[g].first;
            for (int d = 0; d < 3; ++d)
                vh(g, d) = bcs[g].second[d];
        }
        Kokkos::deep_copy(type, th);
        Kokkos::deep_copy(value, vh);
        bc.type = type;
        bc.value = value;

        auto mh = Kokkos::create_mirror_view(materials);
        mh(0) = unilag::fluidMaterial(unilag::gpr::idealGasEos(gamma, 1.0));
        Kokkos::deep_copy(materials, mh);
        Kokkos::deep_copy(cellMaterial, 0);
    }

    //! Initial state from density, pressure and velocity at the cell centroids, its geometry and EOS.
    void initialize(const std::function<void(const double*, double&, double&, double*)>& init, double gamma)
    {
        ASSERT_GT(unilag::computeGeometry<D>(mesh, x, geom, nCells), 0.0) << "the distorted mesh is tangled";
        auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
        auto cn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.cellNodes);
        auto sh = Kokkos::create_mirror_view(state);
        for (LO i = 0; i < nCells; ++i)
        {
            double c[3] = {0, 0, 0}, v[3] = {0, 0, 0}, rho, p;
            for (int k = 0; k < NV; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += xh(cn(i, k), d) / NV;
            init(c, rho, p, v);
            double kin = 0.0;
            for (int d = 0; d < D; ++d)
            {
                sh(i, S::vel + d) = v[d];
                kin += 0.5 * v[d] * v[d];
            }
            sh(i, S::omega) = 1.0 / rho;
            sh(i, S::energy) = p / ((gamma - 1.0) * rho) + kin;
        }
        Kokkos::deep_copy(state, sh);
        unilag::computeEos<D>(state, cellMaterial, materials, aux, nCells);
    }
};

} // namespace unilag_test
