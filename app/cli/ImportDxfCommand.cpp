// `mcdda import-dxf DRAWING.dxf --out MODEL.json`: a model from a CAD drawing (io/DxfImport.hpp).
// The model is written even when it cannot run yet (no supports drawn): what `check` still
// finds is listed so the user knows what to add.

#include "Commands.hpp"

#include "Preprocess.hpp"
#include "io/DxfImport.hpp"
#include "io/ModelWriter.hpp"

#include <iostream>

namespace mcdda::cli {

int run_import_dxf(const Request& r) {
    DxfImportOptions options;
    options.metres_per_unit = r.units.empty() ? 0.0 : metres_per_unit_named(r.units);
    const DxfImportResult imported = import_dxf_file(r.model, options);
    for (const Diagnostic& d : imported.diagnostics) std::cerr << r.model << ": " << format_diagnostic(d) << "\n";
    if (!imported.model) return exit_model_error;
    try {
        write_model_file(r.out, *imported.model);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return exit_output_error;
    }
    if (!r.quiet) std::cout << r.model << ": " << imported.summary << "\nwrote " << r.out << "\n";
    // What the model still lacks (supports, overlapping regions …), for the user to add.
    const Preprocessed p = preprocess_model(*imported.model, PreprocessStage::Cut);
    for (const Diagnostic& d : p.diagnostics)
        std::cerr << r.out << ": still to do: " << format_diagnostic(d) << "\n";
    return exit_ok;
}

}  // namespace mcdda::cli
