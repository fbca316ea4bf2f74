// The checkpoint's block layout (src/io/BlockRows.*, src/io/Checkpoint.*): rows given by any rank in any order come
// back by global id on any rank, bit for bit, with no rank holding a whole table; tables smaller than the number of
// ranks (empty blocks) work; a row missing or given twice is refused when writing, one out of range when reading,
// on every rank alike. `unit` runs these on one rank, unit_mesh_np2 and unit_mesh_np3 on more (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "io/Checkpoint.hpp"

namespace
{

int rankOf()
{
    int r;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}
int sizeOf()
{
    int s;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
}

//! A value no other (gid, column) pair shares, and not exactly representable in few digits.
double valueOf(long long gid, int c)
{
    return gid * 10.0 + c + 1.0 / 3.0;
}

//! Rows of gids g = rank, rank + P, ... (interleaved, descending) of n rows with nc columns.
unilag::io::CheckpointRows interleaved(long long n, int nc)
{
    unilag::io::CheckpointRows rows;
    rows.ncomp = nc;
    for (long long g = n - 1; g >= 0; --g)
        if (g % sizeOf() == rankOf())
        {
            rows.gid.push_back(g);
            for (int c = 0; c < nc; ++c)
                rows.values.push_back(valueOf(g, c));
        }
    return rows;
}

std::string path()
{
    return testing::TempDir() + "unilag_checkpoint_unit.h5";
}

} // namespace

TEST(Checkpoint, BlocksCoverEveryRowOnce)
{
    for (long long n : {0LL, 1LL, 2LL, 7LL, 1000003LL})
        for (int size : {1, 2, 3, 7})
        {
            const unilag::io::RowBlocks b{n, size};
            EXPECT_EQ(b.first(0), 0);
            EXPECT_EQ(b.first(size), n);
            for (long long g : {0LL, n / 2, n - 1})
                if (g >= 0 && g < n)
                {
                    const int r = b.owner(g);
                    EXPECT_TRUE(b.first(r) <= g && g < b.first(r + 1)) << n << " " << size << " " << g;
                }
        }
}

TEST(Checkpoint, RowsComeBackByGlobalIdOnAnyRank)
{
    for (long long n : {2LL, 11LL})
    {
        {
            unilag::io::CheckpointWriter out(MPI_COMM_WORLD, path());
            out.text("title", "unit");
            out.numbers("loop", {1.5, 2.0});
            out.table("cell.state", n, interleaved(n, 3));
            out.table("node.x", n, interleaved(n, 1));
            out.commit();
        }
        unilag::io::CheckpointReader in(MPI_COMM_WORLD, path());
        EXPECT_EQ(in.text("title"), "unit");
        EXPECT_EQ(in.numbers("loop"), (std::vector<double>{1.5, 2.0}));
        // another rank's rows, and one row twice
        std::vector<long long> gid;
        for (long long g = 0; g < n; ++g)
            if (g % sizeOf() == (rankOf() + 1) % sizeOf())
                gid.push_back(g);
        gid.push_back(n - 1);
        const std::vector<double> v = in.rows("cell.state", gid, 3);
        ASSERT_EQ(v.size(), gid.size() * 3);
        for (std::size_t i = 0; i < gid.size(); ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(v[i * 3 + c], valueOf(gid[i], c));
        EXPECT_EQ(in.rows("node.x", gid, 1)[0], valueOf(gid[0], 0));
        EXPECT_THROW(in.rows("node.x", gid, 2), unilag::InputError);
        EXPECT_THROW(in.rows("cell.state", {rankOf() == 0 ? n : 0LL}, 3), unilag::InputError); // every rank throws
    }
    std::remove(path().c_str());
}

TEST(Checkpoint, MissingOrRepeatedRowsAreRefused)
{
    unilag::io::CheckpointRows rows = interleaved(5, 2);
    if (rankOf() == 0) // gid 0 twice on one rank
    {
        rows.gid.push_back(0);
        rows.values.insert(rows.values.end(), {1.0, 2.0});
    }
    unilag::io::CheckpointWriter out(MPI_COMM_WORLD, path());
    EXPECT_THROW(out.table("t", 5, rows), unilag::OutputError);
    EXPECT_THROW(out.table("t", 6, interleaved(5, 2)), unilag::OutputError); // no row 5
}
