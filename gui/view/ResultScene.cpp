#include "view/ResultScene.hpp"

#include "view/ResultFileReader.hpp"
#include "io/FileKind.hpp"
#include "view/DeformScale.hpp"

#include "view/FlatActor.hpp"
#include "view/ModelScene.hpp"
#include "view/OffscreenRender.hpp"
#include "view/LocalisedScalarBar.hpp"
#include "view/PictureText.hpp"
#include "view/Palette.hpp"
#include "view/SceneGeometry.hpp"
#include "view/ScaleBar.hpp"
#include "view/SceneLegend.hpp"
#include "view/Symbols.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindow.h>
#include <vtkIdList.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <utility>

namespace mcdda::view {

namespace {

const Rgb white{1.0, 1.0, 1.0};
const Rgb state_colors[3] = {{0.82, 0.82, 0.82}, {1.0, 0.84, 0.0}, {0.86, 0.06, 0.06}};
const char* const state_labels[3] = {QT_TRANSLATE_NOOP("mcdda::view", "elastic"), QT_TRANSLATE_NOOP("mcdda::view", "yielded before"), QT_TRANSLATE_NOOP("mcdda::view", "yielding now")};
const Rgb joint_color{0.55, 0.0, 0.60};  // purple: not in the rainbow nor the state colours
// Contact forces and bolts: neither in the rainbow, the state colours nor the outline's near-black.
const Rgb contact_force_color{0.0, 0.40, 0.75};
const Rgb bolt_color{0.0, 0.55, 0.25};
const Rgb slip_color{0.95, 0.45, 0.0};     // joint slip: along the joint
const Rgb opening_color{0.45, 0.25, 0.05};  // joint opening: across it

/// How a field's value comes out of its array.
enum Derived : int {
    magnitude = -1,   ///< length of the vector
    principal_1 = -2, ///< larger in-plane principal value of a VTK symmetric tensor (xx, yy, zz, xy, ...)
    principal_3 = -3, ///< smaller one
};

struct FieldInfo {
    const char* name;
    const char* array;   ///< array in the .vtu
    bool point_data;
    int component;       ///< a Derived value, otherwise the component
    const char* units;   ///< "Pa": shown in kPa or MPa, whichever suits the range
    const char* title;   ///< over the legend (translated by picture_text)
};

const FieldInfo field_table[] = {
    {"plastic_state", "plastic_state", false, 0, "-", QT_TRANSLATE_NOOP("mcdda::view", "plastic state")},
    {"plastic_strain", "plastic_strain", false, 0, "-", QT_TRANSLATE_NOOP("mcdda::view", "plastic strain")},
    {"displacement", "displacement", true, magnitude, "m", QT_TRANSLATE_NOOP("mcdda::view", "displacement")},
    {"ux", "displacement", true, 0, "m", QT_TRANSLATE_NOOP("mcdda::view", "x displacement")},
    {"uy", "displacement", true, 1, "m", QT_TRANSLATE_NOOP("mcdda::view", "y displacement")},
    {"stress_xx", "stress", false, 0, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "stress xx")},
    {"stress_yy", "stress", false, 1, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "stress yy")},
    {"stress_xy", "stress", false, 3, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "shear stress xy")},
    {"stress_1", "stress", false, principal_1, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "principal stress 1")},
    {"stress_3", "stress", false, principal_3, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "principal stress 3")},
    // Runs with ground water: the pore pressure and the effective stress σ′ = σ + u the
    // material yields on ("stress" is the total stress).
    {"pore_pressure", "pore_pressure", false, 0, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "pore pressure")},
    {"effective_stress_xx", "effective_stress", false, 0, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "effective stress xx")},
    {"effective_stress_yy", "effective_stress", false, 1, "Pa", QT_TRANSLATE_NOOP("mcdda::view", "effective stress yy")},
    {"effective_stress_1", "effective_stress", false, principal_1, "Pa",
     QT_TRANSLATE_NOOP("mcdda::view", "effective principal stress 1")},
    {"effective_stress_3", "effective_stress", false, principal_3, "Pa",
     QT_TRANSLATE_NOOP("mcdda::view", "effective principal stress 3")},
    // The mechanism of a strength reduction, in the last saved step only (docs/running.md,
    // "Strength reduction runs").
    {"displacement_increment", "displacement_increment", true, magnitude, "m",
     QT_TRANSLATE_NOOP("mcdda::view", "displacement increment")},
    {"plastic_strain_increment", "plastic_strain_increment", false, 0, "-",
     QT_TRANSLATE_NOOP("mcdda::view", "plastic strain increment")},
};

/// The points of cell c in order around its boundary: a six-node triangle (VTK's quadratic
/// triangle: corners, then the midside nodes of edges 01, 12, 20) as the hexagon c0 m01 c1 m12 c2
/// m20, which has the straight edges of the element; other cells as stored.
void boundary_points(vtkUnstructuredGrid* grid, vtkIdType c, vtkIdList* ids)
{
    grid->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() != 6) return;
    vtkIdType p[6];
    for (int k = 0; k < 6; ++k) p[k] = ids->GetId(k);
    const int order[6] = {0, 3, 1, 4, 2, 5};
    for (int k = 0; k < 6; ++k) ids->SetId(k, p[order[k]]);
}

vtkDataArray* find_array(vtkUnstructuredGrid* grid, const FieldInfo& f)
{
    vtkDataArray* a = f.point_data ? grid->GetPointData()->GetArray(f.array) : grid->GetCellData()->GetArray(f.array);
    if (a == nullptr) return nullptr;
    const int needed = f.component == principal_1 || f.component == principal_3 ? 3 : f.component;
    if (needed >= a->GetNumberOfComponents()) return nullptr;
    return a;
}

std::string list_names(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? std::string("none") : s;
}

/// A result file read and checked against the model.
struct Result {
    vtkSmartPointer<vtkUnstructuredGrid> grid;
    const FieldInfo* field = nullptr;
    vtkSmartPointer<vtkPolyData> contacts;  ///< ResultOptions::contacts, read
    int step = -1;    ///< when known
    int stage = 0;    ///< 1-based; 0 = unknown
    double time = std::numeric_limits<double>::quiet_NaN();
    /// A strength reduction's saved trial: the factor its strengths were divided by.
    double strength_factor = std::numeric_limits<double>::quiet_NaN();
};

/// A number of the file's field data (RunOutput writes step, stage, time); NaN when missing.
double field_number(vtkUnstructuredGrid* grid, const char* name)
{
    vtkFieldData* data = grid->GetFieldData();
    vtkDataArray* a = data != nullptr ? data->GetArray(name) : nullptr;
    return a != nullptr && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
}

/// Reads a contacts file (ResultOptions::contacts) with its force arrays checked.
vtkSmartPointer<vtkPolyData> load_contacts(const std::string& path)
{
    // A directory, /dev/null or a pipe is named by what it is, not "no such file".
    if (const std::string kind = not_a_regular_file(path); !kind.empty())
        throw ResultFileError("cannot read contacts " + path + ": it " + kind);
    vtkSmartPointer<vtkPolyData> data = read_contacts_file(path);  // every part checked (ResultFileReader)
    vtkDataArray* force = data != nullptr ? data->GetPointData()->GetArray("force") : nullptr;
    if (force == nullptr || force->GetNumberOfComponents() < 2)
        throw ResultFileError("contacts " + path + " hold no contact forces: is it a contacts file of mcdda run?");
    return data;
}

const FieldInfo& find_field(const ResultOptions& options)
{
    for (const FieldInfo& f : field_table)
        if (options.field == f.name) return f;
    throw ResultFieldError("unknown field \"" + options.field + "\" (available: " + list_names(result_field_names()) +
                           ")");
}

/// The cells of a staged run's grid that are present (cell data "present" ≠ 0): excavated and
/// not yet built elements are not drawn. Points and their data stay as they are.
vtkSmartPointer<vtkUnstructuredGrid> present_cells(vtkSmartPointer<vtkUnstructuredGrid> grid)
{
    vtkDataArray* present = grid->GetCellData()->GetArray("present");
    if (present == nullptr) return grid;
    auto kept = vtkSmartPointer<vtkUnstructuredGrid>::New();
    kept->SetPoints(grid->GetPoints());
    kept->GetPointData()->ShallowCopy(grid->GetPointData());
    kept->GetCellData()->CopyAllocate(grid->GetCellData());
    kept->Allocate(grid->GetNumberOfCells());
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        if (present->GetTuple1(c) == 0.0) continue;
        grid->GetCellPoints(c, ids);
        const vtkIdType to = kept->InsertNextCell(grid->GetCellType(c), ids);
        kept->GetCellData()->CopyData(grid->GetCellData(), c, to);
    }
    return kept;
}

/// The arrays drawn hold finite numbers only (a NaN would colour nothing and scale nothing).
void check_finite(vtkDataArray* a, const std::string& source, const std::string& what)
{
    if (a == nullptr) return;
    vtkIdType bad = 0, first = -1;
    const int components = a->GetNumberOfComponents();
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
        for (int c = 0; c < components; ++c)
            if (!std::isfinite(a->GetComponent(t, c))) {
                if (first < 0) first = t;
                ++bad;
                break;
            }
    if (bad > 0)
        throw ResultFieldError("results " + source + ": " + what + " \"" + a->GetName() + "\" holds values that are not "
                               "finite numbers (NaN or infinity) at " + std::to_string(bad) + " entries, the first at " +
                               std::to_string(first));
}

/// Checks a result grid (read from `source`) against the model and the options.
Result check_result(vtkSmartPointer<vtkUnstructuredGrid> grid, const Preprocessed& model, const std::string& source,
                    const FieldInfo& field, const ResultOptions& options)
{
    Result r;
    r.grid = std::move(grid);
    if (r.grid == nullptr || r.grid->GetNumberOfCells() == 0 || r.grid->GetNumberOfPoints() == 0)
        throw ResultFileError("cannot read results " + source + ": the file is damaged or holds no cells");
    const auto cells = static_cast<std::size_t>(r.grid->GetNumberOfCells());
    if (cells != model.mesh.triangles.size())
        throw ResultFileError("results " + source + " have " + std::to_string(cells) +
                                 " cells but the model's mesh has " + std::to_string(model.mesh.triangles.size()) +
                                 " triangles: were they written by a run of this model (with the same --set options)?");
    r.grid = present_cells(r.grid);
    r.field = &field;
    if (find_array(r.grid, field) == nullptr) {
        std::vector<std::string> present;
        for (const FieldInfo& f : field_table)
            if (find_array(r.grid, f) != nullptr) present.emplace_back(f.name);
        throw ResultFieldError("results " + source + " hold no field \"" + options.field + "\" (available: " +
                               list_names(present) + ")");
    }
    check_finite(find_array(r.grid, field), source, "the field's array");
    if (options.deform != 0.0 || options.deform_auto) {
        vtkDataArray* d = r.grid->GetPointData()->GetArray("displacement");
        if (d == nullptr || d->GetNumberOfComponents() < 2)
            throw ResultFieldError("results " + source + " hold no displacement to deform the mesh with");
        check_finite(d, source, "the array");
    }
    return r;
}

Result load_result(const Preprocessed& model, const std::string& path, const ResultOptions& options)
{
    const FieldInfo& field = find_field(options);
    if (!std::isfinite(options.deform)) throw ResultFieldError("the deformation factor must be a finite number");

    // A directory, /dev/null or a pipe is named by what it is, not "no such file".
    if (const std::string kind = not_a_regular_file(path); !kind.empty())
        throw ResultFileError("cannot read results " + path + ": it " + kind);
    // The file is read by mcdda's own strict reader: its declared counts against the model's
    // mesh before anything is read from them, then every array, index, offset and cell type.
    const vtkSmartPointer<vtkUnstructuredGrid> grid =
        read_result_grid(path, ExpectedMesh{model.mesh.nodes.size(), model.mesh.triangles.size(),
                                            !model.mesh.midside.empty()});
    Result r = check_result(grid, model, path, field, options);
    if (const double step = field_number(grid, "step"); std::isfinite(step)) r.step = static_cast<int>(step);
    if (const double stage = field_number(grid, "stage"); std::isfinite(stage)) r.stage = static_cast<int>(stage);
    r.time = field_number(grid, "time");
    r.strength_factor = field_number(grid, "strength_factor");
    if (!options.contacts.empty()) r.contacts = load_contacts(options.contacts);
    return r;
}

/// The same grid as a result file holds (points undeformed, the arrays of RunOutput), from a
/// snapshot in memory. Arrays with the wrong length are left out (then reported as missing).
Result snapshot_result(const Preprocessed& model, const ResultSnapshot& s, const ResultOptions& options)
{
    const FieldInfo& field = find_field(options);
    if (!std::isfinite(options.deform)) throw ResultFieldError("the deformation factor must be a finite number");
    const Mesh& mesh = model.mesh;
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkPoints> points;
    for (const Point2& q : mesh.nodes) points->InsertNextPoint(q.x, q.y, 0.0);
    grid->SetPoints(points);
    grid->Allocate(static_cast<vtkIdType>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const vtkIdType ids[3] = {static_cast<vtkIdType>(t[0]), static_cast<vtkIdType>(t[1]),
                                  static_cast<vtkIdType>(t[2])};
        grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
    }
    const std::size_t nodes = mesh.nodes.size(), cells = mesh.triangles.size();
    if (s.displacement.size() == 2 * nodes) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("displacement");
        a->SetNumberOfComponents(3);
        for (std::size_t i = 0; i < nodes; ++i) a->InsertNextTuple3(s.displacement[2 * i], s.displacement[2 * i + 1], 0.0);
        grid->GetPointData()->AddArray(a);
    }
    if (mesh.triangle_block.size() == cells) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("block");
        for (int b : mesh.triangle_block) a->InsertNextValue(b);
        grid->GetCellData()->AddArray(a);
    }
    // VTK's symmetric tensor order, as in the files.
    for (const auto& [name, tensors] : {std::pair{"stress", &s.stress}, std::pair{"effective_stress", &s.effective_stress}}) {
        if (tensors->size() != cells) continue;
        vtkNew<vtkDoubleArray> a;
        a->SetName(name);
        a->SetNumberOfComponents(6);
        for (const auto& t : *tensors) {
            const double v[6] = {t[0], t[1], t[2], t[3], 0.0, 0.0};
            a->InsertNextTuple(v);
        }
        grid->GetCellData()->AddArray(a);
    }
    if (s.pore_pressure.size() == cells) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("pore_pressure");
        for (double v : s.pore_pressure) a->InsertNextValue(v);
        grid->GetCellData()->AddArray(a);
    }
    if (s.plastic_state.size() == cells) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("plastic_state");
        for (unsigned char v : s.plastic_state) a->InsertNextValue(v);
        grid->GetCellData()->AddArray(a);
    }
    if (s.plastic_strain.size() == cells) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("plastic_strain");
        for (double v : s.plastic_strain) a->InsertNextValue(v);
        grid->GetCellData()->AddArray(a);
    }
    if (s.present.size() == cells) {
        vtkNew<vtkDoubleArray> a;
        a->SetName("present");
        for (unsigned char v : s.present) a->InsertNextValue(v);
        grid->GetCellData()->AddArray(a);
    }
    Result r = check_result(grid, model, "of step " + std::to_string(s.step), field, options);
    r.step = s.step;
    r.time = s.time;
    r.stage = s.stage;
    return r;
}

double dpi_of(vtkRenderer* renderer)
{
    vtkWindow* window = renderer->GetVTKWindow();
    const int dpi = window != nullptr ? window->GetDPI() : 72;
    return dpi > 0 ? dpi : 72;
}


/// A stress component, shown in the sign convention asked for (the pore pressure is always
/// compression positive, as engineers read it).
bool is_stress(const FieldInfo& f) { return std::string(f.units) == "Pa" && std::string(f.array) != "pore_pressure"; }

/// Value of the field at entry i (cell or point); stresses in the sign convention asked for.
double value_of(vtkDataArray* a, const FieldInfo& f, vtkIdType i, StressSign sign)
{
    const bool compression = sign == StressSign::CompressionPositive && is_stress(f);
    if (f.component >= 0) return (compression ? -1.0 : 1.0) * a->GetComponent(i, f.component);
    if (f.component == principal_1 || f.component == principal_3) {
        const double xx = a->GetComponent(i, 0), yy = a->GetComponent(i, 1), xy = a->GetComponent(i, 3);
        const double centre = 0.5 * (xx + yy), radius = std::hypot(0.5 * (xx - yy), xy);
        // Compression positive: σ1 is the major compressive stress, minus the smaller
        // tension-positive principal stress.
        if (compression) return f.component == principal_1 ? radius - centre : -(centre + radius);
        return f.component == principal_1 ? centre + radius : centre - radius;
    }
    double s = 0.0;
    for (int c = 0; c < a->GetNumberOfComponents(); ++c) s += a->GetComponent(i, c) * a->GetComponent(i, c);
    return std::sqrt(s);
}


/// The colour of `map` at t in [0, 1] (low to high).
Rgb map_colour(ColourMap map, double t)
{
    t = std::clamp(t, 0.0, 1.0);
    auto ramp = [t](std::initializer_list<Rgb> stops) {
        const std::vector<Rgb> c(stops);
        const double x = t * (c.size() - 1);
        const std::size_t k = std::min(static_cast<std::size_t>(x), c.size() - 2);
        const double u = x - k;
        return Rgb{c[k][0] + u * (c[k + 1][0] - c[k][0]), c[k][1] + u * (c[k + 1][1] - c[k][1]),
                   c[k][2] + u * (c[k + 1][2] - c[k][2])};
    };
    switch (map) {
        case ColourMap::Viridis:
            return ramp({{0.267, 0.005, 0.329}, {0.229, 0.322, 0.546}, {0.128, 0.567, 0.551}, {0.369, 0.789, 0.383},
                         {0.993, 0.906, 0.144}});
        case ColourMap::Grey: return ramp({{0.15, 0.15, 0.15}, {0.92, 0.92, 0.92}});
        case ColourMap::Diverging:  // blue – white – red (Moreland's cool–warm)
            return ramp({{0.230, 0.299, 0.754}, {0.865, 0.865, 0.865}, {0.706, 0.016, 0.150}});
        case ColourMap::Rainbow:
        default: {
            Rgb rgb{};
            vtkMath::HSVToRGB(0.667 * (1.0 - t), 1.0, 1.0, &rgb[0], &rgb[1], &rgb[2]);
            return rgb;
        }
    }
}

/// Whether (x, y) lies on one of the grid's cells (their corner triangles).
bool on_grid(vtkUnstructuredGrid* grid, double x, double y)
{
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        grid->GetCellPoints(c, ids);
        if (ids->GetNumberOfIds() < 3) continue;
        double a[3], b[3], d[3];
        grid->GetPoint(ids->GetId(0), a);
        grid->GetPoint(ids->GetId(1), b);
        grid->GetPoint(ids->GetId(2), d);
        const double det = (b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1]);
        if (det == 0.0) continue;
        const double l1 = ((x - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (y - a[1])) / det;
        const double l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
        if (l1 >= -1e-9 && l2 >= -1e-9 && l1 + l2 <= 1.0 + 1e-9) return true;
    }
    return false;
}

/// The cells as drawn: their points displaced by the deformation scale, their polygons, and the
/// elements that scale turned inside out (ResultInfo).
struct DrawnCells {
    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkPolyData> fill;
    double deform = 0.0;
    vtkIdType point_count = 0;
};

/// The smallest deformation scale at which a cell of `grid` is drawn with zero area: its
/// corner triangle, and for six-node cells the four triangles of corners and midside nodes
/// (VTK's order: corners 0–2, then the midsides of 0–1, 1–2, 2–0).
double untangled_scale(vtkUnstructuredGrid* grid, vtkDataArray* displacement)
{
    const vtkIdType n = grid->GetNumberOfPoints();
    std::vector<Point2> points(static_cast<std::size_t>(n)), moved(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        double q[3];
        grid->GetPoint(i, q);
        points[static_cast<std::size_t>(i)] = {q[0], q[1]};
        moved[static_cast<std::size_t>(i)] = {displacement->GetComponent(i, 0), displacement->GetComponent(i, 1)};
    }
    std::vector<std::array<int, 3>> triangles;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        grid->GetCellPoints(c, ids);
        auto id = [&](int k) { return static_cast<int>(ids->GetId(k)); };
        if (ids->GetNumberOfIds() == 6) {
            static const std::array<int, 3> sub[4] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
            for (const auto& t : sub)
                triangles.push_back({id(t[0]), id(t[1]), id(t[2])});
        } else if (ids->GetNumberOfIds() >= 3) {
            triangles.push_back({id(0), id(1), id(2)});
        }
    }
    return largest_untangled_scale(points, moved, triangles);
}

DrawnCells displaced_cells(vtkUnstructuredGrid* grid, const ResultOptions& options, const Box& box, bool record,
                           ResultProbe& shown, ResultInfo& drew)
{
    vtkDataArray* displacement = grid->GetPointData()->GetArray("displacement");
    const vtkIdType point_count = grid->GetNumberOfPoints();
    if (displacement != nullptr)
        for (vtkIdType i = 0; i < point_count; ++i)
            drew.max_displacement = std::max(drew.max_displacement,
                                             std::hypot(displacement->GetComponent(i, 0), displacement->GetComponent(i, 1)));
    // Auto: the largest displacement drawn as 5 % of the model's larger side, but never so
    // large that an element is drawn inside out (DeformScale).
    const double deform = displacement == nullptr ? 0.0
                          : options.deform_auto
                              ? automatic_deform_scale(box.size(), drew.max_displacement, untangled_scale(grid, displacement))
                              : options.deform;
    drew.deform_factor = deform;
    vtkNew<vtkPoints> points;
    for (vtkIdType i = 0; i < point_count; ++i) {
        double q[3];
        grid->GetPoint(i, q);
        if (deform != 0.0) {
            q[0] += deform * displacement->GetComponent(i, 0);
            q[1] += deform * displacement->GetComponent(i, 1);
        }
        points->InsertNextPoint(q[0], q[1], 0.0);
        if (record) shown.points.push_back({q[0], q[1]});
    }
    vtkNew<vtkCellArray> polys;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        boundary_points(grid, c, ids);
        polys->InsertNextCell(ids);
        // The probe interpolates on the corners (the first, third and fifth point of a six-node
        // cell's boundary): exact for cell data, linear for point data.
        const int stride = ids->GetNumberOfIds() == 6 ? 2 : 1;
        if (record && (ids->GetNumberOfIds() == 3 || ids->GetNumberOfIds() == 6))
            shown.triangles.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(stride)),
                                        static_cast<int>(ids->GetId(2 * stride))});
    }
    if (deform != 0.0) {  // elements turned inside out: the scale is too large to read the picture
        auto area = [&](vtkPoints* pts, vtkIdType a, vtkIdType b, vtkIdType c) {
            double p0[3], p1[3], p2[3];
            pts->GetPoint(a, p0);
            pts->GetPoint(b, p1);
            pts->GetPoint(c, p2);
            return (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
        };
        for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
            grid->GetCellPoints(c, ids);
            if (ids->GetNumberOfIds() < 3) continue;
            const double before = area(grid->GetPoints(), ids->GetId(0), ids->GetId(1), ids->GetId(2));
            const double after = area(points, ids->GetId(0), ids->GetId(1), ids->GetId(2));
            if (before != 0.0 && after * (before > 0.0 ? 1.0 : -1.0) <= 0.0) ++drew.inverted_elements;
        }
    }
    DrawnCells out;
    out.points = points.Get();
    out.fill = vtkSmartPointer<vtkPolyData>::New();
    out.fill->SetPoints(points);
    out.fill->SetPolys(polys);
    out.deform = deform;
    out.point_count = point_count;
    return out;
}

/// How the field colours the cells: the mapper and its table, the range shown (widened to round
/// numbers) and the unit.
struct Colouring {
    vtkSmartPointer<vtkPolyDataMapper> mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    vtkSmartPointer<vtkLookupTable> table = vtkSmartPointer<vtkLookupTable>::New();
    double range[2] = {0.0, 1.0};
    std::string units;
    bool categorical = false;  ///< plastic state: a colour per state, no scale
    bool uniform = false;      ///< one value everywhere: shown as that value
    double uniform_value = 0.0, tick_step = 0.0;
};

/// The plastic state: a colour per state, straight onto the cells.
void colour_states(vtkUnstructuredGrid* grid, vtkDataArray* source, vtkPolyData* fill, bool record, ResultProbe& shown,
                   Colouring& out)
{
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetNumberOfComponents(3);
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        const int s = std::clamp(static_cast<int>(std::lround(source->GetComponent(c, 0))), 0, 2);
        unsigned char b[3];
        for (int k = 0; k < 3; ++k) b[k] = static_cast<unsigned char>(std::lround(state_colors[s][k] * 255.0));
        colors->InsertNextTypedTuple(b);
        if (record) shown.values.push_back(s);
    }
    fill->GetCellData()->SetScalars(colors);
    out.mapper->SetScalarModeToUseCellData();
    out.mapper->SetColorModeToDirectScalars();
}

/// The range of the values shown in the unit chosen (stresses: kPa, or MPa from 1 MPa on, unless
/// the options say), with labels at round numbers (1, 2 or 5 × 10ⁿ apart) and the scale widened
/// to them; a uniform field shows its one value, not −1…1.
void set_value_range(vtkDoubleArray* values, const ResultOptions& options, Colouring& c)
{
    const vtkIdType n = values->GetNumberOfTuples();
    c.range[0] = std::numeric_limits<double>::infinity();
    c.range[1] = -c.range[0];
    for (vtkIdType i = 0; i < n; ++i)
        if (const double v = values->GetValue(i); std::isfinite(v))
            c.range[0] = std::min(c.range[0], v), c.range[1] = std::max(c.range[1], v);
    if (!(c.range[0] <= c.range[1])) c.range[0] = 0.0, c.range[1] = 1.0;
    double scale = 1.0;
    if (c.units == "Pa") {
        const bool mpa = options.stress_unit == StressUnit::MPa ||
                         (options.stress_unit == StressUnit::Automatic &&
                          std::max(std::abs(c.range[0]), std::abs(c.range[1])) >= 1e6);
        scale = mpa ? 1e-6 : 1e-3;
        c.units = mpa ? "MPa" : "kPa";
    } else if (c.units == "m" && options.length_unit == LengthUnit::Millimetre) {
        scale = 1e3;
        c.units = "mm";
    }
    if (scale != 1.0) {
        for (vtkIdType i = 0; i < n; ++i) values->SetValue(i, values->GetValue(i) * scale);
        c.range[0] *= scale, c.range[1] *= scale;
    }
    c.uniform = c.range[1] - c.range[0] <= 1e-9 * std::max(std::abs(c.range[0]), std::abs(c.range[1])) ||
                c.range[1] - c.range[0] < 1e-300;
    if (std::isfinite(options.range_min) && std::isfinite(options.range_max) && options.range_min < options.range_max) {
        c.range[0] = options.range_min, c.range[1] = options.range_max;
        c.uniform = false;
        c.tick_step = nice_step((c.range[1] - c.range[0]) / 5.0);
    } else if (c.uniform) {
        c.uniform_value = c.range[0];
        const double pad = std::max(1e-3 * std::abs(c.range[0]), 1e-12);
        c.range[0] -= pad, c.range[1] += pad;
    } else {
        c.tick_step = nice_step((c.range[1] - c.range[0]) / 5.0);
        c.range[0] = std::floor(c.range[0] / c.tick_step + 1e-9) * c.tick_step;
        c.range[1] = std::ceil(c.range[1] / c.tick_step - 1e-9) * c.tick_step;
    }
}

/// A field's values through the colour map chosen (banded when asked).
void colour_values(vtkDataArray* source, const FieldInfo& field, const ResultOptions& options, vtkPolyData* fill,
                   bool record, ResultProbe& shown, Colouring& c)
{
    vtkNew<vtkDoubleArray> values;
    const vtkIdType n = source->GetNumberOfTuples();
    for (vtkIdType i = 0; i < n; ++i) values->InsertNextValue(value_of(source, field, i, options.stress_sign));
    set_value_range(values, options, c);
    if (record)
        for (vtkIdType i = 0; i < n; ++i) shown.values.push_back(values->GetValue(i));
    if (field.point_data) {
        fill->GetPointData()->SetScalars(values);
        c.mapper->SetScalarModeToUsePointData();
    } else {
        fill->GetCellData()->SetScalars(values);
        c.mapper->SetScalarModeToUseCellData();
    }
    const int colours = options.bands > 0 ? std::min(options.bands, 256) : 256;
    c.table->SetNumberOfTableValues(colours);
    c.table->SetTableRange(c.range);
    c.table->Build();
    for (int k = 0; k < colours; ++k) {
        const Rgb colour = map_colour(options.colour_map, colours > 1 ? k / (colours - 1.0) : 0.5);
        c.table->SetTableValue(k, colour[0], colour[1], colour[2], 1.0);
    }
    c.table->UseBelowRangeColorOff();
    c.table->UseAboveRangeColorOff();
    c.mapper->SetLookupTable(c.table);
    c.mapper->SetScalarRange(c.range);
    c.mapper->InterpolateScalarsBeforeMappingOn();
}

Colouring colour_cells(vtkUnstructuredGrid* grid, const FieldInfo& field, const ResultOptions& options, vtkPolyData* fill,
                       bool record, ResultProbe& shown)
{
    Colouring c;
    c.units = field.units;
    c.categorical = std::string(field.name) == "plastic_state";
    vtkDataArray* source = find_array(grid, field);
    c.mapper->SetInputData(fill);
    if (c.categorical) colour_states(grid, source, fill, record, shown, c);
    else colour_values(source, field, options, fill, record, shown, c);
    return c;
}

/// Block boundaries: edges of one cell only, or between cells of different blocks.
void add_block_outlines(vtkRenderer* renderer, vtkUnstructuredGrid* grid, vtkPoints* points, vtkIdType point_count,
                        double z_step, double pixel)
{
    vtkNew<vtkIdList> ids;
    vtkDataArray* block = grid->GetCellData()->GetArray("block");
    std::map<std::pair<vtkIdType, vtkIdType>, std::pair<int, double>> edges;  // edge -> (uses, block)
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        boundary_points(grid, c, ids);
        const vtkIdType n = ids->GetNumberOfIds();
        const double b = block != nullptr ? block->GetComponent(c, 0) : 0.0;
        for (vtkIdType k = 0; k < n; ++k) {
            vtkIdType a = ids->GetId(k), e = ids->GetId((k + 1) % n);
            auto [it, fresh] = edges.try_emplace({std::min(a, e), std::max(a, e)}, 1, b);
            if (!fresh) it->second.first += (it->second.second == b) ? 1 : 2;  // other block: keep it
        }
    }
    vtkNew<vtkPoints> line_points;
    for (vtkIdType i = 0; i < point_count; ++i) {
        double q[3];
        points->GetPoint(i, q);
        line_points->InsertNextPoint(q[0], q[1], 2.0 * z_step);
    }
    vtkNew<vtkCellArray> lines;
    for (const auto& [edge, use] : edges)
        if (use.first != 2) {
            const vtkIdType l[2] = {edge.first, edge.second};
            lines->InsertNextCell(2, l);
        }
    vtkNew<vtkPolyData> outline;
    outline->SetPoints(line_points);
    outline->SetLines(lines);
    renderer->AddActor(flat_actor(outline, palette::block_outline, 1.5 * pixel));
}

/// Joints of the model where they are in rock; only undeformed (they are not part of the .vtu).
/// True when drawn.
bool add_joints(vtkRenderer* renderer, const Preprocessed& model, vtkUnstructuredGrid* grid, const ResultOptions& options,
                double deform, double z_step, double pixel)
{
    const bool joints = options.show_joints && deform == 0.0 && !model.model.joints.empty();
    const bool staged = grid->GetNumberOfCells() < static_cast<vtkIdType>(model.mesh.triangles.size());
    if (!joints) return false;
    {
        vtkNew<vtkPoints> joint_points;
        vtkNew<vtkCellArray> joint_lines;
        for (const Joint& j : model.model.joints)
            for (std::size_t i = 0; i + 1 < j.points.size(); ++i)
                for (const SegmentPiece& piece : split_by_material(model.model, j.points[i], j.points[i + 1])) {
                    if (!piece.in_material) continue;
                    // A staged run's excavated regions are not drawn: nor are joints through them.
                    if (staged && !on_grid(grid, 0.5 * (piece.from.x + piece.to.x), 0.5 * (piece.from.y + piece.to.y)))
                        continue;
                    const vtkIdType l[2] = {joint_points->InsertNextPoint(piece.from.x, piece.from.y, 3.0 * z_step),
                                            joint_points->InsertNextPoint(piece.to.x, piece.to.y, 3.0 * z_step)};
                    joint_lines->InsertNextCell(2, l);
                }
        vtkNew<vtkPolyData> data;
        data->SetPoints(joint_points);
        data->SetLines(joint_lines);
        renderer->AddActor(flat_actor(data, joint_color, 3.0 * pixel));
    }
    return true;
}

/// The piezometric line in force in the result's stage with its ▽ symbol, on a white halo so that
/// it reads on any colour of the scale. True when drawn (a run with ground water).
bool add_water_table(vtkRenderer* renderer, const Preprocessed& model, const Result& r, const ResultOptions& options,
                     const Box& box, double z_step, double pixel)
{
    if (!options.show_water || !box.valid()) return false;
    const Water& water = water_of_stage(model.model, r.stage - 1);  // stage 0 (unknown): the model's
    if (!water.present()) return false;
    const Shapes shapes = water_table_shapes(water, box.xmin, box.xmax, box.centre().x, 1.5 * symbol_size(box));
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (const auto& l : shapes.lines) {
        lines->InsertNextCell(static_cast<vtkIdType>(l.size()));
        for (const Point2& q : l) lines->InsertCellPoint(points->InsertNextPoint(q.x, q.y, 3.5 * z_step));
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    vtkSmartPointer<vtkActor> halo = flat_actor(data, white, 5.5 * pixel);
    halo->SetPosition(0.0, 0.0, -0.2 * z_step);
    renderer->AddActor(halo);
    renderer->AddActor(flat_actor(data, palette::water, 2.5 * pixel));
    return true;
}

/// What the contact marks showed, for the legend.
struct ContactMarks {
    bool drawn = false;
    double largest_force = 0.0, largest_slip = 0.0, largest_opening = 0.0;
    bool any_bolt = false;
};

/// The contact vertices of a contacts file.
std::vector<vtkIdType> contact_vertices(vtkPolyData* c)
{
    vtkCellArray* verts = c->GetVerts();
    vtkNew<vtkIdList> vertex;
    std::vector<vtkIdType> at;
    verts->InitTraversal();
    while (verts->GetNextCell(vertex) != 0)
        if (vertex->GetNumberOfIds() > 0) at.push_back(vertex->GetId(0));
    return at;
}

/// The median size of the result's blocks (the square root of their areas), or 0 when the grid
/// has no block numbers.
double median_block_size(vtkUnstructuredGrid* grid)
{
    vtkDataArray* block = grid->GetCellData()->GetArray("block");
    if (block == nullptr) return 0.0;
    std::map<long, double> area;
    vtkNew<vtkIdList> ids;
    for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell) {
        grid->GetCellPoints(cell, ids);
        if (ids->GetNumberOfIds() < 3) continue;
        double a[3], b[3], c[3];
        grid->GetPoint(ids->GetId(0), a);
        grid->GetPoint(ids->GetId(1), b);
        grid->GetPoint(ids->GetId(2), c);
        area[std::lround(block->GetTuple1(cell))] +=
            0.5 * std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    }
    std::vector<double> sizes;
    for (const auto& [b, value] : area) sizes.push_back(std::sqrt(value));
    if (sizes.empty()) return 0.0;
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    return sizes[sizes.size() / 2];
}

/// Contact forces as ticks from each contact's vertex, the largest 0.3 of the median block size
/// long (at most 6 % of the model): where every joint carries about the same force (an in-situ
/// stress) ticks of a fixed share of the model covered whole blocks. Returns the largest force.
double add_force_ticks(vtkRenderer* renderer, vtkPolyData* c, const std::vector<vtkIdType>& at, const Box& box,
                       double block_size, double z_step, double pixel)
{
    vtkDataArray* force = c->GetPointData()->GetArray("force");
    double largest_force = 0.0;
    for (vtkIdType p : at) largest_force = std::max(largest_force, std::hypot(force->GetComponent(p, 0), force->GetComponent(p, 1)));
    const double longest = block_size > 0.0 ? std::min(0.06 * box.size(), 0.3 * block_size) : 0.06 * box.size();
    const double scale = largest_force > 0.0 ? longest / largest_force : 0.0;
    vtkNew<vtkPoints> force_points;
    vtkNew<vtkCellArray> force_lines;
    for (vtkIdType p : at) {
        const double fx = force->GetComponent(p, 0), fy = force->GetComponent(p, 1);
        if (fx == 0.0 && fy == 0.0) continue;
        double q[3];
        c->GetPoint(p, q);
        const vtkIdType l[2] = {force_points->InsertNextPoint(q[0], q[1], 4.0 * z_step),
                                force_points->InsertNextPoint(q[0] + scale * fx, q[1] + scale * fy, 4.0 * z_step)};
        force_lines->InsertNextCell(2, l);
    }
    vtkNew<vtkPolyData> lines_data;
    lines_data->SetPoints(force_points);
    lines_data->SetLines(force_lines);
    renderer->AddActor(flat_actor(lines_data, contact_force_color, 1.5 * pixel));
    return largest_force;
}

/// Joint slip and opening marks; the largest of each goes into `m`.
void add_slip_and_opening(vtkRenderer* renderer, vtkPolyData* c, const std::vector<vtkIdType>& at, const Box& box,
                          double z_step, double pixel, ContactMarks& m)
{
    // Joint slip (UDEC's jdisp) along the joint and opening across it, centred on each
    // contact's vertex, the largest of each 6 % of the model long.
    vtkDataArray* normal = c->GetPointData()->GetArray("normal");
    for (const char* name : {"slip", "opening"}) {
        vtkDataArray* value = c->GetPointData()->GetArray(name);
        if (value == nullptr || normal == nullptr) continue;
        const bool along = std::string(name) == "slip";
        double& largest = along ? m.largest_slip : m.largest_opening;
        for (vtkIdType p : at) largest = std::max(largest, std::fabs(value->GetTuple1(p)));
        // Round-off gaps and creep (a millionth of the model) are not drawn as if they mattered.
        if (largest <= 1e-6 * box.size()) {
            largest = 0.0;
            continue;
        }
        vtkNew<vtkPoints> points_of;
        vtkNew<vtkCellArray> lines_of;
        for (vtkIdType p : at) {
            const double v = std::fabs(value->GetTuple1(p));
            if (v < 0.01 * largest) continue;
            const double nx = normal->GetComponent(p, 0), ny = normal->GetComponent(p, 1);
            const double dx = along ? -ny : nx, dy = along ? nx : ny;
            const double half = 0.03 * box.size() * v / largest;
            double q[3];
            c->GetPoint(p, q);
            const vtkIdType l[2] = {points_of->InsertNextPoint(q[0] - half * dx, q[1] - half * dy, 4.5 * z_step),
                                    points_of->InsertNextPoint(q[0] + half * dx, q[1] + half * dy, 4.5 * z_step)};
            lines_of->InsertNextCell(2, l);
        }
        vtkNew<vtkPolyData> data_of;
        data_of->SetPoints(points_of);
        data_of->SetLines(lines_of);
        renderer->AddActor(flat_actor(data_of, along ? slip_color : opening_color, 2.5 * pixel));
    }
}

/// Bolts beyond this many are not labelled with their forces (the labels would cover the picture;
/// the cursor still tells each one's force).
constexpr std::size_t most_bolt_labels = 20;

/// Bolts: the poly data's lines, between their anchors, each labelled with its axial force
/// (kN/m) at its middle; `shown` learns them for the cursor. True when there is one.
bool add_bolt_lines(vtkRenderer* renderer, vtkPolyData* c, const Box& box, double z_step, double pixel,
                    ResultProbe& shown)
{
    vtkNew<vtkPoints> bolt_points;
    vtkNew<vtkCellArray> bolt_lines;
    vtkCellArray* lines_in = c->GetLines();
    vtkDataArray* force = c->GetCellData()->GetArray("bolt_force");
    vtkNew<vtkIdList> line;
    lines_in->InitTraversal();
    // Cell data runs over the vertices first, then the lines.
    for (vtkIdType cell = c->GetNumberOfVerts(); lines_in->GetNextCell(line) != 0; ++cell) {
        if (line->GetNumberOfIds() < 2) continue;
        double a[3], b[3];
        c->GetPoint(line->GetId(0), a);
        c->GetPoint(line->GetId(1), b);
        const vtkIdType l[2] = {bolt_points->InsertNextPoint(a[0], a[1], 5.0 * z_step),
                                bolt_points->InsertNextPoint(b[0], b[1], 5.0 * z_step)};
        bolt_lines->InsertNextCell(2, l);
        const double f = force != nullptr && cell < force->GetNumberOfTuples() ? force->GetTuple1(cell) : 0.0;
        shown.bolts.push_back({{a[0], a[1]}, {b[0], b[1]}, f});
    }
    shown.bolt_reach = 0.01 * box.size();
    if (force != nullptr && shown.bolts.size() <= most_bolt_labels)
        for (const ResultProbe::Bolt& bolt : shown.bolts) {
            const std::string text = picture_number("%.3g", bolt.force / 1e3) + " kN/m";
            vtkNew<vtkTextActor> label;
            label->SetInput(text.c_str());
            vtkTextProperty* t = label->GetTextProperty();
            t->SetFontFamilyToArial();
            t->SetFontSize(static_cast<int>(std::lround(10 * pixel)));
            t->SetColor(0.0, 0.0, 0.0);
            t->SetBackgroundColor(1.0, 1.0, 1.0);
            t->SetBackgroundOpacity(0.75);
            t->SetJustificationToCentered();
            t->SetVerticalJustificationToBottom();
            label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
            label->GetPositionCoordinate()->SetValue(0.5 * (bolt.from.x + bolt.to.x), 0.5 * (bolt.from.y + bolt.to.y),
                                                     6.0 * z_step);
            renderer->AddActor2D(label);
        }
    vtkNew<vtkPolyData> bolts_data;
    bolts_data->SetPoints(bolt_points);
    bolts_data->SetLines(bolt_lines);
    renderer->AddActor(flat_actor(bolts_data, bolt_color, 3.0 * pixel));
    return bolt_lines->GetNumberOfCells() > 0;
}

/// Contact forces, joint slip and opening, and bolts (docs/running.md, the contacts files).
ContactMarks add_contact_marks(vtkRenderer* renderer, vtkPolyData* c, vtkUnstructuredGrid* grid, const Box& box,
                               double z_step, double pixel, ResultProbe& shown)
{
    ContactMarks m;
    m.drawn = c != nullptr;
    if (!m.drawn) return m;
    const std::vector<vtkIdType> at = contact_vertices(c);
    m.largest_force = add_force_ticks(renderer, c, at, box, median_block_size(grid), z_step, pixel);
    add_slip_and_opening(renderer, c, at, box, z_step, pixel, m);
    m.any_bolt = add_bolt_lines(renderer, c, box, z_step, pixel, shown);
    return m;
}

/// The legend of the plastic state: a swatch per state and the lines drawn. Returns the width it
/// takes (pixels).
double add_state_legend(vtkRenderer* renderer, const FieldInfo& field, bool joints, bool water, const ContactMarks& marks,
                        std::vector<std::string>& rows)
{
    const double dpi = dpi_of(renderer);
    std::vector<LegendEntry> entries;
    for (int s = 0; s < 3; ++s) entries.push_back({LegendEntry::Icon::Swatch, state_colors[s], picture_text(state_labels[s])});
    entries.push_back({LegendEntry::Icon::Line, palette::block_outline,
                       picture_text(QT_TRANSLATE_NOOP("mcdda::view", "block boundary"))});
    if (joints)
        entries.push_back({LegendEntry::Icon::Line, joint_color, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "joint"))});
    if (water)
        entries.push_back({LegendEntry::Icon::WaterTable, palette::water,
                           picture_text(QT_TRANSLATE_NOOP("mcdda::view", "water table"))});
    if (marks.drawn) {
        char largest[64];
        // No row for forces that are not there ("largest (0 kN/m)" on a model without joints).
        if (marks.largest_force > 0.0) {
            std::snprintf(largest, sizeof largest, " (%s kN/m)", picture_number("%.3g", marks.largest_force / 1e3).c_str());
            entries.push_back({LegendEntry::Icon::Line, contact_force_color,
                               picture_text(QT_TRANSLATE_NOOP("mcdda::view", "contact force, largest")) + largest});
        }
        if (marks.any_bolt)
            entries.push_back({LegendEntry::Icon::Line, bolt_color, picture_text(QT_TRANSLATE_NOOP("mcdda::view", "bolt"))});
        if (marks.largest_slip > 0.0) {
            std::snprintf(largest, sizeof largest, " (%s mm)", picture_number("%.3g", 1e3 * marks.largest_slip).c_str());
            entries.push_back({LegendEntry::Icon::Line, slip_color,
                               picture_text(QT_TRANSLATE_NOOP("mcdda::view", "joint slip, largest")) + largest});
        }
        if (marks.largest_opening > 0.0) {
            std::snprintf(largest, sizeof largest, " (%s mm)", picture_number("%.3g", 1e3 * marks.largest_opening).c_str());
            entries.push_back({LegendEntry::Icon::Line, opening_color,
                               picture_text(QT_TRANSLATE_NOOP("mcdda::view", "joint opening, largest")) + largest});
        }
    }
    const std::string title = picture_text(field.title);
    for (const LegendEntry& e : entries) rows.push_back(e.label);
    add_legend(renderer, title, entries, dpi);
    return legend_width(title, entries, dpi) + 2.0 * legend_margin(dpi);
}

/// The colour scale of a field, with its unit and sign in the title. Returns the width it takes.
double add_scale_bar(vtkRenderer* renderer, const FieldInfo& field, const Colouring& c, const std::string& sign_note,
                     const ResultOptions& options)
{
    const double pixel = dpi_of(renderer) / 72.0;
    const int* size = renderer->GetSize();
    const double width = std::max(1, size[0]);
    vtkNew<LocalisedScalarBar> bar;
    bar->SetLookupTable(c.table);
    // Two lines: the field, then its unit and sign (the bar's column is narrow).
    std::string title = picture_text(field.title) + "\n(" + c.units + (sign_note.empty() ? "" : ", " + sign_note) + ")";
    vtkNew<vtkDoubleArray> labels;
    if (c.uniform) {
        title += "\n" + picture_text(QT_TRANSLATE_NOOP("mcdda::view", "uniform:")) + " " + picture_number("%.4g", c.uniform_value);
        labels->InsertNextValue(c.uniform_value);
    } else {
        for (double t = c.range[0]; t <= c.range[1] + 1e-9 * c.tick_step; t += c.tick_step)
            labels->InsertNextValue(std::abs(t) < 1e-9 * c.tick_step ? 0.0 : t);  // no "-0"
    }
    bar->SetTitle(title.c_str());
    bar->SetUseCustomLabels(true);
    bar->SetCustomLabels(labels);
    bar->SetLabelFormat("%-.4g");
    bar->SetMaximumNumberOfColors(options.bands > 0 ? options.bands : 256);
    bar->UnconstrainedFontSizeOn();
    bar->SetTextPad(static_cast<int>(std::lround(4 * pixel)));
    for (vtkTextProperty* t : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
        t->SetColor(0.0, 0.0, 0.0);
        t->SetFontFamilyToArial();
        t->ShadowOff();
        t->ItalicOff();
        t->BoldOff();
        t->SetFontSize(t == bar->GetTitleTextProperty() ? 14 : 12);
    }
    bar->GetTitleTextProperty()->BoldOn();
    const double bar_width = std::clamp(170.0 * pixel / width, 0.1, 0.3);
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(1.0 - bar_width - 0.01, 0.08);
    bar->GetPosition2Coordinate()->SetValue(bar_width, 0.84);
    bar->SetBarRatio(0.25);
    renderer->AddActor2D(bar);
    return (bar_width + 0.02) * width;
}

/// The title: field, step, stage and time (exported pictures say what they show).
std::string result_title(const Preprocessed& model, const Result& r, const ResultOptions& options,
                         const std::string& shown_title, double deform)
{
    std::string title = options.title;
    if (title.empty()) {
        title = shown_title;
        char part[96];
        // A strength reduction trial is named by its factor (its step number and time only
        // order the saved trials).
        const bool trial = std::isfinite(r.strength_factor);
        // A static run's steps are load steps: their time (Δt apart) says nothing to the user.
        const bool load_steps = !has_dynamic_stage(model.model);
        if (trial) {
            std::snprintf(part, sizeof part, " — %s %s",
                          picture_text(QT_TRANSLATE_NOOP("mcdda::view", "strengths divided by")).c_str(),
                          picture_number("%.4g", r.strength_factor).c_str());
            title += part;
        } else if (r.step >= 0) {
            std::snprintf(part, sizeof part, " — %s %d",
                          (load_steps ? picture_text(QT_TRANSLATE_NOOP("mcdda::view", "load step"))
                                      : picture_text(QT_TRANSLATE_NOOP("mcdda::view", "step"))).c_str(),
                          r.step);
            title += part;
        }
        if (r.stage >= 1 && r.stage <= static_cast<int>(model.model.stages.size()))
            title += ", " + picture_text(QT_TRANSLATE_NOOP("mcdda::view", "stage")) + " \"" +
                     model.model.stages[static_cast<std::size_t>(r.stage - 1)].name + "\"";
        if (std::isfinite(r.time) && !trial && !load_steps) {
            std::snprintf(part, sizeof part, ", t = %s s", picture_number("%g", r.time).c_str());
            title += part;
        }
        if (deform != 0.0) {
            std::snprintf(part, sizeof part, ", %s ×%s", picture_text(QT_TRANSLATE_NOOP("mcdda::view", "deformed")).c_str(),
                          picture_number("%.3g", deform).c_str());
            title += part;
        }
    }
    return title;
}

void add_result(vtkRenderer* renderer, const Preprocessed& model, const Result& r, const ResultOptions& options,
                ResultProbe* probe = nullptr, ResultInfo* info = nullptr)
{
    ResultInfo unused_info;
    ResultInfo& drew = info ? *info : unused_info;
    drew = ResultInfo{};
    ResultProbe unused;
    ResultProbe& shown = probe ? *probe : unused;  // what the picture shows, for value queries
    shown = ResultProbe{};
    vtkUnstructuredGrid* grid = r.grid;
    const FieldInfo& field = *r.field;
    const double pixel = dpi_of(renderer) / 72.0;
    const Box box = model_box(model);
    const double z_step = (box.size() > 0.0 ? box.size() : 1.0) * 1e-3;

    renderer->SetBackground(white.data());
    renderer->GradientBackgroundOff();
    const DrawnCells cells = displaced_cells(grid, options, box, probe != nullptr, shown, drew);
    const Colouring colouring = colour_cells(grid, field, options, cells.fill, probe != nullptr, shown);
    // Which sign the stresses have is said wherever they are named.
    const std::string sign_note = !is_stress(field) ? std::string()
                                  : options.stress_sign == StressSign::CompressionPositive
                                      ? picture_text(QT_TRANSLATE_NOOP("mcdda::view", "compression +"))
                                      : picture_text(QT_TRANSLATE_NOOP("mcdda::view", "tension +"));
    shown.point_values = field.point_data;
    shown.categorical = colouring.categorical;
    shown.title = picture_text(field.title) + (sign_note.empty() ? std::string() : " (" + sign_note + ")");
    shown.units = colouring.units;
    drew.range_min = colouring.range[0], drew.range_max = colouring.range[1];
    vtkNew<vtkActor> fill_actor;
    fill_actor->SetMapper(colouring.mapper);
    fill_actor->GetProperty()->LightingOff();
    renderer->AddActor(fill_actor);

    add_block_outlines(renderer, grid, cells.points, cells.point_count, z_step, pixel);
    const bool joints = add_joints(renderer, model, grid, options, cells.deform, z_step, pixel);
    const bool water = add_water_table(renderer, model, r, options, box, z_step, pixel);
    const ContactMarks marks = add_contact_marks(renderer, r.contacts, grid, box, z_step, pixel, shown);
    const double reserved = colouring.categorical ? add_state_legend(renderer, field, joints, water, marks, drew.legend)
                                                  : add_scale_bar(renderer, field, colouring, sign_note, options);
    const std::string title = result_title(model, r, options, shown.title, cells.deform);
    drew.title = title;
    const double dpi = dpi_of(renderer);
    vtkNew<vtkTextActor> heading;
    heading->SetInput(title.c_str());
    vtkTextProperty* t = heading->GetTextProperty();
    t->SetColor(0.0, 0.0, 0.0);
    t->SetFontFamilyToArial();
    t->SetFontSize(static_cast<int>(std::lround(13 * pixel)));
    t->BoldOn();
    t->SetVerticalJustificationToTop();
    heading->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    heading->GetPositionCoordinate()->SetValue(0.01, 0.99);
    renderer->AddActor2D(heading);
    const double top = 24.0 * pixel;
    if (options.show_axes) {
        add_axes_and_scale_bar(renderer, box, dpi);
        fit_camera(renderer, model, reserved, axes_left_pixels(dpi), axes_bottom_pixels(dpi), top);
    } else {
        fit_camera(renderer, model, reserved, 0.0, 0.0, top);
    }
}

}  // namespace

const std::vector<std::string>& result_field_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const FieldInfo& f : field_table) n.emplace_back(f.name);
        return n;
    }();
    return names;
}

bool parse_colour_map(const std::string& name, ColourMap* map)
{
    static const std::pair<const char*, ColourMap> names[] = {
        {"rainbow", ColourMap::Rainbow}, {"viridis", ColourMap::Viridis}, {"grey", ColourMap::Grey},
        {"gray", ColourMap::Grey}, {"diverging", ColourMap::Diverging}};
    for (const auto& [n, m] : names)
        if (name == n) {
            *map = m;
            return true;
        }
    return false;
}

void build_result_scene(vtkRenderer* renderer, const Preprocessed& model, const std::string& vtu_path,
                        const ResultOptions& options, ResultProbe* probe, ResultInfo* info)
{
    if (renderer == nullptr) return;
    add_result(renderer, model, load_result(model, vtu_path, options), options, probe, info);
}

void build_result_scene(vtkRenderer* renderer, const Preprocessed& model, const ResultSnapshot& snapshot,
                        const ResultOptions& options, ResultProbe* probe, ResultInfo* info)
{
    if (renderer == nullptr) return;
    add_result(renderer, model, snapshot_result(model, snapshot, options), options, probe, info);
}

void render_result_png(const Preprocessed& model, const std::string& vtu_path, const ResultOptions& options,
                       int width, int height, const std::string& png_path, ResultInfo* info)
{
    const Result result = load_result(model, vtu_path, options);  // file problems (and contacts) before X
    render_scene_png([&](vtkRenderer* renderer) { add_result(renderer, model, result, options, nullptr, info); },
                     width, height, png_path, "render_result_png");
}

}  // namespace mcdda::view
