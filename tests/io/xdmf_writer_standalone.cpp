// Standalone MPI test of unilag::io::XdmfWriter: writes a toy triangle mesh and a toy tet mesh over 3 dumps
// with moving nodes (and a repartition), then reads the HDF5 back on rank 0 and checks shapes and values.
// Usage: mpirun -np N xdmf_writer_standalone [outdir]   (default outdir: ./xdmf_writer_out)
#include "core/Mpi.hpp"
#include "io/XdmfWriter.hpp"

#include <hdf5.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using unilag::io::CellField;
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
  int dim;
  std::vector<double> xyz;      // global node coordinates at t=0, nNodes*3
  std::vector<long long> conn;  // global connectivity, nCells*(dim+1)
  long long nNodes() const { return static_cast<long long>(xyz.size() / 3); }
  long long nCells() const { return static_cast<long long>(conn.size() / (dim + 1)); }
};

// 2D: nx x ny quads, each split into 2 triangles.
Mesh triMesh(int nx, int ny) {
  Mesh m{2, {}, {}};
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
  Mesh m{3, {}, {}};
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
  return m.dim == 3 ? x[2] + 0.01 * step : 0.0;
}
double density(long long cell, int step) { return 1.0 + cell + 10.0 * step; }
double velocity(const Mesh& m, long long cell, int c, int step) {
  return c == 0 ? double(cell) : c == 1 ? double(step) : (m.dim == 3 ? -double(cell) : 0.0);
}

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
  auto conn = readAll<long long>(file, "/connectivity", H5T_NATIVE_LLONG, nc, m.dim + 1);
  CHECK(conn.empty() || conn == m.conn, "connectivity values");
  auto rho = readAll<double>(file, "/density", H5T_NATIVE_DOUBLE, nc, 1);
  for (size_t i = 0; i < rho.size(); ++i) CHECK(rho[i] == density(i, step), "density value");
  auto vel = readAll<double>(file, "/velocity", H5T_NATIVE_DOUBLE, nc, 3);
  for (size_t i = 0; i < vel.size(); ++i) CHECK(vel[i] == velocity(m, i / 3, i % 3, step), "velocity value");
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

void runMesh(const Mesh& m, const std::string& dir, const std::string& base, const int modes[3]) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  XdmfWriter w(MPI_COMM_WORLD, dir, base, m.dim);
  const int nv = m.dim + 1;
  long long n0 = 0, n1 = 0, c0 = 0, c1 = 0;
  for (int step = 0; step < 3; ++step) {
    if (step == 0 || modes[step] != modes[step - 1]) {  // (re)partition
      n0 = blockBegin(m.nNodes(), rank, size, modes[step]);
      n1 = blockBegin(m.nNodes(), rank + 1, size, modes[step]);
      c0 = blockBegin(m.nCells(), rank, size, modes[step]);
      c1 = blockBegin(m.nCells(), rank + 1, size, modes[step]);
      CHECK(unilag::mpi::exclusiveOffset(MPI_COMM_WORLD, n1 - n0) == n0, "exclusiveOffset(nodes)");
      CHECK(unilag::mpi::exclusiveOffset(MPI_COMM_WORLD, c1 - c0) == c0, "exclusiveOffset(cells)");
      w.setTopology(n1 - n0, c1 - c0, std::vector<long long>(m.conn.begin() + nv * c0, m.conn.begin() + nv * c1));
    }
    std::vector<double> coords, rho, vel;
    for (long long n = n0; n < n1; ++n)
      for (int c = 0; c < 3; ++c) coords.push_back(movedCoord(m, n, c, step));
    for (long long c = c0; c < c1; ++c) {
      rho.push_back(density(c, step));
      for (int k = 0; k < 3; ++k) vel.push_back(velocity(m, c, k, step));
    }
    const std::string h5 = w.writeStep(10 * step, 0.25 * step, coords, {{"density", 1, rho.data()}, {"velocity", 3, vel.data()}});
    if (rank == 0) {
      verifyDump(h5, m, step);
      char name[64];
      std::snprintf(name, sizeof name, "%s_%06d.xmf", base.c_str(), 10 * step);
      const std::string xmf = slurp(dir + "/" + name);
      CHECK(xmf.find(std::string("TopologyType=\"") + (m.dim == 2 ? "Triangle" : "Tetrahedron") + "\" NumberOfElements=\"" +
                     std::to_string(m.nCells()) + "\"") != std::string::npos, "step xmf topology");
      const size_t t = xmf.find("<Time Value=\"");
      CHECK(t != std::string::npos && std::stod(xmf.substr(t + 13)) == 0.25 * step, "step xmf time");
      CHECK(count(xmf, "Center=\"Cell\"") == 2, "step xmf attributes");
    }
  }
  if (rank == 0) {
    const std::string coll = slurp(w.collectionPath());
    CHECK(count(coll, "<xi:include") == 3, "collection includes all dumps");
    CHECK(coll.find("xmlns:xi=\"http://www.w3.org/2001/XInclude\"") != std::string::npos, "collection xmlns:xi");
    CHECK(!std::filesystem::exists(w.collectionPath() + ".tmp"), "no temp file left");
  }

  // Bad input on rank 0 only must throw on every rank instead of deadlocking.
  bool threw = false;
  try {
    w.setTopology(n1 - n0, c1 - c0, std::vector<long long>(rank == 0 ? 1 : nv * (c1 - c0), 0));
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  CHECK(threw, "setTopology rejects bad connectivity on all ranks");
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
    const int triModes[3] = {0, 0, 2}, tetModes[3] = {1, 1, 2};
    runMesh(triMesh(4, 3), dir, "tri", triModes);
    runMesh(tetMesh(2), dir, "tet", tetModes);
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
