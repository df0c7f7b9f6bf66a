// Runs a model with the mcdda library and prints its progress and how it ended; a parameter
// study would loop over analysis.set({...}) and analysis.run().
//
//   incline MODEL.json [FRICTION_ANGLE_DEGREES]

#include <mcdda/Analysis.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " MODEL.json [JOINT_FRICTION_DEGREES]\n";
        return 2;
    }
    try {
        mcdda::Analysis analysis = mcdda::Analysis::from_file(argv[1]);
        if (argc > 2) analysis.set({std::string("/joint_materials/0/friction_angle=") + argv[2]});
        for (const mcdda::Diagnostic& d : analysis.mesh()) std::cerr << mcdda::format_diagnostic(d) << "\n";
        if (!analysis.ok()) return 1;
        const mcdda::MeshArrays mesh = analysis.mesh_arrays();
        std::cout << "mcdda " << mcdda::library_version() << ": " << mesh.node_count() << " nodes, "
                  << mesh.element_count() << " elements\n";

        mcdda::RunOptions options;
        options.keep_every = -1;  // only the last step's fields
        options.on_step = [](const mcdda::StepProgress& p) {
            std::cout << "step " << p.step << " of " << p.planned_steps << ": largest displacement "
                      << p.max_displacement << " m, unbalanced-force ratio " << p.unbalanced_ratio << "\n";
            return true;  // false would stop the run here
        };
        const mcdda::RunResult result = analysis.run(options);
        std::cout << result.status << " after " << result.steps << " steps (" << result.message << ")\n";
        return result.exit_code;
    } catch (const mcdda::ModelError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
}
