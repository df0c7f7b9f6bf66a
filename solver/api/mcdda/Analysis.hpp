#pragma once
/// \file Analysis.hpp
/// The public interface of the mcdda solver library: load or build a model, change its fields,
/// check it, mesh it, run it with progress and cancellation, and read the results as plain
/// arrays. Installed as <mcdda/Analysis.hpp> with the model description it uses
/// (<mcdda/model/Model.hpp>, <mcdda/model/Diagnostic.hpp>); the solver's internals (the
/// simulation, its linear algebra, elements and material laws) stay behind it, so programs built
/// against it do not depend on them. docs/api.md shows a complete program.
///
/// Units are SI throughout (m, Pa, N/m per metre of model thickness, s, kg/m³), angles in
/// radians, stresses tension positive — the conventions of model/Model.hpp.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <array>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mcdda {

/// The library's version, e.g. "0.1.0".
const char* library_version();

/// A model that cannot be read at all (missing file, malformed JSON, missing required fields):
/// the message lists every problem with its place.
struct ModelError : std::runtime_error {
    ModelError(const std::string& what, std::vector<Diagnostic> problems)
        : std::runtime_error(what), diagnostics(std::move(problems)) {}
    std::vector<Diagnostic> diagnostics;
};

/// The mesh as arrays, in the node and element order of every result.
struct MeshArrays {
    std::vector<double> nodes;   ///< x, y of each node (m), 2 per node
    std::vector<int> triangles;  ///< corner nodes, 3 per element, counter-clockwise
    std::vector<int> block;      ///< block of each element
    std::vector<int> region;     ///< region of each element (index into Model::regions)
    std::vector<int> material;   ///< material of each element
    std::vector<double> area;    ///< area of each element (m²)
    /// The faces of the cracks inside blocks (joints that end in the rock): the nodes (from, to)
    /// of each boundary edge on one, 2 per edge, the block on its left (on six-node meshes an
    /// edge runs from a corner to a midside node or back); the two faces of a crack have
    /// separate nodes at the same places, except at its tips.
    std::vector<int> crack_faces;
    std::vector<int> crack_face_joint;  ///< joint of each crack face edge (index into Model::joints)
    int node_count() const { return static_cast<int>(nodes.size() / 2); }
    int element_count() const { return static_cast<int>(block.size()); }
};

/// The state after one step, per node and per element of MeshArrays.
struct StepFields {
    int step = 0;
    int stage = 1;  ///< 1-based construction stage
    double time = 0.0;
    std::vector<double> displacement;         ///< ux, uy per node (m), since the start
    std::vector<double> stress;               ///< σxx, σyy, σzz, τxy per element (Pa), tension positive, total
    /// σ′ = σ + u, the stress the material yields on (the same as `stress` without water).
    std::vector<double> effective_stress;
    std::vector<double> pore_pressure;        ///< u per element (Pa), compression positive; 0 when dry
    std::vector<double> plastic_strain;       ///< accumulated equivalent plastic strain per element
    std::vector<unsigned char> plastic_state; ///< per element: 0 never yielded, 1 earlier, 2 yielding now
};

/// One row per accepted step.
struct HistoryRow {
    int step = 0;
    int stage = 1;
    double time = 0.0;
    double unbalanced_ratio = 0.0;  ///< largest out-of-balance force over the largest applied force
    double max_displacement = 0.0;  ///< largest nodal displacement magnitude (m)
    int yielding = 0;               ///< elements yielding in the step
    int iterations = 0;             ///< equilibrium iterations of the step
    /// Per measurement point: displacement (m), velocity (m/s), acceleration (m/s²), x and y,
    /// as history.csv's columns (relative to a rigid base, accelerations absolute).
    struct PointMotion {
        double ux = 0.0, uy = 0.0, vx = 0.0, vy = 0.0, ax = 0.0, ay = 0.0;
    };
    std::vector<PointMotion> points;
    PointMotion base;  ///< the base motion's record as applied (zero without one)
};

/// What the progress callback hears after each accepted step.
struct StepProgress {
    int step = 0;
    int planned_steps = 0;
    int stage = 1;
    double time = 0.0;
    double unbalanced_ratio = 0.0;
    double max_displacement = 0.0;
    int yielding = 0;
};

struct RunOptions {
    /// A folder for the run's files (ParaView .pvd/.vtu, history.csv, summary.json; as
    /// `mcdda run`), or empty for none.
    std::string output_folder;
    /// Name of the files in output_folder ("model" when empty).
    std::string name;
    /// Keep the fields of every n-th step in memory (the last always); 0: the model's
    /// analysis.output_every; a negative number: only the last step.
    int keep_every = 0;
    /// Called after every accepted step, on the thread that called run(); returning false stops
    /// the run after that step (status "cancelled").
    std::function<bool(const StepProgress&)> on_step;
    /// Worker threads for element loops and contact search; 0: as many as cores.
    int threads = 0;
};

struct RunResult {
    /// "completed", "unbalanced" (every step ran, not in equilibrium), "collapsed", "failed" or
    /// "cancelled", and the exit code `mcdda run` would give (0, 3, 5, 4, 130).
    std::string status;
    std::string message;
    int exit_code = 0;
    int steps = 0;  ///< accepted steps
    double time = 0.0;
    double unbalanced_ratio = 0.0;
    /// For "collapsed": the load position (steps, fractional) last carried and the first not.
    double collapse_carried = 0.0, collapse_not_carried = 0.0;
    std::vector<HistoryRow> history;
    std::vector<StepFields> saved;  ///< fields kept (RunOptions::keep_every), the last step last
    /// With a base motion: summary.json's permanent_displacement — the largest (m) and each
    /// measurement point's (ux, uy) since the first dynamic stage began, relative to the base.
    bool shaken = false;
    double permanent_displacement = 0.0;
    std::vector<std::array<double, 2>> permanent_displacement_points;
    double seconds = 0.0;           ///< wall-clock time of the run

    /// A strength reduction analysis (the model's or its last stage's): the factor of safety,
    /// as summary.json's `factor_of_safety` (docs/running.md). `history` then holds the steps of
    /// the construction stages; the trials are here.
    struct StrengthTrial {
        int number = 0;
        double factor = 0.0;
        bool stands = false;
        std::string status;   ///< "stands", "collapsed", "unbalanced", "failed"
        std::string message;  ///< why it does not stand
        int steps = 0;
        int iterations = 0;
        double max_displacement = 0.0;  ///< m
    };
    bool strength_reduction = false;
    bool factor_found = false;          ///< the bracket reached the tolerance
    double factor_of_safety = 0.0;      ///< the largest factor that stood (= factor_converged)
    double factor_converged = 0.0;
    double factor_not_converged = 0.0;  ///< the smallest factor that did not stand
    /// "associated", "davis" or "direct": how reduced materials with ψ < φ were solved.
    std::string non_associated_flow = "associated";
    std::vector<StrengthTrial> trials;
};

/// One analysis: a model, its blocks and mesh once made, and its runs.
class Analysis {
public:
    /// Reads a model file and applies `--set`-style overrides ("/pointer=json value"). Throws
    /// ModelError when it cannot be read; warnings are kept in diagnostics().
    static Analysis from_file(const std::string& path, const std::vector<std::string>& overrides = {});
    /// The same for the text of a model file.
    static Analysis from_text(const std::string& json, const std::vector<std::string>& overrides = {});
    explicit Analysis(Model model);
    Analysis(Analysis&&) noexcept;
    Analysis& operator=(Analysis&&) noexcept;
    ~Analysis();

    const Model& model() const;
    /// Replaces the model (blocks and mesh are made again when needed).
    void set_model(Model model);
    /// Changes fields by JSON pointer as `mcdda run --set` does, e.g. "/materials/0/cohesion=2e5".
    /// Throws ModelError (the model unchanged) when an override cannot be applied.
    void set(const std::vector<std::string>& overrides);
    /// The model as the text of a model file.
    std::string to_json() const;

    /// Checks the model and cuts its blocks; the problems found (empty: none). check() and
    /// mesh() are also done by run() when needed.
    std::vector<Diagnostic> check();
    /// Checks, cuts and meshes; the problems found.
    std::vector<Diagnostic> mesh();
    /// True when the last check() or mesh() found no error.
    bool ok() const;
    /// The problems of reading, checking and meshing so far.
    const std::vector<Diagnostic>& diagnostics() const;
    /// The mesh (meshing first when needed; empty when the model has errors).
    MeshArrays mesh_arrays();

    /// Runs the analysis to its end (or a stop). Throws ModelError when the model has errors;
    /// solver failures and collapse are results, not exceptions. A strength reduction analysis
    /// runs its search: RunResult's factor_of_safety and trials.
    RunResult run(const RunOptions& options = {});
    /// Asks a run in progress (on another thread) to stop at its next equilibrium iteration (the
    /// step in progress is abandoned: the state is that of the last load increment accepted).
    void cancel();

private:
    RunResult run_strength_reduction(const RunOptions& options);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace mcdda
