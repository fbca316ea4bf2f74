/*! \file TubeGasRod.hpp
 *  \brief Kernels that couple the gas (TubeGas.hpp) to the free rod (TubeRod.hpp): docs/tube-gas-rod.md.
 *
 *  The coupled state is the rod's (positions r_k, frames, spins) with the TOTAL linear momentum P_k of each node
 *  (wall + the gas of its two half cells), and the gas's (xi_j, m_j, E_j) per cell (segment j, nodes j, j+1).
 *  The gas's spatial momentum per unit s is xi P_perp r_t + (m / c) r' (tube.md 1.8: its tangential part is m,
 *  its transverse part moves with the tube), lumped half a cell to each node:
 *    P_k = M_k v_k + F_k,  M_k = alpha_k I + sum_j (h/2) xi_j (I - t_j t_j^T),  F_k = sum_j (h/2) (m_j / c_j) r'_j,
 *  t_j = r'_j / |r'_j|, c_j = |r'_j|^2. With the gas's (xi, m, entropy) held, the rod part is Hamiltonian:
 *    H = sum_k (P_k - F_k).M_k^-1 (P_k - F_k)/2 + sum_j h [m_j^2 / (2 xi_j c_j) + xi_j e_j(Q_j) + p_ext Q_j]
 *        + (rod elastic and rotary energy),  Q_j = A_j |r'_j|,
 *  and the gas's load on the rod (GasSegmentForce) is exactly -dH/dr: energy and momentum are exchanged as one.
 *  An expandable wall R_j (tube.md 1.3: kinetic a R_t^2 |Gamma| / 2, elastic b (R - R0)^2 |Gamma| / 2, A = pi R^2)
 *  adds sum_j h [pi_R^2 / (2 a sqrt c) + sqrt c b (R - R0)^2 / 2] with its momentum pi_R = a sqrt(c) R_t held.
 *  Kokkos core only; every kernel writes its own node or cell.
 */
#pragma once

#include <Kokkos_Core.hpp>

#include "unilag/TubeGas.hpp"
#include "unilag/TubeRod.hpp"
#include "unilag/TubeWall.hpp"

namespace unilag::gasrod
{

using gas::MetricView;
using gas::StateView;
using rod::cross;
using rod::dot;
using rod::loadV3;
using rod::M3;
using rod::RodViews;
using rod::storeV3;
using rod::V3;
using rod::v3;
using rod::Vec3View;
using ScalarView = Kokkos::View<double*, gas::MemSpace>;

KOKKOS_INLINE_FUNCTION V3 segmentTangent(const RodViews& rod, int j) //!< r'_j = (r_{j+1} - r_j) / h
{
    return (1.0 / rod.h) * (loadV3(rod.position, j + 1) - loadV3(rod.position, j));
}

KOKKOS_INLINE_FUNCTION int nodeFlags(const RodViews& rod, int k)
{
    return k == 0 ? rod.leftFlags : (k == rod.segments ? rod.rightFlags : 0);
}

//! The gas's speed relative to the tube, v = u sqrt(c) with u = (m / xi - g) / c, in cell j under `cell`'s metric.
KOKKOS_INLINE_FUNCTION double relativeSpeed(const StateView& q, const MetricView& cell, int j)
{
    const double c = cell(j, 0);
    return (q(j, 1) / q(j, 0) - cell(j, 1)) / c * Kokkos::Experimental::sqrt(c);
}

//! The gas's internal energy per unit s, U = E - xi (v^2 - k) / 2 (E = xi (e + v^2/2 - k/2), TubeGas.hpp).
KOKKOS_INLINE_FUNCTION double gasInternalEnergy(const StateView& q, const MetricView& cell, int j)
{
    const double v = relativeSpeed(q, cell, j);
    return q(j, 2) + 0.5 * q(j, 0) * (cell(j, 2) - v * v);
}

//! Cells: the gas's metric (c, g, k) = (|r'|^2, r'.r_t, |r_t|^2), r_t the mean of the two nodes' velocities.
struct SegmentMetric
{
    RodViews rod;
    MetricView cell;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const V3 xs = segmentTangent(rod, j);
        const V3 vt = 0.5 * (loadV3(rod.velocity, j) + loadV3(rod.velocity, j + 1));
        cell(j, 0) = dot(xs, xs);
        cell(j, 1) = dot(xs, vt);
        cell(j, 2) = dot(vt, vt);
    }
};

//! Faces: the mean of the two adjacent cells' metrics (an end face takes its cell's), so that the gas's
//! inertial source sees the central difference of the cell metrics.
struct FaceMetric
{
    MetricView cell, face;
    int cells;
    KOKKOS_INLINE_FUNCTION void operator()(int f) const
    {
        const int l = f > 0 ? f - 1 : 0, r = f < cells ? f : cells - 1;
        for (int a = 0; a < 3; ++a)
            face(f, a) = 0.5 * (cell(l, a) + cell(r, a));
    }
};

//! The lumped inertia of node k: M_k and F_k of the file comment.
struct NodeInertia
{
    M3 mass;
    V3 fluid;
};

KOKKOS_INLINE_FUNCTION NodeInertia nodeInertia(const RodViews& rod, const StateView& q, int k)
{
    NodeInertia in;
    for (int a = 0; a < 3; ++a)
    {
        in.fluid[a] = 0.0;
        for (int b = 0; b < 3; ++b)
            in.mass.a[a][b] = a == b ? rod.mass(k) : 0.0;
    }
    for (int j = k - 1; j <= k; ++j)
    {
        if (j < 0 || j >= rod.segments)
            continue;
        const V3 xs = segmentTangent(rod, j);
        const double c = dot(xs, xs), half = 0.5 * rod.h;
        for (int a = 0; a < 3; ++a)
        {
            in.fluid[a] += half * q(j, 1) / c * xs[a];
            for (int b = 0; b < 3; ++b)
                in.mass.a[a][b] += half * q(j, 0) * ((a == b ? 1.0 : 0.0) - xs[a] * xs[b] / c);
        }
    }
    return in;
}

//! x = m^-1 b for an invertible 3 x 3 m (adjugate over determinant).
KOKKOS_INLINE_FUNCTION V3 solve3(const M3& m, const V3& b)
{
    const double(&a)[3][3] = m.a;
    const double adj[3][3] = {{a[1][1] * a[2][2] - a[1][2] * a[2][1], a[0][2] * a[2][1] - a[0][1] * a[2][2],
                               a[0][1] * a[1][2] - a[0][2] * a[1][1]},
                              {a[1][2] * a[2][0] - a[1][0] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0],
                               a[0][2] * a[1][0] - a[0][0] * a[1][2]},
                              {a[1][0] * a[2][1] - a[1][1] * a[2][0], a[0][1] * a[2][0] - a[0][0] * a[2][1],
                               a[0][0] * a[1][1] - a[0][1] * a[1][0]}};
    const double inv = 1.0 / (a[0][0] * adj[0][0] + a[0][1] * adj[1][0] + a[0][2] * adj[2][0]);
    V3 x;
    for (int i = 0; i < 3; ++i)
        x[i] = inv * (adj[i][0] * b[0] + adj[i][1] * b[1] + adj[i][2] * b[2]);
    return x;
}

//! Nodes: P_k = M_k v_k + F_k (the coupled state's momentum, from the velocities; at the start of a run).
struct TotalMomentum
{
    RodViews rod;
    StateView q;
    Vec3View momentum;
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        const NodeInertia in = nodeInertia(rod, q, k);
        storeV3(momentum, k, rod::mul(in.mass, loadV3(rod.velocity, k)) + in.fluid);
    }
};

//! Nodes: v_k = M_k^-1 (P_k - F_k), after anything changed M or F (the gas moved, the rod drifted); 0 where the
//! position is held.
struct VelocityFromMomentum
{
    RodViews rod;
    StateView q;
    Vec3View momentum;
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        if (rod::positionFixed(nodeFlags(rod, k)))
        {
            storeV3(rod.velocity, k, v3(0, 0, 0));
            return;
        }
        const NodeInertia in = nodeInertia(rod, q, k);
        storeV3(rod.velocity, k, solve3(in.mass, loadV3(momentum, k) - in.fluid));
    }
};

/*! Segments: the gas's load n_j = dH/dr'_j (node j takes +n_j, node j+1 takes -n_j, as the elastic segment
 *  forces), the gas's (xi, m, entropy S = p / rho^gamma) held:
 *    n_j = sum_{k=j,j+1} [ xi (v_k.t) P_perp v_k / (2 sqrt c) - m (v_k - 2 (v_k.t) t) / (2 c) ]
 *          - m^2 r' / (xi c^2) - (p - p_ext) A t,
 *  the lumped form of the talk's -xi u (gamma + u Gamma) - (p - p_ext) dQ/dGamma (tube.md 1.5: its centrifugal
 *  and Coriolis parts, and the pressure that pushes the end caps apart). */
struct GasSegmentForce
{
    RodViews rod;
    StateView q;
    ScalarView area, entropy;
    Vec3View load;
    double gamma, pExt;
    //! the wall (when `wall`): radius, momentum pi_R per unit s; its load (b (R - R0)^2 - pi_R^2 / (a c)) t / 2
    bool wall = false;
    ScalarView radius, wallMomentum;
    wall::WallParams w{};
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const V3 xs = segmentTangent(rod, j);
        const double c = dot(xs, xs), root = Kokkos::Experimental::sqrt(c);
        const V3 t = (1.0 / root) * xs;
        const double xi = q(j, 0), m = q(j, 1);
        const double rho = xi / (area(j) * root), p = entropy(j) * Kokkos::Experimental::pow(rho, gamma);
        V3 n = (-m * m / (xi * c * c)) * xs - ((p - pExt) * area(j)) * t;
        if (wall)
        {
            const double stretch = radius(j) - w.restRadius, pr = wallMomentum(j);
            n = n + (0.5 * w.b * stretch * stretch - 0.5 * pr * pr / (w.a * c)) * t;
        }
        for (int k = j; k <= j + 1; ++k)
        {
            const V3 v = loadV3(rod.velocity, k);
            const double vt = dot(v, t);
            n = n + (0.5 * xi * vt / root) * (v - vt * t) - (0.5 * m / c) * (v - (2.0 * vt) * t);
        }
        storeV3(load, j, n);
    }
};

//! Nodes: P_k += tau (elastic load + n_k - n_{k-1}), spins kicked by the elastic torque (rod.force, rod.torque
//! stored by the rod's node gather; the end nodes take one segment's gas load).
struct CoupledKick
{
    RodViews rod;
    Vec3View load, momentum;
    double tau;
    bool spins; // the elastic torque kicks the spins (once per kick: the implicit kick repeats the momentum part)
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        V3 f = loadV3(rod.force, k);
        if (k < rod.segments)
            f = f + loadV3(load, k);
        if (k > 0)
            f = f - loadV3(load, k - 1);
        const int flags = nodeFlags(rod, k);
        for (int a = 0; a < 3; ++a)
        {
            if (!rod::positionFixed(flags))
                momentum(k, a) += tau * f[a];
            if (spins && !rod::rotationFixed(flags))
                rod.spin(k, a) += tau * rod.torque(k, a);
        }
    }
};

//! Cells: the entropy S = p / rho^gamma of the gas state under the metric its last step used.
struct SaveEntropy
{
    StateView q;
    ScalarView area, entropy;
    MetricView cell;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double volume = area(j) * Kokkos::Experimental::sqrt(cell(j, 0)), rho = q(j, 0) / volume;
        const double p = (gamma - 1.0) * gasInternalEnergy(q, cell, j) / volume;
        entropy(j) = p / Kokkos::Experimental::pow(rho, gamma);
    }
};

//! Cells: E = xi (e + v^2/2 - k/2) rebuilt for a new metric, from the held (xi, m, S): the rod moved.
struct RestateEnergy
{
    StateView q;
    ScalarView area, entropy;
    MetricView cell;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double volume = area(j) * Kokkos::Experimental::sqrt(cell(j, 0)), xi = q(j, 0), rho = xi / volume;
        const double p = entropy(j) * Kokkos::Experimental::pow(rho, gamma), v = relativeSpeed(q, cell, j);
        q(j, 2) = volume * p / (gamma - 1.0) + 0.5 * xi * (v * v - cell(j, 2));
    }
};

//! Nodes: the implicit drift's trapezoidal positions r = r0 + tau (v0 + v) / 2 (held nodes stay).
struct TrapezoidalPositions
{
    RodViews rod;
    Vec3View start, startVelocity;
    double tau;
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        if (rod::positionFixed(nodeFlags(rod, k)))
            return;
        for (int a = 0; a < 3; ++a)
            rod.position(k, a) = start(k, a) + 0.5 * tau * (startVelocity(k, a) + rod.velocity(k, a));
    }
};

//! Nodes: mid = (start + now) / 2.
struct MidpointVelocity
{
    Vec3View start, now, mid;
    KOKKOS_INLINE_FUNCTION void operator()(int k) const
    {
        for (int a = 0; a < 3; ++a)
            mid(k, a) = 0.5 * (start(k, a) + now(k, a));
    }
};

//! Nodes: the gas's transverse kinetic energy v_k.(M_k - alpha_k I) v_k / 2 (its tangential part is per cell).
struct NodeGasKinetic
{
    RodViews rod;
    StateView q;
    KOKKOS_INLINE_FUNCTION void operator()(int k, double& sum) const
    {
        NodeInertia in = nodeInertia(rod, q, k);
        for (int a = 0; a < 3; ++a)
            in.mass.a[a][a] -= rod.mass(k);
        const V3 v = loadV3(rod.velocity, k);
        sum += 0.5 * dot(v, rod::mul(in.mass, v));
    }
};

//! Cells, one part of the gas's energy times h: 0 tangential kinetic m^2 / (2 xi c), 1 internal Q p / (g - 1),
//! 2 the outside's p_ext Q (p from the held entropy on the current geometry).
struct CellGasEnergy
{
    RodViews rod;
    StateView q;
    ScalarView area, entropy;
    double gamma, pExt;
    int part;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& sum) const
    {
        const V3 xs = segmentTangent(rod, j);
        const double c = dot(xs, xs), volume = area(j) * Kokkos::Experimental::sqrt(c), xi = q(j, 0);
        const double p = entropy(j) * Kokkos::Experimental::pow(xi / volume, gamma);
        const double e[3] = {q(j, 1) * q(j, 1) / (2.0 * xi * c), volume * p / (gamma - 1.0), pExt * volume};
        sum += rod.h * e[part];
    }
};

/*! Cells: the wall's momentum pi_R = a sqrt(c) R_t from its speed (toSpeed false), or the speed back from the
 *  momentum on the rod as it now is (toSpeed true): the rod part holds pi_R, not R_t. */
struct WallMomentum
{
    RodViews rod;
    ScalarView speed, momentum;
    double a;
    bool toSpeed;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const V3 xs = segmentTangent(rod, j);
        const double scale = a * Kokkos::Experimental::sqrt(dot(xs, xs));
        if (toSpeed)
            speed(j) = momentum(j) / scale;
        else
            momentum(j) = scale * speed(j);
    }
};

/*! Cells: the wall's exchange with the gas on the frozen rod (tube.md 1.5 with |Gamma| = sqrt c): the cell's
 *  H = a sqrt(c) V^2/2 + sqrt(c) [b (R - R0)^2/2 + p_ext pi R^2] + U(pi R^2 sqrt c), U the gas's internal energy
 *  per unit s, is sqrt(c) times the rigid tube's with U / sqrt(c) for U: the rigid discrete-gradient step
 *  (kernels/unilag/TubeWall.hpp) solves it, and the gas gains the whole adiabatic U change. No axial tension. */
struct WallExchangeOnRod
{
    StateView q;
    ScalarView areaCell, radius, speed, dissipated;
    MetricView cell;
    wall::WallParams w;
    double gamma, dt;
    KOKKOS_INLINE_FUNCTION void operator()(int j) const
    {
        const double root = Kokkos::Experimental::sqrt(cell(j, 0)), internal = gasInternalEnergy(q, cell, j);
        const wall::CellExchange x{w, internal / root, radius(j), speed(j), gamma, dt};
        const double d = wall::solveExchange(x), v1 = 2.0 * d / dt - x.v0, vm = 0.5 * (x.v0 + v1);
        q(j, 2) += wall::adiabaticEnergyChange(internal, x.r0, d, gamma);
        radius(j) = x.r0 + d;
        speed(j) = v1;
        areaCell(j) = wall::pi * radius(j) * radius(j);
        dissipated(j) += root * w.c * dt * vm * vm;
    }
};

//! max over cells of the wall's own frequency (W''/a)^(1/2) on the rod (the step's resolution bound; U / sqrt c as
//! in WallExchangeOnRod).
struct WallFrequencyOnRod
{
    StateView q;
    ScalarView radius;
    MetricView cell;
    wall::WallParams w;
    double gamma;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& m) const
    {
        const double root = Kokkos::Experimental::sqrt(cell(j, 0)), internal = gasInternalEnergy(q, cell, j);
        const double omega =
            Kokkos::Experimental::sqrt(wall::potentialCurvature(w, internal / root, radius(j), gamma) / w.a);
        m = omega > m ? omega : m;
    }
};

//! Cells, one part of the wall's energy times h: 0 kinetic a sqrt(c) V^2/2, 1 elastic sqrt(c) b (R - R0)^2/2,
//! 2 the viscous loss so far.
struct CellWallEnergy
{
    RodViews rod;
    ScalarView radius, speed, dissipated;
    wall::WallParams w;
    int part;
    KOKKOS_INLINE_FUNCTION void operator()(int j, double& sum) const
    {
        const V3 xs = segmentTangent(rod, j);
        const double root = Kokkos::Experimental::sqrt(dot(xs, xs)), stretch = radius(j) - w.restRadius;
        const double e[3] = {0.5 * w.a * root * speed(j) * speed(j), 0.5 * w.b * root * stretch * stretch,
                             dissipated(j)};
        sum += rod.h * e[part];
    }
};

} // namespace unilag::gasrod
