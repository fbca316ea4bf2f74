/*! \file SolverHarness.hpp
 *  \brief The solver's own classes on the hand-built meshes of HostMesh.hpp: a GlobalMesh from a connected HostMesh,
 *  scene pieces written in code, and a GPR model distributed on one rank and initialised from the scene. The tests
 *  drive the real operator, integrators and TimeSystem through it, so they check the solver's step sequence rather
 *  than a copy of it.
 */
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Tpetra_Core.hpp>

#include "HostMesh.hpp"
#include "mesh/GlobalMesh.hpp"
#include "solver/GprDiagnostics.hpp"
#include "solver/GprSetup.hpp"
#include "solver/GprSystem.hpp"
#include "solver/Integrators.hpp"

namespace unilag_test
{

//! A constant scene value, or a muparser expression of x, y, z, r.
inline unilag::Expr constant(double v)
{
    return unilag::Expr{"", v};
}
inline unilag::Expr expression(const std::string& text)
{
    return unilag::Expr{text, 0.0};
}

/*! A scene of one ideal gas (gamma, cv = 1) filling region "gas" with the given density, pressure and D velocity
 *  components; boundaries and order are the caller's. */
inline unilag::Scene gasScene(int dim, unilag::Expr density, unilag::Expr pressure,
                              const std::vector<unilag::Expr>& velocity, double gamma = 1.4)
{
    unilag::Scene s;
    s.file = "unit test";
    unilag::MaterialSpec gas;
    gas.eos = unilag::EosKind::IdealGas;
    gas.gamma = gamma;
    s.materials["gas"] = gas;
    unilag::RegionSpec region;
    region.material = "gas";
    region.density = std::move(density);
    region.pressure = std::move(pressure);
    region.velocityComponents = dim;
    for (int d = 0; d < dim; ++d)
        region.velocity[d] = velocity.at(d);
    s.regions["gas"] = region;
    s.writeOutput = false;
    return s;
}

inline unilag::BoundarySpec slipWall()
{
    unilag::BoundarySpec b;
    b.type = unilag::BoundaryKind::SlipWall;
    return b;
}

inline unilag::BoundarySpec imposedVelocity(const std::array<double, 3>& u)
{
    unilag::BoundarySpec b;
    b.type = unilag::BoundaryKind::Velocity;
    b.velocity = u;
    return b;
}

/*! The GPR model of a scene on a mesh distributed over the default communicator (one rank in the unit tests),
 *  initialised as a run starts it: state at t = 0, geometry and EOS current. error holds initialize's message.
 *  Not copyable or movable: the model keeps a reference to scene. */
template <int D> struct SolverHarness
{
    using P = unilag::PhysicsHydro;
    SolverHarness(unilag::Scene s, const unilag::GlobalMesh& g)
        : scene(std::move(s)), model(scene, unilag::DistributedMesh::distribute(g, Tpetra::getDefaultComm())), op(model)
    {
        error = unilag::initialize(model);
        op.refreshGeometry();
        op.computeAux();
    }
    SolverHarness(const SolverHarness&) = delete;
    SolverHarness& operator=(const SolverHarness&) = delete;

    //! A field's local rows on the host, column after column.
    std::vector<double> host(const std::string& field) const
    {
        auto h = model.fields[field].getLocalViewHost(Tpetra::Access::ReadOnly);
        return std::vector<double>(h.data(), h.data() + h.extent(0) * h.extent(1));
    }
    //! Mass, momentum, total energy, sum m|v| and the angular momentum's sums (GprDiagnostics.hpp TotalsLayout).
    std::array<double, unilag::TotalsLayout<D>::size> totals() const
    {
        std::array<double, unilag::TotalsLayout<D>::size> out;
        double t[unilag::TotalsLayout<D>::size];
        unilag::totals(model, t);
        std::copy(t, t + out.size(), out.begin());
        return out;
    }

    unilag::Scene scene;
    unilag::GprModel<D, P> model;
    unilag::GprOperator<D, P> op;
    std::string error;
};

/*! One step of the time loop (TimeLoop.cpp) on system at the stable time step, without halvings: prepareStep,
 *  beginAttempts, the first attempt and, if it is admissible, acceptStep. inspect runs between the attempt and the
 *  acceptance, where the step's node velocities and forces are those its update used. Returns dt, 0 if the attempt
 *  failed (with a test failure). */
template <int D, class P, class Inspect>
double loopStep(unilag::GprSystem<D, P>& system, double t, long step, Inspect&& inspect)
{
    const double dt = system.prepareStep(t, step);
    EXPECT_GT(dt, 0.0) << "step " << step;
    if (!(dt > 0.0))
        return 0.0;
    system.beginAttempts();
    int iterations = 0;
    const bool ok = system.attemptStep(t, dt, 0, iterations);
    EXPECT_TRUE(ok) << "step " << step << ": " << system.failure(t, dt, 0);
    if (!ok)
        return 0.0;
    inspect(dt);
    system.acceptStep(t, dt, iterations);
    return dt;
}

} // namespace unilag_test
