/*! \file LatticeMesh.hpp
 *  \brief `mesh.mesher: lattice`: an axis-aligned rectangle (2D) or box (3D) from a .geo meshed as a regular lattice
 *  instead of by gmsh's frontal algorithm, with no small cell along its sides.
 *
 *  Why: gmsh's frontal mesh of a square lays a seam of half-size cells along each side. On a symmetry plane those
 *  small cells take the converging flow of a blast behind the shock and overshoot its density (2D Sedov: 8.07 at 16k
 *  cells against the exact 6; 3D, 4.8k tetrahedra: 8.06 at order 2; docs/sedov-peak.md, sessions 33-36).
 *  - 2D: equilateral rows along y = y0; in every odd row but the first the node half a cell from x = x0 (and from
 *    x = x1) is moved onto that side, so the cells along it are one full triangle and one of 1.5 times its area
 *    instead of half a cell. The first odd row keeps its half cells so that the corner node (where a blast is
 *    deposited) keeps the lattice's own cells: one right triangle there made the blast lopsided.
 *  - 3D: the body-centred cubic lattice (corners and cell centres), whose tetrahedra are congruent; the boundary
 *    faces' two triangles with their cell's centre are tetrahedra of the same volume.
 *  The size is the triangle's edge (2D) or the cubic cell's (3D; the tetrahedra's edges are it and 0.87 of it).
 */
#pragma once

#include <string>

namespace unilag
{

/*! Meshes the current gmsh model (a .geo already opened and synchronised) as a lattice of edge about `size`: the
 *  model must be one surface (2D) or volume (3D) whose boundary entities lie on the sides of its axis-aligned
 *  bounding box; nodes and cells go to that entity, boundary lines (triangles) to the curve (surface) they lie on, so
 *  the .geo's physical groups name them. Throws InputError naming `source` and the offending entity otherwise. */
void meshAsLattice(const std::string& source, double size);

} // namespace unilag
