#include "Commands.hpp"

#include "Preprocess.hpp"
#include "io/VtuWriter.hpp"
#include "check/ModelValidator.hpp"
#ifdef MCDDA_HAVE_VIEW
#include "view/OffscreenRender.hpp"
#include "view/ResultScene.hpp"
#endif

#include <chrono>
#include <filesystem>
#include <iostream>

namespace mcdda::cli {

namespace fs = std::filesystem;

namespace {

/// Prints diagnostics (warnings unless quiet) and returns whether there is any error.
bool report(const Preprocessed& p, const Request& r) {
    for (const Diagnostic& d : p.diagnostics) {
        if (d.severity == Diagnostic::Severity::Warning && r.quiet) continue;
        std::cerr << r.model << ": " << format_diagnostic(d) << "\n";
    }
    return has_errors(p.diagnostics);
}

void print_profile(const Preprocessed& p, double write_seconds) {
    std::cout << "timing (s): read " << p.seconds_read << ", validate " << p.seconds_validate << ", cut "
              << p.seconds_cut << ", mesh " << p.seconds_mesh << ", write " << write_seconds << ", total "
              << p.seconds_read + p.seconds_validate + p.seconds_cut + p.seconds_mesh + write_seconds << "\n";
    if (p.seconds_mesh > 0 && p.statistics.elements > 0)
        std::cout << "meshed " << p.statistics.elements << " triangles (" << p.statistics.nodes << " nodes, "
                  << p.statistics.blocks << " blocks) in " << p.seconds_mesh << " s: "
                  << static_cast<long>(p.statistics.elements / p.seconds_mesh) << " triangles/s\n";
}

std::string model_stem(const std::string& path) {
    const std::string stem = fs::path(path).stem().string();
    return stem.empty() ? "model" : stem;
}

bool ensure_directory(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
        std::cerr << "error: cannot create output directory " << dir << ": " << ec.message() << "\n";
        return false;
    }
    return true;
}

}  // namespace

int run_check(const Request& r) {
    const Preprocessed p = preprocess_file(r.model, r.overrides, PreprocessStage::Cut);
    if (report(p, r)) {
        std::size_t errors = 0;
        for (const Diagnostic& d : p.diagnostics) errors += d.severity == Diagnostic::Severity::Error;
        std::cerr << r.model << ": " << errors << (errors == 1 ? " error" : " errors") << "\n";
        return exit_model_error;
    }
    if (!r.quiet) {
        std::size_t generated = 0;
        for (const Joint& j : p.model.joints) generated += j.joint_set >= 0;
        double area = 0.0;
        for (const Block& b : p.blocks) area += b.area;
        std::cout << r.model << ": ok - " << p.model.regions.size() << " regions, " << p.model.materials.size()
                  << " materials, " << p.model.joints.size() << " joints (" << generated << " from joint sets), "
                  << p.blocks.size() << " blocks, block area " << area << " m2\n";
    }
    return exit_ok;
}

int run_mesh(const Request& r) {
    const Preprocessed p = preprocess_file(r.model, r.overrides, PreprocessStage::Mesh);
    if (report(p, r)) return exit_model_error;
    if (!ensure_directory(r.out)) return exit_output_error;
    const std::string path = (fs::path(r.out) / (model_stem(r.model) + ".vtu")).string();
    const auto start = std::chrono::steady_clock::now();
    try {
        write_vtu(path, p.mesh);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return exit_output_error;
    }
    const double write_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.quiet) std::cout << describe(p.statistics) << "wrote " << path << "\n";
    if (r.profile) print_profile(p, write_seconds);
    return exit_ok;
}

int run_render(const Request& r) {
#ifdef MCDDA_HAVE_VIEW
    const Preprocessed p = preprocess_file(r.model, r.overrides, PreprocessStage::Mesh);
    if (report(p, r)) return exit_model_error;
    const fs::path out(r.out);
    if (out.has_parent_path() && !ensure_directory(out.parent_path().string())) return exit_output_error;
    const auto start = std::chrono::steady_clock::now();
    try {
        if (r.results.empty()) {
            view::SceneOptions options;
            options.show_mesh = r.show_mesh;
            options.show_axes = r.show_axes;
            view::render_png(p, options, r.width, r.height, r.out);
        } else {
            view::ResultOptions options;
            options.field = r.field;
            options.deform = r.deform;
            options.deform_auto = r.deform_auto;
            options.contacts = r.contacts;
            if (r.compression_positive) options.stress_sign = view::StressSign::CompressionPositive;
            if (!r.colour_map.empty()) view::parse_colour_map(r.colour_map, &options.colour_map);
            options.bands = r.bands;
            if (r.range_min < r.range_max) options.range_min = r.range_min, options.range_max = r.range_max;
            options.show_axes = r.show_axes;
            options.title = r.title;
            view::ResultInfo info;
            view::render_result_png(p, r.results, options, r.width, r.height, r.out, &info);
            if (info.inverted_elements > 0)
                std::cerr << "warning: " << info.inverted_elements
                          << " element(s) drawn inside out at the deformation scale " << info.deform_factor
                          << ": the picture exaggerates too much; use a smaller --deform\n";
            if (options.deform_auto && !r.quiet)
                std::cout << "deformation drawn x" << info.deform_factor << " (largest displacement "
                          << info.max_displacement << " m)\n";
        }
    } catch (const view::ResultFieldError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return exit_model_error;
    } catch (const view::ResultFileError& e) {  // a result file refused: input, like a model
        std::cerr << "error: " << e.what() << "\n";
        return exit_model_error;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return exit_output_error;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.quiet) std::cout << "wrote " << r.out << " (" << r.width << "x" << r.height << ")\n";
    if (r.profile) print_profile(p, seconds);
    return exit_ok;
#else
    std::cerr << "error: this mcdda was built without the VTK views (MCDDA_BUILD_GUI=OFF); render is unavailable\n";
    return exit_usage;
#endif
}

}  // namespace mcdda::cli
