/*! \file RankineHugoniot.hpp
 *  \brief The talk's jump conditions across a shock in a moving, stretched tube (tube.md 1.8), evaluated on
 *  computed solutions: the states on both sides averaged over windows of cells, the tube's metric there, and
 *  each relation's defect relative to its largest term. Used by the tests and apps/tube_gas_rod_study.
 */
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "tube/TubeGas.hpp"

namespace unilag::tube
{

//! One side of a shock in the talk's variables: rho, u (s per time), p, e, and the metric
//! (|Gamma|^2, Gamma.gamma, |gamma|^2) there.
struct ShockSide
{
    double rho = 0, u = 0, p = 0, e = 0;
    std::array<double, 3> metric{0, 0, 0};
    double entropy(double gamma) const; //!< ln(p / rho^gamma)
};

/*! The state next to a shock at s = `at`: each quantity's least-squares line over the cells with centres in
 *  [from, to] (a window clear of the front's few smeared cells), evaluated at `at` (waves behind and ahead of a
 *  shock in a moving tube leave gradients that a plain mean would charge to the jump). `metric` per cell. */
ShockSide shockSide(const GasFields& fields, const std::vector<std::array<double, 3>>& metric, double from, double to,
                    double at, double gamma);

/*! Defects of the three relations of tube.md 1.8 across a shock of speed cs (s per time), each |sum of its
 *  terms| / (largest term), with the metric m = (|G|^2, G.g, |g|^2) at the shock:
 *    c[rho] = [rho u]
 *    c[rho] G.g + c[rho u] |G|^2 = [rho u] G.g + [rho u^2] |G|^2 + [p]
 *    c[rho (e + |g + G u|^2 / 2)] = [rho u |g + G u|^2 / 2 + (p / |G|^2) G.(g + G u) + rho u e]. */
std::array<double, 3> rankineHugoniotDefects(const ShockSide& behind, const ShockSide& ahead, double cs,
                                             const std::array<double, 3>& m);

/*! A shock's speed at t0 from its positions at `samples` times evenly spread over [t0 - halfWidth, t0 + halfWidth]
 *  (least squares): a two-point difference carries the front's sub-cell jitter (about 1% at 14 cells apart).
 *  positionAt(t) advances the solver to t (called with increasing t, t0 among them for odd samples) and returns the
 *  shock's position. */
double fittedShockSpeed(const std::function<double(double t)>& positionAt, double t0, double halfWidth, int samples);

//! A shock measured on a running solution: where and how fast, both sides, the metric, the relations' defects.
struct ShockJump
{
    double position = 0, speed = 0, entropyJump = 0;
    ShockSide behind, ahead;
    std::array<double, 3> metric{0, 0, 0}; //!< the mean of the two sides' (|G|^2, G.g, |g|^2)
    std::array<double, 3> defects{0, 0, 0};
};

//! How a shock is measured: the speed fit over t0 +- halfWidth (samples), the sides' windows [near, far] away.
struct ShockWindows
{
    double halfWidth = 0.02;
    int samples = 9;
    double near = 0.01, far = 0.03;
};

using CellMetric = std::vector<std::array<double, 3>>;

/*! Measures the shock at t0 on a solver that advance(t) moves forward (increasing t only), position() locates
 *  its shock and snapshot() copies its fields and cell metric: fittedShockSpeed, then shockSide on both sides at
 *  t0, then rankineHugoniotDefects with the mean metric. */
ShockJump measureShockJump(const std::function<void(double t)>& advance, const std::function<double()>& position,
                           const std::function<std::pair<GasFields, CellMetric>()>& snapshot, double t0, double gamma,
                           const ShockWindows& windows = {});

} // namespace unilag::tube
