#pragma once
/// \file ModelWriter.hpp
/// Writes a Model as a model file (format "mcdda-model", version 1; docs/model-format.md), the
/// inverse of ModelReader: angles back to degrees, in-situ stress and pressures back to
/// compressive magnitudes, references by name, joint sets as sets (the joints expanded from
/// them are not written). Reading the text again gives the same Model (doubles are written
/// with the shortest representation that round-trips exactly; angles may differ in the last
/// bits from the degree ↔ radian conversion).
///
/// Arcs and circles of the original file are written as their vertices (the Model keeps only
/// the vertices), and a unit weight as the equivalent `density`.

#include "model/Model.hpp"

#include <string>

namespace mcdda {

/// The model file's text (JSON, two-space indentation, points on one line, newline at the end).
std::string write_model_text(const Model& model);

/// Writes the model file to `path` atomically (a temporary beside it, renamed when complete):
/// a failure never leaves a half-written file. Throws std::runtime_error naming the file.
void write_model_file(const std::string& path, const Model& model);

}  // namespace mcdda
