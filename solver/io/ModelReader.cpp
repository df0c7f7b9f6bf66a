#include "io/ModelReader.hpp"

#include "io/AccelerationRecord.hpp"
#include "io/FileKind.hpp"
#include "io/JsonOverrides.hpp"
#include "io/JsonText.hpp"
#include "Version.hpp"
#include "material/MaterialLaws.hpp"
#include "model/Defaults.hpp"
#include "model/ModelFields.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace mcdda {

namespace {

using nlohmann::json;

std::string type_name(const json& j) {
    switch (j.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean";
        case json::value_t::string: return "a string";
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        case json::value_t::discarded: return "nothing";
        default: return "a number";
    }
}

std::string number_text(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

/// Walks the JSON document, collecting diagnostics with JSON pointers. Every accessor returns a
/// value even on error (a default), so one pass reports as many problems as possible.
class Parser {
public:
    explicit Parser(std::vector<Diagnostic>& diagnostics) : diagnostics_(diagnostics) {}

    void error(const std::string& path, const std::string& message) {
        diagnostics_.push_back({Diagnostic::Severity::Error, path, message});
    }
    void warning(const std::string& path, const std::string& message) {
        diagnostics_.push_back({Diagnostic::Severity::Warning, path, message});
    }

    /// Reports keys of `object` that are not in `allowed` (typos must not pass silently).
    void check_keys(const json& object, const std::string& path,
                    std::initializer_list<const char*> allowed) {
        check_keys(object, path, std::vector<const char*>(allowed));
    }

    void check_keys(const json& object, const std::string& path, const std::vector<const char*>& allowed) {
        std::set<std::string> known(allowed.begin(), allowed.end());
        for (auto it = object.begin(); it != object.end(); ++it) {
            if (!known.count(it.key())) {
                std::string list;
                for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
                // The key as JSON text (quotes, escapes); a very long one is shortened and named
                // by its parent's pointer, so that a 10 MB key is not printed (twice).
                constexpr std::size_t longest = 60;
                const std::string& key = it.key();
                if (key.size() <= longest) {
                    std::string escaped;  // JSON pointer escapes: ~ → ~0, / → ~1
                    for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
                    error(path + "/" + escaped,
                          "unknown key " + json(key).dump() + " (expected one of: " + list + ")");
                } else {
                    std::size_t cut = longest;  // not inside a UTF-8 sequence
                    while (cut > 0 && (static_cast<unsigned char>(key[cut]) & 0xC0) == 0x80) --cut;
                    error(path.empty() ? "/" : path,
                          "unknown key " + json(key.substr(0, cut)).dump() + "... (" + std::to_string(key.size()) +
                              " characters; expected one of: " + list + ")");
                }
            }
        }
    }

    bool is_object(const json& j, const std::string& path) {
        if (j.is_object()) return true;
        error(path, "must be an object, got " + type_name(j));
        return false;
    }

    /// The array at `key`, or an empty array when absent (or wrong, after an error).
    const json& array(const json& object, const std::string& path, const char* key) {
        static const json empty = json::array();
        if (!object.contains(key)) return empty;
        const json& j = object.at(key);
        if (!j.is_array()) {
            error(path + "/" + key, "must be an array, got " + type_name(j));
            return empty;
        }
        return j;
    }

    double number(const json& object, const std::string& path, const char* key,
                  std::optional<double> fallback) {
        const std::string where = path + "/" + key;
        if (!object.contains(key)) {
            if (!fallback) error(where, "required number is missing");
            return fallback.value_or(0.0);
        }
        return number_value(object.at(key), where, fallback.value_or(0.0));
    }

    double number_value(const json& j, const std::string& where, double fallback = 0.0) {
        if (!j.is_number()) {
            error(where, "must be a number, got " + type_name(j));
            return fallback;
        }
        const double v = j.get<double>();
        if (!std::isfinite(v)) {
            error(where, "must be finite");
            return fallback;
        }
        return v;
    }

    long integer(const json& object, const std::string& path, const char* key, long fallback) {
        const std::string where = path + "/" + key;
        if (!object.contains(key)) return fallback;
        const json& j = object.at(key);
        if (j.is_number_integer()) return j.get<long>();
        if (j.is_number_float()) {
            const double v = j.get<double>();
            if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9e15) return static_cast<long>(v);
        }
        error(where, "must be a whole number, got " + (j.is_number() ? number_text(j.get<double>()) : type_name(j)));
        return fallback;
    }

    /// A whole number that an int holds (counts of steps, iterations, trials): beyond it the
    /// value is an error, not wrapped around (4294967297 steps were read as 1).
    int whole(const json& object, const std::string& path, const char* key, int fallback) {
        const long v = integer(object, path, key, fallback);
        if (v > std::numeric_limits<int>::max() || v < std::numeric_limits<int>::min()) {
            error(path + "/" + key, "must be a whole number below 2147483648, got " + std::to_string(v));
            return fallback;
        }
        return static_cast<int>(v);
    }

    bool boolean(const json& object, const std::string& path, const char* key, bool fallback) {
        if (!object.contains(key)) return fallback;
        const json& j = object.at(key);
        if (j.is_boolean()) return j.get<bool>();
        error(path + "/" + key, "must be true or false, got " + type_name(j));
        return fallback;
    }

    std::string string(const json& object, const std::string& path, const char* key,
                       std::optional<std::string> fallback) {
        const std::string where = path + "/" + key;
        if (!object.contains(key)) {
            if (!fallback) error(where, "required text is missing");
            return fallback.value_or("");
        }
        const json& j = object.at(key);
        if (j.is_string()) return j.get<std::string>();
        error(where, "must be a string, got " + type_name(j));
        return fallback.value_or("");
    }

    Point2 point_value(const json& j, const std::string& where) {
        if (!j.is_array() || j.size() != 2) {
            error(where, "must be a point [x, y], got " + (j.is_array() ? "an array of " + std::to_string(j.size()) : type_name(j)));
            return {};
        }
        return {number_value(j[0], where + "/0"), number_value(j[1], where + "/1")};
    }

    Point2 point(const json& object, const std::string& path, const char* key,
                 std::optional<Point2> fallback = std::nullopt) {
        if (!object.contains(key)) {
            if (!fallback) error(path + "/" + key, "required point [x, y] is missing");
            return fallback.value_or(Point2{});
        }
        return point_value(object.at(key), path + "/" + key);
    }

    /// Angle given in degrees in the file; returned in radians.
    double angle(const json& object, const std::string& path, const char* key,
                 std::optional<double> fallback_deg) {
        return number(object, path, key, fallback_deg) * degree;
    }

private:
    std::vector<Diagnostic>& diagnostics_;
};

bool near(Point2 a, Point2 b, double scale) { return std::hypot(a.x - b.x, a.y - b.y) <= 1e-9 * scale; }

/// Appends the points of an arc (both ends when `include_end`). Cosines and sines that are zero
/// up to rounding are snapped, so an arc from 0° to 90° meets the axes exactly; a point equal to
/// the ring's previous one (an arc starting where the last edge ended) is not repeated.
void append_arc(Ring& ring, Point2 c, double r, double a0, double a1, int segments, bool include_end) {
    const int last = include_end ? segments : segments - 1;
    for (int i = 0; i <= last; ++i) {
        const double a = a0 + (a1 - a0) * i / segments;
        double cs = std::cos(a), sn = std::sin(a);
        if (std::fabs(cs) < 1e-12) cs = 0.0;
        if (std::fabs(sn) < 1e-12) sn = 0.0;
        const Point2 p{c.x + r * cs, c.y + r * sn};
        if (!ring.empty() && near(ring.back(), p, r)) continue;
        ring.push_back(p);
    }
}

int segment_count(Parser& p, const json& o, const std::string& path, long fallback) {
    const long n = p.integer(o, path, "segments", fallback);
    if (n < 3 || n > 100000) {
        p.error(path + "/segments", "must be between 3 and 100000, got " + std::to_string(n));
        return static_cast<int>(fallback);
    }
    return static_cast<int>(n);
}

/// RING := [ [x,y] | {"arc": {...}} , ... ]  |  {"circle": {"center", "radius", "segments"}}
Ring parse_ring(Parser& p, const json& j, const std::string& path) {
    Ring ring;
    if (j.is_object()) {
        p.check_keys(j, path, {"circle"});
        if (!j.contains("circle")) {
            p.error(path, "a ring is an array of points or {\"circle\": {...}}");
            return ring;
        }
        const json& c = j.at("circle");
        const std::string cpath = path + "/circle";
        if (!p.is_object(c, cpath)) return ring;
        p.check_keys(c, cpath, {"center", "radius", "segments"});
        const Point2 center = p.point(c, cpath, "center");
        const double radius = p.number(c, cpath, "radius", std::nullopt);
        const int n = segment_count(p, c, cpath, 64);
        if (!(radius > 0.0)) {
            p.error(cpath + "/radius", "must be positive, got " + number_text(radius));
            return ring;
        }
        append_arc(ring, center, radius, 0.0, 2.0 * pi, n, false);
        return ring;
    }
    if (!j.is_array()) {
        p.error(path, "must be an array of points [x, y], got " + type_name(j));
        return ring;
    }
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string epath = path + "/" + std::to_string(i);
        const json& e = j[i];
        if (e.is_object()) {
            p.check_keys(e, epath, {"arc"});
            if (!e.contains("arc") || !p.is_object(e.at("arc"), epath + "/arc")) {
                if (!e.contains("arc")) p.error(epath, "expected a point [x, y] or {\"arc\": {...}}");
                continue;
            }
            const json& a = e.at("arc");
            const std::string apath = epath + "/arc";
            p.check_keys(a, apath, {"center", "radius", "start", "end", "segments"});
            const Point2 center = p.point(a, apath, "center");
            const double radius = p.number(a, apath, "radius", std::nullopt);
            const double start = p.angle(a, apath, "start", std::nullopt);
            const double end = p.angle(a, apath, "end", std::nullopt);
            const int n = segment_count(p, a, apath, 16);
            if (!(radius > 0.0)) {
                p.error(apath + "/radius", "must be positive, got " + number_text(radius));
                continue;
            }
            if (start == end) {
                p.error(apath, "start and end angles are equal");
                continue;
            }
            append_arc(ring, center, radius, start, end, n, true);
            // An arc that closes the ring ends on its first point.
            if (i + 1 == j.size() && ring.size() > 1 && near(ring.back(), ring.front(), radius)) ring.pop_back();
        } else {
            ring.push_back(p.point_value(e, epath));
        }
    }
    return ring;
}

/// Resolves a name to an index in `names`; reports an unknown name listing the known ones.
int lookup(Parser& p, const std::map<std::string, int>& names, const std::string& name,
           const std::string& where, const char* what) {
    const auto it = names.find(name);
    if (it != names.end()) return it->second;
    std::string list;
    for (const auto& [n, i] : names) list += (list.empty() ? "" : ", ") + ("\"" + n + "\"");
    p.error(where, std::string("no ") + what + " named \"" + name + "\"" +
                       (list.empty() ? std::string(" (none are defined)") : " (defined: " + list + ")"));
    return -1;
}

/// Records names, reporting duplicates and empty names.
std::map<std::string, int> collect_names(Parser& p, const json& list, const std::string& path) {
    std::map<std::string, int> names;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (!list[i].is_object() || !list[i].contains("name") || !list[i]["name"].is_string()) continue;
        const std::string name = list[i]["name"].get<std::string>();
        const std::string where = path + "/" + std::to_string(i) + "/name";
        if (name.empty()) p.error(where, "must not be empty");
        else if (!names.emplace(name, static_cast<int>(i)).second)
            p.error(where, "duplicate name \"" + name + "\"");
    }
    return names;
}

/// The keys a record may have: `more` and its declared number fields.
template <class Record>
std::vector<const char*> keys_of(const std::vector<RecordField<Record>>& fields, std::initializer_list<const char*> more) {
    std::vector<const char*> keys(more);
    for (const RecordField<Record>& f : fields) keys.push_back(f.field.key);
    return keys;
}

/// The declared number fields of `record` from `o`, in the file's units (ModelFields.hpp);
/// those absent take their default, a required one absent is an error.
template <class Record>
void read_fields(Parser& p, const json& o, const std::string& path, const std::vector<RecordField<Record>>& fields,
                 Record& record) {
    for (const RecordField<Record>& f : fields) {
        std::optional<double> fallback;
        if (f.field.default_value) fallback = to_file_unit(f.field.quantity, *f.field.default_value);
        record.*f.member = from_file_unit(f.field.quantity, p.number(o, path, f.field.key, fallback));
    }
}

/// The same over the values already in `record` (a stage's analysis over the model's): an
/// absent field keeps its value.
template <class Record>
void read_fields_over(Parser& p, const json& o, const std::string& path, const std::vector<RecordField<Record>>& fields,
                      Record& record) {
    for (const RecordField<Record>& f : fields) {
        const double kept = to_file_unit(f.field.quantity, record.*f.member);
        record.*f.member = from_file_unit(f.field.quantity, p.number(o, path, f.field.key, kept));
    }
}

/// The law a material names: "law", or the older `"plastic": false` (elastic) and true
/// (Mohr–Coulomb); Mohr–Coulomb when it says nothing.
const MaterialLaw* material_law(Parser& p, const json& o, const std::string& path) {
    if (o.contains("law") && o.contains("plastic")) {
        p.error(path, "give either \"law\" or the older \"plastic\", not both");
        return nullptr;
    }
    if (o.contains("plastic")) return find_material_law(p.boolean(o, path, "plastic", true) ? "mohr-coulomb" : "elastic");
    const std::string key = p.string(o, path, "law", std::string(material_laws().front()->key));
    const MaterialLaw* law = find_material_law(key);
    if (!law) p.error(path + "/law", "unknown law " + json(key).dump() + " (the laws are " + material_law_keys() + ")");
    return law;
}

/// The keys a material with `law` may have. `"plastic": false` files of the earlier format
/// may still carry Mohr–Coulomb strengths; they are read past.
std::vector<const char*> material_keys(const MaterialLaw& law, bool legacy_elastic) {
    std::vector<const char*> keys = keys_of(material_fields(), {"name", "law", "unit_weight", "saturated_unit_weight", "plastic", "reduce"});
    for (const NumberField& f : (legacy_elastic ? *find_material_law("mohr-coulomb") : law).fields) keys.push_back(f.key);
    return keys;
}

void parse_materials(Parser& p, const json& root, Model& m) {
    const json& list = p.array(root, "", "materials");
    if (list.empty()) p.error("/materials", "at least one material is required");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/materials/" + std::to_string(i);
        const json& o = list[i];
        Material mat;
        const MaterialLaw* law = p.is_object(o, path) ? material_law(p, o, path) : nullptr;
        if (!law) { m.materials.push_back(mat); continue; }
        mat.law = law->key;
        p.check_keys(o, path, material_keys(*law, o.contains("plastic")));
        mat.name = p.string(o, path, "name", std::nullopt);
        read_fields(p, o, path, material_fields(), mat);
        for (const NumberField& f : law->fields) {
            std::optional<double> fallback;
            if (f.default_value) fallback = to_file_unit(f.quantity, *f.default_value);
            mat.parameters[f.key] = from_file_unit(f.quantity, p.number(o, path, f.key, fallback));
        }
        if (o.contains("density") && o.contains("unit_weight"))
            p.error(path, "give either density or unit_weight, not both");
        if (o.contains("unit_weight")) mat.density = p.number(o, path, "unit_weight", 0.0) / standard_gravity;
        if (o.contains("saturated_density") && o.contains("saturated_unit_weight"))
            p.error(path, "give either saturated_density or saturated_unit_weight, not both");
        if (o.contains("saturated_unit_weight"))
            mat.saturated_density = p.number(o, path, "saturated_unit_weight", 0.0) / standard_gravity;
        mat.reduce = p.boolean(o, path, "reduce", true);
        m.materials.push_back(mat);
    }
}

void parse_joint_materials(Parser& p, const json& root, Model& m, std::map<std::string, int>& names) {
    const json& list = p.array(root, "", "joint_materials");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/joint_materials/" + std::to_string(i);
        const json& o = list[i];
        JointMaterial jm;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, keys_of(joint_material_fields(), {"name", "reduce"}));
            jm.name = p.string(o, path, "name", std::nullopt);
            jm.reduce = p.boolean(o, path, "reduce", true);
            read_fields(p, o, path, joint_material_fields(), jm);
        }
        m.joint_materials.push_back(jm);
    }
    if (m.joint_materials.empty()) {
        // Region interfaces need some contact law; a frictional, cohesionless one is the safe default.
        JointMaterial fallback;
        fallback.name = "default";
        fallback.friction_angle = 30.0 * degree;
        m.joint_materials.push_back(fallback);
        names["default"] = 0;
    }
    if (root.contains("default_joint_material")) {
        const std::string name = p.string(root, "", "default_joint_material", std::string());
        m.default_joint_material = lookup(p, names, name, "/default_joint_material", "joint material");
    } else {
        m.default_joint_material = 0;
    }
}

int optional_reference(Parser& p, const json& o, const std::string& path, const char* key,
                       const std::map<std::string, int>& names, const char* what) {
    if (!o.contains(key)) return -1;
    const std::string name = p.string(o, path, key, std::string());
    return lookup(p, names, name, path + "/" + key, what);
}

void parse_geometry(Parser& p, const json& root, Model& m, const std::map<std::string, int>& material_names,
                    const std::map<std::string, int>& joint_material_names) {
    const json& regions = p.array(root, "", "regions");
    if (regions.empty()) p.error("/regions", "at least one region is required");
    for (std::size_t i = 0; i < regions.size(); ++i) {
        const std::string path = "/regions/" + std::to_string(i);
        const json& o = regions[i];
        Region r;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "material", "boundary", "holes", "mesh_size"});
            r.name = p.string(o, path, "name", "region " + std::to_string(i + 1));
            const std::string material = p.string(o, path, "material", std::nullopt);
            r.material = lookup(p, material_names, material, path + "/material", "material");
            if (o.contains("boundary")) r.boundary = parse_ring(p, o.at("boundary"), path + "/boundary");
            else p.error(path + "/boundary", "required ring of points is missing");
            const json& holes = p.array(o, path, "holes");
            for (std::size_t h = 0; h < holes.size(); ++h)
                r.holes.push_back(parse_ring(p, holes[h], path + "/holes/" + std::to_string(h)));
            r.mesh_size = p.number(o, path, "mesh_size", 0.0);
        }
        m.regions.push_back(std::move(r));
    }

    const json& joints = p.array(root, "", "joints");
    for (std::size_t i = 0; i < joints.size(); ++i) {
        const std::string path = "/joints/" + std::to_string(i);
        const json& o = joints[i];
        Joint jt;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "points", "joint_material"});
            jt.name = p.string(o, path, "name", "joint " + std::to_string(i + 1));
            const json& pts = p.array(o, path, "points");
            if (!o.contains("points")) p.error(path + "/points", "required list of points is missing");
            for (std::size_t k = 0; k < pts.size(); ++k)
                jt.points.push_back(p.point_value(pts[k], path + "/points/" + std::to_string(k)));
            jt.joint_material = optional_reference(p, o, path, "joint_material", joint_material_names, "joint material");
        }
        m.joints.push_back(std::move(jt));
    }

    const json& sets = p.array(root, "", "joint_sets");
    for (std::size_t i = 0; i < sets.size(); ++i) {
        const std::string path = "/joint_sets/" + std::to_string(i);
        const json& o = sets[i];
        JointSet s;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "angle", "spacing", "origin", "extent", "joint_material", "persistence",
                                   "trace_length", "stagger"});
            s.name = p.string(o, path, "name", "set " + std::to_string(i + 1));
            s.angle = p.angle(o, path, "angle", std::nullopt);
            s.spacing = p.number(o, path, "spacing", std::nullopt);
            s.origin = p.point(o, path, "origin", Point2{0.0, 0.0});
            if (o.contains("extent")) {
                const json& e = o.at("extent");
                if (!e.is_array() || e.size() != 4) {
                    p.error(path + "/extent", "must be [xmin, ymin, xmax, ymax]");
                } else {
                    std::array<double, 4> box{};
                    for (int k = 0; k < 4; ++k) box[k] = p.number_value(e[k], path + "/extent/" + std::to_string(k));
                    s.extent = box;
                }
            }
            s.joint_material = optional_reference(p, o, path, "joint_material", joint_material_names, "joint material");
            const JointSet defaults;
            s.persistence = p.number(o, path, "persistence", defaults.persistence);
            s.trace_length = p.number(o, path, "trace_length", defaults.trace_length);
            s.stagger = p.number(o, path, "stagger", defaults.stagger);
        }
        m.joint_sets.push_back(s);
    }
}

void parse_tables(Parser& p, const json& root, Model& m) {
    const json& list = p.array(root, "", "load_tables");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/load_tables/" + std::to_string(i);
        const json& o = list[i];
        LoadTable t;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "variable", "points", "extrapolate"});
            t.name = p.string(o, path, "name", std::nullopt);
            const std::string variable = p.string(o, path, "variable", std::string("step"));
            if (variable == "step") t.variable = LoadTable::Variable::Step;
            else if (variable == "time") t.variable = LoadTable::Variable::Time;
            else p.error(path + "/variable", "must be \"step\" or \"time\", got \"" + variable + "\"");
            const json& pts = p.array(o, path, "points");
            if (pts.empty()) p.error(path + "/points", "needs at least one [abscissa, factor] pair");
            for (std::size_t k = 0; k < pts.size(); ++k) {
                const Point2 q = p.point_value(pts[k], path + "/points/" + std::to_string(k));
                t.points.push_back({q.x, q.y});
            }
            t.extrapolate = p.boolean(o, path, "extrapolate", false);
        }
        m.load_tables.push_back(t);
    }
}

void parse_supports_and_loads(Parser& p, const json& root, Model& m, const std::map<std::string, int>& table_names) {
    const json& fixed = p.array(root, "", "fixed_points");
    for (std::size_t i = 0; i < fixed.size(); ++i) {
        const std::string path = "/fixed_points/" + std::to_string(i);
        FixedPoint f;
        if (p.is_object(fixed[i], path)) {
            p.check_keys(fixed[i], path, {"name", "point"});
            f.name = p.string(fixed[i], path, "name", "fixed " + std::to_string(i + 1));
            f.point = p.point(fixed[i], path, "point");
        }
        m.fixed_points.push_back(f);
    }
    const json& rollers = p.array(root, "", "rollers");
    for (std::size_t i = 0; i < rollers.size(); ++i) {
        const std::string path = "/rollers/" + std::to_string(i);
        const json& o = rollers[i];
        Roller r;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "from", "to", "fixed", "displacement", "table"});
            r.name = p.string(o, path, "name", "roller " + std::to_string(i + 1));
            r.from = p.point(o, path, "from");
            r.to = p.point(o, path, "to");
            const std::string fixed_dir = p.string(o, path, "fixed", std::nullopt);
            r.fix_x = fixed_dir == "x" || fixed_dir == "xy";
            r.fix_y = fixed_dir == "y" || fixed_dir == "xy";
            if (!r.fix_x && !r.fix_y && !fixed_dir.empty())
                p.error(path + "/fixed", "must be \"x\", \"y\" or \"xy\", got \"" + fixed_dir + "\"");
            if (o.contains("displacement")) r.displacement = p.point(o, path, "displacement");
            r.table = optional_reference(p, o, path, "table", table_names, "load table");
        }
        m.rollers.push_back(r);
    }
    const json& loads = p.array(root, "", "point_loads");
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const std::string path = "/point_loads/" + std::to_string(i);
        const json& o = loads[i];
        PointLoad l;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "point", "force", "table"});
            l.name = p.string(o, path, "name", "load " + std::to_string(i + 1));
            l.point = p.point(o, path, "point");
            l.force = p.point(o, path, "force");
            l.table = optional_reference(p, o, path, "table", table_names, "load table");
        }
        m.point_loads.push_back(l);
    }
    const json& pressures = p.array(root, "", "edge_pressures");
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        const std::string path = "/edge_pressures/" + std::to_string(i);
        const json& o = pressures[i];
        EdgePressure e;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "from", "to", "pressure", "table"});
            e.name = p.string(o, path, "name", "pressure " + std::to_string(i + 1));
            e.from = p.point(o, path, "from");
            e.to = p.point(o, path, "to");
            e.pressure = p.number(o, path, "pressure", std::nullopt);
            e.table = optional_reference(p, o, path, "table", table_names, "load table");
        }
        m.edge_pressures.push_back(e);
    }
    if (root.contains("gravity")) m.gravity = p.point(root, "", "gravity");
    m.gravity_table = optional_reference(p, root, "", "gravity_table", table_names, "load table");

    if (root.contains("initial_stress")) {
        const json& o = root.at("initial_stress");
        const std::string path = "/initial_stress";
        if (p.is_object(o, path)) {
            const std::string type = p.string(o, path, "type", std::nullopt);
            InitialStress& s = m.initial_stress;
            if (type == "uniform") {
                p.check_keys(o, path, {"type", "sxx", "syy", "sxy", "szz"});
                // Entered compression positive (geotechnical); stored tension positive.
                s.kind = InitialStress::Kind::Uniform;
                s.stress = {-p.number(o, path, "sxx", 0.0), -p.number(o, path, "syy", 0.0),
                            -p.number(o, path, "sxy", 0.0)};
                if (o.contains("szz")) s.stress_zz = -p.number(o, path, "szz", 0.0);
            } else if (type == "gravity") {
                p.check_keys(o, path, {"type", "surface_y", "k0"});
                s.kind = InitialStress::Kind::Gravity;
                s.surface_y = p.number(o, path, "surface_y", std::nullopt);
                s.k0 = p.number(o, path, "k0", std::nullopt);
            } else if (type == "none") {
                p.check_keys(o, path, {"type"});
            } else if (!type.empty()) {
                p.error(path + "/type", "must be \"uniform\", \"gravity\" or \"none\", got \"" + type + "\"");
            }
        }
    }

    const json& points = p.array(root, "", "measurement_points");
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string path = "/measurement_points/" + std::to_string(i);
        MeasurementPoint mp;
        if (p.is_object(points[i], path)) {
            p.check_keys(points[i], path, {"name", "point"});
            mp.name = p.string(points[i], path, "name", std::nullopt);
            mp.point = p.point(points[i], path, "point");
        }
        m.measurement_points.push_back(mp);
    }
    collect_names(p, points, "/measurement_points");
}

void parse_mesh(Parser& p, const json& root, Model& m) {
    if (!root.contains("mesh")) return;
    const json& o = root.at("mesh");
    const std::string path = "/mesh";
    if (!p.is_object(o, path)) return;
    p.check_keys(o, path, {"element", "size", "min_angle", "grading", "local", "max_elements"});
    MeshControls& c = m.mesh;
    const std::string element = p.string(o, path, "element", std::string("auto"));
    if (element == "auto") c.element = ElementType::Automatic;
    else if (element == "t3") c.element = ElementType::T3;
    else if (element == "t6") c.element = ElementType::T6;
    else p.error(path + "/element", "must be \"auto\", \"t3\" or \"t6\", got \"" + element + "\"");
    c.size = p.number(o, path, "size", 0.0);
    c.min_angle = p.angle(o, path, "min_angle", 25.0);
    c.grading = p.number(o, path, "grading", c.grading);
    c.max_elements = p.integer(o, path, "max_elements", c.max_elements);
    const json& local = p.array(o, path, "local");
    for (std::size_t i = 0; i < local.size(); ++i) {
        const std::string lpath = path + "/local/" + std::to_string(i);
        const json& l = local[i];
        if (!p.is_object(l, lpath)) continue;
        p.check_keys(l, lpath, {"point", "from", "to", "size", "radius"});
        LocalSize s;
        if (l.contains("point")) {
            if (l.contains("from") || l.contains("to")) p.error(lpath, "give either point or from/to, not both");
            s.from = s.to = p.point(l, lpath, "point");
        } else {
            s.from = p.point(l, lpath, "from");
            s.to = p.point(l, lpath, "to");
        }
        s.size = p.number(l, lpath, "size", std::nullopt);
        s.radius = p.number(l, lpath, "radius", 0.0);
        c.local.push_back(s);
    }
}

/// The settings of an "analysis" object at `path` over those already in `a` (a stage's analysis
/// overrides the model's).
void parse_analysis_object(Parser& p, const json& o, const std::string& path, AnalysisSettings& a) {
    if (!p.is_object(o, path)) return;
    p.check_keys(o, path, keys_of(analysis_fields(), {"type", "steps", "open_close_iterations", "plastic_iterations",
                                                      "geometry", "output_every", "plasticity", "max_trials",
                                                      "non_associated_flow"}));
    const std::string type = p.string(o, path, "type", std::string(analysis_type_name(a)));
    a.strength_reduction = type == "strength_reduction";
    if (type == "static" || type == "strength_reduction") a.kind = AnalysisSettings::Kind::Static;
    else if (type == "dynamic") a.kind = AnalysisSettings::Kind::Dynamic;
    else p.error(path + "/type", "must be \"static\", \"dynamic\" or \"strength_reduction\", got \"" + type + "\"");
    a.max_trials = p.whole(o, path, "max_trials", a.max_trials);
    const std::string flow = p.string(o, path, "non_associated_flow",
                                       std::string(non_associated_flow_name(a.non_associated_flow)));
    if (flow == "davis") a.non_associated_flow = AnalysisSettings::NonAssociatedFlow::Davis;
    else if (flow == "direct") a.non_associated_flow = AnalysisSettings::NonAssociatedFlow::Direct;
    else p.error(path + "/non_associated_flow", "must be \"davis\" or \"direct\", got \"" + flow + "\"");
    a.steps = p.whole(o, path, "steps", a.steps);
    read_fields_over(p, o, path, analysis_fields(), a);
    a.max_open_close_iterations = p.whole(o, path, "open_close_iterations", a.max_open_close_iterations);
    a.max_plastic_iterations = p.whole(o, path, "plastic_iterations", a.max_plastic_iterations);
    const std::string geometry = p.string(
        o, path, "geometry", std::string(a.geometry == AnalysisSettings::Geometry::Updated ? "updated" : "initial"));
    if (geometry == "updated") a.geometry = AnalysisSettings::Geometry::Updated;
    else if (geometry == "initial") a.geometry = AnalysisSettings::Geometry::Initial;
    else p.error(path + "/geometry", "must be \"updated\" or \"initial\", got \"" + geometry + "\"");
    a.output_every = p.whole(o, path, "output_every", a.output_every);
    a.plasticity = p.boolean(o, path, "plasticity", a.plasticity);
}

/// A "water" object (the model's or a stage's); ModelValidator checks its values.
Water parse_water(Parser& p, const json& o, const std::string& path) {
    Water w;
    if (!p.is_object(o, path)) return w;
    p.check_keys(o, path, {"piezometric_line", "unit_weight"});
    w.unit_weight = p.number(o, path, "unit_weight", w.unit_weight);  // checked by the validator
    if (!o.contains("piezometric_line")) {
        p.error(path + "/piezometric_line", "required line [[x, y], ...] is missing (an empty list: dry)");
        return w;
    }
    const json& line = p.array(o, path, "piezometric_line");
    for (std::size_t i = 0; i < line.size(); ++i)
        w.piezometric_line.push_back(p.point_value(line[i], path + "/piezometric_line/" + std::to_string(i)));
    return w;
}

/// A "seismic_coefficient" object (the model's or a stage's).
SeismicCoefficient parse_seismic(Parser& p, const json& o, const std::string& path) {
    SeismicCoefficient k;
    if (!p.is_object(o, path)) return k;
    p.check_keys(o, path, {"kh", "kv"});
    k.kh = p.number(o, path, "kh", 0.0);
    k.kv = p.number(o, path, "kv", 0.0);
    return k;
}

/// "ground_motions", "base_motion" and "absorbing_boundaries" (docs/model-format.md,
/// "Earthquakes"). Files are read later (load_ground_motion_files).
void parse_earthquake(Parser& p, const json& root, Model& m) {
    const json& motions = p.array(root, "", "ground_motions");
    const auto names = collect_names(p, motions, "/ground_motions");
    for (std::size_t i = 0; i < motions.size(); ++i) {
        const std::string path = "/ground_motions/" + std::to_string(i);
        const json& o = motions[i];
        GroundMotion g;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "file", "points", "units", "scale", "baseline_correction"});
            g.name = p.string(o, path, "name", std::nullopt);
            if (o.contains("file") == o.contains("points"))
                p.error(path, "give either \"file\" (a CSV or .AT2 record) or \"points\" ([[t, a], ...]), one of them");
            g.file = p.string(o, path, "file", std::string());
            if (o.contains("file") && g.file.empty()) p.error(path + "/file", "must name a file");
            const json& points = p.array(o, path, "points");
            for (std::size_t k = 0; k < points.size(); ++k) {
                const Point2 q = p.point_value(points[k], path + "/points/" + std::to_string(k));
                g.points.push_back({q.x, q.y});
            }
            const std::string units = p.string(o, path, "units", std::string("g"));
            if (units == "g") g.units = GroundMotion::Units::G;
            else if (units == "m/s2") g.units = GroundMotion::Units::MetresPerSecondSquared;
            else p.error(path + "/units", "must be \"g\" or \"m/s2\", got \"" + units + "\"");
            g.scale = p.number(o, path, "scale", 1.0);
            g.baseline_correction = p.boolean(o, path, "baseline_correction", true);
        }
        m.ground_motions.push_back(std::move(g));
    }
    if (root.contains("base_motion") && p.is_object(root.at("base_motion"), "/base_motion")) {
        const json& o = root.at("base_motion");
        const std::string path = "/base_motion";
        p.check_keys(o, path, {"type", "x", "y", "from", "to"});
        BaseMotion& b = m.base_motion;
        const std::string type = p.string(o, path, "type", std::string("rigid"));
        if (type == "rigid") b.kind = BaseMotion::Kind::Rigid;
        else if (type == "compliant") b.kind = BaseMotion::Kind::Compliant;
        else p.error(path + "/type", "must be \"rigid\" or \"compliant\", got \"" + type + "\"");
        b.x = optional_reference(p, o, path, "x", names, "ground motion");
        b.y = optional_reference(p, o, path, "y", names, "ground motion");
        if (!o.contains("x") && !o.contains("y"))
            p.error(path, "name the ground motion of \"x\" (horizontal), \"y\" (vertical) or both");
        if (b.kind == BaseMotion::Kind::Compliant) {
            b.from = p.point(o, path, "from");
            b.to = p.point(o, path, "to");
        } else if (o.contains("from") || o.contains("to")) {
            p.error(path, "a rigid base moves every support: \"from\" and \"to\" belong to a compliant base");
        }
    }
    const json& absorbing = p.array(root, "", "absorbing_boundaries");
    collect_names(p, absorbing, "/absorbing_boundaries");
    for (std::size_t i = 0; i < absorbing.size(); ++i) {
        const std::string path = "/absorbing_boundaries/" + std::to_string(i);
        const json& o = absorbing[i];
        AbsorbingBoundary a;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "from", "to"});
            a.name = p.string(o, path, "name", "absorbing boundary " + std::to_string(i + 1));
            a.from = p.point(o, path, "from");
            a.to = p.point(o, path, "to");
        }
        m.absorbing_boundaries.push_back(a);
    }
    if (root.contains("seismic_coefficient"))
        m.seismic_coefficient = parse_seismic(p, root.at("seismic_coefficient"), "/seismic_coefficient");
}

/// Reads the record files the ground motions name, relative to `directory` (the model file's).
void load_ground_motion_files(Model& m, const std::string& directory, std::vector<Diagnostic>& diagnostics) {
    namespace fs = std::filesystem;
    for (std::size_t i = 0; i < m.ground_motions.size(); ++i) {
        GroundMotion& g = m.ground_motions[i];
        if (g.file.empty()) continue;
        fs::path file(g.file);
        if (file.is_relative() && !directory.empty()) file = fs::path(directory) / file;
        try {
            AccelerationRecord r = read_acceleration_record(file.string());
            g.points = std::move(r.points);
        } catch (const std::exception& e) {
            diagnostics.push_back({Diagnostic::Severity::Error, "/ground_motions/" + std::to_string(i) + "/file", e.what()});
        }
    }
}

void parse_analysis(Parser& p, const json& root, Model& m) {
    if (root.contains("analysis")) parse_analysis_object(p, root.at("analysis"), "/analysis", m.analysis);
}

void parse_bolts(Parser& p, const json& root, Model& m) {
    const json& list = p.array(root, "", "bolts");
    collect_names(p, list, "/bolts");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/bolts/" + std::to_string(i);
        const json& o = list[i];
        Bolt b;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, keys_of(bolt_fields(), {"name", "from", "to"}));
            b.name = p.string(o, path, "name", std::nullopt);
            b.from = p.point(o, path, "from");
            b.to = p.point(o, path, "to");
            read_fields(p, o, path, bolt_fields(), b);
        }
        m.bolts.push_back(b);
    }
}

/// Names of a stage's list (regions or items) as strings, each checked.
std::vector<std::string> name_list(Parser& p, const json& o, const std::string& path, const char* key) {
    std::vector<std::string> names;
    const json& list = p.array(o, path, key);
    for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string where = path + "/" + key + "/" + std::to_string(k);
        if (!list[k].is_string()) p.error(where, "must be a name (a string)");
        else names.push_back(list[k].get<std::string>());
    }
    return names;
}

void parse_stages(Parser& p, const json& root, Model& m, const std::map<std::string, int>& material_names,
                  const std::map<std::string, int>& table_names) {
    const json& list = p.array(root, "", "stages");
    collect_names(p, list, "/stages");
    std::map<std::string, int> regions;
    for (std::size_t r = 0; r < m.regions.size(); ++r) regions.emplace(m.regions[r].name, static_cast<int>(r));
    auto region_indices = [&](const json& o, const std::string& path, const char* key) {
        std::vector<int> indices;
        const auto names = name_list(p, o, path, key);
        for (std::size_t k = 0; k < names.size(); ++k) {
            const int r = lookup(p, regions, names[k], path + "/" + key + "/" + std::to_string(k), "region");
            if (r >= 0) indices.push_back(r);
        }
        return indices;
    };
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/stages/" + std::to_string(i);
        const json& o = list[i];
        Stage st;
        st.analysis = m.analysis;
        if (p.is_object(o, path)) {
            p.check_keys(o, path, {"name", "excavate", "activate", "materials", "install", "remove", "analysis",
                                   "release", "target_ratio", "reset_displacements", "water",
                                   "seismic_coefficient"});
            st.name = p.string(o, path, "name", std::nullopt);
            st.excavate = region_indices(o, path, "excavate");
            st.activate = region_indices(o, path, "activate");
            const json& changes = p.array(o, path, "materials");
            for (std::size_t k = 0; k < changes.size(); ++k) {
                const std::string where = path + "/materials/" + std::to_string(k);
                if (!p.is_object(changes[k], where)) continue;
                p.check_keys(changes[k], where, {"region", "material"});
                const int r = lookup(p, regions, p.string(changes[k], where, "region", std::nullopt), where + "/region",
                                     "region");
                const int mat = lookup(p, material_names, p.string(changes[k], where, "material", std::nullopt),
                                       where + "/material", "material");
                if (r >= 0 && mat >= 0) st.materials.push_back({r, mat});
            }
            st.install = name_list(p, o, path, "install");
            st.remove = name_list(p, o, path, "remove");
            if (o.contains("analysis")) parse_analysis_object(p, o.at("analysis"), path + "/analysis", st.analysis);
            if (o.contains("release") && p.is_object(o.at("release"), path + "/release")) {
                const json& r = o.at("release");
                const std::string where = path + "/release";
                p.check_keys(r, where, {"steps", "table"});
                if (r.contains("steps") && r.contains("table"))
                    p.error(where, "give either \"steps\" or \"table\", not both");
                st.release_steps = p.whole(r, where, "steps", 0);
                if (st.release_steps < 0) p.error(where + "/steps", "must be 0 (all the stage's steps) or more");
                st.release_table = optional_reference(p, r, where, "table", table_names, "load table");
            }
            st.target_ratio = p.number(o, path, "target_ratio", 0.0);
            st.reset_displacements = p.boolean(o, path, "reset_displacements", false);
            if (o.contains("water")) st.water = parse_water(p, o.at("water"), path + "/water");
            if (o.contains("seismic_coefficient"))
                st.seismic_coefficient = parse_seismic(p, o.at("seismic_coefficient"), path + "/seismic_coefficient");
        }
        m.stages.push_back(st);
    }
}

}  // namespace

ReadResult read_model_text(const std::string& text, const std::vector<std::string>& overrides,
                           const std::string& source) {
    ReadResult result;
    std::optional<json> parsed = parse_json_text(text, source, result.diagnostics);
    if (!parsed) return result;
    json& root = *parsed;
    apply_overrides(root, overrides, result.diagnostics);

    Parser p(result.diagnostics);
    if (!p.is_object(root, "")) return result;
    p.check_keys(root, "", {"format", "version", "name", "description", "materials", "joint_materials",
                            "default_joint_material", "regions", "joints", "joint_sets", "load_tables",
                            "fixed_points", "rollers", "point_loads", "edge_pressures", "gravity",
                            "gravity_table", "initial_stress", "water", "measurement_points", "mesh", "analysis", "bolts", "stages",
                            "ground_motions", "base_motion", "absorbing_boundaries", "seismic_coefficient"});
    const std::string format = p.string(root, "", "format", std::nullopt);
    if (root.contains("format") && root.at("format").is_string() && format != model_format_name)
        p.error("/format", "must be \"" + std::string(model_format_name) + "\", got \"" + format + "\"");
    const long version = p.integer(root, "", "version", -1);
    if (!root.contains("version")) p.error("/version", "required format version is missing");
    else if (version < 1 || version > model_format_version)
        p.error("/version", "this program reads versions 1 to " + std::to_string(model_format_version) +
                                ", the file is version " + std::to_string(version));
    // Construction stages and bolts came with version 2.
    if (version == 1)
        for (const char* key : {"stages", "bolts"})
            if (root.contains(key))
                p.error(std::string("/") + key, std::string(key) + " need format version 2 (\"version\": 2)");

    Model m;
    m.name = p.string(root, "", "name", std::string());
    m.description = p.string(root, "", "description", std::string());

    parse_materials(p, root, m);
    const auto material_names = collect_names(p, p.array(root, "", "materials"), "/materials");
    auto joint_material_names = collect_names(p, p.array(root, "", "joint_materials"), "/joint_materials");
    parse_joint_materials(p, root, m, joint_material_names);
    parse_tables(p, root, m);
    const auto table_names = collect_names(p, p.array(root, "", "load_tables"), "/load_tables");
    parse_geometry(p, root, m, material_names, joint_material_names);
    parse_supports_and_loads(p, root, m, table_names);
    parse_mesh(p, root, m);
    parse_analysis(p, root, m);
    if (root.contains("water")) m.water = parse_water(p, root.at("water"), "/water");
    parse_bolts(p, root, m);
    parse_stages(p, root, m, material_names, table_names);
    parse_earthquake(p, root, m);
    if (!has_errors(result.diagnostics))
        load_ground_motion_files(m, std::filesystem::path(source).parent_path().string(), result.diagnostics);

    if (has_errors(result.diagnostics)) return result;
    result.model = std::move(m);
    return result;
}

ReadResult read_model_file(const std::string& path, const std::vector<std::string>& overrides) {
    // A directory or a device is refused before reading (/dev/zero never ends); a named pipe
    // (a shell's process substitution) is read like a file.
    const std::string kind = not_a_regular_file(path);
    if (!kind.empty() && kind != "does not exist" && !is_named_pipe(path)) {
        ReadResult r;
        r.diagnostics.push_back({Diagnostic::Severity::Error, "", path + " " + kind + ", not a model file"});
        return r;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        ReadResult r;
        r.diagnostics.push_back({Diagnostic::Severity::Error, "", path + ": cannot open the file"});
        return r;
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return read_model_text(buffer.str(), overrides, path);
}

}  // namespace mcdda
