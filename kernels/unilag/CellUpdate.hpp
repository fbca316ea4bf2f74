/*! \file CellUpdate.hpp
 *  \brief The conservative cell update (docs/gpr-model.md 2.1-2.3), split into what a time integrator combines:
 *   - rates: m dv/dt = sum_r f_ri and m dE/dt = sum_r f_ri . v_r of the subcell forces (SubcellForces), and the heat
 *     fluxes' m dE/dt, m dJ/dt (Heat.hpp); a stage's rates can be stored (storeForceRates, layout RateLayout);
 *   - combine: Q^{n+1} = Q^n + dt/m sum_k w_k R_k over stored or live stages (StageSum, applyUpdate);
 *   - relax: the stiff source of J, implicit over dt (relaxHeatFactor), after the combination; G_e relaxes in
 *     strainUpdate (Hydro.hpp);
 *   - and the geometric volume with the Simpson GCL (2a) checked against it.
 *  updateCells is the forward-Euler combination of one live stage, fused so that a first-order step reads each
 *  cell once; updateCellsFromStages combines stored stages (IMEX tableaux such as ARS(2,2,2)).
 */
#pragma once

#include "unilag/Hydro.hpp"

namespace unilag
{

//! Extrema reported by the cell update; a step is accepted only if volumes and squared sound speeds stay positive.
struct UpdateCheck
{
    double minVolumeRatio; //!< min |T^{n+1}| / |T^n|
    double minSound2;      //!< min squared sound speed of the new states (must stay >= 0; 0: a cold gas)
    double maxGclDefect;   //!< max |m omega - |T^{n+1}|| / |T^{n+1}|
    LO worstCell;          //!< the lowest-index inadmissible cell (volume ratio <= 0 or c^2 < 0; -1 if none)
};

/*! The state the subcell forces of a step are computed from, if it is not the state being updated: at second order
 *  the midpoint state, its configuration, shear stress and reconstruction (the corrector of the midpoint rule). */
template <int D> struct CellFlux
{
    ConstField state;      //!< flux state (velocity)
    ConstField aux;        //!< its pressure and impedance
    ConstField stress;     //!< its shear stress (strain variants)
    CellGeometry geom;     //!< corner vectors of the flux configuration
    Reconstruction<D> rec; //!< limited gradients on that configuration (inactive: first order)
};

//! Columns of a stored stage's rates (owned cells): what the forces and the heat fluxes give, times the mass.
template <int D, class P> struct RateLayout
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        momentum = 0,                        //!< m dv/dt = sum_r f_ri, D columns (2b)
        power = D,                           //!< m dE/dt = sum_r f_ri . v_r (2c)
        heat = D + 1,                        //!< heat: m dE/dt, then m dJ/dt (D columns) of the fluxes (2.3)
        ncomp = P::heat ? 2 * D + 2 : D + 1,
    };
};

/*! \brief The rates of cell i from its subcell forces f_ri = T_i(x_r) c_ri + M_ri (v_r - v_i(x_r)) (2.2; with
 *  scheme.corner_load: consistent the traction term is -cornerLoad, CornerLoad.hpp): the flux state's pressure,
 *  stress and velocity at the nodes (reconstructed at second order), its corner vectors, and the
 *  node velocities of the nodal solve for it. */
template <int D, class P> struct SubcellForces
{
    MeshView<D> mesh;
    ConstField state, aux, stress; //!< flux state, its EOS and shear stress (strain)
    RowField corner;               //!< its corner vectors
    Reconstruction<D> rec;         //!< inactive at first order
    ConstField vnode;

    /*! f_ri of corner k of cell i and the velocity vr of its node r. If scale is given, the magnitudes of its
     *  pressure, impedance and elastic terms are added to it (what a balance of these forces is relative to). */
    KOKKOS_INLINE_FUNCTION Vec<D> cornerForce(const LO i, const int k, Vec<D>& vr, double* scale = nullptr) const
    {
        const LO r = mesh.cellNodes(i, k);
        double pk;
        gpr::Sym3 sk;
        Vec<D> vk;
        cornerValues<D, P>(state, aux, stress, rec, i, r, vk, pk, sk);
        for (int d = 0; d < D; ++d)
            vr[d] = vnode(r, d);
        const Vec<D> ck = cornerVec<D>(corner, i, k);
        const Vec<D> pressure = (-pk) * ck;
        const double z = aux(i, Aux::impedance);
        Mat<D> Mik = subcellMatrix<D>(corner, i, k);
        if (mesh.onTractionFace(r)) // as the nodal solve's (Geometry.hpp)
            freeSurfaceFloor<D>(Mik, cornerInvNorm<D>(corner, i, k));
        const Vec<D> viscous = z * (Mik * (vr - vk));
        Vec<D> f = pressure + viscous;
        double elastic = 0.0;
        if constexpr (P::strain)
        {
            const Vec<D> fs = stressTimes<D>(sk, ck);
            f = f + fs;
            elastic = norm(fs);
        }
        if (consistentLoad<D, P>(rec)) // scheme.corner_load: consistent (CornerLoad.hpp)
            f = f - consistentLoadCorrection<D, P>(mesh, corner, rec, i, k);
        if (scale) // the terms before they cancel: z M v_r and z M v_i, not their small difference
            *scale += norm(pressure) + z * (norm(Mik * vr) + norm(Mik * vk)) + elastic;
        return f;
    }

    KOKKOS_INLINE_FUNCTION void operator()(const LO i, Vec<D>& force, double& power) const
    {
        force = Vec<D>::zero();
        power = 0.0;
        for (int k = 0; k < D + 1; ++k)
        {
            Vec<D> vr;
            const Vec<D> f = cornerForce(i, k, vr);
            force = force + f;
            power += dot(f, vr);
        }
    }
};

/*! Stored rates of up to K stages, combined with weights: sum_k w_k R_k(i, offset + c). With one stage of weight 1
 *  it returns the stored rate itself, bit for bit. */
template <int K> struct StageSum
{
    ConstField rate[K];
    double weight[K] = {};
    int stages = 0;
    int offset = 0;

    KOKKOS_INLINE_FUNCTION double operator()(const LO i, const int c) const
    {
        double s = weight[0] * rate[0](i, offset + c);
        for (int k = 1; k < stages; ++k)
            s += weight[k] * rate[k](i, offset + c);
        return s;
    }
};

//! Subcell-force rates of stored stages, combined (a StageSum over the RateLayout columns momentum and power).
template <int D, int K> struct StoredForces
{
    StageSum<K> sum;
    KOKKOS_INLINE_FUNCTION void operator()(const LO i, Vec<D>& force, double& power) const
    {
        for (int d = 0; d < D; ++d)
            force[d] = sum(i, d);
        power = sum(i, D);
    }
};

/*! \brief Stores a stage's rates of the owned cells in RateLayout: the subcell forces' and, for the heat variants,
 *  the heat fluxes' (heatRate: m dE/dt, m dJ/dt, from heatFluxes). */
template <int D, class P>
void storeRates(const SubcellForces<D, P>& forces, const ConstField& heatRate, const Field& rates)
{
    using R = RateLayout<D, P>;
    auto store = KOKKOS_LAMBDA(const LO i)
    {
        captureBeforeConstexpr(heatRate);
        Vec<D> f;
        double power;
        forces(i, f, power);
        for (int d = 0; d < D; ++d)
            rates(i, R::momentum + d) = f[d];
        rates(i, R::power) = power;
        if constexpr (P::heat)
            for (int c = 0; c < D + 1; ++c)
                rates(i, R::heat + c) = heatRate(i, c);
    };
    Kokkos::parallel_for("unilag::gpr::store_rates", range(forces.mesh.nOwnedCells), store);
}

} // namespace unilag

#include "unilag/CellUpdateApply.hpp"
