/*! \file bench_portable.cpp
 *  \brief The kernels of one first-order Lagrangian step, and the second-order gradients, timed and checked on a
 *  generated mesh with nothing but Kokkos and kernels/: no Trilinos, MPI or gmsh, so that it builds for any Kokkos
 *  backend. apps/CMakeLists.txt builds it for the CPU (OpenMP, as `unilag_bench_portable`), scripts/gpu-bench.sh
 *  for CUDA; the two runs are compared on the same meshes (docs/parallel.md, section 7).
 *
 *  Meshes: the unit square cut into N x N squares of two triangles each (diagonals alternating), or the unit cube
 *  into N^3 cubes of six tetrahedra (Kuhn's subdivision); interior nodes moved by up to 15% of the spacing (a fixed
 *  hash), every boundary a slip wall. `--shuffle` numbers cells and nodes at random, the worst case for caches and
 *  coalescing (a gmsh mesh lies between). State: the smooth flow of apps/bench_kernels.cpp.
 *
 *    unilag_bench_portable [--dim 2|3] [--sizes N1,N2,..] [--shuffle] [--steps K] [--csv FILE]
 *                          [--dump FILE] [--compare FILE]
 *
 *  For each N: K real steps first (CFL 0.5) with the self-check (positive volumes and sound speeds, total energy
 *  conserved to 1e-12 relative), then the timing of the phases of one step repeated from that state, median of the
 *  repeats: geometry, eos, nodal (nodal solve), update (move nodes + cell update), and gradients (the limited
 *  gradients of order 2). Throughput in cells/s of each phase and of the step (the first four). --dump writes the
 *  state after the K steps of the first size, --compare reads such a file (written by another backend) and prints
 *  the largest difference, relative to each field's largest magnitude. Exit 1 if a check fails.
 */
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>

#include "mesh/FaceKey.hpp"
#include "unilag/CellUpdate.hpp"
#include "unilag/Hydro.hpp"
#include "unilag/NodeMotion.hpp"
#include "unilag/Reconstruction.hpp"

namespace
{

using namespace unilag;
using Clock = std::chrono::steady_clock;

struct Options
{
    int dim = 2;
    std::vector<int> sizes;
    bool shuffle = false;
    int steps = 20;
    std::string csv, dump, compare;
};

//! A simplex mesh on the host: cell -> nodes (row-major, positively oriented), node coordinates.
struct HostMesh
{
    int dim = 2, nv = 3;
    std::vector<int> cells;
    std::vector<double> coords; //!< dim per node
    int nCells() const { return int(cells.size()) / nv; }
    int nNodes() const { return int(coords.size()) / dim; }
};

//! A fixed hash of the node index in [-1, 1]: the same perturbation on every backend and machine.
double hashUnit(std::uint64_t n, int salt)
{
    std::uint64_t z = n * 0x9E3779B97F4A7C15ull + std::uint64_t(salt) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) / double(1ull << 52) - 1.0;
}

//! Signed measure of cell c (twice the area in 2D, six times the volume in 3D): only its sign is used.
double orientation(const HostMesh& m, int c)
{
    const int* n = &m.cells[std::size_t(m.nv) * c];
    auto x = [&](int k, int d) {
        return m.coords[std::size_t(m.dim) * n[k] + d] - m.coords[std::size_t(m.dim) * n[0] + d];
    };
    if (m.dim == 2)
        return x(1, 0) * x(2, 1) - x(1, 1) * x(2, 0);
    return x(1, 0) * (x(2, 1) * x(3, 2) - x(2, 2) * x(3, 1)) - x(1, 1) * (x(2, 0) * x(3, 2) - x(2, 2) * x(3, 0)) +
           x(1, 2) * (x(2, 0) * x(3, 1) - x(2, 1) * x(3, 0));
}

HostMesh generateMesh(int dim, int n, bool shuffle)
{
    HostMesh m;
    m.dim = dim;
    m.nv = dim + 1;
    const int np = n + 1;
    const int nodes = dim == 2 ? np * np : np * np * np;
    auto id = [&](int i, int j, int k) { return i + np * (j + np * k); };
    m.coords.resize(std::size_t(dim) * nodes);
    for (int q = 0; q < nodes; ++q)
    {
        const int ijk[3] = {q % np, (q / np) % np, q / (np * np)};
        for (int d = 0; d < dim; ++d)
        {
            const bool interior = ijk[d] > 0 && ijk[d] < n;
            m.coords[std::size_t(dim) * q + d] = (ijk[d] + (interior ? 0.15 * hashUnit(q, d) : 0.0)) / n;
        }
    }
    if (dim == 2)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
            {
                const int a = id(i, j, 0), b = id(i + 1, j, 0), c = id(i + 1, j + 1, 0), d = id(i, j + 1, 0);
                const bool flip = (i + j) % 2 != 0;
                const int t[6] = {a, b, flip ? d : c, flip ? b : a, c, d};
                m.cells.insert(m.cells.end(), t, t + 6);
            }
    else
    {
        const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    for (const auto& p : perms) // the path from corner (0,0,0) to (1,1,1) along the axes p
                    {
                        int c[3] = {i, j, k};
                        m.cells.push_back(id(c[0], c[1], c[2]));
                        for (int s = 0; s < 3; ++s)
                        {
                            ++c[p[s]];
                            m.cells.push_back(id(c[0], c[1], c[2]));
                        }
                    }
    }
    if (shuffle)
    {
        std::mt19937 rng(12345);
        std::vector<int> cellOrder(m.nCells()), nodeOrder(nodes);
        std::iota(cellOrder.begin(), cellOrder.end(), 0);
        std::iota(nodeOrder.begin(), nodeOrder.end(), 0);
        std::shuffle(cellOrder.begin(), cellOrder.end(), rng);
        std::shuffle(nodeOrder.begin(), nodeOrder.end(), rng); // old node -> new node
        HostMesh s = m;
        for (int c = 0; c < m.nCells(); ++c)
            for (int k = 0; k < m.nv; ++k)
                s.cells[std::size_t(m.nv) * c + k] = nodeOrder[m.cells[std::size_t(m.nv) * cellOrder[c] + k]];
        for (int q = 0; q < nodes; ++q)
            for (int d = 0; d < dim; ++d)
                s.coords[std::size_t(dim) * nodeOrder[q] + d] = m.coords[std::size_t(dim) * q + d];
        m = std::move(s);
    }
    for (int c = 0; c < m.nCells(); ++c)
        if (orientation(m, c) < 0.0)
            std::swap(m.cells[std::size_t(m.nv) * c], m.cells[std::size_t(m.nv) * c + 1]);
    return m;
}

//! Device copies of a host mesh as the kernels' MeshView: face neighbours, boundary faces (group 0) and the
//! node -> corner lists (by cell, then corner), as src/mesh/DistributedMesh.cpp builds them on one rank.
template <int D>
MeshView<D> deviceMesh(const HostMesh& h)
{
    constexpr int NV = D + 1;
    const int nc = h.nCells(), nn = h.nNodes();
    Kokkos::View<LO**, Kokkos::LayoutLeft, MemSpace> cellNodes("portable::cellNodes", nc, NV);
    View<int**> faceGroup("portable::cellFaceGroup", nc, NV);
    View<LO**> neighbour("portable::cellNeighbour", nc, NV);
    View<int*> nodeBoundary("portable::nodeBoundary", nn);
    auto cn = Kokkos::create_mirror_view(cellNodes);
    auto fg = Kokkos::create_mirror_view(faceGroup);
    auto nb = Kokkos::create_mirror_view(neighbour);
    auto bn = Kokkos::create_mirror_view(nodeBoundary);
    Kokkos::deep_copy(fg, 0);
    Kokkos::deep_copy(nb, -1);
    Kokkos::deep_copy(bn, 0);
    for (int c = 0; c < nc; ++c)
        for (int k = 0; k < NV; ++k)
            cn(c, k) = h.cells[std::size_t(NV) * c + k];
    auto interior = [&](const FaceRef& a, const FaceRef& b) {
        nb(a.cell, a.k) = b.cell;
        nb(b.cell, b.k) = a.cell;
        fg(a.cell, a.k) = fg(b.cell, b.k) = -1;
    };
    auto boundary = [&](const FaceRef& a) {
        for (int k = 0; k < NV; ++k)
            if (k != a.k)
                bn(cn(a.cell, k)) = 1;
    };
    if (matchFaces(h.cells.data(), std::size_t(nc), NV, interior, boundary))
        throw std::logic_error("generated mesh: a face of more than two cells");
    std::vector<LO> offsets(nn + 1, 0), corners(std::size_t(nc) * NV);
    for (int q : h.cells)
        ++offsets[q + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<LO> pos(offsets.begin(), offsets.end() - 1);
    for (LO q = 0; q < LO(h.cells.size()); ++q) // corners in increasing cell order: sorted as required
        corners[pos[h.cells[q]]++] = q;
    using HostArray = Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
    View<LO*> nodeCornerOffsets("portable::nodeCornerOffsets", nn + 1);
    View<LO*> nodeCorners("portable::nodeCorners", corners.size());
    Kokkos::deep_copy(nodeCornerOffsets, HostArray(offsets.data(), offsets.size()));
    Kokkos::deep_copy(nodeCorners, HostArray(corners.data(), corners.size()));
    Kokkos::deep_copy(cellNodes, cn);
    Kokkos::deep_copy(faceGroup, fg);
    Kokkos::deep_copy(neighbour, nb);
    Kokkos::deep_copy(nodeBoundary, bn);
    MeshView<D> m;
    m.cellNodes = cellNodes;
    m.nodeCornerOffsets = nodeCornerOffsets;
    m.nodeCorners = nodeCorners;
    m.cellFaceGroup = faceGroup;
    m.cellNeighbour = neighbour;
    m.nodeBoundary = nodeBoundary;
    m.nOwnedCells = m.nCells = nc;
    m.nOwnedNodes = m.nNodes = nn;
    return m;
}

//! Everything a first-order hydro step needs on one mesh, the smooth flow of bench_kernels.cpp as its state.
template <int D>
struct Problem
{
    using S = HydroState<D>;
    MeshView<D> m;
    Field state, stateNew, x, xNew, vnode, fnode, aux, grad;
    CellGeometry geom;
    View<double*> mass;
    View<int*> cellMaterial;
    View<Material*> materials;
    BoundaryView bc;
    double time = 0.0;

    explicit Problem(const HostMesh& h) : m(deviceMesh<D>(h))
    {
        const LO nc = m.nCells, nn = m.nNodes;
        state = Field("portable::state", nc, S::ncomp);
        stateNew = Field("portable::stateNew", nc, S::ncomp);
        x = Field("portable::x", nn, D);
        xNew = Field("portable::xNew", nn, D);
        vnode = Field("portable::vnode", nn, D);
        fnode = Field("portable::fnode", nn, D);
        aux = Field("portable::aux", nc, Aux::ncomp<PhysicsHydro>());
        grad = Field("portable::grad", nc, ReconLayout<D, PhysicsHydro>::ncomp);
        geom = CellGeometry(nc, D);
        mass = View<double*>("portable::mass", nc);
        cellMaterial = View<int*>("portable::cellMaterial", nc);
        materials = View<Material*>("portable::materials", 1);
        auto matH = Kokkos::create_mirror_view(materials);
        matH(0) = fluidMaterial(gpr::idealGasEos(1.4, 1.0));
        Kokkos::deep_copy(materials, matH);
        View<int*> type("portable::bcType", 1);
        Kokkos::deep_copy(type, int(BcSlipWall));
        bc.type = type;
        bc.value = Kokkos::View<double* [3], MemSpace>("portable::bcValue", 1);
        bc.thermal = View<int*>("portable::bcThermal", 1);
        bc.temperature = View<double*>("portable::bcTemperature", 1);
        auto xh = Kokkos::create_mirror_view(x);
        for (LO q = 0; q < nn; ++q)
            for (int d = 0; d < D; ++d)
                xh(q, d) = h.coords[std::size_t(D) * q + d];
        Kokkos::deep_copy(x, xh);
        initialState(h);
    }

    //! rho = 1 + 0.1 x, p = 1 + 0.5 sin(3x) cos(2y), v = 0.05 (sin(2y), -sin(2x)[, 0.5 sin(2x + y)]).
    void initialState(const HostMesh& h)
    {
        if (!(computeGeometry<D>(m, x, geom, m.nCells) > 0.0))
            throw std::runtime_error("generated mesh: a cell of non-positive volume");
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.volume);
        auto sh = Kokkos::create_mirror_view(state);
        auto massH = Kokkos::create_mirror_view(mass);
        const double gamma = 1.4;
        for (LO i = 0; i < m.nCells; ++i)
        {
            double c[3] = {0, 0, 0};
            for (int k = 0; k < D + 1; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += h.coords[std::size_t(D) * h.cells[std::size_t(D + 1) * i + k] + d] / (D + 1);
            const double rho = 1.0 + 0.1 * c[0];
            const double p = 1.0 + 0.5 * std::sin(3.0 * c[0]) * std::cos(2.0 * c[1]);
            const double v[3] = {0.05 * std::sin(2.0 * c[1]), -0.05 * std::sin(2.0 * c[0]),
                                 0.025 * std::sin(2.0 * c[0] + c[1])};
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
    }

    // The phases of one step, each a call of the kernels a run makes (src/solver/GprOperator.hpp, order 1).
    void geometry() { computeGeometry<D>(m, x, geom, m.nCells); }
    void eos() { computeEos<D>(state, cellMaterial, materials, aux, m.nCells); }
    void nodal() { nodalSolve<D>(m, bc, state, aux, geom, vnode, fnode); }
    double timeStep() { return stableTimeStep<D>(m, aux, geom, vnode, 0.5, 0.1); }
    UpdateCheck update(double dt)
    {
        moveNodes(x, vnode, dt, xNew, m.nNodes, D);
        return updateCells<D>(m, state, aux, geom, mass, cellMaterial, materials, x, xNew, vnode, dt, stateNew);
    }
    void gradients() { limitedGradients<D, PhysicsHydro>(m, state, aux, ConstField(), geom, x, grad, bc); }

    //! Total energy sum_i m_i E_i (conserved to round-off: slip walls do no work).
    double totalEnergy() const
    {
        double e = 0.0;
        auto st = state;
        auto ms = mass;
        Kokkos::parallel_reduce(
            "portable::total_energy", range(m.nCells),
            KOKKOS_LAMBDA(const LO i, double& sum) { sum += ms(i) * st(i, S::energy); }, e);
        return e;
    }

    //! K steps at CFL 0.5; throws where a step is not valid or the energy drifts by more than 1e-12 relative.
    void evolve(int steps)
    {
        const double e0 = totalEnergy();
        for (int n = 0; n < steps; ++n)
        {
            geometry();
            eos();
            nodal();
            const double dt = timeStep();
            const UpdateCheck check = update(dt);
            if (!(dt > 0.0) || !(check.minVolumeRatio > 0.0) || !(check.minSound2 > 0.0))
                throw std::runtime_error("step " + std::to_string(n) + " is not valid (dt " + std::to_string(dt) +
                                         ", cell " + std::to_string(check.worstCell) + ")");
            std::swap(state, stateNew);
            std::swap(x, xNew);
            time += dt;
        }
        const double drift = std::abs(totalEnergy() - e0) / e0;
        std::printf("  self-check: %d steps to t = %.6e, energy drift %.2e (bound 1e-12)\n", steps, time, drift);
        if (!(drift <= 1e-12))
            throw std::runtime_error("total energy not conserved");
    }
};

constexpr int kPhases = 5;
const char* const kPhaseNames[kPhases] = {"geometry", "eos", "nodal", "update", "gradients"};

//! Median over repeats of each phase's time (s), fenced on both sides; repeats until about 1 s has been spent.
template <int D>
std::vector<double> timePhases(Problem<D>& p)
{
    p.geometry();
    p.eos();
    p.nodal();
    const double dt = p.timeStep();
    std::vector<std::vector<double>> samples(kPhases);
    double spent = 0.0;
    for (int r = 0; r < 200 && (r < 7 || spent < 1.0); ++r)
    {
        for (int k = 0; k < kPhases; ++k)
        {
            Kokkos::fence();
            const auto t0 = Clock::now();
            switch (k)
            {
            case 0: p.geometry(); break;
            case 1: p.eos(); break;
            case 2: p.nodal(); break;
            case 3: p.update(dt); break;
            default: p.gradients(); break;
            }
            Kokkos::fence();
            const double t = std::chrono::duration<double>(Clock::now() - t0).count();
            if (r >= 2) // two warm-up rounds
                samples[k].push_back(t);
            spent += t;
        }
    }
    std::vector<double> median(kPhases);
    for (int k = 0; k < kPhases; ++k)
    {
        auto& s = samples[k];
        std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
        median[k] = s[s.size() / 2];
    }
    return median;
}

//! The header of a dump: dimension, cells, state components, nodes.
struct DumpHeader
{
    char magic[8] = {'U', 'N', 'I', 'L', 'A', 'G', 'P', '1'};
    std::int32_t dim = 0, cells = 0, ncomp = 0, nodes = 0;
};

template <int D>
void writeDump(const Problem<D>& p, const std::string& file)
{
    DumpHeader h;
    h.dim = D;
    h.cells = p.m.nCells;
    h.ncomp = int(p.state.extent(1));
    h.nodes = p.m.nNodes;
    auto st = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.state);
    auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    for (int c = 0; c < h.ncomp; ++c)
        out.write(reinterpret_cast<const char*>(&st(0, c)), std::streamsize(sizeof(double)) * h.cells);
    for (int d = 0; d < D; ++d)
        out.write(reinterpret_cast<const char*>(&xh(0, d)), std::streamsize(sizeof(double)) * h.nodes);
    if (!out)
        throw std::runtime_error(file + ": cannot be written");
    std::printf("  state after the self-check written to %s\n", file.c_str());
}

//! Largest difference of each state component and of the coordinates against a dump, relative to the dump's
//! largest magnitude of that column; returns the largest of them.
template <int D>
double compareDump(const Problem<D>& p, const std::string& file)
{
    std::ifstream in(file, std::ios::binary);
    DumpHeader h, want;
    in.read(reinterpret_cast<char*>(&h), sizeof h);
    if (!in || std::string(h.magic, 8) != std::string(want.magic, 8) || h.dim != D || h.cells != p.m.nCells ||
        h.ncomp != int(p.state.extent(1)) || h.nodes != p.m.nNodes)
        throw std::runtime_error(file + ": not a dump of this mesh (dimension, cells, components or nodes differ)");
    auto st = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.state);
    auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
    double worst = 0.0;
    auto column = [&](const char* name, int count, auto value) {
        std::vector<double> ref(count);
        in.read(reinterpret_cast<char*>(ref.data()), std::streamsize(sizeof(double)) * count);
        double scale = 0.0, diff = 0.0;
        for (int i = 0; i < count; ++i)
        {
            scale = std::max(scale, std::abs(ref[i]));
            diff = std::max(diff, std::abs(value(i) - ref[i]));
        }
        const double rel = scale > 0.0 ? diff / scale : diff;
        std::printf("    %-10s max |difference| / max |reference| = %.3e\n", name, rel);
        worst = std::max(worst, rel);
    };
    std::printf("  against %s:\n", file.c_str());
    for (int c = 0; c < h.ncomp; ++c)
        column(("state[" + std::to_string(c) + "]").c_str(), h.cells, [&](int i) { return st(i, c); });
    for (int d = 0; d < D; ++d)
        column(("x[" + std::to_string(d) + "]").c_str(), h.nodes, [&](int i) { return xh(i, d); });
    if (!in)
        throw std::runtime_error(file + ": truncated");
    return worst;
}

Options parse(int argc, char** argv)
{
    Options o;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        auto next = [&]() -> std::string {
            if (a + 1 >= argc)
                throw std::invalid_argument(arg + " needs a value");
            return argv[++a];
        };
        if (arg.rfind("--kokkos", 0) == 0) // Kokkos' own options (--kokkos-threads=N, ...)
            continue;
        if (arg == "--dim")
            o.dim = std::stoi(next());
        else if (arg == "--sizes")
        {
            const std::string list = next();
            for (std::size_t s = 0; s < list.size();)
            {
                const std::size_t e = std::min(list.find(',', s), list.size());
                o.sizes.push_back(std::stoi(list.substr(s, e - s)));
                s = e + 1;
            }
        }
        else if (arg == "--shuffle")
            o.shuffle = true;
        else if (arg == "--steps")
            o.steps = std::stoi(next());
        else if (arg == "--csv")
            o.csv = next();
        else if (arg == "--dump")
            o.dump = next();
        else if (arg == "--compare")
            o.compare = next();
        else
            throw std::invalid_argument("unknown option " + arg);
    }
    if (o.dim != 2 && o.dim != 3)
        throw std::invalid_argument("--dim must be 2 or 3");
    if (o.sizes.empty())
        o.sizes = o.dim == 2 ? std::vector<int>{64, 128, 256} : std::vector<int>{12, 24};
    if (o.steps < 1 || *std::min_element(o.sizes.begin(), o.sizes.end()) < 2)
        throw std::invalid_argument("--steps must be >= 1 and every size >= 2");
    return o;
}

template <int D>
int run(const Options& o)
{
    const std::string backend = ExecSpace::name();
    const int concurrency = ExecSpace().concurrency();
    std::FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
    if (!o.csv.empty() && !csv)
        throw std::runtime_error(o.csv + ": cannot be written");
    if (csv)
        std::fprintf(csv, "backend,concurrency,dim,n,shuffled,cells,nodes,geometry_s,eos_s,nodal_s,update_s,"
                          "gradients_s,step_cells_per_s\n");
    int status = 0;
    for (std::size_t s = 0; s < o.sizes.size(); ++s)
    {
        const int n = o.sizes[s];
        Problem<D> p(generateMesh(D, n, o.shuffle));
        std::printf("%s (concurrency %d), %dD, N = %d%s: %d cells, %d nodes\n", backend.c_str(), concurrency, D, n,
                    o.shuffle ? " shuffled" : "", p.m.nCells, p.m.nNodes);
        p.evolve(o.steps);
        if (s == 0 && !o.dump.empty())
            writeDump(p, o.dump);
        if (s == 0 && !o.compare.empty() && !(compareDump(p, o.compare) <= 1e-10))
        {
            std::printf("  FAILED: differs from %s by more than 1e-10\n", o.compare.c_str());
            status = 1;
        }
        const std::vector<double> t = timePhases(p);
        const double step = t[0] + t[1] + t[2] + t[3];
        std::printf("  Mcells/s:");
        for (int k = 0; k < kPhases; ++k)
            std::printf(" %s %.2f", kPhaseNames[k], 1e-6 * p.m.nCells / t[k]);
        std::printf(" | step %.2f (%.1f ns per cell-step)\n", 1e-6 * p.m.nCells / step, 1e9 * step / p.m.nCells);
        if (csv)
            std::fprintf(csv, "%s,%d,%d,%d,%d,%d,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n", backend.c_str(), concurrency, D,
                         n, int(o.shuffle), p.m.nCells, p.m.nNodes, t[0], t[1], t[2], t[3], t[4], p.m.nCells / step);
        std::fflush(stdout);
    }
    if (csv)
        std::fclose(csv);
    return status;
}

} // namespace

int main(int argc, char** argv)
{
    Kokkos::ScopeGuard kokkos(argc, argv);
    try
    {
        const Options o = parse(argc, argv);
        return o.dim == 2 ? run<2>(o) : run<3>(o);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "unilag_bench_portable: %s\n", e.what());
        return 1;
    }
}
