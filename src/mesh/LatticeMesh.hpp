/*! \file LatticeMesh.hpp
 *  \brief `mesh.mesher: lattice`: a rectangle from a .geo meshed as an equilateral triangle lattice instead of by
 *  gmsh's frontal algorithm.
 *
 *  Why: gmsh's frontal mesh of a square lays a seam of half-size cells along each side. On a symmetry plane those
 *  small cells take the converging flow of a blast behind the shock and overshoot its density (2D Sedov: 8.07 at 16k
 *  cells against the exact 6). The lattice's rows run along y = y0, and in every odd row but the first the node half a
 *  cell from x = x0 (and from x = x1) is moved onto that side, so the cells along x = x0 are one full triangle and one
 *  of 1.5 times its area instead of half a cell; the first odd row keeps its half cells so that the corner node
 *  (where a blast is deposited) keeps the lattice's own cells (docs/sedov-peak.md, sessions 35-36).
 */
#pragma once

#include <string>

namespace unilag
{

/*! Meshes the current gmsh model (a .geo already opened and synchronised) as a lattice of edge about `size`: the
 *  model must be one plane surface whose boundary curves lie on the sides of an axis-aligned rectangle; nodes and
 *  triangles go to that surface, boundary lines to the curve they lie on, so the .geo's physical groups name them.
 *  Throws InputError naming `source` and the offending entity otherwise. */
void meshAsLattice(const std::string& source, double size);

} // namespace unilag
