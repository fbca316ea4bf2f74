#pragma once
/*! \file XdmfWriter.hpp
 *  \brief Parallel HDF5 + XDMF3 output of cell- and node-centred fields on triangle, tetrahedron or polyline
 *  meshes (ParaView/VisIt readable).
 */
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1  // C API only; OpenMPI's deprecated C++ bindings warn under -Wextra
#endif
#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace unilag::io {

/*! \brief The cells a writer writes: triangles and tetrahedra (the GPR solver's simplices) or polylines (the tube
 *  solver's 2-node segments, XDMF TopologyType "Polyline" with NodesPerElement="2"). */
enum class CellType { Triangle, Tetrahedron, Polyline };

//! Nodes per cell: 3, 4 or 2.
int nodesPerCell(CellType type);

//! The simplex of dimension \p dim: Triangle (2) or Tetrahedron (3). \throws std::invalid_argument otherwise.
CellType simplexCellType(int dim);

/*! \brief One cell-centred field on this rank's owned cells. */
struct CellField {
  std::string name;    //!< dataset/attribute name, e.g. "density" (letters, digits, '_', '-', '.')
  int ncomp;           //!< 1 = scalar, 3 = vector (always 3 for vectors, z = 0 in 2D), 6 = symmetric tensor (xx yy zz xy yz xz)
  const double* data;  //!< row-major, nOwnedCells * ncomp
};

/*! \brief One node-centred field on this rank's owned nodes (the same names and ncomp as a CellField). */
struct NodeField {
  std::string name;    //!< unique among all fields of a dump, cell fields included
  int ncomp;           //!< 1, 3 or 6
  const double* data;  //!< row-major, nOwnedNodes * ncomp, in the order of the owned nodes' output ids
};

/*! \brief Writes one self-contained HDF5 file per dump plus XDMF3 descriptions of it.
 *
 *  Each dump <dir>/<basename>_NNNNNN.h5 holds /coordinates, /connectivity and one dataset per field (cell or node),
 *  written collectively with MPI-IO. Rank 0 writes <basename>_NNNNNN.xmf (one Uniform grid) and keeps
 *  <basename>.xmf, a Temporal Collection that includes every dump written by this writer.
 *  All member functions except collectionPath() are collective over the communicator.
 */
class XdmfWriter {
public:
  /*! \brief Create a writer of \p cellType cells. \p dir must already exist; \p comm is duplicated. */
  XdmfWriter(MPI_Comm comm, std::string dir, std::string basename, CellType cellType);
  /*! \brief A writer of simplices of dimension \p dim: 2 (triangles) or 3 (tetrahedra). */
  XdmfWriter(MPI_Comm comm, std::string dir, std::string basename, int dim);
  /*! \brief Frees the duplicated communicator (if MPI is still initialised). */
  ~XdmfWriter();
  XdmfWriter(const XdmfWriter&) = delete;
  XdmfWriter& operator=(const XdmfWriter&) = delete;

  /*! \brief Set (or reset after repartitioning) the owned node/cell counts and the owned cells'
   *         connectivity as 0-based global output node ids, nodesPerCell() per cell, row-major. Collective.
   *
   *  Global output ids follow mpi::exclusiveOffset (core/Mpi.hpp): rank p owns [offset, offset + nOwned).
   *  \throws std::invalid_argument on every rank if any rank passed inconsistent input.
   */
  void setTopology(long long nOwnedNodes, long long nOwnedCells, const std::vector<long long>& connectivity);

  /*! \brief Write dump \p index at simulation \p time and update the XDMF files. Collective.
   *  \param coords owned node coordinates, row-major nOwnedNodes * 3 (z = 0 in 2D)
   *  \param cellFields cell fields; same names, order and ncomp on every rank
   *  \param nodeFields node fields, likewise (none by default)
   *  \return path of the written .h5 file
   *  \throws std::invalid_argument (bad input, thrown on every rank) or std::runtime_error (HDF5/file error)
   */
  std::string writeStep(int index, double time, const std::vector<double>& coords,
                        const std::vector<CellField>& cellFields, const std::vector<NodeField>& nodeFields = {});

  /*! \brief A restarted run: the collection already holds dumps 0 .. dumps - 1 (those whose files are in dir), and
   *  the next writeStep adds to them. */
  void continueSeries(int dumps);

  /*! \brief Path of the temporal collection file "<dir>/<basename>.xmf". */
  std::string collectionPath() const;

private:
  //! A field of either centring, as the dump writes it.
  struct Dataset {
    std::string name;
    int ncomp;
    const double* data;
    bool onNodes;
  };
  static std::vector<Dataset> datasetsOf(const std::vector<CellField>& cellFields,
                                         const std::vector<NodeField>& nodeFields);
  std::string checkStepInput(int index, const std::vector<double>& coords, const std::vector<Dataset>& fields) const;
  void throwIfAnyRank(const std::string& localError) const;
  std::string stepName(int index) const;
  std::string topologyXml(const std::string& h5) const;
  std::string gridXml(int index, double time, const std::vector<Dataset>& fields) const;
  void writeXmlFiles(int index, double time, const std::vector<Dataset>& fields);

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string dir_, base_;
  CellType cellType_ = CellType::Triangle;
  int nodesPerCell_ = 0, rank_ = 0;
  bool haveTopology_ = false;
  long long nOwnedNodes_ = 0, nOwnedCells_ = 0;  // this rank
  long long nodeOffset_ = 0, cellOffset_ = 0;    // first global id owned by this rank
  long long nNodes_ = 0, nCells_ = 0;            // global totals
  std::vector<long long> connectivity_;
  std::vector<std::pair<int, double>> dumps_;    // (index, time) in the collection, rank 0 only
};

}  // namespace unilag::io
