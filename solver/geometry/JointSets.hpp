#pragma once
/// \file JointSets.hpp
/// Expands joint sets (orientation, spacing, origin, extent, persistence) into individual joints.

#include "model/Model.hpp"

namespace mcdda {

/// Removes previously generated joints from `model.joints` and appends one straight trace per
/// set and spacing, clipped to the set's extent (default: the model's box); a set with
/// persistence < 1 gives the joint segments of each trace instead (see JointSet). Explicit joints
/// keep their indices, so "/joints/i" stays valid. Sets the validator refuses generate nothing.
void expand_joint_sets(Model& model);

}  // namespace mcdda
