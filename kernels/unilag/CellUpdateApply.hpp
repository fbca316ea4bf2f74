/*! \file CellUpdateApply.hpp
 *  \brief The combination and relaxation half of the cell update (CellUpdate.hpp): new velocity, energy and J from
 *  the rates of one live stage or of stored stages, the specific volume from the new geometry with the Simpson GCL
 *  checked against it, and the admissibility checks. Included by CellUpdate.hpp.
 */
#pragma once

namespace unilag
{

/*! Squared sound speed of an updated cell (density rhoNew; E, v, G, J as stored), the admissibility test of every
 *  update: negative for an inadmissible state, and for NaN. A cold cell's E - kinetic is zero only up to round-off:
 *  eps in [-epsRoundoff, 0) counts as 0 (cold-gas.md); a solid's c^2 < 0 from its EOS is still refused. */
template <int D, class P>
KOKKOS_INLINE_FUNCTION double updatedSound2(const Material& m, double rhoNew, double E, const Vec<D>& v,
                                            const gpr::Sym3& G, const Vec<D>& J)
{
    double eps = internalEnergy<D, P>(m, E, v, G, J);
    if (eps < 0.0 && eps >= -m.epsRoundoff)
        eps = 0.0;
    const double c2 = gpr::soundSpeed2(m.eos, rhoNew, gpr::pressure(m.eos, rhoNew, eps));
    return c2 == c2 ? c2 : -Kokkos::reduction_identity<double>::min(); // NaN: report as the worst possible
}

/*! \brief Conservative update of owned cells over dt from rates (forces: m dv/dt, m dE/dt; heat: m dE/dt, m dJ/dt),
 *  writing stateNew. Returns the validity extrema.
 *   - v^{n+1} = v^n + dt/m force, E^{n+1} = E^n + dt/m power (+ dt/m heat E) (2b, 2c);
 *   - omega^{n+1} = |T(xNew)| / m, with the GCL volume omega^n + dt/m sum_r vnode_r . (c^n + 4 c^{n+1/2} + c^{n+1})/6
 *     (2a) checked against it (xNew = x + dt vnode);
 *   - strain: G^{n+1} is already in stateNew (strainUpdate) and is not touched here;
 *   - heat: J^{n+1} = (J^n + dt/m heat J) / (1 + dt rho0 theta^n / (tau2 rho^{n+1} theta0)) (2.3: explicit fluxes,
 *     implicit relaxation).
 *  If geomNew is given, the geometry of the new positions is stored there for owned cells. */
template <int D, class P, class Forces, class Heat>
UpdateCheck applyUpdate(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                        const CellGeometry& geom, const View<const double*>& mass, const View<const int*>& cellMaterial,
                        const View<const Material*>& materials, const ConstField& x, const ConstField& xNew,
                        const ConstField& vnode, double dt, const Field& stateNew, const Forces& forces,
                        const Heat& heat, const CellGeometry& geomNew)
{
    using S = StateLayout<D, P>;
    constexpr int NV = D + 1;
    auto corner = geom.corner;
    auto volume = geom.volume;
    const bool storeNew = geomNew.volume.extent(0) > 0;
    auto update = KOKKOS_LAMBDA(const LO i, double(&ext)[4])
    {
        captureBeforeConstexpr(stateNew, heat, aux);
        Vec<D> xm[NV], xn[NV];
        for (int k = 0; k < NV; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            for (int d = 0; d < D; ++d)
            {
                xn[k][d] = xNew(r, d);
                xm[k][d] = 0.5 * (x(r, d) + xNew(r, d));
            }
        }
        const Simplex<D> sMid(xm), sNew(xn);
        if (storeNew)
            storeGeometry<D>(geomNew, i, sNew); // the next step's geometry of owned cells, at no extra cost
        Vec<D> force;
        double power;
        forces(i, force, power);
        double gclFlux = 0.0;
        for (int k = 0; k < NV; ++k)
        {
            Vec<D> vr;
            for (int d = 0; d < D; ++d)
                vr[d] = vnode(mesh.cellNodes(i, k), d);
            gclFlux += dot(vr, cornerVec<D>(corner, i, k) + 4.0 * sMid.c[k] + sNew.c[k]);
        }
        const double dtm = dt / mass(i);
        Vec<D> v;
        for (int d = 0; d < D; ++d)
        {
            v[d] = state(i, S::vel + d) + dtm * force[d];
            stateNew(i, S::vel + d) = v[d];
        }
        double E = state(i, S::energy) + dtm * power;
        const Material& m = materials(cellMaterial(i));
        // (2a) with Simpson's rule is exact for linear trajectories: the GCL volume must equal the geometric
        // one up to this step's round-off. Store the geometric one (as the paper's Picard loop does), so that
        // round-off does not accumulate over the steps, and report the one-step defect.
        const double omegaGcl = state(i, S::omega) + dtm * gclFlux / 6.0;
        const double omega = sNew.volume / mass(i);
        const double rhoNew = 1.0 / omega;
        gpr::Sym3 G = gpr::identity(1.0);
        if constexpr (P::strain)
            G = loadSym3(stateNew, i, S::G);
        Vec<D> J = Vec<D>::zero();
        if constexpr (P::heat)
        {
            E += dtm * heat(i, 0);
            const double factor =
                m.heat ? gpr::relaxHeatFactor(dt, m.tau2, rhoNew, m.rho0, aux(i, Aux::theta), m.theta0) : 1.0;
            for (int d = 0; d < D; ++d)
            {
                J[d] = (state(i, S::J + d) + dtm * heat(i, 1 + d)) * factor;
                stateNew(i, S::J + d) = J[d];
            }
        }
        stateNew(i, S::energy) = E;
        stateNew(i, S::omega) = omega;

        const double ratio = sNew.volume / volume(i);
        // Admissible state: a non-negative squared sound speed (for an ideal gas: a non-negative internal energy;
        // a cold gas, p = 0, has c0 = 0 and the nodal solver's shock impedance, nodalImpedance).
        double c2 = updatedSound2<D, P>(m, rhoNew, E, v, G, J);
        if (!(omega == omega))
            c2 = -Kokkos::reduction_identity<double>::min();
        ext[0] = lesser(ext[0], ratio);
        ext[1] = lesser(ext[1], c2);
        ext[2] = lesser(ext[2], -Kokkos::Experimental::fabs(mass(i) * omegaGcl - sNew.volume) / sNew.volume);
        if (ratio <= 0.0 || c2 < 0.0)
            ext[3] = lesser(ext[3], double(i));
    };
    double ext[4];
    minReduce<4>("unilag::gpr::update_cells", mesh.nOwnedCells, update, ext);
    const bool bad = ext[3] < double(mesh.nOwnedCells);
    return UpdateCheck{ext[0], ext[1], -ext[2], bad ? LO(ext[3]) : LO(-1)};
}

//! The subcell forces of the flux state (flux, if given; otherwise state, aux, stress, geom) with node velocities vnode.
template <int D, class P>
SubcellForces<D, P> subcellForces(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                                  const ConstField& stress, const CellGeometry& geom, const ConstField& vnode,
                                  const CellFlux<D>& flux = CellFlux<D>())
{
    const bool separate = flux.state.extent(0) > 0;
    return SubcellForces<D, P>{mesh,
                               separate ? flux.state : state,
                               separate ? flux.aux : aux,
                               separate ? flux.stress : stress,
                               separate ? flux.geom.corner : geom.corner,
                               flux.rec,
                               vnode};
}

/*! \brief Forward-Euler update of the owned cells from one live stage: the subcell forces of the flux state (flux, if
 *  given: the midpoint of a second-order step with its reconstruction; otherwise state, aux, geom and stress), whose
 *  nodal solution is vnode, and the heat fluxes heatRate (owned cells: m dE/dt, m dJ/dt). Strain variants: stress is
 *  the sigma of the last nodal solve, so that the forces at a node balance exactly. See applyUpdate. */
template <int D, class P = PhysicsHydro>
UpdateCheck updateCells(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                        const CellGeometry& geom, const View<const double*>& mass, const View<const int*>& cellMaterial,
                        const View<const Material*>& materials, const ConstField& x, const ConstField& xNew,
                        const ConstField& vnode, double dt, const Field& stateNew,
                        const ConstField& stress = ConstField(), const ConstField& heatRate = ConstField(),
                        const CellGeometry& geomNew = CellGeometry(), const CellFlux<D>& flux = CellFlux<D>())
{
    const SubcellForces<D, P> forces = subcellForces<D, P>(mesh, state, aux, stress, geom, vnode, flux);
    StageSum<1> heat;
    heat.rate[0] = heatRate;
    heat.weight[0] = 1.0;
    heat.stages = 1;
    return applyUpdate<D, P>(mesh, state, aux, geom, mass, cellMaterial, materials, x, xNew, vnode, dt, stateNew,
                             forces, heat, geomNew);
}

/*! \brief Update of the owned cells from stored stages (storeRates): Q^{n+1} = Q^n + dt/m sum_k w_k R_k, then the
 *  relaxation of J over dt; vnode is the velocity that moved the nodes (xNew = x + dt vnode). See applyUpdate. */
template <int D, class P, int K>
UpdateCheck updateCellsFromStages(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                                  const CellGeometry& geom, const View<const double*>& mass,
                                  const View<const int*>& cellMaterial, const View<const Material*>& materials,
                                  const ConstField& x, const ConstField& xNew, const ConstField& vnode, double dt,
                                  const Field& stateNew, const StageSum<K>& rates,
                                  const CellGeometry& geomNew = CellGeometry())
{
    StageSum<K> heat = rates;
    heat.offset = RateLayout<D, P>::heat;
    return applyUpdate<D, P>(mesh, state, aux, geom, mass, cellMaterial, materials, x, xNew, vnode, dt, stateNew,
                             StoredForces<D, K>{rates}, heat, geomNew);
}

/*! \brief The a posteriori first-order fallback (docs/gpr-model.md 2.5): marks in flags (owned cells, column 0) every
 *  cell that the update into stateNew / geomNew left inadmissible (inverted, or a negative squared sound speed, the
 *  test of applyUpdate) and that is not marked yet. Returns how many it marked on this rank. */
template <int D, class P>
LO flagInadmissible(const MeshView<D>& mesh, const ConstField& stateNew, const CellGeometry& geomNew,
                    const View<const int*>& cellMaterial, const View<const Material*>& materials, const Field& flags)
{
    using S = StateLayout<D, P>;
    auto volume = geomNew.volume;
    LO marked = 0;
    auto mark = KOKKOS_LAMBDA(const LO i, LO& count)
    {
        if (flags(i, 0) != 0.0)
            return;
        Vec<D> v, J;
        gpr::Sym3 G;
        loadKinematics<D, P>(stateNew, i, v, G, J);
        const double rho = 1.0 / stateNew(i, S::omega);
        const Material& m = materials(cellMaterial(i));
        if (volume(i) <= 0.0 || updatedSound2<D, P>(m, rho, stateNew(i, S::energy), v, G, J) < 0.0)
        {
            flags(i, 0) = 1.0;
            ++count;
        }
    };
    Kokkos::parallel_reduce("unilag::gpr::flag_inadmissible", range(mesh.nOwnedCells), mark, marked);
    return marked;
}

//! The fallback's last resort: marks every cell (owned and ghost) in flags; returns how many owned ones were not.
inline LO flagAll(const Field& flags, LO nOwnedCells)
{
    LO unmarked = 0;
    auto count = KOKKOS_LAMBDA(const LO i, LO& n) { n += flags(i, 0) == 0.0 ? 1 : 0; };
    Kokkos::parallel_reduce("unilag::gpr::count_unflagged", range(nOwnedCells), count, unmarked);
    Kokkos::deep_copy(flags, 1.0);
    return unmarked;
}

} // namespace unilag
