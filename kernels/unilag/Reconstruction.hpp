/*! \file Reconstruction.hpp
 *  \brief Second order in space (docs/gpr-model.md 2.5): a limited linear reconstruction
 *  w_i(x) = w_i + phi_i grad w_i . (x - x_i) of the velocity, the pressure and (strain variants) the shear stress of
 *  each cell, which the nodal solver and the subcell forces evaluate at the nodes x_r instead of the cell values.
 *   - Gradient: weighted least squares over the node-neighbour stencil (every cell that shares a node with cell i,
 *     a face neighbour counted once per shared node, weight 1/|x_j - x_r|^2 for cell j around node r), formed from
 *     sums over each node's cells (LeastSquares.hpp). The stencil is local for every owned cell (DistributedMesh's
 *     ghost layer); ghost cells receive their gradients by one halo exchange.
 *   - Slip walls and symmetry planes: at a node on such planes the mirror images of every cell around the node
 *     (velocity reflected, pressure equal, stress R sigma R), across each plane and their compositions, join the
 *     stencil and the node's limiter bounds, and a cell's own image across its face stands in for the face
 *     neighbour: the stencil and bounds of the mirrored mesh, so that a quadrant with symmetry planes gives the full
 *     plane's solution to round-off (test `symmetry_is_mirror`). With the cell's own image alone the second-order
 *     wall cells differed from the mirrored mesh's by up to 25% in density (2D Sedov, 4k, t = 0.5); without any,
 *     the second-order Kidder shell (polar mesh) jets where its outer surface meets a symmetry plane.
 *   - Limiter (scene key scheme.limiter; measurements in the README, "Limiter"): Barth-Jespersen at the vertices,
 *     per component, in three bounded forms.
 *       - BarthJespersen: the extrema over the cell and its face neighbours bound every vertex value
 *         (no new extrema, first order at shocks: the sharpest 2D Sedov shock). The price: linear fields are clipped
 *         at many vertices (most of them in 3D), so smooth regions get less than full second order.
 *       - VertexBased: the extrema over every cell around the vertex bound it as well (after Kuzmin), which keeps
 *         linear fields whole (at boundary nodes without mirror images with bounds widened by the node's own
 *         linear fit: LeastSquares.hpp nodeBounds): the choice for smooth and elastic flows (the plate).
 *       - NodeFit (the scenes' default): the face bounds widened to the node value of the linear fit over the cells
 *         around the vertex (clamped to their extrema): linear fields kept whole as by VertexBased, mesh-scale noise
 *         damped nearly as by the face bounds (the fit averages it out; unit test NodeFitLimiter).
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
#include "unilag/LeastSquares.hpp"
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
                      Reconstructed what = Reconstructed::All, std::optional<Limiter> tractionLimiter = std::nullopt,
                      GradientScratch* scratch = nullptr)
{
    MechanicalQuantities<D, P> quantities{state, aux, stress, bc, what};
    quantities.ownTractionLimiter = tractionLimiter.has_value();
    quantities.tractionLimiter = tractionLimiter.value_or(limiter);
    limitedGradientsOf<D>(mesh, quantities, geom, x, grad, bc, limiter, scratch);
}

} // namespace unilag
