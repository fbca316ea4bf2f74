/*! \file Reconstruction.hpp
 *  \brief Second order in space (docs/gpr-model.md 2.5): a limited linear reconstruction
 *  w_i(x) = w_i + phi_i grad w_i . (x - x_i) of the velocity, the pressure and (strain variants) the shear stress of
 *  each cell, which the nodal solver and the subcell forces evaluate at the nodes x_r instead of the cell values.
 *   - Gradient: weighted least squares over the node-neighbour stencil (every cell that shares a node with cell i,
 *     weights 1/|x_j - x_i|^2, a face neighbour counted once per shared node). The stencil is local for every owned
 *     cell (DistributedMesh's ghost layer); ghost cells receive their gradients by one halo exchange.
 *   - Slip walls and symmetry planes: at a node on such planes the mirror images of every cell around the node
 *     (velocity reflected, pressure equal, stress R sigma R), across each plane and their compositions, join the
 *     stencil and the node's limiter bounds, and a cell's own image across its face stands in for the face
 *     neighbour: the stencil and bounds of the mirrored mesh, so that a quadrant with symmetry planes gives the full
 *     plane's solution to round-off (test `symmetry_is_mirror`). With the cell's own image alone the second-order
 *     wall cells differed from the mirrored mesh's by up to 25% in density (2D Sedov, 4k, t = 0.5); without any,
 *     the second-order Kidder shell (polar mesh) jets where its outer surface meets a symmetry plane.
 *   - Limiter (scene key scheme.limiter; measurements in the README, "Limiter"): Barth-Jespersen at the vertices,
 *     per component, in two bounded forms.
 *       - BarthJespersen (the default): the extrema over the cell and its face neighbours bound every vertex value
 *         (no new extrema, first order at shocks: the sharpest 2D Sedov shock). The price: linear fields are clipped
 *         at many vertices (most of them in 3D), so smooth regions get less than full second order.
 *       - VertexBased: the extrema over every cell around the vertex bound it as well (after Kuzmin), which keeps
 *         linear fields whole in cells without a boundary vertex: the choice for smooth and elastic flows (the plate).
 *     Limiter::None skips the limiter (shock-free flows only). Bounds over the whole node-neighbour stencil were
 *     measured and not kept: too weak at the 2D Sedov shock, and the viscous 3D Sedov tangles.
 *   - What is reconstructed (scene key scheme.reconstruct): all of it, or the velocity alone (Reconstructed), the
 *     pressure and shear stress keeping their cell values. On Sedov's blast, order 2 left twice order 1's density
 *     scatter behind the shock (an entropy error) and was above order 1 on 64k triangles; the reconstructed
 *     pressure made most of it, even behind the shock where the flow is smooth (docs/sedov.md, session 11). The
 *     velocity alone is first order in the pressure on smooth flows (the vortex), and worse on Noh's implosion.
 *  Sums run over the node -> corner CSR, sorted by global cell id: results are independent of the partition and the
 *  thread count, bit for bit.
 */
#pragma once

#include <optional>

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"

namespace unilag
{

//! Reconstructed quantities and their columns in the gradient field (quantity q, direction d: column q * D + d).
template <int D, class P>
struct ReconLayout
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        vel = 0,                          //!< velocity, D quantities
        pressure = D,                     //!< pressure
        stress = D + 1,                   //!< shear stress as Sym3, 6 quantities (strain only)
        nq = D + 1 + (P::strain ? 6 : 0), //!< number of reconstructed quantities
        ncomp = nq * D,                   //!< columns of the gradient field
    };
};

/*! What the flux kernels need to evaluate a reconstruction: the limited gradients (empty: first order), and the node
 *  positions and cell centroids of the configuration the fluxes are computed on. */
template <int D>
struct Reconstruction
{
    ConstField grad;     //!< cells x ReconLayout::ncomp
    ConstField x;        //!< node positions
    ConstField centroid; //!< cell centroids (CellGeometry::centroid)
    View<const double*> volume; //!< cell volumes (CellGeometry::volume; the mechanical forces' cornerLoad)
    bool consistentLoad = false; //!< scheme.corner_load: consistent (cornerLoad, CornerLoad.hpp), else lumped

    KOKKOS_INLINE_FUNCTION bool active() const { return grad.extent(0) > 0; }

    //! x_r - x_i for node r of cell i.
    KOKKOS_INLINE_FUNCTION Vec<D> offset(LO i, LO r) const
    {
        Vec<D> d;
        for (int a = 0; a < D; ++a)
            d[a] = x(r, a) - centroid(i, a);
        return d;
    }

    //! grad w_q . dx in cell i.
    KOKKOS_INLINE_FUNCTION double delta(LO i, int q, const Vec<D>& dx) const
    {
        double s = 0.0;
        for (int a = 0; a < D; ++a)
            s += grad(i, q * D + a) * dx[a];
        return s;
    }
};

//! The reconstructed quantities of cell j: velocity, pressure, shear stress (strain).
template <int D, class P>
KOKKOS_INLINE_FUNCTION void reconValues(const ConstField& state, const ConstField& aux, const ConstField& stress, LO j,
                                        double (&w)[ReconLayout<D, P>::nq])
{
    using S = StateLayout<D, P>;
    using R = ReconLayout<D, P>;
    for (int d = 0; d < D; ++d)
        w[R::vel + d] = state(j, S::vel + d);
    w[R::pressure] = aux(j, Aux::pressure);
    if constexpr (P::strain)
        for (int c = 0; c < 6; ++c)
            w[R::stress + c] = stress(j, c);
}

/*! The mirror image across a slip wall or symmetry plane with unit normal n of the reconstructed quantities w of a
 *  cell: the velocity reflected (v - 2 (v.n) n), the pressure unchanged, the shear stress R sigma R, R = I - 2 n n^T. */
template <int D, class P>
KOKKOS_INLINE_FUNCTION void mirrorValues(const Vec<D>& n, double (&w)[ReconLayout<D, P>::nq])
{
    using R = ReconLayout<D, P>;
    double vn = 0.0;
    for (int a = 0; a < D; ++a)
        vn += w[R::vel + a] * n[a];
    for (int a = 0; a < D; ++a)
        w[R::vel + a] -= 2.0 * vn * n[a];
    if constexpr (P::strain)
    {
        constexpr int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2}; // xx yy zz xy xz yz
        double sig[3][3], m[3][3], n3[3] = {0.0, 0.0, 0.0};
        for (int a = 0; a < D; ++a)
            n3[a] = n[a];
        for (int c = 0; c < 6; ++c)
            sig[row[c]][col[c]] = sig[col[c]][row[c]] = w[R::stress + c];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
            {
                m[a][b] = 0.0;
                for (int e = 0; e < 3; ++e)
                    m[a][b] += ((a == e ? 1.0 : 0.0) - 2.0 * n3[a] * n3[e]) * sig[e][b];
            }
        for (int c = 0; c < 6; ++c)
        {
            double v = 0.0;
            for (int e = 0; e < 3; ++e)
                v += m[row[c]][e] * ((e == col[c] ? 1.0 : 0.0) - 2.0 * n3[e] * n3[col[c]]);
            w[R::stress + c] = v;
        }
    }
}

//! Unit normal of face f (opposite local vertex f) of cell i on the configuration x, and one of its vertices.
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
    return (1.0 / norm(n)) * n;
}

/*! Limiter of the second-order reconstruction (scene key scheme.limiter). Barth-Jespersen in both bounded forms:
 *  each vertex value stays within the extrema of the cell and its face neighbours (BarthJespersen), and for
 *  VertexBased also of every cell around that vertex (linearity-preserving in the interior, after Kuzmin). */
enum class Limiter
{
    None,
    BarthJespersen,
    VertexBased
};

/*! What the mechanical reconstruction reconstructs (scene key scheme.reconstruct): every quantity, or the velocity
 *  alone, the pressure and shear stress keeping their cell values (the file comment says when and why). */
enum class Reconstructed
{
    All,
    Velocity
};

/*! How the forces load a cell's corners with its reconstructed traction (scene key scheme.corner_load; cornerLoad,
 *  CornerLoad.hpp): the corner values on the corner vectors (Lumped), or the traction's integral against the node's hat
 *  function (Consistent: exact work for linear fields, no mesh-scale entropy noise on smooth flows; but a larger
 *  entropy scatter behind strong shocks on triangles, docs/gpr-model.md 2.5). */
enum class CornerLoad
{
    Lumped,
    Consistent
};

//! How limitedGradientsOf bounds one quantity: what a Limiter means for it (the Q's bounds()).
enum class Bounds
{
    Unlimited,      //!< the least-squares gradient
    FaceNeighbours, //!< vertex values within the extrema of the cell and its face neighbours
    Vertex,         //!< ... or of every cell around the vertex
    CellValue       //!< not reconstructed: gradient 0
};

//! The bounds a Limiter gives every quantity it limits.
KOKKOS_INLINE_FUNCTION constexpr Bounds uniformBounds(Limiter limiter)
{
    return limiter == Limiter::None          ? Bounds::Unlimited
           : limiter == Limiter::VertexBased ? Bounds::Vertex
                                             : Bounds::FaceNeighbours;
}

/*! The quantities a reconstruction fits (the Q of limitedGradientsOf): here velocity, pressure and shear stress
 *  (ReconLayout). Q gives nq, the index bdata of the quantity that boundary faces may impose (here the pressure),
 *  the Bounds each Limiter gives each quantity, atFaces (the limiter bounds the face-centre values, not the vertex
 *  values: where Q's users evaluate it), the values of a cell, the groups across which the cell's mirror image joins
 *  the stencil and its mirrored values, and the imposed boundary value of quantity bdata at a group (false if none).
 *  The other Q: heat::Quantities. */
template <int D, class P>
struct MechanicalQuantities
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        nq = ReconLayout<D, P>::nq,
        bdata = ReconLayout<D, P>::pressure,
    };
    static constexpr bool atFaces = false; //!< limited at the vertices (the nodal solver evaluates it there)
    ConstField state, aux, stress;
    BoundaryView bc;
    Reconstructed what = Reconstructed::All;
    bool ownTractionLimiter = false; //!< scheme.pressure_limiter given: the traction's own bounds
    Limiter tractionLimiter = Limiter::BarthJespersen;

    KOKKOS_INLINE_FUNCTION void values(LO j, double (&w)[nq]) const
    {
        if (what == Reconstructed::All)
            return reconValues<D, P>(state, aux, stress, j, w);
        for (int q = 0; q < nq; ++q) // the traction is not fitted: not loaded either
            w[q] = q < ReconLayout<D, P>::pressure ? state(j, StateLayout<D, P>::vel + q) : 0.0;
    }
    /*! Reconstructed::Velocity: the traction (pressure, shear stress: after the velocity) at cell values; with its
     *  own limiter, the traction bounded by that one (vertex bounds on the pressure keep a strong shock along mesh
     *  edges from scattering the entropy of the two triangle orientations: docs/sedov.md, session 14). */
    KOKKOS_INLINE_FUNCTION Bounds bounds(Limiter limiter, int q) const
    {
        if (q < ReconLayout<D, P>::pressure)
            return uniformBounds(limiter);
        if (what == Reconstructed::Velocity)
            return Bounds::CellValue;
        return uniformBounds(ownTractionLimiter ? tractionLimiter : limiter);
    }
    KOKKOS_INLINE_FUNCTION bool mirrors(int g) const { return bc.type(g) == BcSlipWall; }
    KOKKOS_INLINE_FUNCTION void mirror(const Vec<D>& n, double (&w)[nq]) const { mirrorValues<D, P>(n, w); }
    KOKKOS_INLINE_FUNCTION bool boundaryValue(int g, double& value) const
    {
        if (bc.type(g) != BcPressure)
            return false;
        value = bc.value(g, 0);
        return true;
    }
};

/*! One cell of the least-squares stencil, at offset d from the centroid with values wj (cell i's: wi): its term of
 *  A = sum w d d^T and of the right-hand sides of the fitted quantities, w = 1 / |d|^2, and (PerVertex) the bounds of
 *  the vertex it shares with cell i. */
template <int D, int NQ, bool PerVertex>
KOKKOS_INLINE_FUNCTION void addStencilCell(const Vec<D>& d, const double (&wj)[NQ], const double (&wi)[NQ], int nFit,
                                           Mat<D>& A, Vec<D> (&rhs)[NQ], double (&vmin)[NQ], double (&vmax)[NQ])
{
    const double w = 1.0 / dot(d, d);
    A.addOuter(w, d);
    for (int q = 0; q < nFit; ++q)
        rhs[q] = rhs[q] + (w * (wj[q] - wi[q])) * d;
    if constexpr (PerVertex)
        for (int q = 0; q < nFit; ++q)
        {
            vmin[q] = Kokkos::Experimental::fmin(vmin[q], wj[q]);
            vmax[q] = Kokkos::Experimental::fmax(vmax[q], wj[q]);
        }
}

/*! The mirroring planes (slip walls, symmetry planes: the groups Q mirrors) through node r, gathered from the faces
 *  at r of one cell j around it (local vertex kj of j is r: the faces of j other than face kj contain r). A face whose
 *  normal is within ~45 degrees of a plane already found adds to it (a curved wall's faces at r); up to D planes. The
 *  sums are normalised by the caller. */
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
        Vec<D> n = faceUnitNormal<D>(mesh, x, j, f, vertex);
        int p = 0;
        while (p < nPlanes && Kokkos::Experimental::fabs(dot(n, plane[p])) < 0.7 * norm(plane[p]))
            ++p;
        if (p == nPlanes)
        {
            if (nPlanes == D)
                continue;
            plane[nPlanes++] = Vec<D>::zero();
        }
        plane[p] = plane[p] + (dot(n, plane[p]) < 0.0 ? -1.0 : 1.0) * n;
    }
}

template <int D, class Q, bool PerVertex>
void limitedGradientsKernel(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom,
                            const ConstField& x, const Field& grad, const BoundaryView& bc, Limiter limiter, int nFit);

/*! \brief Limited gradients of the owned cells (docs/gpr-model.md 2.5) of the quantities Q into grad (cells x
 *  Q::nq * D), from the cell values of all local cells (current for ghosts too) on the configuration x with geometry
 *  geom (centroids of all local cells). Limiter::None gives the plain least-squares gradients (exact for linear
 *  fields). Which limiter for which flow: README, Limiter.
 *  With bc given, the cell's mirror image across the groups Q mirrors joins the stencil (file comment), and an
 *  imposed boundary value of quantity Q::bdata is boundary data: a point of its least-squares fit at the face
 *  centroid, and a bound of the face's vertices (for the pressure: without the bound the limiter clips every monotone
 *  pressure profile at such a boundary to first order; without the fit Kidder's unlimited shell tangled on coarse
 *  meshes). */
template <int D, class Q>
void limitedGradientsOf(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom, const ConstField& x,
                        const Field& grad, const BoundaryView& bc, Limiter limiter)
{
    bool perVertex = false; // some quantity needs the extrema around each vertex
    int nFit = 0;           // quantities 0 .. nFit-1 are fitted; those after keep their cell values (Q's bounds)
    for (int q = 0; q < Q::nq; ++q)
    {
        perVertex = perVertex || quantities.bounds(limiter, q) == Bounds::Vertex;
        if (quantities.bounds(limiter, q) != Bounds::CellValue)
            nFit = q + 1;
    }
    // Two kernels: without vertex bounds the per-vertex extrema arrays (NV x NQ x 2 doubles, in a GPU thread's local
    // memory) are not there at all.
    if (perVertex)
        limitedGradientsKernel<D, Q, true>(mesh, quantities, geom, x, grad, bc, limiter, nFit);
    else
        limitedGradientsKernel<D, Q, false>(mesh, quantities, geom, x, grad, bc, limiter, nFit);
}

//! limitedGradientsOf's kernel; PerVertex: some quantity has Bounds::Vertex.
template <int D, class Q, bool PerVertex>
void limitedGradientsKernel(const MeshView<D>& mesh, const Q& quantities, const CellGeometry& geom,
                            const ConstField& x, const Field& grad, const BoundaryView& bc, Limiter limiter, int nFit)
{
    constexpr int NV = D + 1;
    constexpr int NQ = Q::nq;
    constexpr int BQ = Q::bdata;
    constexpr int NVB = PerVertex ? NV : 1; // vertices with their own extrema (none used without PerVertex)
    auto centroid = geom.centroid;
    const bool hasBc = bc.type.extent(0) > 0;
    const bool fitBQ = BQ < nFit;
    auto gradient = KOKKOS_LAMBDA(const LO i)
    {
        double wi[NQ], wj[NQ], wmin[NQ], wmax[NQ]; // wmin, wmax: over the cell and its face neighbours
        double pmin[NV], pmax[NV];                  // bounds of quantity BQ per vertex, with imposed boundary values
        double vmin[NVB][NQ], vmax[NVB][NQ];        // VertexBased: over the cells around each vertex
        Vec<D> rhs[NQ];
        quantities.values(i, wi);
        for (int q = 0; q < NQ; ++q)
        {
            wmin[q] = wmax[q] = wi[q];
            rhs[q] = Vec<D>::zero();
        }
        Vec<D> xi, dx[NV]; // centroid, and its offsets to the vertices
        for (int a = 0; a < D; ++a)
            xi[a] = centroid(i, a);
        for (int k = 0; k < NV; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            for (int a = 0; a < D; ++a)
                dx[k][a] = x(r, a) - xi[a];
        }
        Mat<D> A = Mat<D>::zero();
        const int fitted = nFit; // captured here: nvcc refuses a lambda's first capture inside `if constexpr`
        for (int k = 0; k < NV; ++k)
        {
            if constexpr (PerVertex)
                for (int q = 0; q < fitted; ++q)
                    vmin[k][q] = vmax[k][q] = wi[q];
            const LO r = mesh.cellNodes(i, k);
            Vec<D> plane[D];
            int nPlanes = 0;
            const bool boundaryNode = hasBc && mesh.mayBeOnBoundary(r);
            for (LO c = mesh.nodeCornerOffsets(r); c < mesh.nodeCornerOffsets(r + 1); ++c)
            {
                const LO j = mesh.nodeCorners(c) / NV;
                if (boundaryNode)
                    addMirrorPlanes<D>(mesh, quantities, x, j, mesh.nodeCorners(c) % NV, plane, nPlanes);
                if (j == i)
                    continue;
                Vec<D> d;
                for (int a = 0; a < D; ++a)
                    d[a] = centroid(j, a) - xi[a];
                quantities.values(j, wj);
                addStencilCell<D, NQ, PerVertex>(d, wj, wi, nFit, A, rhs, vmin[k % NVB], vmax[k % NVB]);
            }
            // A node on mirroring planes: the images of every cell around it (cell i's own included) across each
            // plane and their compositions join the stencil and the vertex's bounds, as the cells of the symmetric
            // flow around the node would (they share it with cell i).
            for (int p = 0; p < nPlanes; ++p)
                plane[p] = (1.0 / norm(plane[p])) * plane[p];
            for (LO c = mesh.nodeCornerOffsets(r); nPlanes > 0 && c < mesh.nodeCornerOffsets(r + 1); ++c)
            {
                const LO j = mesh.nodeCorners(c) / NV;
                double wj0[NQ];
                quantities.values(j, wj0);
                for (int image = 1; image < (1 << nPlanes); ++image)
                {
                    Vec<D> d;
                    for (int a = 0; a < D; ++a)
                        d[a] = centroid(j, a) - x(r, a);
                    for (int q = 0; q < NQ; ++q)
                        wj[q] = wj0[q];
                    for (int p = 0; p < nPlanes; ++p)
                        if (image & (1 << p))
                        {
                            d = d - (2.0 * dot(d, plane[p])) * plane[p];
                            quantities.mirror(plane[p], wj);
                        }
                    for (int a = 0; a < D; ++a)
                        d[a] += x(r, a) - xi[a];
                    addStencilCell<D, NQ, PerVertex>(d, wj, wi, nFit, A, rhs, vmin[k % NVB], vmax[k % NVB]);
                }
            }
        }
        // Bounds over the face neighbours. Across a slip wall or symmetry plane (a group Q mirrors) the cell's mirror
        // image stands in for the neighbour (it joined the stencil above, once per vertex on the plane).
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
                wmin[q] = Kokkos::Experimental::fmin(wmin[q], wj[q]);
                wmax[q] = Kokkos::Experimental::fmax(wmax[q], wj[q]);
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
                const double w = double(D) / dot(d, d); // as a face neighbour (D shared vertices) at its distance
                Ap.addOuter(w, d);
                rhsp = rhsp + (w * (pb - wi[BQ])) * d;
                for (int k = 0; k < NV; ++k) // the vertices of face f
                    if (k != f)
                    {
                        pmin[k] = Kokkos::Experimental::fmin(pmin[k], pb);
                        pmax[k] = Kokkos::Experimental::fmax(pmax[k], pb);
                    }
            }
        // A = sum w d d^T is dimensionless (w = 1/|d|^2); a stencil that does not span D directions gives no gradient.
        double trace = 0.0, det;
        for (int a = 0; a < D; ++a)
            trace += A.a[a][a];
        if constexpr (D == 2)
            det = A.a[0][0] * A.a[1][1] - A.a[0][1] * A.a[1][0];
        else
            det = A.a[0][0] * (A.a[1][1] * A.a[2][2] - A.a[1][2] * A.a[2][1]) -
                  A.a[0][1] * (A.a[1][0] * A.a[2][2] - A.a[1][2] * A.a[2][0]) +
                  A.a[0][2] * (A.a[1][0] * A.a[2][1] - A.a[1][1] * A.a[2][0]);
        const double scale = trace / D;
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
                    if (bounds == Bounds::Vertex)
                    {
                        vhi[k] = Kokkos::Experimental::fmax(vhi[k], vmax[k][q]);
                        vlo[k] = Kokkos::Experimental::fmin(vlo[k], vmin[k][q]);
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
                            hi = Kokkos::Experimental::fmax(hi, vhi[m]);
                            lo = Kokkos::Experimental::fmin(lo, vlo[m]);
                        }
                }
                if (dw > 0.0)
                    phi = Kokkos::Experimental::fmin(phi, (hi - wi[q]) / dw);
                else if (dw < 0.0)
                    phi = Kokkos::Experimental::fmin(phi, (lo - wi[q]) / dw);
            }
            for (int a = 0; a < D; ++a)
                grad(i, q * D + a) = phi * g[a];
        }
    };
    Kokkos::parallel_for("unilag::recon::limited_gradients", range(mesh.nOwnedCells), gradient);
}

/*! The a posteriori first-order fallback (docs/gpr-model.md 2.5): the owned cells marked in flags (column 0) lose
 *  their gradients, so that their corner values are their cell values. First order keeps a cell's own work on the
 *  nodes dissipative, sum_r (v_r - v_i) . M (v_r - v_i) >= 0, which the reconstructed corner velocities do not. */
inline void dropFlaggedGradients(const Field& grad, const ConstField& flags, LO nOwnedCells)
{
    const int ncomp = int(grad.extent(1));
    auto drop = KOKKOS_LAMBDA(const LO i)
    {
        if (flags(i, 0) != 0.0)
            for (int c = 0; c < ncomp; ++c)
                grad(i, c) = 0.0;
    };
    Kokkos::parallel_for("unilag::recon::drop_flagged_gradients", range(nOwnedCells), drop);
}

/*! \brief Limited gradients of velocity, pressure and (strain variants) the shear stress `stress` into grad (cells x
 *  ReconLayout::ncomp): limitedGradientsOf with MechanicalQuantities (slip walls and symmetry planes mirror the cell,
 *  an imposed boundary pressure is boundary data). tractionLimiter: the pressure's and shear stress's own limiter
 *  (scheme.pressure_limiter), else limiter's. */
template <int D, class P>
void limitedGradients(const MeshView<D>& mesh, const ConstField& state, const ConstField& aux,
                      const ConstField& stress, const CellGeometry& geom, const ConstField& x, const Field& grad,
                      const BoundaryView& bc = BoundaryView(), Limiter limiter = Limiter::BarthJespersen,
                      Reconstructed what = Reconstructed::All, std::optional<Limiter> tractionLimiter = std::nullopt)
{
    MechanicalQuantities<D, P> quantities{state, aux, stress, bc, what};
    quantities.ownTractionLimiter = tractionLimiter.has_value();
    quantities.tractionLimiter = tractionLimiter.value_or(limiter);
    limitedGradientsOf<D>(mesh, quantities, geom, x, grad, bc, limiter);
}

} // namespace unilag
