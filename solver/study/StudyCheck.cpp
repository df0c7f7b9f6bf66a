#include "study/StudyCheck.hpp"

#include "Preprocess.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

namespace mcdda {

namespace {

/// A name as a token of a JSON pointer: ~ → ~0, / → ~1.
std::string token(const std::string& name)
{
    std::string t;
    for (char c : name) t += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return t;
}

std::vector<std::string> split_pointer(const std::string& pointer)
{
    std::vector<std::string> tokens;
    std::size_t at = 1;
    while (at <= pointer.size()) {
        const std::size_t slash = pointer.find('/', at);
        const std::size_t end = slash == std::string::npos ? pointer.size() : slash;
        tokens.push_back(pointer.substr(at, end - at));
        at = end + 1;
    }
    return tokens;
}

/// Whether `pointer` is one of `pattern`'s: "<i>" takes an array index below `bound`.
bool matches(const std::string& pointer, const std::string& pattern, std::size_t bound)
{
    if (pointer.empty() || pointer[0] != '/') return false;
    const std::vector<std::string> got = split_pointer(pointer), want = split_pointer(pattern);
    if (got.size() != want.size()) return false;
    for (std::size_t k = 0; k < got.size(); ++k) {
        if (want[k] != "<i>") {
            if (got[k] != want[k]) return false;
            continue;
        }
        const std::string& i = got[k];
        if (i.empty() || i.size() > 9 || i.find_first_not_of("0123456789") != std::string::npos ||
            (i.size() > 1 && i[0] == '0') || std::stoul(i) >= bound)
            return false;
    }
    return true;
}

/// The summary patterns with the bound of their index (0 when they have none).
std::vector<std::pair<std::string, std::size_t>> summary_patterns(const Model& model)
{
    std::vector<std::pair<std::string, std::size_t>> p;
    for (const char* key : {"steps", "time", "saved_steps", "unbalanced_ratio", "equilibrium_ratio", "plastic_area",
                            "max_displacement", "factorizations", "symbolic_analyses", "threads"})
        p.push_back({std::string("/") + key, 0});
    const std::size_t stages = std::max<std::size_t>(1, model.stages.size());
    for (const char* key : {"first_step", "last_step", "planned_steps", "unbalanced_ratio"})
        p.push_back({std::string("/stages/<i>/") + key, stages});
    if (!model.bolts.empty()) p.push_back({"/bolts/<i>/force", model.bolts.size()});
    for (const char* key : {"assembly", "factorization", "solve", "contact", "plasticity", "total"})
        p.push_back({std::string("/timing/") + key, 0});
    for (const char* key : {"matrices", "iterations"}) p.push_back({std::string("/reused_factors/") + key, 0});
    for (const char* key : {"total", "per_step", "max_per_step", "load_cuts", "steps_at_rest"})
        p.push_back({std::string("/iterations/") + key, 0});
    for (const char* key : {"nodes", "elements", "blocks"}) p.push_back({std::string("/model/") + key, 0});
    for (const char* side : {"carried", "not_carried"}) {
        p.push_back({std::string("/collapse/") + side + "/step", 0});
        const std::string loads = std::string("/collapse/") + side + "/loads/";
        for (const PointLoad& l : model.point_loads) p.push_back({loads + token(l.name), 0});
        for (const EdgePressure& l : model.edge_pressures) p.push_back({loads + token(l.name), 0});
    }
    if (model.base_motion.present()) {
        for (const char* key : {"largest", "at/0", "at/1"})
            p.push_back({std::string("/permanent_displacement/") + key, 0});
        for (const MeasurementPoint& m : model.measurement_points)
            for (const char* axis : {"0", "1"})
                p.push_back({"/permanent_displacement/points/" + token(m.name) + "/" + axis, 0});
    }
    const AnalysisSettings& last = model.stages.empty() ? model.analysis : model.stages.back().analysis;
    if (last.strength_reduction) {
        for (const char* key : {"value", "converged", "not_converged", "trials"})
            p.push_back({std::string("/factor_of_safety/") + key, 0});
        const auto trials = static_cast<std::size_t>(std::max(1, last.max_trials));
        for (const char* key : {"trial", "factor", "steps", "iterations", "max_displacement"})
            p.push_back({std::string("/factor_of_safety/table/<i>/") + key, trials});
    }
    return p;
}

/// Whether a parameter of `study` sets the displacement of roller `index`.
bool displacement_varied(const StudyDefinition& study, std::size_t index)
{
    const std::string path = "/rollers/" + std::to_string(index) + "/displacement";
    return std::any_of(study.parameters.begin(), study.parameters.end(),
                       [&](const StudyParameter& p) { return p.path.rfind(path, 0) == 0; });
}

std::string joined(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

/// "cu = 15000, E = 5e+06": the values of a run.
std::string values_of(const StudyDefinition& study, const StudyRun& run)
{
    std::string s;
    for (std::size_t k = 0; k < study.parameters.size() && k < run.values.size(); ++k) {
        char value[32];
        std::snprintf(value, sizeof value, "%.6g", run.values[k]);
        s += (s.empty() ? "" : ", ") + study.parameters[k].name + " = " + value;
    }
    return s;
}

}  // namespace

StudyOutputNames study_output_names(const Model& model, const StudyDefinition& study)
{
    StudyOutputNames names;
    for (const auto& [pattern, bound] : summary_patterns(model)) names.summary.push_back(pattern);
    const AnalysisSettings& last = model.stages.empty() ? model.analysis : model.stages.back().analysis;
    std::vector<std::string>& h = names.history;
    if (last.strength_reduction) {  // one row per trial (its status is a word, not a number)
        h = {"trial", "factor", "stands", "steps", "iterations", "max_displacement"};
        for (const MeasurementPoint& m : model.measurement_points) h.insert(h.end(), {m.name + ":ux", m.name + ":uy"});
        return names;
    }
    h = {"step", "time", "stage", "unbalanced_ratio"};
    for (const PointLoad& l : model.point_loads) h.push_back("load:" + l.name);
    for (const EdgePressure& l : model.edge_pressures) h.push_back("load:" + l.name);
    for (const MeasurementPoint& m : model.measurement_points) h.insert(h.end(), {m.name + ":ux", m.name + ":uy"});
    for (std::size_t i = 0; i < model.rollers.size(); ++i) {
        const Roller& r = model.rollers[i];
        if (r.moves() || displacement_varied(study, i))
            for (const char* c : {":ux", ":uy", ":fx", ":fy"}) h.push_back(r.name + c);
    }
    for (const Bolt& b : model.bolts) h.push_back(b.name + ":force");
    if (has_dynamic_stage(model))
        for (const MeasurementPoint& m : model.measurement_points)
            for (const char* c : {":vx", ":vy", ":ax", ":ay"}) h.push_back(m.name + c);
    if (model.base_motion.present())
        for (const char* c : {"base:ax", "base:ay", "base:vx", "base:vy", "base:ux", "base:uy"}) h.push_back(c);
    return names;
}

std::vector<Diagnostic> check_study_outputs(const StudyDefinition& study, const Model& model)
{
    std::vector<Diagnostic> problems;
    const auto patterns = summary_patterns(model);
    const StudyOutputNames names = study_output_names(model, study);
    for (std::size_t i = 0; i < study.outputs.size(); ++i) {
        const StudyOutput& o = study.outputs[i];
        const std::string path = "/outputs/" + std::to_string(i);
        const auto names_it = [&](const auto& p) { return matches(o.summary, p.first, p.second); };
        if (!o.summary.empty() && std::none_of(patterns.begin(), patterns.end(), names_it))
            problems.push_back({Diagnostic::Severity::Error, path + "/summary",
                                "summary.json of this model has no number at " + o.summary + " (it has " +
                                    joined(names.summary) + "; <i> an index from 0)"});
        const auto& columns = names.history;
        if (!o.history.empty() && std::find(columns.begin(), columns.end(), o.history) == columns.end())
            problems.push_back({Diagnostic::Severity::Error, path + "/history",
                                "history.csv of this model has no column \"" + o.history + "\" (it has " +
                                    joined(names.history) + ")"});
    }
    return problems;
}

StudyCheck check_study(const StudyDefinition& study, const std::vector<StudyRun>& runs)
{
    StudyCheck check;
    if (runs.empty()) return check;
    // Each run is started as `mcdda run MODEL --set …` (app/cli/StudyCommand.cpp): its settings
    // must fit a command line (Linux: 128 KiB for one argument, about 2 MB for all of them and
    // the environment), or the run cannot start at all.
    constexpr std::size_t longest_setting = 100000, longest_settings = 1000000;
    for (const StudyRun& run : runs) {
        std::size_t total = 0, longest = 0;
        for (const std::string& o : run.overrides) {
            total += o.size() + 7;  // "--set", the terminating NULs
            longest = std::max(longest, o.size());
        }
        if (total > longest_settings || longest > longest_setting) {
            check.study.push_back({Diagnostic::Severity::Error, "/set",
                                   "the " + std::to_string(run.overrides.size()) + " settings of run " +
                                       std::to_string(run.index) + " (" + std::to_string(total) +
                                       " bytes, the longest " + std::to_string(longest) +
                                       ") do not fit the command line that starts it (at most " +
                                       std::to_string(longest_settings) + " bytes, " +
                                       std::to_string(longest_setting) + " for one): put them in the model"});
            return check;
        }
    }
    const Preprocessed first = preprocess_file(study.model, runs.front().overrides, PreprocessStage::Validate);
    check.model = first.diagnostics;
    if (!first.ok) return check;
    // The runs that have a value of a parameter first: every value of a short list, the ends of
    // a long one.
    std::set<std::size_t> chosen;
    for (std::size_t k = 0; k < study.parameters.size(); ++k) {
        std::map<double, std::size_t> first_with;  // value → the first run that has it
        for (std::size_t r = 0; r < runs.size(); ++r)
            if (k < runs[r].values.size()) first_with.emplace(runs[r].values[k], r);
        if (first_with.size() <= 20) {
            for (const auto& [value, r] : first_with) chosen.insert(r);
        } else if (!first_with.empty()) {
            chosen.insert(first_with.begin()->second);
            chosen.insert(first_with.rbegin()->second);
        }
    }
    chosen.erase(0);
    std::set<std::pair<std::string, std::string>> said;  // one report of each problem
    for (std::size_t r : chosen) {
        const Preprocessed p = preprocess_file(study.model, runs[r].overrides, PreprocessStage::Validate);
        for (const Diagnostic& d : p.diagnostics)
            if (d.severity == Diagnostic::Severity::Error && said.insert({d.path, d.message}).second)
                check.model.push_back({d.severity, d.path,
                                       d.message + " (in run " + std::to_string(runs[r].index) + ": " +
                                           values_of(study, runs[r]) + ")"});
    }
    if (has_errors(check.model)) return check;
    check.study = check_study_outputs(study, first.model);
    check.ok = !has_errors(check.study);
    return check;
}

}  // namespace mcdda
