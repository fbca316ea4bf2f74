/*! \file Timers.hpp
 *  \brief Phase timers (Laghos' StopWatches): each phase accumulates wall seconds after a fence, and opens a
 *  Kokkos profiling region of the same name, so a Kokkos tool (kernel timer, Nsight, VTune) sees the phases too.
 */
#pragma once

#include <array>
#include <chrono>

#include <Kokkos_Core.hpp>

namespace unilag
{

//! The phases of a step that summary.json reports as shares of the wall time.
enum class Phase : int
{
    Geometry,       //!< corner vectors, volumes, lengths
    Eos,            //!< pressure, sound speed, temperature and stress from the state
    NodalSolve,     //!< node velocities and subcell forces
    TimeStep,       //!< the stable time step
    Reconstruction, //!< limited gradients (order 2)
    StrainUpdate,   //!< G_e transport and relaxation (the Picard iterations)
    HeatFluxes,     //!< Rusanov heat fluxes
    CellUpdate,     //!< v, E, omega (and J) from the forces
    EntropyFilter,  //!< the entropy filter after a step (scheme.entropy_filter)
    Halo,           //!< ghost exchanges
    Output,         //!< HDF5/XDMF dumps
    Check,          //!< the force balance at the nodes (boundary impulse and work; every node with --check)
    Count
};

//! The name of a phase, as summary.json and the profiling regions write it.
inline const char* phaseName(Phase p)
{
    static const char* names[] = {"geometry",      "eos",         "nodal_solve", "time_step", "reconstruction",
                                  "strain_update", "heat_fluxes", "cell_update", "entropy_filter", "halo",      "io",
                                  "check"};
    return names[int(p)];
}

struct PhaseTimers
{
    std::array<double, int(Phase::Count)> seconds{};
    double operator[](Phase p) const { return seconds[int(p)]; }
};

//! Times one phase from construction to destruction (after a fence), inside a Kokkos profiling region.
class ScopedTimer
{
  public:
    using Clock = std::chrono::steady_clock;
    ScopedTimer(PhaseTimers& timers, Phase phase) : acc_(timers.seconds[int(phase)]), t0_(Clock::now())
    {
        Kokkos::Profiling::pushRegion(std::string("unilag::") + phaseName(phase));
    }
    ~ScopedTimer()
    {
        Kokkos::fence();
        acc_ += std::chrono::duration<double>(Clock::now() - t0_).count();
        Kokkos::Profiling::popRegion();
    }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

  private:
    double& acc_;
    Clock::time_point t0_;
};

} // namespace unilag
