// DXF import (io/DxfImport.hpp): a drawing in millimetres written here as CAD programs write it
// (LWPOLYLINE, POLYLINE with VERTEX/SEQEND, LINE, POINT, and a CIRCLE that is not imported)
// becomes a model in metres that meshes and runs.

#include "mcdda/Analysis.hpp"
#include "io/DxfImport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace mcdda;

namespace {

/// A DXF drawing of group codes and values, one per line.
class Drawing {
public:
    explicit Drawing(int insunits)
    {
        if (insunits >= 0) add({0, "SECTION"}).add({2, "HEADER"}).add({9, "$INSUNITS"}).add({70, insunits}).add({0, "ENDSEC"});
        add({0, "SECTION"}).add({2, "ENTITIES"});
    }
    Drawing& lwpolyline(const std::string& layer, const std::vector<Point2>& points, bool closed)
    {
        add({0, "LWPOLYLINE"}).add({8, layer}).add({90, static_cast<int>(points.size())}).add({70, closed ? 1 : 0});
        for (const Point2& p : points) add({10, p.x}).add({20, p.y});
        return *this;
    }
    Drawing& polyline(const std::string& layer, const std::vector<Point2>& points, bool closed)
    {
        add({0, "POLYLINE"}).add({8, layer}).add({66, 1}).add({70, closed ? 1 : 0});
        for (const Point2& p : points) add({0, "VERTEX"}).add({8, layer}).add({10, p.x}).add({20, p.y}).add({30, 0.0});
        return add({0, "SEQEND"});
    }
    Drawing& line(const std::string& layer, Point2 a, Point2 b)
    {
        return add({0, "LINE"}).add({8, layer}).add({10, a.x}).add({20, a.y}).add({11, b.x}).add({21, b.y});
    }
    Drawing& point(const std::string& layer, Point2 p) { return add({0, "POINT"}).add({8, layer}).add({10, p.x}).add({20, p.y}); }
    Drawing& circle(const std::string& layer, Point2 c, double r)
    {
        return add({0, "CIRCLE"}).add({8, layer}).add({10, c.x}).add({20, c.y}).add({40, r});
    }
    std::string save(const std::string& name)
    {
        const std::string path = (std::filesystem::temp_directory_path() / name).string();
        std::ofstream(path) << text_.str() << "0\nENDSEC\n0\nEOF\n";
        return path;
    }

private:
    struct Group {
        int code;
        std::string value;
        Group(int c, const std::string& v) : code(c), value(v) {}
        Group(int c, const char* v) : code(c), value(v) {}
        Group(int c, int v) : code(c), value(std::to_string(v)) {}
        Group(int c, double v) : code(c) {
            std::ostringstream s;
            s << v;
            value = s.str();
        }
    };
    Drawing& add(const Group& g)
    {
        text_ << g.code << "\n" << g.value << "\n";
        return *this;
    }
    std::ostringstream text_;
};

/// A 20 m square of rock with a 4 m square opening, a joint and a fault across it, a monitoring
/// point and a circle, in millimetres.
Drawing tunnel_drawing(int insunits)
{
    Drawing d(insunits);
    d.lwpolyline("rock", {{0, 0}, {20000, 0}, {20000, 20000}, {0, 20000}}, true)
        .polyline("holes", {{8000, 8000}, {8000, 12000}, {12000, 12000}, {12000, 8000}}, true)  // clockwise
        .line("joints", {0, 15000}, {20000, 16000})
        .lwpolyline("faults", {{0, 4000}, {6000, 5000}, {20000, 3000}}, false)
        .point("monitor", {10000, 18000})
        .circle("0", {3000, 3000}, 500);
    return d;
}

bool says(const std::vector<Diagnostic>& d, const std::string& words)
{
    return std::any_of(d.begin(), d.end(), [&](const Diagnostic& x) { return x.message.find(words) != std::string::npos; });
}

}  // namespace

TEST(DxfImport, RegionsHolesJointsAndPointsInMetres) {
    const DxfImportResult r = import_dxf_file(tunnel_drawing(4).save("mcdda-tunnel-mm.dxf"));
    ASSERT_TRUE(r.model.has_value()) << r.summary;
    const Model& m = *r.model;
    ASSERT_EQ(m.regions.size(), 1u);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "rock");
    EXPECT_EQ(m.regions[0].boundary[2].x, 20.0);  // 20000 mm
    ASSERT_EQ(m.regions[0].holes.size(), 1u);
    EXPECT_EQ(m.regions[0].holes[0].size(), 4u);
    ASSERT_EQ(m.joints.size(), 2u);
    EXPECT_EQ(m.joints[1].points.size(), 3u);
    ASSERT_EQ(m.joint_materials.size(), 2u);
    EXPECT_EQ(m.joint_materials[static_cast<std::size_t>(m.joints[0].joint_material)].name, "joints");
    EXPECT_EQ(m.joint_materials[static_cast<std::size_t>(m.joints[1].joint_material)].name, "faults");
    ASSERT_EQ(m.measurement_points.size(), 1u);
    EXPECT_EQ(m.measurement_points[0].point.y, 18.0);
    EXPECT_TRUE(says(r.diagnostics, "1 CIRCLE on layer \"0\" skipped")) << r.summary;
    EXPECT_NE(r.summary.find("millimetres ($INSUNITS 4)"), std::string::npos) << r.summary;
}

TEST(DxfImport, UnitsAssumedOrGiven) {
    const std::string path = tunnel_drawing(-1).save("mcdda-tunnel-nounits.dxf");
    const DxfImportResult assumed = import_dxf_file(path);
    ASSERT_TRUE(assumed.model.has_value());
    EXPECT_TRUE(says(assumed.diagnostics, "does not say its units"));
    EXPECT_EQ(assumed.model->regions[0].boundary[2].x, 20000.0);
    DxfImportOptions mm;
    mm.metres_per_unit = metres_per_unit_named("mm");
    EXPECT_EQ(import_dxf_file(path, mm).model->regions[0].boundary[2].x, 20.0);
}

TEST(DxfImport, NothingToMakeARegionOfIsAnError) {
    Drawing d(6);
    d.line("joints", {0, 0}, {1, 1});
    const DxfImportResult r = import_dxf_file(d.save("mcdda-lines-only.dxf"));
    EXPECT_FALSE(r.model.has_value());
    EXPECT_TRUE(says(r.diagnostics, "nothing to make a region of"));
    EXPECT_FALSE(import_dxf_file("/nonexistent.dxf").model.has_value());
}

// With supports added (the drawing has none), the imported model meshes and runs.
TEST(DxfImport, ImportedModelMeshesAndRuns) {
    const DxfImportResult r = import_dxf_file(tunnel_drawing(4).save("mcdda-tunnel-run.dxf"));
    ASSERT_TRUE(r.model.has_value());
    Analysis a(*r.model);
    a.set({R"(/rollers=[{"name": "base", "from": [0, 0], "to": [20, 0], "fixed": "xy"},
                        {"name": "left", "from": [0, 0], "to": [0, 20], "fixed": "x"},
                        {"name": "right", "from": [20, 0], "to": [20, 20], "fixed": "x"}])",
           "/analysis/steps=2"});
    const std::vector<Diagnostic> problems = a.mesh();
    ASSERT_TRUE(a.ok()) << (problems.empty() ? std::string() : format_diagnostic(problems.front()));
    const MeshArrays mesh = a.mesh_arrays();
    double area = 0.0;
    for (double e : mesh.area) area += e;
    EXPECT_NEAR(area, 400.0 - 16.0, 1e-6);  // the square less the opening
    std::set<int> blocks(mesh.block.begin(), mesh.block.end());
    EXPECT_EQ(blocks.size(), 3u);  // cut by the joint and the fault
    const RunResult run = a.run();
    EXPECT_EQ(run.steps, 2) << run.message;
    EXPECT_TRUE(run.status == "completed" || run.status == "unbalanced") << run.status << ": " << run.message;
}

// A line that ends in the rock is a crack in its block: the mesh arrays list its faces.
TEST(DxfImport, ALineEndingInTheRockBecomesACrack) {
    Drawing d(4);
    d.lwpolyline("rock", {{0, 0}, {20000, 0}, {20000, 20000}, {0, 20000}}, true).line("joints", {3000, 5000}, {9000, 6000});
    const DxfImportResult r = import_dxf_file(d.save("mcdda-crack.dxf"));
    ASSERT_TRUE(r.model.has_value()) << r.summary;
    Analysis a(*r.model);
    a.set({R"(/rollers=[{"name": "base", "from": [0, 0], "to": [20, 0], "fixed": "xy"}])"});
    const std::vector<Diagnostic> problems = a.mesh();
    ASSERT_TRUE(a.ok()) << (problems.empty() ? std::string() : format_diagnostic(problems.front()));
    EXPECT_FALSE(says(problems, "dropped"));
    const MeshArrays mesh = a.mesh_arrays();
    ASSERT_GT(mesh.crack_faces.size(), 0u);
    ASSERT_EQ(mesh.crack_faces.size(), 2 * mesh.crack_face_joint.size());
    double length = 0.0;
    for (std::size_t f = 0; f < mesh.crack_face_joint.size(); ++f) {
        EXPECT_EQ(mesh.crack_face_joint[f], 0);
        const int i = mesh.crack_faces[2 * f], j = mesh.crack_faces[2 * f + 1];
        length += std::hypot(mesh.nodes[2 * j] - mesh.nodes[2 * i], mesh.nodes[2 * j + 1] - mesh.nodes[2 * i + 1]);
    }
    EXPECT_NEAR(length, 2.0 * std::hypot(6.0, 1.0), 1e-9);  // both faces of the 6.08 m line
    std::set<int> blocks(mesh.block.begin(), mesh.block.end());
    EXPECT_EQ(blocks.size(), 1u);
}
