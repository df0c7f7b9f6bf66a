#pragma once
// Running example models through the solver for validation tests.

#include "Preprocess.hpp"
#include "run/FactorOfSafety.hpp"
#include "run/Simulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcdda::test {

/// Time and the displacement of every measurement point after each accepted step.
struct History {
    std::vector<double> time;
    std::vector<std::vector<Point2>> points;  ///< [step][measurement point] (ux, uy)

    /// Linear interpolation of point `k`'s displacement at time `t`.
    Point2 at(double t, int k) const;
};

struct Run {
    Preprocessed model;
    std::unique_ptr<Simulation> simulation;
    History history;
};

/// Preprocesses examples/<file> with overrides and runs all its steps (or `steps` when > 0).
/// Fails the calling test (ADD_FAILURE) on any error.
Run run_example(const std::string& file, const std::vector<std::string>& overrides = {}, int steps = 0);

/// The same for model text.
Run run_text(const std::string& json, const std::vector<std::string>& overrides = {}, int steps = 0);

/// A static run loaded until it collapses: the collapse bracket and the load–settlement curve of
/// the first load (point load or edge pressure) and the first measurement point.
struct CollapseRun {
    bool collapsed = false;
    double carried = 0.0, not_carried = 0.0;  ///< magnitude of the first load at the bracket's ends
    std::vector<double> load, settlement;     ///< per accepted step: magnitude, −uy (m)
};

/// Runs examples/<file> with overrides step by step until PlasticCollapse or its last step.
CollapseRun run_to_collapse(const std::string& file, const std::vector<std::string>& overrides = {});

/// The strength reduction search of examples/<file> with overrides: its factor of safety. Fails
/// the calling test when the model is rejected, the search does not complete or finds no factor.
FactorOfSafety strength_reduction_of(const std::string& file, const std::vector<std::string>& overrides = {});

/// Centroid of element `e` in the current configuration.
Point2 centroid(const Simulation& s, int e);

}  // namespace mcdda::test
