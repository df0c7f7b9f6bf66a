#pragma once
/// \file StrengthReduction.hpp
/// The strengths of a model divided by a factor F, as the strength reduction method divides them
/// (Griffiths & Lane 1999; Dawson, Roth & Drescher 1999), for every material and joint material
/// that has `reduce` set. Joints: c/F, atan(tan φ / F), tensile strength / F. Materials: as
/// their law says (MaterialLaw::reduced) — for Mohr–Coulomb the same, with the dilation angle
/// kept at most the reduced friction angle (ψ ≤ φ).

#include "model/Model.hpp"

namespace mcdda {

/// `m` divided by `factor` as its law reduces it. With `flow` Davis, a Mohr–Coulomb material whose
/// dilation angle stays below its reduced friction angle gets Davis's associated equivalent of the
/// reduced strengths: β = cos ψ cos φ / (1 − sin ψ sin φ) of the reduced φ and ψ, c* = β c/F,
/// tan φ* = β tan φ/F, ψ* = φ* (the tensile strength, whose cut-off flows associated already,
/// stays σt/F). A material without `reduce`, or whose law has nothing to reduce, is returned as it is.
Material reduced_strength(const Material& m, double factor, AnalysisSettings::NonAssociatedFlow flow);
JointMaterial reduced_strength(const JointMaterial& j, double factor);

/// Davis's factor β = cos ψ cos φ / (1 − sin ψ sin φ) (1 for ψ = φ).
double davis_factor(double friction_angle, double dilation_angle);

/// Every material and joint material of `model` with `reduce` set, divided by `factor`, block
/// materials treated as the model's `analysis.non_associated_flow` says.
void reduce_strength(Model& model, double factor);

}  // namespace mcdda
