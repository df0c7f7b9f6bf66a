#include "TestModels.hpp"

#include "io/ModelReader.hpp"

#include <algorithm>
#include <filesystem>

namespace mcdda::test {

Model elastic_model() {
    Model model;
    Material rock;
    rock.name = "rock";
    rock.young_modulus = 2e9;
    rock.poisson_ratio = 0.3;
    rock.law = "elastic";
    model.materials.push_back(rock);
    model.analysis.plasticity = false;
    return model;
}

std::string square_model_json() {
    return R"({
  "format": "mcdda-model", "version": 1, "name": "square",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500,
                   "cohesion": 1e6, "friction_angle": 30, "dilation_angle": 0 } ],
  "joint_materials": [ { "name": "joint", "friction_angle": 30 } ],
  "regions": [ { "name": "square", "material": "rock", "boundary": [[0,0],[10,0],[10,10],[0,10]] } ],
  "joints": [],
  "rollers": [ { "name": "base", "from": [0,0], "to": [10,0], "fixed": "xy" } ],
  "mesh": { "size": 1.0, "min_angle": 30 }
})";
}

Preprocessed preprocess_text(const std::string& json, const std::vector<std::string>& overrides,
                             PreprocessStage last) {
    ReadResult read = read_model_text(json, overrides);
    if (!read.model) {
        Preprocessed p;
        p.diagnostics = read.diagnostics;
        return p;
    }
    Preprocessed p = preprocess_model(*read.model, last);
    p.diagnostics.insert(p.diagnostics.begin(), read.diagnostics.begin(), read.diagnostics.end());
    return p;
}

std::string example_path(const std::string& file) { return std::string(MCDDA_EXAMPLES_DIR) + "/" + file; }

std::vector<std::string> example_files() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(MCDDA_EXAMPLES_DIR))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::string refusal_mismatch(const std::vector<std::string>& overrides, const std::string& path,
                             const std::string& fragment) {
    const Preprocessed p = preprocess_text(square_model_json(), overrides, PreprocessStage::Cut);
    if (!p.ok && has_diagnostic(p.diagnostics, Diagnostic::Severity::Error, path, fragment)) return "";
    return "expected error at " + path + " containing \"" + fragment + "\", got:\n" + all_messages(p.diagnostics);
}

bool has_diagnostic(const std::vector<Diagnostic>& diagnostics, Diagnostic::Severity severity,
                    const std::string& path, const std::string& fragment) {
    return std::any_of(diagnostics.begin(), diagnostics.end(), [&](const Diagnostic& d) {
        return d.severity == severity && d.path == path && d.message.find(fragment) != std::string::npos;
    });
}

std::string all_messages(const std::vector<Diagnostic>& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics) text += format_diagnostic(d) + "\n";
    return text.empty() ? "(no diagnostics)" : text;
}

}  // namespace mcdda::test
