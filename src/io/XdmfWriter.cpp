#include "io/XdmfWriter.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/Errors.hpp"
#include "core/Mpi.hpp"

namespace unilag::io {
namespace {

// Owns one HDF5 id. close() is the checked path used on success; the destructor only runs
// for ids not closed explicitly (error unwinding), where a second exception is not an option
// and the error being unwound is the one the run reports (a full disk fails this close too).
class H5Handle {
public:
  H5Handle(hid_t id, herr_t (*closer)(hid_t), const std::string& what) : id_(id), closer_(closer) {
    if (id_ < 0) throw OutputError("XdmfWriter: " + what + " failed");
  }
  ~H5Handle() {
    if (id_ >= 0) closer_(id_);
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  operator hid_t() const { return id_; }
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    if (closer_(id) < 0) throw OutputError("XdmfWriter: closing " + what + " failed");
  }

private:
  hid_t id_;
  herr_t (*closer_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw OutputError("XdmfWriter: " + what + " failed");
}

// Names end up in HDF5 paths and XML text: restrict them so neither needs escaping (no ".", "..").
bool isSafeName(const std::string& s) {
  return !s.empty() && s[0] != '.' && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
  });
}

// Collectively write rows [rowOffset, rowOffset+nRows) of the dataset `name` [nGlobalRows x nCols].
void writeRows(hid_t file, const std::string& fileName, const std::string& name, hid_t memType, hid_t fileType,
               const void* data, hsize_t nGlobalRows, hsize_t rowOffset, hsize_t nRows, hsize_t nCols) {
  const std::string where = fileName + ":/" + name;
  const hsize_t gdims[2] = {nGlobalRows, nCols}, ldims[2] = {nRows, nCols}, start[2] = {rowOffset, 0};
  H5Handle fspace(H5Screate_simple(2, gdims, nullptr), H5Sclose, "H5Screate_simple (file) for " + where);
  H5Handle mspace(H5Screate_simple(2, ldims, nullptr), H5Sclose, "H5Screate_simple (memory) for " + where);
  H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "H5Pcreate(dcpl) for " + where);
  // Every element is written below, so skip the fill pass (a full extra write in parallel).
  check(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER), "H5Pset_fill_time for " + where);
  H5Handle dset(H5Dcreate2(file, ("/" + name).c_str(), fileType, fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                H5Dclose, "H5Dcreate2 for " + where);
  if (nRows == 0) {  // ranks without rows still take part in the collective write
    check(H5Sselect_none(fspace), "H5Sselect_none (file) for " + where);
    check(H5Sselect_none(mspace), "H5Sselect_none (memory) for " + where);
  } else {
    check(H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, ldims, nullptr), "H5Sselect_hyperslab for " + where);
  }
  H5Handle dxpl(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "H5Pcreate(dxpl) for " + where);
  check(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio for " + where);
  static const double dummy = 0.0;  // H5Dwrite rejects a null buffer on some versions even if nothing is selected
  check(H5Dwrite(dset, memType, mspace, fspace, dxpl, data ? data : &dummy), "H5Dwrite for " + where);
  dxpl.close("dxpl of " + where);
  dset.close(where);
  dcpl.close("dcpl of " + where);
  mspace.close("memory space of " + where);
  fspace.close("file space of " + where);
}

// Write via a temporary file and rename, so readers never see a half-written XML file.
void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  const auto discard = [&tmp] {  // no stray .tmp beside the outputs (only our own file: never a folder in the way)
    std::error_code ec;
    if (std::filesystem::is_regular_file(tmp, ec)) std::filesystem::remove(tmp, ec);
  };
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      out.close();
      discard();
      throw OutputError("XdmfWriter: cannot write " + tmp);
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    discard();
    throw OutputError("XdmfWriter: cannot rename " + tmp + " to " + path);
  }
}

std::string dataItem(long long rows, int cols, const char* numberType, const std::string& h5, const std::string& ds) {
  std::ostringstream s;
  s << "    <DataItem Dimensions=\"" << rows << ' ' << cols << "\" NumberType=\"" << numberType
    << "\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/" << ds << "</DataItem>\n";
  return s.str();
}

const char* topologyName(CellType type) {
  switch (type) {
    case CellType::Triangle: return "Triangle";
    case CellType::Tetrahedron: return "Tetrahedron";
    case CellType::Polyline: return "Polyline";
  }
  throw std::invalid_argument("XdmfWriter: unknown cell type");
}

const char* attributeType(int ncomp) { return ncomp == 1 ? "Scalar" : ncomp == 3 ? "Vector" : "Tensor6"; }

}  // namespace

int nodesPerCell(CellType type) {
  switch (type) {
    case CellType::Triangle: return 3;
    case CellType::Tetrahedron: return 4;
    case CellType::Polyline: return 2;
  }
  throw std::invalid_argument("XdmfWriter: unknown cell type");
}

CellType simplexCellType(int dim) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("XdmfWriter: dim must be 2 or 3");
  return dim == 2 ? CellType::Triangle : CellType::Tetrahedron;
}

XdmfWriter::XdmfWriter(MPI_Comm comm, std::string dir, std::string basename, int dim)
    : XdmfWriter(comm, std::move(dir), std::move(basename), simplexCellType(dim)) {}

XdmfWriter::XdmfWriter(MPI_Comm comm, std::string dir, std::string basename, CellType cellType)
    : dir_(std::move(dir)), base_(std::move(basename)), cellType_(cellType), nodesPerCell_(nodesPerCell(cellType)) {
  if (!isSafeName(base_)) throw std::invalid_argument("XdmfWriter: invalid basename '" + base_ + "'");
  if (MPI_Comm_dup(comm, &comm_) != MPI_SUCCESS) throw std::runtime_error("XdmfWriter: MPI_Comm_dup failed");
  MPI_Comm_rank(comm_, &rank_);
  // Every HDF5 call's status is checked and becomes one OutputError naming the file; HDF5's own error stack on
  // stderr would bury that message.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

XdmfWriter::~XdmfWriter() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized && comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

// Input errors must be raised on all ranks together, or the others hang in the next collective.
void XdmfWriter::throwIfAnyRank(const std::string& localError) const {
  int bad = localError.empty() ? 0 : 1, anyBad = 0;
  MPI_Allreduce(&bad, &anyBad, 1, MPI_INT, MPI_LOR, comm_);
  if (anyBad) throw std::invalid_argument(bad ? localError : "XdmfWriter: invalid input on another rank");
}

void XdmfWriter::setTopology(long long nOwnedNodes, long long nOwnedCells, const std::vector<long long>& connectivity) {
  std::string err;
  if (nOwnedNodes < 0 || nOwnedCells < 0) err = "XdmfWriter::setTopology: negative count";
  else if (connectivity.size() != static_cast<size_t>(nOwnedCells) * nodesPerCell_)
    err = "XdmfWriter::setTopology: connectivity size != nOwnedCells * nodes per cell";
  throwIfAnyRank(err);
  long long local[2] = {nOwnedNodes, nOwnedCells}, global[2] = {0, 0};
  MPI_Allreduce(local, global, 2, MPI_LONG_LONG, MPI_SUM, comm_);
  const auto badId = std::find_if(connectivity.begin(), connectivity.end(), [&](long long id) { return id < 0 || id >= global[0]; });
  throwIfAnyRank(badId == connectivity.end() ? "" : "XdmfWriter::setTopology: node id out of range: " + std::to_string(*badId));
  nOwnedNodes_ = nOwnedNodes;
  nOwnedCells_ = nOwnedCells;
  nodeOffset_ = mpi::exclusiveOffset(comm_, nOwnedNodes);
  cellOffset_ = mpi::exclusiveOffset(comm_, nOwnedCells);
  nNodes_ = global[0];
  nCells_ = global[1];
  connectivity_ = connectivity;
  haveTopology_ = true;
}

std::string XdmfWriter::stepName(int index) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06d", index);
  return base_ + buf;
}

std::string XdmfWriter::collectionPath() const { return dir_ + "/" + base_ + ".xmf"; }

void XdmfWriter::continueSeries(int dumps) {
  dumps_.clear();
  // The collection lists indices (the times are in the step files); a restart into another folder has none of them.
  if (rank_ == 0)
    for (int i = 0; i < dumps; ++i)
      if (std::ifstream(dir_ + "/" + stepName(i) + ".xmf").good()) dumps_.emplace_back(i, 0.0);
}

std::vector<XdmfWriter::Dataset> XdmfWriter::datasetsOf(const std::vector<CellField>& cellFields,
                                                         const std::vector<NodeField>& nodeFields) {
  std::vector<Dataset> all;
  for (const CellField& f : cellFields) all.push_back({f.name, f.ncomp, f.data, false});
  for (const NodeField& f : nodeFields) all.push_back({f.name, f.ncomp, f.data, true});
  return all;
}

// This rank's first input error, or "".
std::string XdmfWriter::checkStepInput(int index, const std::vector<double>& coords, const std::vector<Dataset>& fields) const {
  std::string err;
  std::set<std::string> names = {"coordinates", "connectivity"};
  if (index < 0) err = "XdmfWriter::writeStep: negative index";
  else if (coords.size() != static_cast<size_t>(nOwnedNodes_) * 3) err = "XdmfWriter::writeStep: coords size != nOwnedNodes * 3";
  for (const Dataset& f : fields) {
    if (!err.empty()) break;
    if (!isSafeName(f.name) || !names.insert(f.name).second) err = "XdmfWriter::writeStep: invalid or duplicate field name '" + f.name + "'";
    else if (f.ncomp != 1 && f.ncomp != 3 && f.ncomp != 6)
      err = "XdmfWriter::writeStep: field '" + f.name + "' must have ncomp 1, 3 or 6";
    else if (!f.data && (f.onNodes ? nOwnedNodes_ : nOwnedCells_) > 0) err = "XdmfWriter::writeStep: field '" + f.name + "' has no data";
  }
  return err;
}

std::string XdmfWriter::writeStep(int index, double time, const std::vector<double>& coords,
                                  const std::vector<CellField>& cellFields, const std::vector<NodeField>& nodeFields) {
  if (!haveTopology_) throw std::logic_error("XdmfWriter::writeStep: setTopology() was not called");
  const std::vector<Dataset> fields = datasetsOf(cellFields, nodeFields);
  throwIfAnyRank(checkStepInput(index, coords, fields));

  const std::string h5Name = stepName(index) + ".h5", h5Path = dir_ + "/" + h5Name;
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "H5Pcreate(fapl) for " + h5Path);
  check(H5Pset_fapl_mpio(fapl, comm_, MPI_INFO_NULL), "H5Pset_fapl_mpio for " + h5Path);
  H5Handle file(H5Fcreate(h5Path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose, "H5Fcreate of " + h5Path);
  fapl.close("fapl of " + h5Path);
  writeRows(file, h5Path, "coordinates", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, coords.data(), nNodes_, nodeOffset_, nOwnedNodes_, 3);
  writeRows(file, h5Path, "connectivity", H5T_NATIVE_LLONG, H5T_STD_I64LE, connectivity_.data(), nCells_, cellOffset_,
            nOwnedCells_, nodesPerCell_);
  for (const Dataset& f : fields) {
    if (f.onNodes)
      writeRows(file, h5Path, f.name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, f.data, nNodes_, nodeOffset_, nOwnedNodes_, f.ncomp);
    else
      writeRows(file, h5Path, f.name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, f.data, nCells_, cellOffset_, nOwnedCells_, f.ncomp);
  }
  file.close(h5Path);  // collective: the .h5 is complete on disk before rank 0 references it

  std::string xmlError;
  if (rank_ == 0) {
    try {
      writeXmlFiles(index, time, fields);
    } catch (const std::exception& e) {
      xmlError = e.what();
    }
  }
  // Share rank 0's outcome so every rank returns or throws alike.
  int failed = xmlError.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm_);
  if (failed) throw OutputError(rank_ == 0 ? xmlError : "XdmfWriter: writing XDMF files failed on rank 0");
  return h5Path;
}

std::string XdmfWriter::topologyXml(const std::string& h5) const {
  std::ostringstream s;
  s << "   <Topology TopologyType=\"" << topologyName(cellType_) << "\"";
  if (cellType_ == CellType::Polyline) s << " NodesPerElement=\"" << nodesPerCell_ << "\"";  // XDMF needs it for lines
  s << " NumberOfElements=\"" << nCells_ << "\">\n"
    << dataItem(nCells_, nodesPerCell_, "Int", h5, "connectivity") << "   </Topology>\n";
  return s.str();
}

std::string XdmfWriter::gridXml(int index, double time, const std::vector<Dataset>& fields) const {
  const std::string h5 = stepName(index) + ".h5";  // relative: the .xmf files sit next to the .h5
  std::ostringstream s;
  s << std::setprecision(17);
  s << "  <Grid Name=\"" << base_ << "\" GridType=\"Uniform\">\n"
    << "   <Time Value=\"" << time << "\"/>\n"
    << topologyXml(h5)
    << "   <Geometry GeometryType=\"XYZ\">\n"
    << dataItem(nNodes_, 3, "Float", h5, "coordinates") << "   </Geometry>\n";
  for (const Dataset& f : fields)
    s << "   <Attribute Name=\"" << f.name << "\" AttributeType=\"" << attributeType(f.ncomp) << "\" Center=\""
      << (f.onNodes ? "Node" : "Cell") << "\">\n"
      << dataItem(f.onNodes ? nNodes_ : nCells_, f.ncomp, "Float", h5, f.name) << "   </Attribute>\n";
  s << "  </Grid>\n";
  return s.str();
}

void XdmfWriter::writeXmlFiles(int index, double time, const std::vector<Dataset>& fields) {
  const std::string header = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\"";
  writeFileAtomically(dir_ + "/" + stepName(index) + ".xmf",
                      header + ">\n <Domain>\n" + gridXml(index, time, fields) + " </Domain>\n</Xdmf>\n");

  // Rewriting an index (e.g. a run rewound to a restart) drops it and every later dump, keeping time monotonic.
  dumps_.erase(std::remove_if(dumps_.begin(), dumps_.end(), [&](const auto& d) { return d.first >= index; }), dumps_.end());
  dumps_.emplace_back(index, time);
  std::ostringstream s;
  s << header << " xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n <Domain>\n"
    << "  <Grid Name=\"" << base_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& d : dumps_)
    s << "   <xi:include href=\"" << stepName(d.first) << ".xmf\" xpointer=\"xpointer(//Xdmf/Domain/Grid)\"/>\n";
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  writeFileAtomically(collectionPath(), s.str());
}

}  // namespace unilag::io
