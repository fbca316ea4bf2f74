/*! \file GprInitialState.hpp
 *  \brief The state at t = 0: positions, geometry, the regions' density, pressure (or internal energy) and velocity
 *  at each cell's centroid, G_e at rest, J = 0, masses, materials and a point energy deposit. Included by
 *  GprSetup.hpp.
 */
#pragma once

namespace unilag
{

//! A region's initial data: constants or compiled expressions of x, y, z, r.
struct RegionFunctions
{
    explicit RegionFunctions(const RegionSpec& spec) : spec(spec)
    {
        rho = compile(spec.density);
        thermo = compile(spec.hasPressure ? spec.pressure : spec.internalEnergy);
        for (int d = 0; d < spec.velocityComponents; ++d)
            velocity[d] = compile(spec.velocity[d]);
    }
    static std::unique_ptr<Expression> compile(const Expr& e)
    {
        return e.isConstant() ? nullptr : std::make_unique<Expression>(e.text);
    }
    static double eval(const Expr& e, const std::unique_ptr<Expression>& x, const double (&c)[3])
    {
        return x ? (*x)(c[0], c[1], c[2]) : e.value;
    }
    const RegionSpec& spec;
    std::unique_ptr<Expression> rho, thermo, velocity[3];
};

/*! Barycentric coordinates of the points a cell samples its region's data at with `sampling: average`: the centroids
 *  of the corner sub-simplices of its regular subdivision into 4 parts per edge, (i_k + 1 / (D + 1)) / 4 with
 *  sum_k i_k = 3: 10 points in 2D, 20 in 3D, spread evenly through the cell. */
template <int D> std::vector<std::array<double, D + 1>> samplingPoints()
{
    constexpr int n = 4;
    std::vector<std::array<double, D + 1>> points;
    for (int a = 0; a < n; ++a)
        for (int b = 0; a + b < n; ++b)
            for (int c = 0; a + b + c < n && (D == 3 || c == 0); ++c)
            {
                const int idx[4] = {a, b, c, n - 1 - a - b - c};
                std::array<double, D + 1> w;
                for (int k = 0; k < D; ++k)
                    w[k] = (idx[k] + 1.0 / (D + 1)) / n;
                w[D] = (idx[3] + (D == 2 ? idx[2] : 0) + 1.0 / (D + 1)) / n;
                points.push_back(w);
            }
    return points;
}

/*! The mean mass, momentum and total energy of the region's data over the sampling points of cell i, returned as
 *  rho, eps and v (eps = E / m - |v|^2 / 2, at least the points' mean eps: a cold gas stays at 0 up to round-off). */
template <int D, class Mesh, class Sample>
void averageSample(const Mesh& dm, LO i, const std::vector<std::array<double, D + 1>>& points,
                   Sample& sample, double& rho, double& eps, double (&v)[3])
{
    double mass = 0.0, energy = 0.0, momentum[3] = {0.0, 0.0, 0.0};
    for (const auto& w : points)
    {
        double c[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k <= D; ++k)
            for (int d = 0; d < D; ++d)
                c[d] += w[k] * dm.coords0[3 * dm.cellNodesHost[(D + 1) * i + k] + d];
        double rq, eq, vq[3];
        sample(c, rq, eq, vq);
        mass += rq;
        energy += rq * (eq + 0.5 * (vq[0] * vq[0] + vq[1] * vq[1] + vq[2] * vq[2]));
        for (int d = 0; d < 3; ++d)
            momentum[d] += rq * vq[d];
    }
    rho = mass / double(points.size());
    double kin = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        v[d] = momentum[d] / mass;
        kin += 0.5 * v[d] * v[d];
    }
    eps = std::max(energy / mass - kin, 0.0);
}

/*! Writes the initial state of the cells of region r into the state, mass and material rows (host views).
 *  Returns an error naming the key and the cell, "" if fine. */
template <int D, class P, class MatV, class SV, class MH, class VH>
std::string regionState(const GprModel<D, P>& md, std::size_t r, const MatV& mats, const SV& sh, const MH& massH,
                        const MH& matH, const VH& vol)
{
    using S = StateLayout<D, P>;
    const auto& dm = *md.mesh;
    const RegionSpec& spec = md.scene.regions.at(dm.regionNames[r]);
    const std::string key = "regions." + dm.regionNames[r] + ".";
    if (spec.velocityComponents != 0 && spec.velocityComponents != D)
        return md.scene.file + ": key '" + key + "velocity': the mesh is " + std::to_string(D) +
               "D, the velocity has " + std::to_string(spec.velocityComponents) + " components";
    const RegionFunctions f(spec);
    const int mat = int(std::distance(md.scene.materials.begin(), md.scene.materials.find(spec.material)));
    const char* thKey = spec.hasPressure ? "pressure" : "specific_internal_energy";
    const auto points = spec.average ? samplingPoints<D>() : std::vector<std::array<double, D + 1>>{};
    // "FILE: key 'K': value X at cell N REASON", REASON "is not finite" for inf and nan whatever the check
    auto keyError = [&](const std::string& k, double value, const std::string& at, const char* reason)
    {
        std::ostringstream os;
        os << md.scene.file << ": key '" << k << "': value " << std::setprecision(10) << value << at << " "
           << (std::isfinite(value) ? reason : "is not finite");
        return os.str();
    };
    for (LO i = 0; i < dm.nCells; ++i)
    {
        if (dm.cellRegion[i] != int(r))
            continue;
        // the data at one point: rho, the thermodynamic value (pressure or eps) and the velocity
        std::string error;
        auto sample = [&](const double (&c)[3], double& rho, double& eps, double (&v)[3])
        {
            rho = f.eval(spec.density, f.rho, c);
            const double th = f.eval(spec.hasPressure ? spec.pressure : spec.internalEnergy, f.thermo, c);
            const std::string at = " at cell " + std::to_string(dm.cellGid[i]);
            if (!(rho > 0.0) || !std::isfinite(rho))
                error = keyError(key + "density", rho, at, "is not positive");
            else if (!(th >= 0.0) || !std::isfinite(th))
                error = keyError(key + thKey, th, at, "is negative");
            for (int d = 0; d < 3; ++d)
            {
                v[d] = d < spec.velocityComponents && d < D ? f.eval(spec.velocity[d], f.velocity[d], c) : 0.0;
                if (error.empty() && !std::isfinite(0.5 * v[d] * v[d])) // its kinetic energy must be a number too
                    error = keyError(key + "velocity", v[d], at, "gives a kinetic energy that is not finite");
            }
            eps = error.empty() && spec.hasPressure ? gpr::internalEnergy(mats(mat).eos, rho, th) : th;
            if (error.empty() && !std::isfinite(eps))
                error = keyError(key + thKey, th, at, "gives a specific internal energy that is not finite");
        };
        double rho, eps, v[3];
        if (!spec.average)
        {
            double c[3];
            initialCentroid<D>(dm, i, c);
            sample(c, rho, eps, v);
        }
        else
            averageSample<D>(dm, i, points, sample, rho, eps, v);
        if (!error.empty())
            return error;
        double kin = 0.0;
        for (int d = 0; d < D; ++d)
        {
            sh(i, S::vel + d) = v[d];
            kin += 0.5 * v[d] * v[d];
        }
        if (!std::isfinite(eps + kin))
            return keyError(key + "velocity", std::sqrt(2.0 * kin), " at cell " + std::to_string(dm.cellGid[i]),
                            "(its speed) gives a total energy that is not finite");
        sh(i, S::omega) = 1.0 / rho;
        sh(i, S::energy) = eps + kin;
        if constexpr (P::strain)
        {
            // at rest: G_e = (rho / rho0)^{2/3} I, so det G_e = (rho / rho0)^2 (docs/gpr-model.md 1.1) and sigma = 0
            const double g = std::cbrt((rho / mats(mat).rho0) * (rho / mats(mat).rho0));
            for (int k = 0; k < 6; ++k)
                sh(i, S::G + k) = k < 3 ? g : 0.0;
        }
        if constexpr (P::heat)
            for (int d = 0; d < D; ++d)
                sh(i, S::J + d) = 0.0;
        massH(i, 0) = rho * vol(i);
        matH(i, 0) = mat;
    }
    return {};
}

/*! Why the energy deposit cannot be placed ("" if it can): its point must lie in a cell of the initial mesh (on a
 *  boundary counts; a relative 1e-9 of the cell's volume). Else the nearest node, possibly far away, would take the
 *  energy. Collective. */
template <int D, class P> std::string depositOutsideMesh(const GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    int inside = 0;
    for (LO i = 0; i < dm.nOwnedCells && !inside; ++i)
    {
        Vec<D> p[D + 1];
        for (int k = 0; k <= D; ++k)
            for (int a = 0; a < D; ++a)
                p[k][a] = dm.coords0[3 * dm.cellNodesHost[(D + 1) * i + k] + a];
        const double whole = Simplex<D>(p).volume;
        bool in = true;
        for (int k = 0; k <= D && in; ++k)
        {
            // the point replaces vertex k: a negative volume puts it outside the face opposite k
            Vec<D> q[D + 1];
            for (int m = 0; m <= D; ++m)
                q[m] = p[m];
            for (int a = 0; a < D; ++a)
                q[k][a] = md.scene.depositPosition[a];
            in = Simplex<D>(q).volume / whole >= -1e-9;
        }
        inside = in ? 1 : 0;
    }
    MPI_Allreduce(MPI_IN_PLACE, &inside, 1, MPI_INT, MPI_MAX, md.comm);
    if (inside)
        return {};
    std::string where = "[";
    for (int a = 0; a < D; ++a)
        where += (a ? ", " : "") + jsonNumber(md.scene.depositPosition[a]);
    return md.scene.file + ": key 'energy_deposit.position': " + where + "] lies outside the mesh";
}

//! Point energy deposit: into the cells around the node nearest to the point, as a uniform specific energy.
template <int D, class P, class SV, class MH>
void depositEnergy(const GprModel<D, P>& md, const SV& sh, const MH& massH)
{
    using S = StateLayout<D, P>;
    const auto& dm = *md.mesh;
    double best = 1e300;
    GO bestNode = -1;
    for (LO n = 0; n < dm.nOwnedNodes; ++n)
    {
        double d2 = 0;
        for (int d = 0; d < D; ++d)
            d2 += std::pow(dm.coords0[3 * n + d] - md.scene.depositPosition[d], 2);
        if (d2 < best || (d2 == best && dm.nodeGid[n] < bestNode))
        {
            best = d2;
            bestNode = dm.nodeGid[n];
        }
    }
    long long node = bestNode;
    MPI_Bcast(&node, 1, MPI_LONG_LONG, mpi::argMinRank(md.comm, best), md.comm);
    auto touches = [&](LO i)
    {
        for (int k = 0; k < D + 1; ++k)
            if (dm.nodeGid[dm.cellNodesHost[(D + 1) * i + k]] == node)
                return true;
        return false;
    };
    double m[1] = {0.0};
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        if (touches(i))
            m[0] += massH(i, 0);
    mpi::allSum(md.comm, m);
    for (LO i = 0; i < dm.nCells; ++i)
        if (touches(i))
            sh(i, S::energy) += md.scene.depositEnergy / m[0];
}

/*! Material::epsRoundoff of every material: 1e-14 times the problem's specific energy scale, the largest of its mean
 *  specific total energy (sum m E / sum m over the owned cells, all ranks) and what its boundaries impose: |v|^2 / 2
 *  of an imposed velocity, |p| / rho_mean of an imposed pressure or traction (a cold gas at rest has no energy until a
 *  piston drives it: a floor of 0 stopped such a run at ars222's first precursor round-off, eps = -2.5e-71). With
 *  pressure 0 a cell's internal energy E - v^2/2 is 0 only up to the round-off (and underflow) of that difference;
 *  the update must not reject it as unstable. Collective. */
template <int D, class P, class StateHost, class MassHost, class VolumeHost>
void setRoundoffFloor(GprModel<D, P>& md, const StateHost& sh, const MassHost& massH, const VolumeHost& volume)
{
    using S = StateLayout<D, P>;
    double sums[3] = {0.0, 0.0, 0.0};
    for (LO i = 0; i < md.mesh->nOwnedCells; ++i)
    {
        sums[0] += massH(i, 0) * sh(i, S::energy);
        sums[1] += massH(i, 0);
        sums[2] += volume(i);
    }
    mpi::allSum(md.comm, sums);
    double scale = sums[1] > 0.0 ? std::abs(sums[0]) / sums[1] : 0.0;
    auto type = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.bc.type);
    for (std::size_t g = 0; g < md.mesh->boundaryNames.size(); ++g)
    {
        double v2 = 0.0;
        for (int d = 0; d < D; ++d)
            v2 += md.bcValueHost(g, d) * md.bcValueHost(g, d);
        if (type(g) == BcVelocity)
            scale = std::max(scale, 0.5 * v2);
        else if ((type(g) == BcPressure || type(g) == BcTraction) && sums[1] > 0.0)
            scale = std::max(scale, (type(g) == BcPressure ? std::abs(md.bcValueHost(g, 0)) : std::sqrt(v2)) *
                                        sums[2] / sums[1]);
    }
    const double floor = 1e-14 * scale;
    View<Material*> mats("unilag::materials", md.materials.extent(0));
    auto mh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.materials);
    auto out = Kokkos::create_mirror_view(mats);
    for (std::size_t k = 0; k < mh.extent(0); ++k)
    {
        out(k) = mh(k);
        out(k).epsRoundoff = floor;
    }
    Kokkos::deep_copy(mats, out);
    md.materials = mats;
}

//! Initial conditions, masses, materials and boundary table. Returns an error message ("" if fine). Collective.
template <int D, class P> std::string initialize(GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    std::string error = setupBoundaries(md);
    if (error.empty())
        error = setupMaterials(md);
    if (!error.empty())
        return error;
    {
        auto xh = md.fields["x"].getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO n = 0; n < dm.nNodes; ++n)
            for (int d = 0; d < D; ++d)
                xh(n, d) = dm.coords0[3 * n + d];
    }
    if (!(computeGeometry<D>(md.m, md.read("x"), md.geom, dm.nCells) > 0.0))
        return "internal: a cell of the distributed mesh has non-positive volume";

    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.geom.volume);
    auto mats = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md.materials);
    auto massH = md.fields["mass"].getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto matH = md.fields["material"].getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto sh = md.fields["state"].getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t r = 0; r < dm.regionNames.size() && error.empty(); ++r)
        error = regionState(md, r, mats, sh, massH, matH, vol);
    error = mpi::firstMessage(md.comm, error);
    if (!error.empty())
        return error;
    if (md.scene.hasDeposit)
    {
        error = depositOutsideMesh(md);
        if (!error.empty())
            return error;
        depositEnergy(md, sh, massH);
    }
    auto cellMaterial = Kokkos::create_mirror_view(md.cellMaterial);
    for (LO i = 0; i < dm.nCells; ++i)
        cellMaterial(i) = int(matH(i, 0));
    Kokkos::deep_copy(md.cellMaterial, cellMaterial);
    setRoundoffFloor(md, sh, massH, vol);
    return {};
}

} // namespace unilag
