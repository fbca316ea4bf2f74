#include "io/Checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "core/Errors.hpp"

namespace unilag::io
{
namespace
{

const char* const formatTag = "unilag checkpoint 1";

//! Gathers every rank's (gid, values) to rank 0; returns, there, the rows in global-id order.
std::vector<double> gatherRows(MPI_Comm comm, long long nGlobal, const CheckpointRows& rows, std::string& error)
{
    int rank, size;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const int n = int(rows.gid.size());
    std::vector<int> counts(size), offsets(size, 0);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    for (int r = 1; r < size; ++r)
        offsets[r] = offsets[r - 1] + counts[r - 1];
    const int total = rank == 0 ? offsets[size - 1] + counts[size - 1] : 0;
    std::vector<long long> gid(total);
    MPI_Gatherv(rows.gid.data(), n, MPI_LONG_LONG, gid.data(), counts.data(), offsets.data(), MPI_LONG_LONG, 0, comm);
    for (int r = 0; r < size; ++r)
    {
        counts[r] *= rows.ncomp;
        offsets[r] *= rows.ncomp;
    }
    std::vector<double> values(std::size_t(total) * rows.ncomp), ordered;
    MPI_Gatherv(rows.values.data(), n * rows.ncomp, MPI_DOUBLE, values.data(), counts.data(), offsets.data(),
                MPI_DOUBLE, 0, comm);
    if (rank != 0)
        return ordered;
    if (total != nGlobal)
        error = "the ranks hold " + std::to_string(total) + " rows, not " + std::to_string(nGlobal);
    ordered.assign(std::size_t(nGlobal) * rows.ncomp, 0.0);
    for (int i = 0; i < total && error.empty(); ++i)
    {
        if (gid[i] < 0 || gid[i] >= nGlobal)
            error = "global id " + std::to_string(gid[i]) + " out of range";
        else
            for (int c = 0; c < rows.ncomp; ++c)
                ordered[std::size_t(gid[i]) * rows.ncomp + c] = values[std::size_t(i) * rows.ncomp + c];
    }
    return ordered;
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
    std::string error;
    std::vector<double> ordered = gatherRows(comm_, nGlobal, rows, error);
    int bad = error.empty() ? 0 : 1;
    MPI_Bcast(&bad, 1, MPI_INT, 0, comm_);
    if (bad)
        throw OutputError("checkpoint " + path_ + ": table '" + name + "': " + error);
    tables_[name] = std::move(ordered);
    tableColumns_[name] = rows.ncomp;
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

//! Rank 0: the whole file, or the reason it cannot be written.
std::string writeFile(const std::string& path, const std::map<std::string, std::string>& texts,
                      const std::map<std::string, std::vector<double>>& vectors,
                      const std::map<std::string, std::vector<double>>& tables, const std::map<std::string, int>& cols)
{
    try
    {
        H5Id file{H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
        if (file.id < 0)
            return "cannot create " + path;
        H5Id gt{H5Gcreate2(file.id, "texts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
        H5Id gv{H5Gcreate2(file.id, "vectors", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
        H5Id gr{H5Gcreate2(file.id, "tables", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
        if (gt.id < 0 || gv.id < 0 || gr.id < 0)
            return "cannot create the groups of " + path;
        for (const auto& [name, v] : texts)
        {
            const hsize_t n = v.size();
            writeDataset(gt.id, name, H5T_NATIVE_CHAR, 1, &n, v.data());
        }
        for (const auto& [name, v] : vectors)
        {
            const hsize_t n = v.size();
            writeDataset(gv.id, name, H5T_NATIVE_DOUBLE, 1, &n, v.data());
        }
        for (const auto& [name, v] : tables)
        {
            const hsize_t dims[2] = {v.size() / hsize_t(cols.at(name)), hsize_t(cols.at(name))};
            writeDataset(gr.id, name, H5T_NATIVE_DOUBLE, 2, dims, v.data());
        }
        if (H5Fflush(file.id, H5F_SCOPE_GLOBAL) < 0)
            return "cannot flush " + path;
    }
    catch (const OutputError& e)
    {
        return path + ": " + e.what();
    }
    return {};
}

//! Names of the members of a group.
std::vector<std::string> members(hid_t group)
{
    std::vector<std::string> names;
    H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
                [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t
                {
                    static_cast<std::vector<std::string>*>(data)->push_back(name);
                    return 0;
                },
                &names);
    return names;
}

//! Reads a dataset as doubles (or chars into text); dims gets its shape.
bool readDataset(hid_t group, const std::string& name, hid_t type, std::vector<hsize_t>& dims, void* (*resize)(void*, std::size_t), void* out)
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

} // namespace

void CheckpointWriter::commit()
{
    int rank;
    MPI_Comm_rank(comm_, &rank);
    std::string error;
    const std::string tmp = path_ + ".tmp";
    if (rank == 0)
    {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        texts_["format"] = formatTag;
        error = writeFile(tmp, texts_, vectors_, tables_, tableColumns_);
        if (error.empty() && std::rename(tmp.c_str(), path_.c_str()) != 0)
            error = "cannot rename " + tmp + " to " + path_;
        if (!error.empty())
            std::remove(tmp.c_str());
    }
    bcastString(comm_, error);
    if (!error.empty())
        throw OutputError("checkpoint: " + error);
}

CheckpointReader::CheckpointReader(MPI_Comm comm, const std::string& path) : path_(path)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    std::string error;
    if (rank == 0)
    {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
        H5Id gt{file.id < 0 ? -1 : H5Gopen2(file.id, "texts", H5P_DEFAULT), H5Gclose};
        H5Id gv{file.id < 0 ? -1 : H5Gopen2(file.id, "vectors", H5P_DEFAULT), H5Gclose};
        H5Id gr{file.id < 0 ? -1 : H5Gopen2(file.id, "tables", H5P_DEFAULT), H5Gclose};
        std::vector<hsize_t> dims;
        bool ok = gt.id >= 0 && gv.id >= 0 && gr.id >= 0;
        for (const std::string& name : ok ? members(gt.id) : std::vector<std::string>())
            ok = ok && readDataset(gt.id, name, H5T_NATIVE_CHAR, dims, resizeText, &texts_[name]);
        for (const std::string& name : ok ? members(gv.id) : std::vector<std::string>())
            ok = ok && readDataset(gv.id, name, H5T_NATIVE_DOUBLE, dims, resizeDoubles, &vectors_[name]);
        for (const std::string& name : ok ? members(gr.id) : std::vector<std::string>())
        {
            ok = ok && readDataset(gr.id, name, H5T_NATIVE_DOUBLE, dims, resizeDoubles, &tables_[name]) &&
                 dims.size() == 2;
            tableColumns_[name] = ok ? int(dims[1]) : 0;
        }
        if (!ok)
            error = "not a readable checkpoint (missing, truncated or corrupt HDF5)";
        else if (texts_["format"] != formatTag)
            error = "not a unilag checkpoint (format '" + texts_["format"] + "', expected '" + formatTag + "')";
    }
    bcastString(comm, error);
    if (!error.empty())
        throw InputError("--restart '" + path + "': " + error);
    bcastMap(comm, texts_);
    bcastMap(comm, vectors_);
    bcastMap(comm, tables_);
    bcastMap(comm, tableColumns_);
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
    auto it = tables_.find(name);
    if (it == tables_.end() || tableColumns_.at(name) != ncomp)
        throw InputError("--restart '" + path_ + "': no table '" + name + "' of " + std::to_string(ncomp) +
                         " columns");
    const std::vector<double>& t = it->second;
    const long long n = (long long)(t.size() / std::size_t(ncomp));
    std::vector<double> out(gid.size() * std::size_t(ncomp));
    for (std::size_t i = 0; i < gid.size(); ++i)
    {
        if (gid[i] < 0 || gid[i] >= n)
            throw InputError("--restart '" + path_ + "': table '" + name + "' has no row " + std::to_string(gid[i]));
        for (int c = 0; c < ncomp; ++c)
            out[i * std::size_t(ncomp) + c] = t[std::size_t(gid[i]) * ncomp + c];
    }
    return out;
}

} // namespace unilag::io
