/*! \file TubeScene.hpp
 *  \brief A tube scene: the tube, its fluid, its end conditions, the stability study and the output, read and
 *  validated by the shared scene walker (config::ConfigNode). Bad input throws InputError naming file and key.
 *
 *  The Euler-Bernoulli study is dimensionless (tube.md 2.1): it takes the mass ratios beta directly from
 *  `stability.beta`. The physical tube (`tube:` and `fluid:` keys) is optional; when given, it supplies the
 *  scales (EI, M, m, beta) reported in summary.json, and its own beta when `stability.beta` is absent.
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tube/ArteryScene.hpp"
#include "tube/GasScene.hpp"
#include "tube/TubeDynamicsScene.hpp"

namespace Teuchos
{
class ParameterList;
}

namespace unilag::tube
{

enum class EndCondition
{
    Clamped,
    Pinned,
    Free
};
enum class TubeModel
{
    EulerBernoulli, //!< inextensible, unshearable, no area change: the classical pipe (tube.md 2.1)
    Geometric       //!< finite shear and extension, rotary inertia, area change K (docs/tube-model.md 7)
};

/*! What loads the area change A = A0 - K psi'^2 / 2 about the straight state (docs/tube-model.md 7.3): the bending
 *  stiffness becomes EI + K (rho_f U^2 / 2 - mu0). Dynamic: mu0 = 0, the multiplier taken as the pressure level,
 *  ambient (0) at the free outlet, so the dynamic pressure rho_f U^2 / 2 stiffens. Static: mu0 = rho_f U^2 / 2 - p0
 *  (the fluid equation's Bernoulli relation) with the static pressure p0 ambient, so K drops out. */
enum class AreaPressure
{
    Dynamic,
    Static
};

/*! The geometric model's dimensionless parameters (docs/tube-model.md 7.2), in the units of the Euler-Bernoulli
 *  problem (lengths by L, time by L^2 sqrt((M + m) / EI), energies by EI / L). All 0: the Euler-Bernoulli limit. */
struct GeometricParameters
{
    double shear = 0.0;      //!< EI / (kappa G A_w L^2): shear compliance
    double extension = 0.0;  //!< EI / (E A_w L^2) = (r_g / L)^2: axial compliance
    double rotary = 0.0;     //!< rho_w I / ((M + m) L^2): rotary inertia of the wall section
    double areaChange = 0.0; //!< K / (A_i L^2) (A_i = pi Ri^2, the fluid's area A0)
    AreaPressure pressure = AreaPressure::Dynamic;
    //! The growth of the psi'^2 coefficient per u^2: K rho_f U^2 / (2 EI) = areaChange u^2 / 2 (dynamic), else 0.
    double areaStiffening() const { return pressure == AreaPressure::Dynamic ? 0.5 * areaChange : 0.0; }
};

const char* endName(EndCondition e);

//! The physical tube and fluid (SI units), when the scene gives them.
struct PhysicalTube
{
    double length = 1.0, outerRadius = 0.0, innerRadius = 0.0;
    double youngsModulus = 0.0, poissonRatio = 0.3, wallDensity = 0.0, shearCoefficient = 0.5;
    double fluidDensity = 0.0;
    double areaChange = 0.0; //!< K of A = A0 - K |Omega|^2 / 2 (m^2)
    AreaPressure areaPressure = AreaPressure::Dynamic;

    double wallArea() const;           //!< A_w = pi (Ro^2 - Ri^2)
    double secondMoment() const;       //!< I = pi (Ro^4 - Ri^4) / 4
    double radiusOfGyration() const;   //!< r_g = sqrt(I / A_w)
    double slenderness() const;        //!< L / r_g
    double shearModulus() const;       //!< G = E / (2 (1 + nu))
    double bendingStiffness() const;   //!< EI
    double fluidMassPerLength() const; //!< M = rho_f pi Ri^2
    double wallMassPerLength() const;  //!< m = rho_w pi (Ro^2 - Ri^2)
    double massRatio() const;          //!< beta = M / (M + m)
    double velocityScale() const;      //!< U = u sqrt(EI / M) / L
    double timeScale() const;          //!< t = tau L^2 sqrt((M + m) / EI)
    //! The geometric model's ratios of this tube (shear with the shear coefficient kappa, area change K).
    GeometricParameters geometricParameters() const;
};

//! The linear stability study (dimensionless, tube.md 2.1).
struct StabilityStudy
{
    std::vector<double> beta; //!< mass ratios, each in [0, 1)
    int elements = 40;        //!< finite elements along the tube
    int modes = 16;           //!< Galerkin on the lowest modes without flow (0: every element dof)
    double speedMax = 30.0;   //!< the scan for the first instability stops here (u)
    double speedStep = 0.02;  //!< scan step in u (an unstable window narrower than this can be missed)
    double tolerance = 1e-6;  //!< bisection width in u
    int locusModes = 4;       //!< modes in the Argand loci
    int locusPoints = 101;    //!< flow speeds in the loci, from 0 to locusSpeedFactor u_cf
    double locusSpeedFactor = 1.25;
};

struct TubeScene
{
    std::string file, name;
    TubeModel model = TubeModel::EulerBernoulli;
    bool hasPhysical = false; //!< the scene gave the physical tube
    PhysicalTube physical;
    EndCondition left = EndCondition::Clamped, right = EndCondition::Free; //!< flow enters at the left end
    StabilityStudy stability;
    bool hasDynamics = false;  //!< `dynamics:` given: a nonlinear time run instead of the stability study
    DynamicsSettings dynamics; //!< (needs the physical tube)
    bool hasGas = false;       //!< `gas:` given: the gas in a rigid tube (no `tube:`, `ends:`, `stability:`)
    GasSettings gas;
    bool hasArtery = false;    //!< `artery:` given: one 1D artery (likewise alone)
    ArterySettings artery;
    std::string outputDirectory;
    bool plot = true;                                 //!< write stability.png (apps/tube_stability_plot.py)
    bool progress = true;                             //!< a time run's progress line (the CLI's --quiet: false)
    std::shared_ptr<Teuchos::ParameterList> resolved; //!< the scene after --set, for scene.yaml
};

//! Read and validate a tube scene (top-level key `unilag:`), applying `--set` overrides. Throws InputError.
TubeScene readTubeScene(const std::string& file, const std::vector<std::string>& overrides);

/*! Whether the scene file is a tube scene (its `unilag:` section has a `tube:`, `gas:` or `artery:` section), for `unilag run` to
 *  dispatch it; false if the file cannot be read (the continuum reader then reports why). */
bool isTubeScene(const std::string& file);

/*! A tube's radii from node: outer_radius with inner_radius or wall_thickness (not both), inner < outer. Missing
 *  keys are input errors if required, NaN otherwise (the caller then names what is missing). Throws InputError. */
void readTubeRadii(config::ConfigNode& node, bool required, double& outer, double& inner);

//! Write the resolved scene as YAML.
void writeTubeScene(const TubeScene& scene, const std::string& file);

} // namespace unilag::tube
