/*! \file Heat.hpp
 *  \brief Explicit Rusanov heat-conduction fluxes of the GPR model at t^n (docs/gpr-model.md 2.3): the conduction rates
 *  of the total energy and of the thermal impulse J of every owned cell.
 *
 *  With m_i dE_i/dt = -sum_f (q.n)_f s_f and m_i dJ_i/dt = -sum_f (theta I . n)_f s_f over the NV faces of cell i,
 *  the face fluxes between cell i and the cell j across the face (n the unit normal out of i, s_f the face area)
 *  are, first order (cell values on both sides; order 2 below):
 *     (q.n)_f         = 1/2 (q_i + q_j) . n      - 1/2 lambda_f rho_f (eps_j - eps_i)
 *     (theta I . n)_f = 1/2 (theta_i + theta_j) n - 1/2 lambda_f rho_f (J_j - J_i)
 *  with the heat flux q = alpha^2 theta J (docs/gpr-model.md 1.2), lambda_f = max(c_h,i, c_h,j),
 *  rho_f = (rho_i + rho_j)/2.
 *  Documented choices (they differ from the paper's fluxes, docs/gpr-model.md 2.3):
 *   - c_h = (alpha / rho) sqrt(theta / cv): the speed of the heat subsystem with the LOCAL density. The paper
 *     writes rho0 (docs/gpr-model.md 1.2), which underestimates the speed where rho < rho0 and makes the explicit
 *     scheme unstable there.
 *     Only c_h enters lambda_f: the Rusanov viscosity of the heat subsystem, not the full signal speed a_i.
 *   - The energy flux dissipates the jump of the specific INTERNAL energy eps, not of E as in the paper, so that
 *     jumps of kinetic and elastic energy are not diffused by heat conduction; the factor rho_f makes the units
 *     those of the conserved quantity rho E (and rho J in the J flux).
 *   - Materials with heat == 0 neither conduct nor receive: their rates are zero, and a face between a
 *     conducting cell and a non-conducting one is adiabatic (mirror state) for the conducting cell.
 *  Boundary faces (cellFaceGroup >= 0) take a ghost state from bc.thermal of the group:
 *   - adiabatic:  theta_g = theta_i, eps_g = eps_i, J_g = J_i - 2 (J_i . n) n, rho_g = rho_i; evaluated in closed
 *     form, (q.n)_f = 0 exactly and (theta I . n)_f = (theta_i + c_h,i rho_i J_i . n) n;
 *   - isothermal: theta_g = theta_w = bc.temperature(g), eps_g = eps_i + cv (theta_w - theta_i) (ideal-gas-like;
 *     it only sets the dissipation), J_g = J_i, rho_g = rho_i, same material as cell i.
 *  An interior face without a local neighbour (never for owned cells of a DistributedMesh) is adiabatic.
 *
 *  Order 2 (Faces::rec given: the fluxes at t^n and of the midpoint or stage state). Each side's theta, eps and J are
 *  its limited linear reconstruction at the face centre x_f, w_i,f = w_i + grad w_i . (x_f - x_i) (heat::Quantities,
 *  with the least squares and limiter of Reconstruction.hpp, bounding the face-centre values), in the central part and
 *  the jump alike; c_h and q from these values, rho_f still the mean of the cell densities. The jumps are then
 *  O(h^2) in smooth regions, so that the Rusanov dissipation no longer adds an O(h) diffusivity to the Fourier limit.
 *  Boundary faces use the side's face values in the ghost states above. x_f is computed alike from both cells
 *  (faceCentre), and a side's values depend on (cell, x_f) only: the two evaluations of a face stay exact negatives.
 *
 *  Conservation. Each cell sums its own faces (no atomics; bitwise independent of the thread count and, with
 *  the ghost layer, of the partition). A face flux is computed twice, once from each side, and the two results
 *  are exact negatives in floating point: the formulas are symmetric in (i, j) up to the exactly antisymmetric
 *  differences (a - b = -(b - a) in IEEE arithmetic, sums and max commute), and the face area vector is the
 *  antisymmetrised S_ij = (A_i - A_j)/2 of the two cells' outward area vectors A = -D c_k (each cell computes
 *  its corner vectors from its own node order, so A_i = -A_j holds only to round-off for tetrahedra; it is exact
 *  for triangles). Hence the total energy exchanged between owned cells sums to zero up to the round-off of the
 *  per-cell sums. The per-cell quantities of both sides are products and quotients only (no FMA contraction can
 *  make them differ between the two evaluations). Order 2 adds the dot products grad w . (x_f - x_i), the same
 *  expression (sideAt) in both evaluations: the x86-64 build (no -mfma) contracts none; under CUDA, which contracts
 *  by default, the exact antisymmetry at order 2 is not yet checked (-fmad=false would guarantee it).
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Gpr.hpp"
#include "unilag/Physics.hpp"
#include "unilag/Reconstruction.hpp"
#include "unilag/Reduce.hpp"

namespace unilag
{
namespace heat
{

//! What a face flux needs from one side: density, temperature, internal energy, heat speed, q = alpha^2 theta J.
template <int D>
struct Side
{
    double rho, theta, eps, ch;
    double alpha, alpha2, cv;
    Vec<D> J, q;
    int heat; //!< material conducts
};

//! Heat-subsystem speed c_h = (alpha / rho) sqrt(theta / cv) with the local density (see the file comment).
KOKKOS_INLINE_FUNCTION double heatSpeed(double alpha, double rho, double theta, double cv)
{
    return alpha / rho * Kokkos::Experimental::sqrt(Kokkos::Experimental::fmax(theta / cv, 0.0));
}

/*! \brief Fluxes (q.n) s and (theta I . n) s through a face of area vector S (s = |S|, pointing from a to b).
 *  Swapping a and b and negating S gives exactly the negated results. */
template <int D>
KOKKOS_INLINE_FUNCTION void rusanov(const Side<D>& a, const Side<D>& b, const Vec<D>& S, double s, double& fE,
                                    Vec<D>& fJ)
{
    const double lambda = Kokkos::Experimental::fmax(a.ch, b.ch);
    const double diss = 0.5 * lambda * (0.5 * (a.rho + b.rho)) * s;
    double qS = 0.0;
    for (int d = 0; d < D; ++d)
        qS += (a.q[d] + b.q[d]) * S[d];
    fE = 0.5 * qS - diss * (b.eps - a.eps);
    const double theta = 0.5 * (a.theta + b.theta);
    for (int d = 0; d < D; ++d)
        fJ[d] = theta * S[d] - diss * (b.J[d] - a.J[d]);
}

/*! Order 2: the heat quantities' reconstruction (limitedGradientsOf; columns q * D + d of the gradient field) and
 *  their boundary treatment: adiabatic faces mirror the cell (J reflected, as the ghost state), an isothermal wall's
 *  temperature is boundary data of theta. */
template <int D, class P>
struct Quantities
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        theta = 0,      //!< quantities (J: D of them)
        eps = 1,
        J = 2,
        nq = 2 + D,     //!< quantities
        ncomp = nq * D, //!< columns of the gradient field
        bdata = theta
    };
    static constexpr bool atFaces = true; //!< the fluxes use face-centre values only: bound those
    ConstField state, aux;
    BoundaryView bc;

    KOKKOS_INLINE_FUNCTION void values(LO j, double (&w)[nq]) const
    {
        w[theta] = aux(j, Aux::theta);
        w[eps] = aux(j, Aux::eps);
        for (int d = 0; d < D; ++d)
            w[J + d] = state(j, StateLayout<D, P>::J + d);
    }
    KOKKOS_INLINE_FUNCTION Bounds bounds(Limiter limiter, int) const { return uniformBounds(limiter); }
    KOKKOS_INLINE_FUNCTION bool mirrors(int g) const { return bc.thermal(g) != ThermalIsothermal; }
    KOKKOS_INLINE_FUNCTION void mirror(const Vec<D>& n, double (&w)[nq]) const
    {
        double jn = 0.0;
        for (int a = 0; a < D; ++a)
            jn += w[J + a] * n[a];
        for (int a = 0; a < D; ++a)
            w[J + a] -= 2.0 * jn * n[a];
    }
    KOKKOS_INLINE_FUNCTION bool boundaryValue(int g, double& value) const
    {
        if (bc.thermal(g) != ThermalIsothermal)
            return false;
        value = bc.temperature(g);
        return true;
    }
};

/*! Centre of face k of cell i (the mean of its vertices), bitwise the same from either cell of the face: in 3D the
 *  three coordinates are summed in increasing order (the cells list the face's nodes in different orders). */
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> faceCentre(const MeshView<D>& mesh, const ConstField& x, LO i, int k)
{
    LO fv[D];
    int nf = 0;
    for (int m = 0; m < D + 1; ++m)
        if (m != k)
            fv[nf++] = mesh.cellNodes(i, m);
    Vec<D> c;
    for (int a = 0; a < D; ++a)
    {
        if constexpr (D == 2)
            c[a] = 0.5 * (x(fv[0], a) + x(fv[1], a));
        else
        {
            using Kokkos::Experimental::fmax, Kokkos::Experimental::fmin;
            const double u = x(fv[0], a), v = x(fv[1], a), w = x(fv[2], a);
            const double lo = fmin(u, fmin(v, w)), hi = fmax(u, fmax(v, w));
            const double mid = fmax(fmin(u, v), fmin(fmax(u, v), w)); // the median
            c[a] = (lo + mid + hi) / 3.0;
        }
    }
    return c;
}

//! Adiabatic face (mirror state) in closed form: (q.n) s = 0, (theta I . n) s = (theta + c_h rho J.n) n s.
template <int D>
KOKKOS_INLINE_FUNCTION void adiabatic(const Side<D>& a, const Vec<D>& S, double s, double& fE, Vec<D>& fJ)
{
    fE = 0.0;
    const double coef = a.theta + a.ch * a.rho * (dot(a.J, S) / s);
    for (int d = 0; d < D; ++d)
        fJ[d] = coef * S[d];
}

//! The face fluxes of the cells of one mesh (a functor the kernel calls per face; also callable from tests).
template <int D, class P>
struct Faces
{
    static constexpr int NV = D + 1;
    using S = StateLayout<D, P>;
    static_assert(P::heat, "heat fluxes need the J columns (a Physics with heat)");

    MeshView<D> mesh;
    BoundaryView bc;
    ConstField state, aux;
    RowField corner;
    View<const int*> cellMaterial;
    View<const Material*> materials;
    Reconstruction<D> rec; //!< order 2: Quantities' gradients (empty: cell values, first order)

    //! Side of cell i with the given theta, eps, J (its cell values, or reconstructed at a face).
    KOKKOS_INLINE_FUNCTION Side<D> side(LO i, double theta, double eps, const Vec<D>& J) const
    {
        const Material& m = materials(cellMaterial(i));
        Side<D> s;
        s.heat = m.heat;
        s.rho = 1.0 / state(i, S::omega);
        s.theta = theta;
        s.eps = eps;
        s.alpha = m.alpha;
        s.alpha2 = m.alpha * m.alpha;
        s.cv = m.eos.cv;
        s.ch = heatSpeed(m.alpha, s.rho, s.theta, s.cv);
        for (int d = 0; d < D; ++d)
        {
            s.J[d] = J[d];
            s.q[d] = s.alpha2 * s.theta * s.J[d];
        }
        return s;
    }

    KOKKOS_INLINE_FUNCTION Side<D> side(LO i) const
    {
        Vec<D> J;
        for (int d = 0; d < D; ++d)
            J[d] = state(i, S::J + d);
        return side(i, aux(i, Aux::theta), aux(i, Aux::eps), J);
    }

    /*! Side of cell i at the face centre xf: theta, eps, J reconstructed (w_i + grad w_i . (xf - x_i)), rho the cell's.
     *  A function of (i, xf) only, so that both cells of a face evaluate it bitwise alike. */
    KOKKOS_INLINE_FUNCTION Side<D> sideAt(LO i, const Vec<D>& xf) const
    {
        using H = Quantities<D, P>;
        Vec<D> dx, J;
        for (int d = 0; d < D; ++d)
            dx[d] = xf[d] - rec.centroid(i, d);
        for (int d = 0; d < D; ++d)
            J[d] = state(i, S::J + d) + rec.delta(i, H::J + d, dx);
        return side(i, aux(i, Aux::theta) + rec.delta(i, H::theta, dx), aux(i, Aux::eps) + rec.delta(i, H::eps, dx), J);
    }

    /*! \brief Fluxes (q.n) s and (theta I . n) s out of cell i (cell values c = side(i)) through its face k. */
    KOKKOS_INLINE_FUNCTION void face(LO i, const Side<D>& c, int k, double& fE, Vec<D>& fJ) const
    {
        const bool second = rec.active();
        Vec<D> xf;
        if (second)
            xf = faceCentre<D>(mesh, rec.x, i, k);
        const Side<D> a = second ? sideAt(i, xf) : c;
        Vec<D> A; // outward area vector of face k
        for (int d = 0; d < D; ++d)
            A[d] = -double(D) * corner(i, k * D + d);
        const int g = mesh.cellFaceGroup(i, k);
        if (g >= 0)
        {
            const double s = norm(A);
            if (bc.thermal(g) == ThermalIsothermal)
            {
                Side<D> b = a;
                b.theta = bc.temperature(g);
                b.eps = a.eps + a.cv * (b.theta - a.theta);
                b.ch = heatSpeed(a.alpha, a.rho, b.theta, a.cv);
                for (int d = 0; d < D; ++d)
                    b.q[d] = a.alpha2 * b.theta * a.J[d];
                rusanov(a, b, A, s, fE, fJ);
            }
            else
                adiabatic(a, A, s, fE, fJ);
            return;
        }
        const LO j = mesh.cellNeighbour(i, k);
        if (j < 0)
        {
            adiabatic(a, A, norm(A), fE, fJ);
            return;
        }
        const Side<D> b = second ? sideAt(j, xf) : side(j);
        A = sharedFaceArea<D>(mesh, corner, i, k, j);
        const double s = norm(A);
        if (!b.heat)
            adiabatic(a, A, s, fE, fJ);
        else
            rusanov(a, b, A, s, fE, fJ);
    }
};

} // namespace heat

/*! Heat-conduction rates of owned cells at t^n: rate(i, 0) = -sum_f (q.n)_f s_f (so m_i dE_i/dt gets this), and
 *  rate(i, 1 + d) = -sum_f (theta I . n)_f,d s_f (m_i dJ_i,d/dt gets this), d < D. Faces of cell i are its NV faces;
 *  interior faces use the neighbour cellNeighbour(i,k); boundary faces a ghost state from bc.thermal of the face group.
 *  Needs state (StateLayout<D,P>: omega, J) and aux (Aux::theta, Aux::eps) on all local cells (owned and ghosts),
 *  geom.corner of the owned cells and their face neighbours; cells of a material with heat == 0 get zero rates.
 *  The flux formulas and the boundary states are described in the file comment. Order 2: rec holds heat::Quantities'
 *  limited gradients of all local cells (ghosts exchanged), the node positions and the centroids; both sides' values
 *  are then reconstructed at the face centres. */
template <int D, class P>
void heatFluxes(const MeshView<D>& mesh, const BoundaryView& bc, const ConstField& state, const ConstField& aux,
                const CellGeometry& geom, const View<const int*>& cellMaterial, const View<const Material*>& materials,
                const Field& rate, const Reconstruction<D>& rec = Reconstruction<D>())
{
    constexpr int NV = D + 1;
    const heat::Faces<D, P> faces{mesh, bc, state, aux, geom.corner, cellMaterial, materials, rec};
    auto cell = KOKKOS_LAMBDA(const LO i)
    {
        const heat::Side<D> a = faces.side(i);
        double rE = 0.0;
        Vec<D> rJ = Vec<D>::zero();
        if (a.heat)
            for (int k = 0; k < NV; ++k)
            {
                double fE;
                Vec<D> fJ;
                faces.face(i, a, k, fE, fJ);
                rE -= fE;
                for (int d = 0; d < D; ++d)
                    rJ[d] -= fJ[d];
            }
        rate(i, 0) = rE;
        for (int d = 0; d < D; ++d)
            rate(i, 1 + d) = rJ[d];
    };
    Kokkos::parallel_for("unilag::heat::fluxes", range(mesh.nOwnedCells), cell);
}

/*! Heat entering the owned cells through isothermal walls, -sum (q.n)_f s_f over their boundary faces: the only heat
 *  that changes the total energy (adiabatic walls pass none, interior faces cancel). For the energy balance. */
template <int D, class P> double boundaryHeatRate(const heat::Faces<D, P>& faces)
{
    constexpr int NV = D + 1;
    auto cell = KOKKOS_LAMBDA(const LO i, double(&acc)[1])
    {
        const heat::Side<D> a = faces.side(i);
        if (!a.heat)
            return;
        for (int k = 0; k < NV; ++k)
        {
            const int g = faces.mesh.cellFaceGroup(i, k);
            if (g < 0 || faces.bc.thermal(g) != ThermalIsothermal)
                continue;
            double fE;
            Vec<D> fJ;
            faces.face(i, a, k, fE, fJ);
            acc[0] -= fE;
        }
    };
    double sum[1];
    sumReduce<1>("unilag::check::boundary_heat", faces.mesh.nOwnedCells, cell, sum);
    return sum[0];
}

} // namespace unilag
