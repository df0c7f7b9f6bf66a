#pragma once
/// \file ModelValidator.hpp
/// Checks a Model for values a user can get wrong: impossible material constants, empty or
/// degenerate items, a model with nothing fixed. Each problem names its JSON pointer.
/// Topology that needs exact geometry (self-intersection, overlaps, joints outside every region)
/// is checked by PolygonChecks and the block cutter.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <vector>

namespace mcdda {

/// Appends the problems of `model` to `diagnostics`.
void validate_model(const Model& model, std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda
