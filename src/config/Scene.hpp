/*! \file Scene.hpp
 *  \brief The continuum (GPR) scene: one YAML file read by the shared walker (Walker.hpp), `--set` overrides,
 *  validation, and every option string turned into an enum once.
 *
 *  Every key is checked against the schema in Scene.cpp: an unknown or misspelt key, a wrong type or an
 *  out-of-range value raises InputError naming the file and the key path, before anything is written.
 */
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tube/RiemannExact.hpp"

#include <Teuchos_ParameterList.hpp>

#include "config/Walker.hpp"
#include "core/Errors.hpp"
#include "unilag/Reconstruction.hpp"

namespace unilag
{

using config::Expr;

/*! Order 2's time integrator (scheme.integrator; docs/gpr-model.md 2.6): the midpoint predictor-corrector, or the
 *  paper's IMEX ARS(2,2,2) (reference gpr.md 2.6). Order 1 is forward/backward Euler. */
enum class Integrator
{
    Midpoint,
    Ars222
};

enum class EosKind
{
    IdealGas,
    MieGruneisen,
    NeoHookean
};

//! Strain relaxation laws of the scene (docs/gpr-model.md 1.4); the kernels see StrainNone, StrainConstant or
//! StrainPlastic.
enum class RelaxationLaw
{
    Fluid,    //!< no shear stress
    Viscous,  //!< tau1 from the viscosity
    Elastic,  //!< tau1 = +inf
    Constant, //!< tau1 as given
    Plastic   //!< tau1 = tau10 (sigma_Y / sigma_bar)^n
};

enum class BoundaryKind
{
    Free,
    SlipWall,
    Symmetry,
    Velocity,
    Pressure,
    Traction
};

enum class ThermalKind
{
    Adiabatic,
    Isothermal
};

enum class ExactSolution
{
    None,
    Sedov,
    Stationary, //!< the initial state is the solution at all times (the isentropic vortex): L2 errors at the end
    Riemann     //!< a 1D Riemann problem along x in an ideal gas (Sod): L1(density) against the exact solution
};

//! One side of a Riemann problem (exact.left / exact.right): density, velocity along x, pressure.
struct RiemannSide
{
    double density = 1.0, velocity = 0.0, pressure = 1.0;
};

struct MaterialSpec
{
    EosKind eos = EosKind::IdealGas; //!< docs/gpr-model.md 1.3
    double gamma = 1.4;              //!< ideal gas
    double cv = 1.0;
    double rho0 = 1.0, c0 = 1.0, Gamma0 = 0.0, s = 0.0; //!< Mie-Grueneisen (rho0 also neo-Hookean)
    double csh = 0.0;                                   //!< neo-Hookean modulus rho0 csh^2

    // GPR constitutive model (docs/gpr-model.md 1.2, 1.4). rho0 above is also the reference density of G_e (at rest
    // G_e = (rho/rho0)^{2/3} I) and of the relaxation laws; for an ideal gas it defaults to 1.
    double shearSpeed = 0.0; //!< c_sh >= 0 (key shear_sound_speed); 0 with law "fluid"
    RelaxationLaw strainLaw = RelaxationLaw::Fluid;
    double tau1 = 0.0;      //!< relaxation time: constant law as given; viscous 6 mu/(rho0 csh^2); elastic +inf
    double viscosity = 0.0; //!< viscous law: mu
    double tau10 = 0.0, yieldStress = 0.0, exponent = 0.0; //!< plastic law tau1 = tau10 (sigma_Y / sigma_bar)^n
    bool heatConduction = false;                           //!< key heat_conduction present
    double alpha = 0.0;                                    //!< heat: alpha
    double tau2 = 0.0;   //!< heat: relaxation time (given, or from kappa: tau2 = kappa rho0/(alpha^2 theta0))
    double kappa = 0.0;  //!< heat: Fourier conductivity (given, or from tau2)
    double theta0 = 0.0; //!< heat: reference temperature
};

struct RegionSpec
{
    std::string material;
    Expr density;
    Expr pressure;       //!< either pressure ...
    Expr internalEnergy; //!< ... or specific internal energy
    bool hasPressure = true;
    std::array<Expr, 3> velocity;
    int velocityComponents = 0;
    //! sampling: average: each cell takes the mean mass, momentum and energy of the expressions over points spread
    //! through it (GprInitialState.hpp), not their values at its centroid; for data discontinuous inside cells
    bool average = false;
};

struct BoundarySpec
{
    BoundaryKind type = BoundaryKind::SlipWall;
    std::array<double, 3> velocity{0.0, 0.0, 0.0};
    Expr pressure; //!< imposed pressure (normal traction -p n): a constant or an expression of t
    std::array<double, 3> traction{0.0, 0.0, 0.0}; //!< imposed traction vector T n (type traction)
    ThermalKind thermal = ThermalKind::Adiabatic;  //!< adiabatic: q . n = 0
    double temperature = 0.0;                      //!< isothermal wall temperature (> 0)
};

struct Scene
{
    std::string file;      //!< path of the scene file
    std::string directory; //!< folder of the scene file (relative paths resolve against it)
    std::string name;

    // mesh
    std::string geometry; //!< .geo to mesh at start-up (resolved path), or
    std::string meshFile; //!< .msh to read (resolved path)
    double meshSize = 0.0;
    bool meshLattice = false; //!< mesh.mesher: lattice (a rectangle or box as a lattice; LatticeMesh.hpp)

    std::map<std::string, MaterialSpec> materials;
    std::map<std::string, RegionSpec> regions;      //!< by gmsh physical group name (cells)
    std::map<std::string, BoundarySpec> boundaries; //!< by gmsh physical group name (faces)

    bool hasDeposit = false;
    std::array<double, 3> depositPosition{0.0, 0.0, 0.0};
    double depositEnergy = 0.0;

    double endTime = 1.0;
    double cfl = 0.5;
    double maxVolumeChange = 0.1;
    double initialTimeStep = 0.0; //!< 0: from the CFL condition, scaled by 0.1
    double maxGrowth = 1.1;
    long maxSteps = 10000000;
    bool maxStepsGiven = false; //!< the scene caps the steps: a run that cannot reach its end time runs to the cap
    int maxRetries = 8;

    // scheme
    double picardTolerance = 1e-10; //!< max_i |sigma^{l+1} - sigma^l|_F / (rho_i a_i^2) to stop the Picard loop
    int picardMaxIterations = 50;   //!< cap: the step is cut and retried when it is reached
    int order = 1;                  //!< 1: first order; 2: limited linear reconstruction + midpoint predictor-corrector
    Limiter limiter = Limiter::NodeFit; //!< order 2 only
    std::optional<Limiter> pressureLimiter; //!< order 2: the pressure's and shear stress's own (else limiter)
    Reconstructed reconstruct = Reconstructed::All; //!< order 2 only: every quantity, or the velocity alone
    CornerLoad cornerLoad = CornerLoad::Lumped;     //!< order 2 only: how the traction loads the corners
    Integrator integrator = Integrator::Midpoint; //!< order 2 only (ars222 is rejected at order 1)
    double entropyFilter = 0.0; //!< C of the entropy filter after each step (EntropyFilter.hpp), 0 = none

    std::string outputDirectory = "output";
    std::string outputSource = "output folder"; //!< where outputDirectory came from, for messages ("--output", a key)
    double outputInterval = 0.0; //!< 0: first and last state only
    double checkpointInterval = 0.0; //!< simulated time between checkpoints (0: none)
    bool writeOutput = true;

    // parallel: the load balance of a run on several ranks (TimeControl)
    long balanceInterval = 50;       //!< steps between checks of the ranks' busy times (0: none)
    long earlyBalanceInterval = -1;  //!< steps between checks in the first interval (-1: earlyChecks())
    double imbalanceThreshold = 1.1; //!< repartition when max / mean of the busy times exceeds it (< 1: always)
    bool repartition = true;         //!< false: measure and report only
    bool rankSpeeds = true;          //!< weigh each rank's cells by its measured speed (TimeControl::rankSpeeds)
    //! The early checks' interval: the scene's, or by default a fifth of the check interval (at least 1).
    long earlyChecks() const
    {
        return earlyBalanceInterval >= 0 ? earlyBalanceInterval : std::max(1L, balanceInterval / 5);
    }
    //! The partitioner of repartitions: Zoltan2's multijagged or rcb, or sfc (ranges of the global ids, which follow
    //! a Morton curve of the cells, GlobalMesh.cpp)
    std::string partitioner = "multijagged";

    ExactSolution exactSolution = ExactSolution::None;
    std::string exactTable;            //!< resolved path of a radial profile (csv)
    double exactShockRadius = 0.0;     //!< at exactTime
    double exactTime = 1.0;            //!< time of the tabulated profile (self-similar scaling to other times)
    RiemannSide riemannLeft, riemannRight; //!< Riemann: the states left and right of x = riemannPosition at t = 0
    double riemannPosition = 0.0;
    double riemannGamma = 1.4; //!< Riemann: the ideal gas' gamma (every material's)
    double maxL1Density = 0.0;         //!< --check bound, 0 = none
    double maxDensity = 0.0;           //!< --check bound on the largest cell density over the run, 0 = none
    double shockRadiusTolerance = 0.0; //!< --check bound (relative), 0 = none
    std::map<std::string, double> boundaryRadius; //!< exact mean distance from the origin of a boundary group
    double radiusTolerance = 0.0;                 //!< --check bound on it (relative), 0 = none
    //! Stationary: --check bounds on the L2 errors of specific volume, velocity and total energy (0 = none)
    double maxL2[3] = {0.0, 0.0, 0.0};

    Teuchos::ParameterList resolved; //!< the scene with defaults filled in, written beside the output
};

/*! \brief Read, override and validate a scene. Throws InputError.
 *  \param overrides "key.path=value" strings from --set (dots separate nested keys). */
Scene readScene(const std::string& file, const std::vector<std::string>& overrides);

//! The exact solution of the scene's Riemann problem (exact.solution: riemann). Throws std::runtime_error on vacuum.
tube::RiemannExact riemannSolution(const Scene& scene);

//! Write the resolved scene as YAML (a run writes it into its output folder, rank 0).
void writeScene(const Scene& scene, const std::string& file);

} // namespace unilag
