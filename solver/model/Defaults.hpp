#pragma once
/// \file Defaults.hpp
/// The constants and default values that the reader, the writer, the validator and the desktop
/// program's forms share, declared once: π, degrees, the standard gravity that turns a unit
/// weight into a density, the largest physical values, and the materials of a new model.

#include "model/Model.hpp"

#include <string>

namespace mcdda {

constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.0;
/// m/s²: a unit weight γ is read as a density γ / g, and gravity's standard magnitude.
constexpr double standard_gravity = 9.81;

// Beyond these a value is no physical input but a typo or a unit error; the solver would spend
// minutes on it or overflow. The pressure at the Earth's centre is 3.6e11 Pa, the stiffest solid
// (diamond) has E ≈ 1.2e12 Pa, the densest metal 22,600 kg/m³, and geotechnical centrifuges spin
// at up to a few hundred g.
constexpr double max_stress = 1e12;   ///< Pa: strengths, pressures, in-situ stresses
constexpr double max_modulus = 1e14;  ///< Pa: leaves room for "rigid" footings and plates
constexpr double max_density = 1e5;   ///< kg/m³
constexpr double max_gravity = 1e4;   ///< m/s², about 1,000 g

/// A new model's rock: E 10 GPa, ν 0.25, unit weight 25.5 kN/m³ (typed as such, not 25.506),
/// c 1 MPa, φ 35°, ψ 0°.
Material default_rock(const std::string& name);
/// A new model's joints: φj 30°, no cohesion or tension, automatic stiffness.
JointMaterial default_joint(const std::string& name);
/// An empty model holding those two materials, standard gravity and a static analysis of 20
/// load steps of 1 s.
Model new_model(const std::string& rock_name, const std::string& joint_name);

}  // namespace mcdda
