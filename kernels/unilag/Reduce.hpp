/*! \file Reduce.hpp
 *  \brief Fixed-size multi-value reductions (several sums or extrema in one pass over the cells).
 */
#pragma once

#include "unilag/Types.hpp"

namespace unilag
{

//! N sums in one parallel_reduce. f(i, double (&acc)[N]) adds cell i's contributions.
template <int N, class F>
struct SumN
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
            acc[k] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        for (int k = 0; k < N; ++k)
            dst[k] += src[k];
    }
};

template <int N, class F>
void sumReduce(const char* label, LO n, const F& f, double (&out)[N])
{
    SumN<N, F> functor{N, f};
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> result(out, N);
    Kokkos::parallel_reduce(label, range(n), functor, result);
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

template <int N, class F>
void minReduce(const char* label, LO n, const F& f, double (&out)[N])
{
    MinN<N, F> functor{N, f};
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> result(out, N);
    Kokkos::parallel_reduce(label, range(n), functor, result);
}

} // namespace unilag
