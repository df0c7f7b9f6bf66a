#pragma once
/// \file ResultSnapshot.hpp
/// One moment of a run, copied out of the solver's state on the worker thread and handed to the
/// GUI thread as std::shared_ptr<const ResultSnapshot> (docs/architecture.md, platform facts): plain data, no Qt, no VTK.
/// Node and element order are those of the run's mesh (Preprocessed::mesh).

#include <array>
#include <vector>

namespace mcdda {

class Simulation;

struct ResultSnapshot {
    int step = 0;         ///< accepted steps so far
    int total_steps = 0;  ///< steps the analysis asks for
    double time = 0.0;    ///< s
    int stage = 1;        ///< construction stage of the last step, 1-based as in the result files
    std::vector<double> displacement;         ///< m, 2 per node (ux, uy), since the start
    /// Pa, per element (xx, yy, zz, xy), tension positive: the total stress, as in the files.
    std::vector<std::array<double, 4>> stress;
    /// With ground water (empty without): the effective stress the solver works with, σ′ = σ + u,
    /// and the pore pressure u (Pa, compression positive), per element.
    std::vector<std::array<double, 4>> effective_stress;
    std::vector<double> pore_pressure;
    std::vector<double> plastic_strain;       ///< per element, accumulated equivalent
    std::vector<unsigned char> plastic_state;  ///< per element: 0 never, 1 earlier, 2 yielding now
    std::vector<unsigned char> present;  ///< per element, 0 when excavated or not yet built (empty: all present)

    /// The current state of `simulation`.
    static ResultSnapshot of(const Simulation& simulation);
};

}  // namespace mcdda
