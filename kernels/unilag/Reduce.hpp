/*! \file Reduce.hpp
 *  \brief Fixed-size multi-value reductions (several sums or extrema in one pass over the cells).
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{

//! Neumaier's compensated addition: (sum, c) += x.
KOKKOS_INLINE_FUNCTION void compensatedAdd(double& sum, double& c, double x)
{
    const double t = sum + x;
    if (Kokkos::Experimental::fabs(sum) >= Kokkos::Experimental::fabs(x))
        c += (sum - t) + x;
    else
        c += (x - t) + sum;
    sum = t;
}

/*! \brief N sums in one parallel_reduce, compensated (Neumaier), so that conservation diagnostics over 10^5-10^6
 *  cells are accurate to a few ulps whatever the thread count. f(i, double (&acc)[N]) sets cell i's contributions
 *  (acc arrives zeroed). */
template <int N, class F>
struct SumN
{
    using value_type = double[];
    using size_type = std::size_t;
    const unsigned value_count = 2 * N; // N sums, then N compensations
    F f;
    KOKKOS_INLINE_FUNCTION void operator()(const LO i, value_type acc) const
    {
        double term[N];
        for (int k = 0; k < N; ++k)
            term[k] = 0.0;
        f(i, term);
        for (int k = 0; k < N; ++k)
            compensatedAdd(acc[k], acc[N + k], term[k]);
    }
    KOKKOS_INLINE_FUNCTION void init(value_type acc) const
    {
        for (int k = 0; k < 2 * N; ++k)
            acc[k] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        for (int k = 0; k < N; ++k)
        {
            double sum = dst[k], c = dst[N + k] + src[N + k];
            compensatedAdd(sum, c, src[k]);
            dst[k] = sum;
            dst[N + k] = c;
        }
    }
};

template <int N, class F>
void sumReduce(const char* label, LO n, const F& f, double (&out)[N])
{
    SumN<N, F> functor{2 * N, f};
    double both[2 * N];
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> result(both, 2 * N);
    Kokkos::parallel_reduce(label, range(n), functor, result);
    for (int k = 0; k < N; ++k)
        out[k] = both[k] + both[N + k];
}

//! N minima in one parallel_reduce (maxima: reduce the negated value).
template <int N, class F>
struct MinN
{
    using value_type = double[];
    using size_type = std::size_t;
    const unsigned value_count = N;
    F f;
    KOKKOS_INLINE_FUNCTION void operator()(const LO i, value_type acc) const
    {
        double (&a)[N] = *reinterpret_cast<double(*)[N]>(acc);
        f(i, a);
    }
    KOKKOS_INLINE_FUNCTION void init(value_type acc) const
    {
        for (int k = 0; k < N; ++k)
            acc[k] = Kokkos::reduction_identity<double>::min();
    }
    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        for (int k = 0; k < N; ++k)
            if (src[k] < dst[k])
                dst[k] = src[k];
    }
};

/*! \brief N minima over [0, n). Minima do not depend on the order of the joins, so `dynamic` (dynamic scheduling,
 *  for loops whose cost varies from cell to cell, e.g. plastic flow in part of the mesh) keeps results bitwise
 *  identical for any thread count. */
template <int N, class F>
void minReduce(const char* label, LO n, const F& f, double (&out)[N], bool dynamic = false)
{
    MinN<N, F> functor{N, f};
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> result(out, N);
    if (dynamic)
        Kokkos::parallel_reduce(label, Kokkos::RangePolicy<ExecSpace, Kokkos::Schedule<Kokkos::Dynamic>>(0, n), functor,
                                result);
    else
        Kokkos::parallel_reduce(label, range(n), functor, result);
}

/*! The largest f(i) over [0, n), the lowest i among equal values, and M numbers of that i (e.g. its centroid) in one
 *  pass: result [value, i, payload...]. f(i, double (&payload)[M]) returns the value and fills the payload. The
 *  (value, lowest index) order does not depend on the joins, so the result is the same for any thread count. */
template <int M, class F>
struct LargestAt
{
    using value_type = double[];
    using size_type = std::size_t;
    const unsigned value_count = 2 + M;
    F f;
    KOKKOS_INLINE_FUNCTION static bool before(const volatile double* a, const volatile double* b)
    {
        return a[0] > b[0] || (a[0] == b[0] && a[1] < b[1]);
    }
    KOKKOS_INLINE_FUNCTION void operator()(const LO i, value_type acc) const
    {
        double mine[2 + M];
        double(&payload)[M] = *reinterpret_cast<double(*)[M]>(mine + 2);
        mine[0] = f(i, payload);
        mine[1] = double(i);
        if (before(mine, acc))
            for (int k = 0; k < 2 + M; ++k)
                acc[k] = mine[k];
    }
    KOKKOS_INLINE_FUNCTION void init(value_type acc) const
    {
        acc[0] = Kokkos::reduction_identity<double>::max();
        acc[1] = Kokkos::reduction_identity<double>::min();
        for (int k = 2; k < 2 + M; ++k)
            acc[k] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        if (before(src, dst))
            for (int k = 0; k < 2 + M; ++k)
                dst[k] = src[k];
    }
};

template <int M, class F>
void largestAt(const char* label, LO n, const F& f, double (&out)[2 + M])
{
    LargestAt<M, F> functor{2 + M, f};
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> result(out, 2 + M);
    Kokkos::parallel_reduce(label, range(n), functor, result);
}

} // namespace unilag
