// Heat-conduction kernels (kernels/unilag/Heat.hpp) on hand-built distorted simplex meshes, without MPI maps:
// zero rates for a uniform state, bitwise antisymmetric face fluxes and energy conservation, the discrete
// gradient of a linear temperature, adiabatic (q.n = 0 exactly), isothermal and non-conducting boundaries.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

#include "HostMesh.hpp"
#include "unilag/Heat.hpp"

namespace
{

using unilag::Field;
using unilag::LO;
using unilag::ThermalAdiabatic;
using unilag::ThermalIsothermal;
using PH = unilag::Physics<false, false, true>;
using unilag_test::connect;
using unilag_test::cubeMesh;
using unilag_test::HostMesh;
using unilag_test::squareMesh;
using unilag_test::wallGroup;

// ---- the kernel's data ----

template <int D> struct Heat
{
    using S = unilag::StateLayout<D, PH>;
    static constexpr int NV = D + 1;

    LO nCells, nNodes;
    unilag::MeshView<D> mesh;
    unilag::BoundaryView bc;
    unilag::View<int*> cellMaterial;
    unilag::View<unilag::Material*> materials;
    Field x, state, aux, rate;
    unilag::CellGeometry geom;
    std::vector<std::array<double, D>> centroid;
    unilag::Reconstruction<D> rec; //!< empty: first order; reconstruct(): order 2

    //! bcs: thermal type and wall temperature per boundary group.
    Heat(const HostMesh<D>& h, const std::vector<unilag::Material>& mats,
         const std::vector<std::pair<int, double>>& bcs)
        : nCells(h.nCells()), nNodes(h.nNodes()), cellMaterial("cellMaterial", nCells),
          materials("materials", mats.size()), x("x", nNodes, D), state("state", nCells, S::ncomp),
          aux("aux", nCells, unilag::Aux::ncomp<PH>()), rate("rate", nCells, 1 + D), geom(nCells, D), centroid(nCells)
    {
        mesh = unilag_test::deviceMesh<D>(h, x);
        for (LO i = 0; i < nCells; ++i)
        {
            centroid[i].fill(0.0);
            for (int k = 0; k < NV; ++k)
                for (int d = 0; d < D; ++d)
                    centroid[i][d] += h.x[D * h.cells[NV * i + k] + d] / NV;
        }

        unilag::View<int*> thermal("thermal", bcs.size());
        unilag::View<double*> temperature("temperature", bcs.size());
        auto th = Kokkos::create_mirror_view(thermal);
        auto tw = Kokkos::create_mirror_view(temperature);
        for (std::size_t g = 0; g < bcs.size(); ++g)
        {
            th(g) = bcs[g].first;
            tw(g) = bcs[g].second;
        }
        Kokkos::deep_copy(thermal, th);
        Kokkos::deep_copy(temperature, tw);
        bc.thermal = thermal;
        bc.temperature = temperature;

        auto mh = Kokkos::create_mirror_view(materials);
        for (std::size_t q = 0; q < mats.size(); ++q)
            mh(q) = mats[q];
        Kokkos::deep_copy(materials, mh);
        Kokkos::deep_copy(cellMaterial, 0);

        EXPECT_GT(unilag::computeGeometry<D>(mesh, x, geom, nCells), 0.0) << "the distorted mesh is tangled";
    }

    //! Set per cell (from its centroid): material, density, temperature, internal energy, J.
    void initialize(const std::function<void(LO, const double*, int&, double&, double&, double&, double*)>& init)
    {
        auto sh = Kokkos::create_mirror_view(state);
        auto ah = Kokkos::create_mirror_view(aux);
        auto mh = Kokkos::create_mirror_view(cellMaterial);
        for (LO i = 0; i < nCells; ++i)
        {
            double rho = 1.0, theta = 1.0, eps = 1.0, J[3] = {0.0, 0.0, 0.0};
            int mat = 0;
            init(i, centroid[i].data(), mat, rho, theta, eps, J);
            mh(i) = mat;
            sh(i, S::omega) = 1.0 / rho;
            for (int d = 0; d < D; ++d)
                sh(i, S::J + d) = J[d];
            ah(i, unilag::Aux::theta) = theta;
            ah(i, unilag::Aux::eps) = eps;
        }
        Kokkos::deep_copy(state, sh);
        Kokkos::deep_copy(aux, ah);
        Kokkos::deep_copy(cellMaterial, mh);
    }

    //! Order 2: the fluxes from theta, eps, J reconstructed at the faces (Barth-Jespersen, bounded at the faces).
    void reconstruct()
    {
        Field grad("heatGradients", nCells, unilag::heat::Quantities<D, PH>::ncomp);
        unilag::limitedGradientsOf<D>(mesh, unilag::heat::Quantities<D, PH>{state, aux, bc}, geom, x, grad, bc,
                                      unilag::Limiter::BarthJespersen);
        rec = unilag::Reconstruction<D>{grad, x, geom.centroid, geom.volume, false};
    }

    //! Run the kernel; the rates on the host.
    Kokkos::View<double**, Kokkos::LayoutLeft, Kokkos::HostSpace> rates()
    {
        Kokkos::deep_copy(rate, -12345.0);
        unilag::heatFluxes<D, PH>(mesh, bc, state, aux, geom, cellMaterial, materials, rate, rec);
        return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), rate);
    }

    //! Face fluxes (fE, fJ) of every face of every cell as the kernel computes them, cell x (NV * (1 + D)).
    Kokkos::View<double**, Kokkos::LayoutLeft, Kokkos::HostSpace> faceFluxes()
    {
        Field f("faceFluxes", nCells, NV * (1 + D));
        const unilag::heat::Faces<D, PH> faces{mesh, bc, state, aux, geom.corner, cellMaterial, materials, rec};
        Kokkos::parallel_for(
            "test::heat::faces", unilag::range(nCells), KOKKOS_LAMBDA(const LO i) {
                const auto a = faces.side(i);
                for (int k = 0; k < NV; ++k)
                {
                    double fE;
                    unilag::Vec<D> fJ;
                    faces.face(i, a, k, fE, fJ);
                    f(i, k * (1 + D)) = fE;
                    for (int d = 0; d < D; ++d)
                        f(i, k * (1 + D) + 1 + d) = fJ[d];
                }
            });
        return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f);
    }

    //! Sum over faces of |A_f| (the scale of the rates' round-off).
    double areaScale(LO i) const
    {
        auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.corner);
        double s = 0.0;
        for (int k = 0; k < NV; ++k)
        {
            double a2 = 0.0;
            for (int d = 0; d < D; ++d)
                a2 += c(i, k * D + d) * c(i, k * D + d);
            s += D * std::sqrt(a2);
        }
        return s;
    }
};

unilag::Material gas(double alpha, double cv, int heat = 1)
{
    unilag::Material m = unilag::fluidMaterial(unilag::gpr::idealGasEos(1.4, cv));
    m.heat = heat;
    m.alpha = alpha;
    m.tau2 = 1e-3;
    return m;
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// ---- (1) uniform temperature and internal energy, J = 0: zero rates ----

template <int D> void checkUniform(HostMesh<D> h)
{
    // groups: even walls adiabatic, odd walls isothermal at the cells' temperature
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, wallGroup));
    const double theta = 2.5, cv = 0.7;
    std::vector<std::pair<int, double>> bcs;
    for (int g = 0; g < 2 * D; ++g)
        bcs.emplace_back(g % 2 ? ThermalIsothermal : ThermalAdiabatic, theta);
    Heat<D> heat(h, {gas(3.0, cv)}, bcs);
    heat.initialize(
        [&](LO, const double*, int&, double& rho, double& th, double& eps, double*)
        {
            rho = 1.3;
            th = theta;
            eps = cv * theta;
        });
    const auto r = heat.rates();
    for (LO i = 0; i < heat.nCells; ++i)
    {
        EXPECT_EQ(r(i, 0), 0.0) << "cell " << i;
        for (int d = 0; d < D; ++d)
            EXPECT_LE(std::abs(r(i, 1 + d)), 1e-14 * theta * heat.areaScale(i)) << "cell " << i << " d " << d;
    }
}

TEST(HeatKernels, UniformStateGivesZeroRates2D)
{
    checkUniform<2>(squareMesh(8, 0.3, 11));
}

TEST(HeatKernels, UniformStateGivesZeroRates3D)
{
    checkUniform<3>(cubeMesh(4, 0.3, 12));
}

// ---- (2) random states: bitwise antisymmetric face fluxes, conserved total energy ----

template <int D> void checkConservation(HostMesh<D> h, unsigned seed, bool order2 = false)
{
    constexpr int NV = D + 1;
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, wallGroup));
    // two conducting gases and one non-conducting material; every wall adiabatic
    Heat<D> heat(h, {gas(2.0, 0.7), gas(5.0, 2.0), gas(4.0, 1.0, 0)},
                 std::vector<std::pair<int, double>>(2 * D, {ThermalAdiabatic, 0.0}));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    heat.initialize(
        [&](LO, const double*, int& mat, double& rho, double& th, double& eps, double* J)
        {
            const double m = u(rng);
            mat = m < 0.45 ? 0 : (m < 0.9 ? 1 : 2);
            rho = 0.5 + u(rng);
            th = 0.5 + 2.0 * u(rng);
            eps = (mat == 1 ? 2.0 : 0.7) * th * (0.8 + 0.4 * u(rng));
            for (int d = 0; d < D; ++d)
                J[d] = u(rng) - 0.5;
        });
    if (order2)
        heat.reconstruct(); // each side's face values: both evaluations of a face must still agree bitwise

    // face by face: the flux out of i through face k is exactly minus the flux out of j through its face m
    const auto f = heat.faceFluxes();
    auto mat = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), heat.cellMaterial);
    auto corner = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), heat.geom.corner);
    int pairs = 0, naiveMismatch = 0;
    for (LO i = 0; i < heat.nCells; ++i)
        for (int k = 0; k < NV; ++k)
        {
            const LO j = h.neighbour[NV * i + k];
            if (j < 0 || mat(i) == 2 || mat(j) == 2)
                continue;
            const int m = int(std::find(&h.neighbour[NV * j], &h.neighbour[NV * j] + NV, i) - &h.neighbour[NV * j]);
            ASSERT_LT(m, NV);
            ++pairs;
            // +0 and -0 alike: at order 2 both sides' face values can coincide (clipped to one bound), and a J flux
            // theta S_d - diss * 0 with S_d = 0 is +0 from both cells (4 faces of the 3D mesh); sums are unaffected
            for (int c = 0; c < 1 + D; ++c)
                EXPECT_TRUE(sameBits(f(i, k * (1 + D) + c), -f(j, m * (1 + D) + c)) ||
                            (f(i, k * (1 + D) + c) == 0.0 && f(j, m * (1 + D) + c) == 0.0))
                    << "cells " << i << ", " << j << " component " << c << ": " << f(i, k * (1 + D) + c) << " vs "
                    << f(j, m * (1 + D) + c);
            for (int d = 0; d < D; ++d)
                naiveMismatch += !sameBits(corner(i, k * D + d), -corner(j, m * D + d));
        }
    EXPECT_GT(pairs, 0);
    if (D == 2)
        EXPECT_EQ(naiveMismatch, 0) << "triangles: the two cells' face vectors are exact negatives";
    else
        std::printf("[ info ] 3D: %d of %d face-vector components differ between the two sides' corner vectors "
                    "(hence the antisymmetrised area vector)\n",
                    naiveMismatch, pairs * D);

    // cells: non-conducting cells get zero rates; the energy rates sum to zero up to round-off
    const auto r = heat.rates();
    double sum = 0.0, scale = 0.0;
    int nonzero = 0;
    for (LO i = 0; i < heat.nCells; ++i)
    {
        if (mat(i) == 2)
        {
            for (int c = 0; c < 1 + D; ++c)
                EXPECT_EQ(r(i, c), 0.0);
            continue;
        }
        sum += r(i, 0);
        scale += std::abs(r(i, 0));
        nonzero += r(i, 0) != 0.0;
    }
    EXPECT_GT(nonzero, heat.nCells / 2);
    EXPECT_LE(std::abs(sum), 1e-14 * scale) << "sum " << sum << " scale " << scale;
}

TEST(HeatKernels, AntisymmetricFluxesConserveEnergy2D)
{
    checkConservation<2>(squareMesh(10, 0.3, 21), 5);
}

TEST(HeatKernels, AntisymmetricFluxesConserveEnergy3D)
{
    checkConservation<3>(cubeMesh(5, 0.3, 22), 6);
}

TEST(HeatKernels, AntisymmetricFluxesConserveEnergyOrder2_2D)
{
    checkConservation<2>(squareMesh(10, 0.3, 21), 5, true);
}

TEST(HeatKernels, AntisymmetricFluxesConserveEnergyOrder2_3D)
{
    checkConservation<3>(cubeMesh(5, 0.3, 22), 6, true);
}

// ---- (3) linear temperature, J = 0: the J rate is -|T| grad theta ----

TEST(HeatKernels, LinearTemperatureGradient2D)
{
    // Uniform diagonals under an affine map: the two triangles at every interior face form a parallelogram, so
    // the mean of the centroid values of a linear field is its value at the face midpoint and the central
    // flux sum_f theta_f S_f equals |T| grad theta exactly (up to round-off) for cells with interior faces only.
    HostMesh<2> h = squareMesh(8, 0.0, 0, true);
    const double A[2][2] = {{1.3, 0.4}, {-0.2, 0.9}}, shift[2] = {0.1, -0.3};
    for (LO r = 0; r < h.nNodes(); ++r)
    {
        const double x = h.x[2 * r], y = h.x[2 * r + 1];
        h.x[2 * r] = A[0][0] * x + A[0][1] * y + shift[0];
        h.x[2 * r + 1] = A[1][0] * x + A[1][1] * y + shift[1];
    }
    ASSERT_NO_FATAL_FAILURE(connect<2>(h, wallGroup));
    const double cv = 1.5, a = 3.0, b[2] = {0.7, -0.4};
    Heat<2> heat(h, {gas(2.0, cv)}, std::vector<std::pair<int, double>>(4, {ThermalAdiabatic, 0.0}));
    heat.initialize(
        [&](LO, const double* c, int&, double& rho, double& th, double& eps, double*)
        {
            rho = 1.0;
            th = a + b[0] * c[0] + b[1] * c[1];
            eps = cv * th;
        });
    const auto r = heat.rates();
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), heat.geom.volume);
    int interior = 0;
    for (LO i = 0; i < heat.nCells; ++i)
    {
        if (std::any_of(&h.faceGroup[3 * i], &h.faceGroup[3 * i] + 3, [](int g) { return g >= 0; }))
            continue;
        ++interior;
        for (int d = 0; d < 2; ++d)
            EXPECT_NEAR(r(i, 1 + d), -vol(i) * b[d], 1e-13 * a * heat.areaScale(i)) << "cell " << i << " d " << d;
    }
    EXPECT_GT(interior, 50);
}

// ---- (4) boundaries: adiabatic (q.n = 0 exactly), isothermal, non-conducting neighbour ----

template <int D> HostMesh<D> singleCell()
{
    HostMesh<D> h;
    if constexpr (D == 2)
        h.x = {0.1, 0.0, 1.0, 0.2, 0.3, 0.9};
    else
        h.x = {0.1, 0.0, 0.0, 1.0, 0.2, 0.1, 0.3, 0.9, 0.0, 0.2, 0.1, 1.1};
    for (int k = 0; k < D + 1; ++k)
    {
        h.cells.push_back(k);
        h.wall.push_back(0);
    }
    h.faceGroup.assign(D + 1, 0);
    h.neighbour.assign(D + 1, -1);
    return h;
}

template <int D> void checkBoundaries()
{
    constexpr int NV = D + 1;
    const double cv = 0.8, theta = 1.7;
    auto init = [&](LO, const double*, int&, double& rho, double& th, double& eps, double* J)
    {
        rho = 2.0;
        th = theta;
        eps = cv * theta + 0.3;
        for (int d = 0; d < D; ++d)
            J[d] = 0.3 - 0.2 * d;
    };
    {
        // adiabatic: q.n = 0 exactly on every face, whatever J
        Heat<D> heat(singleCell<D>(), {gas(2.0, cv)}, {{ThermalAdiabatic, 0.0}});
        heat.initialize(init);
        const auto f = heat.faceFluxes();
        for (int k = 0; k < NV; ++k)
            EXPECT_EQ(f(0, k * (1 + D)), 0.0);
        EXPECT_EQ(heat.rates()(0, 0), 0.0);
    }
    {
        // isothermal, hotter wall and J = 0: the cell heats up (through the dissipation term alone)
        Heat<D> heat(singleCell<D>(), {gas(2.0, cv)}, {{ThermalIsothermal, theta + 1.0}});
        heat.initialize(
            [&](LO i, const double* c, int& m, double& rho, double& th, double& eps, double* J)
            {
                init(i, c, m, rho, th, eps, J);
                for (int d = 0; d < D; ++d)
                    J[d] = 0.0;
            });
        EXPECT_GT(heat.rates()(0, 0), 0.0);
    }
    {
        // isothermal at the cell temperature, same eps: q.n = 1/2 alpha^2 (2 theta) J.n per face, and the
        // energy rate is -alpha^2 theta J . sum_f S_f = 0 up to round-off
        Heat<D> heat(singleCell<D>(), {gas(2.0, cv)}, {{ThermalIsothermal, theta}});
        heat.initialize(init);
        EXPECT_LE(std::abs(heat.rates()(0, 0)), 1e-14 * 4.0 * theta * heat.areaScale(0));
    }
}

TEST(HeatKernels, Boundaries2D)
{
    checkBoundaries<2>();
}

TEST(HeatKernels, Boundaries3D)
{
    checkBoundaries<3>();
}

TEST(HeatKernels, NonConductingNeighbourIsAdiabatic2D)
{
    // left half conducts, right half does not: no energy crosses the interface, and the conducting half
    // conserves its energy to round-off
    HostMesh<2> h = squareMesh(6, 0.2, 31);
    ASSERT_NO_FATAL_FAILURE(connect<2>(h, wallGroup));
    Heat<2> heat(h, {gas(2.0, 1.0), gas(2.0, 1.0, 0)}, std::vector<std::pair<int, double>>(4, {ThermalAdiabatic, 0.0}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    heat.initialize(
        [&](LO, const double* c, int& mat, double& rho, double& th, double& eps, double* J)
        {
            mat = c[0] < 0.5 ? 0 : 1;
            rho = 1.0 + u(rng);
            th = 1.0 + u(rng);
            eps = th;
            J[0] = u(rng) - 0.5;
            J[1] = u(rng) - 0.5;
        });
    const auto f = heat.faceFluxes();
    auto mat = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), heat.cellMaterial);
    const auto r = heat.rates();
    double sum = 0.0, scale = 0.0;
    int interface = 0;
    for (LO i = 0; i < heat.nCells; ++i)
    {
        if (mat(i) == 1)
        {
            EXPECT_EQ(r(i, 0), 0.0);
            continue;
        }
        sum += r(i, 0);
        scale += std::abs(r(i, 0));
        for (int k = 0; k < 3; ++k)
        {
            const LO j = h.neighbour[3 * i + k];
            if (j >= 0 && mat(j) == 1)
            {
                ++interface;
                EXPECT_EQ(f(i, k * 3), 0.0);
            }
        }
    }
    EXPECT_GT(interface, 0);
    EXPECT_LE(std::abs(sum), 1e-14 * scale);
}

} // namespace
