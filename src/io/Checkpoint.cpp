#include "io/Checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <type_traits>

#include "core/Errors.hpp"
#include "core/Mpi.hpp"

namespace unilag::io
{
namespace
{

// 2: each text, list and table carries its FNV-1a checksum (group "checksums"), so that a corrupt value is refused
const char* const formatTag = "unilag checkpoint 4"; // 4: the scene sections, the initial shape quality

//! FNV-1a (64 bits) continued over n bytes: a checksum of the values as written, whatever the number of ranks.
std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t n)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k)
        hash = (hash ^ bytes[k]) * 0x100000001b3ull;
    return hash;
}
constexpr std::uint64_t fnvStart = 0xcbf29ce484222325ull;

std::string hex(std::uint64_t v)
{
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", (unsigned long long)v);
    return buffer;
}

void bcastString(MPI_Comm comm, std::string& s)
{
    long long n = (long long)s.size();
    MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, comm);
    s.resize(std::size_t(n));
    MPI_Bcast(s.data(), int(n), MPI_CHAR, 0, comm);
}

void bcastVector(MPI_Comm comm, std::vector<double>& v)
{
    long long n = (long long)v.size();
    MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, comm);
    v.resize(std::size_t(n));
    // in chunks: an MPI count is an int
    for (long long first = 0; first < n; first += 1 << 28)
        MPI_Bcast(v.data() + first, int(std::min<long long>(n - first, 1 << 28)), MPI_DOUBLE, 0, comm);
}

template <class T> void bcastMap(MPI_Comm comm, std::map<std::string, T>& m)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    long long n = (long long)m.size();
    MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, comm);
    auto it = m.begin();
    std::map<std::string, T> out;
    for (long long k = 0; k < n; ++k)
    {
        std::string name = rank == 0 ? it->first : std::string();
        T value = rank == 0 ? it->second : T();
        bcastString(comm, name);
        if constexpr (std::is_same_v<T, int>)
            MPI_Bcast(&value, 1, MPI_INT, 0, comm);
        else if constexpr (std::is_same_v<T, std::string>)
            bcastString(comm, value);
        else
            bcastVector(comm, value);
        out[name] = std::move(value);
        if (rank == 0)
            ++it;
    }
    m = std::move(out);
}

} // namespace

void CheckpointWriter::table(const std::string& name, long long nGlobal, const CheckpointRows& rows)
{
    int size;
    MPI_Comm_size(comm_, &size);
    std::string error;
    std::vector<double> block = rowsToBlocks(comm_, RowBlocks{nGlobal, size}, rows, error);
    error = mpi::firstMessage(comm_, error);
    if (!error.empty())
        throw OutputError("checkpoint " + path_ + ": table '" + name + "': " + error);
    blocks_[name] = std::move(block);
    shapes_[name] = {nGlobal, rows.ncomp};
}

namespace
{

//! One HDF5 id, closed on scope exit; a negative id is the error `what` (thrown by the caller's fail).
struct H5Id
{
    hid_t id;
    herr_t (*close)(hid_t);
    ~H5Id()
    {
        if (id >= 0)
            close(id);
    }
};

void writeDataset(hid_t group, const std::string& name, hid_t type, int rank, const hsize_t* dims, const void* data)
{
    H5Id space{H5Screate_simple(rank, dims, nullptr), H5Sclose};
    H5Id set{H5Dcreate2(group, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose};
    const bool empty = dims[0] == 0 || (rank == 2 && dims[1] == 0);
    if (space.id < 0 || set.id < 0 || (!empty && H5Dwrite(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0))
        throw OutputError("cannot write dataset '" + name + "'");
}

/*! Rows [first, first + n) of a table's dataset, read or written as a hyperslab of its file space. */
bool rowsIo(hid_t set, hsize_t first, hsize_t n, hsize_t ncomp, double* data, bool write)
{
    if (n == 0 || ncomp == 0)
        return true;
    H5Id file{H5Dget_space(set), H5Sclose};
    const hsize_t start[2] = {first, 0}, count[2] = {n, ncomp};
    H5Id memory{H5Screate_simple(2, count, nullptr), H5Sclose};
    if (file.id < 0 || memory.id < 0 ||
        H5Sselect_hyperslab(file.id, H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
        return false;
    return (write ? H5Dwrite(set, H5T_NATIVE_DOUBLE, memory.id, file.id, H5P_DEFAULT, data)
                  : H5Dread(set, H5T_NATIVE_DOUBLE, memory.id, file.id, H5P_DEFAULT, data)) >= 0;
}

//! Each value of a map as a 1-D dataset of group (texts as chars, lists as doubles); OutputError if it cannot.
template <class Map> void writeDatasets(hid_t group, const Map& values, hid_t type)
{
    for (const auto& [name, v] : values)
    {
        const hsize_t n = v.size();
        writeDataset(group, name, type, 1, &n, v.data());
    }
}

//! Rank 0: creates the file with its texts and lists, and the (empty) group of the tables; "" or the reason.
std::string createFile(const std::string& path, const std::map<std::string, std::string>& texts,
                       const std::map<std::string, std::vector<double>>& vectors, H5Id& file, H5Id& tables)
{
    file.id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file.id < 0)
        return "cannot create " + path;
    H5Id gt{H5Gcreate2(file.id, "texts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    H5Id gv{H5Gcreate2(file.id, "vectors", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    tables.id = H5Gcreate2(file.id, "tables", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (gt.id < 0 || gv.id < 0 || tables.id < 0)
        return "cannot create the groups of " + path;
    try
    {
        writeDatasets(gt.id, texts, H5T_NATIVE_CHAR);
        writeDatasets(gv.id, vectors, H5T_NATIVE_DOUBLE);
    }
    catch (const OutputError& e)
    {
        return path + ": " + e.what();
    }
    return {};
}

/*! Rank 0: the table `name` (blocks, nc columns) into group, from this rank's block and each other rank's in turn
 *  (received even after a failure, so that no rank waits forever); "" or the reason. */
std::string writeTable(MPI_Comm comm, hid_t group, const std::string& name, const RowBlocks& blocks, int nc,
                       std::vector<double> block, bool ok, std::uint64_t& checksum)
{
    checksum = fnvStart;
    const hsize_t dims[2] = {hsize_t(blocks.n), hsize_t(nc)};
    H5Id space{ok ? H5Screate_simple(2, dims, nullptr) : -1, H5Sclose};
    H5Id set{ok && space.id >= 0
                 ? H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
                 : -1,
             H5Dclose};
    bool written = set.id >= 0;
    for (int r = 0; r < blocks.size; ++r)
    {
        block.resize(std::size_t(blocks.count(r)) * nc);
        if (r > 0)
            recvDoubles(comm, block.data(), block.size(), r);
        checksum = fnv1a(checksum, block.data(), block.size() * sizeof(double));
        written = written &&
                  rowsIo(set.id, hsize_t(blocks.first(r)), hsize_t(blocks.count(r)), hsize_t(nc), block.data(), true);
    }
    return !ok || written ? std::string() : "cannot write table '" + name + "'";
}

//! Names of the members of a group.
std::vector<std::string> members(hid_t group)
{
    std::vector<std::string> names;
    H5Literate(
        group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
        [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t
        {
            static_cast<std::vector<std::string>*>(data)->push_back(name);
            return 0;
        },
        &names);
    return names;
}

//! Reads a dataset as doubles (or chars into text); dims gets its shape.
bool readDataset(hid_t group, const std::string& name, hid_t type, std::vector<hsize_t>& dims,
                 void* (*resize)(void*, std::size_t), void* out)
{
    H5Id set{H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose};
    if (set.id < 0)
        return false;
    H5Id space{H5Dget_space(set.id), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space.id);
    if (rank < 1 || rank > 2)
        return false;
    dims.assign(std::size_t(rank), 0);
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
    std::size_t n = 1;
    for (hsize_t d : dims)
        n *= std::size_t(d);
    void* buffer = resize(out, n);
    return n == 0 || H5Dread(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer) >= 0;
}

void* resizeDoubles(void* v, std::size_t n)
{
    auto& d = *static_cast<std::vector<double>*>(v);
    d.resize(n);
    return d.data();
}

void* resizeText(void* v, std::size_t n)
{
    auto& s = *static_cast<std::string*>(v);
    s.resize(n);
    return s.data();
}

//! The checksums of the texts and lists, by "text.NAME" and "list.NAME".
std::map<std::string, std::string> checksums(const std::map<std::string, std::string>& texts,
                                             const std::map<std::string, std::vector<double>>& vectors)
{
    std::map<std::string, std::string> sums;
    for (const auto& [name, v] : texts)
        sums["text." + name] = hex(fnv1a(fnvStart, v.data(), v.size()));
    for (const auto& [name, v] : vectors)
        sums["list." + name] = hex(fnv1a(fnvStart, v.data(), v.size() * sizeof(double)));
    return sums;
}

//! Rank 0: the group "checksums", one text each; "" or the reason.
std::string writeChecksums(hid_t file, const std::map<std::string, std::string>& sums, const std::string& path)
{
    H5Id group{H5Gcreate2(file, "checksums", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    try
    {
        if (group.id < 0)
            throw OutputError("cannot create its checksums");
        writeDatasets(group.id, sums, H5T_NATIVE_CHAR);
    }
    catch (const OutputError& e)
    {
        return path + ": " + e.what();
    }
    return {};
}

} // namespace

void CheckpointWriter::commit()
{
    int rank, size;
    MPI_Comm_rank(comm_, &rank);
    MPI_Comm_size(comm_, &size);
    std::string error;
    const std::string tmp = path_ + ".tmp";
    {
        H5Id file{-1, H5Fclose}, tables{-1, H5Gclose};
        if (rank == 0)
        {
            H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
            texts_["format"] = formatTag;
            error = createFile(tmp, texts_, vectors_, file, tables);
        }
        std::map<std::string, std::string> sums = checksums(texts_, vectors_);
        for (const auto& [name, block] : blocks_)
        {
            const RowBlocks blocks{shapes_[name].first, size};
            if (rank != 0)
                sendDoubles(comm_, block.data(), block.size(), 0);
            else
            {
                std::uint64_t sum;
                const std::string e =
                    writeTable(comm_, tables.id, name, blocks, shapes_[name].second, block, error.empty(), sum);
                error = error.empty() ? e : error;
                sums["table." + name] = hex(sum);
            }
        }
        if (rank == 0 && error.empty())
            error = writeChecksums(file.id, sums, tmp);
        if (rank == 0 && error.empty() && H5Fflush(file.id, H5F_SCOPE_GLOBAL) < 0)
            error = "cannot flush " + tmp;
    }
    if (rank == 0)
    {
        if (error.empty() && std::rename(tmp.c_str(), path_.c_str()) != 0)
            error = "cannot rename " + tmp + " to " + path_;
        if (!error.empty())
            std::remove(tmp.c_str());
    }
    bcastString(comm_, error);
    if (!error.empty())
        throw OutputError("checkpoint: " + error);
}

namespace
{

const char* const unreadable = "not a readable checkpoint (missing, truncated or corrupt HDF5)";

//! A value whose checksum does not match: "text.NAME", "list.NAME" or "table.NAME".
std::string corrupt(const std::string& what)
{
    const auto dot = what.find('.');
    return "corrupt: " + what.substr(0, dot) + " '" + what.substr(dot + 1) + "' does not match its checksum";
}

/*! Rank 0: opens the checkpoint, reads its texts and lists, and the shapes {rows, columns} of its tables; "" or the
 *  reason. */
std::string openFile(const std::string& path, H5Id& file, H5Id& tables, std::map<std::string, std::string>& texts,
                     std::map<std::string, std::vector<double>>& vectors,
                     std::map<std::string, std::vector<double>>& shapes, std::map<std::string, std::string>& sums)
{
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    H5Id gt{file.id < 0 ? -1 : H5Gopen2(file.id, "texts", H5P_DEFAULT), H5Gclose};
    H5Id gv{file.id < 0 ? -1 : H5Gopen2(file.id, "vectors", H5P_DEFAULT), H5Gclose};
    tables.id = file.id < 0 ? -1 : H5Gopen2(file.id, "tables", H5P_DEFAULT);
    if (file.id >= 0 && (gt.id < 0 || gv.id < 0 || tables.id < 0)) // a dump, say: readable, but not a checkpoint
        return "an HDF5 file but not a unilag checkpoint (no texts, vectors and tables groups; a checkpoint is "
               "<DIR>/checkpoint.h5)";
    std::vector<hsize_t> dims;
    bool ok = gt.id >= 0 && gv.id >= 0 && tables.id >= 0;
    for (const std::string& name : ok ? members(gt.id) : std::vector<std::string>())
        ok = ok && readDataset(gt.id, name, H5T_NATIVE_CHAR, dims, resizeText, &texts[name]);
    for (const std::string& name : ok ? members(gv.id) : std::vector<std::string>())
        ok = ok && readDataset(gv.id, name, H5T_NATIVE_DOUBLE, dims, resizeDoubles, &vectors[name]);
    for (const std::string& name : ok ? members(tables.id) : std::vector<std::string>())
    {
        H5Id set{H5Dopen2(tables.id, name.c_str(), H5P_DEFAULT), H5Dclose};
        H5Id space{set.id < 0 ? -1 : H5Dget_space(set.id), H5Sclose};
        hsize_t shape[2] = {0, 0};
        ok = ok && space.id >= 0 && H5Sget_simple_extent_ndims(space.id) == 2 &&
             H5Sget_simple_extent_dims(space.id, shape, nullptr) == 2;
        shapes[name] = {double(shape[0]), double(shape[1])};
    }
    if (!ok)
        return unreadable;
    if (texts["format"] != formatTag)
        return "not a unilag checkpoint of this version (format '" + printable(texts["format"]) + "', expected '" +
               formatTag + "')";
    H5Id gs{H5Gopen2(file.id, "checksums", H5P_DEFAULT), H5Gclose};
    for (const std::string& name : gs.id >= 0 ? members(gs.id) : std::vector<std::string>())
        ok = ok && readDataset(gs.id, name, H5T_NATIVE_CHAR, dims, resizeText, &sums[name]);
    if (gs.id < 0 || !ok)
        return unreadable;
    for (const auto& [name, sum] : checksums(texts, vectors))
        if (sums[name] != sum)
            return corrupt(name);
    return {};
}

/*! Rank 0: reads the table `name` block by block, keeps its own block and sends each other rank its own (zeros
 *  after a failure, so that no rank waits forever); "" or the reason. */
std::string readTable(MPI_Comm comm, hid_t group, const std::string& name, const RowBlocks& blocks, int nc,
                      std::vector<double>& own, bool ok, const std::string& sum)
{
    std::uint64_t checksum = fnvStart;
    H5Id set{ok ? H5Dopen2(group, name.c_str(), H5P_DEFAULT) : -1, H5Dclose};
    bool read = set.id >= 0;
    std::vector<double> buffer;
    for (int r = 0; r < blocks.size; ++r)
    {
        std::vector<double>& block = r == 0 ? own : buffer;
        block.assign(std::size_t(blocks.count(r)) * nc, 0.0);
        read = read &&
               rowsIo(set.id, hsize_t(blocks.first(r)), hsize_t(blocks.count(r)), hsize_t(nc), block.data(), false);
        if (!read)
            std::fill(block.begin(), block.end(), 0.0);
        checksum = fnv1a(checksum, block.data(), block.size() * sizeof(double));
        if (r > 0)
            sendDoubles(comm, block.data(), block.size(), r);
    }
    if (ok && read && hex(checksum) != sum)
        return corrupt("table." + name);
    return !ok || read ? std::string() : unreadable;
}

} // namespace

CheckpointReader::CheckpointReader(MPI_Comm comm, const std::string& path) : comm_(comm), path_(path)
{
    int rank, size;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    std::string error;
    H5Id file{-1, H5Fclose}, tables{-1, H5Gclose};
    std::map<std::string, std::vector<double>> shapes;
    std::map<std::string, std::string> sums;
    if (rank == 0)
        error = openFile(path, file, tables, texts_, vectors_, shapes, sums);
    bcastString(comm, error);
    if (!error.empty())
        throw InputError("--restart '" + path + "': " + error);
    bcastMap(comm, texts_);
    bcastMap(comm, vectors_);
    bcastMap(comm, shapes);
    for (const auto& [name, shape] : shapes)
    {
        const RowBlocks blocks{(long long)shape[0], size};
        const int nc = int(shape[1]);
        shapes_[name] = {blocks.n, nc};
        std::vector<double>& block = blocks_[name];
        block.assign(std::size_t(blocks.count(rank)) * nc, 0.0);
        if (rank == 0)
        {
            const std::string e =
                readTable(comm, tables.id, name, blocks, nc, block, error.empty(), sums["table." + name]);
            error = error.empty() ? e : error;
        }
        else
            recvDoubles(comm, block.data(), block.size(), 0);
    }
    bcastString(comm, error);
    if (!error.empty())
        throw InputError("--restart '" + path + "': " + error);
}

std::string CheckpointReader::text(const std::string& name) const
{
    auto it = texts_.find(name);
    if (it == texts_.end())
        throw InputError("--restart '" + path_ + "': no text '" + name + "'");
    return it->second;
}

const std::vector<double>& CheckpointReader::numbers(const std::string& name) const
{
    auto it = vectors_.find(name);
    if (it == vectors_.end())
        throw InputError("--restart '" + path_ + "': no list '" + name + "'");
    return it->second;
}

std::vector<double> CheckpointReader::rows(const std::string& name, const std::vector<long long>& gid, int ncomp) const
{
    auto it = shapes_.find(name);
    if (it == shapes_.end() || it->second.second != ncomp)
        throw InputError("--restart '" + path_ + "': no table '" + name + "' of " + std::to_string(ncomp) + " columns");
    int size;
    MPI_Comm_size(comm_, &size);
    std::string error;
    std::vector<double> out =
        rowsFromBlocks(comm_, RowBlocks{it->second.first, size}, blocks_.at(name), ncomp, gid, error);
    error = mpi::firstMessage(comm_, error);
    if (!error.empty())
        throw InputError("--restart '" + path_ + "': table '" + name + "' has " + error);
    return out;
}

} // namespace unilag::io
