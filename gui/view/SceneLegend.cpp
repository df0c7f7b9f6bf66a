#include "view/SceneLegend.hpp"

#include "view/PictureText.hpp"
#include "view/Symbols.hpp"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace mcdda::view {

namespace {

constexpr int title_points = 14;
constexpr int label_points = 12;

/// Pixel sizes of the layout at a given DPI.
struct Metrics {
    double k;  ///< pixels per point
    double pad, title_row, row, icon_w, icon_h, gap;
    explicit Metrics(double dpi)
        : k(dpi / 72.0), pad(9 * k), title_row(24 * k), row(21 * k), icon_w(34 * k),
          icon_h(14 * k), gap(9 * k) {}
};

void style_text(vtkTextProperty* t, int points, bool bold)
{
    t->SetFontFamilyToArial();
    t->SetFontSize(points);
    t->SetBold(bold);
    t->SetColor(palette::text.data());
    t->SetJustificationToLeft();
    t->SetVerticalJustificationToCentered();
}

int text_width(const std::string& s, int points, bool bold, double dpi)
{
    if (s.empty()) return 0;
    vtkNew<vtkTextProperty> t;
    style_text(t, points, bold);
    int box[4] = {0, 0, 0, 0};
    vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
    if (renderer == nullptr || !renderer->GetBoundingBox(t, s, box, static_cast<int>(std::lround(dpi))))
        return static_cast<int>(std::lround(0.6 * points * dpi / 72.0 * s.size()));  // estimate
    return box[1] - box[0] + 1;
}

/// A 2-D actor drawing `shapes` given in pixels relative to the legend's top left corner.
void add_shapes_2d(vtkRenderer* renderer, vtkCoordinate* anchor, Point2 origin, const Shapes& shapes,
                   const Rgb& color, double line_width, double opacity = 1.0)
{
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkCellArray> polys;
    auto add_points = [&](const std::vector<Point2>& list, vtkCellArray* cells) {
        cells->InsertNextCell(static_cast<vtkIdType>(list.size()));
        for (const Point2& q : list) cells->InsertCellPoint(points->InsertNextPoint(q.x, q.y, 0.0));
    };
    for (const auto& l : shapes.lines) add_points(l, lines);
    for (const auto& f : shapes.fills) add_points(f, polys);
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    data->SetPolys(polys);

    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(data);
    vtkNew<vtkActor2D> actor;
    actor->SetMapper(mapper);
    actor->GetPositionCoordinate()->SetCoordinateSystemToViewport();
    actor->GetPositionCoordinate()->SetReferenceCoordinate(anchor);
    actor->GetPositionCoordinate()->SetValue(origin.x, origin.y);
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    actor->GetProperty()->SetLineWidth(static_cast<float>(line_width));
    actor->GetProperty()->SetOpacity(opacity);
    renderer->AddActor2D(actor);
}

void add_text(vtkRenderer* renderer, vtkCoordinate* anchor, Point2 at, const std::string& s, int points,
              bool bold)
{
    vtkNew<vtkTextActor> text;
    text->SetInput(s.c_str());
    style_text(text->GetTextProperty(), points, bold);
    text->GetPositionCoordinate()->SetCoordinateSystemToViewport();
    text->GetPositionCoordinate()->SetReferenceCoordinate(anchor);
    text->GetPositionCoordinate()->SetValue(at.x, at.y);
    renderer->AddActor2D(text);
}

/// The icon of `e` inside the box centred at `c` (pixels).
Shapes icon_shapes(const LegendEntry& e, Point2 c, const Metrics& m)
{
    const double w = m.icon_w / 2, h = m.icon_h / 2;
    Shapes s;
    switch (e.icon) {
    case LegendEntry::Icon::Swatch:
        s.fills.push_back({{c.x - w, c.y - h}, {c.x + w, c.y - h}, {c.x + w, c.y + h}, {c.x - w, c.y + h}});
        break;
    case LegendEntry::Icon::Line:
        s.lines.push_back({{c.x - w, c.y}, {c.x + w, c.y}});
        break;
    case LegendEntry::Icon::Pin: {
        const double size = m.icon_h / 1.3;
        s = fixed_point_symbol({c.x, c.y + 0.65 * size}, {0, -1}, size);
        break;
    }
    case LegendEntry::Icon::Roller: {
        const double size = m.icon_h / 1.25;
        s = roller_symbol({c.x, c.y + 0.62 * size}, {0, -1}, size);
        break;
    }
    case LegendEntry::Icon::Arrow:
        s = arrow({c.x - w, c.y}, {c.x + w, c.y}, 9 * m.k, 9 * m.k, 2.5 * m.k);
        break;
    case LegendEntry::Icon::Pressure:
        s.lines.push_back({{c.x - w, c.y + h}, {c.x + w, c.y + h}});
        for (double f : {-0.75, 0.0, 0.75})
            s.append(arrow({c.x + f * w, c.y + h}, {c.x + f * w, c.y - h}, 6 * m.k, 6 * m.k, 1.8 * m.k));
        break;
    case LegendEntry::Icon::Diamond:
        s = measurement_symbol(c, m.icon_h * 0.9);
        break;
    case LegendEntry::Icon::Dashpot:
    case LegendEntry::Icon::CompliantBase: {  // a dashed line along the top with a dashpot hanging from it
        const double size = m.icon_h / 1.5;
        for (double x = -w; x < w; x += 0.95 * size)
            s.lines.push_back({{c.x + x, c.y + h}, {c.x + std::min(w, x + 0.6 * size), c.y + h}});
        s.append(dashpot_symbol({c.x, c.y + h}, {0, -1}, size));
        if (e.icon == LegendEntry::Icon::CompliantBase)
            s.append(arrow({c.x + 0.6 * w, c.y - h}, {c.x + 0.6 * w, c.y + h}, 5 * m.k, 5 * m.k, 1.5 * m.k));
        break;
    }
    case LegendEntry::Icon::WaterTable:  // the line with its ▽ (pixels: y grows upwards here too)
        s.lines.push_back({{c.x - w, c.y - 0.1 * h}, {c.x + w, c.y - 0.1 * h}});
        s.append(water_table_symbol({c.x, c.y - 0.1 * h}, m.icon_h * 0.7));
        break;
    }
    return s;
}

std::string material_label(const Model& model, int index)
{
    if (index < 0 || index >= static_cast<int>(model.materials.size())) return picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Unassigned material"));
    const std::string& name = model.materials[static_cast<std::size_t>(index)].name;
    return name.empty() ? picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Material")) + " " + std::to_string(index + 1) : name;
}

}  // namespace

std::string legend_title(const Preprocessed& p)
{
    std::string title = p.model.name.empty() ? picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Legend")) : p.model.name;
    // Short enough that the legend leaves the model room in a window of the default size.
    if (title.size() > 32) {
        std::size_t cut = 29;
        while (cut > 0 && (static_cast<unsigned char>(title[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
        title = title.substr(0, cut) + "...";
    }
    return title;
}

std::vector<LegendEntry> legend_entries(const Preprocessed& p, const SceneOptions& options)
{
    std::vector<LegendEntry> entries;
    if (!options.show_legend) return entries;
    const Model& m = p.model;

    std::set<int> used;  // materials actually drawn
    if (!p.mesh.triangles.empty()) {
        used.insert(p.mesh.triangle_material.begin(), p.mesh.triangle_material.end());
    } else if (!p.blocks.empty()) {
        for (const Block& b : p.blocks) used.insert(b.material);
    } else {
        for (const Region& r : m.regions) used.insert(r.material);
    }
    for (int index : used) {
        const int shown = index >= 0 && index < static_cast<int>(m.materials.size()) ? index : -1;
        entries.push_back({LegendEntry::Icon::Swatch, material_color(shown), material_label(m, index)});
    }
    if (!m.regions.empty() || !p.blocks.empty())
        entries.push_back({LegendEntry::Icon::Line, palette::block_outline,
                           p.blocks.empty() ? picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Region boundary"))
                                            : picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Block boundary"))});
    if (options.show_joints && !m.joints.empty())
        entries.push_back({LegendEntry::Icon::Line, palette::joint, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Joint"))});
    if (options.show_water && water_of_stage(m, options.stage).present())
        entries.push_back({LegendEntry::Icon::WaterTable, palette::water, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Water table"))});
    if (options.show_supports && !m.fixed_points.empty())
        entries.push_back({LegendEntry::Icon::Pin, palette::support, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Fixed point"))});
    // Rollers fixing both directions are drawn as pins (see roller_shapes).
    const bool fixed_lines = std::any_of(m.rollers.begin(), m.rollers.end(),
                                         [](const Roller& r) { return r.fix_x && r.fix_y; });
    const bool rollers = std::any_of(m.rollers.begin(), m.rollers.end(),
                                     [](const Roller& r) { return r.fix_x != r.fix_y; });
    if (options.show_supports && fixed_lines)
        entries.push_back({LegendEntry::Icon::Pin, palette::support, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Fixed line (x and y)"))});
    if (options.show_supports && rollers)
        entries.push_back({LegendEntry::Icon::Roller, palette::support, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Roller"))});
    if (options.show_supports && !m.bolts.empty())
        entries.push_back({LegendEntry::Icon::Line, palette::bolt, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Bolt"))});
    if (options.show_supports && !m.absorbing_boundaries.empty())
        entries.push_back({LegendEntry::Icon::Dashpot, palette::absorbing, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Absorbing boundary"))});
    if (options.show_supports && m.base_motion.kind == BaseMotion::Kind::Compliant)
        entries.push_back({LegendEntry::Icon::CompliantBase, palette::absorbing, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Compliant base (earthquake input)"))});
    if (options.show_loads && !m.point_loads.empty())
        entries.push_back({LegendEntry::Icon::Arrow, palette::point_load, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Point load"))});
    if (options.show_loads && !m.edge_pressures.empty())
        entries.push_back({LegendEntry::Icon::Pressure, palette::pressure, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Edge pressure"))});
    if (options.show_points && !m.measurement_points.empty())
        entries.push_back({LegendEntry::Icon::Diamond, palette::measurement, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "Measurement point"))});
    return entries;
}

int legend_margin(double dpi) { return static_cast<int>(std::lround(10.0 * dpi / 72.0)); }

int legend_width(const std::string& title, const std::vector<LegendEntry>& entries, double dpi)
{
    if (entries.empty()) return 0;
    const Metrics m(dpi);
    int labels = 0;
    for (const LegendEntry& e : entries) labels = std::max(labels, text_width(e.label, label_points, false, dpi));
    const double body = m.icon_w + m.gap + labels;
    const double inner = std::max(body, static_cast<double>(text_width(title, title_points, true, dpi)));
    return static_cast<int>(std::ceil(2 * m.pad + inner));
}

void add_legend(vtkRenderer* renderer, const std::string& title, const std::vector<LegendEntry>& entries,
                double dpi)
{
    if (renderer == nullptr || entries.empty()) return;
    const Metrics m(dpi);
    const double width = legend_width(title, entries, dpi);
    const double height =
        std::ceil(m.pad + m.title_row + m.row * static_cast<double>(entries.size()) + 0.6 * m.pad);
    const double margin = legend_margin(dpi);

    // Everything below is placed relative to the box's top left corner, which hangs from the
    // viewport's top right corner: it stays put when the window is resized.
    vtkNew<vtkCoordinate> anchor;
    anchor->SetCoordinateSystemToNormalizedViewport();
    anchor->SetValue(1.0, 1.0);
    const Point2 origin{-margin - width, -margin};

    Shapes box;
    box.fills.push_back({{0, 0}, {width, 0}, {width, -height}, {0, -height}});
    add_shapes_2d(renderer, anchor, origin, box, {1.0, 1.0, 1.0}, 1.0, 0.92);
    Shapes frame;
    const double e = 0.5;  // on pixel centres, so every side of a 1 px frame shows
    frame.lines.push_back({{e, -e}, {width - e, -e}, {width - e, e - height}, {e, e - height}, {e, -e}});
    add_shapes_2d(renderer, anchor, origin, frame, palette::legend_frame, m.k);

    add_text(renderer, anchor, {origin.x + m.pad, origin.y - m.pad - m.title_row / 2}, title, title_points, true);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const LegendEntry& e = entries[i];
        const double y = -m.pad - m.title_row - (static_cast<double>(i) + 0.5) * m.row;
        const Point2 centre{m.pad + m.icon_w / 2, y};
        const Shapes icon = icon_shapes(e, centre, m);
        const bool thick = e.icon == LegendEntry::Icon::Line;
        add_shapes_2d(renderer, anchor, origin, icon, e.color, (thick ? 3.0 : 1.5) * m.k);
        if (e.icon == LegendEntry::Icon::Swatch) {  // dark edge so light swatches stand out
            Shapes edge;
            edge.lines.push_back(icon.fills.front());
            edge.lines.back().push_back(icon.fills.front().front());
            add_shapes_2d(renderer, anchor, origin, edge, palette::block_outline, m.k);
        }
        add_text(renderer, anchor, {origin.x + m.pad + m.icon_w + m.gap, origin.y + y}, e.label, label_points,
                 false);
    }
}

}  // namespace mcdda::view
