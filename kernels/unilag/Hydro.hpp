/*! \file Hydro.hpp
 *  \brief First-order cell-centred Lagrangian step of the GPR model (T = -p I + sigma): EOS and derived cell
 *  quantities, Maire-type nodal solver with subcell forces, time-step limits and the G_e update (the conservative
 *  cell update with the GCL volume is in CellUpdate.hpp). Every kernel is a template on the Physics variant (Physics.hpp): the hydrodynamic one
 *  compiles to the Euler solver, with no stress, G_e or J work.
 *
 *  Equation numbers are those of docs/gpr-model.md section 2 (Boscheri, Chiocchetti & Peshkov, JCP 2022):
 *   - subcell matrix  M_ir = z_i sum_{f in F_ri} (s_f/D) n_f n_f = z_i sum_{j != k} c_j c_j^T / |c_j|
 *   - nodal solve     M_r v_r = sum_i (M_ir v_i - T_i c_ri)                  (2.2)
 *   - subcell force   f_ri = T_i c_ri + M_ir (v_r - v_i)
 *   - cell update     v_i += dt/m_i sum_r f_ri,  E_i += dt/m_i sum_r f_ri . v_r  (2b, 2c; CellUpdate.hpp)
 *   - GCL             omega_i += dt/m_i sum_r v_r . (c^n + 4 c^{n+1/2} + c^{n+1})/6  (2a, Simpson: exact);
 *                     checked against |T_i^{n+1}| / m_i every step, which is what is stored (CellUpdate.hpp)
 *  Every node sum is a gather over the node -> corner CSR map (no atomics): results are bitwise independent of
 *  the thread count, and, since corners are ordered by global cell id, of the MPI partition.
 *  Second order: v_i, p_i and sigma_i in the nodal solve and the subcell forces become the limited reconstruction
 *  at the node, v_i(x_r) etc. (Reconstruction.hpp, cornerValues); the update then takes its forces from the midpoint
 *  state of the predictor-corrector (CellFlux), and strainUpdate its transport.
 */
#pragma once

#include "unilag/CornerLoad.hpp"
#include "unilag/Geometry.hpp"
#include "unilag/Gpr.hpp"
#include "unilag/NodeMotion.hpp"
#include "unilag/Physics.hpp"
#include "unilag/Reconstruction.hpp"
#include "unilag/Reduce.hpp"

namespace unilag
{

/*! \brief Specific internal energy eps = E - |v|^2/2 - E_e(G) - alpha^2 |J|^2 / 2 (docs/gpr-model.md 1.2) of a state
 *  row whose velocity, G_e and J are given (the energy is split the same way everywhere, so the total is what is
 *  conserved). */
template <int D, class P>
KOKKOS_INLINE_FUNCTION double internalEnergy(const Material& m, double energy, const Vec<D>& v, const gpr::Sym3& G,
                                             const Vec<D>& J)
{
    double kin = 0.0;
    for (int d = 0; d < D; ++d)
        kin += 0.5 * v[d] * v[d];
    double eps = energy - kin;
    if constexpr (P::strain)
        if (m.strainLaw != StrainNone)
            eps -= gpr::elasticEnergy(m.csh, G);
    if constexpr (P::heat)
        if (m.heat)
        {
            double j2 = 0.0;
            for (int d = 0; d < D; ++d)
                j2 += J[d] * J[d];
            eps -= 0.5 * m.alpha * m.alpha * j2;
        }
    return eps;
}

//! Velocity, G_e and J of a state row (G_e and J only where the variant carries them).
template <int D, class P, class F>
KOKKOS_INLINE_FUNCTION void loadKinematics(const F& state, LO i, Vec<D>& v, gpr::Sym3& G, Vec<D>& J)
{
    using S = StateLayout<D, P>;
    for (int d = 0; d < D; ++d)
        v[d] = state(i, S::vel + d);
    if constexpr (P::strain)
        G = loadSym3(state, i, S::G);
    else
        G = gpr::identity(1.0);
    if constexpr (P::heat)
        for (int d = 0; d < D; ++d)
            J[d] = state(i, S::J + d);
    else
        J = Vec<D>::zero();
}

/*! \brief Derived cell quantities for cells [0, nCells): pressure, signal speed a = sqrt(c0^2 + 4/3 c_sh^2 + c_h^2),
 *  impedance z = rho a, internal energy, temperature (heat) and the shear stress sigma(rho, G_e) (strain), which is
 *  written to `stress` (nCells x 6; ignored by the other variants). */
template <int D, class P = PhysicsHydro>
void computeEos(const ConstField& state, const View<const int*>& cellMaterial, const View<const Material*>& materials,
                const Field& aux, LO nCells, const Field& stress = Field())
{
    using S = StateLayout<D, P>;
    auto eos = KOKKOS_LAMBDA(const LO i)
    {
        captureBeforeConstexpr(stress);
        const double rho = 1.0 / state(i, S::omega);
        const Material& m = materials(cellMaterial(i));
        Vec<D> v, J;
        gpr::Sym3 G;
        loadKinematics<D, P>(state, i, v, G, J);
        const double eps = internalEnergy<D, P>(m, state(i, S::energy), v, G, J);
        const double p = gpr::pressure(m.eos, rho, eps);
        double a2 = Kokkos::Experimental::fmax(gpr::soundSpeed2(m.eos, rho, p), 0.0);
        if constexpr (P::strain)
        {
            const bool shear = m.strainLaw != StrainNone;
            a2 += shear ? (4.0 / 3.0) * m.csh * m.csh : 0.0;
            storeSym3(stress, i, 0, shear ? gpr::shearStress(rho, m.csh, G) : gpr::Sym3{0, 0, 0, 0, 0, 0});
        }
        double theta = 0.0;
        if constexpr (P::heat)
        {
            theta = gpr::temperature(m.eos, rho, eps);
            if (m.heat)
                a2 += m.alpha * m.alpha * Kokkos::Experimental::fmax(theta, 0.0) / (m.eos.cv * rho * rho);
        }
        const double a = Kokkos::Experimental::sqrt(a2);
        aux(i, Aux::pressure) = p;
        aux(i, Aux::sound) = a;
        aux(i, Aux::impedance) = rho * a; // what nodalImpedance refines; rho a is Maire's where it is not called
        aux(i, Aux::signal) = a;
        aux(i, Aux::eps) = eps;
        aux(i, Aux::theta) = theta;
    };
    Kokkos::parallel_for("unilag::gpr::eos", range(nCells), eos);
}

/*! \brief Slope Gamma_D of the linear shock Hugoniot U_s = a + Gamma_D u_p in the strong-shock limit (Dukowicz,
 *  JCP 61, 1985): (gamma + 1) / 2 for an ideal gas, s for Mie-Grueneisen (its own U_s-u_p slope); 1 for the
 *  barotropic neo-Hookean law, which has no Hugoniot parameter (a choice: the acoustic limit of the others). */
KOKKOS_INLINE_FUNCTION double shockSlope(const gpr::EosParams& e)
{
    if (e.type == gpr::EosParams::IdealGas)
        return 0.5 * (e.gamma + 1.0);
    if (e.type == gpr::EosParams::MieGruneisen)
        return e.s;
    return 1.0;
}

namespace impedance
{
/*! a_eff: the frozen speed a less the part of the shear that relaxes within a cell's acoustic time h / a (constant
 *  tau1 only; nodalImpedance's comment). */
KOKKOS_INLINE_FUNCTION double effectiveSpeed2(const Material& m, double a, double length, bool strain)
{
    double a2 = a * a;
    if (strain && m.strainLaw == StrainConstant && a > 0.0)
    {
        // phi = 1 / (1 + h / (a tau1)): tau1 = +inf gives 1, tau1 = 0 gives 0, no inf / inf
        const double phi = 1.0 / (1.0 + length / (a * m.tau1));
        a2 = Kokkos::Experimental::fmax(a2 - (4.0 / 3.0) * m.csh * m.csh * (1.0 - phi), 0.0);
    }
    return a2;
}

//! Signal s = a_eff + shock term and impedance rho s of cell i.
KOKKOS_INLINE_FUNCTION void store(const Field& aux, LO i, double rho, double a2, double shockTerm)
{
    double s = Kokkos::Experimental::sqrt(a2) + shockTerm;
    // The shock term carries the round-off velocities ahead of a front into a cold gas, one cell per solve,
    // decaying to subnormal numbers (1e-320), for which the entries of M lose their digits: a speed below
    // 1e-100 (in any units no physical speed) is 0, and the node takes the cold gas's velocity (nodalSolve).
    if (s < 1e-100)
        s = 0.0;
    aux(i, Aux::signal) = s;
    aux(i, Aux::impedance) = rho * s;
}
} // namespace impedance

/*! \brief The nodal solver's impedance z_i = rho_i (a_eff + Gamma_D |dv|_i) for cells [0, nCells), after
 *  computeEos, into Aux::impedance, its speed into Aux::signal (the time step's too) and the shock term Gamma_D |dv|
 *  into Aux::compression; docs/cold-gas.md.
 *   - Dukowicz's shock term Gamma_D |dv| keeps z > 0 where a vanishes (a cold gas, p = 0) and is the impedance of
 *     a strong shock: |dv|_i = max over the cell's corners of the compression -(v_r - v_i) . c_k / |c_k| (0 if
 *     none: rarefactions and shear keep rho a), v_r the node velocities of the last nodal solve (vnode: the
 *     previous step's, or the predictor's for the corrector). Lagged, so z is fixed during the nodal solve, the
 *     Picard loop and the subcell forces: the forces balance at every node as before.
 *   - a_eff: the frozen speed a of computeEos less the part of the shear that relaxes within a cell's acoustic time
 *     h / a: a_eff^2 = a^2 - (4/3) c_sh^2 (1 - phi), phi = tau1 / (tau1 + h / a) (constant tau1 only). tau1 = 1e-14
 *     gives the fluid's c0 (the hydrodynamic limit), tau1 = inf the elastic sqrt(c0^2 + 4/3 c_sh^2); plastic solids
 *     keep the frozen speed. Aux::sound stays a (the heat fluxes' Rusanov speed, gpr-model.md 2.3). */
template <int D, class P = PhysicsHydro>
void nodalImpedance(const MeshView<D>& mesh, const ConstField& state, const View<const int*>& cellMaterial,
                    const View<const Material*>& materials, const CellGeometry& geom, const ConstField& vnode,
                    const Field& aux, LO nCells)
{
    using S = StateLayout<D, P>;
    auto length = geom.length;
    auto corner = geom.corner;
    auto kernel = KOKKOS_LAMBDA(const LO i)
    {
        const Material& m = materials(cellMaterial(i));
        const double a2 = impedance::effectiveSpeed2(m, aux(i, Aux::sound), length(i), P::strain);
        // the compression rate of the corners: -(v_r - v_i) . c_k / |c_k|, c_k the outward corner vector
        double dv = 0.0;
        for (int k = 0; k < D + 1; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            double w = 0.0;
            for (int d = 0; d < D; ++d)
                w -= (vnode(r, d) - state(i, S::vel + d)) * corner(i, k * D + d);
            dv = Kokkos::Experimental::fmax(dv, w * cornerInvNorm<D>(corner, i, k));
        }
        const double shockTerm = shockSlope(m.eos) * dv;
        aux(i, Aux::compression) = shockTerm;
        impedance::store(aux, i, 1.0 / state(i, S::omega), a2, shockTerm);
    };
    Kokkos::parallel_for("unilag::gpr::nodal_impedance", range(nCells), kernel);
}

/*! nodalImpedance's signal and impedance for cells [0, nCells) after a change of the cells' internal energy alone
 *  (the entropy filter: velocities, nodes and geometry as they were), with the shock term it stored: bit for bit
 *  what nodalImpedance would give, without its loop over the corners. */
template <int D, class P = PhysicsHydro>
void renewImpedance(const ConstField& state, const View<const int*>& cellMaterial,
                    const View<const Material*>& materials, const CellGeometry& geom, const Field& aux, LO nCells)
{
    using S = StateLayout<D, P>;
    auto length = geom.length;
    auto kernel = KOKKOS_LAMBDA(const LO i)
    {
        const Material& m = materials(cellMaterial(i));
        const double a2 = impedance::effectiveSpeed2(m, aux(i, Aux::sound), length(i), P::strain);
        impedance::store(aux, i, 1.0 / state(i, S::omega), a2, aux(i, Aux::compression));
    };
    Kokkos::parallel_for("unilag::gpr::renew_impedance", range(nCells), kernel);
}

//! Subcell matrix M_ik of corner k of a cell (without the impedance factor).
template <int D>
KOKKOS_INLINE_FUNCTION Mat<D> subcellMatrix(const RowField& corner, LO i, int k)
{
    Mat<D> M = Mat<D>::zero();
    for (int j = 0; j < D + 1; ++j)
    {
        if (j == k)
            continue;
        M.addOuter(cornerInvNorm<D>(corner, i, j), cornerVec<D>(corner, i, j));
    }
    return M;
}

/*! \brief Velocity, pressure and shear stress (strain) of cell i at its node r: the cell values, plus the limited
 *  linear reconstruction at second order (rec active). Used alike by the nodal solver and the subcell forces. */
template <int D, class P>
KOKKOS_INLINE_FUNCTION void cornerValues(const ConstField& state, const ConstField& aux, const ConstField& stress,
                                         const Reconstruction<D>& rec, LO i, LO r, Vec<D>& v, double& p,
                                         gpr::Sym3& sigma)
{
    using S = StateLayout<D, P>;
    using R = ReconLayout<D, P>;
    for (int d = 0; d < D; ++d)
        v[d] = state(i, S::vel + d);
    p = aux(i, Aux::pressure);
    if constexpr (P::strain)
        sigma = loadSym3(stress, i, 0);
    if (rec.active())
    {
        const Vec<D> dx = rec.offset(i, r);
        for (int d = 0; d < D; ++d)
            v[d] += rec.delta(i, R::vel + d, dx);
        p += rec.delta(i, R::pressure, dx);
        if constexpr (P::strain)
        {
            sigma.xx += rec.delta(i, R::stress + 0, dx);
            sigma.yy += rec.delta(i, R::stress + 1, dx);
            sigma.zz += rec.delta(i, R::stress + 2, dx);
            sigma.xy += rec.delta(i, R::stress + 3, dx);
            sigma.xz += rec.delta(i, R::stress + 4, dx);
            sigma.yz += rec.delta(i, R::stress + 5, dx);
        }
    }
}

/*! \brief Nodal solver at owned nodes: node velocity v_r and the net force sum_i f_ri it exerts on the fluid
 *  (non-zero only where a boundary condition acts; used for the momentum and energy balance).
 *  T_i = -p_i I + sigma_i with sigma from `stress` (strain variants; the Picard iterate). */
template <int D, class P = PhysicsHydro>
void nodalSolve(const MeshView<D>& mesh, const BoundaryView& bc, const ConstField& state, const ConstField& aux,
                const CellGeometry& geom, const Field& vnode, const Field& fnode, const ConstField& stress = ConstField(),
                const Reconstruction<D>& rec = Reconstruction<D>())
{
    constexpr int NV = D + 1;
    auto corner = geom.corner;
    auto solve_node = KOKKOS_LAMBDA(const LO r)
    {
        Mat<D> M = Mat<D>::zero();
        Vec<D> b = Vec<D>::zero();
        Vec<D> bext = Vec<D>::zero(); // imposed tractions: sum over boundary faces at r of (s_f / D) t_ext
        // the same system with z_i = rho_i: used where every z_i at r is 0 (a cold gas at rest), M_r = 0 then
        Mat<D> Mcold = Mat<D>::zero();
        Vec<D> bcold = Vec<D>::zero();
        // Slip-wall normals, clustered by direction: faces whose normals differ by less than ~45 degrees (a
        // curved or faceted wall) share one constraint; walls meeting at a corner or an edge give one each,
        // whichever boundary groups they belong to.
        constexpr int MaxSlip = 2 * D;
        Vec<D> slipNormal[MaxSlip];
        int nSlip = 0;
        int imposed = -1;
        const bool boundaryNode = mesh.mayBeOnBoundary(r); // else no face at r has a group: skip their loop
        for (LO q = mesh.nodeCornerOffsets(r); q < mesh.nodeCornerOffsets(r + 1); ++q)
        {
            const LO cid = mesh.nodeCorners(q);
            const LO i = cid / NV;
            const int k = cid % NV;
            const double z = aux(i, Aux::impedance);
            double p;
            gpr::Sym3 sigma;
            Vec<D> vi;
            cornerValues<D, P>(state, aux, stress, rec, i, r, vi, p, sigma);
            Mat<D> Mik = subcellMatrix<D>(corner, i, k);
            const Vec<D> ck = cornerVec<D>(corner, i, k);
            if (mesh.onTractionFace(r))
                freeSurfaceFloor<D>(Mik, cornerInvNorm<D>(corner, i, k));
            const Vec<D> Mv = Mik * vi;
            for (int a = 0; a < D; ++a)
            {
                b[a] += z * Mv[a] + p * ck[a];
                for (int e = 0; e < D; ++e)
                    M.a[a][e] += z * Mik.a[a][e];
            }
            if constexpr (P::strain)
                b = b - stressTimes<D>(sigma, ck);
            if (consistentLoad<D, P>(rec))
                b = b + consistentLoadCorrection<D, P>(mesh, corner, rec, i, k);
            const double rho = 1.0 / state(i, StateLayout<D, P>::omega);
            for (int a = 0; a < D; ++a)
            {
                bcold[a] += rho * Mv[a];
                for (int e = 0; e < D; ++e)
                    Mcold.a[a][e] += rho * Mik.a[a][e];
            }
            for (int j = 0; j < NV && boundaryNode; ++j)
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
                else if (t == BcTraction)
                {
                    // (s_f / D) t_ext with s_f = D |c_j|
                    const double w = norm(cornerVec<D>(corner, i, j));
                    for (int d = 0; d < D; ++d)
                        bext[d] += w * bc.value(g, d);
                }
                else if (t == BcSlipWall)
                {
                    // outward area vector of face j is -D c_j
                    const Vec<D> n = wallNormal<D>(bc, g, (-double(D)) * cornerVec<D>(corner, i, j));
                    addWallNormal<D>(n, slipNormal, nSlip);
                }
            }
        }
        double trace = 0.0;
        for (int a = 0; a < D; ++a)
            trace += M.a[a][a];
        const bool cold = !(trace > 0.0);
        const Vec<D> bz = b;
        if (cold)
        {
            // No cell at r resists a velocity jump: z_i = 0 around r, which only a cold (p = 0), stress-free
            // material at rest relative to its nodes gives (nodalImpedance), so b = 0 and the forces vanish
            // whatever v_r is. Take the velocity the cells impose with equal sound speeds (a mass-weighted mean);
            // the subcell forces keep z_i = 0, so they still balance (F_r = 0 as before).
            M = Mcold;
            b = bcold;
            trace = 0.0;
            for (int a = 0; a < D; ++a)
                trace += M.a[a][a];
        }
        // Solve the system scaled to a unit trace: near a cold gas the z_i span hundreds of decades (the shock term
        // of the round-off velocities ahead of the front), and the determinant of M would underflow to 0.
        const double unit = trace > 0.0 ? trace : 1.0;
        for (int a = 0; a < D; ++a)
        {
            b[a] /= unit;
            bext[a] /= unit;
            for (int e = 0; e < D; ++e)
                M.a[a][e] /= unit;
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
            // then solve (Proj M Proj + Q Q^T) v = Proj b with Proj = I - Q Q^T, which gives Q^T v = 0 exactly in exact
            // arithmetic and the Maire wall solution in the free directions.
            Vec<D> Q[D];
            const int nq = orthonormalBasis<D>(slipNormal, nSlip, Q);
            if (nq == D)
            {
                v = Vec<D>::zero();
            }
            else
            {
                Mat<D> Proj = Mat<D>::zero();
                for (int a = 0; a < D; ++a)
                    Proj.a[a][a] = 1.0;
                for (int s = 0; s < nq; ++s)
                    Proj.addOuter(-1.0, Q[s]);
                Mat<D> A = Mat<D>::zero();
                for (int a = 0; a < D; ++a)
                    for (int e = 0; e < D; ++e)
                    {
                        double sum = 0.0;
                        for (int f = 0; f < D; ++f)
                            for (int g = 0; g < D; ++g)
                                sum += Proj.a[a][f] * M.a[f][g] * Proj.a[g][e];
                        A.a[a][e] = sum;
                    }
                for (int s = 0; s < nq; ++s)
                    A.addOuter(1.0, Q[s]);
                v = solve(A, Proj * (b + bext));
                // remove the round-off normal component so that walls do no work
                for (int s = 0; s < nq; ++s)
                    v = v - dot(v, Q[s]) * Q[s];
            }
        }
        const Vec<D> F = cold ? (-1.0) * bz : unit * (M * v - b); // sum_i f_ri: the force of the boundary (walls, pistons, tractions) on the fluid
        for (int d = 0; d < D; ++d)
        {
            vnode(r, d) = v[d];
            fnode(r, d) = F[d];
        }
    };
    Kokkos::parallel_for("unilag::gpr::nodal_solve", range(mesh.nOwnedNodes), solve_node);
}

/*! \brief Largest stable step over owned cells: CFL h_i / c_i (h_i: timeStepLength) and a bound on the relative
 *  volume change |dV/dt| dt / V <= maxVolumeChange. */
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
        const double c = aux(i, Aux::signal); // the nodal solver's speed (nodalImpedance): a_eff + Gamma_D |dv|
        double step = cfl * timeStepLength<D>(corner, i, length(i), volume(i)) / (c > 0.0 ? c : 1e-300);
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

//! Extrema of one Picard iteration of the G_e update.
struct PicardCheck
{
    double maxChange;      //!< max_i |sigma^{l+1} - sigma^l|_F / (rho_i a_i^2) (the stopping criterion)
    double minVolumeRatio; //!< min |T(x^{l+1})| / |T^n|
    LO badCell;            //!< a cell whose volume or G_e became inadmissible (-1 if none)
};

/*! \brief One Picard iteration of the implicit G_e update (docs/gpr-model.md 2.4) for owned cells, from the node
 *  velocities of the last nodal solve: positions x^{l+1} (xNew), rho^{l+1} = m / |T(x^{l+1})|, the velocity gradient
 *  L = (1/|T^n|) sum_r v_r (x) c_r^n, the transport increment dT = -dt (G^n L + L^T G^n) (explicit in G^n), the
 *  stiff relaxation over dt (transportAndRelax: exponential, with the Navier-Stokes limit; the plastic law relaxes
 *  G^n + dT with tau1 consistent with the result, relaxPlasticStrain), and sigma^{l+1} = sigma(rho^{l+1}, G^{l+1}).
 *  Writes G^{l+1} into stateNew and sigma^{l+1} into sigmaNew; sigmaOld is the iterate the nodal solve used.
 *  plasticHint (plastic variant, one per cell, NaN = none) carries each cell's plastic-flow parameter between calls.
 *  Second order (midpoint corrector): fluxState and fluxGeom, if given, are the midpoint state and configuration,
 *  so that dT = -dt (G^{n+1/2} L^{n+1/2} + L^T G^{n+1/2}) with L from the midpoint corner vectors; the relaxation
 *  still starts from G^n and spans dt. increment, if given, receives dT (0 where G is not updated): ARS(2,2,2)
 *  takes its stage's stiff source from the residual G - G^n - dT (Ars.hpp). plasticWork, if given, counts each
 *  cell's plastic-law evaluations (relaxPlasticStrain's work: the per-cell cost the load balance weighs). */
template <int D, class P>
PicardCheck strainUpdate(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                         const CellGeometry& geom, const View<const double*>& mass, const View<const int*>& cellMaterial,
                         const View<const Material*>& materials, const ConstField& xNew, const ConstField& vnode,
                         double dt, const ConstField& sigmaOld, const Field& sigmaNew, const Field& stateNew,
                         const View<double*>& plasticHint = View<double*>(), const ConstField& fluxState = ConstField(),
                         const CellGeometry& fluxGeom = CellGeometry(), const Field& increment = Field(),
                         const View<double*>& plasticWork = View<double*>())
{
    static_assert(P::strain, "strainUpdate is for the strain variants");
    const bool keep = increment.extent(0) > 0;
    const bool count = plasticWork.extent(0) > 0;
    using S = StateLayout<D, P>;
    const bool midpoint = fluxState.extent(0) > 0;
    auto corner = midpoint ? fluxGeom.corner : geom.corner;
    auto volume = geom.volume;
    auto fluxVolume = midpoint ? fluxGeom.volume : geom.volume;
    auto transported = midpoint ? fluxState : state;
    auto update = KOKKOS_LAMBDA(const LO i, double (&ext)[3])
    {
        captureBeforeConstexpr(plasticHint, plasticWork, count);
        const Material& m = materials(cellMaterial(i));
        const gpr::Sym3 G0 = loadSym3(state, i, S::G);
        const double newVolume = cellVolumeAt<D>(mesh, xNew, i);
        const double ratio = newVolume / volume(i);
        ext[1] = lesser(ext[1], ratio);
        bool bad = !(ratio > 0.0);
        if (m.strainLaw == StrainNone || bad)
        {
            storeSym3(stateNew, i, S::G, G0);
            storeSym3(sigmaNew, i, 0, gpr::Sym3{0, 0, 0, 0, 0, 0});
            if (keep)
                storeSym3(increment, i, 0, gpr::Sym3{0, 0, 0, 0, 0, 0});
        }
        else
        {
            const double rho = mass(i) / newVolume;
            const Mat<3> L = cellVelocityGradient<D>(mesh, vnode, corner, i, 1.0 / fluxVolume(i));
            const gpr::Sym3 dT = (-dt) * gpr::transportRate(midpoint ? loadSym3(transported, i, S::G) : G0, L);
            if (keep)
                storeSym3(increment, i, 0, dT);
            gpr::Sym3 G;
            if constexpr (P::plastic)
                G = m.strainLaw == StrainPlastic
                        ? gpr::relaxPlasticStrain(G0 + dT, rho, m.csh, dt, m.tau10, m.sigmaY, m.exponent,
                                                  &plasticHint(i), count ? &plasticWork(i) : nullptr)
                        : gpr::transportAndRelax(G0, dT, dt, m.tau1);
            else
                G = gpr::transportAndRelax(G0, dT, dt, m.tau1);
            const gpr::Sym3 sigma = gpr::shearStress(rho, m.csh, G);
            storeSym3(stateNew, i, S::G, G);
            storeSym3(sigmaNew, i, 0, sigma);
            const double an = aux(i, Aux::sound);
            const double za = an * an / state(i, S::omega); // rho a^2 at t^n (not z a: z carries the shock term)
            const double change =
                Kokkos::Experimental::sqrt(gpr::norm2(sigma - loadSym3(sigmaOld, i, 0))) / za;
            // admissible: G SPD (det and trace positive), finite stress
            const double dG = gpr::det(G);
            bad = !(dG > 0.0) || !(gpr::trace(G) > 0.0) || !(change == change);
            ext[0] = lesser(ext[0], bad ? -1e300 : -change);
        }
        if (bad)
            ext[2] = lesser(ext[2], double(i));
    };
    double ext[3];
    minReduce<3>("unilag::gpr::strain_update", mesh.nOwnedCells, update, ext, P::plastic);
    const bool bad = ext[2] < double(mesh.nOwnedCells);
    return PicardCheck{-ext[0], ext[1], bad ? LO(ext[2]) : LO(-1)};
}

} // namespace unilag
