// Standalone MPI test of unilag::io::XdmfWriter: writes a toy triangle mesh, a toy tet mesh and two polylines (with
// node fields) over 3 dumps with moving nodes (and a repartition), then reads the HDF5 back on rank 0 and checks
// shapes and values.
// Usage: mpirun -np N xdmf_writer_standalone [outdir]   (default outdir: ./xdmf_writer_out)
#include "core/Mpi.hpp"
#include "io/XdmfWriter.hpp"

#include <hdf5.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using unilag::io::CellField;
using unilag::io::CellType;
using unilag::io::NodeField;
using unilag::io::XdmfWriter;

namespace {

int failures = 0;
#define CHECK(cond, msg)                                                          \
  do {                                                                            \
    if (!(cond)) {                                                                \
      ++failures;                                                                 \
      std::fprintf(stderr, "FAIL %s:%d: %s (%s)\n", __FILE__, __LINE__, msg, #cond); \
    }                                                                             \
  } while (0)

struct Mesh {
  CellType type;
  bool in3d;                    // z moves and vectors have a z component
  bool nodeFields;              // dumps carry node fields too
  std::vector<double> xyz;      // global node coordinates at t=0, nNodes*3
  std::vector<long long> conn;  // global connectivity, nCells*nv()
  int nv() const { return unilag::io::nodesPerCell(type); }
  long long nNodes() const { return static_cast<long long>(xyz.size() / 3); }
  long long nCells() const { return static_cast<long long>(conn.size() / nv()); }
};

// 2D: nx x ny quads, each split into 2 triangles.
Mesh triMesh(int nx, int ny) {
  Mesh m{CellType::Triangle, false, false, {}, {}};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.xyz.insert(m.xyz.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const long long a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      m.conn.insert(m.conn.end(), {a, b, d, a, d, c});
    }
  return m;
}

// 3D: a column of nz unit cubes, each split into 6 tets around the main diagonal (Kuhn split).
Mesh tetMesh(int nz) {
  Mesh m{CellType::Tetrahedron, true, false, {}, {}};
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) m.xyz.insert(m.xyz.end(), {double(i), double(j), double(k)});
  const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (const auto& p : perm) {
      int ijk[3] = {0, 0, 0};
      auto id = [&] { return 4LL * (k + ijk[2]) + 2 * ijk[1] + ijk[0]; };
      m.conn.push_back(id());
      for (int axis : p) { ijk[axis] = 1; m.conn.push_back(id()); }
    }
  return m;
}

// Two polylines of n nodes each (a helix and a straight line), segments (i, i+1) along each.
Mesh polylineMesh(int n) {
  Mesh m{CellType::Polyline, true, true, {}, {}};
  for (int i = 0; i < n; ++i) m.xyz.insert(m.xyz.end(), {std::cos(0.5 * i), std::sin(0.5 * i), 0.1 * i});
  for (int i = 0; i < n; ++i) m.xyz.insert(m.xyz.end(), {2.0 + 0.25 * i, 0.0, 0.0});
  for (long long line = 0; line < 2; ++line)
    for (long long i = 0; i + 1 < n; ++i) m.conn.insert(m.conn.end(), {line * n + i, line * n + i + 1});
  return m;
}

// Partition n items in contiguous blocks. mode 0: even; 1: last rank empty (if >1 rank); 2: rank p gets weight p+1.
long long blockBegin(long long n, int rank, int size, int mode) {
  if (mode == 1 && size > 1) return rank >= size - 1 ? n : n * rank / (size - 1);
  if (mode == 2) return n * (static_cast<long long>(rank) * (rank + 1) / 2) / (static_cast<long long>(size) * (size + 1) / 2);
  return n * rank / size;
}

double movedCoord(const Mesh& m, long long node, int c, int step) {
  const double* x = &m.xyz[3 * node];
  if (c == 0) return x[0] + 0.1 * step * (1.0 + x[1]);
  if (c == 1) return x[1] + 0.05 * step * x[0];
  return m.in3d ? x[2] + 0.01 * step : 0.0;
}
double density(long long cell, int step) { return 1.0 + cell + 10.0 * step; }
double velocity(const Mesh& m, long long cell, int c, int step) {
  return c == 0 ? double(cell) : c == 1 ? double(step) : (m.in3d ? -double(cell) : 0.0);
}
double pressure(long long node, int step) { return 0.5 * node - 3.0 * step; }
double displacement(long long node, int c, int step) { return c == 2 ? -double(node) : double(step * (c + 1)) + node; }

// Read a whole 2D dataset with the expected shape and memory type; records failures.
template <class T>
std::vector<T> readAll(hid_t file, const char* name, hid_t memType, hsize_t rows, hsize_t cols) {
  std::vector<T> out;
  hid_t dset = H5Dopen2(file, name, H5P_DEFAULT);
  CHECK(dset >= 0, name);
  if (dset < 0) return out;
  hid_t space = H5Dget_space(dset);
  hsize_t dims[2] = {0, 0};
  const int rank = H5Sget_simple_extent_ndims(space);
  CHECK(rank == 2, name);
  if (rank == 2) H5Sget_simple_extent_dims(space, dims, nullptr);
  CHECK(dims[0] == rows && dims[1] == cols, name);
  hid_t ftype = H5Dget_type(dset);
  CHECK(H5Tget_size(ftype) == 8, name);
  CHECK(H5Tget_class(ftype) == (memType == H5T_NATIVE_DOUBLE ? H5T_FLOAT : H5T_INTEGER), name);
  if (dims[0] == rows && dims[1] == cols) {
    out.resize(rows * cols);
    CHECK(H5Dread(dset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0, name);
  }
  H5Tclose(ftype);
  H5Sclose(space);
  H5Dclose(dset);
  return out;
}

void verifyDump(const std::string& h5Path, const Mesh& m, int step) {
  const hsize_t nn = m.nNodes(), nc = m.nCells();
  hid_t file = H5Fopen(h5Path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(file >= 0, h5Path.c_str());
  if (file < 0) return;
  auto xyz = readAll<double>(file, "/coordinates", H5T_NATIVE_DOUBLE, nn, 3);
  for (size_t i = 0; i < xyz.size(); ++i)
    CHECK(xyz[i] == movedCoord(m, i / 3, i % 3, step), "coordinates value");
  auto conn = readAll<long long>(file, "/connectivity", H5T_NATIVE_LLONG, nc, m.nv());
  CHECK(conn.empty() || conn == m.conn, "connectivity values");
  auto rho = readAll<double>(file, "/density", H5T_NATIVE_DOUBLE, nc, 1);
  for (size_t i = 0; i < rho.size(); ++i) CHECK(rho[i] == density(i, step), "density value");
  auto vel = readAll<double>(file, "/velocity", H5T_NATIVE_DOUBLE, nc, 3);
  for (size_t i = 0; i < vel.size(); ++i) CHECK(vel[i] == velocity(m, i / 3, i % 3, step), "velocity value");
  if (m.nodeFields) {
    auto p = readAll<double>(file, "/pressure", H5T_NATIVE_DOUBLE, nn, 1);
    CHECK(p.size() == nn, "pressure read");
    for (size_t i = 0; i < p.size(); ++i) CHECK(p[i] == pressure(i, step), "pressure value");
    auto u = readAll<double>(file, "/displacement", H5T_NATIVE_DOUBLE, nn, 3);
    CHECK(u.size() == 3 * nn, "displacement read");
    for (size_t i = 0; i < u.size(); ++i) CHECK(u[i] == displacement(i / 3, i % 3, step), "displacement value");
  }
  CHECK(H5Fclose(file) >= 0, "H5Fclose");
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
int count(const std::string& hay, const std::string& needle) {
  int n = 0;
  for (size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + 1)) ++n;
  return n;
}

// Rows [n0, n1) of the nodes and [c0, c1) of the cells: this rank's part of a dump.
struct Part {
  long long n0, n1, c0, c1;
};

// The fields of dump `step` on this rank's part, written with w; returns the .h5 path.
std::string writeDump(XdmfWriter& w, const Mesh& m, const Part& part, int step) {
  std::vector<double> coords, rho, vel, p, u;
  for (long long n = part.n0; n < part.n1; ++n) {
    p.push_back(pressure(n, step));
    for (int c = 0; c < 3; ++c) {
      coords.push_back(movedCoord(m, n, c, step));
      u.push_back(displacement(n, c, step));
    }
  }
  for (long long c = part.c0; c < part.c1; ++c) {
    rho.push_back(density(c, step));
    for (int k = 0; k < 3; ++k) vel.push_back(velocity(m, c, k, step));
  }
  const std::vector<CellField> cellFields{{"density", 1, rho.data()}, {"velocity", 3, vel.data()}};
  if (!m.nodeFields) return w.writeStep(10 * step, 0.25 * step, coords, cellFields);  // the GPR solver's call
  return w.writeStep(10 * step, 0.25 * step, coords, cellFields, {{"pressure", 1, p.data()}, {"displacement", 3, u.data()}});
}

// The step's .xmf: topology line, time and the attributes of either centring.
void checkStepXmf(const std::string& dir, const std::string& base, const Mesh& m, int step) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%06d.xmf", base.c_str(), 10 * step);
  const std::string xmf = slurp(dir + "/" + name);
  const char* topology = m.type == CellType::Triangle      ? "Triangle\""
                         : m.type == CellType::Tetrahedron ? "Tetrahedron\""
                                                           : "Polyline\" NodesPerElement=\"2\"";
  CHECK(xmf.find(std::string("TopologyType=\"") + topology + " NumberOfElements=\"" + std::to_string(m.nCells()) + "\"") !=
            std::string::npos, "step xmf topology");
  CHECK(xmf.find("Dimensions=\"" + std::to_string(m.nCells()) + " " + std::to_string(m.nv()) + "\"") != std::string::npos,
        "step xmf connectivity shape");
  const size_t t = xmf.find("<Time Value=\"");
  CHECK(t != std::string::npos && std::stod(xmf.substr(t + 13)) == 0.25 * step, "step xmf time");
  CHECK(count(xmf, "Center=\"Cell\"") == 2, "step xmf cell attributes");
  CHECK(count(xmf, "Center=\"Node\"") == (m.nodeFields ? 2 : 0), "step xmf node attributes");
  if (m.nodeFields)
    CHECK(xmf.find("Dimensions=\"" + std::to_string(m.nNodes()) + " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" +
                   std::string(name, std::strlen(name) - 4) + ".h5:/displacement<") != std::string::npos,
          "step xmf node vector shape");
}

// Bad input on rank 0 only must throw on every rank instead of deadlocking.
void checkBadInput(XdmfWriter& w, const Mesh& m, const Part& part, int rank) {
  bool threw = false;
  try {
    w.setTopology(part.n1 - part.n0, part.c1 - part.c0, std::vector<long long>(rank == 0 ? 1 : m.nv() * (part.c1 - part.c0), 0));
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  CHECK(threw, "setTopology rejects bad connectivity on all ranks");
  if (!m.nodeFields) return;
  // A node field may not reuse a cell field's name (both are datasets of the same file).
  std::vector<double> coords(3 * (part.n1 - part.n0)), rho(part.c1 - part.c0), p(part.n1 - part.n0);
  threw = false;
  try {
    w.setTopology(part.n1 - part.n0, part.c1 - part.c0,
                  std::vector<long long>(m.conn.begin() + m.nv() * part.c0, m.conn.begin() + m.nv() * part.c1));
    w.writeStep(99, 9.0, coords, {{"density", 1, rho.data()}}, {{rank == 0 ? "density" : "pressure", 1, p.data()}});
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  CHECK(threw, "writeStep rejects a node field named like a cell field on all ranks");
}

void runMesh(const Mesh& m, const std::string& dir, const std::string& base, const int modes[3]) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  XdmfWriter w(MPI_COMM_WORLD, dir, base, m.type);
  const int nv = m.nv();
  Part part{0, 0, 0, 0};
  for (int step = 0; step < 3; ++step) {
    if (step == 0 || modes[step] != modes[step - 1]) {  // (re)partition
      part = {blockBegin(m.nNodes(), rank, size, modes[step]), blockBegin(m.nNodes(), rank + 1, size, modes[step]),
              blockBegin(m.nCells(), rank, size, modes[step]), blockBegin(m.nCells(), rank + 1, size, modes[step])};
      CHECK(unilag::mpi::exclusiveOffset(MPI_COMM_WORLD, part.n1 - part.n0) == part.n0, "exclusiveOffset(nodes)");
      CHECK(unilag::mpi::exclusiveOffset(MPI_COMM_WORLD, part.c1 - part.c0) == part.c0, "exclusiveOffset(cells)");
      w.setTopology(part.n1 - part.n0, part.c1 - part.c0,
                    std::vector<long long>(m.conn.begin() + nv * part.c0, m.conn.begin() + nv * part.c1));
    }
    const std::string h5 = writeDump(w, m, part, step);
    if (rank == 0) {
      verifyDump(h5, m, step);
      checkStepXmf(dir, base, m, step);
    }
  }
  if (rank == 0) {
    const std::string coll = slurp(w.collectionPath());
    CHECK(count(coll, "<xi:include") == 3, "collection includes all dumps");
    CHECK(coll.find("xmlns:xi=\"http://www.w3.org/2001/XInclude\"") != std::string::npos, "collection xmlns:xi");
    CHECK(!std::filesystem::exists(w.collectionPath() + ".tmp"), "no temp file left");
  }
  checkBadInput(w, m, part, rank);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::string dir = argc > 1 ? argv[1] : "xdmf_writer_out";
  if (rank == 0) std::filesystem::create_directories(dir);
  MPI_Barrier(MPI_COMM_WORLD);
  try {
    const int triModes[3] = {0, 0, 2}, tetModes[3] = {1, 1, 2}, lineModes[3] = {2, 1, 0};
    runMesh(triMesh(4, 3), dir, "tri", triModes);
    runMesh(tetMesh(2), dir, "tet", tetModes);
    runMesh(polylineMesh(7), dir, "polyline", lineModes);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rank %d: exception: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  int total = 0;
  MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) std::printf(total == 0 ? "xdmf_writer: PASS\n" : "xdmf_writer: FAIL (%d failed checks)\n", total);
  MPI_Finalize();
  return total == 0 ? 0 : 1;
}
