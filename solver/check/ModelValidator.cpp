#include "check/ModelValidator.hpp"

#include "geometry/PolygonChecks.hpp"
#include "material/MaterialLaws.hpp"
#include "model/Defaults.hpp"
#include "model/ModelFields.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

namespace mcdda {

namespace {

constexpr double max_coordinate = 1e7;  // m; beyond this the model is surely in the wrong units

std::string num(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}
std::string deg(double radians) { return num(radians * 180.0 / pi) + "°"; }

class Checker {
public:
    explicit Checker(std::vector<Diagnostic>& d) : d_(d) {}
    void error(const std::string& path, const std::string& message) {
        d_.push_back({Diagnostic::Severity::Error, path, message});
    }
    void warning(const std::string& path, const std::string& message) {
        d_.push_back({Diagnostic::Severity::Warning, path, message});
    }
    void point(const Point2& p, const std::string& path) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::fabs(p.x) > max_coordinate ||
            std::fabs(p.y) > max_coordinate)
            error(path, "coordinates (" + num(p.x) + ", " + num(p.y) + ") are beyond ±1e7 m");
    }

    /// An error when |value| exceeds `limit` (finite values only; others are checked elsewhere).
    void at_most(double value, double limit, const std::string& path, const std::string& what, const std::string& unit) {
        if (std::isfinite(value) && std::fabs(value) > limit)
            error(path, what + " of " + num(value) + " " + unit + " is beyond any physical value (at most " + num(limit) +
                            " " + unit + "): check the units");
    }

private:
    std::vector<Diagnostic>& d_;
};

/// The declared ranges and physical limits of `record`'s number fields (ModelFields.hpp).
template <class Record>
void check_fields(Checker& c, const Record& record, const std::vector<RecordField<Record>>& fields,
                  const std::string& path) {
    for (const RecordField<Record>& f : fields) {
        const double value = record.*f.member;
        const std::string where = path + "/" + f.field.key;
        if (std::string why = range_error(f.field, value); !why.empty()) c.error(where, why);
        else if (std::string why = limit_error(f.field, value); !why.empty()) c.error(where, why);
    }
}

/// A law's own fields: present (or defaulted), in range, within physical limits; then the
/// checks the law makes across its fields.
void check_law(Checker& c, const Material& mat, const MaterialLaw& law, bool plasticity, const std::string& path) {
    for (const NumberField& f : law.fields) {
        const double value = law_value(mat, f);
        const std::string where = path + "/" + f.key;
        if (std::isnan(value) && !mat.parameters.count(f.key))
            c.error(where, std::string(f.name) + " is required by the " + law.label + " law");
        else if (std::string why = range_error(f, value); !why.empty()) c.error(where, why);
        else if (std::string why = limit_error(f, value); !why.empty()) c.error(where, why);
    }
    if (!law.check) return;
    std::vector<LawProblem> problems;
    law.check(mat, plasticity, problems);
    for (const LawProblem& p : problems) c.error(p.field.empty() ? path : path + "/" + p.field, p.message);
}

/// A contact spring at most this many times the stiffest Young's modulus of the model.
constexpr double max_contact_stiffness_ratio = 1000.0;

/// Contact springs (a joint material's kn and ks, the analysis penalty) far stiffer than the
/// rock: the automatic penalty, four times the stiffest modulus, already holds the faces together
/// against the blocks' own deformation, and a spring a million times stiffer only ruins the
/// equations' conditioning (a joint shear stiffness of 1.8e19 N/m on the jointed tunnel,
/// E = 20 GPa: 230 s of CPU for one step, which ended far from equilibrium).
void check_contact_stiffness(Checker& c, const Model& m) {
    double stiffest = 0.0;
    for (const Material& mat : m.materials)
        if (std::isfinite(mat.young_modulus)) stiffest = std::max(stiffest, mat.young_modulus);
    if (!(stiffest > 0.0)) return;
    const double limit = max_contact_stiffness_ratio * stiffest;
    const auto at_most = [&](double value, const std::string& path, const std::string& what) {
        if (std::isfinite(value) && value > limit)
            c.error(path, what + " of " + num(value) + " N/m is more than " + num(max_contact_stiffness_ratio) +
                              " times the stiffest material's Young's modulus (" + num(stiffest) +
                              " Pa): use at most " + num(limit) + " N/m, or 0 (automatic: " + num(4.0 * stiffest) +
                              " N/m); a contact that stiff holds nothing more and leaves the equations unsolvable in reasonable time");
    };
    for (std::size_t i = 0; i < m.joint_materials.size(); ++i) {
        const std::string path = "/joint_materials/" + std::to_string(i);
        at_most(m.joint_materials[i].normal_stiffness, path + "/normal_stiffness", "a normal stiffness");
        at_most(m.joint_materials[i].shear_stiffness, path + "/shear_stiffness", "a shear stiffness");
    }
    at_most(m.analysis.penalty, "/analysis/penalty", "a penalty");
    for (std::size_t i = 0; i < m.stages.size(); ++i)
        at_most(m.stages[i].analysis.penalty, "/stages/" + std::to_string(i) + "/analysis/penalty", "a penalty");
}

bool any_strength_reduction(const Model& m) {
    return m.analysis.strength_reduction ||
           std::any_of(m.stages.begin(), m.stages.end(), [](const Stage& s) { return s.analysis.strength_reduction; });
}

void check_materials(Checker& c, const Model& m) {
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
        const Material& mat = m.materials[i];
        const std::string path = "/materials/" + std::to_string(i);
        check_fields(c, mat, material_fields(), path);
        const MaterialLaw* law = find_material_law(mat.law);
        if (!law) {
            c.error(path + "/law", "unknown law \"" + mat.law + "\" (the laws are " + material_law_keys() + ")");
        } else {
            check_law(c, mat, *law, m.analysis.plasticity, path);
            if (mat.reduce && mat.may_yield() && !law->reduced && any_strength_reduction(m))
                c.error(path + "/reduce", std::string("a strength reduction cannot reduce a ") + law->label +
                                              " material; set \"reduce\": false to keep its strength");
        }
        if (m.analysis.kind == AnalysisSettings::Kind::Dynamic && !(mat.density > 0.0))
            c.error(path + "/density", "a dynamic analysis needs a positive density (or unit weight)");
    }
    for (std::size_t i = 0; i < m.joint_materials.size(); ++i)
        check_fields(c, m.joint_materials[i], joint_material_fields(), "/joint_materials/" + std::to_string(i));
    check_contact_stiffness(c, m);
}

/// A piezometric line that gives one level at each x, within reach of the model, and water
/// that weighs something.
void check_water(Checker& c, const Model& m, const Water& w, const std::string& path) {
    if (!(w.unit_weight > 0.0) || !std::isfinite(w.unit_weight))
        c.error(path + "/unit_weight", "the unit weight of water must be positive (got " + num(w.unit_weight) +
                                           " N/m³; fresh water 9810)");
    else
        c.at_most(w.unit_weight, 1e5, path + "/unit_weight", "a unit weight of water", "N/m³");
    const std::vector<Point2>& line = w.piezometric_line;
    if (line.size() == 1) c.error(path + "/piezometric_line", "needs at least two points (none: dry ground)");
    const auto box = m.bounds();
    const double size = std::hypot(box[2] - box[0], box[3] - box[1]);
    for (std::size_t i = 0; i < line.size(); ++i) {
        const std::string where = path + "/piezometric_line/" + std::to_string(i);
        c.point(line[i], where);
        if (i > 0 && !(line[i].x > line[i - 1].x)) {
            c.error(where, "the line must run left to right so that it gives one water level at each x: point " +
                               std::to_string(i + 1) + " (" + num(line[i].x) + ", " + num(line[i].y) + ") is " +
                               (line[i].x == line[i - 1].x ? "straight above or below" : "left of") + " point " +
                               std::to_string(i) + " (" + num(line[i - 1].x) + ", " + num(line[i - 1].y) + ")");
            break;
        }
        // Far outside the model is a typo or a unit slip (mm for m): the line is held level beyond its ends anyway.
        if (!m.regions.empty() && size > 0.0) {
            const double dx = std::max({box[0] - line[i].x, line[i].x - box[2], 0.0});
            const double dy = std::max({box[1] - line[i].y, line[i].y - box[3], 0.0});
            if (std::hypot(dx, dy) > size)
                c.error(where, "point (" + num(line[i].x) + ", " + num(line[i].y) +
                                   ") lies far outside the model (x " + num(box[0]) + " to " + num(box[2]) + ", y " +
                                   num(box[1]) + " to " + num(box[3]) + " m): a typing or unit slip?");
        }
    }
}

void check_water(Checker& c, const Model& m) {
    check_water(c, m, m.water, "/water");
    for (std::size_t s = 0; s < m.stages.size(); ++s)
        if (m.stages[s].water) check_water(c, m, *m.stages[s].water, "/stages/" + std::to_string(s) + "/water");
    if (!has_water(m)) return;
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
        const Material& mat = m.materials[i];
        if (mat.saturated_density > 0.0 && mat.saturated_density < mat.density)
            c.warning("/materials/" + std::to_string(i) + "/saturated_density",
                      "\"" + mat.name + "\" is lighter saturated than dry (" + num(mat.saturated_density * standard_gravity) +
                          " < " + num(mat.density * standard_gravity) + " N/m³)");
    }
    if (m.gravity.x == 0.0 && m.gravity.y == 0.0)
        c.warning("/water", "the model has ground water but no gravity: the pore pressures act, the ground weighs nothing");
}

/// Length of the overlap of two segments lying on one line (0 when they do not share a line).
double collinear_overlap(Point2 a, Point2 b, Point2 c, Point2 d, double tolerance) {
    const double lx = b.x - a.x, ly = b.y - a.y, length = std::hypot(lx, ly);
    if (!(length > 0.0)) return 0.0;
    const double ux = lx / length, uy = ly / length;
    auto off = [&](Point2 p) { return std::fabs((p.x - a.x) * uy - (p.y - a.y) * ux); };
    if (off(c) > tolerance || off(d) > tolerance) return 0.0;
    auto along = [&](Point2 p) { return (p.x - a.x) * ux + (p.y - a.y) * uy; };
    const double lo = std::max(0.0, std::min(along(c), along(d))), hi = std::min(length, std::max(along(c), along(d)));
    return std::max(0.0, hi - lo);
}

/// Median spacing of a record's times (s).
double sampling_interval(const GroundMotion& g) {
    std::vector<double> dt;
    for (std::size_t k = 1; k < g.points.size(); ++k) dt.push_back(g.points[k][0] - g.points[k - 1][0]);
    if (dt.empty()) return 0.0;
    std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
    return dt[dt.size() / 2];
}

/// Records, the base they shake, dashpots and pseudo-static loads (docs/model-format.md, "Earthquakes").
void check_earthquake(Checker& c, const Model& m) {
    for (std::size_t i = 0; i < m.ground_motions.size(); ++i) {
        const GroundMotion& g = m.ground_motions[i];
        const std::string path = "/ground_motions/" + std::to_string(i);
        if (g.name.empty()) c.error(path + "/name", "a ground motion needs a name");
        const std::string where = g.file.empty() ? path + "/points" : path + "/file";
        if (g.points.size() < 2)
            c.error(where, "an acceleration record needs at least two points (time, acceleration)");
        for (std::size_t k = 0; k < g.points.size(); ++k) {
            if (!std::isfinite(g.points[k][0]) || !std::isfinite(g.points[k][1])) {
                c.error(where, "point " + std::to_string(k + 1) + " is not a finite number");
                break;
            }
            if (k > 0 && !(g.points[k][0] > g.points[k - 1][0])) {
                c.error(g.file.empty() ? where + "/" + std::to_string(k) : where,
                        "times must increase: " + num(g.points[k][0]) + " s follows " + num(g.points[k - 1][0]) + " s");
                break;
            }
        }
        if (!std::isfinite(g.scale) || g.scale == 0.0) c.error(path + "/scale", "the scale must be a finite number other than 0");
        double peak = 0.0;
        for (const auto& q : g.points) peak = std::max(peak, std::fabs(q[1]));
        const double peak_g = peak * std::fabs(g.scale) / (g.units == GroundMotion::Units::G ? 1.0 : standard_gravity);
        if (std::isfinite(peak_g) && peak_g > 10.0)
            c.error(where, "the peak acceleration is " + num(peak_g) + " g: beyond any earthquake (check \"units\": " +
                               (g.units == GroundMotion::Units::G ? "the record is read in g" : "the record is read in m/s²") + ")");
    }
    const BaseMotion& b = m.base_motion;
    if (b.present()) {
        // What an editor can produce and the file cannot say: a base shaken by nothing, a record that is not there.
        const int records = static_cast<int>(m.ground_motions.size());
        if (b.x < 0 && b.y < 0)
            c.error("/base_motion", "name the ground motion of \"x\" (horizontal), \"y\" (vertical) or both");
        for (const auto& [index, key] : {std::pair{b.x, "/base_motion/x"}, std::pair{b.y, "/base_motion/y"}})
            if (index >= records) c.error(key, "names no ground motion of the model (" + std::to_string(records) + " given)");
        if (!has_dynamic_stage(m))
            c.warning("/base_motion", "the base motion shakes only dynamic stages and this model has none (\"analysis\": {\"type\": \"dynamic\"})");
        if (b.kind == BaseMotion::Kind::Rigid && m.fixed_points.empty() && m.rollers.empty())
            c.error("/base_motion", "a rigid base moves the supports, and nothing is fixed: add rollers or fixed points along the base");
        if (b.kind == BaseMotion::Kind::Compliant) {
            c.point(b.from, "/base_motion/from");
            c.point(b.to, "/base_motion/to");
            if (std::hypot(b.to.x - b.from.x, b.to.y - b.from.y) == 0.0)
                c.error("/base_motion", "the compliant base runs from a point to itself");
            // The dashpots carry no static load: the weight must stand on supports in a stage before.
            const bool gravity = m.gravity.x != 0.0 || m.gravity.y != 0.0;
            if (gravity && stage_is_dynamic(m, 0))
                c.error("/base_motion", "a compliant base cannot carry the model's weight from the start: let a first, static "
                                        "stage stand on supports along the base and remove them in the dynamic stage (their "
                                        "forces then act on the base; docs/model-format.md, \"Earthquakes\")");
        }
        // The record must be sampled finely enough by the time step.
        for (int r : {b.x, b.y}) {
            if (r < 0 || r >= static_cast<int>(m.ground_motions.size())) continue;
            const GroundMotion& g = m.ground_motions[r];
            const double interval = sampling_interval(g);
            const int stages = std::max<int>(1, static_cast<int>(m.stages.size()));
            for (int s = 0; s < stages; ++s) {
                if (!stage_is_dynamic(m, s)) continue;
                const AnalysisSettings& a = m.stages.empty() ? m.analysis : m.stages[s].analysis;
                const std::string where = m.stages.empty() ? "/analysis/time_step" : "/stages/" + std::to_string(s) + "/analysis/time_step";
                if (interval > 0.0 && a.time_step > 1.01 * interval)
                    c.error(where, "the time step " + num(a.time_step) + " s is " + num(a.time_step / interval) +
                                       " times the sampling interval of \"" + g.name + "\" (" + num(interval) +
                                       " s): its shaking between samples would be skipped; use at most " + num(interval) + " s");
            }
        }
    }
    // Dashpots: on boundaries without supports, and with a time step the waves can be followed at.
    std::vector<std::pair<std::string, std::array<Point2, 2>>> dashpots;
    for (std::size_t i = 0; i < m.absorbing_boundaries.size(); ++i) {
        const AbsorbingBoundary& a = m.absorbing_boundaries[i];
        const std::string path = "/absorbing_boundaries/" + std::to_string(i);
        c.point(a.from, path + "/from");
        c.point(a.to, path + "/to");
        if (std::hypot(a.to.x - a.from.x, a.to.y - a.from.y) == 0.0) c.error(path, "the boundary runs from a point to itself");
        dashpots.push_back({path, {a.from, a.to}});
    }
    if (b.kind == BaseMotion::Kind::Compliant) dashpots.push_back({"/base_motion", {b.from, b.to}});
    if (!dashpots.empty()) {
        const auto box = m.bounds();
        const double tolerance = 1e-6 * std::max(1.0, std::hypot(box[2] - box[0], box[3] - box[1]));
        const int stages = std::max<int>(1, static_cast<int>(m.stages.size()));
        for (int s = 0; s < stages; ++s) {
            if (!stage_is_dynamic(m, s)) continue;
            const std::vector<std::string> absent = m.stages.empty() ? std::vector<std::string>{} : items_absent(m, s);
            for (const Roller& r : m.rollers) {
                if (std::find(absent.begin(), absent.end(), r.name) != absent.end()) continue;
                for (const auto& [path, seg] : dashpots)
                    if (collinear_overlap(seg[0], seg[1], r.from, r.to, tolerance) > tolerance)
                        c.error(path, "dashpots on a boundary that also has a fixed support (roller \"" + r.name + "\"" +
                                          (m.stages.empty() ? std::string() : " in stage \"" + m.stages[s].name + "\"") +
                                          "): a support reflects the waves the dashpots should let out; remove it in the dynamic stage");
            }
            // A wave should not cross an element in one step.
            const AnalysisSettings& a = m.stages.empty() ? m.analysis : m.stages[s].analysis;
            double fastest = 0.0;
            for (const Material& mat : m.materials) fastest = std::max(fastest, shear_wave_speed(mat));
            const double size = m.mesh.size > 0.0 ? m.mesh.size : std::hypot(box[2] - box[0], box[3] - box[1]) / 20.0;
            if (fastest > 0.0 && size > 0.0 && a.time_step * fastest > size)
                c.error(m.stages.empty() ? "/analysis/time_step" : "/stages/" + std::to_string(s) + "/analysis/time_step",
                        "a shear wave (" + num(fastest) + " m/s) crosses " + num(a.time_step * fastest / size) +
                            " elements of " + num(size) + " m in one time step of " + num(a.time_step) +
                            " s: the waves the dashpots absorb are not followed; use at most " + num(size / fastest) + " s");
        }
    }
    auto check_seismic = [&](const SeismicCoefficient& k, const std::string& path) {
        if (!std::isfinite(k.kh) || std::fabs(k.kh) > 2.0) c.error(path + "/kh", "kh must lie between -2 and 2 (got " + num(k.kh) + ")");
        if (!std::isfinite(k.kv) || std::fabs(k.kv) > 2.0) c.error(path + "/kv", "kv must lie between -2 and 2 (got " + num(k.kv) + ")");
        if (k.present() && m.gravity.x == 0.0 && m.gravity.y == 0.0)
            c.warning(path, "a seismic coefficient is a fraction of gravity, and the model has none: no load");
    };
    check_seismic(m.seismic_coefficient, "/seismic_coefficient");
    for (std::size_t s = 0; s < m.stages.size(); ++s)
        if (m.stages[s].seismic_coefficient)
            check_seismic(*m.stages[s].seismic_coefficient, "/stages/" + std::to_string(s) + "/seismic_coefficient");
}

void check_geometry(Checker& c, const Model& m) {
    if (m.regions.empty()) c.error("/regions", "at least one region is required");
    for (std::size_t i = 0; i < m.regions.size(); ++i) {
        const Region& r = m.regions[i];
        const std::string path = "/regions/" + std::to_string(i);
        if (r.boundary.size() < 3)
            c.error(path + "/boundary", "a region boundary needs at least 3 vertices (got " + std::to_string(r.boundary.size()) + ")");
        if (!(r.mesh_size >= 0.0 && std::isfinite(r.mesh_size)))
            c.error(path + "/mesh_size", "the region's mesh size must be positive (got " + num(r.mesh_size) +
                                             " m; 0 or none: the model's size field)");
        for (std::size_t k = 0; k < r.boundary.size(); ++k) c.point(r.boundary[k], path + "/boundary/" + std::to_string(k));
        for (std::size_t h = 0; h < r.holes.size(); ++h) {
            const std::string hpath = path + "/holes/" + std::to_string(h);
            if (r.holes[h].size() < 3)
                c.error(hpath, "a hole needs at least 3 vertices (got " + std::to_string(r.holes[h].size()) + ")");
            for (std::size_t k = 0; k < r.holes[h].size(); ++k) c.point(r.holes[h][k], hpath + "/" + std::to_string(k));
        }
    }
    for (std::size_t i = 0; i < m.joints.size(); ++i) {
        const Joint& j = m.joints[i];
        if (j.joint_set >= 0) continue;
        const std::string path = "/joints/" + std::to_string(i);
        if (j.points.size() < 2) c.error(path + "/points", "a joint needs at least 2 points");
        for (std::size_t k = 0; k < j.points.size(); ++k) {
            c.point(j.points[k], path + "/points/" + std::to_string(k));
            if (k > 0 && j.points[k].x == j.points[k - 1].x && j.points[k].y == j.points[k - 1].y)
                c.error(path + "/points/" + std::to_string(k), "repeats the previous point (zero-length joint segment)");
        }
    }
    // A copy of a region or joint adds nothing but work: the cutter's arrangement merges copies
    // pairwise (a thousand copies of one region: minutes), so they are refused by name.
    const auto key = [](const std::vector<Point2>& points) {
        std::string text(points.size() * 2 * sizeof(double), '\0');
        for (std::size_t k = 0; k < points.size(); ++k) {
            std::memcpy(&text[16 * k], &points[k].x, sizeof(double));
            std::memcpy(&text[16 * k + 8], &points[k].y, sizeof(double));
        }
        return text;
    };
    std::unordered_map<std::string, std::size_t> first_region, first_joint;
    for (std::size_t i = 0; i < m.regions.size(); ++i) {
        const auto [it, fresh] = first_region.emplace(key(m.regions[i].boundary), i);
        if (!fresh)
            c.error("/regions/" + std::to_string(i) + "/boundary",
                    "region \"" + m.regions[i].name + "\" has the boundary of region \"" + m.regions[it->second].name +
                        "\" (/regions/" + std::to_string(it->second) + "): leave the copy out");
    }
    for (std::size_t i = 0; i < m.joints.size(); ++i) {
        if (m.joints[i].joint_set >= 0) continue;
        const auto [it, fresh] = first_joint.emplace(key(m.joints[i].points), i);
        if (!fresh)
            c.error("/joints/" + std::to_string(i) + "/points",
                    "joint \"" + m.joints[i].name + "\" has the points of joint \"" + m.joints[it->second].name +
                        "\" (/joints/" + std::to_string(it->second) + "): leave the copy out");
    }
    const auto model_box = m.bounds();
    for (std::size_t i = 0; i < m.joint_sets.size(); ++i) {
        const JointSet& s = m.joint_sets[i];
        const std::string path = "/joint_sets/" + std::to_string(i);
        c.point(s.origin, path + "/origin");
        // The box the set is generated in (as in expand_joint_sets) bounds what it can generate.
        const auto box = s.extent.value_or(model_box);
        const double diagonal = std::hypot(box[2] - box[0], box[3] - box[1]);
        const bool spacing_ok = s.spacing > 0.0 && diagonal / s.spacing <= max_joint_set_traces;
        if (!(s.spacing > 0.0)) {
            c.error(path + "/spacing", "spacing must be positive (got " + num(s.spacing) + " m)");
        } else if (!spacing_ok) {
            c.error(path + "/spacing", "spacing " + num(s.spacing) + " m would generate more than " +
                                           std::to_string(max_joint_set_traces) + " joints");
        }
        if (s.extent && !((*s.extent)[2] > (*s.extent)[0] && (*s.extent)[3] > (*s.extent)[1]))
            c.error(path + "/extent", "extent must be [xmin, ymin, xmax, ymax] with xmax > xmin and ymax > ymin");

        const bool persistence_ok = s.persistence > 0.0 && s.persistence <= 1.0;
        if (!persistence_ok)
            c.error(path + "/persistence", "persistence must lie in (0, 1] (got " + num(s.persistence) + ")");
        if (!(s.stagger >= 0.0 && s.stagger < 1.0))
            c.error(path + "/stagger", "stagger must lie in [0, 1) (got " + num(s.stagger) + ")");
        if (!(s.trace_length >= 0.0)) {
            c.error(path + "/trace_length", "trace length must not be negative (got " + num(s.trace_length) + " m)");
        } else if (persistence_ok && s.persistence < 1.0) {
            if (!(s.trace_length > 0.0)) {
                c.error(path + "/trace_length", "a joint set with persistence below 1 needs a positive trace length");
            } else if (spacing_ok) {
                // Each trace crossing the box holds at most chord / period + 2 segments.
                const double period = s.trace_length / s.persistence;
                const double segments = (diagonal / s.spacing + 1.0) * (diagonal / period + 2.0);
                if (segments > static_cast<double>(max_joint_set_segments))
                    c.error(path + "/trace_length", "trace length " + num(s.trace_length) + " m with persistence " +
                                                        num(s.persistence) + " would generate more than " +
                                                        std::to_string(max_joint_set_segments) + " joint segments");
            }
        }
    }
}

void check_boundary_conditions(Checker& c, const Model& m) {
    for (std::size_t i = 0; i < m.fixed_points.size(); ++i)
        c.point(m.fixed_points[i].point, "/fixed_points/" + std::to_string(i) + "/point");
    for (std::size_t i = 0; i < m.rollers.size(); ++i) {
        const Roller& r = m.rollers[i];
        const std::string path = "/rollers/" + std::to_string(i);
        c.point(r.from, path + "/from");
        c.point(r.to, path + "/to");
        if (r.from.x == r.to.x && r.from.y == r.to.y) c.error(path, "from and to are the same point");
        c.point(r.displacement, path + "/displacement");
        if ((r.displacement.x != 0.0 && !r.fix_x) || (r.displacement.y != 0.0 && !r.fix_y))
            c.error(path + "/displacement", "prescribes a direction the roller does not fix (\"fixed\" must include it)");
    }
    for (std::size_t i = 0; i < m.point_loads.size(); ++i)
        c.point(m.point_loads[i].point, "/point_loads/" + std::to_string(i) + "/point");
    for (std::size_t i = 0; i < m.edge_pressures.size(); ++i) {
        const EdgePressure& e = m.edge_pressures[i];
        const std::string path = "/edge_pressures/" + std::to_string(i);
        if (e.from.x == e.to.x && e.from.y == e.to.y) c.error(path, "from and to are the same point");
        c.at_most(e.pressure, max_stress, path + "/pressure", "pressure", "Pa");
    }
    c.at_most(std::hypot(m.gravity.x, m.gravity.y), max_gravity, "/gravity", "gravity", "m/s²");
    if (m.initial_stress.kind == InitialStress::Kind::Uniform) {
        const char* keys[] = {"sxx", "syy", "sxy"};
        for (int k = 0; k < 3; ++k)
            c.at_most(m.initial_stress.stress[k], max_stress, std::string("/initial_stress/") + keys[k], "in-situ stress", "Pa");
        if (m.initial_stress.stress_zz) c.at_most(*m.initial_stress.stress_zz, max_stress, "/initial_stress/szz", "in-situ stress", "Pa");
    }
    if (m.initial_stress.kind == InitialStress::Kind::Gravity) {
        if (!(std::fabs(m.initial_stress.surface_y) <= max_coordinate))
            c.error("/initial_stress/surface_y", "surface_y " + num(m.initial_stress.surface_y) + " m is beyond ±1e7 m");
        // The vertical stress at the model's lowest point.
        double lowest = m.initial_stress.surface_y, heaviest = 0.0;
        for (const Region& r : m.regions)
            for (const Point2& p : r.boundary) lowest = std::min(lowest, p.y);
        for (const Material& mat : m.materials) heaviest = std::max(heaviest, mat.density);
        const double deepest = heaviest * std::hypot(m.gravity.x, m.gravity.y) * (m.initial_stress.surface_y - lowest);
        if (std::fabs(m.initial_stress.surface_y) <= max_coordinate)
            c.at_most(deepest, max_stress, "/initial_stress/surface_y", "the in-situ vertical stress at the model's base", "Pa");
    }
    for (std::size_t i = 0; i < m.load_tables.size(); ++i) {
        const LoadTable& t = m.load_tables[i];
        for (std::size_t k = 1; k < t.points.size(); ++k)
            if (!(t.points[k][0] > t.points[k - 1][0]))
                c.error("/load_tables/" + std::to_string(i) + "/points/" + std::to_string(k),
                        "abscissas must increase strictly (" + num(t.points[k][0]) + " follows " + num(t.points[k - 1][0]) + ")");
    }
    if (m.initial_stress.kind == InitialStress::Kind::Gravity) {
        if (!(m.initial_stress.k0 >= 0.0)) c.error("/initial_stress/k0", "K0 must not be negative");
        if (m.gravity.x == 0.0 && m.gravity.y == 0.0)
            c.warning("/initial_stress", "gravity-based in-situ stress with zero gravity gives no stress");
    }
    // Before anything is drawn only the missing region is worth saying.
    if (m.fixed_points.empty() && m.rollers.empty() && !m.regions.empty()) {
        if (m.analysis.kind == AnalysisSettings::Kind::Static)
            c.error("", "nothing is fixed: add fixed points or rollers (a static analysis of free blocks is a mechanism)");
        else
            c.warning("", "nothing is fixed: every block is free to move");
    }
    for (std::size_t i = 0; i < m.measurement_points.size(); ++i)
        c.point(m.measurement_points[i].point, "/measurement_points/" + std::to_string(i) + "/point");
}

void check_analysis(Checker& c, const AnalysisSettings& a, const std::string& path);

void check_controls(Checker& c, const Model& m) {
    const MeshControls& mesh = m.mesh;
    if (!(mesh.size >= 0.0)) c.error("/mesh/size", "mesh size must be positive (or 0 for automatic)");
    if (!(mesh.min_angle > 0.0 && mesh.min_angle <= 34.0 * pi / 180.0))
        c.error("/mesh/min_angle", "minimum angle must lie in (0°, 34°] for the refinement to end (got " + deg(mesh.min_angle) + ")");
    if (!(mesh.grading > 0.0)) c.error("/mesh/grading", "grading must be positive");
    if (!(mesh.max_elements > 0)) c.error("/mesh/max_elements", "must be positive");
    for (std::size_t i = 0; i < mesh.local.size(); ++i) {
        const std::string path = "/mesh/local/" + std::to_string(i);
        if (!(mesh.local[i].size > 0.0)) c.error(path + "/size", "local size must be positive");
        if (!(mesh.local[i].radius >= 0.0)) c.error(path + "/radius", "radius must not be negative");
    }
    check_analysis(c, m.analysis, "/analysis");
}

void check_bolts(Checker& c, const Model& m) {
    for (std::size_t i = 0; i < m.bolts.size(); ++i) {
        const Bolt& b = m.bolts[i];
        const std::string path = "/bolts/" + std::to_string(i);
        check_fields(c, b, bolt_fields(), path);
        if (b.name.empty()) c.error(path + "/name", "a bolt needs a name (stages install it by name)");
        for (std::size_t k = 0; k < i; ++k)
            if (!b.name.empty() && m.bolts[k].name == b.name) {
                c.error(path + "/name", "duplicate bolt name \"" + b.name + "\" (also bolt " + std::to_string(k + 1) + ")");
                break;
            }
        if (std::hypot(b.to.x - b.from.x, b.to.y - b.from.y) <= 0.0) c.error(path, "bolt \"" + b.name + "\" has no length");
        for (const char* end : {"from", "to"}) {
            const Point2 q = std::string(end) == "from" ? b.from : b.to;
            bool inside = false;
            for (const Region& r : m.regions) inside = inside || region_contains(r, q);
            if (!inside)
                c.error(path + "/" + end, "bolt \"" + b.name + "\" ends at (" + num(q.x) + ", " + num(q.y) +
                                              "), outside every region");
        }
    }
}

/// Stages: what each names exists, and is present or absent as its action needs.
/// Names that head columns of history.csv ("<point>:ux", "load:<name>", "<bolt>:force"): a
/// comma, quote or line break would split or break the column, and a leading =, +, - or @ makes
/// a spreadsheet take the header for a formula and run it (CSV injection).
void check_column_names(Checker& c, const Model& m) {
    const auto check = [&c](const std::string& name, const std::string& path, const char* what, bool leads = true) {
        if (name.find_first_of(",\"\n\r") != std::string::npos)
            c.error(path + "/name", std::string("the ") + what + " name \"" + name +
                                        "\" heads a column of history.csv: it may not hold a comma, a quote or a line break");
        else if (leads && !name.empty() && std::string("=+-@\t").find(name.front()) != std::string::npos)
            c.error(path + "/name", std::string("the ") + what + " name \"" + name +
                                        "\" heads a column of history.csv, where a spreadsheet would take it for a formula: "
                                        "it may not begin with =, +, - or @");
    };
    for (std::size_t i = 0; i < m.measurement_points.size(); ++i)
        check(m.measurement_points[i].name, "/measurement_points/" + std::to_string(i), "measurement point");
    for (std::size_t i = 0; i < m.rollers.size(); ++i)
        if (m.rollers[i].moves()) check(m.rollers[i].name, "/rollers/" + std::to_string(i), "moving support");
    for (std::size_t i = 0; i < m.point_loads.size(); ++i)
        check(m.point_loads[i].name, "/point_loads/" + std::to_string(i), "point load", false);  // after "load:"
    for (std::size_t i = 0; i < m.edge_pressures.size(); ++i)
        check(m.edge_pressures[i].name, "/edge_pressures/" + std::to_string(i), "edge pressure", false);
    for (std::size_t i = 0; i < m.bolts.size(); ++i) check(m.bolts[i].name, "/bolts/" + std::to_string(i), "bolt");
}

void check_stages(Checker& c, const Model& m) {
    std::vector<std::pair<std::string, std::string>> items;  // (name, kind)
    for (const FixedPoint& f : m.fixed_points) items.emplace_back(f.name, "fixed point");
    for (const Roller& r : m.rollers) items.emplace_back(r.name, "roller");
    for (const PointLoad& l : m.point_loads) items.emplace_back(l.name, "point load");
    for (const EdgePressure& l : m.edge_pressures) items.emplace_back(l.name, "edge pressure");
    for (const Bolt& b : m.bolts) items.emplace_back(b.name, "bolt");
    auto kinds_of = [&](const std::string& name) {
        std::vector<std::string> kinds;
        for (const auto& [n, kind] : items)
            if (n == name) kinds.push_back(kind);
        return kinds;
    };
    std::vector<char> region_present(m.regions.size(), 1);
    for (const Stage& st : m.stages)
        for (int r : st.activate) region_present[r] = 0;
    std::map<std::string, bool> item_present;
    for (const auto& [name, kind] : items) item_present[name] = true;
    for (const Stage& st : m.stages)
        for (const std::string& name : st.install) item_present[name] = false;
    for (std::size_t i = 0; i < m.stages.size(); ++i) {
        const Stage& st = m.stages[i];
        const std::string path = "/stages/" + std::to_string(i);
        check_analysis(c, st.analysis, path + "/analysis");
        // A safety stage starts from the stresses of the stages before it and ends the analysis.
        if (st.analysis.strength_reduction && i + 1 != m.stages.size())
            c.error(path + "/analysis/type", "a strength reduction stage (\"" + st.name +
                                                 "\") must be the last stage: it ends with the factor of safety, "
                                                 "not with a state later stages could start from");
        if (!(st.target_ratio >= 0.0)) c.error(path + "/target_ratio", "must not be negative (0 = run all steps)");
        for (std::size_t k = 0; k < st.excavate.size(); ++k) {
            const int r = st.excavate[k];
            if (!region_present[r])
                c.error(path + "/excavate/" + std::to_string(k), "region \"" + m.regions[r].name + "\" is not there to excavate in stage \"" + st.name + "\"");
            region_present[r] = 0;
        }
        for (std::size_t k = 0; k < st.activate.size(); ++k) {
            const int r = st.activate[k];
            if (region_present[r] && std::count(st.excavate.begin(), st.excavate.end(), r) == 0)
                c.error(path + "/activate/" + std::to_string(k), "region \"" + m.regions[r].name + "\" is already there in stage \"" + st.name + "\"");
            region_present[r] = 1;
        }
        if (std::none_of(region_present.begin(), region_present.end(), [](char p) { return p != 0; }))
            c.error(path, "stage \"" + st.name + "\" leaves no region in the model");
        for (const auto& [list, installing] : {std::pair{&st.install, true}, std::pair{&st.remove, false}})
            for (std::size_t k = 0; k < list->size(); ++k) {
                const std::string& name = (*list)[k];
                const std::string where = path + (installing ? "/install/" : "/remove/") + std::to_string(k);
                const auto kinds = kinds_of(name);
                if (kinds.empty()) {
                    c.error(where, "no support, load or bolt named \"" + name + "\"");
                    continue;
                }
                if (kinds.size() > 1) {
                    c.error(where, "\"" + name + "\" names both a " + kinds[0] + " and a " + kinds[1] + ": give them different names");
                    continue;
                }
                if (item_present[name] == installing)
                    c.error(where, kinds[0] + " \"" + name + "\" is " + (installing ? "already there" : "not there") +
                                       " in stage \"" + st.name + "\"");
                item_present[name] = installing;
            }
    }
}

void check_analysis(Checker& c, const AnalysisSettings& a, const std::string& at) {
    const std::string path = at;
    if (a.steps < 1) c.error(path + "/steps", "at least one step is needed");
    check_fields(c, a, analysis_fields(), path);
    if (a.max_open_close_iterations < 1) c.error(path + "/open_close_iterations", "must be at least 1");
    if (a.max_plastic_iterations < 1) c.error(path + "/plastic_iterations", "must be at least 1");
    if (a.output_every < 1) c.error(path + "/output_every", "must be at least 1");
    if (a.strength_reduction && a.max_trials < 3)
        c.error(path + "/max_trials", "a strength reduction search needs at least 3 trials (got " +
                                          std::to_string(a.max_trials) + ")");
}

}  // namespace

namespace {
void check_load_tables(Checker& c, const Model& m);  // defined at the end of the file
}  // namespace

void validate_model(const Model& model, std::vector<Diagnostic>& diagnostics) {
    Checker c(diagnostics);
    check_materials(c, model);
    check_geometry(c, model);
    check_boundary_conditions(c, model);
    check_load_tables(c, model);
    check_controls(c, model);
    check_bolts(c, model);
    check_column_names(c, model);
    check_stages(c, model);
    check_water(c, model);
    check_earthquake(c, model);
}

namespace {

// What the model reader already refuses in a file but an editor (the desktop program's Loads
// tab) can produce: a table without a name or points, two tables of one name (the file refers
// to tables by name), a load referring to a table that is not there.
void check_load_tables(Checker& c, const Model& m) {
    const auto& tables = m.load_tables;
    for (std::size_t i = 0; i < tables.size(); ++i) {
        const LoadTable& t = tables[i];
        const std::string path = "/load_tables/" + std::to_string(i);
        if (t.name.empty()) {
            c.error(path + "/name", "a load table needs a name");
        } else {
            // Reported at both tables, so the error concerns whichever one was just renamed.
            for (std::size_t k = 0; k < tables.size(); ++k)
                if (k != i && tables[k].name == t.name) {
                    c.error(path + "/name", "another load table is named \"" + t.name + "\"");
                    break;
                }
        }
        if (t.points.empty()) c.error(path + "/points", "a load table needs at least one [abscissa, factor] pair");
        for (std::size_t k = 0; k < t.points.size(); ++k)
            if (!std::isfinite(t.points[k][0]) || !std::isfinite(t.points[k][1]))
                c.error(path + "/points/" + std::to_string(k), "abscissa and factor must be finite numbers");
    }
    const auto reference = [&](int table, const std::string& path) {
        if (table < -1 || table >= static_cast<int>(tables.size()))
            c.error(path + "/table", "refers to a missing load table (index " + std::to_string(table) + ")");
    };
    for (std::size_t i = 0; i < m.rollers.size(); ++i) reference(m.rollers[i].table, "/rollers/" + std::to_string(i));
    for (std::size_t i = 0; i < m.point_loads.size(); ++i)
        reference(m.point_loads[i].table, "/point_loads/" + std::to_string(i));
    for (std::size_t i = 0; i < m.edge_pressures.size(); ++i)
        reference(m.edge_pressures[i].table, "/edge_pressures/" + std::to_string(i));
}

}  // namespace

}  // namespace mcdda
