// The plain geometry behind the pictures: which side is rock, joint splitting, symbol shapes.
// No rendering, no X server.

#include "TunnelModel.hpp"
#include "view/ResultProbe.hpp"
#include "view/SceneGeometry.hpp"
#include "view/Symbols.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;
using namespace mcdda::view;
using namespace mcdda::guitest;

TEST(SceneGeometry, InsideMaterialHonoursHoles)
{
    const Model m = tunnel_model();
    EXPECT_TRUE(inside_material(m, {1, 1}));
    EXPECT_TRUE(inside_material(m, {9, 9}));
    EXPECT_FALSE(inside_material(m, hole_centre));
    EXPECT_FALSE(inside_material(m, {-1, 5}));
    EXPECT_FALSE(inside_material(m, {5, 11}));
    EXPECT_FALSE(inside_material(Model{}, {0, 0}));
}

TEST(SceneGeometry, JointIsSplitAtBoundaryAndOpening)
{
    const Model m = tunnel_model();
    const Joint& j = m.joints.front();
    const auto pieces = split_by_material(m, j.points[0], j.points[1]);
    // outside, rock, opening, rock, outside
    ASSERT_EQ(pieces.size(), 5u);
    const bool expected[] = {false, true, false, true, false};
    for (std::size_t i = 0; i < pieces.size(); ++i) EXPECT_EQ(pieces[i].in_material, expected[i]) << i;
    EXPECT_NEAR(pieces[1].from.x, 0.0, 1e-9);
    EXPECT_NEAR(pieces[3].to.x, 10.0, 1e-9);
    // The pieces cover the segment without gaps.
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        EXPECT_NEAR(pieces[i].from.x, pieces[i - 1].to.x, 1e-12);
        EXPECT_NEAR(pieces[i].from.y, pieces[i - 1].to.y, 1e-12);
    }
}

TEST(SceneGeometry, NormalPointsIntoRock)
{
    const Model m = tunnel_model();
    const Point2 right = normal_into_material(m, {10, 0}, {10, 10}, 0.1);
    EXPECT_NEAR(right.x, -1.0, 1e-12);
    const Point2 left = normal_into_material(m, {0, 10}, {0, 0}, 0.1);
    EXPECT_NEAR(left.x, 1.0, 1e-12);
    const Point2 down = direction_out_of_material(m, {5, 0}, 0.5);
    EXPECT_NEAR(down.y, -1.0, 1e-12);
    const Point2 up = direction_out_of_material(m, {5, 10}, 0.5);
    EXPECT_NEAR(up.y, 1.0, 1e-12);
}

TEST(SceneGeometry, BoxAndSymbolSize)
{
    Preprocessed p;
    EXPECT_FALSE(model_box(p).valid());
    EXPECT_DOUBLE_EQ(symbol_size(model_box(p)), 1.0);
    p.model = tunnel_model();
    const Box box = model_box(p);
    ASSERT_TRUE(box.valid());
    EXPECT_LE(box.xmin, -1.0);  // the joint sticks out
    EXPECT_GE(box.xmax, 11.0);
    EXPECT_NEAR(symbol_size(box), box.size() / 40.0, 1e-12);
}

TEST(Symbols, ArrowEndsAtItsTip)
{
    const Shapes s = arrow({0, 0}, {3, 4}, 1.0, 0.6, 0.2);
    ASSERT_EQ(s.fills.size(), 2u);
    const auto& head = s.fills.back();
    EXPECT_DOUBLE_EQ(head[0].x, 3.0);
    EXPECT_DOUBLE_EQ(head[0].y, 4.0);
    for (const auto& f : s.fills)
        for (const Point2& q : f) EXPECT_LE(std::hypot(q.x, q.y), 5.0 + 1e-9);
}

TEST(Symbols, PressureArrowsEndOnTheEdgePointingIntoRock)
{
    const Model m = tunnel_model();
    const double size = 0.3;
    const Shapes s = edge_pressure_shapes(m, size);
    int tips = 0;
    for (const auto& f : s.fills) {
        if (f.size() != 3) continue;  // heads are the triangles
        ++tips;
        EXPECT_NEAR(f[0].x, 10.0, 1e-9);                          // tip on the loaded edge x = 10
        EXPECT_GT(f[1].x, 10.0);                                   // head behind it, outside
        EXPECT_GT(f[2].x, 10.0);
    }
    EXPECT_GE(tips, 2);
}

TEST(Symbols, SupportsLieOutsideTheRock)
{
    const Model m = tunnel_model();
    const double size = 0.3;
    for (const Shapes& s : {fixed_point_shapes(m, size), roller_shapes(m, size)})
        for (const auto& f : s.fills) {  // apexes touch the boundary: test the centroids
            Point2 c;
            for (const Point2& q : f) c = {c.x + q.x / f.size(), c.y + q.y / f.size()};
            EXPECT_FALSE(inside_material(m, c)) << c.x << ", " << c.y;
        }
}

TEST(Symbols, EmptyModelHasNoSymbols)
{
    const Model m;
    EXPECT_TRUE(fixed_point_shapes(m, 1).empty());
    EXPECT_TRUE(roller_shapes(m, 1).empty());
    EXPECT_TRUE(point_load_shapes(m, 1).empty());
    EXPECT_TRUE(edge_pressure_shapes(m, 1).empty());
    EXPECT_TRUE(measurement_shapes(m, 1).empty());
}

// The value query behind the status bar: point values interpolate linearly inside a triangle,
// cell values are constant, states read as words, outside is nothing.
TEST(ResultProbe, InterpolatesPointValuesAndReadsCells)
{
    view::ResultProbe probe;
    probe.points = {{0, 0}, {2, 0}, {0, 2}, {2, 2}};
    probe.triangles = {{0, 1, 2}, {1, 3, 2}};
    probe.values = {0.0, 2.0, 4.0, 6.0};
    probe.point_values = true;
    probe.title = "x displacement";
    probe.units = "m";
    double v = 0.0;
    ASSERT_TRUE(probe.valueAt(0.5, 0.5, &v));
    EXPECT_NEAR(v, 0.5 + 2.0 * 0.5, 1e-12);  // u = x + 2y on both triangles
    ASSERT_TRUE(probe.valueAt(1.5, 1.5, &v));
    EXPECT_NEAR(v, 1.5 + 2.0 * 1.5, 1e-12);
    EXPECT_FALSE(probe.valueAt(3.0, 1.0, &v));
    EXPECT_EQ(probe.describe(3.0, 1.0), "");
    EXPECT_EQ(probe.describe(1.0, 0.0), "x displacement = 1 m");

    probe.point_values = false;
    probe.values = {-12.5, 3.0};
    probe.units = "MPa";
    probe.title = "stress xx";
    EXPECT_EQ(probe.describe(0.2, 0.2), "stress xx = -12.5 MPa");
    probe.categorical = true;
    probe.values = {0.0, 2.0};
    probe.title = "plastic state";
    EXPECT_EQ(probe.describe(1.8, 1.8), "plastic state: yielding now");
    EXPECT_TRUE(view::ResultProbe{}.describe(0.5, 0.5).empty());
}
