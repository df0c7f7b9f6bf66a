// Joint set expansion: fully persistent traces, and segments with rock bridges (persistence,
// trace length, stagger) at exactly the places docs/model-format.md describes.

#include "TestModels.hpp"
#include "geometry/JointSets.hpp"
#include "io/ModelReader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::square_model_json;

namespace {

/// The 10 m square with one joint set given as JSON, read and expanded.
Model expanded_square(const std::string& joint_set) {
    const ReadResult r = read_model_text(square_model_json(), {"/joint_sets=[" + joint_set + "]"});
    EXPECT_TRUE(r.model) << all_messages(r.diagnostics);
    Model m = r.model ? *r.model : Model{};
    expand_joint_sets(m);
    return m;
}

struct Segment {
    double x0, y0, x1, y1;
};

/// The generated joints, each a single straight piece, sorted by start point (x, then y).
std::vector<Segment> segments_of(const Model& m) {
    std::vector<Segment> out;
    for (const Joint& j : m.joints) {
        EXPECT_EQ(j.joint_set, 0);
        EXPECT_EQ(j.points.size(), 2u);
        if (j.points.size() == 2) out.push_back({j.points[0].x, j.points[0].y, j.points[1].x, j.points[1].y});
    }
    std::sort(out.begin(), out.end(), [](const Segment& a, const Segment& b) {
        return a.x0 != b.x0 ? a.x0 < b.x0 : a.y0 < b.y0;
    });
    return out;
}

void expect_segments(const std::vector<Segment>& actual, std::vector<Segment> expected) {
    std::sort(expected.begin(), expected.end(), [](const Segment& a, const Segment& b) {
        return a.x0 != b.x0 ? a.x0 < b.x0 : a.y0 < b.y0;
    });
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        SCOPED_TRACE("segment " + std::to_string(i));
        EXPECT_NEAR(actual[i].x0, expected[i].x0, 1e-9);
        EXPECT_NEAR(actual[i].y0, expected[i].y0, 1e-9);
        EXPECT_NEAR(actual[i].x1, expected[i].x1, 1e-9);
        EXPECT_NEAR(actual[i].y1, expected[i].y1, 1e-9);
    }
}

// Generated joints run 1e-6 of the box diagonal past the box, so they cross its edges.
const double margin = 1e-6 * std::hypot(10.0, 10.0);

}  // namespace

TEST(JointSets, PersistentSetGivesOneTracePerSpacing) {
    const Model m = expanded_square(R"({"name": "bedding", "angle": 0, "spacing": 2, "origin": [0, 1]})");
    std::vector<Segment> expected;
    for (double y : {1.0, 3.0, 5.0, 7.0, 9.0}) expected.push_back({-margin, y, 10.0 + margin, y});
    expect_segments(segments_of(m), expected);
    EXPECT_EQ(m.joints.front().name, "bedding #1");
    EXPECT_EQ(m.joints.back().name, "bedding #5");
}

TEST(JointSets, PersistenceOneIgnoresTraceLengthAndStagger) {
    const std::string base = R"("name": "s", "angle": 33, "spacing": 1.7, "origin": [2, 3])";
    const Model plain = expanded_square("{" + base + "}");
    const Model full = expanded_square("{" + base + R"(, "persistence": 1, "trace_length": 0.8, "stagger": 0.2})");
    ASSERT_GT(plain.joints.size(), 5u);
    ASSERT_EQ(full.joints.size(), plain.joints.size());
    for (std::size_t i = 0; i < plain.joints.size(); ++i) {
        EXPECT_EQ(full.joints[i].name, plain.joints[i].name);
        ASSERT_EQ(full.joints[i].points.size(), 2u);
        for (int k = 0; k < 2; ++k) {
            // Bit for bit: a persistent set is generated exactly as before persistence existed.
            EXPECT_EQ(full.joints[i].points[k].x, plain.joints[i].points[k].x);
            EXPECT_EQ(full.joints[i].points[k].y, plain.joints[i].points[k].y);
        }
    }
}

TEST(JointSets, HalfPersistentSetHasSegmentsBridgesAndStagger) {
    // Period 2 / 0.5 = 4 m: 2 m of joint, 2 m of bridge; each trace up (k = 1, 2, ...) is shifted
    // by 0.25 · 4 = 1 m along +x. Pieces that would only touch the box edge are not generated.
    const Model m = expanded_square(R"({"name": "bridged", "angle": 0, "spacing": 2, "origin": [0, 1],
                                        "persistence": 0.5, "trace_length": 2, "stagger": 0.25})");
    const double M = margin;
    expect_segments(segments_of(m), {
        {-M, 1, 2, 1}, {4, 1, 6, 1}, {8, 1, 10 + M, 1},  // k = 0: starts at the origin
        {1, 3, 3, 3}, {5, 3, 7, 3}, {9, 3, 10 + M, 3},   // k = 1: shifted 1 m
        {2, 5, 4, 5}, {6, 5, 8, 5},                      // k = 2: shifted 2 m, bridges at both edges
        {-M, 7, 1, 7}, {3, 7, 5, 7}, {7, 7, 9, 7},       // k = 3: shifted 3 m
        {-M, 9, 2, 9}, {4, 9, 6, 9}, {8, 9, 10 + M, 9},  // k = 4: shifted a whole period
    });
    // Inner segments are exactly the trace length; bridges between them are period − length.
    for (const Segment& s : segments_of(m)) {
        const bool inner = s.x0 > 0.0 && s.x1 < 10.0;
        if (inner) EXPECT_NEAR(s.x1 - s.x0, 2.0, 1e-12);
    }
    EXPECT_EQ(m.joints.size(), 14u);
    EXPECT_EQ(m.joints.back().name, "bridged #14");
}

TEST(JointSets, StaggerRunsAlongTheTracesAndBackwardsForNegativeTraces) {
    // Vertical traces (angle 90°): trace k lies at x = 5 − 3k (left of the upward direction is −x).
    // Period 2 / 0.4 = 5 m, shift per trace 0.3 · 5 = 1.5 m upwards; trace −1 is shifted by
    // −1.5 m, i.e. by 3.5 m, as the pattern repeats every 5 m.
    const Model m = expanded_square(R"({"angle": 90, "spacing": 3, "origin": [5, 0],
                                        "persistence": 0.4, "trace_length": 2, "stagger": 0.3})");
    const double M = margin;
    expect_segments(segments_of(m), {
        {5, -M, 5, 2}, {5, 5, 5, 7},                        // k = 0, through the origin
        {2, 1.5, 2, 3.5}, {2, 6.5, 2, 8.5},                 // k = 1
        {8, -M, 8, 0.5}, {8, 3.5, 8, 5.5}, {8, 8.5, 8, 10 + M},  // k = −1
    });
}

TEST(JointSets, SegmentPatternDoesNotDependOnTheExtent) {
    const std::string set = R"("angle": 0, "spacing": 2, "origin": [0, 1], "persistence": 0.5, "trace_length": 2,
                               "stagger": 0.25)";
    const Model whole = expanded_square("{" + set + "}");
    const Model part = expanded_square("{" + set + R"(, "extent": [2.5, 0, 10, 4]})");
    // In x ∈ [2.5, 10], y ∈ [0, 4]: traces y = 1 and y = 3; the segment [1, 3] of y = 3 is cut
    // at x = 2.5, and [0, 2] of y = 1 lies outside.
    const double M = 1e-6 * std::hypot(7.5, 4.0);
    expect_segments(segments_of(part), {
        {4, 1, 6, 1}, {8, 1, 10 + M, 1},
        {2.5 - M, 3, 3, 3}, {5, 3, 7, 3}, {9, 3, 10 + M, 3},
    });
    // Every segment inside the part lies on a segment of the whole.
    for (const Segment& s : segments_of(part)) {
        const bool on_whole = std::any_of(whole.joints.begin(), whole.joints.end(), [&](const Joint& j) {
            return j.points[0].y == s.y0 && j.points[0].x <= std::max(s.x0, 2.5) + 1e-9 &&
                   j.points[1].x >= std::min(s.x1, 10.0) - 1e-9;
        });
        EXPECT_TRUE(on_whole) << s.x0 << ", " << s.y0 << " – " << s.x1;
    }
}

TEST(JointSets, SetsTheValidatorRefusesGenerateNothing) {
    // Far beyond the segment limit, or without a trace length: nothing, not a partial set.
    EXPECT_TRUE(expanded_square(R"({"angle": 0, "spacing": 0.1, "persistence": 0.5, "trace_length": 0.001})").joints.empty());
    EXPECT_TRUE(expanded_square(R"({"angle": 0, "spacing": 1, "persistence": 0.5})").joints.empty());
    EXPECT_TRUE(expanded_square(R"({"angle": 0, "spacing": 1, "persistence": 0.5, "trace_length": 1, "stagger": 1})").joints.empty());
}
