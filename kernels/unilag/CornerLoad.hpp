/*! \file CornerLoad.hpp
 *  \brief The load of a cell's traction T = -p I + sigma on its corners (docs/gpr-model.md 2.2, 2.5): sigma c for the
 *  shear stress, and at second order the lumped load (corner values on the corner vector) or the consistent one
 *  (scene key scheme.corner_load). Used alike by the nodal solver (Hydro.hpp) and the subcell forces (CellUpdate.hpp).
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Gpr.hpp"
#include "unilag/Physics.hpp"
#include "unilag/Reconstruction.hpp"

namespace unilag
{

/*! \brief Shear-stress part of the traction on a corner: sigma c (the D x D block of the Sym3 stress). */
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> stressTimes(const gpr::Sym3& s, const Vec<D>& c)
{
    Vec<D> r;
    if constexpr (D == 2)
    {
        r[0] = s.xx * c[0] + s.xy * c[1];
        r[1] = s.xy * c[0] + s.yy * c[1];
    }
    else
    {
        r[0] = s.xx * c[0] + s.xy * c[1] + s.xz * c[2];
        r[1] = s.xy * c[0] + s.yy * c[1] + s.yz * c[2];
        r[2] = s.xz * c[0] + s.yz * c[1] + s.zz * c[2];
    }
    return r;
}

//! sigma_i c for the Sym3 stress row i of a field.
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> stressTimes(const ConstField& stress, LO i, const Vec<D>& c)
{
    return stressTimes<D>(loadSym3(stress, i, 0), c);
}

/*! \brief The load of cell i's traction on its corner k, L_k = integral over the cell's faces at node k of phi_k (p I -
 *  sigma) n ds (phi_k the node's hat function, n the outward normal; docs/gpr-model.md 2.5). For the cell's linear
 *  reconstruction q(x) = q_i + grad q . (x - x_i) on a straight simplex this is
 *      L_k = q_i c_k + |T_i| grad q / (D + 1),   q = p I - sigma (grad: grad p - div sigma),
 *  the cell value on the corner vector plus an equal share of the cell's net force. Why not the corner value q_k c_k:
 *  both give the same net force, but sum_k q_k c_k . v_k integrates the flux q v of linear fields with an error of
 *  O(h^3) per cell whose sign follows the cell's shape (mesh-scale entropy noise at second order), and sum_k L_k . v_k
 *  is exact. Only with scheme.corner_load: consistent (rec.consistentLoad): behind strong shocks on triangles it
 *  scatters the entropy more than the lumped load (docs/gpr-model.md 2.5), which stays the default. pk, sk: the corner
 *  values at k (cornerValues); the lumped load, and cell values (first order, or a pressure and stress at cell
 *  values), give (pk I - sk) c_k bit for bit. */
template <int D, class P>
KOKKOS_INLINE_FUNCTION bool consistentLoad(const Reconstruction<D>& rec)
{
    return rec.active() && rec.consistentLoad;
}

/*! L_k minus the lumped load (pk I - sk) c_k (cornerLoad): what the consistent load adds, -(delta T_k) c_k +
 *  |T_i| div T_i / (D + 1) with delta T_k the reconstruction's offset at node k. The kernels add it to their lumped
 *  terms, which thus stay bit for bit those of scheme.corner_load: lumped. */
template <int D, class P>
KOKKOS_INLINE_FUNCTION Vec<D> consistentLoadCorrection(const MeshView<D>& mesh, const RowField& corner,
                                                       const Reconstruction<D>& rec, LO i, int k)
{
    using R = ReconLayout<D, P>;
    const Vec<D> ck = cornerVec<D>(corner, i, k);
    const Vec<D> dk = rec.offset(i, mesh.cellNodes(i, k));
    const double share = rec.volume(i) / double(D + 1);
    Vec<D> net; // grad p - div sigma
    for (int a = 0; a < D; ++a)
        net[a] = rec.grad(i, R::pressure * D + a);
    Vec<D> load = (-rec.delta(i, R::pressure, dk)) * ck;
    if constexpr (P::strain)
    {
        constexpr int comp[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}}; // Sym3 xx yy zz xy xz yz of (row, column)
        gpr::Sym3 dsk{rec.delta(i, R::stress + 0, dk), rec.delta(i, R::stress + 1, dk),
                      rec.delta(i, R::stress + 2, dk), rec.delta(i, R::stress + 3, dk),
                      rec.delta(i, R::stress + 4, dk), rec.delta(i, R::stress + 5, dk)};
        load = load + stressTimes<D>(dsk, ck);
        for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b)
                net[a] -= rec.grad(i, (R::stress + comp[a][b]) * D + b);
    }
    return load + share * net;
}

//! The load of corner k (the comment above): lumped, plus the correction with scheme.corner_load: consistent.
template <int D, class P>
KOKKOS_INLINE_FUNCTION Vec<D> cornerLoad(const MeshView<D>& mesh, const RowField& corner, const Reconstruction<D>& rec,
                                         LO i, int k, double pk, const gpr::Sym3& sk)
{
    const Vec<D> ck = cornerVec<D>(corner, i, k);
    Vec<D> load = pk * ck;
    if constexpr (P::strain)
        load = load - stressTimes<D>(sk, ck);
    if (consistentLoad<D, P>(rec))
        load = load + consistentLoadCorrection<D, P>(mesh, corner, rec, i, k);
    return load;
}

} // namespace unilag
