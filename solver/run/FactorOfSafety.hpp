#pragma once
/// \file FactorOfSafety.hpp
/// The result of a strength reduction search (run/StrengthReduction.hpp): its trials and the
/// bracket of the factor of safety.

#include <string>
#include <vector>

namespace mcdda {

/// One trial: the model (or its safety stage) solved with its strengths divided by `factor`.
struct StrengthTrial {
    int number = 0;            ///< 1, 2, … in the order they ran
    double factor = 0.0;
    bool stands = false;       ///< every step reached equilibrium
    std::string status;        ///< "stands", "collapsed", "unbalanced", "failed"
    std::string message;       ///< why it does not stand
    int steps = 0;             ///< steps of the trial completed
    int iterations = 0;        ///< equilibrium iterations of the trial
    double max_displacement = 0.0;  ///< largest nodal displacement of the trial's last state (m)
    double seconds = 0.0;      ///< wall time of the trial
};

struct FactorOfSafety {
    bool found = false;        ///< a bracket [stands, does not stand] within the tolerance was reached
    double value = 0.0;        ///< the largest factor at which the model stands
    double converged = 0.0;    ///< = value: the last factor that stood
    double not_converged = 0.0;  ///< the smallest factor tried at which it did not
    int trials = 0;
    /// How the reduced block materials flowed: "associated" (none has ψ < φ), else the model's
    /// non_associated_flow, "davis" or "direct".
    std::string non_associated_flow = "associated";
    std::vector<StrengthTrial> table;
};

}  // namespace mcdda
