#pragma once
// Small models for tests, written as model-file text so the reader is exercised too.

#include "Preprocess.hpp"

#include <string>
#include <vector>

namespace mcdda::test {

/// A valid 10 m x 10 m square of one material, fixed along its base, no joints.
std::string square_model_json();

/// A model of one elastic material "rock" (E = 2 GPa, ν = 0.3) and no plasticity, for tests of
/// element assembly on hand-made meshes.
Model elastic_model();

/// Preprocesses JSON text (with overrides) up to `last`.
Preprocessed preprocess_text(const std::string& json, const std::vector<std::string>& overrides = {},
                             PreprocessStage last = PreprocessStage::Mesh);

/// Path of an example model shipped in examples/.
std::string example_path(const std::string& file);

/// All example model files.
std::vector<std::string> example_files();

/// True when some diagnostic of `severity` has exactly `path` and contains `fragment`.
bool has_diagnostic(const std::vector<Diagnostic>& diagnostics, Diagnostic::Severity severity,
                    const std::string& path, const std::string& fragment);

/// All diagnostics joined, for failure messages.
std::string all_messages(const std::vector<Diagnostic>& diagnostics);

/// The square model with `overrides`, cut into blocks: "" when it is refused with an error at
/// `path` whose message holds `fragment`, otherwise what was expected and the messages it gave.
std::string refusal_mismatch(const std::vector<std::string>& overrides, const std::string& path,
                             const std::string& fragment);

}  // namespace mcdda::test
