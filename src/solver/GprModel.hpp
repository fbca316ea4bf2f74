/*! \file GprModel.hpp
 *  \brief The discretised GPR model of one run: mesh, field set, derived cell quantities, geometry, materials and
 *  boundary table. Plain data shared by the operator (GprOperator.hpp), the set-up (GprSetup.hpp), the
 *  diagnostics and the output; the dimension D and physics variant P (Physics.hpp) are compile-time.
 *
 *  Field names (FieldSet), persistent unless said:
 *   cells  state (omega, v, E[, G_e][, J]: StateLayout), mass, material (index, as a double), sigma_prev
 *          (strain: the Picard start's history), sigma_prev2 (strain, order 2), plastic_hint (plastic: each cell's
 *          last plastic-flow parameter), plastic_hint_corrector (plastic, order 2); scratch: plastic_work (plastic:
 *          each cell's plastic-law evaluations since the last partition, the load balance's cost; plastic_rate:
 *          their rate per step over the last load-balance window, carried through repartitions), state_new, sigma
 *          (the stress iterate), sigma_next, sigma0, state_mid, gradients (midpoint),
 *          gradients_n (order 2: the state at t^n), heat_gradients, heat_gradients_n (order 2, heat: theta,
 *          eps, J of the midpoint and of t^n);
 *          ars222 (GprArs.hpp), created on first use: ars_rates0,
 *          ars_rates1 (stored stage rates), ars_strain_increment (stage 1's G_e transport increment);
 *   nodes  x (positions); scratch: x_new, v_node, v_node0, x_mid; ars222: ars_v0, ars_v1 (stage velocities).
 */
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "config/Scene.hpp"
#include "core/Mpi.hpp"
#include "core/Timers.hpp"
#include "physics/Expression.hpp"
#include "state/FieldSet.hpp"
#include "unilag/CellUpdate.hpp"
#include "unilag/Heat.hpp"

namespace unilag
{

//! One column of a field as a rank-1 device view over all local rows (mass, material index, plastic hints).
inline View<double*> column(MV& field, int c = 0)
{
    return Kokkos::subview(field.getLocalViewDevice(Tpetra::Access::ReadWrite), Kokkos::ALL(), c);
}

//! The centroid of local cell i in the initial configuration.
template <int D> void initialCentroid(const DistributedMesh& dm, LO i, double (&c)[3])
{
    c[0] = c[1] = c[2] = 0.0;
    for (int k = 0; k < D + 1; ++k)
        for (int d = 0; d < D; ++d)
            c[d] += dm.coords0[3 * dm.cellNodesHost[(D + 1) * i + k] + d] / (D + 1);
}
template <int D, class P> struct GprModel
{
    using S = StateLayout<D, P>;

    GprModel(const Scene& scene, std::shared_ptr<DistributedMesh> mesh);

    /*! The model on a new distribution of the same mesh (repartitioning): persistent fields and the scratch fields
     *  in carry move by global id, the other work arrays are reallocated empty (geometry and EOS are the caller's
     *  to recompute). Collective. */
    void remesh(std::shared_ptr<DistributedMesh> newMesh, const std::vector<std::string>& carry);
    //! m.nodeTraction from bc: the local nodes on a free, pressure or traction face (after bc is set, and remesh).
    void markTractionNodes();

    const Scene& scene;
    std::shared_ptr<DistributedMesh> mesh;
    MPI_Comm comm;
    int rank = 0, size = 1;
    MeshView<D> m;
    FieldSet fields;
    bool order2;
    Limiter limiter;
    Reconstructed reconstruct;
    bool consistentLoad; //!< scene.cornerLoad == Consistent
    std::optional<Limiter> pressureLimiter; //!< scene.pressureLimiter: the traction's own limiter, if given

    Field fnode, aux;           //!< subcell force sums at owned nodes; EOS, speeds, temperature, stress at t^n
    Field heatRate;             //!< heat: m dE/dt and m dJ/dt of the fluxes at t^n (owned cells)
    Field auxMid, sigmaMid;     //!< order 2: EOS and shear stress at the midpoint
    Field heatRateMid;          //!< order 2, heat: midpoint fluxes
    CellGeometry geom, geomNew; //!< at t^n; the next step's (owned cells, written by the update)
    CellGeometry geomMid;       //!< order 2: the midpoint configuration
    GradientScratch gradientSums; //!< order 2: the least-squares node sums (LeastSquares.hpp), reused every call
    View<int*> cellMaterial;    //!< the material field as integers, for the kernels
    View<const Material*> materials;
    BoundaryView bc;
    Kokkos::View<double* [3], MemSpace> bcValue; //!< bc.value, writable
    Kokkos::View<double* [3], MemSpace>::HostMirror bcValueHost;
    std::vector<std::pair<int, std::unique_ptr<Expression>>> pressureLaws; //!< time-dependent imposed pressures
    bool isothermalWalls = false; //!< some boundary imposes a temperature (heat then enters the energy balance)
    PhaseTimers timers;

    ConstField read(const std::string& f) const { return fields[f].getLocalViewDevice(Tpetra::Access::ReadOnly); }
    Field write(const std::string& f) const { return fields[f].getLocalViewDevice(Tpetra::Access::ReadWrite); }
    Field overwrite(const std::string& f) const { return fields[f].getLocalViewDevice(Tpetra::Access::OverwriteAll); }
    View<const double*> mass() const { return column(fields["mass"]); }
    //! Plastic variant: the warm-start hints of the predictor (or first-order step) or of the corrector.
    View<double*> plasticHint(bool corrector) const
    {
        if constexpr (!P::plastic)
            return View<double*>();
        return column(fields[corrector ? "plastic_hint_corrector" : "plastic_hint"]);
    }
    //! Plastic variant: each cell's plastic-law evaluations since the last partition (relaxPlasticStrain's work).
    View<double*> plasticWork() const
    {
        if constexpr (!P::plastic)
            return View<double*>();
        return column(fields["plastic_work"]);
    }

  private:
    //! The work arrays sized by the local mesh (not fields: never migrated nor checkpointed).
    void allocateWork();
};

template <int D, class P>
GprModel<D, P>::GprModel(const Scene& scene_, std::shared_ptr<DistributedMesh> mesh_)
    : scene(scene_), mesh(std::move(mesh_)), comm(mpi::rawComm(mesh->comm)), m(mesh->view<D>()), fields(mesh),
      order2(scene.order == 2), limiter(scene.limiter), reconstruct(scene.reconstruct),
      consistentLoad(scene.cornerLoad == CornerLoad::Consistent), pressureLimiter(scene.pressureLimiter)
{
    rank = mpi::rank(comm);
    size = mpi::size(comm);
    const auto P_ = Lifetime::Persistent, S_ = Lifetime::Scratch;
    fields.add("state", Entity::Cell, S::ncomp, P_);
    fields.add("state_new", Entity::Cell, S::ncomp, S_);
    fields.add("mass", Entity::Cell, 1, P_);
    fields.add("material", Entity::Cell, 1, P_);
    fields.add("x", Entity::Node, D, P_);
    fields.add("x_new", Entity::Node, D, S_);
    fields.add("v_node", Entity::Node, D, S_);
    if constexpr (P::strain)
    {
        for (const char* f : {"sigma", "sigma_next", "sigma0"})
            fields.add(f, Entity::Cell, 6, S_);
        fields.add("sigma_prev", Entity::Cell, 6, P_);
        if (order2)
            fields.add("sigma_prev2", Entity::Cell, 6, P_);
        if constexpr (P::plastic)
            for (const char* f : {"plastic_hint", "plastic_hint_corrector"})
                if (order2 || std::string(f) == "plastic_hint")
                {
                    fields.add(f, Entity::Cell, 1, P_);
                    Kokkos::deep_copy(column(fields[f]), std::numeric_limits<double>::quiet_NaN());
                }
        if constexpr (P::plastic)
        {
            fields.add("plastic_work", Entity::Cell, 1, S_); // the load balance's cost (GprSystem::cellCosts)
            fields.add("plastic_rate", Entity::Cell, 1, S_); // its last window's rate per step (predictedTimes)
        }
    }
    if (P::strain || order2)
        fields.add("v_node0", Entity::Node, D, S_);
    if (order2)
    {
        fields.add("state_mid", Entity::Cell, S::ncomp, S_);
        fields.add("x_mid", Entity::Node, D, S_);
        fields.add("gradients", Entity::Cell, ReconLayout<D, P>::ncomp, S_);
        fields.add("gradients_n", Entity::Cell, ReconLayout<D, P>::ncomp, S_);
        fields.add("first_order", Entity::Cell, 1, S_); // the step's a posteriori fallback cells (1), else 0
        if constexpr (P::heat)
        {
            fields.add("heat_gradients", Entity::Cell, heat::Quantities<D, P>::ncomp, S_);
            fields.add("heat_gradients_n", Entity::Cell, heat::Quantities<D, P>::ncomp, S_);
        }
    }
    if (scene.entropyFilter > 0.0)
        fields.add("eps_gradient", Entity::Cell, D, S_); // the entropy filter's grad eps (EntropyFilter.hpp)
    allocateWork();
}

template <int D, class P> void GprModel<D, P>::allocateWork()
{
    const auto& dm = *mesh;
    fnode = Field("unilag::fnode", dm.nOwnedNodes, D);
    aux = Field("unilag::aux", dm.nCells, Aux::ncomp<P>());
    if constexpr (P::heat)
        heatRate = Field("unilag::heatRate", dm.nOwnedCells, 1 + D);
    geom = CellGeometry(dm.nCells, D);
    geomNew = CellGeometry(dm.nCells, D);
    if (order2)
    {
        geomMid = CellGeometry(dm.nCells, D);
        auxMid = Field("unilag::auxMid", dm.nCells, Aux::ncomp<P>());
        if constexpr (P::strain)
            sigmaMid = Field("unilag::sigmaMid", dm.nCells, 6);
        if constexpr (P::heat)
            heatRateMid = Field("unilag::heatRateMid", dm.nOwnedCells, 1 + D);
    }
    cellMaterial = View<int*>("unilag::cellMaterial", dm.nCells);
}

template <int D, class P>
void GprModel<D, P>::remesh(std::shared_ptr<DistributedMesh> newMesh, const std::vector<std::string>& carry)
{
    fields.migrate(newMesh, carry);
    mesh = std::move(newMesh);
    m = mesh->view<D>();
    markTractionNodes();
    allocateWork();
    auto materialHost = fields["material"].getLocalViewHost(Tpetra::Access::ReadOnly);
    auto cellMaterialHost = Kokkos::create_mirror_view(cellMaterial);
    for (LO i = 0; i < mesh->nCells; ++i)
        cellMaterialHost(i) = int(materialHost(i, 0));
    Kokkos::deep_copy(cellMaterial, cellMaterialHost);
}

template <int D, class P> void GprModel<D, P>::markTractionNodes()
{
    const auto& dm = *mesh;
    const auto type = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), bc.type);
    const int nv = D + 1;
    View<int*> traction("unilag::nodeTraction", dm.nNodes);
    auto th = Kokkos::create_mirror_view(traction); // zero-initialised
    bool any = false;
    for (LO i = 0; i < dm.nCells; ++i) // every cell at a node of an owned cell is local, so each node is complete
        for (int f = 0; f < nv; ++f)
        {
            const int g = dm.cellFaceGroupHost[std::size_t(nv) * i + f];
            if (g < 0 || !(type(g) == BcFree || type(g) == BcPressure || type(g) == BcTraction))
                continue;
            any = true;
            for (int k = 0; k < nv; ++k)
                if (k != f) // face f is opposite local node f
                    th(dm.cellNodesHost[std::size_t(nv) * i + k]) = 1;
        }
    Kokkos::deep_copy(traction, th);
    m.nodeTraction = any ? traction : View<int*>(); // empty: no node to look up
}

} // namespace unilag
