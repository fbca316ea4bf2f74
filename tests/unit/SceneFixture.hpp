/*! \file SceneFixture.hpp
 *  \brief The scene tests' helpers: inputs/sedov2d.yaml with absolute paths, material blocks, a temporary folder,
 *  and the InputError a call raises (test_scene.cpp, test_scene_errors.cpp). */
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "config/Scene.hpp"

namespace unilag_test
{


namespace fs = std::filesystem;

inline const std::string kSource = UNILAG_SOURCE_DIR;
inline const std::string kGeometry = kSource + "/inputs/geometry/quadrant2d.geo";
inline const std::string kTable = kSource + "/inputs/exact/sedov_cyl_gamma1.4_E0.244816quadrant_t1.csv";

//! text with the single occurrence of `from` replaced by `to` (fails the test if `from` is not there once).
inline std::string replaced(const std::string& text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos)
    {
        ADD_FAILURE() << "'" << from << "' does not occur exactly once in the scene";
        return text;
    }
    return text.substr(0, at) + to + text.substr(at + from.size());
}

//! inputs/sedov2d.yaml with absolute paths to the geometry and the exact table.
inline std::string sedovScene()
{
    const std::string text = R"(%YAML 1.1
---
unilag:
  title: sedov2d
  mesh:
    geometry: @GEOMETRY@
    size: 0.0144
  materials:
    gas: { eos: ideal_gas, gamma: 1.4 }
  regions:
    gas: { material: gas, density: 1.0, velocity: [0.0, 0.0], pressure: 1.0e-6 }
  energy_deposit: { position: [0.0, 0.0], energy: 0.244816 }
  boundaries:
    axis_x: { type: symmetry }
    axis_y: { type: symmetry }
    outer: { type: slip_wall }
  time: { end: 1.0, cfl: 0.5 }
  output: { directory: output/sedov2d, interval: 0.1 }
  exact:
    solution: sedov
    table: @TABLE@
    shock_radius: 0.9988
    shock_radius_tolerance: 0.03
...
)";
    return replaced(replaced(text, "@GEOMETRY@", kGeometry), "@TABLE@", kTable);
}

/*! sedovScene() with the material 'gas' given by `block`: its keys, one per line, indented by 6 spaces. The
 *  region still uses 'gas'; other materials can follow in the block at 4 spaces. */
inline std::string withMaterial(const std::string& block)
{
    return replaced(sedovScene(), "    gas: { eos: ideal_gas, gamma: 1.4 }\n", "    gas:\n" + block);
}

//! A beryllium-like elastoplastic solid (docs/gpr-model.md 3.6) as the material 'gas'.
inline const std::string kPlastic = R"(      eos: mie_gruneisen
      rho0: 1845
      c0: 8000
      Gamma0: 1.11
      s: 1.124
      cv: 1825
      shear_sound_speed: 9070
      strain_relaxation:
        law: plastic
        tau10: 1.0
        yield_stress: 3.3e8
        exponent: 20
)";

//! An ideal gas with the GPR hydrodynamic limit and heat conduction (docs/gpr-model.md 3.5) as the material 'gas'.
inline const std::string kHeat = R"(      eos: ideal_gas
      gamma: 1.4
      cv: 2.5
      shear_sound_speed: 1.0
      strain_relaxation: { law: constant, tau1: 1e-14 }
      heat_conduction:
        alpha: 2.0
        kappa: 1e-2
        reference_temperature: 1
)";

//! A fresh directory under the system temp folder for the current test, removed afterwards.
class TempDir
{
  public:
    TempDir()
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("unilag_unit_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir()
    {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string write(const std::string& name, const std::string& text) const
    {
        const fs::path p = path_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

inline bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

//! The message of the InputError that f throws ("" and a test failure if it throws nothing or something else).
template <class F> std::string inputError(F&& f)
{
    try
    {
        f();
    }
    catch (const unilag::InputError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "expected unilag::InputError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected unilag::InputError, nothing was thrown";
    return {};
}

//! Writes the scene text and returns readScene's InputError message; checks it names the file and the key.
inline std::string sceneError(const TempDir& dir, const std::string& text, const std::string& key,
                       const std::vector<std::string>& overrides = {})
{
    const std::string file = dir.write("scene.yaml", text);
    const std::string msg = inputError([&] { unilag::readScene(file, overrides); });
    EXPECT_PRED2(contains, msg, file);
    EXPECT_PRED2(contains, msg, "'" + key + "'");
    return msg;
}


} // namespace unilag_test
