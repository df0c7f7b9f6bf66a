#pragma once
/// \file Defaults.hpp
/// The constants and default values that the reader, the writer, the validator and the desktop
/// program's forms share, declared once: π, degrees, the standard gravity that turns a unit
/// weight into a density, and the materials of a new model.

#include "model/Model.hpp"

#include <string>

namespace mcdda {

constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.0;
/// m/s²: a unit weight γ is read as a density γ / g, and gravity's standard magnitude.
constexpr double standard_gravity = 9.81;

/// A new model's rock: E 10 GPa, ν 0.25, unit weight 25.5 kN/m³ (typed as such, not 25.506),
/// c 1 MPa, φ 35°, ψ 0°.
Material default_rock(const std::string& name);
/// A new model's joints: φj 30°, no cohesion or tension, automatic stiffness.
JointMaterial default_joint(const std::string& name);
/// An empty model holding those two materials, standard gravity and a static analysis of 20
/// load steps of 1 s.
Model new_model(const std::string& rock_name, const std::string& joint_name);

}  // namespace mcdda
