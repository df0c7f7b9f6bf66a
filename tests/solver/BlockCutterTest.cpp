// Block cutting: joints cut regions into blocks exactly; pieces that separate nothing become cracks.

#include "TestModels.hpp"
#include "geometry/PolygonChecks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;
using Severity = Diagnostic::Severity;

namespace {

Preprocessed cut(const std::vector<std::string>& overrides) {
    return preprocess_text(square_model_json(), overrides, PreprocessStage::Cut);
}

double total_area(const std::vector<Block>& blocks) {
    double a = 0.0;
    for (const Block& b : blocks) a += b.area;
    return a;
}

}  // namespace

TEST(BlockCutter, OneJointAcrossGivesTwoBlocks) {
    const Preprocessed p = cut({"/joints=[{\"name\": \"j\", \"points\": [[-1,3],[11,3]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.blocks.size(), 2u);
    // Blocks are ordered by their lowest vertex: the lower one first.
    EXPECT_NEAR(p.blocks[0].area, 30.0, 1e-9);
    EXPECT_NEAR(p.blocks[1].area, 70.0, 1e-9);
    // The cut edge is tagged with the joint; the outer boundary edges with the region.
    int joint_edges = 0;
    for (const EdgeTag& t : p.blocks[0].tags[0]) joint_edges += t.joint == 0;
    EXPECT_EQ(joint_edges, 1);
}

TEST(BlockCutter, CrossingJointsAndAPolylineCutExactly) {
    const Preprocessed p = cut({"/joints=[{\"points\": [[0,0],[10,10]]}, {\"points\": [[0,10],[10,0]]},"
                                " {\"points\": [[-1,7],[5,8],[11,7]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    // Diagonals give 4 triangles; the polyline above the centre cuts the top triangle and the
    // upper parts of the left and right ones: 7 blocks.
    EXPECT_EQ(p.blocks.size(), 7u);
    EXPECT_NEAR(total_area(p.blocks), 100.0, 1e-9);
    for (const Block& b : p.blocks) {
        EXPECT_GT(b.area, 0.0);
        EXPECT_GT(signed_area(b.outer), 0.0);  // outer rings counter-clockwise
    }
}

TEST(BlockCutter, DanglingJointPiecesBecomeCracksWithoutAWarning) {
    const Preprocessed p = cut({"/joints=[{\"name\": \"partial\", \"points\": [[-2,5],[4,5]]},"
                                " {\"name\": \"inner\", \"points\": [[3,8],[6,8]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_EQ(p.blocks.size(), 1u);
    EXPECT_NEAR(p.blocks[0].area, 100.0, 1e-9);
    EXPECT_TRUE(p.diagnostics.empty()) << all_messages(p.diagnostics);
    // The cracks are no part of the block's outline.
    EXPECT_EQ(p.blocks[0].outer.size(), 5u);  // 4 corners + where "partial" met the boundary
    EXPECT_TRUE(p.blocks[0].holes.empty());
    EXPECT_EQ(p.blocks[0].cracks.size(), 2u);
}

// The cracks are known by place, block and joint (for the mesher, the contacts' joint material
// and the pictures).
TEST(BlockCutter, CracksAreListedWithTheirBlockAndJoint) {
    const Preprocessed p = cut({"/joints=[{\"name\": \"partial\", \"points\": [[-2,5],[4,5]]},"
                                " {\"name\": \"inner\", \"points\": [[3,8],[6,8]]},"
                                " {\"name\": \"across\", \"points\": [[-1,2],[11,2]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_TRUE(p.blocks[0].cracks.empty());  // below "across": nothing dangles
    const auto& pieces = p.blocks[1].cracks;
    ASSERT_EQ(pieces.size(), 2u);
    double partial = 0.0, inner = 0.0;
    for (const Block::Crack& piece : pieces) {
        const double length = std::hypot(piece.to.x - piece.from.x, piece.to.y - piece.from.y);
        if (piece.joint == 0) {
            partial += length;
            EXPECT_NEAR(piece.from.y, 5.0, 1e-12);
            EXPECT_NEAR(std::min(piece.from.x, piece.to.x), 0.0, 1e-12);  // from the boundary on
        }
        if (piece.joint == 1) {
            inner += length;
            EXPECT_NEAR(piece.from.y, 8.0, 1e-12);
        }
    }
    EXPECT_NEAR(partial, 4.0, 1e-12);
    EXPECT_NEAR(inner, 3.0, 1e-12);
}

TEST(BlockCutter, NonPersistentSetCrossingAPersistentOneCutsWhereItRunsJointToJoint) {
    // Vertical persistent traces at x = 3 and 7. Horizontal segments (period 12 m, 6 m long,
    // stagger 0.5) at y = 1, 5, 9: on y = 5 the segment [2, 8] crosses both traces and cuts the
    // middle block in two; its ends (1 m each) and the segments [0, 2] and [8, 10] on y = 1 and
    // y = 9 end inside blocks and become cracks: 2 + 4 · 2 = 10 m in 6 pieces.
    const Preprocessed p = cut({"/joint_sets=[{\"name\": \"vertical\", \"angle\": 90, \"spacing\": 4, \"origin\": [3, 0]},"
                                " {\"name\": \"bridged\", \"angle\": 0, \"spacing\": 4, \"origin\": [2, 5],"
                                "  \"persistence\": 0.5, \"trace_length\": 6, \"stagger\": 0.5}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    int bridged_segments = 0;
    for (const Joint& j : p.model.joints) bridged_segments += j.joint_set == 1;
    EXPECT_EQ(bridged_segments, 5);
    ASSERT_EQ(p.blocks.size(), 4u);
    EXPECT_NEAR(total_area(p.blocks), 100.0, 1e-9);
    std::vector<double> areas;
    for (const Block& b : p.blocks) areas.push_back(b.area);
    std::sort(areas.begin(), areas.end());
    EXPECT_NEAR(areas[0], 20.0, 1e-9);  // middle strip below y = 5
    EXPECT_NEAR(areas[1], 20.0, 1e-9);  // and above
    EXPECT_NEAR(areas[2], 30.0, 1e-9);
    EXPECT_NEAR(areas[3], 30.0, 1e-9);
    double crack_length = 0.0;
    int cracks = 0;
    for (const Block& b : p.blocks)
        for (const Block::Crack& c : b.cracks) {
            EXPECT_EQ(p.model.joints[c.joint].joint_set, 1);  // the persistent set cuts along its whole length
            crack_length += std::hypot(c.to.x - c.from.x, c.to.y - c.from.y);
            ++cracks;
        }
    EXPECT_NEAR(crack_length, 10.0, 1e-9);
    EXPECT_EQ(cracks, 6);
}

TEST(BlockCutter, RegionHoleSurvivesWhenNoJointReachesIt) {
    const Preprocessed p = cut({"/regions/0/holes=[[[4,4],[6,4],[6,6],[4,6]]]",
                                "/joints=[{\"points\": [[0,2],[10,2]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_NEAR(p.blocks[1].area, 80.0 - 4.0, 1e-9);
    ASSERT_EQ(p.blocks[1].holes.size(), 1u);
    EXPECT_LT(signed_area(p.blocks[1].holes[0]), 0.0);  // holes clockwise
}

TEST(BlockCutter, JointAlongARegionInterfaceKeepsTwoBlocks) {
    const Preprocessed p = cut({"/regions/-={\"name\": \"east\", \"material\": \"rock\", \"boundary\": [[10,0],[20,0],[20,10],[10,10]]}",
                                "/joints=[{\"name\": \"contact\", \"points\": [[10,-1],[10,11]]}]"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_EQ(p.blocks.size(), 2u);
    EXPECT_NEAR(total_area(p.blocks), 200.0, 1e-9);
}

TEST(BlockCutter, JointedTunnelBlocksTileTheRegion) {
    const Preprocessed p = preprocess_file(mcdda::test::example_path("jointed-tunnel.json"), {}, PreprocessStage::Cut);
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    // Two joint sets (30° and 120° at 6.5 m) and a fault through a 40 m square with a 3 m
    // radius tunnel. The count was checked by drawing the blocks; any change in cutting shows here.
    EXPECT_EQ(p.blocks.size(), 66u);
    EXPECT_GE(p.blocks.size(), 20u);  // the example's promise
    const Region& rock = p.model.regions[0];
    const double region_area = signed_area(rock.boundary) + signed_area(rock.holes[0]) * (signed_area(rock.holes[0]) < 0 ? 1 : -1);
    EXPECT_NEAR(region_area, 1600.0 - 0.5 * 64 * 9.0 * std::sin(2 * M_PI / 64), 1e-9);
    EXPECT_NEAR(total_area(p.blocks), region_area, 1e-9 * region_area);
    int blocks_touching_tunnel = 0;
    for (const Block& b : p.blocks) {
        EXPECT_GT(b.area, 1e-6);
        EXPECT_EQ(b.material, 0);
        bool touches = false;
        for (const Point2& q : b.outer) touches |= std::fabs(std::hypot(q.x, q.y) - 3.0) < 1e-9;
        blocks_touching_tunnel += touches;
    }
    EXPECT_GE(blocks_touching_tunnel, 4);
}

// What the run would refuse is refused after cutting already (what `mcdda check` runs): supports
// and pressures that lie along no block boundary.
TEST(BlockCutter, SupportsAndPressuresOffEveryBlockBoundaryAreRefusedBeforeMeshing) {
    const Preprocessed ok = preprocess_text(
        square_model_json(),
        {R"(/edge_pressures=[{"name": "top", "from": [2, 10], "to": [8, 10], "pressure": 1e5}])",
         R"(/rollers/-={"name": "corner", "from": [10, 10], "to": [12, 12], "fixed": "x"})"},
        PreprocessStage::Cut);
    EXPECT_TRUE(ok.ok) << all_messages(ok.diagnostics);  // along an edge; through a corner vertex

    const Preprocessed bad = preprocess_text(
        square_model_json(),
        {R"(/edge_pressures=[{"name": "inside", "from": [2, 5], "to": [8, 5], "pressure": 1e5}])",
         R"(/rollers/-={"name": "away", "from": [20, 0], "to": [30, 0], "fixed": "y"})"},
        PreprocessStage::Cut);
    EXPECT_FALSE(bad.ok);
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/rollers/1", "lies along no block boundary"))
        << all_messages(bad.diagnostics);
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/edge_pressures/0", "lies along no block boundary"))
        << all_messages(bad.diagnostics);

    // Points outside every block (a typo in a coordinate) went to the nearest node silently.
    const Preprocessed points = preprocess_text(
        square_model_json(),
        {R"(/point_loads=[{"name": "push", "point": [500, 5], "force": [1, 0]}])",
         R"(/fixed_points=[{"name": "pin", "point": [5, -3]}])",
         R"(/measurement_points=[{"name": "inside", "point": [5, 5]}, {"name": "corner", "point": [10, 10]},
                                 {"name": "off", "point": [11, 5]}])"},
        PreprocessStage::Cut);
    EXPECT_FALSE(points.ok);
    EXPECT_TRUE(has_diagnostic(points.diagnostics, Severity::Error, "/point_loads/0/point",
                               "point load \"push\" at (500, 5) lies outside every block"))
        << all_messages(points.diagnostics);
    EXPECT_TRUE(has_diagnostic(points.diagnostics, Severity::Error, "/fixed_points/0/point", "outside every block"));
    EXPECT_TRUE(has_diagnostic(points.diagnostics, Severity::Error, "/measurement_points/2/point", "outside every block"));
    EXPECT_FALSE(has_diagnostic(points.diagnostics, Severity::Error, "/measurement_points/0/point", "outside"));
    EXPECT_FALSE(has_diagnostic(points.diagnostics, Severity::Error, "/measurement_points/1/point", "outside"));
}

// Features far below the model's size cannot be meshed (CGAL's refinement crashed or spun on
// them): `check` already refuses them, naming the block, region and place.
TEST(BlockCutter, SliversAndNearlyCoincidentVerticesAreRefusedWithTheirPlace) {
    const Preprocessed sliver = preprocess_text(square_model_json(), {"/regions/0/boundary=[[0,0],[10,0],[10,1e-9]]"},
                                                PreprocessStage::Cut);
    EXPECT_FALSE(sliver.ok);
    EXPECT_TRUE(has_diagnostic(sliver.diagnostics, Severity::Error, "/regions/0", "an edge 1e-09 m long near (10, 0)"))
        << all_messages(sliver.diagnostics);

    // A vertex a denormal number away from its neighbour.
    const Preprocessed close = preprocess_text(
        square_model_json(), {"/regions/0/boundary=[[0,0],[10,0],[10,10],[5e-324,10],[0,10]]"}, PreprocessStage::Cut);
    EXPECT_FALSE(close.ok);
    EXPECT_TRUE(has_diagnostic(close.diagnostics, Severity::Error, "/regions/0", "cannot be meshed"))
        << all_messages(close.diagnostics);

    // A thin spike: a vertex 1e-8 m from an edge it does not end (no short edge).
    const Preprocessed spike = preprocess_text(
        square_model_json(), {"/regions/0/boundary=[[0,0],[10,0],[10,10],[5,1e-8],[0,10]]"}, PreprocessStage::Cut);
    EXPECT_FALSE(spike.ok);
    EXPECT_TRUE(has_diagnostic(spike.diagnostics, Severity::Error, "/regions/0", "from an edge it does not end"))
        << all_messages(spike.diagnostics);

    // A millimetre is far above the limit (1e-6 of the model's size): accepted.
    const Preprocessed fine = preprocess_text(
        square_model_json(), {"/regions/0/boundary=[[0,0],[10,0],[10,10],[5,0.001],[0,10]]"}, PreprocessStage::Cut);
    EXPECT_TRUE(fine.ok) << all_messages(fine.diagnostics);
}

// A joint drawn through vertices of a hole's polygon (a joint set through a tunnel): in floating
// point it misses them by ~1e-16 m, which left edges of that length in both blocks and crashed the
// mesher. The joint is routed through the vertices instead, and the model meshes.
TEST(BlockCutter, AJointThroughPolygonVerticesPassesExactlyThroughThem) {
    const std::vector<std::string> overrides = {
        "/regions/0/boundary=[[-20,-20],[20,-20],[20,20],[-20,20]]",
        R"(/regions/0/holes=[{"circle": {"center": [0, 0], "radius": 3, "segments": 64}}])",
        R"(/joints=[{"name": "diagonal", "points": [[-20,-20],[20,20]]}])", "/rollers=[]",
        R"(/rollers/-={"name": "base", "from": [-20,-20], "to": [20,-20], "fixed": "xy"})",
        R"(/mesh={"size": 2, "min_angle": 28})"};
    const Preprocessed p = preprocess_text(square_model_json(), overrides, PreprocessStage::Mesh);
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_EQ(p.blocks.size(), 2u);
    EXPECT_NEAR(total_area(p.blocks), 1600.0 - 64 * 0.5 * 9 * std::sin(2 * M_PI / 64), 1e-6);
    EXPECT_GT(p.statistics.elements, 100);
    EXPECT_GE(p.statistics.min_angle_deg, 28.0 - 1e-9);
}

// Joints drawn through one point meet there only up to rounding: exactly, three or more of them
// cross at a few points 1e-15 m apart, which made a sliver block ("an edge 0 m long") and refused
// the model. Their crossings are made one point, and each joint passes through it.
TEST(BlockCutter, JointsDrawnThroughOnePointMeetThereExactly) {
    const double cx = 5.3, cy = 4.7;
    for (int count : {3, 4, 7}) {
        std::ostringstream joints;
        joints.precision(17);
        joints << "/joints=[";
        for (int i = 0; i < count; ++i) {
            const double angle = 3.0 * M_PI / 180.0 + i * M_PI / count;
            const double dx = 20.0 * std::cos(angle), dy = 20.0 * std::sin(angle);
            joints << (i ? "," : "") << "{\"name\": \"j" << i << "\", \"points\": [[" << cx - dx << "," << cy - dy
                   << "],[" << cx + dx << "," << cy + dy << "]]}";
        }
        joints << "]";
        const Preprocessed p = preprocess_text(square_model_json(), {joints.str()}, PreprocessStage::Mesh);
        ASSERT_TRUE(p.ok) << count << " joints: " << all_messages(p.diagnostics);
        EXPECT_EQ(p.blocks.size(), static_cast<std::size_t>(2 * count)) << count << " joints";
        EXPECT_NEAR(total_area(p.blocks), 100.0, 1e-9);
        // Every block has the meeting point as a corner, one and the same.
        for (const Block& b : p.blocks) {
            int corners_there = 0;
            for (const Point2& q : b.outer) corners_there += std::hypot(q.x - cx, q.y - cy) < 1e-6;
            EXPECT_EQ(corners_there, 1) << count << " joints";
        }
    }
    // Joints ending in the rock (cracks) crossing at one point: one block.
    const Preprocessed cracks = preprocess_text(
        square_model_json(),
        {R"(/joints=[{"name": "a", "points": [[2,5],[8,5]]}, {"name": "b", "points": [[3.5,2.4019237886],[6.5,7.5980762114]]},
                     {"name": "c", "points": [[6.5,2.4019237886],[3.5,7.5980762114]]}])"},
        PreprocessStage::Mesh);
    ASSERT_TRUE(cracks.ok) << all_messages(cracks.diagnostics);
    EXPECT_EQ(cracks.blocks.size(), 1u);
}

// Crossing joint sets make block corners in proportion to the product of their traces; more than
// the mesh may have elements is refused before the arrangement is built (it took minutes and
// gigabytes for a few million crossings).
TEST(BlockCutter, JointSetsCrossingMoreOftenThanTheMeshMayHaveElementsAreRefusedEarly) {
    const std::vector<std::string> sets = {
        R"(/joint_sets=[{"name": "a", "angle": 0, "spacing": 0.5, "origin": [0.25, 0.25]},
                        {"name": "b", "angle": 90, "spacing": 0.5, "origin": [0.25, 0.25]}])"};
    std::vector<std::string> small = sets;
    small.push_back("/mesh/max_elements=300");
    const Preprocessed refused = cut(small);
    EXPECT_FALSE(refused.ok);
    EXPECT_TRUE(has_diagnostic(refused.diagnostics, Severity::Error, "/joint_sets", "may cross up to 400 times"))
        << all_messages(refused.diagnostics);
    const Preprocessed cut_ok = cut(sets);  // the default limit: 20 × 20 traces cut 21 × 21 blocks
    ASSERT_TRUE(cut_ok.ok) << all_messages(cut_ok.diagnostics);
    EXPECT_EQ(cut_ok.blocks.size(), 441u);
}
