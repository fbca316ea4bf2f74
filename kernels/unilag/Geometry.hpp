/*! \file Geometry.hpp
 *  \brief Simplex geometry: volumes, corner vectors c_ri = d|T_i|/dx_r, characteristic lengths.
 *
 *  Conventions (docs/gpr-model.md 2.1): a cell is a simplex with NV = D+1 nodes, positively oriented. The corner vector
 *  of local node k is c_k = d|T|/dx_k = -(1/D) s_k n_k, where s_k n_k is the outward area vector of the face
 *  opposite node k. Hence sum_k c_k = 0, (1/D) sum_k c_k . x_k = |T|, and the face opposite k has outward
 *  area vector -D c_k. Face k of a cell always means "the face opposite local node k".
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{

//! Connectivity and coordinates a kernel needs, as Views (copied by value into lambdas).
template <int D>
struct MeshView
{
    static constexpr int NV = D + 1;
    Kokkos::View<const LO**, Kokkos::LayoutLeft, MemSpace> cellNodes;  //!< map: cell -> NV nodes
    View<const LO*> nodeCornerOffsets;                                 //!< map: node -> corners (CSR offsets)
    View<const LO*> nodeCorners;                                       //!< corner id = cell * NV + k, sorted by global cell id
    View<const int**> cellFaceGroup; //!< boundary group of face k of a cell, -1 if interior (LayoutRight default)
    View<const LO**> cellNeighbour;  //!< local cell across face k, -1 on the boundary (complete for owned cells)
    View<const int*> nodeBoundary;   //!< 1 if a boundary face of a local cell holds the node (empty: not known)
    View<const int*> nodeTraction;   //!< 1 if a free, pressure or traction face holds the node (empty: none)
    LO nOwnedCells = 0, nCells = 0;  //!< owned cells first, then ghosts
    LO nOwnedNodes = 0, nNodes = 0;  //!< owned nodes first, then the other nodes of local cells

    //! Whether node r may lie on a boundary face: true where nodeBoundary was not given (callers then look).
    KOKKOS_INLINE_FUNCTION bool mayBeOnBoundary(LO r) const { return nodeBoundary.extent(0) == 0 || nodeBoundary(r) != 0; }
    //! Whether node r is known to lie on a boundary face.
    KOKKOS_INLINE_FUNCTION bool onBoundary(LO r) const { return nodeBoundary.extent(0) > 0 && nodeBoundary(r) != 0; }
    //! Whether node r lies on a face where the traction is imposed (its corners take freeSurfaceFloor).
    KOKKOS_INLINE_FUNCTION bool onTractionFace(LO r) const
    {
        return nodeTraction.extent(0) > 0 && nodeTraction(r) != 0;
    }
};

//! Corner geometry of one simplex from its node positions.
template <int D>
struct Simplex
{
    static constexpr int NV = D + 1;
    Vec<D> c[NV];    //!< corner vectors
    double volume;   //!< signed measure |T|
    Vec<D> centroid; //!< mean of the vertices (the reconstruction's expansion point)

    KOKKOS_INLINE_FUNCTION explicit Simplex(const Vec<D> (&x)[NV])
    {
        centroid = Vec<D>::zero();
        for (int k = 0; k < NV; ++k)
            centroid = centroid + (1.0 / NV) * x[k];
        if constexpr (D == 2)
        {
            // c_k = 1/2 perp(x_{k+1} - x_{k-1}), perp(a) = (a_y, -a_x)
            for (int k = 0; k < 3; ++k)
            {
                const Vec<2>& a = x[(k + 2) % 3];
                const Vec<2>& b = x[(k + 1) % 3];
                c[k][0] = 0.5 * (b[1] - a[1]);
                c[k][1] = -0.5 * (b[0] - a[0]);
            }
            volume = 0.5 * ((x[1][0] - x[0][0]) * (x[2][1] - x[0][1]) - (x[1][1] - x[0][1]) * (x[2][0] - x[0][0]));
        }
        else
        {
            // c_k = -(1/6) (x_b - x_a) x (x_c - x_a) with (k, a, b, c) an even permutation of (0, 1, 2, 3)
            constexpr int face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
            for (int k = 0; k < 4; ++k)
            {
                const Vec<3> u = x[face[k][1]] - x[face[k][0]];
                const Vec<3> w = x[face[k][2]] - x[face[k][0]];
                c[k][0] = -(u[1] * w[2] - u[2] * w[1]) / 6.0;
                c[k][1] = -(u[2] * w[0] - u[0] * w[2]) / 6.0;
                c[k][2] = -(u[0] * w[1] - u[1] * w[0]) / 6.0;
            }
            const Vec<3> e1 = x[1] - x[0], e2 = x[2] - x[0], e3 = x[3] - x[0];
            volume = (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
                      e1[2] * (e2[0] * e3[1] - e2[1] * e3[0])) /
                     6.0;
        }
    }

    //! Incircle (2D) / insphere (3D) diameter: 2|T| / sum_k |c_k| in both dimensions.
    KOKKOS_INLINE_FUNCTION double charLength() const
    {
        double s = 0.0;
        for (int k = 0; k < NV; ++k)
            s += norm(c[k]);
        return 2.0 * volume / s;
    }
};

//! Load the node positions of cell i.
template <int D>
KOKKOS_INLINE_FUNCTION void gatherNodes(const MeshView<D>& m, const ConstField& x, LO i, Vec<D> (&xi)[D + 1])
{
    for (int k = 0; k < D + 1; ++k)
    {
        const LO r = m.cellNodes(i, k);
        for (int d = 0; d < D; ++d)
            xi[k][d] = x(r, d);
    }
}

/*! \brief Shape quality of cell i: its insphere diameter over that of the regular simplex whose edges are the
 *  cell's longest, sqrt(D (D + 1) / 2) h_i / l_max: 1 for a regular simplex, towards 0 for a flat one, whose
 *  time step and shock heating go like 1 / quality (docs/sedov.md, session 29). `insphere`: CellGeometry::length. */
template <int D>
KOKKOS_INLINE_FUNCTION double shapeQuality(const Vec<D> (&xi)[D + 1], double insphere)
{
    double longest2 = 0.0;
    for (int a = 0; a < D + 1; ++a)
        for (int b = a + 1; b < D + 1; ++b)
        {
            const Vec<D> e = xi[b] - xi[a];
            const double e2 = dot(e, e);
            longest2 = e2 > longest2 ? e2 : longest2;
        }
    return Kokkos::Experimental::sqrt(0.5 * D * (D + 1) / longest2) * insphere;
}

//! Per-cell geometry of the current configuration.
struct CellGeometry
{
    View<double*> volume;  //!< |T_i|
    View<double*> length;  //!< characteristic length h_i
    RowField corner;       //!< cell x (NV*D + NV): c_k component d in column k*D + d, then 1 / |c_k| (cornerInvNorm)
    Field centroid;        //!< cell x D: vertex mean

    CellGeometry() = default;
    CellGeometry(LO nCells, int dim)
        : volume("unilag::volume", nCells), length("unilag::length", nCells),
          corner("unilag::corner", nCells, (dim + 1) * (dim + 1)), centroid("unilag::centroid", nCells, dim)
    {
    }
};

/*! 1 / |c_k| of corner k of cell i, stored beside the corner vectors by storeGeometry: the weight of c_k in the
 *  subcell matrices, which the nodal solve and the subcell forces read D + 1 times per cell and step (a square root
 *  and a division each, 15-20% of a first-order step when computed there). */
template <int D>
KOKKOS_INLINE_FUNCTION double cornerInvNorm(const RowField& corner, LO i, int k)
{
    return corner(i, (D + 1) * D + k);
}

/*! The area vector of the face between cell i (its face k) and its neighbour j, antisymmetrised: (A_i - A_j)/2 with
 *  A = -D c the cells' outward area vectors, (D/2)(c_j,m - c_i,k), m the face of j facing i. Exact negatives from
 *  either side in floating point, so face fluxes built on it conserve to round-off (heat fluxes, entropy filter). */
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> sharedFaceArea(const MeshView<D>& mesh, const RowField& corner, LO i, int k, LO j)
{
    Vec<D> A = Vec<D>::zero();
    for (int m = 0; m < D + 1; ++m)
        if (mesh.cellNeighbour(j, m) == i)
        {
            for (int d = 0; d < D; ++d)
                A[d] = (0.5 * D) * (corner(j, m * D + d) - corner(i, k * D + d));
            break;
        }
    return A;
}

//! Store the geometry of a simplex as cell i of g.
template <int D>
KOKKOS_INLINE_FUNCTION void storeGeometry(const CellGeometry& g, LO i, const Simplex<D>& s)
{
    double sumNorms = 0.0; // charLength's sum, in its order: the same bits
    for (int k = 0; k < D + 1; ++k)
    {
        const double cNorm = norm(s.c[k]);
        sumNorms += cNorm;
        for (int d = 0; d < D; ++d)
            g.corner(i, k * D + d) = s.c[k][d];
        g.corner(i, (D + 1) * D + k) = 1.0 / cNorm;
    }
    g.volume(i) = s.volume;
    g.length(i) = 2.0 * s.volume / sumNorms; // Simplex::charLength
    for (int d = 0; d < D; ++d)
        g.centroid(i, d) = s.centroid[d];
}

template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> cornerVec(const RowField& corner, LO i, int k)
{
    Vec<D> c;
    for (int d = 0; d < D; ++d)
        c[d] = corner(i, k * D + d);
    return c;
}

/*! \brief Volumes, corner vectors and lengths of cells [first, nCells) for positions x.
 *  Returns the smallest volume found (<= 0 flags an inverted or degenerate cell). */
template <int D>
double computeGeometry(const MeshView<D>& mesh, const ConstField& x, const CellGeometry& g, LO nCells, LO first = 0)
{
    constexpr int NV = D + 1;
    double minVolume = 0.0;
    auto geometry = KOKKOS_LAMBDA(const LO i, double& vmin)
    {
        Vec<D> xi[NV];
        gatherNodes<D>(mesh, x, i, xi);
        const Simplex<D> s(xi);
        storeGeometry<D>(g, i, s);
        if (s.volume < vmin)
            vmin = s.volume;
    };
    Kokkos::parallel_reduce("unilag::geometry::cells", Kokkos::RangePolicy<ExecSpace>(first, std::max(first, nCells)),
                            geometry, Kokkos::Min<double>(minVolume));
    return minVolume;
}

//! The volume of cell i on the positions x (a trial configuration: the Picard iterate, a stage's end).
template <int D> KOKKOS_INLINE_FUNCTION double cellVolumeAt(const MeshView<D>& mesh, const ConstField& x, LO i)
{
    Vec<D> xi[D + 1];
    gatherNodes<D>(mesh, x, i, xi);
    return Simplex<D>(xi).volume;
}

/*! The velocity gradient of cell i, L = (1/|T_i|) sum_r v_r (x) c_ri (exact for the linear velocity field of its
 *  nodes; docs/gpr-model.md 2.4), with the corner vectors of the configuration of volume 1 / inverseVolume, as a
 *  3x3 matrix (zero rows and columns beyond D). */
template <int D>
KOKKOS_INLINE_FUNCTION Mat<3> cellVelocityGradient(const MeshView<D>& mesh, const ConstField& vnode,
                                                   const RowField& corner, LO i, double inverseVolume)
{
    Mat<3> L = Mat<3>::zero();
    for (int k = 0; k < D + 1; ++k)
    {
        const LO r = mesh.cellNodes(i, k);
        for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b)
                L.a[a][b] += vnode(r, a) * corner(i, k * D + b) * inverseVolume;
    }
    return L;
}

//! S = sum_j c_j c_j^T / |c_j| of cell i: sum_k M_ik = D S (the subcell matrices of Hydro.hpp); trace S = sum_j |c_j|.
template <int D>
KOKKOS_INLINE_FUNCTION Mat<D> summedCornerOuters(const RowField& corner, LO i)
{
    Mat<D> S = Mat<D>::zero();
    for (int j = 0; j < D + 1; ++j)
        S.addOuter(cornerInvNorm<D>(corner, i, j), cornerVec<D>(corner, i, j));
    return S;
}

//! det(lambda I - S) = lambda^3 - c2 lambda^2 + c1 lambda - c0 of a symmetric 3x3 matrix S.
KOKKOS_INLINE_FUNCTION void characteristicCoefficients(const Mat<3>& S, double& c2, double& c1, double& c0)
{
    c2 = S.a[0][0] + S.a[1][1] + S.a[2][2];
    c1 = S.a[0][0] * S.a[1][1] + S.a[0][0] * S.a[2][2] + S.a[1][1] * S.a[2][2] - S.a[0][1] * S.a[0][1] -
         S.a[0][2] * S.a[0][2] - S.a[1][2] * S.a[1][2];
    c0 = S.a[0][0] * (S.a[1][1] * S.a[2][2] - S.a[1][2] * S.a[1][2]) -
         S.a[0][1] * (S.a[0][1] * S.a[2][2] - S.a[1][2] * S.a[0][2]) +
         S.a[0][2] * (S.a[0][1] * S.a[1][2] - S.a[1][1] * S.a[0][2]);
}

/*! An upper bound of the largest eigenvalue of the symmetric positive semi-definite 3x3 matrix S that is exact to
 *  round-off where that eigenvalue exceeds `floor`, or any value <= floor where it does not. Newton's method on the
 *  characteristic polynomial from an upper bound (Wolkowicz-Styan's) descends monotonically onto lambda_max (all
 *  roots real), and each iterate is an upper bound, so it stops as soon as one falls below floor: no libm calls. */
KOKKOS_INLINE_FUNCTION double largestEigenvalueAbove(const Mat<3>& S, double floor)
{
    double c2, c1, c0;
    characteristicCoefficients(S, c2, c1, c0);
    double frobenius2 = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            frobenius2 += S.a[a][b] * S.a[a][b];
    // Wolkowicz-Styan: lambda_max <= m + sqrt(2) s with m = trace / 3, s^2 = |S|_F^2 / 3 - m^2 (tighter than |S|_F)
    const double m = c2 / 3.0, s2 = frobenius2 / 3.0 - m * m;
    double lambda = m + Kokkos::Experimental::sqrt(2.0 * (s2 > 0.0 ? s2 : 0.0));
    if (lambda <= floor)
        return floor;
    for (int it = 0; it < 40 && lambda > floor; ++it)
    {
        const double p = ((lambda - c2) * lambda + c1) * lambda - c0;
        const double slope = (3.0 * lambda - 2.0 * c2) * lambda + c1;
        if (!(p > 0.0) || !(slope > 0.0))
            break; // at lambda_max to round-off
        const double next = lambda - p / slope;
        if (!(next < lambda))
            break;
        lambda = next;
    }
    return lambda > floor ? lambda : floor;
}

/*! The smallest eigenvalue of the symmetric positive semi-definite matrix S where it lies below `ceiling`, else a
 *  value >= ceiling. 3x3: Newton's method on the characteristic polynomial from 0 rises monotonically onto
 *  lambda_min (the polynomial is increasing and concave left of it) and stops once above ceiling. */
template <int D>
KOKKOS_INLINE_FUNCTION double smallestEigenvalueBelow(const Mat<D>& S, double ceiling)
{
    if constexpr (D == 2)
    {
        const double mean = 0.5 * (S.a[0][0] + S.a[1][1]), half = 0.5 * (S.a[0][0] - S.a[1][1]);
        return mean - Kokkos::Experimental::sqrt(half * half + S.a[0][1] * S.a[0][1]);
    }
    else
    {
        double c2, c1, c0;
        characteristicCoefficients(S, c2, c1, c0);
        double lambda = 0.0;
        for (int it = 0; it < 60 && lambda < ceiling; ++it)
        {
            const double p = ((lambda - c2) * lambda + c1) * lambda - c0;
            const double slope = (3.0 * lambda - 2.0 * c2) * lambda + c1;
            if (!(p < 0.0) || !(slope > 0.0))
                break; // at lambda_min to round-off
            const double next = lambda - p / slope;
            if (!(next > lambda))
                break;
            lambda = next;
        }
        return lambda;
    }
}

/*! The subcell matrix M_ik at a node of imposed traction (free, pressure, traction), with its smallest eigenvalue
 *  raised to |c_k| / 8 (it is |c_k| / 2 on an equilateral triangle, |c_k| / 3 on a regular tetrahedron: well-shaped
 *  corners keep M_ik). A zero-traction node moves at v_r - v = M_r^-1 sum_i p_i c_ir from its cells, and where an
 *  expansion into vacuum stretches the boundary cells, their faces at r turn parallel and M_r loses its stiffness in
 *  one direction: the node ran away along it and stretched the cells further (a gas square expanding into vacuum had
 *  a node at x = 34 by t = 2, three times the gas's escape speed; docs/gpr-model.md 2.2, Boundaries). With the floor,
 *  z_i M_ik >= z_i |c_ik| / 8 and a node moves at most 8 max_i(p_i / z_i) from its cells. The nodal solve and the
 *  subcell forces share the matrix, so conservation and the node balance hold as before. */
template <int D>
KOKKOS_INLINE_FUNCTION void freeSurfaceFloor(Mat<D>& M, double invNorm)
{
    const double floor = 0.125 / invNorm;
    const double lambda = smallestEigenvalueBelow<D>(M, floor);
    if (lambda < floor)
        for (int a = 0; a < D; ++a)
            M.a[a][a] += floor - lambda;
}

/*! \brief The time step's length of cell i: the insphere diameter 2|T|/sum_k |c_k| (Simplex::charLength), or the
 *  relaxation length 4|T| / lambda_max(sum_k M_ik) where that is smaller (docs/gpr-model.md 1.5).
 *  With the nodes held, the subcell forces relax the cell's velocity at the rate lambda = z lambda_max(sum_k M_ik) / m,
 *  and an explicit step is stable for lambda dt <= 2. On a regular simplex lambda_max = sum_k |c_k|, so lambda dt =
 *  2 CFL and the insphere diameter decides; on flat cells lambda_max reaches D sum_k |c_k|: split prisms and gmsh's
 *  tetrahedra have cells at 2.3-2.9 times, where CFL 0.5 gave lambda dt = 2.3-2.9 and Sod went wrong at its contact
 *  (docs/sod.md). The relaxation length keeps lambda dt <= 4 CFL (2 at the scenes' 0.5). A triangle never needs it:
 *  lambda_max(sum_j c_j c_j^T / |c_j|) <= its trace sum_j |c_j|, so its relaxation length is at least the incircle
 *  diameter (test TimeStepLength.TrianglesNeverNeedTheRelaxationLength), and 2D takes the incircle diameter. */
template <int D>
KOKKOS_INLINE_FUNCTION double timeStepLength(const RowField& corner, LO i, double insphereDiameter, double volume)
{
    if constexpr (D == 2)
        return insphereDiameter;
    else
    {
        // the relaxation length decides where lambda_max(S) > (2/3) trace S (sum_k M_ik = 3 S)
        const Mat<3> S = summedCornerOuters<3>(corner, i);
        const double floor = (2.0 / 3.0) * (S.a[0][0] + S.a[1][1] + S.a[2][2]);
        const double lambda = largestEigenvalueAbove(S, floor);
        if (!(lambda > floor))
            return insphereDiameter;
        const double relaxation = 4.0 * volume / (3.0 * lambda);
        return relaxation < insphereDiameter ? relaxation : insphereDiameter;
    }
}

} // namespace unilag
