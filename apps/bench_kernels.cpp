/*! \file bench_kernels.cpp
 *  \brief Google Benchmark microbenchmarks of the hot kernels of one Lagrangian step.
 *
 *  Build with `cmake --preset release -DUNILAG_ENABLE_BENCHMARKS=ON && cmake --build build/release --target
 *  unilag_bench`, then run e.g. `OMP_NUM_THREADS=2 OMP_PROC_BIND=spread ./build/release/apps/unilag_bench
 *  --benchmark_min_time=0.2` (any Google Benchmark option works: `--benchmark_filter=step/2D` selects, and
 *  only the meshes of the selected benchmarks are generated, once each). Meshes come from
 *  inputs/geometry/quadrant2d.geo (triangles, 4k to 250k cells) and octant3d.geo (tetrahedra, 8k and 64k);
 *  set UNILAG_INPUTS to the inputs folder if the source tree has moved. The state is a smooth non-trivial field
 *  with every boundary a slip wall, on one MPI rank. Benchmarks: `geometry/<D>D/<size>` is computeGeometry,
 *  `nodal_solve/...` nodalSolve (its gather over the node->corner CSR included), `reconstruction/...` the limited
 *  gradients of the second-order reconstruction (velocity, pressure), `cell_update/...` moveNodes +
 *  updateCells with a CFL time step, `step/...` a whole step (geometry, EOS, nodal solve, move, update; the step
 *  is recomputed from the same state each iteration, so every iteration does identical work). Times are
 *  manual times between two Kokkos::fence() calls. Counters: `cells/s` (and `nodes/s` for the nodal solver) is
 *  owned cells (nodes) processed per second of kernel time, i.e. the cell-steps/s a run would reach if that
 *  kernel were the whole step; `bytes_per_second` (geometry only) is a lower bound of the memory traffic (each
 *  array read or written once); `cells` and `nodes` are the mesh size; the step benchmark also reports the share
 *  of its time spent in `geometry`, `eos`, `nodal`, `update` (fractions summing to about 1).
 *  `variant_step/<variant>/...` is a whole step of each physics variant (hydro, elastic, plastic, heat,
 *  plastic_heat) with one Picard iteration, so the cost of each variant per cell-step sits next to the hydro one;
 *  its counter `picard_iteration` is the share of one Picard iteration (nodal solve + G_e update) in the step.
 */
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <utility>

#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <Tpetra_Core.hpp>

#include "bench_material.hpp"
#include "config/Scene.hpp"
#include "mesh/DistributedMesh.hpp"
#include "mesh/GlobalMesh.hpp"
#include "unilag/Heat.hpp"
#include "unilag/CellUpdate.hpp"

namespace
{

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace unilag;

fs::path inputsDir()
{
    if (const char* env = std::getenv("UNILAG_INPUTS"); env && *env)
        return fs::path(env);
    return fs::path(__FILE__).parent_path().parent_path() / "inputs";
}

//! One mesh with a representative state: everything a step needs, as plain Kokkos Views on one rank.
template <int D>
struct Fixture
{
    using S = HydroState<D>;

    std::shared_ptr<DistributedMesh> dm;
    MeshView<D> m;
    Field state, stateNew, x, xNew, vnode, fnode, aux;
    CellGeometry geom;
    View<double*> mass;
    View<int*> cellMaterial;
    View<Material*> materials;
    BoundaryView bc;
    double dt = 0.0;

    Fixture(const fs::path& geo, double h)
    {
        Scene scene;
        scene.file = geo.string();
        scene.directory = geo.parent_path().string();
        scene.name = "bench";
        scene.geometry = geo.string();
        scene.meshSize = h;
        {
            GlobalMesh global = loadMesh(scene);
            if (global.dim != D)
                throw std::runtime_error(geo.string() + ": expected a " + std::to_string(D) + "D mesh");
            dm = DistributedMesh::distribute(global, Tpetra::getDefaultComm());
        }
        m = dm->view<D>();
        const LO nc = dm->nCells, nn = dm->nNodes;
        state = Field("bench::state", nc, S::ncomp);
        stateNew = Field("bench::stateNew", nc, S::ncomp);
        x = Field("bench::x", nn, D);
        xNew = Field("bench::xNew", nn, D);
        vnode = Field("bench::vnode", nn, D);
        fnode = Field("bench::fnode", dm->nOwnedNodes, D);
        aux = Field("bench::aux", nc, Aux::ncomp<PhysicsHydro>());
        geom = CellGeometry(nc, D);
        mass = View<double*>("bench::mass", nc);
        cellMaterial = View<int*>("bench::cellMaterial", nc); // zero: one material
        materials = View<Material*>("bench::materials", 1);
        Kokkos::deep_copy(materials, fluidMaterial(gpr::idealGasEos(1.4, 1.0)));

        // Every boundary group is a slip wall.
        const int ng = std::max(int(dm->boundaryNames.size()), 1);
        View<int*> type("bench::bcType", ng);
        Kokkos::View<double* [3], MemSpace> value("bench::bcValue", ng);
        Kokkos::deep_copy(type, int(BcSlipWall));
        bc.type = type;
        bc.value = value;
        bc.thermal = View<int*>("bench::bcThermal", ng); // adiabatic
        bc.temperature = View<double*>("bench::bcTemperature", ng);

        // Coordinates, geometry, then a smooth state at the cell centroids:
        // rho = 1 + 0.1 x, p = 1 + 0.5 sin(3x) cos(2y), v = 0.05 (sin(2y), -sin(2x)[, 0.5 sin(2x + y)]).
        {
            auto xh = Kokkos::create_mirror_view(x);
            for (LO n = 0; n < nn; ++n)
                for (int d = 0; d < D; ++d)
                    xh(n, d) = dm->coords0[3 * n + d];
            Kokkos::deep_copy(x, xh);
        }
        if (!(computeGeometry<D>(m, x, geom, nc) > 0.0))
            throw std::runtime_error("a cell of the mesh has non-positive volume");
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.volume);
        auto sh = Kokkos::create_mirror_view(state);
        auto massH = Kokkos::create_mirror_view(mass);
        const double gamma = 1.4;
        for (LO i = 0; i < nc; ++i)
        {
            double c[3] = {0, 0, 0};
            for (int k = 0; k < D + 1; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += dm->coords0[3 * dm->cellNodesHost[(D + 1) * i + k] + d] / (D + 1);
            const double rho = 1.0 + 0.1 * c[0];
            const double p = 1.0 + 0.5 * std::sin(3.0 * c[0]) * std::cos(2.0 * c[1]);
            double v[3] = {0.05 * std::sin(2.0 * c[1]), -0.05 * std::sin(2.0 * c[0]), 0.025 * std::sin(2.0 * c[0] + c[1])};
            double kin = 0.0;
            for (int d = 0; d < D; ++d)
            {
                sh(i, S::vel + d) = v[d];
                kin += 0.5 * v[d] * v[d];
            }
            sh(i, S::omega) = 1.0 / rho;
            sh(i, S::energy) = p / ((gamma - 1.0) * rho) + kin;
            massH(i) = rho * vol(i);
        }
        Kokkos::deep_copy(state, sh);
        Kokkos::deep_copy(mass, massH);

        // One real step to fix a CFL time step and check that the update is valid.
        computeEos<D>(state, cellMaterial, materials, aux, nc);
        nodalSolve<D>(m, bc, state, aux, geom, vnode, fnode);
        dt = stableTimeStep<D>(m, aux, geom, vnode, 0.5, 0.1);
        moveNodes(x, vnode, dt, xNew, nn, D);
        const UpdateCheck check = updateCells<D>(m, state, aux, geom, mass, cellMaterial, materials, x, xNew, vnode, dt, stateNew);
        if (!(dt > 0.0) || !(check.minVolumeRatio > 0.0) || !(check.minSound2 > 0.0))
            throw std::runtime_error("the benchmark state does not give a valid step (dt " + std::to_string(dt) + ")");
    }
};

struct MeshSpec
{
    const char* label; //!< nominal cell count, used in benchmark names
    double h;
};
const MeshSpec sizes2d[] = {{"4k", 0.0288}, {"16k", 0.0144}, {"64k", 0.0072}, {"250k", 0.00365}};
const MeshSpec sizes3d[] = {{"8k", 0.1}, {"64k", 0.05}}; // 8.3k and 64.4k tetrahedra

//! Meshes built on first use, by dimension and size; destroyed in main before Kokkos is finalized.
struct Cache
{
    std::map<double, std::unique_ptr<Fixture<2>>> f2;
    std::map<double, std::unique_ptr<Fixture<3>>> f3;
    std::map<std::string, std::shared_ptr<void>> variants; //!< VariantFixture<D, P> by type and mesh size
};
Cache* cache = nullptr;

template <int D>
Fixture<D>* fixture(benchmark::State& state, double h)
{
    auto& map = [&]() -> auto& {
        if constexpr (D == 2)
            return cache->f2;
        else
            return cache->f3;
    }();
    auto it = map.find(h);
    if (it == map.end())
    {
        const fs::path geo = inputsDir() / "geometry" / (D == 2 ? "quadrant2d.geo" : "octant3d.geo");
        try
        {
            it = map.emplace(h, std::make_unique<Fixture<D>>(geo, h)).first;
        }
        catch (const std::exception& e)
        {
            state.SkipWithError(e.what());
            return nullptr;
        }
    }
    return it->second.get();
}

template <class F>
void timed(benchmark::State& state, F&& body)
{
    for (auto _ : state)
    {
        Kokkos::fence();
        const auto t0 = Clock::now();
        body();
        Kokkos::fence();
        state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
    }
}

void setCounters(benchmark::State& state, const DistributedMesh& dm, bool nodes)
{
    state.counters["cells/s"] = benchmark::Counter(dm.nOwnedCells, benchmark::Counter::kIsIterationInvariantRate);
    if (nodes)
        state.counters["nodes/s"] = benchmark::Counter(dm.nOwnedNodes, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["cells"] = double(dm.nOwnedCells);
    state.counters["nodes"] = double(dm.nOwnedNodes);
}

template <int D>
void benchGeometry(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    timed(state, [&] { benchmark::DoNotOptimize(computeGeometry<D>(f->m, f->x, f->geom, f->m.nCells)); });
    setCounters(state, *f->dm, false);
    // Compulsory traffic: connectivity and results per cell, coordinates once per node.
    const double bytes = double(f->m.nCells) * ((D + 1) * sizeof(LO) + (2 + (D + 1) * D) * sizeof(double)) +
                         double(f->m.nNodes) * D * sizeof(double);
    state.SetBytesProcessed(int64_t(bytes * double(state.iterations())));
}

template <int D>
void benchNodal(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    timed(state, [&] { nodalSolve<D>(f->m, f->bc, f->state, f->aux, f->geom, f->vnode, f->fnode); });
    setCounters(state, *f->dm, true);
}

//! Limited gradients of the second-order reconstruction (velocity, pressure), owned cells.
template <int D>
void benchReconstruction(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    Field grad("bench::grad", f->m.nCells, ReconLayout<D, PhysicsHydro>::ncomp);
    GradientScratch sums; // kept between calls, as the solver keeps it
    timed(state, [&] {
        limitedGradients<D, PhysicsHydro>(f->m, f->state, f->aux, ConstField(), f->geom, f->x, grad, BoundaryView(),
                                          Limiter::BarthJespersen, Reconstructed::All, std::nullopt, &sums);
    });
    setCounters(state, *f->dm, false);
}

template <int D>
void benchUpdate(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    timed(state, [&] {
        moveNodes(f->x, f->vnode, f->dt, f->xNew, f->m.nNodes, D);
        benchmark::DoNotOptimize(
            updateCells<D>(f->m, f->state, f->aux, f->geom, f->mass, f->cellMaterial, f->materials, f->x, f->xNew, f->vnode, f->dt, f->stateNew));
    });
    setCounters(state, *f->dm, false);
}

template <int D>
void benchStep(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    double phase[4] = {0, 0, 0, 0}; // geometry, eos, nodal, update
    auto lap = [](Clock::time_point& t, double& acc) {
        Kokkos::fence();
        const auto now = Clock::now();
        acc += std::chrono::duration<double>(now - t).count();
        t = now;
    };
    for (auto _ : state)
    {
        Kokkos::fence();
        const auto t0 = Clock::now();
        auto t = t0;
        benchmark::DoNotOptimize(computeGeometry<D>(f->m, f->x, f->geom, f->m.nCells));
        lap(t, phase[0]);
        computeEos<D>(f->state, f->cellMaterial, f->materials, f->aux, f->m.nCells);
        lap(t, phase[1]);
        nodalSolve<D>(f->m, f->bc, f->state, f->aux, f->geom, f->vnode, f->fnode);
        lap(t, phase[2]);
        moveNodes(f->x, f->vnode, f->dt, f->xNew, f->m.nNodes, D);
        benchmark::DoNotOptimize(
            updateCells<D>(f->m, f->state, f->aux, f->geom, f->mass, f->cellMaterial, f->materials, f->x, f->xNew, f->vnode, f->dt, f->stateNew));
        lap(t, phase[3]);
        state.SetIterationTime(std::chrono::duration<double>(t - t0).count());
    }
    setCounters(state, *f->dm, false);
    const double total = phase[0] + phase[1] + phase[2] + phase[3];
    if (total > 0.0)
    {
        state.counters["geometry"] = phase[0] / total;
        state.counters["eos"] = phase[1] / total;
        state.counters["nodal"] = phase[2] / total;
        state.counters["update"] = phase[3] / total;
    }
}

/*! The state of a physics variant on a base fixture's mesh: the same flow, plus bench::setVariantState's G_e and J,
 *  and bench::variantMaterial (bench_material.hpp). */
template <int D, class P>
struct VariantFixture
{
    using S = StateLayout<D, P>;
    Fixture<D>* base;
    Field state, stateNew, aux, sigma, sigmaNew, heatRate;
    View<Material*> materials;
    View<double*> plasticHint; //!< cold (NaN) in every iteration: the cost of a first Picard iterate

    VariantFixture(Fixture<D>* f) : base(f)
    {
        const LO nc = f->m.nCells;
        state = Field("bench::vstate", nc, S::ncomp);
        stateNew = Field("bench::vstateNew", nc, S::ncomp);
        aux = Field("bench::vaux", nc, Aux::ncomp<P>());
        sigma = Field("bench::sigma", nc, 6);
        sigmaNew = Field("bench::sigmaNew", nc, 6);
        heatRate = Field("bench::heatRate", nc, 1 + D);
        plasticHint = View<double*>("bench::plasticHint", nc);
        const Material mat = bench::variantMaterial<P>();
        materials = View<Material*>("bench::vmaterials", 1);
        Kokkos::deep_copy(materials, mat);
        auto sh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f->state);
        auto vh = Kokkos::create_mirror_view(state);
        auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f->x);
        for (LO i = 0; i < nc; ++i)
        {
            double c[3] = {0, 0, 0};
            for (int k = 0; k < D + 1; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += xh(f->dm->cellNodesHost[(D + 1) * i + k], d) / (D + 1);
            for (int col = 0; col < 2 + D; ++col)
                vh(i, col) = sh(i, col);
            bench::setVariantState<D, P>([&](int col) -> double& { return vh(i, col); }, 1.0 / sh(i, 0), c);
        }
        Kokkos::deep_copy(state, vh);
        computeEos<D, P>(state, f->cellMaterial, materials, aux, nc, sigma);
    }
};

/*! A whole step of a physics variant with one Picard iteration: geometry, EOS (+ stress), [heat fluxes], nodal
 *  solve, move, [G_e update], cell update. Counter `picard_iteration` is the share of one more Picard iteration
 *  (nodal solve + G_e update) in that time: a step with k iterations costs about (1 + (k - 1) share) of it. */
template <int D, class P>
void benchVariant(benchmark::State& state, double h)
{
    Fixture<D>* f = fixture<D>(state, h);
    if (!f)
        return;
    auto& slot = cache->variants[std::string(typeid(P).name()) + std::to_string(D) + "/" + std::to_string(h)];
    if (!slot)
        slot = std::make_shared<VariantFixture<D, P>>(f);
    auto* v = static_cast<VariantFixture<D, P>*>(slot.get());
    double iter = 0.0, total = 0.0;
    for (auto _ : state)
    {
        if constexpr (P::plastic)
            Kokkos::deep_copy(v->plasticHint, std::numeric_limits<double>::quiet_NaN());
        Kokkos::fence();
        const auto t0 = Clock::now();
        computeGeometry<D>(f->m, f->x, f->geom, f->m.nCells);
        computeEos<D, P>(v->state, f->cellMaterial, v->materials, v->aux, f->m.nCells, v->sigma);
        if constexpr (P::heat)
            heatFluxes<D, P>(f->m, f->bc, v->state, v->aux, f->geom, f->cellMaterial, v->materials, v->heatRate);
        Kokkos::fence();
        const auto t1 = Clock::now();
        nodalSolve<D, P>(f->m, f->bc, v->state, v->aux, f->geom, f->vnode, f->fnode, v->sigma);
        moveNodes(f->x, f->vnode, f->dt, f->xNew, f->m.nNodes, D);
        if constexpr (P::strain)
            benchmark::DoNotOptimize(strainUpdate<D, P>(f->m, v->state, v->aux, f->geom, f->mass, f->cellMaterial,
                                                        v->materials, f->xNew, f->vnode, f->dt, v->sigma, v->sigmaNew,
                                                        v->stateNew, v->plasticHint));
        Kokkos::fence();
        const auto t2 = Clock::now();
        benchmark::DoNotOptimize(updateCells<D, P>(f->m, v->state, v->aux, f->geom, f->mass, f->cellMaterial,
                                                   v->materials, f->x, f->xNew, f->vnode, f->dt, v->stateNew, v->sigma,
                                                   v->heatRate));
        Kokkos::fence();
        const auto t3 = Clock::now();
        iter += std::chrono::duration<double>(t2 - t1).count();
        total += std::chrono::duration<double>(t3 - t0).count();
        state.SetIterationTime(std::chrono::duration<double>(t3 - t0).count());
    }
    setCounters(state, *f->dm, false);
    if (total > 0.0)
        state.counters["picard_iteration"] = iter / total;
}

template <int D, std::size_t N>
void registerVariants(const MeshSpec (&specs)[N])
{
    using Fn = void (*)(benchmark::State&, double);
    const std::pair<const char*, Fn> variants[] = {{"hydro", benchVariant<D, PhysicsHydro>},
                                                   {"elastic", benchVariant<D, Physics<true, false, false>>},
                                                   {"plastic", benchVariant<D, Physics<true, true, false>>},
                                                   {"heat", benchVariant<D, Physics<false, false, true>>},
                                                   {"plastic_heat", benchVariant<D, Physics<true, true, true>>}};
    for (const auto& [variant, fn] : variants)
        for (const MeshSpec& s : specs)
        {
            const std::string name = std::string("variant_step/") + variant + "/" + std::to_string(D) + "D/" + s.label;
            const double h = s.h;
            benchmark::RegisterBenchmark(name.c_str(), [fn, h](benchmark::State& st) { fn(st, h); })
                ->UseManualTime()
                ->Unit(benchmark::kMicrosecond);
        }
}

template <int D, std::size_t N>
void registerAll(const MeshSpec (&specs)[N])
{
    using Fn = void (*)(benchmark::State&, double);
    const std::pair<const char*, Fn> kernels[] = {
        {"geometry", benchGeometry<D>}, {"nodal_solve", benchNodal<D>}, {"reconstruction", benchReconstruction<D>},
        {"cell_update", benchUpdate<D>}, {"step", benchStep<D>}};
    for (const auto& [kernel, fn] : kernels)
        for (const MeshSpec& s : specs)
        {
            const std::string name = std::string(kernel) + "/" + std::to_string(D) + "D/" + s.label;
            const double h = s.h;
            benchmark::RegisterBenchmark(name.c_str(), [fn, h](benchmark::State& st) { fn(st, h); })
                ->UseManualTime()
                ->Unit(benchmark::kMicrosecond);
        }
}

} // namespace

int main(int argc, char** argv)
{
    Tpetra::ScopeGuard scope(&argc, &argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    std::printf("unilag_bench: Kokkos %s, concurrency %d; inputs %s\n", ExecSpace::name(),
                int(ExecSpace::concurrency()), inputsDir().string().c_str());
    std::fflush(stdout);

    registerAll<2>(sizes2d);
    registerAll<3>(sizes3d);
    registerVariants<2>(sizes2d);
    registerVariants<3>(sizes3d);

    cache = new Cache;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    delete cache; // every View (and Tpetra map) goes before the scope guard finalizes Kokkos
    cache = nullptr;
    return 0;
}
