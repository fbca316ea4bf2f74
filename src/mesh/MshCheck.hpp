/*! \file MshCheck.hpp
 *  \brief The structure of a gmsh .msh file, checked before gmsh reads it: gmsh's own reader trusts the counts and
 *  node references of the file and crashes on many malformed ones (a node line without its z coordinate is a
 *  segmentation fault in gmsh 4.8), where a user must get one message naming the file and line (README, "Bad input").
 */
#pragma once

#include <string>

namespace unilag
{

/*! Check the sections of the .msh file at path that gmsh reads without checking: ASCII format 2.2 and 4.1, $Nodes,
 *  $Elements, $PhysicalNames and (4.1) $Entities: counts, fields per line, finite coordinates, known element types,
 *  node tags that exist. Other sections only need their $End line. Binary files and other versions go to gmsh
 *  unchecked. Throws InputError "PATH: line N: what" on the first defect. */
void checkMshFile(const std::string& path);

} // namespace unilag
