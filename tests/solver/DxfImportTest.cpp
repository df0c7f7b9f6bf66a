// DXF import (io/DxfImport.hpp): a drawing in millimetres written here as CAD programs write it
// (LWPOLYLINE, POLYLINE with VERTEX/SEQEND, LINE, POINT, and a CIRCLE that is not imported)
// becomes a model in metres that meshes and runs.

#include "mcdda/Analysis.hpp"
#include "io/DxfImport.hpp"
#include "io/ModelWriter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
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
    /// Any group, as a damaged or hostile file has it.
    Drawing& group(int code, const std::string& value) { return add({code, value}); }
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

std::string messages(const std::vector<Diagnostic>& d)
{
    std::string text;
    for (const Diagnostic& x : d) text += format_diagnostic(x) + "\n";
    return text;
}

/// A file of exactly these bytes.
std::string save_bytes(const std::string& name, const std::string& bytes)
{
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
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

// A count is believed only as far as the file holds its items: dxflib allocates what it declares
// (10⁹ vertices in a 104-byte file were 3 GB, or std::bad_alloc). Refused at once, with the line.
TEST(DxfImport, DeclaredCountsBeyondTheContentAreRefused) {
    Drawing lw(6);
    lw.group(0, "LWPOLYLINE").group(8, "rock").group(90, "1000000000").group(70, "1");
    for (const char* v : {"0", "0", "1", "0", "0", "1"}) lw.group(10, v).group(20, v);
    const auto start = std::chrono::steady_clock::now();
    const DxfImportResult r = import_dxf_file(lw.save("mcdda-count-1e9.dxf"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    EXPECT_FALSE(r.model.has_value());
    // The LWPOLYLINE starts on line 15 (after the header's 14), the value of its 90 is on line 20.
    EXPECT_TRUE(says(r.diagnostics, "line 20: the LWPOLYLINE on layer \"rock\" from line 15 declares 1000000000 "
                                    "vertices (group code 90) but holds 6"))
        << messages(r.diagnostics);
    // Fewer than it holds: dxflib would overwrite the last vertex with the rest.
    Drawing fewer(6);
    fewer.group(0, "LWPOLYLINE").group(8, "rock").group(90, "3").group(70, "1");
    for (const char* v : {"0", "5", "5", "0"}) fewer.group(10, v).group(20, v);
    EXPECT_TRUE(says(import_dxf_file(fewer.save("mcdda-count-fewer.dxf")).diagnostics, "declares 3 vertices"));
    // Entities that are not imported still must not make dxflib allocate beyond their content.
    Drawing spline(6);
    spline.lwpolyline("rock", {{0, 0}, {1, 0}, {1, 1}}, true).group(0, "SPLINE").group(8, "0").group(72, "2000000000");
    EXPECT_TRUE(says(import_dxf_file(spline.save("mcdda-count-spline.dxf")).diagnostics,
                     "the SPLINE on layer \"0\" from line 35 declares 2000000000 knots (group code 72) but holds 0"));
}

// dxflib reads "abc", "NaN", "-inf", "1e" and "" as 0 without a word: each is an error with its
// line, entity and layer.
TEST(DxfImport, CoordinatesThatAreNotNumbersAreRefusedWithTheirLine) {
    for (const std::string& bad : {"abc", "NaN", "-inf", "1e", "", "0x10", "1e999"}) {
        Drawing d(6);
        d.group(0, "LWPOLYLINE").group(8, "rock").group(90, "3").group(70, "1");
        d.group(10, "0").group(20, "0").group(10, bad).group(20, "0").group(10, "1").group(20, "1");
        const DxfImportResult r = import_dxf_file(d.save("mcdda-bad-number.dxf"));
        EXPECT_FALSE(r.model.has_value()) << bad;
        const std::string quoted = bad.empty() ? "is empty, not a number" : "is \"" + bad + "\"";
        const std::string where = "line 28: the x (group code 10) of the LWPOLYLINE on layer \"rock\" from line 15 ";
        EXPECT_TRUE(says(r.diagnostics, where + quoted)) << bad << ": " << messages(r.diagnostics);
    }
    // A decimal comma is what dxflib reads too; it is a number.
    Drawing comma(6);
    comma.group(0, "LWPOLYLINE").group(8, "rock").group(90, "3").group(70, "1");
    comma.group(10, "0").group(20, "0").group(10, "1,5").group(20, "0").group(10, "1").group(20, "1");
    const DxfImportResult ok = import_dxf_file(comma.save("mcdda-comma.dxf"));
    ASSERT_TRUE(ok.model.has_value()) << messages(ok.diagnostics);
    EXPECT_EQ(ok.model->regions[0].boundary[1].x, 1.5);
}

// Layer names of drawings before AutoCAD 2007 are in the Windows code page: read as such into
// UTF-8, the model file (JSON) can hold them.
TEST(DxfImport, Latin1LayerNamesBecomeUtf8) {
    Drawing d(6);
    d.lwpolyline("ro\xff" "ck", {{0, 0}, {20, 0}, {20, 10}, {0, 10}}, true).line("Kl\xfc" "fte", {0, 5}, {20, 6});
    const DxfImportResult r = import_dxf_file(d.save("mcdda-latin1.dxf"));
    ASSERT_TRUE(r.model.has_value()) << messages(r.diagnostics);
    EXPECT_EQ(r.model->materials[0].name, "ro\u00ffck");
    EXPECT_EQ(r.model->joint_materials[0].name, "Kl\u00fcfte");
    EXPECT_NE(write_model_text(*r.model).find("\"ro\u00ffck\""), std::string::npos);
}

// What is not an ASCII DXF says what it is, not "no closed polyline".
TEST(DxfImport, BinaryUtf16AndOtherFilesSayWhatTheyAre) {
    auto error_of = [](const std::string& path) { return messages(import_dxf_file(path).diagnostics); };
    EXPECT_NE(error_of(save_bytes("mcdda-binary.dxf", std::string("AutoCAD Binary DXF\r\n\x1a\0\0\0", 26)))
                  .find("a binary DXF, which is not supported: save the drawing as ASCII DXF"),
              std::string::npos);
    const std::string text = "0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n";
    std::string le = "\xff\xfe", be = "\xfe\xff", bare;
    for (char c : text) le += std::string{c, '\0'}, be += std::string{'\0', c}, bare += std::string{c, '\0'};
    for (const std::string& bytes : {le, be, bare})
        EXPECT_NE(error_of(save_bytes("mcdda-utf16.dxf", bytes)).find("UTF-16 text, which is not supported"),
                  std::string::npos);
    const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    EXPECT_NE(error_of(save_bytes("mcdda-png.dxf", png)).find("NUL byte"), std::string::npos);
    EXPECT_NE(error_of(save_bytes("mcdda-text.dxf", "hello\nworld\n")).find("line 1: \"hello\" is not a DXF group code"),
              std::string::npos);
    EXPECT_NE(error_of("/dev/zero").find("/dev/zero is a character device, not a DXF drawing"), std::string::npos);
}
