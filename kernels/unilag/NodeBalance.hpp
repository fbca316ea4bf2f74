/*! \file NodeBalance.hpp
 *  \brief The momentum balance at the nodes (docs/gpr-model.md 2.2), from the subcell forces the cell update
 *  applied: F_r = sum_i f_ri, the net force the cells around node r receive through it.
 *
 *  Momentum is conserved because the nodal solver makes F_r vanish wherever no boundary condition acts; at a
 *  boundary node F_r is the force of the boundary on the material. So
 *   - interior, free, pressure and traction nodes: F_r = b_r, the imposed traction sum_f (s_f / D) t_ext of the
 *     boundary faces at r (zero when there are none);
 *   - slip walls and symmetry planes add a reaction R_r = F_r - b_r that does no work: R_r . v_r = 0 (relative to
 *     |R_r| (|v_r| + c), c the largest sound speed around r);
 *   - imposed velocities (pistons, clamps): F_r is whatever reaction holds the velocity.
 *  The boundary impulse and work the conservation check subtracts are sums of F_r and F_r . v_r over boundary
 *  nodes only, so an interior imbalance shows both here and as a momentum change. Checked with --check.
 */
#pragma once

#include "unilag/CellUpdate.hpp"

namespace unilag
{

//! Rates summed over boundary nodes, and the largest relative imbalance (round-off if the scheme balances).
template <int D> struct NodeBalanceRates
{
    double impulse[D] = {}; //!< sum of F_r over boundary nodes: d(momentum)/dt
    double work = 0.0;      //!< sum of F_r . v_r over boundary nodes: d(energy)/dt of the subcell forces
    double passiveWork = 0.0; //!< of walls, symmetry planes and free surfaces: sum (F_r - b_r) . v_r (must vanish)
    double maxImbalance = 0.0; //!< max |F_r - b_r| (or |(F_r - b_r) . v_r| / |v_r| at walls) / sum_i |f_ri| parts
    LO worstNode = -1;        //!< local node with maxImbalance (-1 if none)
    double maxForce = 0.0;    //!< the largest sum_i |f_ri| parts over the nodes
};

//! Columns of the per-node scratch written by nodeBalance before it is reduced.
template <int D> struct NodeBalanceLayout
{
    enum : int // enumerators, not static members: device code may bind them to references (View indices)
    {
        force = 0,
        power = D,
        passivePower = D + 1,
        imbalance = D + 2,
        scale = D + 3, //!< sum_i |f_ri| parts
        ncomp = D + 4
    };
};

/*! rates.maxImbalance and worstNode over the nodes of out (nodeBalance's) whose forces exceed forceFloor. The
 *  solver passes 1e-30 of the largest forces on any rank: a cold gas's precursor (velocities down to 1e-300,
 *  docs/cold-gas.md) has its nodal solve on impedances that vanish with the velocity (a = 0, z = rho Gamma |dv|),
 *  whose round-off is not relative to the node's forces (ars222 with node_fit on the cold piston: interior nodes
 *  with forces of 1e-131 to 1e-150 and a relative imbalance of 1; on the cold 3D Sedov octant 1e-97, with 0.69).
 *  Such forces move no conserved total by 1e-13; an ambient pressure of 1e-6 still gives 1e-8 and is checked. */
template <int D>
void worstImbalance(const View<const LO*>& nodes, const Field& out, double forceFloor, NodeBalanceRates<D>& rates)
{
    using L = NodeBalanceLayout<D>;
    const LO count = LO(nodes.extent(0));
    rates.maxImbalance = 0.0;
    rates.worstNode = -1;
    if (count == 0)
        return;
    // the largest imbalance, then the first node that has it (minima join element-wise, hence two passes); a node
    // whose forces are not finite counts as the largest (fmin would skip a nan, and nan > forceFloor is false)
    const double huge = Kokkos::reduction_identity<double>::min();
    auto negated = KOKKOS_LAMBDA(const LO n, double(&acc)[1])
    {
        const double scale = out(n, L::scale), imbalance = out(n, L::imbalance);
        const bool finite = scale - scale == 0.0 && imbalance - imbalance == 0.0;
        const double value = !finite ? -huge : (scale > forceFloor ? -imbalance : huge);
        acc[0] = Kokkos::Experimental::fmin(acc[0], value);
    };
    double largest[1], first[1];
    minReduce<1>("unilag::check::node_balance_max", count, negated, largest);
    const double worst = largest[0] < 0.0 ? largest[0] : 0.0;
    auto index = KOKKOS_LAMBDA(const LO n, double(&acc)[1])
    {
        double value[1] = {huge};
        negated(n, value);
        if (value[0] == worst && double(n) < acc[0])
            acc[0] = double(n);
    };
    minReduce<1>("unilag::check::node_balance_worst", count, index, first);
    rates.maxImbalance = -worst;
    if (!(first[0] < double(count)))
        return;
    LO node = -1;
    Kokkos::deep_copy(Kokkos::View<LO, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(&node),
                      Kokkos::subview(nodes, LO(first[0])));
    rates.worstNode = node;
}

/*! F_r and its expected value at the nodes in `nodes` (owned), per node into `out` (NodeBalanceLayout), then summed,
 *  with the largest force; the worst imbalance is worstImbalance's, once the caller has the floor (over all ranks).
 *  Non-boundary nodes add nothing to the sums but their imbalance. `forces` must be those of the last update. */
template <int D, class P>
NodeBalanceRates<D> nodeBalance(const SubcellForces<D, P>& forces, const BoundaryView& bc, const View<const LO*>& nodes,
                                const Field& out)
{
    using L = NodeBalanceLayout<D>;
    constexpr int NV = D + 1;
    const MeshView<D> mesh = forces.mesh;
    auto corner = forces.corner;
    auto balance = KOKKOS_LAMBDA(const LO n)
    {
        const LO r = nodes(n);
        Vec<D> F = Vec<D>::zero(), b = Vec<D>::zero(), v = Vec<D>::zero();
        double scale = 0.0, sound = 0.0;
        bool boundary = false, wall = false, imposed = false;
        for (LO q = mesh.nodeCornerOffsets(r); q < mesh.nodeCornerOffsets(r + 1); ++q)
        {
            const LO i = mesh.nodeCorners(q) / NV;
            const int k = mesh.nodeCorners(q) % NV;
            F = F + forces.cornerForce(i, k, v, &scale);
            sound = Kokkos::Experimental::fmax(sound, forces.aux(i, Aux::sound));
            for (int j = 0; j < NV; ++j)
            {
                const int g = j == k ? -1 : mesh.cellFaceGroup(i, j);
                if (g < 0)
                    continue;
                boundary = true;
                const int t = bc.type(g);
                imposed = imposed || t == BcVelocity;
                wall = wall || t == BcSlipWall;
                if (t == BcPressure) // (s_f / D) t_ext = p c_j, as in the nodal solve
                    b = b + bc.value(g, 0) * cornerVec<D>(corner, i, j);
                else if (t == BcTraction)
                {
                    const double w = norm(cornerVec<D>(corner, i, j));
                    for (int d = 0; d < D; ++d)
                        b[d] += w * bc.value(g, d);
                }
            }
        }
        const Vec<D> reaction = F - b;
        double imbalance = 0.0, passive = 0.0;
        if (!imposed && wall)
        {
            // relative to the node's speed and the sound speed: at rest v_r is a round-off normal velocity
            passive = dot(reaction, v);
            const double speed = norm(v) + sound;
            imbalance = speed * scale > 0.0 ? Kokkos::Experimental::fabs(passive) / (speed * scale) : 0.0;
        }
        else if (!imposed)
        {
            passive = boundary ? dot(reaction, v) : 0.0;
            imbalance = scale > 0.0 ? norm(reaction) / scale : 0.0;
        }
        for (int d = 0; d < D; ++d)
            out(n, L::force + d) = boundary ? F[d] : 0.0;
        out(n, L::power) = boundary ? dot(F, v) : 0.0;
        out(n, L::passivePower) = passive;
        out(n, L::imbalance) = imbalance;
        out(n, L::scale) = scale;
    };
    const LO count = LO(nodes.extent(0));
    Kokkos::parallel_for("unilag::check::node_balance", range(count), balance);

    NodeBalanceRates<D> rates;
    double sums[D + 2];
    auto sum = KOKKOS_LAMBDA(const LO n, double(&acc)[D + 2])
    {
        for (int c = 0; c < D + 2; ++c)
            acc[c] = out(n, c);
    };
    sumReduce<D + 2>("unilag::check::node_balance_sums", count, sum, sums);
    for (int d = 0; d < D; ++d)
        rates.impulse[d] = sums[L::force + d];
    rates.work = sums[L::power];
    rates.passiveWork = sums[L::passivePower];
    double largest[1];
    auto negatedScale = KOKKOS_LAMBDA(const LO n, double(&acc)[1])
    {
        acc[0] = Kokkos::Experimental::fmin(acc[0], -out(n, L::scale));
    };
    minReduce<1>("unilag::check::node_balance_force", count, negatedScale, largest);
    rates.maxForce = count > 0 ? -largest[0] : 0.0;
    return rates;
}

} // namespace unilag
