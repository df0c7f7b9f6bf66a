#pragma once
/// \file Preprocess.hpp
/// The pre-processing pipeline every front end uses: read → validate → cut blocks → mesh.

#include "geometry/Block.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/MeshStatistics.hpp"
#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <string>
#include <vector>

namespace mcdda {

/// Everything pre-processing produces. `ok` is false as soon as any error diagnostic exists;
/// later stages are then skipped and their members stay empty.
struct Preprocessed {
    Model model;
    std::vector<Block> blocks;
    Mesh mesh;
    MeshStatistics statistics;
    std::vector<Diagnostic> diagnostics;
    bool ok = false;
    /// Seconds spent in each stage (read, validate, cut, mesh).
    double seconds_read = 0, seconds_validate = 0, seconds_cut = 0, seconds_mesh = 0;
};

enum class PreprocessStage { Validate, Cut, Mesh };

/// Reads a model file, applies `--set` overrides (JSON pointer = value), validates it and runs
/// the pipeline up to `last`. Never throws for bad input: problems become diagnostics.
Preprocessed preprocess_file(const std::string& path, const std::vector<std::string>& overrides,
                             PreprocessStage last = PreprocessStage::Mesh);

/// The same for an already-read model (e.g. the GUI's document).
Preprocessed preprocess_model(const Model& model, PreprocessStage last = PreprocessStage::Mesh);

}  // namespace mcdda
