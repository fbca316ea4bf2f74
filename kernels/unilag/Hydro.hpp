/*! \file Hydro.hpp
 *  \brief First-order cell-centred Lagrangian step in the hydrodynamic limit (T = -p I): EOS, Maire-type
 *  nodal solver with subcell forces, time-step limits, and the conservative cell update with the GCL volume.
 *
 *  Equation numbers refer to gpr.md section 2 (Boscheri, Chiocchetti & Peshkov, JCP 2022):
 *   - subcell matrix  M_ir = z_i sum_{f in F_ri} (s_f/D) n_f n_f = z_i sum_{j != k} c_j c_j^T / |c_j|
 *   - nodal solve     M_r v_r = sum_i (M_ir v_i - T_i c_ri)                  (2.2)
 *   - subcell force   f_ri = T_i c_ri + M_ir (v_r - v_i)
 *   - cell update     v_i += dt/m_i sum_r f_ri,  E_i += dt/m_i sum_r f_ri . v_r  (2b, 2c)
 *   - GCL             omega_i += dt/m_i sum_r v_r . (c^n + 4 c^{n+1/2} + c^{n+1})/6  (2a, Simpson: exact);
 *                     checked against |T_i^{n+1}| / m_i every step, which is what is stored
 *  Every node sum is a gather over the node -> corner CSR map (no atomics): results are bitwise independent of
 *  the thread count, and, since corners are ordered by global cell id, of the MPI partition.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Gpr.hpp"
#include "unilag/Reduce.hpp"

namespace unilag
{

//! Column indices of the hydrodynamic state (specific volume, velocity, specific total energy).
template <int D>
struct HydroState
{
    static constexpr int omega = 0;
    static constexpr int vel = 1;
    static constexpr int energy = 1 + D;
    static constexpr int ncomp = 2 + D;
};

//! Column indices of per-cell quantities derived from the state by the EOS.
struct Aux
{
    static constexpr int pressure = 0;
    static constexpr int sound = 1;
    static constexpr int impedance = 2;
    static constexpr int ncomp = 3;
};

//! Material parameters (plain data, one entry per material, read inside kernels): the EOS of gpr.md 1.3.
using Material = gpr::EosParams;

enum BcType : int
{
    BcFree = 0,     //!< zero traction
    BcSlipWall = 1, //!< v . n = 0 (also symmetry planes)
    BcVelocity = 2, //!< imposed velocity vector (piston, clamped)
    BcPressure = 3  //!< imposed pressure: normal traction -p n (free surface when p = 0)
};

//! Boundary conditions by boundary group id (the group of a face is MeshView::cellFaceGroup).
struct BoundaryView
{
    View<const int*> type;                        //!< group -> BcType
    Kokkos::View<const double* [3], MemSpace> value; //!< group -> imposed velocity, or pressure in component 0
};

//! Derived cell quantities (pressure, sound speed, impedance z = rho c) for cells [0, nCells).
template <int D>
void computeEos(const ConstField& state, const View<const int*>& cellMaterial, const View<const Material*>& materials,
                const Field& aux, LO nCells)
{
    using S = HydroState<D>;
    auto eos = KOKKOS_LAMBDA(const LO i)
    {
        const double rho = 1.0 / state(i, S::omega);
        double kin = 0.0;
        for (int d = 0; d < D; ++d)
            kin += 0.5 * state(i, S::vel + d) * state(i, S::vel + d);
        const Material& m = materials(cellMaterial(i));
        const double p = gpr::pressure(m, rho, state(i, S::energy) - kin);
        const double c = Kokkos::Experimental::sqrt(Kokkos::Experimental::fmax(gpr::soundSpeed2(m, rho, p), 0.0));
        aux(i, Aux::pressure) = p;
        aux(i, Aux::sound) = c;
        aux(i, Aux::impedance) = rho * c;
    };
    Kokkos::parallel_for("unilag::hydro::eos", range(nCells), eos);
}

//! Subcell matrix M_ik of corner k of a cell (without the impedance factor).
template <int D>
KOKKOS_INLINE_FUNCTION Mat<D> subcellMatrix(const Field& corner, LO i, int k)
{
    Mat<D> M = Mat<D>::zero();
    for (int j = 0; j < D + 1; ++j)
    {
        if (j == k)
            continue;
        const Vec<D> c = cornerVec<D>(corner, i, j);
        M.addOuter(1.0 / norm(c), c);
    }
    return M;
}

/*! \brief Nodal solver at owned nodes: node velocity v_r and the net force sum_i f_ri it exerts on the fluid
 *  (non-zero only where a boundary condition acts; used for the momentum and energy balance). */
template <int D>
void nodalSolve(const MeshView<D>& mesh, const BoundaryView& bc, const ConstField& state, const ConstField& aux,
                const CellGeometry& geom, const Field& vnode, const Field& fnode)
{
    using S = HydroState<D>;
    constexpr int NV = D + 1;
    auto corner = geom.corner;
    auto solve_node = KOKKOS_LAMBDA(const LO r)
    {
        Mat<D> M = Mat<D>::zero();
        Vec<D> b = Vec<D>::zero();
        Vec<D> bext = Vec<D>::zero(); // imposed tractions: sum over boundary faces at r of (s_f / D) t_ext
        // Slip-wall normals, clustered by direction: faces whose normals differ by less than ~45 degrees (a
        // curved or faceted wall) share one constraint; walls meeting at a corner or an edge give one each,
        // whichever boundary groups they belong to.
        constexpr int MaxSlip = 2 * D;
        Vec<D> slipNormal[MaxSlip];
        int nSlip = 0;
        int imposed = -1;
        for (LO q = mesh.nodeCornerOffsets(r); q < mesh.nodeCornerOffsets(r + 1); ++q)
        {
            const LO cid = mesh.nodeCorners(q);
            const LO i = cid / NV;
            const int k = cid % NV;
            const double z = aux(i, Aux::impedance);
            const double p = aux(i, Aux::pressure);
            Mat<D> Mik = subcellMatrix<D>(corner, i, k);
            Vec<D> vi, ck = cornerVec<D>(corner, i, k);
            for (int d = 0; d < D; ++d)
                vi[d] = state(i, S::vel + d);
            const Vec<D> Mv = Mik * vi;
            for (int a = 0; a < D; ++a)
            {
                b[a] += z * Mv[a] + p * ck[a];
                for (int e = 0; e < D; ++e)
                    M.a[a][e] += z * Mik.a[a][e];
            }
            for (int j = 0; j < NV; ++j)
            {
                const int g = (j == k) ? -1 : mesh.cellFaceGroup(i, j);
                if (g < 0)
                    continue;
                const int t = bc.type(g);
                if (t == BcVelocity && imposed < 0)
                    imposed = g;
                else if (t == BcPressure)
                {
                    // t_ext = -p n on face j, whose outward area vector is -D c_j: (s_f / D) t_ext = p c_j
                    bext = bext + bc.value(g, 0) * cornerVec<D>(corner, i, j);
                }
                else if (t == BcSlipWall)
                {
                    // outward area vector of face j is -D c_j
                    const Vec<D> n = (-double(D)) * cornerVec<D>(corner, i, j);
                    const double len = norm(n);
                    int best = -1;
                    double bestCos = 0.7;
                    for (int s = 0; s < nSlip; ++s)
                    {
                        const double cosine = dot(n, slipNormal[s]) / (len * norm(slipNormal[s]));
                        if (cosine > bestCos)
                        {
                            bestCos = cosine;
                            best = s;
                        }
                    }
                    if (best < 0 && nSlip < MaxSlip)
                    {
                        best = nSlip++;
                        slipNormal[best] = Vec<D>::zero();
                    }
                    if (best >= 0)
                        slipNormal[best] = slipNormal[best] + n;
                }
            }
        }
        Vec<D> v;
        if (imposed >= 0)
        {
            for (int d = 0; d < D; ++d)
                v[d] = bc.value(imposed, d);
        }
        else if (nSlip == 0)
        {
            v = solve(M, b + bext);
        }
        else
        {
            // Orthonormal basis Q of the constrained directions (Gram-Schmidt; parallel walls count once),
            // then solve (P M P + Q Q^T) v = P b with P = I - Q Q^T, which gives Q^T v = 0 exactly in exact
            // arithmetic and the Maire wall solution in the free directions.
            Vec<D> Q[D];
            int nq = 0;
            for (int s = 0; s < nSlip && nq < D; ++s)
            {
                Vec<D> u = slipNormal[s];
                const double len0 = norm(u);
                for (int a = 0; a < nq; ++a)
                    u = u - dot(u, Q[a]) * Q[a];
                const double len = norm(u);
                if (len > 1e-8 * len0)
                    Q[nq++] = (1.0 / len) * u;
            }
            if (nq == D)
            {
                v = Vec<D>::zero();
            }
            else
            {
                Mat<D> P = Mat<D>::zero();
                for (int a = 0; a < D; ++a)
                    P.a[a][a] = 1.0;
                for (int s = 0; s < nq; ++s)
                    P.addOuter(-1.0, Q[s]);
                Mat<D> A = Mat<D>::zero();
                for (int a = 0; a < D; ++a)
                    for (int e = 0; e < D; ++e)
                    {
                        double sum = 0.0;
                        for (int f = 0; f < D; ++f)
                            for (int g = 0; g < D; ++g)
                                sum += P.a[a][f] * M.a[f][g] * P.a[g][e];
                        A.a[a][e] = sum;
                    }
                for (int s = 0; s < nq; ++s)
                    A.addOuter(1.0, Q[s]);
                v = solve(A, P * (b + bext));
                // remove the round-off normal component so that walls do no work
                for (int s = 0; s < nq; ++s)
                    v = v - dot(v, Q[s]) * Q[s];
            }
        }
        const Vec<D> F = M * v - b; // sum_i f_ri: the force of the boundary (walls, pistons, tractions) on the fluid
        for (int d = 0; d < D; ++d)
        {
            vnode(r, d) = v[d];
            fnode(r, d) = F[d];
        }
    };
    Kokkos::parallel_for("unilag::hydro::nodal_solve", range(mesh.nOwnedNodes), solve_node);
}

/*! \brief Largest stable step over owned cells: CFL h_i / c_i and a bound on the relative volume change
 *  |dV/dt| dt / V <= maxVolumeChange. */
template <int D>
double stableTimeStep(const MeshView<D>& mesh, const ConstField& aux, const CellGeometry& geom,
                      const ConstField& vnode, double cfl, double maxVolumeChange)
{
    auto corner = geom.corner;
    auto volume = geom.volume;
    auto length = geom.length;
    auto dt_cell = KOKKOS_LAMBDA(const LO i, double (&dt)[1])
    {
        double dvdt = 0.0;
        for (int k = 0; k < D + 1; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            for (int d = 0; d < D; ++d)
                dvdt += corner(i, k * D + d) * vnode(r, d);
        }
        const double c = aux(i, Aux::sound);
        double step = cfl * length(i) / (c > 0.0 ? c : 1e-300);
        const double rate = Kokkos::Experimental::fabs(dvdt) / volume(i);
        if (rate > 0.0 && maxVolumeChange / rate < step)
            step = maxVolumeChange / rate;
        if (step < dt[0])
            dt[0] = step;
    };
    double dt[1];
    minReduce<1>("unilag::hydro::time_step", mesh.nOwnedCells, dt_cell, dt);
    return dt[0];
}

//! Moves nodes [0, n): xNew = x + dt v.
inline void moveNodes(const ConstField& x, const ConstField& vnode, double dt, const Field& xNew, LO n, int dim)
{
    auto move = KOKKOS_LAMBDA(const LO r)
    {
        for (int d = 0; d < dim; ++d)
            xNew(r, d) = x(r, d) + dt * vnode(r, d);
    };
    Kokkos::parallel_for("unilag::hydro::move_nodes", range(n), move);
}

//! Extrema reported by the cell update; a step is accepted only if volumes and squared sound speeds stay positive.
struct UpdateCheck
{
    double minVolumeRatio; //!< min |T^{n+1}| / |T^n|
    double minSound2;      //!< min squared sound speed of the new states (must stay positive)
    double maxGclDefect;   //!< max |m omega - |T^{n+1}|| / |T^{n+1}|
    LO worstCell;          //!< a cell with the smallest volume ratio or internal energy (-1 if none bad)
};

/*! \brief Conservative update of owned cells from the subcell forces (2b, 2c) and the Simpson GCL (2a),
 *  writing stateNew. Returns the validity extrema. */
template <int D>
UpdateCheck updateCells(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                        const CellGeometry& geom, const View<const double*>& mass, const View<const int*>& cellMaterial,
                        const View<const Material*>& materials, const ConstField& x, const ConstField& xNew,
                        const ConstField& vnode, double dt, const Field& stateNew)
{
    using S = HydroState<D>;
    constexpr int NV = D + 1;
    auto corner = geom.corner;
    auto volume = geom.volume;
    auto update = KOKKOS_LAMBDA(const LO i, double (&ext)[4])
    {
        Vec<D> vi;
        for (int d = 0; d < D; ++d)
            vi[d] = state(i, S::vel + d);
        const double z = aux(i, Aux::impedance);
        const double p = aux(i, Aux::pressure);
        Vec<D> xm[NV], xn[NV], vr[NV];
        for (int k = 0; k < NV; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            for (int d = 0; d < D; ++d)
            {
                vr[k][d] = vnode(r, d);
                xn[k][d] = xNew(r, d);
                xm[k][d] = 0.5 * (x(r, d) + xNew(r, d));
            }
        }
        const Simplex<D> sMid(xm), sNew(xn);
        Vec<D> force = Vec<D>::zero();
        double power = 0.0, flux = 0.0;
        for (int k = 0; k < NV; ++k)
        {
            const Vec<D> ck = cornerVec<D>(corner, i, k);
            const Vec<D> f = (-p) * ck + z * (subcellMatrix<D>(corner, i, k) * (vr[k] - vi));
            force = force + f;
            power += dot(f, vr[k]);
            flux += dot(vr[k], ck + 4.0 * sMid.c[k] + sNew.c[k]);
        }
        const double dtm = dt / mass(i);
        double kin = 0.0;
        for (int d = 0; d < D; ++d)
        {
            const double v = vi[d] + dtm * force[d];
            stateNew(i, S::vel + d) = v;
            kin += 0.5 * v * v;
        }
        const double E = state(i, S::energy) + dtm * power;
        // (2a) with Simpson's rule is exact for linear trajectories: the GCL volume must equal the geometric
        // one up to this step's round-off. Store the geometric one (as the paper's Picard loop does), so that
        // round-off does not accumulate over the steps, and report the one-step defect.
        const double omegaGcl = state(i, S::omega) + dtm * flux / 6.0;
        const double omega = sNew.volume / mass(i);
        stateNew(i, S::energy) = E;
        stateNew(i, S::omega) = omega;

        const double ratio = sNew.volume / volume(i);
        // Admissible state: a positive squared sound speed (for an ideal gas: a positive internal energy).
        const double rhoNew = 1.0 / omega;
        const Material& m = materials(cellMaterial(i));
        double c2 = gpr::soundSpeed2(m, rhoNew, gpr::pressure(m, rhoNew, E - kin));
        if (!(c2 == c2) || !(omega == omega))
            c2 = -Kokkos::reduction_identity<double>::min(); // NaN: report as the worst possible
        ext[0] = Kokkos::Experimental::fmin(ext[0], ratio);
        ext[1] = Kokkos::Experimental::fmin(ext[1], c2);
        ext[2] = Kokkos::Experimental::fmin(ext[2], -Kokkos::Experimental::fabs(mass(i) * omegaGcl - sNew.volume) /
                                                         sNew.volume);
        if (ratio <= 0.0 || c2 <= 0.0)
            ext[3] = Kokkos::Experimental::fmin(ext[3], double(i));
    };
    double ext[4];
    minReduce<4>("unilag::hydro::update_cells", mesh.nOwnedCells, update, ext);
    const bool bad = ext[3] < double(mesh.nOwnedCells);
    return UpdateCheck{ext[0], ext[1], -ext[2], bad ? LO(ext[3]) : LO(-1)};
}

} // namespace unilag
