/*! \file Heat.hpp
 *  \brief Placeholder: explicit Rusanov heat fluxes (gpr.md 2.3) land from the `heat` branch.
 */
#pragma once

#include "unilag/Geometry.hpp"
#include "unilag/Physics.hpp"

namespace unilag
{
template <int D, class P>
void heatFluxes(const MeshView<D>&, const BoundaryView&, const ConstField&, const ConstField&, const CellGeometry&,
                const View<const int*>&, const View<const Material*>&, const Field& rate)
{
    Kokkos::deep_copy(rate, 0.0);
}
} // namespace unilag
