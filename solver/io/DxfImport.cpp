#include "io/DxfImport.hpp"

#include "geometry/PolygonChecks.hpp"
#include "io/DxfFileCheck.hpp"
#include "io/FileKind.hpp"
#include "io/TextEncoding.hpp"
#include "model/Defaults.hpp"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace mcdda {

namespace {

/// Metres per unit of the DXF $INSUNITS codes that make sense for a rock model; 0 otherwise.
double metres_per_insunit(int code)
{
    switch (code) {
    case 1: return 0.0254;    // inches
    case 2: return 0.3048;    // feet
    case 4: return 0.001;     // millimetres
    case 5: return 0.01;      // centimetres
    case 6: return 1.0;       // metres
    case 7: return 1000.0;    // kilometres
    case 10: return 0.9144;   // yards
    case 14: return 0.1;      // decimetres
    default: return 0.0;
    }
}

const char* unit_name(double metres_per_unit)
{
    if (metres_per_unit == 1.0) return "metres";
    if (metres_per_unit == 0.001) return "millimetres";
    if (metres_per_unit == 0.01) return "centimetres";
    if (metres_per_unit == 1000.0) return "kilometres";
    if (metres_per_unit == 0.0254) return "inches";
    if (metres_per_unit == 0.3048) return "feet";
    return "drawing units";
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool is_hole_layer(const std::string& layer)
{
    const std::string l = lower(layer);
    return l == "holes" || l == "hole" || l == "openings" || l == "opening";
}

struct Shape {
    std::string layer;
    std::vector<Point2> points;
    bool closed = false;
};

/// Collects the entities dxflib reads. Polylines arrive as a header and then their vertices
/// (LWPOLYLINE and POLYLINE alike); one is complete when the next entity or the sequence's end
/// comes.
class Collector : public DL_CreationAdapter {
public:
    std::vector<Shape> shapes;       ///< polylines and lines
    std::vector<Shape> points;       ///< one point each
    std::map<std::string, int> skipped;  ///< "CIRCLE on layer \"0\"" → count
    int insunits = -1;
    bool bulges = false, elevations = false;

    void addPolyline(const DL_PolylineData& data) override
    {
        finish();
        current_ = Shape{layer(), {}, (data.flags & 1) != 0};
        open_ = true;
    }
    void addVertex(const DL_VertexData& data) override
    {
        if (!open_) return;
        current_.points.push_back({data.x, data.y});
        bulges = bulges || data.bulge != 0.0;
        elevations = elevations || data.z != 0.0;
    }
    void endSequence() override { finish(); }
    void addLine(const DL_LineData& data) override
    {
        finish();
        shapes.push_back({layer(), {{data.x1, data.y1}, {data.x2, data.y2}}, false});
        elevations = elevations || data.z1 != 0.0 || data.z2 != 0.0;
    }
    void addPoint(const DL_PointData& data) override
    {
        finish();
        points.push_back({layer(), {{data.x, data.y}}, false});
    }
    void setVariableInt(const std::string& key, int value, int) override
    {
        if (key == "$INSUNITS") insunits = value;
    }
    // Everything else that is drawn is counted, to be reported.
    void addArc(const DL_ArcData&) override { skip("ARC"); }
    void addCircle(const DL_CircleData&) override { skip("CIRCLE"); }
    void addEllipse(const DL_EllipseData&) override { skip("ELLIPSE"); }
    void addSpline(const DL_SplineData&) override { skip("SPLINE"); }
    void addXLine(const DL_XLineData&) override { skip("XLINE"); }
    void addRay(const DL_RayData&) override { skip("RAY"); }
    void addInsert(const DL_InsertData&) override { skip("INSERT (block reference)"); }
    void addText(const DL_TextData&) override { skip("TEXT"); }
    void addMText(const DL_MTextData&) override { skip("MTEXT"); }
    void addHatch(const DL_HatchData&) override { skip("HATCH"); }
    void addSolid(const DL_SolidData&) override { skip("SOLID"); }
    void add3dFace(const DL_3dFaceData&) override { skip("3DFACE"); }
    void addTrace(const DL_TraceData&) override { skip("TRACE"); }
    void addImage(const DL_ImageData&) override { skip("IMAGE"); }
    void addLeader(const DL_LeaderData&) override { skip("LEADER"); }
    void addDimAlign(const DL_DimensionData&, const DL_DimAlignedData&) override { skip("DIMENSION"); }
    void addDimLinear(const DL_DimensionData&, const DL_DimLinearData&) override { skip("DIMENSION"); }
    void addDimRadial(const DL_DimensionData&, const DL_DimRadialData&) override { skip("DIMENSION"); }
    void addDimDiametric(const DL_DimensionData&, const DL_DimDiametricData&) override { skip("DIMENSION"); }
    void addDimAngular(const DL_DimensionData&, const DL_DimAngular2LData&) override { skip("DIMENSION"); }
    void addDimAngular3P(const DL_DimensionData&, const DL_DimAngular3PData&) override { skip("DIMENSION"); }
    void addDimOrdinate(const DL_DimensionData&, const DL_DimOrdinateData&) override { skip("DIMENSION"); }
    void addBlock(const DL_BlockData&) override { in_block_ = true; }
    void endBlock() override
    {
        finish();
        in_block_ = false;
    }

    /// Completes the polyline being read (at the end of the file too).
    void finish()
    {
        if (!open_) return;
        open_ = false;
        if (!in_block_) shapes.push_back(current_);
    }

private:
    // Drawings before AutoCAD 2007 name layers in the Windows code page, not UTF-8.
    std::string layer() { return as_utf8(getAttributes().getLayer()); }
    void skip(const std::string& kind)
    {
        finish();
        if (!in_block_) ++skipped[kind + " on layer \"" + layer() + "\""];
    }

    Shape current_;
    bool open_ = false;
    bool in_block_ = false;  // block definitions are drawn only through INSERTs, which are skipped
};

template <class Named>
int index_named(std::vector<Named>& list, const std::string& name, Named (*make)(const std::string&))
{
    for (std::size_t i = 0; i < list.size(); ++i)
        if (list[i].name == name) return static_cast<int>(i);
    list.push_back(make(name));
    return static_cast<int>(list.size()) - 1;
}

std::string joined(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

}  // namespace

double metres_per_unit_named(const std::string& name)
{
    static const std::map<std::string, double> units{{"m", 1.0},     {"mm", 0.001},   {"cm", 0.01},
                                                      {"km", 1000.0}, {"in", 0.0254}, {"ft", 0.3048}};
    const auto it = units.find(lower(name));
    return it == units.end() ? 0.0 : it->second;
}

DxfImportResult import_dxf_file(const std::string& path, const DxfImportOptions& options)
{
    DxfImportResult result;
    auto error = [&](const std::string& message) {
        result.diagnostics.push_back({Diagnostic::Severity::Error, "", message});
    };
    auto warning = [&](const std::string& message) {
        result.diagnostics.push_back({Diagnostic::Severity::Warning, "", message});
    };
    if (const std::string kind = not_a_regular_file(path); !kind.empty()) {
        error(kind == "does not exist" ? "cannot open " + path + ": no such file"
                                       : path + " " + kind + ", not a DXF drawing");
        return result;
    }
    // dxflib believes the file (counts, numbers, encoding): what it cannot cope with is refused
    // first.
    result.diagnostics = check_dxf_file(path);
    if (has_errors(result.diagnostics)) return result;
    Collector c;
    DL_Dxf dxf;
    if (!dxf.in(path, &c)) {
        error("cannot read " + path + " as a DXF drawing");
        return result;
    }
    c.finish();

    double scale = options.metres_per_unit;
    std::string units;
    if (scale > 0.0) {
        units = std::string(unit_name(scale)) + " (as given)";
    } else if (metres_per_insunit(c.insunits) > 0.0) {
        scale = metres_per_insunit(c.insunits);
        units = std::string(unit_name(scale)) + " ($INSUNITS " + std::to_string(c.insunits) + ")";
    } else {
        scale = 1.0;
        units = "metres (assumed)";
        warning(c.insunits <= 0 ? "the drawing does not say its units ($INSUNITS): read as metres; give --units if not"
                                : "the drawing's units ($INSUNITS " + std::to_string(c.insunits) +
                                      ") are not a length mcdda knows: read as metres; give --units if not");
    }
    if (c.bulges) warning("polylines with arc segments (bulges): the arcs are read as straight segments");
    if (c.elevations) warning("entities with z coordinates: z is ignored (the model is the x-y plane)");
    for (const auto& [what, count] : c.skipped)
        warning(std::to_string(count) + " " + what + " skipped: only LWPOLYLINE, POLYLINE, LINE and POINT are imported");

    Model m = new_model("", "");
    m.materials.clear();
    m.joint_materials.clear();
    m.default_joint_material = -1;
    std::vector<std::string> region_layers, joint_layers;
    std::vector<Shape> holes;
    auto scaled = [&](std::vector<Point2> points) {
        for (Point2& p : points) p = {p.x * scale, p.y * scale};
        // A closing vertex that repeats the first is dropped.
        if (points.size() > 2 && points.front().x == points.back().x && points.front().y == points.back().y)
            points.pop_back();
        return points;
    };
    int joint_count = 0, skipped_small = 0;
    for (const Shape& s : c.shapes) {
        std::vector<Point2> points = scaled(s.points);
        const bool closed = s.closed || (s.points.size() > 3 && s.points.front().x == s.points.back().x &&
                                         s.points.front().y == s.points.back().y);
        if (closed) {
            if (points.size() < 3 || std::abs(signed_area(points)) <= 0.0) {
                ++skipped_small;
                continue;
            }
            if (signed_area(points) < 0.0) std::reverse(points.begin(), points.end());  // counter-clockwise
            if (is_hole_layer(s.layer)) {
                holes.push_back({s.layer, points, true});
                continue;
            }
            Region r;
            r.material = index_named(m.materials, s.layer, &default_rock);
            r.boundary = points;
            if (std::find(region_layers.begin(), region_layers.end(), s.layer) == region_layers.end())
                region_layers.push_back(s.layer);
            r.name = s.layer + " " + std::to_string(m.regions.size() + 1);
            m.regions.push_back(r);
        } else {
            if (points.size() < 2) continue;
            Joint j;
            j.points = points;
            j.joint_material = index_named(m.joint_materials, s.layer, &default_joint);
            if (std::find(joint_layers.begin(), joint_layers.end(), s.layer) == joint_layers.end())
                joint_layers.push_back(s.layer);
            j.name = "joint " + std::to_string(++joint_count);
            m.joints.push_back(j);
        }
    }
    if (skipped_small > 0)
        warning(std::to_string(skipped_small) + " closed polylines with fewer than 3 vertices or no area skipped");
    int hole_count = 0;
    for (const Shape& h : holes) {
        // The region around the hole: the one containing its first vertex, the smallest if nested.
        int around = -1;
        for (std::size_t r = 0; r < m.regions.size(); ++r)
            if (region_contains(m.regions[r], h.points.front()) &&
                (around < 0 || std::abs(signed_area(m.regions[r].boundary)) <
                                   std::abs(signed_area(m.regions[static_cast<std::size_t>(around)].boundary))))
                around = static_cast<int>(r);
        if (around < 0) {
            std::ostringstream where;
            where << "(" << h.points.front().x << ", " << h.points.front().y << ")";
            warning("a closed polyline on layer \"" + h.layer + "\" at " + where.str() +
                    " lies in no region: skipped (holes must lie inside a region)");
            continue;
        }
        std::vector<Point2> ring = h.points;
        std::reverse(ring.begin(), ring.end());  // holes run clockwise
        m.regions[static_cast<std::size_t>(around)].holes.push_back(ring);
        ++hole_count;
    }
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        MeasurementPoint p;
        p.name = c.points[i].layer + " " + std::to_string(i + 1);
        p.point = {c.points[i].points.front().x * scale, c.points[i].points.front().y * scale};
        m.measurement_points.push_back(p);
    }
    if (m.joint_materials.empty()) m.joint_materials.push_back(default_joint("joints"));
    m.default_joint_material = 0;
    if (m.regions.empty()) {
        error("no closed polyline (LWPOLYLINE or POLYLINE) outside a holes/openings layer: nothing to make a region of");
        return result;
    }
    m.name = as_utf8(std::filesystem::path(path).stem().string());
    m.description = "Imported from " + as_utf8(std::filesystem::path(path).filename().string()) + " (units: " + units +
                    "); materials and joint materials carry default properties.";
    std::ostringstream summary;
    summary << m.regions.size() << " regions (layers " << joined(region_layers) << "), " << hole_count << " holes, "
            << m.joints.size() << " joints" << (joint_layers.empty() ? "" : " (layers " + joined(joint_layers) + ")")
            << ", " << m.measurement_points.size() << " measurement points; units: " << units;
    result.summary = summary.str();
    result.model = std::move(m);
    return result;
}

}  // namespace mcdda
