// Off-screen pictures of a model: rendered to PNG, read back, and checked pixel by pixel.
// Needs an X server (run under xvfb-run; ctest does).

#include "TunnelModel.hpp"
#include "view/ModelScene.hpp"
#include "view/LocalisedScalarBar.hpp"
#include "view/OffscreenRender.hpp"
#include "view/PictureText.hpp"
#include "view/Palette.hpp"
#include "view/ResultProbe.hpp"
#include "view/ResultScene.hpp"
#include "view/ScaleBar.hpp"
#include "view/SceneGeometry.hpp"
#include "io/ModelReader.hpp"
#include "io/VtuWriter.hpp"
#include "run/RunLoop.hpp"
#include "run/RunOutput.hpp"
#include "run/StrengthReduction.hpp"

#include <gtest/gtest.h>

#include <vtkActor2D.h>
#include <vtkActor2DCollection.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <string>

namespace fs = std::filesystem;
using namespace mcdda;
using namespace mcdda::guitest;

namespace {

constexpr int width = 800;
constexpr int height = 600;

using Rgb8 = std::array<int, 3>;

Rgb8 to_bytes(const view::Rgb& c)
{
    return {static_cast<int>(std::lround(c[0] * 255)), static_cast<int>(std::lround(c[1] * 255)),
            static_cast<int>(std::lround(c[2] * 255))};
}

bool near(const Rgb8& a, const Rgb8& b, int tolerance = 6)
{
    for (int i = 0; i < 3; ++i)
        if (std::abs(a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(i)]) > tolerance) return false;
    return true;
}

/// A PNG read back, addressed like VTK's display: x right, y up, (0, 0) bottom left.
class Picture {
public:
    explicit Picture(const std::string& path)
    {
        reader_->SetFileName(path.c_str());
        reader_->Update();
        image_ = reader_->GetOutput();
        image_->GetDimensions(dims_);
    }
    int width() const { return dims_[0]; }
    int height() const { return dims_[1]; }
    int components() const { return image_->GetNumberOfScalarComponents(); }
    Rgb8 at(int x, int y) const
    {
        Rgb8 c{};
        for (int i = 0; i < 3; ++i)
            c[static_cast<std::size_t>(i)] = static_cast<int>(image_->GetScalarComponentAsDouble(x, y, 0, i));
        return c;
    }
    /// Pixels in the (2r+1)² window around (x, y) for which `test` holds.
    int count_around(int x, int y, int r, const std::function<bool(const Rgb8&)>& test) const
    {
        int n = 0;
        for (int j = y - r; j <= y + r; ++j)
            for (int i = x - r; i <= x + r; ++i)
                if (i >= 0 && j >= 0 && i < width() && j < height() && test(at(i, j))) ++n;
        return n;
    }
    /// Pixels in [x0, x1) × [y0, y1) for which `test` holds.
    int count_in(int x0, int y0, int x1, int y1, const std::function<bool(const Rgb8&)>& test) const
    {
        int n = 0;
        for (int j = std::max(0, y0); j < std::min(height(), y1); ++j)
            for (int i = std::max(0, x0); i < std::min(width(), x1); ++i)
                if (test(at(i, j))) ++n;
        return n;
    }

private:
    vtkNew<vtkPNGReader> reader_;
    vtkImageData* image_ = nullptr;
    int dims_[3] = {0, 0, 0};
};

/// Where render_png puts model points: the same scene in a window of the same size and DPI
/// gives the same camera.
class Projection {
public:
    Projection(const Preprocessed& p, const view::SceneOptions& options)
        : Projection([&](vtkRenderer* r) { view::build_model_scene(r, p, options); })
    {
    }
    explicit Projection(const std::function<void(vtkRenderer*)>& build)
    {
        window_->SetOffScreenRendering(1);
        window_->SetSize(width, height);
        window_->SetDPI(view::png_dpi(width, height));
        window_->AddRenderer(renderer_);
        build(renderer_);
    }
    std::array<int, 2> pixel(Point2 q)
    {
        renderer_->SetWorldPoint(q.x, q.y, 0.0, 1.0);
        renderer_->WorldToDisplay();
        double d[3];
        renderer_->GetDisplayPoint(d);
        return {static_cast<int>(std::lround(d[0])), static_cast<int>(std::lround(d[1]))};
    }

private:
    vtkNew<vtkRenderWindow> window_;
    vtkNew<vtkRenderer> renderer_;
};

std::string output_path(const std::string& name) { return (fs::path(MCDDA_TEST_OUTPUT_DIR) / name).string(); }

class RenderPng : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (std::getenv("DISPLAY") == nullptr) GTEST_SKIP() << "no X display; run under xvfb-run";
    }
};

const Rgb8 background = to_bytes(view::palette::background);
const Rgb8 rock = to_bytes(view::material_color(0));

bool is_dark(const Rgb8& c) { return c[0] < 110 && c[1] < 110 && c[2] < 110; }
/// Joint red, not the orange of pressures (g ≈ 84) or the purple of point loads.
bool is_red(const Rgb8& c) { return c[0] > 170 && c[1] < 60 && c[2] < 60; }

/// Checks shared by the meshed, cut-only and model-only pictures.
void expect_model_picture(const Preprocessed& p, const std::string& path, bool meshed)
{
    const view::SceneOptions options;
    ASSERT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    Picture picture(path);
    ASSERT_EQ(picture.width(), width);
    ASSERT_EQ(picture.height(), height);
    ASSERT_GE(picture.components(), 3);

    for (auto [x, y] : {std::array<int, 2>{2, 2}, {width - 3, 2}, {2, height - 3}, {width - 3, height - 3}})
        EXPECT_TRUE(near(picture.at(x, y), background)) << "corner " << x << "," << y;

    Projection projection(p, options);
    for (const Point2& q : rock_samples()) {
        const auto [x, y] = projection.pixel(q);
        const int matches = picture.count_around(x, y, 3, [](const Rgb8& c) { return near(c, rock); });
        EXPECT_GE(matches, 20) << "rock colour expected around model point (" << q.x << ", " << q.y << ")";
    }
    for (const Point2& q : opening_samples()) {
        const auto [x, y] = projection.pixel(q);
        const int matches = picture.count_around(x, y, 3, [](const Rgb8& c) { return near(c, background); });
        EXPECT_GE(matches, 45) << "background expected in the opening at (" << q.x << ", " << q.y << ")";
    }

    // Within the square: outlines (and mesh edges) are dark, the joint is red.
    const auto lo = projection.pixel({0, 0});
    const auto hi = projection.pixel({10, 10});
    const int dark = picture.count_in(lo[0], lo[1], hi[0], hi[1], is_dark);
    const int red = picture.count_in(lo[0], lo[1], hi[0], hi[1], is_red);
    const int square = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    EXPECT_GT(square, 100 * 100) << "the model should cover a good part of the picture";
    EXPECT_GT(dark, meshed ? square / 40 : square / 200) << "outline/mesh pixels";
    EXPECT_GT(red, square / 400) << "joint pixels";

    // The legend, right of the model: white box with the material's swatch.
    const int swatch = picture.count_in(hi[0] + 5, 0, width, height, [](const Rgb8& c) { return near(c, rock); });
    EXPECT_GT(swatch, 100) << "material swatch in the legend";
}

}  // namespace

TEST_F(RenderPng, MeshedModel)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    ASSERT_TRUE(p.ok);
    ASSERT_FALSE(p.mesh.triangles.empty());
    const std::string path = output_path("render_meshed.png");
    fs::remove(path);
    view::render_png(p, {}, width, height, path);
    expect_model_picture(p, path, true);
}

TEST_F(RenderPng, BlocksWithoutMesh)
{
    const Preprocessed p = preprocess_model(tunnel_model(), PreprocessStage::Cut);
    ASSERT_TRUE(p.ok);
    ASSERT_TRUE(p.mesh.triangles.empty());
    ASSERT_FALSE(p.blocks.empty());
    const std::string path = output_path("render_blocks.png");
    view::render_png(p, {}, width, height, path);
    expect_model_picture(p, path, false);
}

TEST_F(RenderPng, ModelGeometryOnly)
{
    Preprocessed p;
    p.model = tunnel_model();
    const std::string path = output_path("render_geometry.png");
    view::render_png(p, {}, width, height, path);
    expect_model_picture(p, path, false);
}

TEST_F(RenderPng, MeshHiddenLeavesFewerDarkPixels)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    ASSERT_TRUE(p.ok);
    view::SceneOptions plain;
    plain.show_mesh = false;
    const std::string with = output_path("render_mesh_on.png");
    const std::string without = output_path("render_mesh_off.png");
    view::render_png(p, {}, width, height, with);
    view::render_png(p, plain, width, height, without);
    Picture a(with), b(without);
    Projection projection(p, {});
    const auto lo = projection.pixel({0, 0});
    const auto hi = projection.pixel({10, 10});
    EXPECT_GT(a.count_in(lo[0], lo[1], hi[0], hi[1], is_dark), 2 * b.count_in(lo[0], lo[1], hi[0], hi[1], is_dark));
}

TEST_F(RenderPng, EmptyModelGivesBackground)
{
    const std::string path = output_path("render_empty.png");
    view::render_png(Preprocessed{}, {}, 320, 240, path);
    Picture picture(path);
    ASSERT_EQ(picture.width(), 320);
    ASSERT_EQ(picture.height(), 240);
    EXPECT_EQ(picture.count_in(0, 0, 320, 240, [](const Rgb8& c) { return near(c, background); }), 320 * 240);
}

TEST_F(RenderPng, LargePictureKeepsProportions)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string path = output_path("render_large.png");
    view::render_png(p, {}, 1800, 1200, path);
    Picture picture(path);
    EXPECT_EQ(picture.width(), 1800);
    EXPECT_EQ(picture.height(), 1200);
    EXPECT_GT(picture.count_in(0, 0, 1800, 1200, [](const Rgb8& c) { return near(c, rock); }), 1800 * 1200 / 5);
}

TEST_F(RenderPng, BadRequestsThrowAndLeaveNoFile)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    EXPECT_THROW(view::render_png(p, {}, 0, 100, output_path("bad.png")), std::runtime_error);
    EXPECT_THROW(view::render_png(p, {}, 100, -5, output_path("bad.png")), std::runtime_error);
    EXPECT_THROW(view::render_png(p, {}, 100, 100, ""), std::runtime_error);
    const std::string missing = output_path("no/such/folder/picture.png");
    try {
        view::render_png(p, {}, 100, 100, missing);
        ADD_FAILURE() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_FALSE(fs::exists(output_path("bad.png")));
}

TEST_F(RenderPng, NoDisplayIsAClearError)
{
    const std::string display = std::getenv("DISPLAY");
    unsetenv("DISPLAY");
    try {
        view::render_png(Preprocessed{}, {}, 100, 100, output_path("nodisplay.png"));
        ADD_FAILURE() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("DISPLAY"), std::string::npos) << e.what();
    }
    setenv("DISPLAY", ":987", 1);  // nobody listens there
    try {
        view::render_png(Preprocessed{}, {}, 100, 100, output_path("nodisplay.png"));
        ADD_FAILURE() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot connect"), std::string::npos) << e.what();
    }
    setenv("DISPLAY", display.c_str(), 1);
    EXPECT_FALSE(fs::exists(output_path("nodisplay.png")));
}

TEST_F(RenderPng, HiddenJointsLeaveNoRed)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    view::SceneOptions options;
    options.show_joints = false;
    const std::string path = output_path("render_no_joints.png");
    view::render_png(p, options, width, height, path);
    Picture picture(path);
    EXPECT_EQ(picture.count_in(0, 0, width, height, is_red), 0);
    // Not a blank picture: the same rock and outlines as with the joints shown, whose red the
    // test would otherwise never have seen.
    const std::string shown_path = output_path("render_with_joints.png");
    view::render_png(p, {}, width, height, shown_path);
    Picture shown(shown_path);
    EXPECT_GT(shown.count_in(0, 0, width, height, is_red), 200);
    const int total = width * height;
    const int plain = picture.count_in(0, 0, width, height, [](const Rgb8& c) { return near(c, background); });
    EXPECT_LT(plain, total * 9 / 10) << "the rock should cover a good part of the picture";
    EXPECT_GT(picture.count_in(0, 0, width, height, is_dark), total / 200) << "outlines, mesh and legend text";
}

// A joint that separates no blocks (it ends in the rock) is a crack in its block, part of the
// analysis: drawn in the red of the joints, like the one that cuts blocks.
TEST_F(RenderPng, AJointEndingInRockIsDrawnAsAJoint)
{
    Model m = tunnel_model();
    Joint floating;
    floating.name = "ends in rock";
    floating.points = {{6.0, 1.0}, {9.0, 1.0}};
    floating.joint_material = 0;
    m.joints.push_back(floating);
    const Preprocessed p = preprocess_model(m);
    ASSERT_TRUE(p.ok);
    const std::string path = output_path("render_crack.png");
    view::render_png(p, {}, width, height, path);
    Picture picture(path);
    Projection projection(p, {});
    for (double x : {6.5, 7.5, 8.5}) {
        const auto [px, py] = projection.pixel({x, 1.0});
        EXPECT_GE(picture.count_around(px, py, 2, is_red), 3) << "at x = " << x;
    }
    // Beyond its tips the rock shows no joint.
    for (double x : {4.5, 9.7}) {
        const auto [px, py] = projection.pixel({x, 1.0});
        EXPECT_EQ(picture.count_around(px, py, 2, is_red), 0) << "at x = " << x;
    }
    const auto [jx, jy] = projection.pixel({8.0, joint_y0 + 8.0 * joint_slope});
    EXPECT_GE(picture.count_around(jx, jy, 3, is_red), 5);
}

// Every example model renders to a picture that shows rock, outlines and a legend. The PNGs
// stay in the build folder as example_<name>.png.
TEST_F(RenderPng, ExampleModels)
{
    const fs::path folder(MCDDA_EXAMPLES_DIR);
    if (!fs::is_directory(folder)) GTEST_SKIP() << "no examples folder";
    int rendered = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const Preprocessed p = preprocess_file(entry.path().string(), {});
        std::string messages;
        for (const Diagnostic& d : p.diagnostics) messages += format_diagnostic(d) + "\n";
        EXPECT_TRUE(p.ok) << messages;
        const std::string path = output_path("example_" + entry.path().stem().string() + ".png");
        view::render_png(p, {}, 1200, 800, path);
        Picture picture(path);
        ASSERT_EQ(picture.width(), 1200);
        const int total = 1200 * 800;
        const int plain = picture.count_in(0, 0, 1200, 800, [](const Rgb8& c) { return near(c, background); });
        const int dark = picture.count_in(0, 0, 1200, 800, is_dark);
        EXPECT_LT(plain, total * 9 / 10) << "the model should cover a good part of the picture";
        EXPECT_GT(dark, total / 200) << "outlines, mesh and legend text";
        ++rendered;
    }
    EXPECT_GT(rendered, 0);
}

// Result pictures: a fake result .vtu of the tunnel model where every cell left of x = 5 is
// "yielding now" (2) and the rest elastic (0).
namespace {

std::string write_fake_result(const Preprocessed& p, const std::string& name)
{
    VtuFields fields;
    VtuField state{"plastic_state", 1, {}};
    VtuField displacement{"displacement", 3, {}};
    for (const auto& t : p.mesh.triangles) {
        const double cx = (p.mesh.nodes[t[0]].x + p.mesh.nodes[t[1]].x + p.mesh.nodes[t[2]].x) / 3.0;
        state.values.push_back(cx < 5.0 ? 2.0 : 0.0);
    }
    for (const Point2& q : p.mesh.nodes) displacement.values.insert(displacement.values.end(), {0.01 * q.x, 0.0, 0.0});
    fields.cell_data.push_back(state);
    fields.point_data.push_back(displacement);
    const std::string path = output_path(name);
    write_vtu(path, p.mesh, fields);
    return path;
}

/// A fake result whose mesh shrinks towards x = 0 (ux = −0.01 x) and whose stresses vary with
/// x: σxx = −100 kPa · x, σyy = −2 MPa, τxy = 0.3 MPa (tension positive, as the files hold them).
std::string write_fake_stress_result(const Preprocessed& p, const std::string& name)
{
    VtuFields fields;
    VtuField stress{"stress", 6, {}};
    VtuField displacement{"displacement", 3, {}};
    for (const auto& t : p.mesh.triangles) {
        const double cx = (p.mesh.nodes[t[0]].x + p.mesh.nodes[t[1]].x + p.mesh.nodes[t[2]].x) / 3.0;
        stress.values.insert(stress.values.end(), {-1e5 * cx, -2e6, 0.0, 0.3e6, 0.0, 0.0});
    }
    for (const Point2& q : p.mesh.nodes) displacement.values.insert(displacement.values.end(), {-0.01 * q.x, 0.0, 0.0});
    fields.cell_data.push_back(stress);
    fields.point_data.push_back(displacement);
    const std::string path = output_path(name);
    write_vtu(path, p.mesh, fields);
    return path;
}

/// Builds the result scene in an off-screen renderer of the test's size and says what it drew.
view::ResultInfo drawn(const Preprocessed& p, const std::string& vtu, const view::ResultOptions& options,
                       view::ResultProbe* probe = nullptr)
{
    view::ResultInfo info;
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options, probe, &info); });
    return info;
}

bool is_state_red(const Rgb8& c) { return c[0] > 190 && c[1] < 50 && c[2] < 50; }
bool is_state_grey(const Rgb8& c) { return near(c, {209, 209, 209}, 10); }
bool is_state_yellow(const Rgb8& c) { return c[0] > 230 && c[1] > 190 && c[2] < 40; }

}  // namespace

TEST_F(RenderPng, ResultPlasticState)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    ASSERT_TRUE(p.ok);
    const std::string vtu = write_fake_result(p, "result_fake.vtu");
    const std::string path = output_path("result_plastic_state.png");
    fs::remove(path);
    const view::ResultOptions options;  // plastic_state, undeformed
    view::render_result_png(p, vtu, options, width, height, path);
    ASSERT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    Picture picture(path);
    ASSERT_EQ(picture.width(), width);
    ASSERT_EQ(picture.height(), height);

    const Rgb8 white{255, 255, 255};
    for (auto [x, y] : {std::array<int, 2>{2, 2}, {width - 3, 2}, {2, height - 3}, {width - 3, height - 3}})
        EXPECT_TRUE(near(picture.at(x, y), white)) << "corner " << x << "," << y;

    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    for (const Point2& q : rock_samples()) {
        const auto [x, y] = projection.pixel(q);
        if (q.x < 5.0) {
            EXPECT_GE(picture.count_around(x, y, 3, is_state_red), 40) << "red expected at (" << q.x << ", " << q.y << ")";
        } else {
            EXPECT_GE(picture.count_around(x, y, 3, is_state_grey), 40) << "grey expected at (" << q.x << ", " << q.y << ")";
            EXPECT_EQ(picture.count_around(x, y, 3, is_state_red), 0) << "no red at (" << q.x << ", " << q.y << ")";
        }
    }
    const auto lo = projection.pixel({0, 0});
    const auto hi = projection.pixel({10, 10});
    // Right half of the square: no red at all; left half: mostly red.
    EXPECT_EQ(picture.count_in(projection.pixel({5.3, 0})[0], lo[1], hi[0] - 2, hi[1], is_state_red), 0);
    const int left = (projection.pixel({5, 0})[0] - lo[0]) * (hi[1] - lo[1]);
    EXPECT_GT(picture.count_in(lo[0], lo[1], projection.pixel({5, 0})[0], hi[1], is_state_red), left / 2);
    // Block outlines are dark.
    EXPECT_GT(picture.count_in(lo[0] - 3, lo[1] - 3, hi[0] + 4, hi[1] + 4, is_dark), 4 * (hi[0] - lo[0]));
    // The categorical legend right of the model: the three swatches.
    EXPECT_GT(picture.count_in(hi[0] + 5, 0, width, height, is_state_yellow), 50) << "legend swatch";
    EXPECT_GT(picture.count_in(hi[0] + 5, 0, width, height, is_state_red), 50) << "legend swatch";
    EXPECT_GT(picture.count_in(hi[0] + 5, 0, width, height, is_state_grey), 50) << "legend swatch";
}

TEST_F(RenderPng, ResultDisplacementWithScalarBar)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_result(p, "result_fake_disp.vtu");
    const std::string path = output_path("result_displacement.png");
    view::ResultOptions options;
    options.field = "displacement";
    options.deform = 20.0;
    view::render_result_png(p, vtu, options, width, height, path);
    Picture picture(path);
    // Displacement grows with x: blue on the left, red on the right; with deform the square is
    // stretched by 20 % to 12 m wide, so the red side lies beyond where x = 10 was.
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    const auto left = projection.pixel({0.3, 8.5});
    const auto right = projection.pixel({11.7, 8.5});
    auto blue = [](const Rgb8& c) { return c[2] > 180 && c[0] < 60; };
    EXPECT_GE(picture.count_around(left[0], left[1], 2, blue), 15);
    EXPECT_GE(picture.count_around(right[0], right[1], 2, is_state_red), 15);
    // The scalar bar on the right: the full rainbow, red at the top, blue at the bottom.
    const int bar_x0 = right[0] + 10;
    EXPECT_GT(picture.count_in(bar_x0, 0, width, height, blue), 100) << "scalar bar";
    EXPECT_GT(picture.count_in(bar_x0, 0, width, height, is_state_red), 100) << "scalar bar";
}

TEST_F(RenderPng, ResultErrors)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_result(p, "result_fake_err.vtu");
    const std::string path = output_path("result_bad.png");
    view::ResultOptions options;
    options.field = "pressure";
    try {
        view::render_result_png(p, vtu, options, 200, 200, path);
        ADD_FAILURE() << "expected an exception";
    } catch (const view::ResultFieldError& e) {
        EXPECT_NE(std::string(e.what()).find("plastic_state, plastic_strain"), std::string::npos) << e.what();
    }
    options.field = "stress_xx";  // a known field the fake file lacks
    try {
        view::render_result_png(p, vtu, options, 200, 200, path);
        ADD_FAILURE() << "expected an exception";
    } catch (const view::ResultFieldError& e) {
        EXPECT_NE(std::string(e.what()).find("available: plastic_state, displacement"), std::string::npos) << e.what();
    }
    options.field = "plastic_state";
    EXPECT_THROW(view::render_result_png(p, output_path("no_such.vtu"), options, 200, 200, path), std::runtime_error);
    const Preprocessed coarse = preprocess_model(tunnel_model(), PreprocessStage::Cut);  // no mesh
    try {
        view::render_result_png(coarse, vtu, options, 200, 200, path);
        ADD_FAILURE() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cells but the model's mesh has"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
}

namespace {

/// A square of 2 m blocks (two joint sets) under an in-situ stress, run one step: every joint
/// carries about the same force.
struct JointedSquare {
    Preprocessed model;
    std::string vtu, vtp;
};

const JointedSquare& jointed_square()
{
    static const JointedSquare square = [] {
        const char* text = R"({
  "format": "mcdda-model", "version": 2, "name": "jointed square",
  "materials": [ { "name": "rock", "young_modulus": 1e10, "poisson_ratio": 0.25, "unit_weight": 26000, "plastic": false } ],
  "joint_materials": [ { "name": "joint", "friction_angle": 35 } ],
  "regions": [ { "name": "rock", "material": "rock", "boundary": [[0,0],[20,0],[20,20],[0,20]] } ],
  "joint_sets": [ { "name": "A", "angle": 0, "spacing": 2, "origin": [0.5, 1] },
                  { "name": "B", "angle": 90, "spacing": 2, "origin": [1, 0.5] } ],
  "rollers": [ { "name": "base", "from": [0,0], "to": [20,0], "fixed": "y" },
               { "name": "left", "from": [0,0], "to": [0,20], "fixed": "x" },
               { "name": "right", "from": [20,0], "to": [20,20], "fixed": "x" } ],
  "edge_pressures": [ { "name": "top", "from": [0,20], "to": [20,20], "pressure": 2e6 } ],
  "gravity": [0, -9.81],
  "initial_stress": { "type": "gravity", "surface_y": 96.9, "k0": 0.8 },
  "mesh": { "size": 1.0, "min_angle": 30 },
  "analysis": { "type": "static", "steps": 1, "time_step": 1.0, "output_every": 1 }
})";
        JointedSquare s;
        const auto read = read_model_text(text, {}, "jointed square");
        if (!read.model) return s;
        s.model = preprocess_model(*read.model);
        if (!s.model.ok) return s;
        const fs::path dir = fs::path(MCDDA_TEST_OUTPUT_DIR) / "jointed-square";
        fs::remove_all(dir);
        {
            Simulation simulation(s.model);
            RunOutput output(dir.string(), "square");
            run_steps(simulation, &output, nullptr, nullptr);
        }
        s.vtu = (dir / "square_000001.vtu").string();
        s.vtp = (dir / "square_contacts_000001.vtp").string();
        return s;
    }();
    return square;
}

}  // namespace

// Every joint of the jointed square carries about the same force. Ticks a fixed share of the model
// long (6 %: 0.95 m on 2 m blocks) covered most of the picture; 0.3 of the median block size
// leaves the blocks in sight.
TEST_F(RenderPng, ContactForceTicksLeaveTheBlocksInSight)
{
    const JointedSquare& square = jointed_square();
    ASSERT_TRUE(square.model.ok);
    const Preprocessed& p = square.model;
    const std::string &vtu = square.vtu, &vtp = square.vtp;
    ASSERT_TRUE(fs::exists(vtu) && fs::exists(vtp));
    auto is_force_blue = [](const Rgb8& c) { return near(c, to_bytes(view::Rgb{0.0, 0.40, 0.75}), 20); };
    view::ResultOptions options;
    options.field = "plastic_state";
    options.contacts = vtp;
    const std::string drawn = output_path("result_contact_forces_in_situ.png");
    view::render_result_png(p, vtu, options, width, height, drawn);
    Picture picture(drawn);
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    const auto lo = projection.pixel({0.0, 0.0}), hi = projection.pixel({20.0, 20.0});
    EXPECT_GT(picture.count_in(std::min(lo[0], hi[0]), std::min(lo[1], hi[1]), std::max(lo[0], hi[0]),
                               std::max(lo[1], hi[1]), is_force_blue),
              500)
        << "the ticks are drawn";
    // The longest straight run of blue, across or along the rows (two ticks of the contacts on
    // either side of a joint, pointing away from each other), is at most two thirds of a block:
    // the old ticks, 6 % of the model (0.95 m each), made runs of 94 % of a block.
    int longest = 0;
    const int x0 = std::min(lo[0], hi[0]), x1 = std::max(lo[0], hi[0]), y0 = std::min(lo[1], hi[1]), y1 = std::max(lo[1], hi[1]);
    for (int x = x0; x <= x1; ++x)
        for (int y = y0, run = 0; y <= y1; ++y) {
            run = is_force_blue(picture.at(x, y)) ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    for (int y = y0; y <= y1; ++y)
        for (int x = x0, run = 0; x <= x1; ++x) {
            run = is_force_blue(picture.at(x, y)) ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    const double block_pixels = (x1 - x0) / 10.0;  // 2 m blocks across 20 m
    EXPECT_LT(longest, 0.65 * block_pixels) << "the ticks cover the blocks";
    EXPECT_GT(longest, block_pixels / 6.0) << "the ticks are long enough to read";
}

// Numbers drawn into a German picture use its decimal comma everywhere: title, legend rows, the
// colour scale's labels (formatted by VTK), the rulers and what the cursor tells; an English one
// keeps the point.
TEST_F(RenderPng, GermanPicturesWriteDecimalCommas)
{
    const JointedSquare& square = jointed_square();
    ASSERT_TRUE(square.model.ok);
    struct Restore {
        ~Restore() { view::set_picture_decimal_point('.'); }
    } restore;
    auto texts = [&](char point, view::ResultInfo& info, std::vector<std::string>& labels, std::string& told) {
        view::set_picture_decimal_point(point);
        view::ResultOptions options;
        options.contacts = square.vtp;
        options.field = "displacement";
        options.deform = 2.5;
        view::ResultProbe probe;
        Projection projection([&](vtkRenderer* r) {
            view::build_result_scene(r, square.model, square.vtu, options, &probe, &info);
            r->GetRenderWindow()->Render();
            vtkActor2DCollection* actors = r->GetActors2D();
            actors->InitTraversal();
            while (vtkActor2D* a = actors->GetNextActor2D())
                if (auto* bar = view::LocalisedScalarBar::SafeDownCast(a)) labels = bar->label_texts();
        });
        told = probe.describe(5.3, 5.7);
        options.field = "plastic_state";
        view::ResultInfo state;
        Projection legend([&](vtkRenderer* r) { view::build_result_scene(r, square.model, square.vtu, options, nullptr, &state); });
        info.legend = state.legend;
    };
    auto has = [](const std::vector<std::string>& rows, const std::string& part) {
        for (const std::string& row : rows)
            if (row.find(part) != std::string::npos) return true;
        return false;
    };
    view::ResultInfo german, english;
    std::vector<std::string> german_labels, english_labels;
    std::string german_told, english_told;
    texts(',', german, german_labels, german_told);
    texts('.', english, english_labels, english_told);

    EXPECT_NE(german.title.find("×2,5"), std::string::npos) << german.title;
    EXPECT_NE(english.title.find("×2.5"), std::string::npos) << english.title;
    // The largest contact force, e.g. "(1,04e+03 kN/m)".
    ASSERT_TRUE(has(german.legend, "kN/m"));
    for (const std::string& row : german.legend)
        if (row.find("kN/m") != std::string::npos) {
            EXPECT_NE(row.find(','), std::string::npos) << row;
            EXPECT_EQ(row.find('.'), std::string::npos) << row;
        }
    ASSERT_GE(german_labels.size(), 3u);
    ASSERT_EQ(german_labels.size(), english_labels.size());
    int commas = 0;
    for (std::size_t i = 0; i < german_labels.size(); ++i) {
        EXPECT_EQ(german_labels[i].find('.'), std::string::npos) << german_labels[i];
        std::string back = german_labels[i];
        for (char& c : back)
            if (c == ',') c = '.', ++commas;
        EXPECT_EQ(back, english_labels[i]);
    }
    EXPECT_GT(commas, 0) << "the colour scale's labels";
    EXPECT_NE(german_told.find(','), std::string::npos) << german_told;
    EXPECT_NE(english_told.find('.'), std::string::npos) << english_told;
    view::set_picture_decimal_point(',');
    EXPECT_EQ(view::with_picture_decimals("x 1.5 m, 2.e-05, file.json, v.1, 3."), "x 1,5 m, 2,e-05, file.json, v.1, 3.");
}

// A block resting on a base, bolted to it, run for a few steps: the contacts file of its last
// step drawn over the result shows the contact forces (blue, vertical, at the interface) and the
// bolt (green); the same picture without the file shows neither.
TEST_F(RenderPng, ResultContactForcesAndBolts)
{
    const char* text = R"({
  "format": "mcdda-model", "version": 2, "name": "bolted block",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "plastic": false } ],
  "joint_materials": [ { "name": "interface", "friction_angle": 30 } ],
  "regions": [ { "name": "base", "material": "rock", "boundary": [[0,0],[4,0],[4,1],[0,1]] },
               { "name": "block", "material": "rock", "boundary": [[1,1],[3,1],[3,2],[1,2]] } ],
  "rollers": [ { "name": "bottom", "from": [0,0], "to": [4,0], "fixed": "xy" } ],
  "bolts": [ { "name": "bolt", "from": [2.5,0.3], "to": [2.5,1.8], "stiffness": 1e7, "pretension": 20000 } ],
  "gravity": [0, -9.81],
  "mesh": { "size": 0.25, "min_angle": 30 },
  "analysis": { "type": "static", "steps": 5, "time_step": 1.0, "output_every": 5 }
})";
    const auto read = read_model_text(text, {}, "bolted block");
    ASSERT_TRUE(read.model);
    const Preprocessed p = preprocess_model(*read.model);
    ASSERT_TRUE(p.ok);
    const fs::path dir = fs::path(MCDDA_TEST_OUTPUT_DIR) / "bolted-block";
    fs::remove_all(dir);
    {
        Simulation simulation(p);
        RunOutput output(dir.string(), "bolted");
        run_steps(simulation, &output, nullptr, nullptr);
    }
    const std::string vtu = (dir / "bolted_000005.vtu").string(), vtp = (dir / "bolted_contacts_000005.vtp").string();
    ASSERT_TRUE(fs::exists(vtu) && fs::exists(vtp));
    auto is_force_blue = [](const Rgb8& c) { return near(c, to_bytes(view::Rgb{0.0, 0.40, 0.75}), 20); };
    auto is_bolt_green = [](const Rgb8& c) { return near(c, to_bytes(view::Rgb{0.0, 0.55, 0.25}), 20); };

    view::ResultOptions options;
    const std::string plain = output_path("result_without_contacts.png");
    view::render_result_png(p, vtu, options, width, height, plain);
    options.contacts = vtp;
    const std::string drawn = output_path("result_contact_forces.png");
    view::render_result_png(p, vtu, options, width, height, drawn);
    Picture without(plain), with(drawn);
    EXPECT_EQ(without.count_in(0, 0, width, height, is_force_blue), 0);
    EXPECT_EQ(without.count_in(0, 0, width, height, is_bolt_green), 0);

    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    // Contact forces stand on the interface y = 1 between x = 1 and 3; the bolt at x = 2.5.
    const auto a = projection.pixel({1.0, 1.0}), b = projection.pixel({3.0, 1.2});
    EXPECT_GT(with.count_in(a[0] - 2, a[1] - 30, b[0] + 2, b[1] + 30, is_force_blue), 40);
    const auto bolt_low = projection.pixel({2.5, 0.4}), bolt_high = projection.pixel({2.5, 1.7});
    EXPECT_GT(with.count_in(bolt_low[0] - 4, bolt_low[1], bolt_low[0] + 4, bolt_high[1], is_bolt_green),
              (bolt_high[1] - bolt_low[1]) / 2);
    // Nothing blue far from the interface (the block's top).
    const auto top = projection.pixel({2.0, 1.9});
    EXPECT_EQ(with.count_around(top[0], top[1], 3, is_force_blue), 0);
    // The bolt's axial force is written at its middle (dark digits over a light ground) and
    // told under the cursor.
    auto is_ink = [](const Rgb8& c) { return c[0] < 70 && c[1] < 70 && c[2] < 70; };
    const auto middle = projection.pixel({2.5, 1.05});
    const int ink_with = with.count_in(middle[0] - 40, middle[1], middle[0] + 40, middle[1] + 16, is_ink);
    const int ink_without = without.count_in(middle[0] - 40, middle[1], middle[0] + 40, middle[1] + 16, is_ink);
    EXPECT_GT(ink_with, ink_without + 15) << "the bolt's force label";
    view::ResultProbe probe;
    {
        vtkNew<vtkRenderer> renderer;
        view::build_result_scene(renderer, p, vtu, options, &probe);
    }
    ASSERT_EQ(probe.bolts.size(), 1u);
    EXPECT_GT(probe.bolts[0].force, 0.0);  // pretensioned, then loaded by the block's weight
    char force[32];
    std::snprintf(force, sizeof force, "%.3g kN/m", probe.bolts[0].force / 1e3);
    const std::string on_bolt = probe.describe(2.5, 1.05);
    EXPECT_EQ(on_bolt.rfind("bolt, axial force " + std::string(force), 0), 0u) << on_bolt;
    EXPECT_NE(on_bolt.find("; "), std::string::npos) << on_bolt;  // the field there follows
    EXPECT_EQ(probe.describe(0.5, 0.5).find("bolt"), std::string::npos);

    EXPECT_THROW(view::render_result_png(p, vtu, [&] {
        view::ResultOptions o;
        o.contacts = (dir / "missing.vtp").string();
        return o;
    }(), width, height, output_path("never.png")), std::runtime_error);
}

// The slope's wedge slides along its joint: the contacts file of a later step drawn over the
// result shows the slip (orange lines) along that joint and nowhere else.
TEST_F(RenderPng, ResultJointSlip)
{
    const Preprocessed p = preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/slope-wedge.json", {"/analysis/steps=10"});
    ASSERT_TRUE(p.ok);
    const fs::path dir = fs::path(MCDDA_TEST_OUTPUT_DIR) / "slope-wedge";
    fs::remove_all(dir);
    {
        Simulation simulation(p);
        RunOutput output(dir.string(), "wedge");
        run_steps(simulation, &output, nullptr, nullptr);
    }
    const std::string vtu = (dir / "wedge_000010.vtu").string(), vtp = (dir / "wedge_contacts_000010.vtp").string();
    view::ResultOptions options;
    options.contacts = vtp;
    const std::string path = output_path("result_joint_slip.png");
    view::render_result_png(p, vtu, options, width, height, path);
    Picture picture(path);
    auto is_slip = [](const Rgb8& c) { return near(c, to_bytes(view::Rgb{0.95, 0.45, 0.0}), 20); };
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    // Along the joint from (12, 3) to (32.8, 15): slip at its middle; none at the slope's base.
    int along = 0;
    for (double t : {0.3, 0.5, 0.7}) {
        const auto q = projection.pixel({12.0 + t * 20.78, 3.0 + t * 12.0});
        along += picture.count_around(q[0], q[1], 6, is_slip);
    }
    EXPECT_GT(along, 20);
    const auto base = projection.pixel({30.0, -3.0});
    EXPECT_EQ(picture.count_around(base[0], base[1], 6, is_slip), 0);
}

// The mechanism of a strength reduction as `mcdda render --field displacement_increment` draws
// it: the planar wedge of examples/slope-wedge.json searched for its factor; the last saved
// step (the first factor that did not stand) holds the increments, the wedge above the joint at
// the warm end of the scale, the ground below blue, and the title names the factor instead of a
// step. (The wedge slides as one body, at the field's largest value; the legend rounds its top
// up to a tick, so that value is drawn orange to red depending on where it falls.)
TEST_F(RenderPng, StrengthReductionMechanism)
{
    const Preprocessed p =
        preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/slope-wedge.json", {"/analysis/type=\"strength_reduction\""});
    ASSERT_TRUE(p.ok);
    const fs::path dir = fs::path(MCDDA_TEST_OUTPUT_DIR) / "wedge-safety";
    fs::remove_all(dir);
    {
        StrengthReductionSearch search(p);
        RunOutput output(dir.string(), "wedge");
        ASSERT_EQ(search.run(&output, {}).status, RunStatus::Completed);
        ASSERT_TRUE(search.factor().found);
    }
    std::string vtu;  // the last saved step
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".vtu" && entry.path().string() > vtu) vtu = entry.path().string();
    ASSERT_FALSE(vtu.empty());
    view::ResultOptions options;
    options.field = "displacement_increment";
    const std::string path = output_path("result_mechanism.png");
    view::ResultInfo info;
    view::render_result_png(p, vtu, options, width, height, path, &info);
    EXPECT_NE(info.title.find("displacement increment — strengths divided by 0.63"), std::string::npos) << info.title;
    EXPECT_EQ(info.title.find("step"), std::string::npos) << info.title;
    Picture picture(path);
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, options); });
    const auto wedge = projection.pixel({22.0, 11.0});
    const auto ground = projection.pixel({30.0, 2.0});
    auto blue = [](const Rgb8& c) { return c[2] > 180 && c[0] < 60; };
    auto warm = [](const Rgb8& c) { return c[0] > 230 && c[1] < 130 && c[2] < 40; };
    EXPECT_GE(picture.count_around(wedge[0], wedge[1], 3, warm), 40);
    EXPECT_GE(picture.count_around(ground[0], ground[1], 3, blue), 40);
    EXPECT_EQ(picture.count_around(ground[0], ground[1], 3, warm), 0);
    // The step that stood before it has no increments: a clear error naming the field.
    options.field = "plastic_strain_increment";
    std::string stood;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".vtu" && entry.path().string() != vtu && entry.path().string() > stood)
            stood = entry.path().string();
    ASSERT_FALSE(stood.empty());
    EXPECT_THROW(view::render_result_png(p, stood, options, 200, 200, output_path("result_no_mechanism.png")),
                 view::ResultFieldError);
}

// Rulers and a scale bar in the bottom-left corner (and none when switched
// off), a title naming the field and what is known of the step over the picture.
TEST_F(RenderPng, ResultRulersScaleBarAndTitle)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_result(p, "result_fake_axes.vtu");
    view::ResultOptions options;
    options.field = "displacement";
    const std::string with_path = output_path("result_axes.png"), without_path = output_path("result_no_axes.png");
    view::ResultInfo info;
    view::render_result_png(p, vtu, options, width, height, with_path, &info);
    EXPECT_NE(info.title.find("displacement"), std::string::npos) << info.title;
    options.show_axes = false;
    view::render_result_png(p, vtu, options, width, height, without_path);
    Picture with(with_path), without(without_path);
    // Below and left of the model (outside its box, joints included): the rulers' lines, ticks
    // and numbers and the scale bar; nothing there without them.
    auto below_left = [&](const Picture& picture, bool axes) {
        view::ResultOptions o = options;
        o.show_axes = axes;
        Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, o); });
        const view::Box box = view::model_box(p);
        const auto lo = projection.pixel({box.xmin, box.ymin});
        return picture.count_in(0, 0, lo[0] - 4, height, is_dark) + picture.count_in(lo[0] - 4, 0, width / 2, lo[1] - 4, is_dark);
    };
    EXPECT_GT(below_left(with, true), 200) << "rulers and scale bar";
    EXPECT_LT(below_left(without, false), 5);
    // The title: dark text in the top-left corner of both.
    EXPECT_GT(with.count_in(0, height - 22, width / 2, height, is_dark), 40);
    EXPECT_GT(without.count_in(0, height - 22, width / 2, height, is_dark), 40);
}

// The desktop view makes its rulers before its window knows the screen's pixel ratio (at 72 dpi);
// drawn into a window of 144 dpi they take that window's resolution: the numbers of the left
// ruler stand right of x = 60 px (its line is at 100 px), where 72-dpi rulers leave nothing.
TEST_F(RenderPng, RulersFollowTheWindowsResolution)
{
    const int side = 1600;  // render_scene_png gives a 1600-pixel picture 144 dpi
    ASSERT_EQ(view::png_dpi(side, side), 144);
    const std::string path = output_path("rulers_144dpi.png");
    view::render_scene_png(
        [](vtkRenderer* r) {
            r->SetBackground(1.0, 1.0, 1.0);
            r->AddViewProp(view::make_axes_and_scale_bar(view::Box{0.0, 0.0, 10.0, 10.0}, 72.0));
            vtkCamera* camera = r->GetActiveCamera();
            camera->ParallelProjectionOn();
            camera->SetFocalPoint(5.0, 5.0, 0.0);
            camera->SetPosition(5.0, 5.0, 10.0);
            camera->SetParallelScale(8.0);
        },
        side, side, path);
    Picture picture(path);
    EXPECT_GT(picture.count_in(60, side / 4, 95, 3 * side / 4, is_dark), 100) << "the left ruler's numbers";
}

// Round legend values, a uniform field shown as one value (not −1…1), a range
// chosen by hand, colour bands and other colour maps.
TEST_F(RenderPng, ResultLegendRoundsAndUniformFields)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_result(p, "result_fake_legend.vtu");  // ux = 0.01 x, uy = 0
    view::ResultOptions options;
    options.field = "ux";
    const view::ResultInfo ux = drawn(p, vtu, options);
    // The field spans about 0…0.1 m (minus the mesh's round-off): the ends are round numbers.
    const double step = view::nice_step((ux.range_max - ux.range_min) / 5.0);
    EXPECT_NEAR(ux.range_min / step, std::round(ux.range_min / step), 1e-9);
    EXPECT_NEAR(ux.range_max / step, std::round(ux.range_max / step), 1e-9);
    EXPECT_LE(ux.range_min, 0.0);
    EXPECT_GE(ux.range_max, 0.1 - 1e-12);
    EXPECT_LT(ux.range_max, 0.11);
    options.field = "uy";  // zero everywhere
    const view::ResultInfo uy = drawn(p, vtu, options);
    EXPECT_LT(std::abs(uy.range_min), 1e-6);
    EXPECT_LT(std::abs(uy.range_max), 1e-6);
    options.field = "ux";
    options.range_min = -0.05, options.range_max = 0.2;
    const view::ResultInfo chosen = drawn(p, vtu, options);
    EXPECT_EQ(chosen.range_min, -0.05);
    EXPECT_EQ(chosen.range_max, 0.2);

    // Bands: few distinct colours in the model; grey: no saturated colour in it.
    auto model_colours = [&](const view::ResultOptions& o, const std::string& name, int* saturated) {
        const std::string path = output_path(name);
        view::render_result_png(p, vtu, o, width, height, path);
        Picture picture(path);
        Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, vtu, o); });
        std::set<Rgb8> colours;
        *saturated = 0;
        for (double x = 0.2; x < 9.8; x += 0.05) {
            const auto px = projection.pixel({x, 0.5});
            const Rgb8 c = picture.at(px[0], px[1]);
            colours.insert(c);
            if (std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}) > 60) ++*saturated;
        }
        return colours.size();
    };
    view::ResultOptions smooth;
    smooth.field = "ux";
    smooth.show_joints = false;
    int saturated = 0;
    EXPECT_GT(model_colours(smooth, "result_smooth.png", &saturated), 40u);
    EXPECT_GT(saturated, 100);
    view::ResultOptions banded = smooth;
    banded.bands = 5;
    EXPECT_LE(model_colours(banded, "result_bands.png", &saturated), 8u);
    view::ResultOptions grey = smooth;
    grey.colour_map = view::ColourMap::Grey;
    model_colours(grey, "result_grey.png", &saturated);
    EXPECT_EQ(saturated, 0);
}

// The automatic deformation scale draws the largest displacement as 5 % of
// the model's size, and a scale that turns elements inside out is reported.
TEST_F(RenderPng, ResultAutoDeformationAndInvertedElements)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_stress_result(p, "result_fake_shrink.vtu");  // ux = −0.01 x
    view::ResultOptions options;
    options.field = "displacement";
    options.deform_auto = true;
    const view::ResultInfo automatic = drawn(p, vtu, options);
    EXPECT_NEAR(automatic.max_displacement, 0.1, 1e-9);  // at x = 10 m
    EXPECT_NEAR(automatic.deform_factor * automatic.max_displacement, 0.05 * view::model_box(p).size(), 1e-9);
    EXPECT_EQ(automatic.inverted_elements, 0);
    options.deform_auto = false;
    options.deform = 50.0;  // x (1 − 0.5): still the right way round
    EXPECT_EQ(drawn(p, vtu, options).inverted_elements, 0);
    options.deform = 200.0;  // x (1 − 2): every element mirrored
    const view::ResultInfo mirrored = drawn(p, vtu, options);
    EXPECT_EQ(mirrored.inverted_elements, static_cast<int>(p.mesh.triangles.size()));
}

// The geotechnical sign convention: stresses negated, σ1 the major compressive
// stress (σ1 ≥ σ3), the convention named in the legend and the probe.
TEST_F(RenderPng, ResultStressSignConvention)
{
    const Preprocessed p = preprocess_model(tunnel_model());
    const std::string vtu = write_fake_stress_result(p, "result_fake_stress.vtu");
    auto probe_at = [&](const std::string& field, view::StressSign sign, Point2 q, std::string* title = nullptr) {
        view::ResultOptions options;
        options.field = field;
        options.stress_sign = sign;
        view::ResultProbe probe;
        const view::ResultInfo info = drawn(p, vtu, options, &probe);
        if (title) *title = info.title;
        double v = std::numeric_limits<double>::quiet_NaN();
        EXPECT_TRUE(probe.valueAt(q.x, q.y, &v));
        return v * (probe.units == "MPa" ? 1e6 : 1e3);  // in the legend's units: to Pa
    };
    const Point2 q{8.5, 8.5};
    std::string tension_title, compression_title;
    const double sxx_t = probe_at("stress_xx", view::StressSign::TensionPositive, q, &tension_title);
    const double sxx_c = probe_at("stress_xx", view::StressSign::CompressionPositive, q, &compression_title);
    EXPECT_LT(sxx_t, 0.0);
    EXPECT_DOUBLE_EQ(sxx_c, -sxx_t);
    EXPECT_NE(tension_title.find("tension +"), std::string::npos) << tension_title;
    EXPECT_NE(compression_title.find("compression +"), std::string::npos) << compression_title;
    const double s1_t = probe_at("stress_1", view::StressSign::TensionPositive, q);
    const double s3_t = probe_at("stress_3", view::StressSign::TensionPositive, q);
    const double s1_c = probe_at("stress_1", view::StressSign::CompressionPositive, q);
    const double s3_c = probe_at("stress_3", view::StressSign::CompressionPositive, q);
    EXPECT_GE(s1_t, s3_t);
    EXPECT_GE(s1_c, s3_c);  // σ1 ≥ σ3 in compression too
    EXPECT_DOUBLE_EQ(s1_c, -s3_t);
    EXPECT_DOUBLE_EQ(s3_c, -s1_t);
    EXPECT_GT(s1_c, 0.0);  // both principal stresses are compressive here
}


// The live picture of a staged run names the stage as the saved steps' pictures do
// (the snapshot carries it).
TEST_F(RenderPng, LiveResultTitleNamesTheStage)
{
    Model m = tunnel_model();
    Stage in_situ;
    in_situ.name = "in situ";
    in_situ.analysis = m.analysis;
    Stage dig = in_situ;
    dig.name = "excavation";
    m.stages = {in_situ, dig};
    const Preprocessed p = preprocess_model(m);
    ASSERT_TRUE(p.ok);
    ResultSnapshot s;
    s.step = 7;
    s.total_steps = 10;
    s.time = 7.0;
    s.stage = 2;
    s.displacement.assign(2 * p.mesh.nodes.size(), 0.0);
    view::ResultOptions options;
    options.field = "displacement";
    view::ResultInfo info;
    Projection projection([&](vtkRenderer* r) { view::build_result_scene(r, p, s, options, nullptr, &info); });
    EXPECT_NE(info.title.find("step 7"), std::string::npos) << info.title;
    EXPECT_NE(info.title.find("stage \"excavation\""), std::string::npos) << info.title;
}
