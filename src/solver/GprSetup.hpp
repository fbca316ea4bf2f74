/*! \file GprSetup.hpp
 *  \brief From a validated scene and a distributed mesh to the state at t = 0: the boundary table by group, the
 *  materials, the regions' initial states at the cell centroids (owned and ghost cells alike, so nothing needs an
 *  exchange), the masses and a point energy deposit. Every mismatch between scene and mesh is an input error.
 */
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Format.hpp"
#include "mesh/BoundaryPlanes.hpp"
#include "solver/GprModel.hpp"

namespace unilag
{

//! Kernel material data of a scene material (the scene reader has validated it).
inline Material toMaterial(const MaterialSpec& spec)
{
    Material m;
    m.eos = spec.eos == EosKind::IdealGas       ? gpr::idealGasEos(spec.gamma, spec.cv)
            : spec.eos == EosKind::MieGruneisen ? gpr::mieGruneisenEos(spec.rho0, spec.c0, spec.Gamma0, spec.s, spec.cv)
                                                : gpr::neoHookeanEos(spec.rho0, spec.csh, spec.cv);
    m.rho0 = spec.rho0;
    if (spec.strainLaw != RelaxationLaw::Fluid)
    {
        m.csh = spec.shearSpeed;
        m.strainLaw = spec.strainLaw == RelaxationLaw::Plastic ? StrainPlastic : StrainConstant;
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

//! The kernels' boundary type of a scene boundary (a symmetry plane is a slip wall).
inline int kernelBoundaryType(BoundaryKind k)
{
    switch (k)
    {
    case BoundaryKind::Velocity:
        return BcVelocity;
    case BoundaryKind::Free:
        return BcFree;
    case BoundaryKind::Pressure:
        return BcPressure;
    case BoundaryKind::Traction:
        return BcTraction;
    default:
        return BcSlipWall;
    }
}

/*! Where an imposed pressure is not a number over the run, "value nan at t = 0.25 is not finite" ("" if it is at
 *  t = 0, the end time and 1000 times between; law null: the constant value): a nan there would stop the run
 *  blaming a cell beside it. */
inline std::string pressureNotFinite(Expression* law, double value, double endTime)
{
    const int samples = law ? 1000 : 0;
    for (int k = 0; k <= samples; ++k)
    {
        const double t = samples ? endTime * k / samples : 0.0;
        const double p = law ? (*law)(0.0, 0.0, 0.0, t) : value;
        if (!std::isfinite(p))
        {
            std::ostringstream os;
            os << "value " << p << " at t = " << t << " is not finite";
            return os.str();
        }
    }
    return {};
}

//! Boundary table by group id; every group of the mesh needs a condition and every condition a group.
template <int D, class P> std::string setupBoundaries(GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    const Scene& scene = md.scene;
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
        auto it = scene.boundaries.find(dm.boundaryNames[g]);
        if (it == scene.boundaries.end())
            return scene.file + ": key 'boundaries': the mesh has a boundary group '" + dm.boundaryNames[g] +
                   "' with no condition";
        const BoundarySpec& b = it->second;
        th(g) = kernelBoundaryType(b.type);
        for (int d = 0; d < 3; ++d)
            vh(g, d) = b.type == BoundaryKind::Traction ? b.traction[d] : b.velocity[d];
        thermalH(g) = b.thermal == ThermalKind::Isothermal ? ThermalIsothermal : ThermalAdiabatic;
        md.isothermalWalls = md.isothermalWalls || b.thermal == ThermalKind::Isothermal;
        tempH(g) = b.temperature;
        if (b.type == BoundaryKind::Pressure)
        {
            vh(g, 0) = b.pressure.value;
            Expression* law = nullptr;
            if (!b.pressure.isConstant())
                law = md.pressureLaws.emplace_back(g, std::make_unique<Expression>(b.pressure.text)).second.get();
            const std::string bad = pressureNotFinite(law, b.pressure.value, scene.endTime);
            if (!bad.empty())
                return scene.file + ": key 'boundaries." + dm.boundaryNames[g] + ".pressure': " + bad;
        }
    }
    for (const auto& [name, spec] : scene.boundaries)
        if (std::find(dm.boundaryNames.begin(), dm.boundaryNames.end(), name) == dm.boundaryNames.end())
            return scene.file + ": key 'boundaries." + name + "': the mesh has no boundary group '" + name + "'";
    // slip walls and symmetry planes made of planes impose their fixed normals (wallNormal, Physics.hpp)
    Kokkos::View<double* [MaxWallPlanes][3], MemSpace> plane("unilag::bcPlane", std::max(ng, 1));
    auto ph = Kokkos::create_mirror_view(plane); // zero-initialised
    const auto planes = flatBoundaryPlanes(dm, md.comm, MaxWallPlanes);
    for (int g = 0; g < ng; ++g)
        for (std::size_t p = 0; p < planes[g].size() && th(g) == BcSlipWall; ++p)
            for (int d = 0; d < 3; ++d)
                ph(g, p, d) = planes[g][p][d];
    Kokkos::deep_copy(type, th);
    Kokkos::deep_copy(value, vh);
    Kokkos::deep_copy(thermal, thermalH);
    Kokkos::deep_copy(temperature, tempH);
    Kokkos::deep_copy(plane, ph);
    md.bc = BoundaryView{type, value, thermal, temperature, plane};
    md.markTractionNodes();
    md.bcValue = value;
    md.bcValueHost = vh;
    return {};
}

//! Materials, indexed in the order of the scene's map; every region of the mesh needs an initial state.
template <int D, class P> std::string setupMaterials(GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    const Scene& scene = md.scene;
    View<Material*> mats("unilag::materials", scene.materials.size());
    auto mh = Kokkos::create_mirror_view(mats);
    int index = 0;
    for (const auto& [name, spec] : scene.materials)
        mh(index++) = toMaterial(spec);
    Kokkos::deep_copy(mats, mh);
    md.materials = mats;
    for (const auto& name : dm.regionNames)
        if (!scene.regions.count(name))
            return scene.file + ": key 'regions': the mesh has a region '" + name + "' with no initial state";
    for (const auto& [name, spec] : scene.regions)
        if (std::find(dm.regionNames.begin(), dm.regionNames.end(), name) == dm.regionNames.end())
            return scene.file + ": key 'regions." + name + "': the mesh has no region (physical group) '" + name + "'";
    return {};
}

} // namespace unilag

#include "solver/GprInitialState.hpp"
