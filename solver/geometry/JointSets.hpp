#pragma once
/// \file JointSets.hpp
/// Expands joint sets (orientation, spacing, origin, extent) into individual joint traces.

#include "model/Model.hpp"

namespace mcdda {

/// Removes previously generated joints from `model.joints` and appends one straight trace per
/// set and spacing, clipped to the set's extent (default: the model's box). Explicit joints keep
/// their indices, so "/joints/i" stays valid.
void expand_joint_sets(Model& model);

}  // namespace mcdda
