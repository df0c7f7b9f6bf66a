#include "io/ModelWriter.hpp"

#include "io/AtomicFile.hpp"
#include "Version.hpp"
#include "material/MaterialLaws.hpp"
#include "model/Defaults.hpp"
#include "model/ModelFields.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mcdda {

namespace {

// Keys in the order of docs/model-format.md, not sorted.
using json = nlohmann::ordered_json;

/// Radians (inside) to degrees (file), the shortest decimal that reads back exactly.
double to_degrees(double radians) { return to_file_unit(Quantity::Angle, radians); }

/// The declared number fields of `record` (ModelFields.hpp) into `o`, in the file's units.
template <class Record>
void write_fields(const Record& record, const std::vector<RecordField<Record>>& fields, json& o) {
    for (const RecordField<Record>& f : fields) o[f.field.key] = to_file_unit(f.field.quantity, record.*f.member);
}

json point(Point2 p) { return json::array({p.x, p.y}); }

json water_json(const Water& w) {
    json line = json::array();
    for (const Point2& p : w.piezometric_line) line.push_back(point(p));
    return json{{"piezometric_line", std::move(line)}, {"unit_weight", w.unit_weight}};
}

json ring(const Ring& r) {
    json out = json::array();
    for (const Point2& p : r) out.push_back(point(p));
    return out;
}

/// Name of item `index` of `list`, for a reference; an index out of range is a program error.
template <class List>
std::string name_of(const List& list, int index, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= list.size())
        throw std::invalid_argument(std::string("model refers to a missing ") + what + " (index " +
                                    std::to_string(index) + ")");
    return list[static_cast<std::size_t>(index)].name;
}

/// The "analysis" object of `a`; with `base` (a stage's), only the settings that differ from it.
json analysis_json(const AnalysisSettings& a, const AnalysisSettings* base) {
    json o;
    auto put = [&](const char* key, auto value, auto base_value) {
        if (!base || value != base_value) o[key] = value;
    };
    const AnalysisSettings defaults;
    const AnalysisSettings& b = base ? *base : defaults;
    put("type", std::string(analysis_type_name(a)), std::string(analysis_type_name(b)));
    put("steps", a.steps, b.steps);
    for (const RecordField<AnalysisSettings>& f : analysis_fields())
        put(f.field.key, to_file_unit(f.field.quantity, a.*f.member), to_file_unit(f.field.quantity, b.*f.member));
    put("open_close_iterations", a.max_open_close_iterations, b.max_open_close_iterations);
    put("plastic_iterations", a.max_plastic_iterations, b.max_plastic_iterations);
    put("geometry", std::string(a.geometry == AnalysisSettings::Geometry::Initial ? "initial" : "updated"),
        std::string(b.geometry == AnalysisSettings::Geometry::Initial ? "initial" : "updated"));
    put("output_every", a.output_every, b.output_every);
    put("plasticity", a.plasticity, b.plasticity);
    put("max_trials", a.max_trials, b.max_trials);
    put("non_associated_flow", std::string(non_associated_flow_name(a.non_associated_flow)),
        std::string(non_associated_flow_name(b.non_associated_flow)));
    if (o.is_null()) o = json::object();
    return o;
}

json to_json(const Model& m) {
    json root;
    root["format"] = model_format_name;
    root["version"] = model_format_version;
    if (!m.name.empty()) root["name"] = m.name;
    if (!m.description.empty()) root["description"] = m.description;

    json materials = json::array();
    for (const Material& mat : m.materials) {
        json o;
        o["name"] = mat.name;
        o["law"] = mat.law;
        write_fields(mat, material_fields(), o);
        if (mat.saturated_density == 0.0) o.erase("saturated_density");  // dry models stay as they were
        if (const MaterialLaw* law = find_material_law(mat.law))
            for (const NumberField& f : law->fields)
                if (const double v = law_value(mat, f); std::isfinite(v)) o[f.key] = to_file_unit(f.quantity, v);
        if (!mat.reduce) o["reduce"] = false;
        materials.push_back(std::move(o));
    }
    root["materials"] = std::move(materials);

    if (!m.joint_materials.empty()) {
        json list = json::array();
        for (const JointMaterial& jm : m.joint_materials) {
            json o;
            o["name"] = jm.name;
            write_fields(jm, joint_material_fields(), o);
            if (!jm.reduce) o["reduce"] = false;
            list.push_back(std::move(o));
        }
        root["joint_materials"] = std::move(list);
    }
    if (m.default_joint_material >= 0)
        root["default_joint_material"] = name_of(m.joint_materials, m.default_joint_material, "joint material");

    json regions = json::array();
    for (const Region& r : m.regions) {
        json o;
        o["name"] = r.name;
        o["material"] = name_of(m.materials, r.material, "material");
        o["boundary"] = ring(r.boundary);
        if (!r.holes.empty()) {
            json holes = json::array();
            for (const Ring& h : r.holes) holes.push_back(ring(h));
            o["holes"] = std::move(holes);
        }
        if (r.mesh_size > 0.0) o["mesh_size"] = r.mesh_size;
        regions.push_back(std::move(o));
    }
    root["regions"] = std::move(regions);

    json joints = json::array();
    for (const Joint& j : m.joints) {
        if (j.joint_set >= 0) continue;  // generated from a joint set: the set is written instead
        json o;
        o["name"] = j.name;
        json pts = json::array();
        for (const Point2& p : j.points) pts.push_back(point(p));
        o["points"] = std::move(pts);
        if (j.joint_material >= 0)
            o["joint_material"] = name_of(m.joint_materials, j.joint_material, "joint material");
        joints.push_back(std::move(o));
    }
    if (!joints.empty()) root["joints"] = std::move(joints);

    if (!m.joint_sets.empty()) {
        json list = json::array();
        for (const JointSet& s : m.joint_sets) {
            json o;
            o["name"] = s.name;
            o["angle"] = to_degrees(s.angle);
            o["spacing"] = s.spacing;
            o["origin"] = point(s.origin);
            if (s.extent) o["extent"] = json::array({(*s.extent)[0], (*s.extent)[1], (*s.extent)[2], (*s.extent)[3]});
            if (s.joint_material >= 0)
                o["joint_material"] = name_of(m.joint_materials, s.joint_material, "joint material");
            // Only what differs from a fully persistent set, so older files are written as they were.
            const JointSet defaults;
            if (s.persistence != defaults.persistence) o["persistence"] = s.persistence;
            if (s.trace_length != defaults.trace_length) o["trace_length"] = s.trace_length;
            if (s.stagger != defaults.stagger) o["stagger"] = s.stagger;
            list.push_back(std::move(o));
        }
        root["joint_sets"] = std::move(list);
    }

    if (!m.load_tables.empty()) {
        json list = json::array();
        for (const LoadTable& t : m.load_tables) {
            json o;
            o["name"] = t.name;
            o["variable"] = t.variable == LoadTable::Variable::Time ? "time" : "step";
            json pts = json::array();
            for (const auto& q : t.points) pts.push_back(json::array({q[0], q[1]}));
            o["points"] = std::move(pts);
            o["extrapolate"] = t.extrapolate;
            list.push_back(std::move(o));
        }
        root["load_tables"] = std::move(list);
    }

    if (!m.fixed_points.empty()) {
        json list = json::array();
        for (const FixedPoint& f : m.fixed_points) list.push_back(json{{"name", f.name}, {"point", point(f.point)}});
        root["fixed_points"] = std::move(list);
    }
    if (!m.rollers.empty()) {
        json list = json::array();
        for (const Roller& r : m.rollers) {
            json o;
            o["name"] = r.name;
            o["from"] = point(r.from);
            o["to"] = point(r.to);
            o["fixed"] = r.fix_x && r.fix_y ? "xy" : r.fix_x ? "x" : r.fix_y ? "y" : "";
            if (r.moves()) o["displacement"] = point(r.displacement);
            if (r.table >= 0) o["table"] = name_of(m.load_tables, r.table, "load table");
            list.push_back(std::move(o));
        }
        root["rollers"] = std::move(list);
    }
    if (!m.point_loads.empty()) {
        json list = json::array();
        for (const PointLoad& l : m.point_loads) {
            json o;
            o["name"] = l.name;
            o["point"] = point(l.point);
            o["force"] = point(l.force);
            if (l.table >= 0) o["table"] = name_of(m.load_tables, l.table, "load table");
            list.push_back(std::move(o));
        }
        root["point_loads"] = std::move(list);
    }
    if (!m.edge_pressures.empty()) {
        json list = json::array();
        for (const EdgePressure& e : m.edge_pressures) {
            json o;
            o["name"] = e.name;
            o["from"] = point(e.from);
            o["to"] = point(e.to);
            o["pressure"] = e.pressure;  // positive pushes into the material, in file and model alike
            if (e.table >= 0) o["table"] = name_of(m.load_tables, e.table, "load table");
            list.push_back(std::move(o));
        }
        root["edge_pressures"] = std::move(list);
    }
    root["gravity"] = point(m.gravity);
    if (m.gravity_table >= 0) root["gravity_table"] = name_of(m.load_tables, m.gravity_table, "load table");

    const InitialStress& s = m.initial_stress;
    if (s.kind == InitialStress::Kind::Uniform) {
        // Stored tension positive; the file holds compressive magnitudes.
        json o;
        o["type"] = "uniform";
        o["sxx"] = -s.stress[0];
        o["syy"] = -s.stress[1];
        o["sxy"] = -s.stress[2];
        if (s.stress_zz) o["szz"] = -*s.stress_zz;
        root["initial_stress"] = std::move(o);
    } else if (s.kind == InitialStress::Kind::Gravity) {
        root["initial_stress"] = json{{"type", "gravity"}, {"surface_y", s.surface_y}, {"k0", s.k0}};
    }

    if (m.water.present()) root["water"] = water_json(m.water);

    if (!m.ground_motions.empty()) {
        json list = json::array();
        for (const GroundMotion& g : m.ground_motions) {
            json o{{"name", g.name}};
            if (!g.file.empty()) {
                o["file"] = g.file;
            } else {
                json points = json::array();
                for (const auto& q : g.points) points.push_back({q[0], q[1]});
                o["points"] = std::move(points);
            }
            o["units"] = g.units == GroundMotion::Units::G ? "g" : "m/s2";
            if (g.scale != 1.0) o["scale"] = g.scale;
            if (!g.baseline_correction) o["baseline_correction"] = false;
            list.push_back(std::move(o));
        }
        root["ground_motions"] = std::move(list);
    }
    if (m.base_motion.present()) {
        const BaseMotion& b = m.base_motion;
        json o{{"type", b.kind == BaseMotion::Kind::Rigid ? "rigid" : "compliant"}};
        if (b.x >= 0) o["x"] = name_of(m.ground_motions, b.x, "ground motion");
        if (b.y >= 0) o["y"] = name_of(m.ground_motions, b.y, "ground motion");
        if (b.kind == BaseMotion::Kind::Compliant) {
            o["from"] = point(b.from);
            o["to"] = point(b.to);
        }
        root["base_motion"] = std::move(o);
    }
    if (!m.absorbing_boundaries.empty()) {
        json list = json::array();
        for (const AbsorbingBoundary& a : m.absorbing_boundaries)
            list.push_back(json{{"name", a.name}, {"from", point(a.from)}, {"to", point(a.to)}});
        root["absorbing_boundaries"] = std::move(list);
    }
    if (m.seismic_coefficient.present())
        root["seismic_coefficient"] = json{{"kh", m.seismic_coefficient.kh}, {"kv", m.seismic_coefficient.kv}};

    if (!m.measurement_points.empty()) {
        json list = json::array();
        for (const MeasurementPoint& p : m.measurement_points)
            list.push_back(json{{"name", p.name}, {"point", point(p.point)}});
        root["measurement_points"] = std::move(list);
    }

    {
        const MeshControls& c = m.mesh;
        json o;
        o["element"] = c.element == ElementType::T3 ? "t3" : c.element == ElementType::T6 ? "t6" : "auto";
        o["size"] = c.size;
        o["min_angle"] = to_degrees(c.min_angle);
        o["grading"] = c.grading;
        if (!c.local.empty()) {
            json list = json::array();
            for (const LocalSize& l : c.local) {
                json e;
                if (l.from.x == l.to.x && l.from.y == l.to.y) {
                    e["point"] = point(l.from);
                } else {
                    e["from"] = point(l.from);
                    e["to"] = point(l.to);
                }
                e["size"] = l.size;
                e["radius"] = l.radius;
                list.push_back(std::move(e));
            }
            o["local"] = std::move(list);
        }
        o["max_elements"] = c.max_elements;
        root["mesh"] = std::move(o);
    }

    root["analysis"] = analysis_json(m.analysis, nullptr);
    if (!m.bolts.empty()) {
        json list = json::array();
        for (const Bolt& b : m.bolts) {
            json o{{"name", b.name}, {"from", point(b.from)}, {"to", point(b.to)}};
            write_fields(b, bolt_fields(), o);
            list.push_back(std::move(o));
        }
        root["bolts"] = std::move(list);
    }
    if (!m.stages.empty()) {
        json list = json::array();
        for (const Stage& st : m.stages) {
            json o;
            o["name"] = st.name;
            auto regions = [&](const std::vector<int>& indices) {
                json names = json::array();
                for (int r : indices) names.push_back(name_of(m.regions, r, "region"));
                return names;
            };
            if (!st.excavate.empty()) o["excavate"] = regions(st.excavate);
            if (!st.activate.empty()) o["activate"] = regions(st.activate);
            if (!st.materials.empty()) {
                json changes = json::array();
                for (const auto& [r, mat] : st.materials)
                    changes.push_back({{"region", name_of(m.regions, r, "region")},
                                       {"material", name_of(m.materials, mat, "material")}});
                o["materials"] = std::move(changes);
            }
            if (!st.install.empty()) o["install"] = st.install;
            if (!st.remove.empty()) o["remove"] = st.remove;
            const json analysis = analysis_json(st.analysis, &m.analysis);
            if (!analysis.empty()) o["analysis"] = analysis;
            if (st.release_table >= 0) o["release"] = {{"table", name_of(m.load_tables, st.release_table, "load table")}};
            else if (st.release_steps > 0) o["release"] = {{"steps", st.release_steps}};
            if (st.target_ratio > 0.0) o["target_ratio"] = st.target_ratio;
            if (st.reset_displacements) o["reset_displacements"] = true;
            if (st.water) o["water"] = water_json(*st.water);
            if (st.seismic_coefficient)
                o["seismic_coefficient"] = json{{"kh", st.seismic_coefficient->kh}, {"kv", st.seismic_coefficient->kv}};
            list.push_back(std::move(o));
        }
        root["stages"] = std::move(list);
    }
    return root;
}

/// An array of numbers only (a point, an extent) is written on one line.
bool is_flat(const json& j) {
    if (!j.is_array()) return false;
    for (const json& e : j)
        if (e.is_structured()) return false;
    return true;
}

/// Arrays of flat arrays (rings, polylines, table points) get several points per line.
bool is_list_of_flat(const json& j) {
    if (!j.is_array() || j.empty()) return false;
    for (const json& e : j)
        if (!is_flat(e)) return false;
    return true;
}

/// Pretty printer: objects one key per line; points inline. Scalars are dumped by nlohmann,
/// whose number output is the shortest text that reads back to the same double (at most 17
/// significant digits), so every value round-trips exactly.
void print(std::ostream& out, const json& j, int indent) {
    const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
    if (j.is_primitive()) {
        out << j.dump();
    } else if (j.is_object()) {
        if (j.empty()) { out << "{}"; return; }
        out << "{\n";
        bool first = true;
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (!first) out << ",\n";
            first = false;
            out << pad << json(it.key()).dump() << ": ";
            print(out, it.value(), indent + 2);
        }
        out << "\n" << std::string(static_cast<std::size_t>(indent), ' ') << "}";
    } else if (is_flat(j)) {
        out << "[";
        for (std::size_t i = 0; i < j.size(); ++i) out << (i ? ", " : "") << j[i].dump();
        out << "]";
    } else if (is_list_of_flat(j)) {
        constexpr std::size_t per_line = 4;
        out << "[";
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (i % per_line == 0) out << (i ? ",\n" : "\n") << pad;
            else out << ", ";
            print(out, j[i], indent + 2);
        }
        out << "\n" << std::string(static_cast<std::size_t>(indent), ' ') << "]";
    } else {
        out << "[";
        for (std::size_t i = 0; i < j.size(); ++i) {
            out << (i ? ",\n" : "\n") << pad;
            print(out, j[i], indent + 2);
        }
        out << "\n" << std::string(static_cast<std::size_t>(indent), ' ') << "]";
    }
}

}  // namespace

std::string write_model_text(const Model& model) {
    std::ostringstream out;
    print(out, to_json(model), 0);
    out << "\n";
    return out.str();
}

void write_model_file(const std::string& path, const Model& model) {
    // Convert first: a model that cannot be written must not even create the temporary.
    const std::string text = write_model_text(model);
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace mcdda
