#include "Preprocess.hpp"

#include "fem/BoundaryConditions.hpp"
#include "geometry/BlockCutter.hpp"
#include "geometry/BlockFeatures.hpp"
#include "geometry/JointSets.hpp"
#include "geometry/PolygonChecks.hpp"
#include "io/ModelReader.hpp"
#include "mesh/BlockMesher.hpp"
#include "mesh/QuadraticMesh.hpp"
#include "check/ModelValidator.hpp"

#include <chrono>
#include <exception>

namespace mcdda {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run_pipeline(Preprocessed& p, PreprocessStage last) {
    using clock = std::chrono::steady_clock;
    try {
        auto t = clock::now();
        expand_joint_sets(p.model);
        validate_model(p.model, p.diagnostics);
        if (!has_errors(p.diagnostics)) check_region_rings(p.model, p.diagnostics);
        p.seconds_validate = seconds_since(t);
        if (has_errors(p.diagnostics) || last == PreprocessStage::Validate) {
            p.ok = !has_errors(p.diagnostics);
            return;
        }
        t = clock::now();
        p.blocks = cut_blocks(p.model, p.diagnostics);
        p.seconds_cut = seconds_since(t);
        if (!has_errors(p.diagnostics) && p.blocks.empty())
            p.diagnostics.push_back({Diagnostic::Severity::Error, "/regions", "the regions form no block"});
        // What the run would refuse, refused here already (so `mcdda check` does).
        if (!has_errors(p.diagnostics)) check_block_features(p.model, p.blocks, p.diagnostics);
        if (!has_errors(p.diagnostics)) check_supports_on_blocks(p.model, p.blocks, p.diagnostics);
        if (has_errors(p.diagnostics) || last != PreprocessStage::Mesh) {
            p.ok = !has_errors(p.diagnostics);
            return;
        }
        t = clock::now();
        p.mesh = mesh_blocks(p.model, p.blocks, p.diagnostics);
        if (!has_errors(p.diagnostics) && p.model.element() == ElementType::T6) add_midside_nodes(p.mesh);
        p.statistics = compute_statistics(p.mesh, p.blocks);
        p.seconds_mesh = seconds_since(t);
        p.ok = !has_errors(p.diagnostics);
    } catch (const std::exception& e) {
        // Geometry libraries signal impossible input by exceptions; never let them escape.
        p.diagnostics.push_back({Diagnostic::Severity::Error, "", std::string("internal failure: ") + e.what()});
        p.ok = false;
    }
}

}  // namespace

Preprocessed preprocess_file(const std::string& path, const std::vector<std::string>& overrides,
                             PreprocessStage last) {
    Preprocessed p;
    const auto start = std::chrono::steady_clock::now();
    ReadResult read = read_model_file(path, overrides);
    p.seconds_read = seconds_since(start);
    p.diagnostics = std::move(read.diagnostics);
    if (!read.model) return p;
    p.model = std::move(*read.model);
    run_pipeline(p, last);
    return p;
}

Preprocessed preprocess_model(const Model& model, PreprocessStage last) {
    Preprocessed p;
    p.model = model;
    run_pipeline(p, last);
    return p;
}

}  // namespace mcdda
