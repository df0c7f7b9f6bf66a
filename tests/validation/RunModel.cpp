#include "RunModel.hpp"

#include "io/ModelReader.hpp"
#include "run/StrengthReduction.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace mcdda::test {

Point2 History::at(double t, int k) const {
    if (time.empty()) return {};
    if (t <= time.front()) return points.front()[k];
    for (std::size_t i = 1; i < time.size(); ++i)
        if (t <= time[i]) {
            const double w = (t - time[i - 1]) / (time[i] - time[i - 1]);
            const Point2 a = points[i - 1][k], b = points[i][k];
            return {a.x + w * (b.x - a.x), a.y + w * (b.y - a.y)};
        }
    return points.back()[k];
}

namespace {

Run run(Preprocessed p, int steps) {
    Run r;
    r.model = std::move(p);
    if (!r.model.ok) {
        std::string text;
        for (const Diagnostic& d : r.model.diagnostics) text += format_diagnostic(d) + "\n";
        ADD_FAILURE() << "model rejected:\n" << text;
        return r;
    }
    r.simulation = std::make_unique<Simulation>(r.model);
    const int total = steps > 0 ? steps : r.simulation->planned_steps();
    auto record = [&] {
        const SimulationState& s = r.simulation->state();
        r.history.time.push_back(s.time);
        std::vector<Point2> row;
        for (int node : r.simulation->boundary_conditions().measurement_nodes)
            row.push_back({s.displacement[2 * node], s.displacement[2 * node + 1]});
        r.history.points.push_back(row);
    };
    record();
    while (r.simulation->state().step < total && !r.simulation->finished()) {
        r.simulation->advance();
        record();
    }
    return r;
}

}  // namespace

Run run_example(const std::string& file, const std::vector<std::string>& overrides, int steps) {
    return run(preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/" + file, overrides), steps);
}

Run run_text(const std::string& json, const std::vector<std::string>& overrides, int steps) {
    ReadResult read = read_model_text(json, overrides);
    if (!read.model) {
        Preprocessed p;
        p.diagnostics = read.diagnostics;
        return run(std::move(p), steps);
    }
    return run(preprocess_model(*read.model), steps);
}

CollapseRun run_to_collapse(const std::string& file, const std::vector<std::string>& overrides) {
    const Preprocessed p = preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/" + file, overrides);
    CollapseRun r;
    if (!p.ok) {
        ADD_FAILURE() << file << " rejected";
        return r;
    }
    Simulation s(p);
    const int node = s.boundary_conditions().measurement_nodes.at(0);
    try {
        while (s.state().step < p.model.analysis.steps) {
            s.advance();
            r.load.push_back(s.load_magnitudes()[0].second);
            r.settlement.push_back(-s.state().displacement[2 * node + 1]);
        }
    } catch (const PlasticCollapse& e) {
        r.collapsed = true;
        r.carried = s.load_magnitudes_at(e.carried)[0].second;
        r.not_carried = s.load_magnitudes_at(e.not_carried)[0].second;
        std::cout << file << ": " << e.what() << "\n";
    }
    return r;
}

Point2 centroid(const Simulation& s, int e) {
    const auto& t = s.mesh().triangles[e];
    const auto& n = s.state().nodes;
    return {(n[t[0]].x + n[t[1]].x + n[t[2]].x) / 3.0, (n[t[0]].y + n[t[1]].y + n[t[2]].y) / 3.0};
}

FactorOfSafety strength_reduction_of(const std::string& file, const std::vector<std::string>& overrides) {
    const Preprocessed p = preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/" + file, overrides);
    EXPECT_TRUE(p.ok) << file << " rejected";
    if (!p.ok) return {};
    StrengthReductionSearch search(p);
    const RunEnd end = search.run(nullptr, {});
    EXPECT_EQ(end.status, RunStatus::Completed) << file << ": " << end.message;
    EXPECT_TRUE(search.factor().found) << file;
    return search.factor();
}

}  // namespace mcdda::test
