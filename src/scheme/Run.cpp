#include "scheme/Run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <unistd.h>

#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include "io/XdmfWriter.hpp"
#include "mesh/DistributedMesh.hpp"
#include "physics/Exact.hpp"
#include "physics/Expression.hpp"
#include "unilag/Heat.hpp"
#include "unilag/Hydro.hpp"
#include "unilag/Reconstruction.hpp"

namespace unilag
{
namespace
{

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

MPI_Comm rawComm(const Teuchos::RCP<const Comm>& comm)
{
    auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm);
    return mpi.is_null() ? MPI_COMM_SELF : (*mpi->getRawMpiComm())();
}

//! The first non-empty message over the ranks (by rank), the same on every rank. Collective.
std::string firstMessage(MPI_Comm comm, const std::string& local)
{
    int size;
    MPI_Comm_size(comm, &size);
    const int mine = int(local.size());
    std::vector<int> lens(size);
    MPI_Allgather(&mine, 1, MPI_INT, lens.data(), 1, MPI_INT, comm);
    for (int p = 0; p < size; ++p)
        if (lens[p] > 0)
        {
            std::string msg = local;
            msg.resize(lens[p]);
            MPI_Bcast(msg.data(), lens[p], MPI_CHAR, p, comm);
            return msg;
        }
    return {};
}

double allMin(MPI_Comm comm, double v)
{
    double r;
    MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MIN, comm);
    return r;
}

template <int N>
void allSum(MPI_Comm comm, double (&v)[N])
{
    MPI_Allreduce(MPI_IN_PLACE, v, N, MPI_DOUBLE, MPI_SUM, comm);
}

//! Phase timers (seconds), Laghos style.
struct Timers
{
    double geometry = 0, nodal = 0, strain = 0, heat = 0, update = 0, halo = 0, io = 0, recon = 0;
};

class ScopedTimer
{
  public:
    explicit ScopedTimer(double& acc) : acc_(acc), t0_(Clock::now()) {}
    ~ScopedTimer()
    {
        Kokkos::fence();
        acc_ += std::chrono::duration<double>(Clock::now() - t0_).count();
    }

  private:
    double& acc_;
    Clock::time_point t0_;
};

std::string jsonNumber(double v)
{
    if (!std::isfinite(v))
        return "null";
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

//! Kernel material data of a scene material (the scene reader has validated it).
Material toMaterial(const MaterialSpec& spec)
{
    Material m;
    m.eos = spec.eos == "ideal_gas"       ? gpr::idealGasEos(spec.gamma, spec.cv)
            : spec.eos == "mie_gruneisen" ? gpr::mieGruneisenEos(spec.rho0, spec.c0, spec.Gamma0, spec.s, spec.cv)
                                          : gpr::neoHookeanEos(spec.rho0, spec.csh, spec.cv);
    m.rho0 = spec.rho0;
    if (spec.strainLaw != "fluid")
    {
        m.csh = spec.shearSpeed;
        m.strainLaw = spec.strainLaw == "plastic" ? StrainPlastic : StrainConstant;
        m.tau1 = spec.tau1;
        m.tau10 = spec.tau10;
        m.sigmaY = spec.yieldStress;
        m.exponent = spec.exponent;
    }
    if (spec.heatConduction)
    {
        m.heat = 1;
        m.alpha = spec.alpha;
        m.tau2 = spec.tau2;
        m.theta0 = spec.theta0;
    }
    return m;
}

/*! The solver for one scene: dimension D and the physics variant P (Physics.hpp) are compile-time, so a scene
 *  pays only for the equations its materials need. */
template <int D, class P>
class GprSolver
{
    using S = StateLayout<D, P>;

  public:
    GprSolver(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options)
        : scene_(scene), mesh_(std::move(mesh)), options_(options), comm_(rawComm(mesh_->comm))
    {
        MPI_Comm_rank(comm_, &rank_);
        MPI_Comm_size(comm_, &size_);
        m_ = mesh_->view<D>();
        const auto& dm = *mesh_;
        state_ = Teuchos::rcp(new MV(dm.cellMapOverlap, S::ncomp));
        stateNew_ = Teuchos::rcp(new MV(dm.cellMapOverlap, S::ncomp));
        x_ = Teuchos::rcp(new MV(dm.nodeMapOverlap, D));
        xNew_ = Teuchos::rcp(new MV(dm.nodeMapOverlap, D));
        vnode_ = Teuchos::rcp(new MV(dm.nodeMapOverlap, D));
        fnode_ = Field("unilag::fnode", dm.nOwnedNodes, D);
        aux_ = Field("unilag::aux", dm.nCells, Aux::ncomp<P>());
        if constexpr (P::strain)
        {
            sigma_ = Teuchos::rcp(new MV(dm.cellMapOverlap, 6));
            sigmaNext_ = Teuchos::rcp(new MV(dm.cellMapOverlap, 6));
            sigmaPrev_ = Teuchos::rcp(new MV(dm.cellMapOverlap, 6));
            sigma0_ = Teuchos::rcp(new MV(dm.cellMapOverlap, 6));
            if (scene_.order == 2)
                sigmaPrev2_ = Teuchos::rcp(new MV(dm.cellMapOverlap, 6));
            if constexpr (P::plastic)
            {
                plasticHint_ = View<double*>("unilag::plasticHint", dm.nOwnedCells);
                Kokkos::deep_copy(plasticHint_, std::numeric_limits<double>::quiet_NaN());
                if (scene_.order == 2)
                {
                    plasticHintCorrector_ = View<double*>("unilag::plasticHintCorrector", dm.nOwnedCells);
                    Kokkos::deep_copy(plasticHintCorrector_, std::numeric_limits<double>::quiet_NaN());
                }
            }
        }
        if constexpr (P::heat)
            heatRate_ = Field("unilag::heatRate", dm.nOwnedCells, 1 + D);
        geom_ = CellGeometry(dm.nCells, D);
        geomNew_ = CellGeometry(dm.nCells, D);
        if (P::strain || scene_.order == 2)
            vnode0_ = Teuchos::rcp(new MV(dm.nodeMapOverlap, D));
        if (scene_.order == 2)
        {
            stateMid_ = Teuchos::rcp(new MV(dm.cellMapOverlap, S::ncomp));
            xMid_ = Teuchos::rcp(new MV(dm.nodeMapOverlap, D));
            grad_ = Teuchos::rcp(new MV(dm.cellMapOverlap, ReconLayout<D, P>::ncomp));
            geomMid_ = CellGeometry(dm.nCells, D);
            auxMid_ = Field("unilag::auxMid", dm.nCells, Aux::ncomp<P>());
            if constexpr (P::strain)
                sigmaMid_ = Field("unilag::sigmaMid", dm.nCells, 6);
            if constexpr (P::heat)
                heatRateMid_ = Field("unilag::heatRateMid", dm.nOwnedCells, 1 + D);
        }
        mass_ = View<double*>("unilag::mass", dm.nCells);
        cellMaterial_ = View<int*>("unilag::cellMaterial", dm.nCells);
    }

    //! Initial conditions, masses and boundary table. Returns an error message ("" if fine). Collective.
    std::string initialize()
    {
        const auto& dm = *mesh_;
        std::string error;
        // Boundary table by group id; every group of the mesh needs a condition.
        {
            const int ng = int(dm.boundaryNames.size());
            View<int*> type("unilag::bcType", std::max(ng, 1)), thermal("unilag::bcThermal", std::max(ng, 1));
            View<double*> temperature("unilag::bcTemperature", std::max(ng, 1));
            Kokkos::View<double* [3], MemSpace> value("unilag::bcValue", std::max(ng, 1));
            auto th = Kokkos::create_mirror_view(type);
            auto vh = Kokkos::create_mirror_view(value);
            auto thermalH = Kokkos::create_mirror_view(thermal);
            auto tempH = Kokkos::create_mirror_view(temperature);
            for (int g = 0; g < ng; ++g)
            {
                auto it = scene_.boundaries.find(dm.boundaryNames[g]);
                if (it == scene_.boundaries.end())
                    return scene_.file + ": key 'boundaries': the mesh has a boundary group '" + dm.boundaryNames[g] +
                           "' with no condition";
                const auto& t = it->second.type;
                th(g) = t == "velocity"   ? BcVelocity
                        : t == "free"     ? BcFree
                        : t == "pressure" ? BcPressure
                        : t == "traction" ? BcTraction
                                          : BcSlipWall;
                for (int d = 0; d < 3; ++d)
                    vh(g, d) = t == "traction" ? it->second.traction[d] : it->second.velocity[d];
                thermalH(g) = it->second.thermal == "isothermal" ? ThermalIsothermal : ThermalAdiabatic;
                tempH(g) = it->second.temperature;
                if (t == "pressure")
                {
                    const Expr& e = it->second.pressure;
                    vh(g, 0) = e.value;
                    if (!e.isConstant())
                        pressureLaws_.emplace_back(g, std::make_unique<Expression>(e.text));
                }
            }
            for (const auto& [name, spec] : scene_.boundaries)
                if (std::find(dm.boundaryNames.begin(), dm.boundaryNames.end(), name) == dm.boundaryNames.end())
                    return scene_.file + ": key 'boundaries." + name + "': the mesh has no boundary group '" + name + "'";
            Kokkos::deep_copy(type, th);
            Kokkos::deep_copy(value, vh);
            Kokkos::deep_copy(thermal, thermalH);
            Kokkos::deep_copy(temperature, tempH);
            bc_.type = type;
            bc_.value = value;
            bc_.thermal = thermal;
            bc_.temperature = temperature;
            bcValue_ = value;
            bcValueHost_ = vh;
        }
        // Materials, indexed in the order of the scene's map.
        std::vector<std::string> matNames;
        View<Material*> mats("unilag::materials", scene_.materials.size());
        auto mh = Kokkos::create_mirror_view(mats);
        for (const auto& [name, spec] : scene_.materials)
        {
            mh(matNames.size()) = toMaterial(spec);
            matNames.push_back(name);
        }
        Kokkos::deep_copy(mats, mh);
        materials_ = mats;
        for (const auto& name : dm.regionNames)
            if (!scene_.regions.count(name))
                return scene_.file + ": key 'regions': the mesh has a region '" + name + "' with no initial state";
        for (const auto& [name, spec] : scene_.regions)
            if (std::find(dm.regionNames.begin(), dm.regionNames.end(), name) == dm.regionNames.end())
                return scene_.file + ": key 'regions." + name + "': the mesh has no region (physical group) '" + name + "'";

        // Coordinates.
        {
            auto xh = x_->getLocalViewHost(Tpetra::Access::OverwriteAll);
            for (LO n = 0; n < dm.nNodes; ++n)
                for (int d = 0; d < D; ++d)
                    xh(n, d) = dm.coords0[3 * n + d];
        }
        double vmin;
        {
            auto x = x_->getLocalViewDevice(Tpetra::Access::ReadOnly);
            vmin = computeGeometry<D>(m_, x, geom_, dm.nCells);
        }
        if (!(vmin > 0.0))
            return "internal: a cell of the distributed mesh has non-positive volume";

        // Region states at cell centroids (owned and ghost cells alike, so no exchange is needed).
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.volume);
        auto massH = Kokkos::create_mirror_view(mass_);
        auto matH = Kokkos::create_mirror_view(cellMaterial_);
        auto sh = state_->getLocalViewHost(Tpetra::Access::OverwriteAll);
        std::vector<double> pressure(dm.nCells), eps(dm.nCells);
        for (std::size_t r = 0; r < dm.regionNames.size() && error.empty(); ++r)
        {
            const RegionSpec& spec = scene_.regions.at(dm.regionNames[r]);
            const std::string key = "regions." + dm.regionNames[r] + ".";
            if (spec.velocityComponents != 0 && spec.velocityComponents != D)
            {
                error = scene_.file + ": key '" + key + "velocity': the mesh is " + std::to_string(D) +
                        "D, the velocity has " + std::to_string(spec.velocityComponents) + " components";
                break;
            }
            auto compile = [](const Expr& e) { return e.isConstant() ? nullptr : std::make_unique<Expression>(e.text); };
            auto rhoE = compile(spec.density);
            auto thE = compile(spec.hasPressure ? spec.pressure : spec.internalEnergy);
            std::unique_ptr<Expression> velE[3];
            for (int d = 0; d < spec.velocityComponents; ++d)
                velE[d] = compile(spec.velocity[d]);
            const int mat = int(std::distance(scene_.materials.begin(), scene_.materials.find(spec.material)));
            for (LO i = 0; i < dm.nCells; ++i)
            {
                if (dm.cellRegion[i] != int(r))
                    continue;
                double c[3] = {0, 0, 0};
                for (int k = 0; k < D + 1; ++k)
                    for (int d = 0; d < D; ++d)
                        c[d] += dm.coords0[3 * dm.cellNodesHost[(D + 1) * i + k] + d] / (D + 1);
                auto eval = [&](const Expr& e, std::unique_ptr<Expression>& x) { return x ? (*x)(c[0], c[1], c[2]) : e.value; };
                const double rho = eval(spec.density, rhoE);
                const double th = eval(spec.hasPressure ? spec.pressure : spec.internalEnergy, thE);
                const char* thKey = spec.hasPressure ? "pressure" : "specific_internal_energy";
                if (!(rho > 0.0) || !std::isfinite(rho))
                {
                    error = scene_.file + ": key '" + key + "density': value " + std::to_string(rho) +
                            " at cell " + std::to_string(dm.cellGid[i]) + " is not positive";
                    break;
                }
                if (!(th >= 0.0) || !std::isfinite(th))
                {
                    error = scene_.file + ": key '" + key + thKey + "': value " + std::to_string(th) + " at cell " +
                            std::to_string(dm.cellGid[i]) + " is negative";
                    break;
                }
                double kin = 0.0;
                for (int d = 0; d < D; ++d)
                {
                    const double v = d < spec.velocityComponents ? eval(spec.velocity[d], velE[d]) : 0.0;
                    sh(i, S::vel + d) = v;
                    kin += 0.5 * v * v;
                }
                eps[i] = spec.hasPressure ? gpr::internalEnergy(mh(mat).eos, rho, th) : th;
                sh(i, S::omega) = 1.0 / rho;
                sh(i, S::energy) = eps[i] + kin;
                if constexpr (P::strain)
                {
                    // at rest: G_e = (rho / rho0)^{2/3} I, so det G_e = (rho / rho0)^2 (gpr.md 1.1) and sigma = 0
                    const double g = std::cbrt((rho / mh(mat).rho0) * (rho / mh(mat).rho0));
                    for (int c = 0; c < 6; ++c)
                        sh(i, S::G + c) = c < 3 ? g : 0.0;
                }
                if constexpr (P::heat)
                    for (int d = 0; d < D; ++d)
                        sh(i, S::J + d) = 0.0;
                massH(i) = rho * vol(i);
                matH(i) = mat;
            }
        }
        error = firstMessage(comm_, error);
        if (!error.empty())
            return error;

        // Point energy deposit: into the cells around the node nearest to the point, uniform specific energy.
        if (scene_.hasDeposit)
        {
            struct
            {
                double dist;
                int rank;
            } best{1e300, rank_}, global;
            GO bestNode = -1;
            for (LO n = 0; n < dm.nOwnedNodes; ++n)
            {
                double d2 = 0;
                for (int d = 0; d < D; ++d)
                    d2 += std::pow(dm.coords0[3 * n + d] - scene_.depositPosition[d], 2);
                if (d2 < best.dist || (d2 == best.dist && dm.nodeGid[n] < bestNode))
                {
                    best.dist = d2;
                    bestNode = dm.nodeGid[n];
                }
            }
            MPI_Allreduce(&best, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm_);
            long long node = bestNode;
            MPI_Bcast(&node, 1, MPI_LONG_LONG, global.rank, comm_);
            double m[1] = {0.0};
            auto touches = [&](LO i) {
                for (int k = 0; k < D + 1; ++k)
                    if (dm.nodeGid[dm.cellNodesHost[(D + 1) * i + k]] == node)
                        return true;
                return false;
            };
            for (LO i = 0; i < dm.nOwnedCells; ++i)
                if (touches(i))
                    m[0] += massH(i);
            allSum(comm_, m);
            for (LO i = 0; i < dm.nCells; ++i)
                if (touches(i))
                    sh(i, S::energy) += scene_.depositEnergy / m[0];
        }
        Kokkos::deep_copy(mass_, massH);
        Kokkos::deep_copy(cellMaterial_, matH);
        return {};
    }

    //! Mass (sum of |T_i| / omega_i: tests the GCL), momentum, total energy, and sum m|v| over owned cells.
    void totals(double (&out)[D + 3])
    {
        auto s = state_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        auto volume = geom_.volume;
        auto mass = mass_;
        auto sum = KOKKOS_LAMBDA(const LO i, double (&acc)[D + 3])
        {
            acc[0] += volume(i) / s(i, S::omega);
            double v2 = 0.0;
            for (int d = 0; d < D; ++d)
            {
                acc[1 + d] += mass(i) * s(i, S::vel + d);
                v2 += s(i, S::vel + d) * s(i, S::vel + d);
            }
            acc[1 + D] += mass(i) * s(i, S::energy);
            acc[2 + D] += mass(i) * Kokkos::Experimental::sqrt(v2);
        };
        sumReduce<D + 3>("unilag::diagnostics::totals", m_.nOwnedCells, sum, out);
        allSum(comm_, out);
    }

    //! Geometry of local cells [first, nCells) at the current positions.
    void refreshGeometry(LO first = 0)
    {
        ScopedTimer t(timers_.geometry);
        auto x = x_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        computeGeometry<D>(m_, x, geom_, m_.nCells, first);
    }

    int run()
    {
        const auto& dm = *mesh_;
        const fs::path outDir = scene_.outputDirectory;
        std::unique_ptr<io::XdmfWriter> writer;
        if (scene_.writeOutput)
        {
            writer = std::make_unique<io::XdmfWriter>(comm_, outDir.string(), "unilag", D);
            std::vector<long long> conn(std::size_t(dm.nOwnedCells) * (D + 1));
            for (LO i = 0; i < dm.nOwnedCells; ++i)
                for (int k = 0; k < D + 1; ++k)
                    conn[(D + 1) * i + k] = dm.nodeOutputId[dm.cellNodesHost[(D + 1) * i + k]];
            writer->setTopology(dm.nOwnedNodes, dm.nOwnedCells, conn);
        }

        refreshGeometry();
        computeAux();
        double initial[D + 3];
        totals(initial);
        double impulse[D] = {}, work = 0.0;
        double t = 0.0, dtPrev = scene_.initialTimeStep;
        long step = 0;
        int dumps = 0, retries = 0;
        double maxGcl = 0.0;
        double nextOutput = scene_.outputInterval > 0 ? scene_.outputInterval : scene_.endTime;
        if (writer)
            dump(*writer, dumps++, t);

        if (rank_ == 0)
        {
            steps_ = std::make_unique<std::ofstream>(outDir / "steps.csv");
            *steps_ << "step,t,dt,picard_iterations,dt_halvings\n";
        }
        const auto wall0 = Clock::now();
        auto lastReport = wall0;
        const bool tty = isatty(fileno(stdout));
        std::string failure;
        const double tEnd = scene_.endTime;
        const bool order2 = scene_.order == 2;
        while (t < tEnd * (1.0 - 1e-14) && step < scene_.maxSteps)
        {
            // 1. Nodal solve on the configuration at t^n (geometry and EOS are current for all local cells).
            setBoundaryTime(t);
            if constexpr (P::strain)
                startPicard(step, order2);
            solveNodes();
            if constexpr (P::heat)
            {
                // explicit heat fluxes at t^n (gpr.md 2.3): independent of dt
                ScopedTimer timer(timers_.heat);
                auto s = state_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                heatFluxes<D, P>(m_, bc_, s, aux_, geom_, cellMaterial_, materials_, heatRate_);
            }
            // 2. Time step: CFL, volume change, growth, output times and the end time.
            double dt;
            {
                ScopedTimer timer(timers_.nodal);
                auto v = vnode_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                dt = allMin(comm_, stableTimeStep<D>(m_, aux_, geom_, v, scene_.cfl, scene_.maxVolumeChange));
            }
            if (!(dt > 0.0) || !std::isfinite(dt))
            {
                failure = "the stable time step is " + jsonNumber(dt) + " at t = " + jsonNumber(t);
                break;
            }
            dt = dtPrev > 0.0 ? std::min(dt, scene_.maxGrowth * dtPrev) : 0.1 * dt;
            if (dt < 1e-12 * tEnd)
            {
                failure = collapse(t, dt, step);
                break;
            }
            const double target = std::min(nextOutput, tEnd);
            if (t + dt > target * (1.0 - 1e-12))
                dt = target - t;
            if (!(dt > 0.0))
            {
                failure = "internal: zero time step at t = " + jsonNumber(t) + " (output time " + jsonNumber(target) + ")";
                break;
            }

            // 3. Move nodes and update cells; reject steps that invert a cell, make the state inadmissible or
            //    leave the Picard loop unconverged, halving dt (v^0 and sigma^n do not depend on dt).
            //    Second order: this first-order update over dt/2 is the predictor, and corrector() then takes the
            //    whole step with the fluxes of the midpoint state.
            UpdateCheck check{};
            int attempt = 0, iterations = 0;
            std::string picardFailure;
            if (vnode0_)
                Tpetra::deep_copy(*vnode0_, *vnode_);
            for (;; ++attempt)
            {
                bool ok = true;
                picardFailure.clear();
                const double dtFirst = order2 ? 0.5 * dt : dt;
                if (attempt > 0 && vnode0_)
                {
                    Tpetra::deep_copy(*vnode_, *vnode0_);
                    setBoundaryTime(t);
                }
                if constexpr (P::strain)
                {
                    if (attempt > 0)
                        Tpetra::deep_copy(*sigma_, *sigma0_);
                    ok = picard(dtFirst, iterations, picardFailure);
                }
                if (ok)
                {
                    ScopedTimer timer(timers_.update);
                    const StepViews w = stepViews();
                    const auto &x = w.x, &v = w.v, &s = w.s;
                    const auto &xn = w.xn, &sn = w.sn;
                    if constexpr (!P::strain)
                        moveNodes(x, v, dtFirst, xn, m_.nNodes, D); // (the converged Picard iterate has moved them)
                    ConstField sigma;
                    if constexpr (P::strain)
                        sigma = sigma_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                    check = reduceCheck(updateCells<D, P>(m_, s, aux_, geom_, mass_, cellMaterial_, materials_, x, xn,
                                                          v, dtFirst, sn, sigma, heatRate_, geomNew_));
                }
                ok = ok && check.minVolumeRatio > 0.0 && check.minSound2 > 0.0;
                if (ok && order2)
                {
                    ok = corrector(t, dt, check, picardFailure);
                    ok = ok && check.minVolumeRatio > 0.0 && check.minSound2 > 0.0;
                }
                if (ok)
                    break;
                if (attempt >= scene_.maxRetries)
                    break;
                dt *= 0.5;
                ++retries;
            }
            if (!picardFailure.empty() && attempt >= scene_.maxRetries)
            {
                failure = "at t = " + jsonNumber(t) + " after " + std::to_string(attempt) + " halvings of dt: " +
                          picardFailure;
                break;
            }
            if (!(check.minVolumeRatio > 0.0 && check.minSound2 > 0.0))
            {
                failure = diagnose(check, t, dt, attempt);
                break;
            }
            if constexpr (P::strain)
                if (order2)
                    notePredictorStress();
            picardTotal_ += iterations;
            picardMax_ = std::max(picardMax_, iterations);
            stepLog(step + 1, t + dt, dt, iterations, attempt);
            maxGcl = std::max(maxGcl, check.maxGclDefect);
            // 4. Boundary impulse and work (only nodes where a condition acts carry a net force).
            {
                auto v = vnode_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                auto f = fnode_;
                auto sum = KOKKOS_LAMBDA(const LO r, double (&acc)[D + 1])
                {
                    for (int d = 0; d < D; ++d)
                    {
                        acc[d] += f(r, d);
                        acc[D] += f(r, d) * v(r, d);
                    }
                };
                double acc[D + 1];
                sumReduce<D + 1>("unilag::diagnostics::boundary", m_.nOwnedNodes, sum, acc);
                allSum(comm_, acc);
                for (int d = 0; d < D; ++d)
                    impulse[d] += dt * acc[d];
                work += dt * acc[D];
            }
            {
                ScopedTimer timer(timers_.halo);
                auto owned = stateNew_->offsetViewNonConst(dm.cellMap, 0);
                stateNew_->doImport(*owned, *dm.cellImporter, Tpetra::INSERT);
            }
            std::swap(state_, stateNew_);
            std::swap(x_, xNew_);
            std::swap(geom_, geomNew_); // owned cells: written by the update; ghosts are computed here
            t += dt;
            dtPrev = dt;
            ++step;
            refreshGeometry(m_.nOwnedCells);
            computeAux();

            if (t >= nextOutput * (1.0 - 1e-12) && t < tEnd * (1.0 - 1e-14))
            {
                if (writer)
                    dump(*writer, dumps++, t);
                nextOutput = scene_.outputInterval > 0 ? nextOutput + scene_.outputInterval : tEnd;
            }
            if (options_.progress && rank_ == 0)
            {
                const auto now = Clock::now();
                const double since = std::chrono::duration<double>(now - lastReport).count();
                if ((tty && since > 0.2) || since > 5.0)
                {
                    const double el = std::chrono::duration<double>(now - wall0).count();
                    const double eta = el * (tEnd - t) / std::max(t, 1e-300);
                    std::printf("%sstep %ld  t %.6g  dt %.3g  %5.1f%%  ETA %.0fs%s", tty ? "\r" : "", step, t, dt,
                                100.0 * t / tEnd, eta, tty ? "   " : "\n");
                    std::fflush(stdout);
                    lastReport = now;
                }
            }
        }
        if (options_.progress && rank_ == 0 && tty)
            std::printf("\n");
        const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();
        if (failure.empty() && writer)
            dump(*writer, dumps++, t);

        // Conservation: mass from the geometry (GCL), momentum and energy net of boundary impulse and work.
        double final_[D + 3];
        totals(final_);
        const double massChange = std::abs(final_[0] - initial[0]) / initial[0];
        double dp = 0.0;
        for (int d = 0; d < D; ++d)
            dp += std::pow(final_[1 + d] - initial[1 + d] - impulse[d], 2);
        // relative to the momentum in play: sum m|v|, or for a body nearly at rest sqrt(2 M E), the momentum its
        // energy could give it (the forces whose round-off this measures scale with it)
        const double momentumScale =
            std::max(final_[2 + D] + initial[2 + D], std::sqrt(2.0 * initial[0] * std::abs(initial[1 + D])));
        const double momentumChange = std::sqrt(dp) / std::max(momentumScale, 1e-300);
        // relative to the largest energy in play (a body at rest hit by a piston starts with none)
        const double energyScale = std::max({std::abs(initial[1 + D]), std::abs(final_[1 + D]), std::abs(work)});
        const double energyChange = std::abs(final_[1 + D] - initial[1 + D] - work) / std::max(energyScale, 1e-300);

        // Exact solution.
        double l1 = -1.0, shock = -1.0;
        double exactShock = scene_.exactShockRadius;
        if (scene_.exactSolution == "sedov" && failure.empty())
        {
            // Self-similar: R(t) = R(t_table) (t / t_table)^alpha, alpha = 2 / (d + 2) (Sedov, planar energy release
            // in d dimensions); the profile is a function of r / R(t).
            const RadialProfile exact(scene_.exactTable);
            const double scale = std::pow(t / scene_.exactTime, 2.0 / (D + 2.0));
            l1 = radialL1Density(exact, 1.0 / scale);
            shock = shockRadius(exact);
            exactShock *= scale;
        }

        const std::vector<double> radii = boundaryRadii();

        const GO cells = dm.nGlobalCells, nodes = dm.nGlobalNodes;
        const double cellSteps = double(cells) * double(step) / std::max(wall, 1e-300);
        std::ostringstream js;
        js << "{\n  \"scene\": \"" << scene_.file << "\",\n  \"title\": \"" << scene_.name << "\",\n"
           << "  \"status\": \"" << (failure.empty() ? "completed" : "unstable") << "\",\n"
           << "  \"dimension\": " << D << ",\n  \"cells\": " << cells << ",\n  \"nodes\": " << nodes << ",\n"
           << "  \"ranks\": " << size_ << ",\n  \"threads\": " << options_.threads << ",\n"
           << "  \"steps\": " << step << ",\n  \"retries\": " << retries << ",\n"
           << "  \"physics\": {\"strain\": " << (P::strain ? "true" : "false")
           << ", \"plastic\": " << (P::plastic ? "true" : "false") << ", \"heat\": " << (P::heat ? "true" : "false")
           << "},\n"
           << "  \"picard_iterations\": {\"mean\": " << jsonNumber(step > 0 ? double(picardTotal_) / step : 0.0)
           << ", \"max\": " << picardMax_ << "},\n"
           << "  \"t_final\": " << jsonNumber(t) << ",\n  \"wall_seconds\": " << jsonNumber(wall) << ",\n"
           << "  \"cell_steps_per_second\": " << jsonNumber(cellSteps) << ",\n"
           << "  \"mass_relative_change\": " << jsonNumber(massChange) << ",\n"
           << "  \"momentum_relative_change\": " << jsonNumber(momentumChange) << ",\n"
           << "  \"energy_relative_change\": " << jsonNumber(energyChange) << ",\n"
           << "  \"max_gcl_defect\": " << jsonNumber(maxGcl) << ",\n"
           << "  \"boundary_work\": " << jsonNumber(work) << ",\n";
        if (l1 >= 0.0)
            js << "  \"l1_density_error\": " << jsonNumber(l1) << ",\n  \"shock_radius\": " << jsonNumber(shock)
               << ",\n  \"exact_shock_radius\": " << jsonNumber(exactShock) << ",\n";
        js << "  \"boundary_mean_radius\": {";
        for (std::size_t g = 0; g < radii.size(); ++g)
            js << (g ? ", " : "") << "\"" << dm.boundaryNames[g] << "\": " << jsonNumber(radii[g]);
        js << "},\n";
        js << "  \"time_share\": {\"geometry\": " << jsonNumber(timers_.geometry / wall)
           << ", \"nodal_solve\": " << jsonNumber(timers_.nodal / wall)
           << ", \"reconstruction\": " << jsonNumber(timers_.recon / wall)
           << ", \"strain_update\": " << jsonNumber(timers_.strain / wall)
           << ", \"heat_fluxes\": " << jsonNumber(timers_.heat / wall)
           << ", \"cell_update\": " << jsonNumber(timers_.update / wall)
           << ", \"halo\": " << jsonNumber(timers_.halo / wall) << ", \"io\": " << jsonNumber(timers_.io / wall)
           << "},\n";
        if (!failure.empty())
        {
            std::string f = failure;
            std::replace(f.begin(), f.end(), '"', '\'');
            js << "  \"failure\": \"" << f << "\",\n";
        }
        js << "  \"output\": \"" << (writer ? writer->collectionPath() : std::string()) << "\"\n}\n";
        if (rank_ == 0)
        {
            std::ofstream(outDir / "summary.json") << js.str();
            std::printf("unilag: %s %dD, %lld cells, %d rank(s) x %d thread(s): %ld steps to t = %.6g in %.3g s "
                        "(%.3g cell-steps/s); mass %.1e, momentum %.1e, energy %.1e",
                        scene_.name.c_str(), D, (long long)cells, size_, options_.threads, step, t, wall, cellSteps,
                        massChange, momentumChange, energyChange);
            if (P::strain)
                std::printf("; Picard %.2f mean, %d max", step > 0 ? double(picardTotal_) / step : 0.0, picardMax_);
            if (l1 >= 0.0)
                std::printf("; L1(density) %.4g, shock radius %.4g", l1, shock);
            std::printf("\nunilag: output in %s\n", (writer ? writer->collectionPath() : outDir.string()).c_str());
        }
        if (!failure.empty())
        {
            if (rank_ == 0)
                std::fprintf(stderr, "unilag: error: the run went unstable: %s\n", failure.c_str());
            return ExitUnstable;
        }
        if (options_.check)
            return selfCheck(massChange, momentumChange, energyChange, maxGcl, l1, shock, exactShock, radii);
        return ExitOk;
    }

  private:
    //! EOS, signal speeds, temperature and sigma^n (into sigma_) for all local cells.
    void computeAux()
    {
        ScopedTimer timer(timers_.nodal);
        auto s = state_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        Field sigma;
        if constexpr (P::strain)
            sigma = sigma_->getLocalViewDevice(Tpetra::Access::OverwriteAll);
        computeEos<D, P>(s, cellMaterial_, materials_, aux_, m_.nCells, sigma);
    }

    /*! First Picard iterate of a step, by linear extrapolation in time of the previous fixed points (the steps grow by
     *  at most 10%), which saves one or two iterations; the fixed point does not depend on it. Kept in sigma0_ for a
     *  retry. On all local cells, so ghosts need no exchange.
     *   - first order: sigma^0 = 2 sigma^n - sigma^{n-1} (sigma_ holds sigma^n, from computeAux);
     *   - second order, the predictor: sigma^0 = 2 s^{n-1/2} - s^{n-3/2} with s the previous predictors' fixed points
     *     (notePredictorStress). Extrapolating sigma^n instead starts about 1e-4 rho a^2 away on the Be shell (the
     *     first-order predictor and the second-order state differ by the scheme's truncation error), which cost
     *     8-18 iterations instead of 2. */
    void startPicard(long step, bool order2)
    {
        auto sigma = sigma_->getLocalViewDevice(Tpetra::Access::ReadWrite);
        auto prev = sigmaPrev_->getLocalViewDevice(Tpetra::Access::ReadWrite);
        if (order2)
        {
            if (step >= 1)
            {
                auto prev2 = sigmaPrev2_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                const bool extrapolate = step >= 2;
                auto start = KOKKOS_LAMBDA(const LO i)
                {
                    for (int c = 0; c < 6; ++c)
                        sigma(i, c) = extrapolate ? 2.0 * prev(i, c) - prev2(i, c) : prev(i, c);
                };
                Kokkos::parallel_for("unilag::gpr::picard_start", range(m_.nCells), start);
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
            Kokkos::parallel_for("unilag::gpr::picard_start", range(m_.nCells), start);
        }
        Tpetra::deep_copy(*sigma0_, *sigma_);
    }

    //! Second order: keep the accepted predictor's fixed point (sigma_) and the one before, for startPicard.
    void notePredictorStress()
    {
        std::swap(sigmaPrev2_, sigmaPrev_);
        Tpetra::deep_copy(*sigmaPrev_, *sigma_);
    }

    //! Device views of a step's arrays: positions at t^n and new ones, node velocities, the state and the new state.
    struct StepViews
    {
        ConstField x;
        Field xn;
        ConstField v, s;
        Field sn;
    };
    StepViews stepViews()
    {
        return {x_->getLocalViewDevice(Tpetra::Access::ReadOnly), xNew_->getLocalViewDevice(Tpetra::Access::ReadWrite),
                vnode_->getLocalViewDevice(Tpetra::Access::ReadOnly), state_->getLocalViewDevice(Tpetra::Access::ReadOnly),
                stateNew_->getLocalViewDevice(Tpetra::Access::ReadWrite)};
    }

    //! Imposed boundary pressures at time t (scene expressions of t).
    void setBoundaryTime(double t)
    {
        if (pressureLaws_.empty())
            return;
        for (auto& [g, law] : pressureLaws_)
            bcValueHost_(g, 0) = (*law)(0.0, 0.0, 0.0, t);
        Kokkos::deep_copy(bcValue_, bcValueHost_);
    }

    //! The global extrema of a cell update's checks. Collective.
    UpdateCheck reduceCheck(UpdateCheck check)
    {
        double ext[3] = {-check.minVolumeRatio, -check.minSound2, check.maxGclDefect};
        MPI_Allreduce(MPI_IN_PLACE, ext, 3, MPI_DOUBLE, MPI_MAX, comm_);
        check.minVolumeRatio = -ext[0];
        check.minSound2 = -ext[1];
        check.maxGclDefect = ext[2];
        return check;
    }

    /*! Corrector of a second-order step (midpoint rule): the predictor has left Q^{n+1/2} in stateNew_ (owned cells),
     *  the positions x^{n+1/2} in xNew_ (all local nodes) and the geometry of the owned cells in geomNew_. Completes
     *  the midpoint state on the ghosts, reconstructs (limited gradients, exchanged), solves the nodes with the
     *  reconstructed midpoint values at t^n + dt/2, and updates Q^n over dt with those fluxes: x^{n+1} = x^n + dt v_r,
     *  G_e from G^n with the midpoint transport and an implicit relaxation over dt, heat fluxes of the midpoint state.
     *  The result is in stateNew_, xNew_, geomNew_ as after a first-order step. Collective; false (with a message in
     *  failure) if the G_e update finds an inadmissible cell, and check tells whether the update is admissible. */
    bool corrector(double t, double dt, UpdateCheck& check, std::string& failure)
    {
        const auto& dm = *mesh_;
        std::swap(stateMid_, stateNew_);
        std::swap(xMid_, xNew_);
        std::swap(geomMid_, geomNew_);
        {
            ScopedTimer timer(timers_.halo);
            auto owned = stateMid_->offsetViewNonConst(dm.cellMap, 0);
            stateMid_->doImport(*owned, *dm.cellImporter, Tpetra::INSERT);
        }
        auto xm = xMid_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        auto sm = stateMid_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        {
            ScopedTimer timer(timers_.geometry);
            computeGeometry<D>(m_, xm, geomMid_, m_.nCells, m_.nOwnedCells);
        }
        {
            ScopedTimer timer(timers_.nodal);
            computeEos<D, P>(sm, cellMaterial_, materials_, auxMid_, m_.nCells, sigmaMid_);
        }
        setBoundaryTime(t + 0.5 * dt);
        {
            ScopedTimer timer(timers_.recon);
            auto g = grad_->getLocalViewDevice(Tpetra::Access::ReadWrite);
            limitedGradients<D, P>(m_, sm, auxMid_, sigmaMid_, geomMid_, xm, g, bc_, limiter_);
        }
        {
            ScopedTimer timer(timers_.halo);
            auto owned = grad_->offsetViewNonConst(dm.cellMap, 0);
            grad_->doImport(*owned, *dm.cellImporter, Tpetra::INSERT);
        }
        auto grad = grad_->getLocalViewDevice(Tpetra::Access::ReadOnly);
        const Reconstruction<D> rec{grad, xm, geomMid_.centroid};
        if constexpr (P::heat)
        {
            ScopedTimer timer(timers_.heat);
            heatFluxes<D, P>(m_, bc_, sm, auxMid_, geomMid_, cellMaterial_, materials_, heatRateMid_);
        }
        {
            ScopedTimer timer(timers_.nodal);
            auto v = vnode_->getLocalViewDevice(Tpetra::Access::ReadWrite);
            nodalSolve<D, P>(m_, bc_, sm, auxMid_, geomMid_, v, fnode_, sigmaMid_, rec);
        }
        {
            ScopedTimer timer(timers_.halo);
            auto owned = vnode_->offsetViewNonConst(mesh_->nodeMap, 0);
            vnode_->doImport(*owned, *mesh_->nodeImporter, Tpetra::INSERT);
        }
        const StepViews w = stepViews();
        const auto &x = w.x, &v = w.v, &s = w.s;
        const auto &xn = w.xn, &sn = w.sn;
        moveNodes(x, v, dt, xn, m_.nNodes, D);
        if constexpr (P::strain)
        {
            PicardCheck pc;
            {
                ScopedTimer timer(timers_.strain);
                auto snext = sigmaNext_->getLocalViewDevice(Tpetra::Access::ReadWrite);
                pc = strainUpdate<D, P>(m_, s, aux_, geom_, mass_, cellMaterial_, materials_, xn, v, dt, sigmaMid_,
                                        snext, sn, plasticHintCorrector_, sm, geomMid_);
            }
            double bad = pc.badCell >= 0 ? 1.0 : 0.0;
            MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_DOUBLE, MPI_MAX, comm_);
            if (bad > 0.0)
            {
                const std::string local = pc.badCell >= 0 ? "cell " + std::to_string(dm.cellGid[pc.badCell]) +
                                                                " became inadmissible (inverted, or G_e not positive "
                                                                "definite) in the corrector with dt " + jsonNumber(dt)
                                                          : std::string();
                failure = firstMessage(comm_, local);
                return false;
            }
        }
        ScopedTimer timer(timers_.update);
        check = reduceCheck(updateCells<D, P>(m_, s, aux_, geom_, mass_, cellMaterial_, materials_, x, xn, v, dt, sn,
                                              ConstField(), heatRateMid_, geomNew_,
                                              CellFlux<D>{sm, auxMid_, sigmaMid_, geomMid_, rec}));
        return true;
    }

    //! Nodal solve at owned nodes with T = -p^n I + sigma_ (strain), then node velocities to all local nodes.
    void solveNodes()
    {
        {
            ScopedTimer timer(timers_.nodal);
            auto s = state_->getLocalViewDevice(Tpetra::Access::ReadOnly);
            auto v = vnode_->getLocalViewDevice(Tpetra::Access::ReadWrite);
            ConstField sigma;
            if constexpr (P::strain)
                sigma = sigma_->getLocalViewDevice(Tpetra::Access::ReadOnly);
            nodalSolve<D, P>(m_, bc_, s, aux_, geom_, v, fnode_, sigma);
        }
        ScopedTimer timer(timers_.halo);
        auto owned = vnode_->offsetViewNonConst(mesh_->nodeMap, 0);
        vnode_->doImport(*owned, *mesh_->nodeImporter, Tpetra::INSERT);
    }

    /*! Picard loop of gpr.md 2.4 for a step dt: vnode_ holds the nodal solution for sigma_ = sigma^0. Each
     *  iteration moves the nodes, updates G_e implicitly (strainUpdate, G^{l+1} into stateNew_) and, unless the
     *  stress has converged, solves the nodes again with sigma^{l+1}. On success vnode_ and sigma_ are the
     *  consistent pair the cell update needs (the forces at each node then balance exactly). Collective. */
    bool picard(double dt, int& iterations, std::string& failure)
    {
        const auto& dm = *mesh_;
        double change = 0.0, prevChange = 0.0, omega = 1.0;
        for (int l = 0; l < scene_.picardMaxIterations; ++l)
        {
            iterations = l + 1;
            PicardCheck pc;
            {
                ScopedTimer timer(timers_.strain);
                const StepViews w = stepViews();
                const auto &x = w.x, &v = w.v, &s = w.s;
                const auto &xn = w.xn, &sn = w.sn;
                auto so = sigma_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                auto snext = sigmaNext_->getLocalViewDevice(Tpetra::Access::ReadWrite);
                moveNodes(x, v, dt, xn, m_.nNodes, D);
                pc = strainUpdate<D, P>(m_, s, aux_, geom_, mass_, cellMaterial_, materials_, xn, v, dt, so, snext, sn,
                                        plasticHint_);
            }
            double ext[3] = {pc.maxChange, -pc.minVolumeRatio, pc.badCell >= 0 ? 1.0 : 0.0};
            MPI_Allreduce(MPI_IN_PLACE, ext, 3, MPI_DOUBLE, MPI_MAX, comm_);
            change = ext[0];
            if (ext[2] > 0.0 || !(-ext[1] > 0.0))
            {
                std::string local;
                if (pc.badCell >= 0)
                    local = "cell " + std::to_string(dm.cellGid[pc.badCell]) + " became inadmissible (inverted, or G_e not "
                            "positive definite) in Picard iteration " + std::to_string(l + 1) + " with dt " +
                            jsonNumber(dt);
                failure = firstMessage(comm_, local);
                return false;
            }
            if (change <= scene_.picardTolerance)
                return true;
            if (l + 1 == scene_.picardMaxIterations)
                break;
            // Damping. The iteration map sigma -> v(sigma) -> sigma' has the Jacobian -K C^T M^{-1} C (K the
            // stiffness dt rho c_sh^2, C the corner vectors, M the nodal impedance matrices): real eigenvalues in
            // [-kappa, 0], kappa ~ CFL (c_sh / a)^2 times a mesh factor, which can exceed 1 on fine meshes. Plain
            // Picard then diverges; sigma <- sigma + omega (sigma' - sigma) with omega = 2 / (2 + kappa) contracts by
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
                auto so = sigma_->getLocalViewDevice(Tpetra::Access::ReadOnly);
                auto snext = sigmaNext_->getLocalViewDevice(Tpetra::Access::ReadWrite);
                const double w = omega;
                auto damp = KOKKOS_LAMBDA(const LO i)
                {
                    for (int c = 0; c < 6; ++c)
                        snext(i, c) = so(i, c) + w * (snext(i, c) - so(i, c));
                };
                Kokkos::parallel_for("unilag::gpr::picard_damping", range(m_.nOwnedCells), damp);
            }
            std::swap(sigma_, sigmaNext_);
            {
                ScopedTimer timer(timers_.halo);
                auto owned = sigma_->offsetViewNonConst(dm.cellMap, 0);
                sigma_->doImport(*owned, *dm.cellImporter, Tpetra::INSERT);
            }
            solveNodes();
        }
        failure = "the Picard loop did not converge in " + std::to_string(scene_.picardMaxIterations) +
                  " iterations (relative stress change " + jsonNumber(change) + " > tolerance " +
                  jsonNumber(scene_.picardTolerance) + ", last dt " + jsonNumber(dt) + ")";
        return false;
    }

    //! One line per accepted step in steps.csv (rank 0): time, dt, Picard iterations, dt halvings.
    void stepLog(long step, double t, double dt, int iterations, int halvings)
    {
        if (steps_)
            *steps_ << step << ',' << std::setprecision(12) << t << ',' << dt << ',' << iterations << ',' << halvings
                    << '\n';
    }

    std::string diagnose(const UpdateCheck& check, double t, double dt, int attempts)
    {
        std::string local;
        if (check.worstCell >= 0)
        {
            const auto& dm = *mesh_;
            const LO i = check.worstCell;
            auto sn = stateNew_->getLocalViewHost(Tpetra::Access::ReadOnly);
            auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.volume);
            std::ostringstream os;
            double c[3] = {0, 0, 0};
            for (int k = 0; k < D + 1; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += dm.coords0[3 * dm.cellNodesHost[(D + 1) * i + k] + d] / (D + 1);
            double kin = 0.0;
            for (int d = 0; d < D; ++d)
                kin += 0.5 * sn(i, S::vel + d) * sn(i, S::vel + d);
            os << "cell " << dm.cellGid[i] << " (initial centroid " << c[0] << ", " << c[1] << ", " << c[2]
               << ") at t = " << t << " after " << attempts << " halvings of dt (last dt " << dt
               << "): volume ratio " << check.minVolumeRatio << ", specific internal energy "
               << sn(i, S::energy) - kin << ", density " << 1.0 / sn(i, S::omega) << ", volume " << vol(i);
            local = os.str();
        }
        return firstMessage(comm_, local);
    }

    //! The time step has collapsed: report the smallest cell (the mesh is tangling there).
    std::string collapse(double t, double dt, long step)
    {
        const auto& dm = *mesh_;
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.volume);
        struct
        {
            double v;
            int rank;
        } mine{1e300, rank_}, global;
        LO cell = -1;
        for (LO i = 0; i < dm.nOwnedCells; ++i)
            if (vol(i) < mine.v)
            {
                mine.v = vol(i);
                cell = i;
            }
        MPI_Allreduce(&mine, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm_);
        std::string local;
        if (rank_ == global.rank && cell >= 0)
        {
            std::ostringstream os;
            os << "the time step collapsed to " << dt << " at t = " << t << " (step " << step
               << "); the smallest cell is " << dm.cellGid[cell] << " with volume " << vol(cell)
               << ": the mesh is tangling there";
            local = os.str();
        }
        return firstMessage(comm_, local);
    }

    int selfCheck(double massChange, double momentumChange, double energyChange, double gcl, double l1, double shock,
                  double exactShock, const std::vector<double>& radii)
    {
        std::vector<std::string> fails;
        auto bound = [&](const char* what, double value, double limit) {
            if (!(value <= limit))
            {
                std::ostringstream os;
                os << what << " = " << value << " exceeds " << limit;
                fails.push_back(os.str());
            }
        };
        // Round-off bounds: everything is conservative by construction.
        bound("mass relative change", massChange, 1e-12);
        bound("momentum relative change", momentumChange, 1e-12);
        bound("energy relative change", energyChange, 1e-12);
        bound("GCL defect |m omega - |T|| / |T|", gcl, 1e-12);
        if (scene_.maxL1Density > 0.0)
            bound("L1(density) error", l1, scene_.maxL1Density);
        if (scene_.shockRadiusTolerance > 0.0)
            bound("relative shock radius error", std::abs(shock - exactShock) / exactShock,
                  scene_.shockRadiusTolerance);
        if (scene_.radiusTolerance > 0.0)
            for (const auto& [group, exact] : scene_.boundaryRadius)
            {
                const auto& names = mesh_->boundaryNames;
                const auto it = std::find(names.begin(), names.end(), group);
                const double r = it == names.end() ? -1.0 : radii[it - names.begin()];
                bound(("relative error of the mean radius of '" + group + "'").c_str(), std::abs(r - exact) / exact,
                      scene_.radiusTolerance);
            }
        if (rank_ == 0)
        {
            for (const auto& f : fails)
                std::fprintf(stderr, "unilag: check failed: %s\n", f.c_str());
            if (fails.empty())
                std::printf("unilag: check passed\n");
        }
        return fails.empty() ? ExitOk : ExitCheck;
    }

    //! Mean distance from the origin of the nodes of each boundary group (shell radii: Kidder, beryllium shell).
    std::vector<double> boundaryRadii()
    {
        const auto& dm = *mesh_;
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
        auto xh = x_->getLocalViewHost(Tpetra::Access::ReadOnly);
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
        MPI_Allreduce(MPI_IN_PLACE, acc.data(), 2 * ng, MPI_DOUBLE, MPI_SUM, comm_);
        std::vector<double> radii(ng);
        for (int g = 0; g < ng; ++g)
            radii[g] = acc[2 * g + 1] > 0 ? acc[2 * g] / acc[2 * g + 1] : 0.0;
        return radii;
    }

    //! Volume-weighted mean |rho - rho_exact(|centroid|)| over the domain.
    double radialL1Density(const RadialProfile& exact, double radiusScale)
    {
        auto [r, rho, vol] = cellRadii();
        double acc[2] = {0.0, 0.0};
        for (std::size_t i = 0; i < r.size(); ++i)
        {
            acc[0] += vol[i] * std::abs(rho[i] - exact.density(radiusScale * r[i]));
            acc[1] += vol[i];
        }
        allSum(comm_, acc);
        return acc[0] / acc[1];
    }

    //! Radius where the shell-averaged density falls to half-way between its peak and the ambient value.
    double shockRadius(const RadialProfile& exact)
    {
        auto [r, rho, vol] = cellRadii();
        double hsum[2] = {0.0, double(r.size())};
        {
            auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.length);
            for (LO i = 0; i < m_.nOwnedCells; ++i)
                hsum[0] += len(i);
        }
        allSum(comm_, hsum);
        const double width = 2.0 * hsum[0] / hsum[1];
        double rmax = 0.0;
        for (double x : r)
            rmax = std::max(rmax, x);
        rmax = -allMin(comm_, -rmax);
        const int nb = int(rmax / width) + 1;
        std::vector<double> bins(2 * nb, 0.0);
        for (std::size_t i = 0; i < r.size(); ++i)
        {
            const int b = std::min(nb - 1, int(r[i] / width));
            bins[2 * b] += vol[i] * rho[i];
            bins[2 * b + 1] += vol[i];
        }
        MPI_Allreduce(MPI_IN_PLACE, bins.data(), 2 * nb, MPI_DOUBLE, MPI_SUM, comm_);
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

    std::tuple<std::vector<double>, std::vector<double>, std::vector<double>> cellRadii()
    {
        const auto& dm = *mesh_;
        auto xh = x_->getLocalViewHost(Tpetra::Access::ReadOnly);
        auto sh = state_->getLocalViewHost(Tpetra::Access::ReadOnly);
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.volume);
        std::vector<double> r(dm.nOwnedCells), rho(dm.nOwnedCells), v(dm.nOwnedCells);
        for (LO i = 0; i < dm.nOwnedCells; ++i)
        {
            double c[3] = {0, 0, 0};
            for (int k = 0; k < D + 1; ++k)
                for (int d = 0; d < D; ++d)
                    c[d] += xh(dm.cellNodesHost[(D + 1) * i + k], d) / (D + 1);
            r[i] = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            rho[i] = 1.0 / sh(i, S::omega);
            v[i] = vol(i);
        }
        return {r, rho, v};
    }

    void dump(io::XdmfWriter& writer, int index, double t)
    {
        ScopedTimer timer(timers_.io);
        const auto& dm = *mesh_;
        const LO n = dm.nOwnedCells;
        auto xh = x_->getLocalViewHost(Tpetra::Access::ReadOnly);
        auto sh = state_->getLocalViewHost(Tpetra::Access::ReadOnly);
        auto ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), aux_);
        auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom_.volume);
        std::vector<double> coords(3 * std::size_t(dm.nOwnedNodes), 0.0);
        for (LO r = 0; r < dm.nOwnedNodes; ++r)
            for (int d = 0; d < D; ++d)
                coords[3 * r + d] = xh(r, d);
        std::vector<double> rho(n), p(n), vel(3 * std::size_t(n), 0.0), eps(n), volume(n), part(n, rank_), gid(n);
        for (LO i = 0; i < n; ++i)
        {
            rho[i] = 1.0 / sh(i, S::omega);
            p[i] = ah(i, Aux::pressure);
            double kin = 0.0;
            for (int d = 0; d < D; ++d)
            {
                vel[3 * i + d] = sh(i, S::vel + d);
                kin += 0.5 * vel[3 * i + d] * vel[3 * i + d];
            }
            eps[i] = sh(i, S::energy) - kin;
            volume[i] = vol(i);
            gid[i] = double(dm.cellGid[i]);
        }
        std::vector<io::CellField> fields{{"density", 1, rho.data()},
                                          {"pressure", 1, p.data()},
                                          {"velocity", 3, vel.data()},
                                          {"specific_internal_energy", 1, eps.data()},
                                          {"volume", 1, volume.data()},
                                          {"rank", 1, part.data()},
                                          {"global_id", 1, gid.data()}};
        std::vector<double> mises, gdet, gdev, gten, theta, jvec;
        if constexpr (P::strain)
        {
            // von Mises stress (plastic maps), det G_e and the G_e anisotropy |dev G| / tr G
            auto sg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sigma_->getLocalViewDevice(Tpetra::Access::ReadOnly));
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

    const Scene& scene_;
    const Limiter limiter_ = scene_.limiter == "none"           ? Limiter::None
                             : scene_.limiter == "vertex_based" ? Limiter::VertexBased
                                                                : Limiter::BarthJespersen;
    std::shared_ptr<DistributedMesh> mesh_;
    RunOptions options_;
    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    MeshView<D> m_;
    Teuchos::RCP<MV> state_, stateNew_, x_, xNew_, vnode_;
    Teuchos::RCP<MV> sigma_, sigmaNext_, vnode0_; //!< strain: Picard stress iterates, nodal solution for sigma^0
    Teuchos::RCP<MV> sigmaPrev_, sigma0_;         //!< strain: sigma^{n-1}; the first iterate sigma^0
    Teuchos::RCP<MV> sigmaPrev2_;                 //!< strain, second order: the predictor's fixed point before last
    Teuchos::RCP<MV> stateMid_, xMid_, grad_;     //!< second order: midpoint state and positions, limited gradients
    CellGeometry geomMid_;                        //!< second order: midpoint geometry
    Field auxMid_, sigmaMid_, heatRateMid_;       //!< second order: EOS, shear stress and heat fluxes at the midpoint
    Field fnode_, aux_;
    Field heatRate_; //!< heat: m dE/dt and m dJ/dt of the fluxes at t^n (owned cells)
    View<double*> plasticHint_; //!< plastic: each owned cell's last plastic-flow parameter (warm start)
    View<double*> plasticHintCorrector_; //!< plastic, second order: the same for the corrector (a step twice as long)
    long picardTotal_ = 0;
    int picardMax_ = 0;
    std::unique_ptr<std::ofstream> steps_;
    CellGeometry geom_, geomNew_;
    View<double*> mass_;
    View<int*> cellMaterial_;
    View<const Material*> materials_;
    BoundaryView bc_;
    Kokkos::View<double* [3], MemSpace> bcValue_;                           //!< bc_.value, writable
    Kokkos::View<double* [3], MemSpace>::HostMirror bcValueHost_;
    std::vector<std::pair<int, std::unique_ptr<Expression>>> pressureLaws_; //!< time-dependent imposed pressures
    Timers timers_;
};

template <int D, class P>
int runPhysics(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options, MPI_Comm comm)
{
    GprSolver<D, P> solver(scene, mesh, options);
    const std::string error = solver.initialize();
    int rank;
    MPI_Comm_rank(comm, &rank);
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    // Only now, with the input fully validated, does anything get written.
    if (rank == 0)
    {
        fs::create_directories(scene.outputDirectory);
        writeScene(scene, (fs::path(scene.outputDirectory) / "scene.yaml").string());
    }
    MPI_Barrier(comm);
    return solver.run();
}

/*! The physics variant a scene needs, from its materials: G_e where some material has shear stiffness, the
 *  plasticity law where some material uses it, J where some material conducts heat. */
template <int D>
int runDim(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options, MPI_Comm comm)
{
    bool strain = false, plastic = false, heat = false;
    for (const auto& [name, spec] : scene.materials)
    {
        strain |= spec.strainLaw != "fluid";
        plastic |= spec.strainLaw == "plastic";
        heat |= spec.heatConduction;
    }
    if (plastic)
        return heat ? runPhysics<D, Physics<true, true, true>>(scene, mesh, options, comm)
                    : runPhysics<D, Physics<true, true, false>>(scene, mesh, options, comm);
    if (strain)
        return heat ? runPhysics<D, Physics<true, false, true>>(scene, mesh, options, comm)
                    : runPhysics<D, Physics<true, false, false>>(scene, mesh, options, comm);
    return heat ? runPhysics<D, Physics<false, false, true>>(scene, mesh, options, comm)
                : runPhysics<D, PhysicsHydro>(scene, mesh, options, comm);
}

} // namespace

int runScene(const Scene& scene, const RunOptions& options, const Teuchos::RCP<const Comm>& comm)
{
    MPI_Comm mpi = rawComm(comm);
    int rank;
    MPI_Comm_rank(mpi, &rank);
    GlobalMesh global;
    std::string error;
    if (rank == 0)
    {
        try
        {
            global = loadMesh(scene);
        }
        catch (const InputError& e)
        {
            error = e.what();
        }
    }
    error = firstMessage(mpi, error);
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    auto mesh = DistributedMesh::distribute(global, comm);
    global = GlobalMesh();
    return mesh->dim == 2 ? runDim<2>(scene, mesh, options, mpi) : runDim<3>(scene, mesh, options, mpi);
}

} // namespace unilag
