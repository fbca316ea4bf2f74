/*! \file SmallLaunch.hpp
 *  \brief Kernel launches of the tube solvers (rod, gas, wall, artery): on the default execution space, or on
 *  Kokkos::Serial when asked (`serial`) and the views are host-accessible, since a tube of a few hundred nodes or
 *  cells spends more time in OpenMP fork/join than in its kernels. On a GPU build `serial` has no effect.
 */
#pragma once

#include <utility>

#include <Kokkos_Core.hpp>

namespace unilag::tube::launch
{

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;

//! Whether a serial launch can reach the default memory space (host backends).
constexpr bool serialReachable()
{
#if defined(KOKKOS_ENABLE_SERIAL)
    return Kokkos::SpaceAccessibility<Kokkos::Serial, MemSpace>::accessible;
#else
    return false;
#endif
}

template <class Functor> void forEach(const char* name, int n, bool serial, const Functor& f)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (serialReachable())
        if (serial)
            return Kokkos::parallel_for(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f);
#endif
    (void)serial;
    Kokkos::parallel_for(name, Kokkos::RangePolicy<ExecSpace>(0, n), f);
}

//! parallel_reduce into `result` (a value or a reducer).
template <class Functor, class Result> void reduce(const char* name, int n, bool serial, const Functor& f, Result&& result)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (serialReachable())
        if (serial)
            return Kokkos::parallel_reduce(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f,
                                           std::forward<Result>(result));
#endif
    (void)serial;
    Kokkos::parallel_reduce(name, Kokkos::RangePolicy<ExecSpace>(0, n), f, std::forward<Result>(result));
}

/*! An inclusive scan in index order on one thread. Kokkos' parallel_scan adds its threads' chunks, whose bounds move
 *  with the thread count (3 threads changed the rod's p A in the 13th digit), and a tube's results must not; a scan
 *  is n additions, less than a launch costs. */
template <class Functor> struct InOrderScan
{
    Functor f;
    int n;
    KOKKOS_INLINE_FUNCTION void operator()(int) const
    {
        typename Functor::value_type sum{};
        for (int i = 0; i < n; ++i)
            f(i, sum, true);
    }
};

//! One thread's work: on Kokkos::Serial where the views are host-accessible (an OpenMP launch of one iteration would
//! fork a team for nothing).
template <class Functor> void scan(const char* name, int n, const Functor& f)
{
    forEach(name, 1, true, InOrderScan<Functor>{f, n});
}

} // namespace unilag::tube::launch
