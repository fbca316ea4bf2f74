/*! \file LeastSquares.hpp
 *  \brief The limited least-squares gradients of the second-order reconstruction (docs/gpr-model.md 2.5), in two
 *  kernels: sums over the cells around each node, then each cell's gradient from its nodes' sums.
 *
 *  The gradient of cell i minimises sum_r sum_{j around r} w_jr (u_j - u_i - g . (x_j - x_i))^2 over the cells j
 *  around each node r of cell i (a face neighbour once per shared node), with the weight w_jr = 1 / |x_j - x_r|^2 of
 *  cell j's distance to the node, not to cell i. That weight makes the normal equations separable: with
 *  e_j = x_j - x_r and a_j = u_j - u_ref (u_ref: the node's first cell, which keeps the sums small where u is
 *  nearly uniform),
 *      A_i = sum_r [S2 - S1 e_i^T - e_i S1^T + S0 e_i e_i^T],
 *      b_i = sum_r [T1 - T0 e_i - a_i (S1 - S0 e_i)],
 *  where S0 = sum w, S1 = sum w e, S2 = sum w e e^T, T0 = sum w a, T1 = sum w a e over the cells around r (cell i's
 *  own term vanishes: e_j - e_i = 0). nodeSums forms them once per node; each cell then reads D + 1 rows instead
 *  of visiting the ~6 (2D) or ~24 (3D) cells around each of its nodes. Until session 24 the weight was
 *  1 / |x_j - x_i|^2 and every cell visited its stencil: 4.4x a first-order step's cost for the 3D gradients.
 *  At mirroring nodes (slip walls, symmetry planes) the images of the cells around the node join the sums, and the
 *  vertex bounds (Bounds::Vertex) are the sums' extrema of the same cells.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"

namespace unilag
{

//! Outward unit normal of face f (opposite local vertex f) of cell i on the configuration x, and one of its vertices.
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> faceUnitNormal(const MeshView<D>& mesh, const ConstField& x, LO i, int f, LO& vertex)
{
    LO fv[D];
    int nf = 0;
    for (int k = 0; k < D + 1; ++k)
        if (k != f)
            fv[nf++] = mesh.cellNodes(i, k);
    vertex = fv[0];
    Vec<D> n;
    if constexpr (D == 2)
    {
        n[0] = x(fv[1], 1) - x(fv[0], 1);
        n[1] = x(fv[0], 0) - x(fv[1], 0);
    }
    else
    {
        double a[3], b[3];
        for (int c = 0; c < 3; ++c)
        {
            a[c] = x(fv[1], c) - x(fv[0], c);
            b[c] = x(fv[2], c) - x(fv[0], c);
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
    }
    double inward = 0.0; // towards the opposite vertex: the vertex order alone leaves the sign to the face's index
    for (int a = 0; a < D; ++a)
        inward += n[a] * (x(mesh.cellNodes(i, f), a) - x(fv[0], a));
    return (inward > 0.0 ? -1.0 : 1.0) / norm(n) * n;
}

/*! Limiter of the second-order reconstruction (scene key scheme.limiter). Barth-Jespersen in three bounded forms:
 *  each vertex value stays within the extrema of the cell and its face neighbours (BarthJespersen), and for
 *  VertexBased also of every cell around that vertex (linearity-preserving in the interior, after Kuzmin); NodeFit
 *  widens the face bounds to the node value of the linear fit over the cells around the vertex only (linearity-
 *  preserving too, but as tight as the face bounds on mesh-scale noise: the fit averages it out). */
enum class Limiter
{
    None,
    BarthJespersen,
    VertexBased,
    NodeFit
};

//! How limitedGradientsOf bounds one quantity: what a Limiter means for it (the Q's bounds()).
enum class Bounds
{
    Unlimited,      //!< the least-squares gradient
    FaceNeighbours, //!< vertex values within the extrema of the cell and its face neighbours
    Vertex,         //!< ... or of every cell around the vertex
    NodeFit,        //!< ... or the vertex's value of the linear fit over the cells around it
    CellValue       //!< not reconstructed: gradient 0
};

//! The bounds a Limiter gives every quantity it limits.
KOKKOS_INLINE_FUNCTION constexpr Bounds uniformBounds(Limiter limiter)
{
    return limiter == Limiter::None          ? Bounds::Unlimited
           : limiter == Limiter::VertexBased ? Bounds::Vertex
           : limiter == Limiter::NodeFit     ? Bounds::NodeFit
                                             : Bounds::FaceNeighbours;
}

/*! The mirroring planes (slip walls, symmetry planes: the groups Q mirrors) through node r, gathered from the faces
 *  at r of one cell j around it (local vertex kj of j is r: the faces of j other than face kj contain r) by the
 *  nodal solver's rule (addWallNormal): a curved wall's faces join one plane, walls meeting at a corner or a wedge
 *  are one each; up to D planes. */
template <int D, class Q>
KOKKOS_INLINE_FUNCTION void addMirrorPlanes(const MeshView<D>& mesh, const Q& quantities, const ConstField& x, LO j,
                                            int kj, Vec<D> (&plane)[D], int& nPlanes)
{
    for (int f = 0; f < D + 1; ++f)
    {
        const int g = f == kj ? -1 : mesh.cellFaceGroup(j, f);
        if (g < 0 || !quantities.mirrors(g))
            continue;
        LO vertex;
        addWallNormal<D>(faceUnitNormal<D>(mesh, x, j, f, vertex), plane, nPlanes);
    }
}

//! Columns of a node's row of least-squares sums (NQ quantities; PerVertex: their extrema too).
template <int D, int NQ, bool PerVertex>
struct NodeSumLayout
{
    enum : int
    {
        count = 0,                         //!< number of terms (cells and images)
        s0 = 1,                            //!< sum w
        s1 = 2,                            //!< sum w e, D columns
        s2 = 2 + D,                        //!< sum w e e^T, upper triangle row by row
        q0 = 2 + D + D * (D + 1) / 2,      //!< per quantity: u_ref, sum w a, sum w a e (D)
        perQ = 2 + D,
        lo = q0 + NQ * perQ,               //!< PerVertex: min of each quantity around the node
        hi = lo + NQ,                      //!< PerVertex: max of each quantity
        ncol = lo + (PerVertex ? 2 * NQ : 0),
    };
    KOKKOS_INLINE_FUNCTION static constexpr int sym(int a, int b) { return s2 + a * D - a * (a - 1) / 2 + (b - a); }
};

//! Work space of the node sums, kept from call to call (a caller without one gets a fresh allocation).
struct GradientScratch
{
    Kokkos::View<double**, MemSpace> sums;
    Kokkos::View<double**, MemSpace> rows(LO nNodes, int ncol)
    {
        if (LO(sums.extent(0)) < nNodes || int(sums.extent(1)) < ncol)
            sums = Kokkos::View<double**, MemSpace>(Kokkos::view_alloc(Kokkos::WithoutInitializing,
                                                                       "unilag::recon::node_sums"),
                                                    nNodes, ncol);
        return sums;
    }
};

/*! One cell (or image) around a node, at e from the node with values wj: its terms of the node's sums (S0, S1, S2,
 *  T0, T1 against the reference values ref) and of its extrema. */
template <int D, int NQ, bool PerVertex>
KOKKOS_INLINE_FUNCTION void addNodeTerm(const Vec<D>& e, const double (&wj)[NQ], const double (&ref)[NQ], int nFit,
                                        double (&s)[NodeSumLayout<D, NQ, PerVertex>::ncol])
{
    using L = NodeSumLayout<D, NQ, PerVertex>;
    const double w = 1.0 / dot(e, e);
    s[L::count] += 1.0;
    s[L::s0] += w;
    for (int a = 0; a < D; ++a)
    {
        s[L::s1 + a] += w * e[a];
        for (int b = a; b < D; ++b)
            s[L::sym(a, b)] += w * e[a] * e[b];
    }
    for (int q = 0; q < NQ; ++q) // to NQ, not nFit: a compile-time trip count keeps s in registers on a GPU
    {
        if (q >= nFit)
            continue;
        const double wa = w * (wj[q] - ref[q]);
        double* t = s + L::q0 + q * L::perQ;
        t[1] += wa;
        for (int a = 0; a < D; ++a)
            t[2 + a] += wa * e[a];
        if constexpr (PerVertex)
        {
            s[L::lo + q] = lesser(s[L::lo + q], wj[q]);
            s[L::hi + q] = greater(s[L::hi + q], wj[q]);
        }
    }
}

/*! The node value of each fitted quantity's weighted linear fit over the node's cells (and images) from its sums s,
 *  min_{c,b} sum w (a - c - b.e)^2: exact for a linear field. False where the cells do not span D directions (a
 *  corner node with one cell). */
template <int D, int NQ>
KOKKOS_INLINE_FUNCTION bool nodeFitValues(const double (&s)[NodeSumLayout<D, NQ, true>::ncol], int nFit,
                                          double (&atNode)[NQ])
{
    using L = NodeSumLayout<D, NQ, true>;
    const double s0 = s[L::s0];
    if (!(s[L::count] > D) || !(s0 > 0.0))
        return false;
    Vec<D> mean; // S1 / S0
    for (int a = 0; a < D; ++a)
        mean[a] = s[L::s1 + a] / s0;
    Mat<D> C; // the fit's normal matrix once c is eliminated: S2 - S1 S1^T / S0 (dimensionless, as A of a cell)
    double trace = 0.0;
    for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b)
        {
            C.a[a][b] = s[L::sym(a < b ? a : b, a < b ? b : a)] - s[L::s1 + a] * mean[b];
            trace += a == b ? C.a[a][a] : 0.0;
        }
    const double det = determinant(C), scale = trace / D;
    if (!(det > 1e-10 * (D == 2 ? scale * scale : scale * scale * scale)))
        return false;
    for (int q = 0; q < NQ; ++q) // to NQ, not nFit: a compile-time trip count keeps s in registers on a GPU
    {
        if (q >= nFit)
            continue;
        const double* t = s + L::q0 + q * L::perQ; // u_ref, T0 = sum w a, T1 = sum w a e
        Vec<D> rhs;
        for (int a = 0; a < D; ++a)
            rhs[a] = t[2 + a] - mean[a] * t[1];
        const Vec<D> b = solve(C, rhs);
        double c = t[1];
        for (int a = 0; a < D; ++a)
            c -= s[L::s1 + a] * b[a];
        atNode[q] = t[0] + c / s0;
    }
    return true;
}

/*! The per-vertex bounds (columns lo, hi of s, which hold the extrema of the node's cells and images) of the
 *  quantities bounded by Vertex or NodeFit. openBoundary: a boundary node without mirror images, whose cells lie on
 *  one side of it, so that their extrema do not bound a linear field's value there: Vertex bounds are widened by the
 *  node fit (before, they clipped linear fields at every such vertex: a spinning elastic ring kept 78% of its
 *  kinetic energy over half a turn; docs/gpr-model.md 3.11). NodeFit bounds are the node fit alone, clamped to the
 *  extrema inside (a least-squares fit may overshoot its data; so NodeFit stays within Vertex's bounds); where no fit
 *  exists they are empty, which leaves the face bounds. */
template <int D, class Q>
KOKKOS_INLINE_FUNCTION void nodeBounds(const Q& quantities, Limiter limiter, bool openBoundary, int nFit,
                                       double (&s)[NodeSumLayout<D, Q::nq, true>::ncol])
{
    using L = NodeSumLayout<D, Q::nq, true>;
    bool needed = false; // the fit (a D x D solve per quantity) only where some bound takes it
    for (int q = 0; q < Q::nq; ++q)
    {
        const Bounds bounds = quantities.bounds(limiter, q);
        needed = needed || (q < nFit && (bounds == Bounds::NodeFit || (bounds == Bounds::Vertex && openBoundary)));
    }
    if (!needed)
        return;
    double atNode[Q::nq];
    const bool fitted = nodeFitValues<D, Q::nq>(s, nFit, atNode);
    for (int q = 0; q < Q::nq; ++q)
    {
        if (q >= nFit)
            continue;
        const Bounds bounds = quantities.bounds(limiter, q);
        double& lo = s[L::lo + q];
        double& hi = s[L::hi + q];
        if (bounds == Bounds::Vertex && openBoundary && fitted)
        {
            lo = lesser(lo, atNode[q]);
            hi = greater(hi, atNode[q]);
        }
        else if (bounds == Bounds::NodeFit)
        {
            const double v = !fitted ? 0.0 : openBoundary ? atNode[q] : greater(lo, lesser(hi, atNode[q]));
            lo = fitted ? v : 1e300;
            hi = fitted ? v : -1e300;
        }
    }
}

/*! The least-squares sums of every local node whose cells are all local (the nodes of owned cells; the others' rows
 *  are not read), the images across the mirroring planes through the node included. */
template <int D, class Q, bool PerVertex>
void nodeSums(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom, const ConstField& x,
              const Kokkos::View<double**, MemSpace>& sums, bool hasBc, Limiter limiter, int nFit)
{
    constexpr int NV = D + 1;
    constexpr int NQ = Q::nq;
    using L = NodeSumLayout<D, NQ, PerVertex>;
    auto centroid = geom.centroid;
    auto node = KOKKOS_LAMBDA(const LO r)
    {
        const int fitted = nFit; // captured here: nvcc refuses a lambda's first capture inside `if constexpr`
        const Limiter bounded = limiter; // likewise captured here, for the same reason
        double s[L::ncol], ref[NQ] = {}, wj[NQ]; // ref stays 0 at a node without corners (never a local one)
        for (int c = 0; c < L::ncol; ++c)
            s[c] = 0.0;
        const LO begin = mesh.nodeCornerOffsets(r), end = mesh.nodeCornerOffsets(r + 1);
        if (begin < end)
            quantities.values(mesh.nodeCorners(begin) / NV, ref);
        for (int q = 0; q < NQ; ++q)
        {
            if (q >= fitted)
                continue;
            s[L::q0 + q * L::perQ] = ref[q];
            if constexpr (PerVertex)
                s[L::lo + q] = s[L::hi + q] = ref[q];
        }
        Vec<D> xr, plane[D];
        for (int a = 0; a < D; ++a)
            xr[a] = x(r, a);
        int nPlanes = 0;
        const bool boundaryNode = hasBc && mesh.mayBeOnBoundary(r);
        for (LO c = begin; c < end; ++c)
        {
            const LO j = mesh.nodeCorners(c) / NV;
            if (boundaryNode)
                addMirrorPlanes<D>(mesh, quantities, x, j, mesh.nodeCorners(c) % NV, plane, nPlanes);
            Vec<D> e;
            for (int a = 0; a < D; ++a)
                e[a] = centroid(j, a) - xr[a];
            quantities.values(j, wj);
            addNodeTerm<D, NQ, PerVertex>(e, wj, ref, fitted, s);
        }
        // The images of every cell around the node across each plane and their compositions: the cells of the
        // symmetric flow around it. An image reflects through the span of its planes: reflections across planes
        // that are not orthogonal (deformed free sides, an arc meeting a plane) do not commute, and the order in
        // which the planes are found follows the cell numbering, which a rotated mesh changes.
        for (int image = 1; image < (1 << nPlanes); ++image)
        {
            Vec<D> chosen[D], basis[D];
            int nChosen = 0;
            for (int p = 0; p < nPlanes; ++p)
                if (image & (1 << p))
                    chosen[nChosen++] = plane[p];
            const int nBasis = orthonormalBasis<D>(chosen, nChosen, basis);
            for (LO c = begin; c < end; ++c)
            {
                const LO j = mesh.nodeCorners(c) / NV;
                Vec<D> e;
                for (int a = 0; a < D; ++a)
                    e[a] = centroid(j, a) - xr[a];
                quantities.values(j, wj);
                for (int b = 0; b < nBasis; ++b)
                {
                    e = e - (2.0 * dot(e, basis[b])) * basis[b];
                    quantities.mirror(basis[b], wj);
                }
                addNodeTerm<D, NQ, PerVertex>(e, wj, ref, fitted, s);
            }
        }
        if constexpr (PerVertex)
            nodeBounds<D>(quantities, bounded, boundaryNode && nPlanes == 0 && mesh.onBoundary(r), fitted, s);
        for (int c = 0; c < L::ncol; ++c)
            sums(r, c) = s[c];
    };
    Kokkos::parallel_for("unilag::recon::node_sums", range(mesh.nNodes), node);
}

/*! The limited gradients of cell i from the normal equations A g = rhs[q] of its stencil (wi: its values; dx: its
 *  vertices' offsets from the centroid; vmin, vmax: PerVertex, the extrema around each vertex), into grad: the
 *  bounds over the face neighbours, an imposed value of quantity Q::bdata as boundary data (weighing as D stencil
 *  members of weight dataWeight / |d|^2), Barth-Jespersen. */
template <int D, class Q, bool PerVertex>
KOKKOS_INLINE_FUNCTION void limitCellGradients(const MeshView<D>& mesh, const Q& quantities, const ConstField& x,
                                               const Field& grad, LO i, const double (&wi)[Q::nq],
                                               const Vec<D> (&dx)[D + 1], const Mat<D>& A, const Vec<D> (&rhs)[Q::nq],
                                               const double (&vmin)[PerVertex ? D + 1 : 1][Q::nq],
                                               const double (&vmax)[PerVertex ? D + 1 : 1][Q::nq], bool hasBc,
                                               Limiter limiter, int nFit, double dataWeight)
{
    constexpr int NV = D + 1;
    constexpr int NQ = Q::nq;
    constexpr int BQ = Q::bdata;
    const bool fitBQ = BQ < nFit;
    double wj[NQ], wmin[NQ], wmax[NQ]; // wmin, wmax: over the cell and its face neighbours
    double pmin[NV], pmax[NV];         // bounds of quantity BQ per vertex, with imposed boundary values
    for (int q = 0; q < NQ; ++q)
        wmin[q] = wmax[q] = wi[q];
    // Bounds over the face neighbours. Across a slip wall or symmetry plane (a group Q mirrors) the cell's mirror
    // image stands in for the neighbour (its images joined the node sums, once per vertex on the plane).
    for (int f = 0; f < NV; ++f)
    {
        const LO j = mesh.cellNeighbour(i, f);
        if (j >= 0)
            quantities.values(j, wj);
        else
        {
            const int g = hasBc ? mesh.cellFaceGroup(i, f) : -1;
            if (g < 0 || !quantities.mirrors(g))
                continue;
            LO vertex;
            const Vec<D> n = faceUnitNormal<D>(mesh, x, i, f, vertex);
            for (int q = 0; q < NQ; ++q)
                wj[q] = wi[q];
            quantities.mirror(n, wj);
        }
        for (int q = 0; q < nFit; ++q)
        {
            wmin[q] = lesser(wmin[q], wj[q]);
            wmax[q] = greater(wmax[q], wj[q]);
        }
    }
    for (int k = 0; k < NV; ++k)
    {
        pmin[k] = wmin[BQ];
        pmax[k] = wmax[BQ];
    }
    Mat<D> Ap = A;                   // quantity BQ's own fit: imposed boundary values are data at their faces
    Vec<D> rhsp = rhs[BQ];
    if (hasBc && fitBQ)
        for (int f = 0; f < NV; ++f)
        {
            const int g = mesh.cellFaceGroup(i, f);
            double pb;
            if (g < 0 || !quantities.boundaryValue(g, pb))
                continue;
            Vec<D> d = Vec<D>::zero(); // face centroid - cell centroid
            for (int k = 0; k < NV; ++k)
                if (k != f)
                    d = d + (1.0 / D) * dx[k];
            const double w = double(D) * dataWeight / dot(d, d); // as D stencil members of mean weight, at |d|
            Ap.addOuter(w, d);
            rhsp = rhsp + (w * (pb - wi[BQ])) * d;
            for (int k = 0; k < NV; ++k) // the vertices of face f
                if (k != f)
                {
                    pmin[k] = lesser(pmin[k], pb);
                    pmax[k] = greater(pmax[k], pb);
                }
        }
    // A = sum w d d^T is dimensionless (w = 1/|d|^2); a stencil that does not span D directions gives no gradient.
    double trace = 0.0;
    for (int a = 0; a < D; ++a)
        trace += A.a[a][a];
    const double det = determinant(A), scale = trace / D;
    const bool spans = det > 1e-10 * (D == 2 ? scale * scale : scale * scale * scale);
    for (int q = 0; q < NQ; ++q)
    {
        const Bounds bounds = quantities.bounds(limiter, q);
        if (bounds == Bounds::CellValue) // every q >= nFit too
        {
            for (int a = 0; a < D; ++a)
                grad(i, q * D + a) = 0.0;
            continue;
        }
        const Vec<D> g = !spans ? Vec<D>::zero() : q == BQ ? solve(Ap, rhsp) : solve(A, rhs[q]);
        // Barth-Jespersen: the largest phi in [0, 1] that keeps every vertex value within its bounds, or
        // (Q::atFaces) every face-centre value within the widest bounds of the face's vertices.
        double vhi[NV], vlo[NV];
        for (int k = 0; k < NV; ++k)
        {
            vhi[k] = q == BQ ? pmax[k] : wmax[q];
            vlo[k] = q == BQ ? pmin[k] : wmin[q];
            if constexpr (PerVertex)
                if (bounds == Bounds::Vertex || bounds == Bounds::NodeFit)
                {
                    vhi[k] = greater(vhi[k], vmax[k][q]);
                    vlo[k] = lesser(vlo[k], vmin[k][q]);
                }
        }
        double phi = 1.0;
        for (int k = 0; k < NV && bounds != Bounds::Unlimited; ++k)
        {
            double dw = dot(g, dx[k]), hi = vhi[k], lo = vlo[k];
            if constexpr (Q::atFaces)
            {
                dw = -dw / D; // face k, opposite vertex k: its centre is at -dx_k / D from the centroid
                hi = vhi[(k + 1) % NV];
                lo = vlo[(k + 1) % NV];
                for (int m = 0; m < NV; ++m)
                    if (m != k)
                    {
                        hi = greater(hi, vhi[m]);
                        lo = lesser(lo, vlo[m]);
                    }
            }
            if (dw > 0.0)
                phi = lesser(phi, (hi - wi[q]) / dw);
            else if (dw < 0.0)
                phi = lesser(phi, (lo - wi[q]) / dw);
        }
        for (int a = 0; a < D; ++a)
            grad(i, q * D + a) = phi * g[a];
    }
}

/*! The cells' normal equations from their nodes' sums (file comment), then limitCellGradients. */
template <int D, class Q, bool PerVertex>
void gradientsFromNodeSums(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom,
                           const ConstField& x, const Kokkos::View<const double**, MemSpace>& sums, const Field& grad,
                           bool hasBc, Limiter limiter, int nFit)
{
    constexpr int NV = D + 1;
    constexpr int NQ = Q::nq;
    constexpr int NVB = PerVertex ? NV : 1;
    using L = NodeSumLayout<D, NQ, PerVertex>;
    auto centroid = geom.centroid;
    auto gradient = KOKKOS_LAMBDA(const LO i)
    {
        const int fitted = nFit; // captured here: nvcc refuses a lambda's first capture inside `if constexpr`
        double wi[NQ], vmin[NVB][NQ], vmax[NVB][NQ];
        Vec<D> rhs[NQ], dx[NV];
        quantities.values(i, wi);
        for (int q = 0; q < NQ; ++q)
            rhs[q] = Vec<D>::zero();
        Mat<D> A = Mat<D>::zero();
        double members = 0.0; // of the stencil: the terms of the nodes' sums but cell i's own
        for (int k = 0; k < NV; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            members += sums(r, L::count) - 1.0;
            Vec<D> e, s1; // e_i = x_i - x_r
            for (int a = 0; a < D; ++a)
            {
                dx[k][a] = x(r, a) - centroid(i, a);
                e[a] = -dx[k][a];
                s1[a] = sums(r, L::s1 + a);
            }
            const double s0 = sums(r, L::s0);
            for (int a = 0; a < D; ++a)
                for (int b = a; b < D; ++b)
                {
                    const double t = sums(r, L::sym(a, b)) - s1[a] * e[b] - e[a] * s1[b] + s0 * e[a] * e[b];
                    A.a[a][b] += t;
                    if (b != a)
                        A.a[b][a] += t;
                }
            const Vec<D> s1e = s1 - s0 * e; // S1 - S0 e_i
            for (int q = 0; q < NQ; ++q)
            {
                if (q >= fitted)
                    continue;
                const int t = L::q0 + q * L::perQ;
                const double ai = wi[q] - sums(r, t), t0 = sums(r, t + 1);
                for (int a = 0; a < D; ++a)
                    rhs[q][a] += sums(r, t + 2 + a) - t0 * e[a] - ai * s1e[a];
                if constexpr (PerVertex)
                {
                    vmin[k][q] = sums(r, L::lo + q);
                    vmax[k][q] = sums(r, L::hi + q);
                }
            }
        }
        // A boundary datum weighs as D members of the stencil's mean w |d|^2 (the trace of A over its members)
        double trace = 0.0;
        for (int a = 0; a < D; ++a)
            trace += A.a[a][a];
        const double dataWeight = members > 0.0 ? trace / members : 1.0;
        limitCellGradients<D, Q, PerVertex>(mesh, quantities, x, grad, i, wi, dx, A, rhs, vmin, vmax, hasBc, limiter,
                                            fitted, dataWeight);
    };
    Kokkos::parallel_for("unilag::recon::limited_gradients", range(mesh.nOwnedCells), gradient);
}

/*! \brief Limited gradients of the owned cells (docs/gpr-model.md 2.5) of the quantities Q into grad (cells x
 *  Q::nq * D), from the cell values of all local cells (current for ghosts too) on the configuration x with geometry
 *  geom (centroids of all local cells). Limiter::None gives the plain least-squares gradients (exact for linear
 *  fields). Which limiter for which flow: README, Limiter.
 *  With bc given, the cell's mirror image across the groups Q mirrors joins the stencil (file comment), and an
 *  imposed boundary value of quantity Q::bdata is boundary data: a point of its least-squares fit at the face
 *  centroid, and a bound of the face's vertices (for the pressure: without the bound the limiter clips every monotone
 *  pressure profile at such a boundary to first order; without the fit Kidder's unlimited shell tangled on coarse
 *  meshes). scratch: the node sums' storage kept between calls (the solver's); without it, allocated here. */
template <int D, class Q>
void limitedGradientsOf(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom, const ConstField& x,
                        const Field& grad, const BoundaryView& bc, Limiter limiter,
                        GradientScratch* scratch = nullptr)
{
    bool perVertex = false; // some quantity needs the extrema around each vertex
    int nFit = 0;           // quantities 0 .. nFit-1 are fitted; those after keep their cell values (Q's bounds)
    for (int q = 0; q < Q::nq; ++q)
    {
        const Bounds bounds = quantities.bounds(limiter, q);
        perVertex = perVertex || bounds == Bounds::Vertex || bounds == Bounds::NodeFit;
        if (bounds != Bounds::CellValue)
            nFit = q + 1;
    }
    // Without vertex bounds the node sums carry no extrema and the cells no per-vertex arrays (NV x NQ x 2 doubles in
    // a GPU thread's local memory).
    GradientScratch local;
    GradientScratch& work = scratch ? *scratch : local;
    const bool hasBc = bc.type.extent(0) > 0;
    if (perVertex)
    {
        auto sums = work.rows(mesh.nNodes, NodeSumLayout<D, Q::nq, true>::ncol);
        nodeSums<D, Q, true>(mesh, quantities, geom, x, sums, hasBc, limiter, nFit);
        gradientsFromNodeSums<D, Q, true>(mesh, quantities, geom, x, sums, grad, hasBc, limiter, nFit);
    }
    else
    {
        auto sums = work.rows(mesh.nNodes, NodeSumLayout<D, Q::nq, false>::ncol);
        nodeSums<D, Q, false>(mesh, quantities, geom, x, sums, hasBc, limiter, nFit);
        gradientsFromNodeSums<D, Q, false>(mesh, quantities, geom, x, sums, grad, hasBc, limiter, nFit);
    }
}

} // namespace unilag
