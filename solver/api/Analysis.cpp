#include "mcdda/Analysis.hpp"

#include "fem/MeshTopology.hpp"

#include "Preprocess.hpp"
#include "Version.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"
#include "parallel/ParallelFor.hpp"
#include "run/RunLoop.hpp"
#include "run/RunOutput.hpp"
#include "run/Simulation.hpp"
#include "run/StrengthReduction.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>

namespace mcdda {

namespace {

/// The problems as one message, a line each.
std::string message_of(const std::string& what, const std::vector<Diagnostic>& diagnostics)
{
    std::string text = what;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error) text += "\n" + format_diagnostic(d);
    return text;
}

Model model_or_throw(const ReadResult& r, const std::string& what)
{
    if (!r.model || has_errors(r.diagnostics)) throw ModelError(message_of(what, r.diagnostics), r.diagnostics);
    return *r.model;
}

double largest_displacement(const SimulationState& s)
{
    double largest = 0.0;
    for (Eigen::Index i = 0; i + 1 < s.displacement.size(); i += 2)
        largest = std::max(largest, std::hypot(s.displacement[i], s.displacement[i + 1]));
    return largest;
}

HistoryRow history_row(const StepReport& report, const Simulation& simulation)
{
    const SimulationState& s = simulation.state();
    HistoryRow row;
    row.step = report.step;
    row.stage = report.stage + 1;
    row.time = report.time;
    row.unbalanced_ratio = report.unbalanced_ratio;
    row.max_displacement = largest_displacement(s);
    row.yielding = report.yielding;
    row.iterations = report.plastic_iterations;
    const Simulation::BaseState base = simulation.base_state(s.time);
    const Eigen::Vector2d frame = simulation.relative_to_base() ? base.acceleration : Eigen::Vector2d::Zero();
    const Eigen::VectorXd u = s.reported_displacement();
    for (int node : simulation.boundary_conditions().measurement_nodes) {
        const Eigen::Index x = 2 * node;
        row.points.push_back({u[x], u[x + 1], s.velocity[x], s.velocity[x + 1], s.acceleration[x] + frame.x(),
                              s.acceleration[x + 1] + frame.y()});
    }
    row.base = {base.displacement.x(), base.displacement.y(), base.velocity.x(), base.velocity.y(), base.acceleration.x(),
                base.acceleration.y()};
    return row;
}

StepProgress progress_of(const HistoryRow& row, const Simulation& simulation)
{
    return {row.step, simulation.planned_steps(), row.stage, row.time, row.unbalanced_ratio, row.max_displacement,
            row.yielding};
}

StepFields fields_of(const Simulation& simulation)
{
    const SimulationState& s = simulation.state();
    StepFields f;
    f.step = s.step;
    f.stage = s.stage + 1;
    f.time = s.time;
    f.displacement.assign(s.displacement.data(), s.displacement.data() + s.displacement.size());
    f.pore_pressure = simulation.pore_pressures();
    f.stress.reserve(4 * s.stress.size());
    f.effective_stress.reserve(4 * s.stress.size());
    for (std::size_t e = 0; e < s.stress.size(); ++e) {
        const double zz = e < s.stress_zz.size() ? s.stress_zz[e] : 0.0;
        const double u = f.pore_pressure[e];
        f.effective_stress.insert(f.effective_stress.end(), {s.stress[e][0], s.stress[e][1], zz, s.stress[e][2]});
        f.stress.insert(f.stress.end(), {s.stress[e][0] - u, s.stress[e][1] - u, zz - u, s.stress[e][2]});
    }
    f.plastic_strain = s.plastic_strain;
    f.plastic_state = s.plastic_state;
    return f;
}

}  // namespace

const char* library_version() { return version_string; }

struct Analysis::Impl {
    Model model;
    Preprocessed preprocessed;
    bool preprocessed_valid = false;            ///< preprocessed is of `model`
    PreprocessStage stage = PreprocessStage::Validate;
    std::vector<Diagnostic> read_diagnostics;  ///< warnings of reading the file
    /// The model file read (empty: from text): record files are named relative to its folder.
    std::string source = "model";
    std::vector<Diagnostic> diagnostics;
    std::atomic<bool> cancel{false};

    /// Preprocessing of the current model up to `last` (again only when the model changed or
    /// a later stage is asked for).
    const Preprocessed& prepare(PreprocessStage last)
    {
        if (!preprocessed_valid || static_cast<int>(stage) < static_cast<int>(last)) {
            preprocessed = preprocess_model(model, last);
            preprocessed_valid = true;
            stage = last;
            diagnostics = read_diagnostics;
            diagnostics.insert(diagnostics.end(), preprocessed.diagnostics.begin(), preprocessed.diagnostics.end());
        }
        return preprocessed;
    }

    void changed(Model m)
    {
        model = std::move(m);
        preprocessed_valid = false;
        read_diagnostics.clear();
        diagnostics.clear();
    }
};

Analysis::Analysis(Model model) : impl_(std::make_unique<Impl>()) { impl_->model = std::move(model); }
Analysis::Analysis(Analysis&&) noexcept = default;
Analysis& Analysis::operator=(Analysis&&) noexcept = default;
Analysis::~Analysis() = default;

Analysis Analysis::from_file(const std::string& path, const std::vector<std::string>& overrides)
{
    const ReadResult r = read_model_file(path, overrides);
    Analysis a(model_or_throw(r, path + ": the model cannot be read"));
    a.impl_->read_diagnostics = r.diagnostics;
    a.impl_->diagnostics = r.diagnostics;
    a.impl_->source = path;
    return a;
}

Analysis Analysis::from_text(const std::string& json, const std::vector<std::string>& overrides)
{
    const ReadResult r = read_model_text(json, overrides);
    Analysis a(model_or_throw(r, "the model cannot be read"));
    a.impl_->read_diagnostics = r.diagnostics;
    a.impl_->diagnostics = r.diagnostics;
    return a;
}

const Model& Analysis::model() const { return impl_->model; }

void Analysis::set_model(Model model) { impl_->changed(std::move(model)); }

void Analysis::set(const std::vector<std::string>& overrides)
{
    if (overrides.empty()) return;
    const ReadResult r = read_model_text(write_model_text(impl_->model), overrides, impl_->source);
    impl_->changed(model_or_throw(r, "the changes cannot be applied"));
}

std::string Analysis::to_json() const { return write_model_text(impl_->model); }

std::vector<Diagnostic> Analysis::check()
{
    impl_->prepare(PreprocessStage::Cut);
    return impl_->diagnostics;
}

std::vector<Diagnostic> Analysis::mesh()
{
    impl_->prepare(PreprocessStage::Mesh);
    return impl_->diagnostics;
}

bool Analysis::ok() const { return impl_->preprocessed_valid && impl_->preprocessed.ok; }

const std::vector<Diagnostic>& Analysis::diagnostics() const { return impl_->diagnostics; }

MeshArrays Analysis::mesh_arrays()
{
    const Preprocessed& p = impl_->prepare(PreprocessStage::Mesh);
    MeshArrays a;
    const Mesh& m = p.mesh;
    a.nodes.reserve(2 * m.nodes.size());
    for (const Point2& q : m.nodes) a.nodes.insert(a.nodes.end(), {q.x, q.y});
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        a.triangles.insert(a.triangles.end(), t.begin(), t.end());
        const int b = m.triangle_block[e];
        a.block.push_back(b);
        a.region.push_back(b >= 0 && b < static_cast<int>(p.blocks.size()) ? p.blocks[static_cast<std::size_t>(b)].region : -1);
        a.material.push_back(e < m.triangle_material.size() ? m.triangle_material[e] : -1);
        const Point2 &p0 = m.nodes[static_cast<std::size_t>(t[0])], &p1 = m.nodes[static_cast<std::size_t>(t[1])],
                     &p2 = m.nodes[static_cast<std::size_t>(t[2])];
        a.area.push_back(0.5 * ((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y)));
    }
    if (std::any_of(p.blocks.begin(), p.blocks.end(), [](const Block& b) { return !b.cracks.empty(); }))
        for (const BoundaryEdge& e : build_topology(m, p.blocks).edges)
            if (e.crack) {
                a.crack_faces.insert(a.crack_faces.end(), {e.from, e.to});
                a.crack_face_joint.push_back(e.joint);
            }
    return a;
}

RunResult Analysis::run(const RunOptions& options)
{
    const auto started = std::chrono::steady_clock::now();
    const Preprocessed& p = impl_->prepare(PreprocessStage::Mesh);
    if (!p.ok) throw ModelError(message_of("the model has errors", impl_->diagnostics), impl_->diagnostics);
    if (options.threads > 0) set_thread_count(options.threads);
    impl_->cancel = false;
    if (is_strength_reduction(p.model)) return run_strength_reduction(options);

    std::unique_ptr<Simulation> owned;
    try {
        owned = std::make_unique<Simulation>(p);
    } catch (const std::exception& e) {  // a model the solver cannot set up
        throw ModelError(e.what(), {});
    }
    Simulation& simulation = *owned;
    std::unique_ptr<RunOutput> output;
    if (!options.output_folder.empty())
        output = std::make_unique<RunOutput>(options.output_folder, options.name.empty() ? "model" : options.name);

    RunResult result;
    const int keep_every = options.keep_every != 0 ? options.keep_every : std::max(1, p.model.analysis.output_every);
    bool stopped_by_callback = false;
    auto on_step = [&](const StepReport& report) {
        result.history.push_back(history_row(report, simulation));
        if (keep_every > 0 && report.step % keep_every == 0) result.saved.push_back(fields_of(simulation));
        if (options.on_step && !options.on_step(progress_of(result.history.back(), simulation)))
            stopped_by_callback = true;
    };
    const RunEnd end = run_steps(simulation, output.get(),
                                 [&] { return stopped_by_callback || impl_->cancel.load(); }, on_step);
    if (output) output->write_summary(&simulation, end.status, end.message);

    const SimulationState& s = simulation.state();
    if (result.saved.empty() || result.saved.back().step != s.step) result.saved.push_back(fields_of(simulation));
    result.status = status_name(end.status);
    result.message = end.message;
    result.exit_code = exit_status(end.status);
    result.steps = s.step;
    result.time = s.time;
    result.unbalanced_ratio = s.unbalanced_ratio;
    result.collapse_carried = end.collapse_carried;
    result.collapse_not_carried = end.collapse_not_carried;
    if (simulation.full_model().base_motion.present()) {
        result.shaken = true;
        const Eigen::VectorXd u = simulation.displacement_since_shaking();
        for (Eigen::Index n = 0; 2 * n + 1 < u.size(); ++n)
            result.permanent_displacement = std::max(result.permanent_displacement, std::hypot(u[2 * n], u[2 * n + 1]));
        for (int node : simulation.boundary_conditions().measurement_nodes)
            result.permanent_displacement_points.push_back({u[2 * node], u[2 * node + 1]});
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

RunResult Analysis::run_strength_reduction(const RunOptions& options)
{
    const auto started = std::chrono::steady_clock::now();
    const Preprocessed& p = impl_->prepare(PreprocessStage::Mesh);
    std::unique_ptr<StrengthReductionSearch> search;
    try {
        search = std::make_unique<StrengthReductionSearch>(p);
    } catch (const std::exception& e) {
        throw ModelError(e.what(), {});
    }
    std::unique_ptr<RunOutput> output;
    if (!options.output_folder.empty())
        output = std::make_unique<RunOutput>(options.output_folder, options.name.empty() ? "model" : options.name);
    RunResult result;
    bool stopped_by_callback = false;
    StrengthReductionSearch::Callbacks callbacks;
    callbacks.should_stop = [&] { return stopped_by_callback || impl_->cancel.load(); };
    callbacks.on_step = [&](const StepReport& report) {  // the construction stages
        result.history.push_back(history_row(report, search->simulation()));
        if (options.on_step && !options.on_step(progress_of(result.history.back(), search->simulation())))
            stopped_by_callback = true;
    };
    const RunEnd end = search->run(output.get(), callbacks);
    const FactorOfSafety& f = search->factor();
    if (output) output->write_summary(&search->simulation(), end.status, end.message, &f);

    result.status = status_name(end.status);
    result.message = end.message;
    result.exit_code = exit_status(end.status);
    result.steps = search->simulation().state().step;
    result.time = search->simulation().state().time;
    result.unbalanced_ratio = search->simulation().state().unbalanced_ratio;
    result.saved.push_back(fields_of(search->simulation()));
    result.strength_reduction = true;
    result.factor_found = f.found;
    result.factor_of_safety = f.value;
    result.factor_converged = f.converged;
    result.factor_not_converged = f.not_converged;
    result.non_associated_flow = f.non_associated_flow;
    for (const StrengthTrial& t : f.table)
        result.trials.push_back({t.number, t.factor, t.stands, t.status, t.message, t.steps, t.iterations,
                                 t.max_displacement});
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

void Analysis::cancel() { impl_->cancel = true; }

}  // namespace mcdda
