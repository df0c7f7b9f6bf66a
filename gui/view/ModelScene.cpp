#include "view/ModelScene.hpp"

#include "view/FlatActor.hpp"
#include "view/Palette.hpp"
#include "view/ScaleBar.hpp"
#include "view/SceneGeometry.hpp"
#include "view/SceneLegend.hpp"
#include "view/Symbols.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkContourTriangulator.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindow.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace mcdda::view {

namespace {

/// Depth of each layer, in units of the model size ×1e-3. The camera looks down −z with a
/// parallel projection, so these offsets only decide what is drawn over what.
enum Layer { fill_layer = 0, mesh_layer = 1, outline_layer = 2, joint_layer = 3, water_layer = 4, symbol_layer = 5 };

struct Style {
    double pixel = 1.0;     ///< pixels per point (window DPI / 72): scales line widths and text
    double z_step = 1e-3;   ///< m between layers
    double symbol = 1.0;    ///< symbol size (m)
    std::vector<int> hidden_regions;  ///< SceneOptions::hidden_regions

    bool hidden(int region) const
    {
        return std::find(hidden_regions.begin(), hidden_regions.end(), region) != hidden_regions.end();
    }
    /// Whether mesh triangle t lies in a hidden region.
    bool hides_triangle(const Preprocessed& p, std::size_t t) const
    {
        if (hidden_regions.empty() || t >= p.mesh.triangle_block.size()) return false;
        const int b = p.mesh.triangle_block[t];
        return b >= 0 && b < static_cast<int>(p.blocks.size()) && hidden(p.blocks[static_cast<std::size_t>(b)].region);
    }
};

double dpi_of(vtkRenderer* renderer)
{
    vtkWindow* window = renderer->GetVTKWindow();
    const int dpi = window != nullptr ? window->GetDPI() : 72;
    return dpi > 0 ? dpi : 72;
}

std::array<unsigned char, 3> bytes(const Rgb& c)
{
    auto b = [](double v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    return {b(c[0]), b(c[1]), b(c[2])};
}


void add_shapes(vtkRenderer* renderer, const Shapes& shapes, const Rgb& color, double line_width, double z)
{
    if (shapes.empty()) return;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkCellArray> polys;
    auto add = [&](const std::vector<Point2>& list, vtkCellArray* cells) {
        cells->InsertNextCell(static_cast<vtkIdType>(list.size()));
        for (const Point2& q : list) cells->InsertCellPoint(points->InsertNextPoint(q.x, q.y, z));
    };
    for (const auto& l : shapes.lines)
        if (l.size() >= 2) add(l, lines);
    for (const auto& f : shapes.fills)
        if (f.size() >= 3) add(f, polys);
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    data->SetPolys(polys);
    renderer->AddActor(flat_actor(data, color, line_width));
}

/// Closed polylines of the given rings.
Shapes ring_lines(const std::vector<const Ring*>& rings)
{
    Shapes s;
    for (const Ring* r : rings) {
        if (r->size() < 2) continue;
        std::vector<Point2> l(r->begin(), r->end());
        l.push_back(r->front());
        s.lines.push_back(std::move(l));
    }
    return s;
}

/// Fills with a colour per cell, built up polygon by polygon.
class FillBuilder {
public:
    explicit FillBuilder(double z) : z_(z) { colors_->SetNumberOfComponents(3); }

    /// The mesh nodes; call once, before any add_triangle and on an empty builder.
    void add_nodes(const std::vector<Point2>& nodes)
    {
        for (const Point2& q : nodes) points_->InsertNextPoint(q.x, q.y, z_);
    }
    /// A mesh triangle by node indices.
    void add_triangle(const std::array<int, 3>& t, const Rgb& color)
    {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        polys_->InsertNextCell(3, ids);
        push_color(color);
    }

    /// A polygon with holes, triangulated here (outer ring made counter-clockwise, holes
    /// clockwise, as vtkContourTriangulator expects).
    void add_polygon(const Ring& outer, const std::vector<Ring>& holes, const Rgb& color)
    {
        if (outer.size() < 3) return;
        vtkNew<vtkCellArray> segments;
        auto add_ring = [&](const Ring& ring, bool counter_clockwise) {
            if (ring.size() < 3) return;
            Ring r = ring;
            if ((signed_area(r) > 0.0) != counter_clockwise) std::reverse(r.begin(), r.end());
            const vtkIdType first = points_->GetNumberOfPoints();
            for (const Point2& q : r) points_->InsertNextPoint(q.x, q.y, z_);
            const auto n = static_cast<vtkIdType>(r.size());
            for (vtkIdType i = 0; i < n; ++i) {
                const vtkIdType ids[2] = {first + i, first + (i + 1) % n};
                segments->InsertNextCell(2, ids);
            }
        };
        add_ring(outer, true);
        for (const Ring& h : holes) add_ring(h, false);

        vtkNew<vtkPolyData> contours;
        contours->SetPoints(points_);
        contours->SetLines(segments);
        const vtkIdType before = polys_->GetNumberOfCells();
        const double normal[3] = {0.0, 0.0, 1.0};
        vtkContourTriangulator::TriangulateContours(contours, 0, segments->GetNumberOfCells(), polys_, normal);
        for (vtkIdType i = before; i < polys_->GetNumberOfCells(); ++i) push_color(color);
    }

    vtkSmartPointer<vtkActor> actor() const
    {
        vtkNew<vtkPolyData> data;
        data->SetPoints(points_);
        data->SetPolys(polys_);
        data->GetCellData()->SetScalars(colors_);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(data);
        mapper->SetScalarModeToUseCellData();
        mapper->SetColorModeToDirectScalars();
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        actor->GetProperty()->LightingOff();
        return actor;
    }

    bool empty() const { return polys_->GetNumberOfCells() == 0; }

private:
    void push_color(const Rgb& c)
    {
        const auto b = bytes(c);
        colors_->InsertNextTypedTuple(b.data());
    }

    double z_;
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> polys_;
    vtkNew<vtkUnsignedCharArray> colors_;
};

int material_of_triangle(const Preprocessed& p, std::size_t t)
{
    if (t < p.mesh.triangle_material.size()) return p.mesh.triangle_material[t];
    if (t < p.mesh.triangle_block.size()) {
        const int b = p.mesh.triangle_block[t];
        if (b >= 0 && b < static_cast<int>(p.blocks.size())) return p.blocks[static_cast<std::size_t>(b)].material;
    }
    return -1;
}

Rgb color_of_material(const Model& m, int index)
{
    return material_color(index >= 0 && index < static_cast<int>(m.materials.size()) ? index : -1);
}

void add_fill(vtkRenderer* renderer, const Preprocessed& p, const Style& st)
{
    FillBuilder fill(fill_layer * st.z_step);
    const Mesh& mesh = p.mesh;
    const auto node_count = static_cast<int>(mesh.nodes.size());
    if (!mesh.triangles.empty()) {
        fill.add_nodes(mesh.nodes);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            if (std::any_of(tri.begin(), tri.end(), [&](int n) { return n < 0 || n >= node_count; })) continue;
            if (st.hides_triangle(p, t)) continue;
            fill.add_triangle(tri, color_of_material(p.model, material_of_triangle(p, t)));
        }
    } else if (!p.blocks.empty()) {
        for (const Block& b : p.blocks)
            if (!st.hidden(b.region)) fill.add_polygon(b.outer, b.holes, color_of_material(p.model, b.material));
    } else {
        for (std::size_t i = 0; i < p.model.regions.size(); ++i) {
            const Region& r = p.model.regions[i];
            if (!st.hidden(static_cast<int>(i))) fill.add_polygon(r.boundary, r.holes, color_of_material(p.model, r.material));
        }
    }
    if (!fill.empty()) renderer->AddActor(fill.actor());
}

void add_mesh_edges(vtkRenderer* renderer, const Preprocessed& p, const Style& st)
{
    const Mesh& mesh = p.mesh;
    if (mesh.triangles.empty()) return;
    const auto node_count = static_cast<int>(mesh.nodes.size());
    std::vector<std::pair<int, int>> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (st.hides_triangle(p, i)) continue;
        const auto& t = mesh.triangles[i];
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
            if (a < 0 || b < 0 || a >= node_count || b >= node_count) continue;
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    vtkNew<vtkPoints> points;
    const double z = mesh_layer * st.z_step;
    for (const Point2& q : mesh.nodes) points->InsertNextPoint(q.x, q.y, z);
    vtkNew<vtkCellArray> lines;
    for (const auto& [a, b] : edges) {
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    renderer->AddActor(flat_actor(data, palette::mesh_edge, std::max(1.0, 0.8 * st.pixel)));
}

void add_outlines(vtkRenderer* renderer, const Preprocessed& p, const Style& st)
{
    std::vector<const Ring*> rings;
    if (!p.blocks.empty()) {
        for (const Block& b : p.blocks) {
            if (st.hidden(b.region)) continue;
            rings.push_back(&b.outer);
            for (const Ring& h : b.holes) rings.push_back(&h);
        }
    } else {
        for (const Region& r : p.model.regions) {
            rings.push_back(&r.boundary);
            for (const Ring& h : r.holes) rings.push_back(&h);
        }
    }
    add_shapes(renderer, ring_lines(rings), palette::block_outline, 2.0 * st.pixel, outline_layer * st.z_step);
}

/// Whether `p` lies inside the ring (even–odd rule).
bool inside_ring(const Ring& ring, const Point2& p)
{
    bool inside = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
            p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
            inside = !inside;
    return inside;
}

bool inside_region(const Region& r, const Point2& p)
{
    if (r.boundary.size() < 3 || !inside_ring(r.boundary, p)) return false;
    return std::none_of(r.holes.begin(), r.holes.end(), [&](const Ring& h) { return h.size() >= 3 && inside_ring(h, p); });
}

void add_joints(vtkRenderer* renderer, const Preprocessed& p, const Style& st)
{
    const Model& model = p.model;
    // Not through regions hidden in the stage shown (an excavated opening).
    auto in_hidden_region = [&](const Point2& a, const Point2& b) {
        const Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
        for (int r : st.hidden_regions)
            if (r >= 0 && r < static_cast<int>(model.regions.size()) && inside_region(model.regions[static_cast<std::size_t>(r)], mid))
                return true;
        return false;
    };
    Shapes inside, outside;
    for (const Joint& j : model.joints)
        for (std::size_t i = 0; i + 1 < j.points.size(); ++i)
            for (const SegmentPiece& piece : split_by_material(model, j.points[i], j.points[i + 1])) {
                // A joint set's traces beyond the rock (openings, empty space) cut nothing: not
                // drawn. An explicit joint's are, lightly, to show where it was drawn wrong.
                if (!piece.in_material && j.joint_set >= 0) continue;
                if (!piece.in_material) outside.lines.push_back({piece.from, piece.to});
                // Before the blocks are cut, the traces as drawn.
                else if (p.blocks.empty() && !in_hidden_region(piece.from, piece.to))
                    inside.lines.push_back({piece.from, piece.to});
            }
    // Once cut, what the analysis uses is drawn as a joint: the block edges on one and the
    // cracks (joint pieces ending in the rock), so the picture shows the joints the analysis has.
    for (const Block& b : p.blocks) {
        for (std::size_t r = 0; r < b.tags.size(); ++r) {
            const Ring& ring = r == 0 ? b.outer : b.holes[r - 1];
            for (std::size_t k = 0; k < ring.size() && k < b.tags[r].size(); ++k) {
                const Point2 &from = ring[k], &to = ring[(k + 1) % ring.size()];
                if (b.tags[r][k].joint >= 0 && !in_hidden_region(from, to)) inside.lines.push_back({from, to});
            }
        }
        for (const Block::Crack& crack : b.cracks)
            if (!in_hidden_region(crack.from, crack.to)) inside.lines.push_back({crack.from, crack.to});
    }
    const double z = joint_layer * st.z_step;
    add_shapes(renderer, outside, palette::joint_outside, 1.5 * st.pixel, z);
    add_shapes(renderer, inside, palette::joint, 3.0 * st.pixel, z);
}

/// The water in force in the stage shown: its piezometric line across the model (held level
/// beyond its ends, as the solver does) with the ▽ symbol above the middle of the model.
void add_water(vtkRenderer* renderer, const Preprocessed& p, const SceneOptions& options, const Box& box, const Style& st)
{
    const Water& water = water_of_stage(p.model, options.stage);
    if (!water.present()) return;
    const std::vector<Point2>& line = water.piezometric_line;
    const double xmin = box.valid() ? box.xmin : line.front().x, xmax = box.valid() ? box.xmax : line.back().x;
    const Shapes shapes = water_table_shapes(water, xmin, xmax, 0.5 * (xmin + xmax), 1.5 * st.symbol);
    add_shapes(renderer, shapes, palette::water, 2.5 * st.pixel, water_layer * st.z_step);
}

void add_measurement_labels(vtkRenderer* renderer, const Model& model, const Style& st)
{
    for (const MeasurementPoint& m : model.measurement_points) {
        if (m.name.empty()) continue;
        vtkNew<vtkTextActor> text;
        text->SetInput(m.name.c_str());
        vtkTextProperty* t = text->GetTextProperty();
        t->SetFontFamilyToArial();
        t->SetFontSize(11);
        t->SetColor(palette::measurement.data());
        t->SetBackgroundColor(palette::background.data());
        t->SetBackgroundOpacity(0.75);
        t->SetJustificationToLeft();
        t->SetVerticalJustificationToBottom();
        text->GetPositionCoordinate()->SetCoordinateSystemToWorld();
        text->GetPositionCoordinate()->SetValue(m.point.x + 0.5 * st.symbol, m.point.y + 0.5 * st.symbol,
                                                symbol_layer * st.z_step);
        renderer->AddActor2D(text);
    }
}

}  // namespace

void build_model_scene(vtkRenderer* renderer, const Preprocessed& p, const SceneOptions& options)
{
    if (renderer == nullptr) return;
    const Box box = model_box(p);
    Style st;
    st.pixel = dpi_of(renderer) / 72.0;
    st.symbol = symbol_size(box);
    st.z_step = (box.size() > 0.0 ? box.size() : 1.0) * 1e-3;
    st.hidden_regions = options.hidden_regions;

    renderer->SetBackground(palette::background.data());
    renderer->GradientBackgroundOff();

    add_fill(renderer, p, st);
    if (options.show_mesh) add_mesh_edges(renderer, p, st);
    add_outlines(renderer, p, st);
    if (options.show_joints) add_joints(renderer, p, st);
    if (options.show_water) add_water(renderer, p, options, box, st);

    const double z = symbol_layer * st.z_step;
    // The supports, loads and bolts of the stage shown: a copy without those absent in it.
    std::optional<Model> staged;
    if (!options.hidden_items.empty()) {
        staged = p.model;
        auto drop_hidden = [&](auto& items) {
            items.erase(std::remove_if(items.begin(), items.end(),
                                       [&](const auto& item) {
                                           return std::count(options.hidden_items.begin(), options.hidden_items.end(),
                                                             item.name) > 0;
                                       }),
                        items.end());
        };
        drop_hidden(staged->fixed_points);
        drop_hidden(staged->rollers);
        drop_hidden(staged->point_loads);
        drop_hidden(staged->edge_pressures);
        drop_hidden(staged->bolts);
    }
    const Model& items = staged ? *staged : p.model;
    if (options.show_supports) {
        add_shapes(renderer, roller_shapes(items, st.symbol), palette::support, 2.0 * st.pixel, z);
        add_shapes(renderer, fixed_point_shapes(items, st.symbol), palette::support, 1.5 * st.pixel, z);
        Shapes bolts;  // rock bolts: a line between their anchors
        for (const Bolt& b : items.bolts) bolts.lines.push_back({b.from, b.to});
        add_shapes(renderer, bolts, palette::bolt, 3.0 * st.pixel, z);
        // Dashpots let waves out where the model is cut off: drawn with the supports they replace.
        add_shapes(renderer, absorbing_boundary_shapes(items, st.symbol), palette::absorbing, 2.0 * st.pixel, z);
        add_shapes(renderer, compliant_base_shapes(items, st.symbol), palette::absorbing, 2.0 * st.pixel, z);
    }
    if (options.show_loads) {
        add_shapes(renderer, edge_pressure_shapes(items, st.symbol), palette::pressure, 1.5 * st.pixel, z);
        add_shapes(renderer, point_load_shapes(items, st.symbol), palette::point_load, 1.5 * st.pixel, z);
    }
    if (options.show_points) {
        add_shapes(renderer, measurement_shapes(p.model, st.symbol), palette::measurement, 1.0 * st.pixel, z);
        add_measurement_labels(renderer, p.model, st);
    }
    add_legend(renderer, legend_title(p), legend_entries(p, options), dpi_of(renderer));
    if (options.show_axes && box.valid()) add_axes_and_scale_bar(renderer, box, dpi_of(renderer));  // not on nothing
    fit_camera(renderer, p, options);
}

void fit_camera(vtkRenderer* renderer, const Preprocessed& p, const SceneOptions& options)
{
    if (renderer == nullptr) return;
    const double dpi = dpi_of(renderer);
    const auto entries = legend_entries(p, options);
    const double reserved =
        entries.empty() ? 0.0 : legend_width(legend_title(p), entries, dpi) + 2.0 * legend_margin(dpi);
    if (options.show_axes)
        fit_camera(renderer, p, reserved, axes_left_pixels(dpi), axes_bottom_pixels(dpi));
    else
        fit_camera(renderer, p, reserved);
}

void fit_camera(vtkRenderer* renderer, const Preprocessed& p, double reserved, double left, double bottom, double top)
{
    if (renderer == nullptr) return;
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    if (!vtkMath::AreBoundsInitialized(b)) {
        const Box box = model_box(p);
        if (box.valid()) {
            b[0] = box.xmin, b[1] = box.xmax, b[2] = box.ymin, b[3] = box.ymax;
        } else {
            b[0] = -1, b[1] = 1, b[2] = -1, b[3] = 1;
        }
        b[4] = b[5] = 0.0;
    }
    const double cx = 0.5 * (b[0] + b[1]), cy = 0.5 * (b[2] + b[3]);
    double wx = b[1] - b[0], wy = b[3] - b[2];
    if (!(wx > 0.0) && !(wy > 0.0)) wx = wy = 2.0;  // a single point: show 2 m around it

    const int* size = renderer->GetSize();
    const double width = std::max(1, size[0]), height = std::max(1, size[1]);
    if (!(reserved > 0.0) || reserved > 0.45 * width) reserved = 0.0;  // narrow window: let the legend overlap instead
    if (left + reserved > 0.6 * width) left = 0.0;  // a tiny picture: axes over the model rather than no model
    if (bottom + top > 0.5 * height) bottom = top = 0.0;
    const double usable = width - reserved - left, usable_height = height - bottom - top;

    const double margin = 1.08;  // 4 % free on each side
    const double metres_per_pixel = margin * std::max(wy / usable_height, wx / usable);
    double half_height = 0.5 * metres_per_pixel * height;
    if (!(half_height > 0.0)) half_height = 1.0;
    // The model centred in the free part.
    const double fx = cx + 0.5 * (reserved - left) * metres_per_pixel;
    const double fy = cy + 0.5 * (top - bottom) * metres_per_pixel;

    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    const double distance = std::max({wx, wy, 1.0}) * 10.0;
    camera->SetFocalPoint(fx, fy, 0.0);
    camera->SetPosition(fx, fy, distance);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(half_height);
    renderer->ResetCameraClippingRange();
}

}  // namespace mcdda::view
