// mcdda: the headless command line. Sample runs:
//   mcdda check examples/jointed-tunnel.json
//   mcdda mesh examples/kirsch.json --out out/ --set /mesh/size=0.2
//   mcdda render examples/jointed-tunnel.json --out out/jointed-tunnel.png

#include "CommandLine.hpp"
#include "Commands.hpp"
#include "VirtualDisplay.hpp"
#include "Version.hpp"
#include "linalg/BlasInfo.hpp"
#include "linalg/FreedMemoryReuse.hpp"

#include <iostream>

int main(int argc, char** argv) {
    using namespace mcdda::cli;
    mcdda::reuse_freed_memory();  // before any thread starts
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::string error;
    const auto request = parse_command_line(args, error);
    if (!request) {
        std::cerr << "mcdda: " << error << "\nTry 'mcdda --help'.\n";
        return exit_usage;
    }
    if (request->help) {
        std::cout << usage_text();
        return exit_ok;
    }
    if (request->version) {
        std::cout << "mcdda " << mcdda::version_string << " (model format " << mcdda::model_format_name << " "
                  << mcdda::model_format_version << ")\n"
                  << "BLAS: " << mcdda::blas_in_use() << "\n";
        return exit_ok;
    }
    try {
        if (request->command == "check") return run_check(*request);
        if (request->command == "mesh") return run_mesh(*request);
        if (request->command == "run") return run_run(*request);
        if (request->command == "study") return run_study(*request);
        if (request->command == "import-dxf") return run_import_dxf(*request);
        if (request->command == "render") {
            int status = 0;
            switch (ensure_display(args, status, error)) {
            case DisplayOutcome::present: return run_render(*request);
            case DisplayOutcome::rerun: return status;
            case DisplayOutcome::unavailable: break;
            }
            std::cerr << "mcdda render: " << error << "\n";
            return exit_output_error;
        }
    } catch (const std::exception& e) {
        std::cerr << "mcdda: unexpected failure: " << e.what() << "\n";
        return exit_output_error;
    }
    return exit_usage;
}
