#pragma once
/// \file StrengthReduction.hpp
/// The strengths of a model divided by a factor F, as the strength reduction method divides them
/// (Griffiths & Lane 1999; Dawson, Roth & Drescher 1999): c/F, atan(tan φ / F), tensile
/// strength / F, for every material and joint material that has `reduce` set; the dilation
/// angle is kept at most the reduced friction angle (ψ ≤ φ).

#include "model/Model.hpp"

namespace mcdda {

Material reduced_strength(const Material& m, double factor);
JointMaterial reduced_strength(const JointMaterial& j, double factor);

/// Every material and joint material of `model` with `reduce` set, divided by `factor`.
void reduce_strength(Model& model, double factor);

}  // namespace mcdda
