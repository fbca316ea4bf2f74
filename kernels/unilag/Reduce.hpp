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

} // namespace unilag
