#include "model/Model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace mcdda {

const char* non_associated_flow_name(AnalysisSettings::NonAssociatedFlow f) {
    return f == AnalysisSettings::NonAssociatedFlow::Davis ? "davis" : "direct";
}

const char* analysis_type_name(const AnalysisSettings& a) {
    if (a.strength_reduction) return "strength_reduction";
    return a.kind == AnalysisSettings::Kind::Dynamic ? "dynamic" : "static";
}

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

double Water::level(double x) const {
    const std::vector<Point2>& line = piezometric_line;
    if (line.empty()) return -std::numeric_limits<double>::infinity();
    if (x <= line.front().x) return line.front().y;
    if (x >= line.back().x) return line.back().y;
    // The first vertex beyond x (the model checker refuses lines whose x does not increase).
    const auto after = std::upper_bound(line.begin(), line.end(), x, [](double v, const Point2& q) { return v < q.x; });
    const Point2 a = *(after - 1), b = *after;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

double Water::pore_pressure(Point2 p) const {
    if (!present()) return 0.0;
    return unit_weight * std::max(0.0, level(p.x) - p.y);
}

const Water& water_of_stage(const Model& model, int stage) {
    for (int k = std::min(stage, static_cast<int>(model.stages.size()) - 1); k >= 0; --k)
        if (model.stages[static_cast<std::size_t>(k)].water) return *model.stages[static_cast<std::size_t>(k)].water;
    return model.water;
}

double shear_wave_speed(const Material& m) {
    const double shear_modulus = m.young_modulus / (2.0 * (1.0 + m.poisson_ratio));
    return m.density > 0.0 && shear_modulus > 0.0 ? std::sqrt(shear_modulus / m.density) : 0.0;
}

double pressure_wave_speed(const Material& m) {
    const double nu = m.poisson_ratio;
    const double constrained = m.young_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    return m.density > 0.0 && constrained > 0.0 ? std::sqrt(constrained / m.density) : 0.0;
}

bool stage_is_dynamic(const Model& model, int stage) {
    const AnalysisSettings& a = model.stages.empty() ? model.analysis : model.stages[static_cast<std::size_t>(stage)].analysis;
    return a.kind == AnalysisSettings::Kind::Dynamic;
}

bool has_dynamic_stage(const Model& model) {
    if (model.stages.empty()) return stage_is_dynamic(model, 0);
    for (std::size_t s = 0; s < model.stages.size(); ++s)
        if (stage_is_dynamic(model, static_cast<int>(s))) return true;
    return false;
}

const SeismicCoefficient& seismic_of_stage(const Model& model, int stage) {
    for (int k = std::min(stage, static_cast<int>(model.stages.size()) - 1); k >= 0; --k)
        if (model.stages[static_cast<std::size_t>(k)].seismic_coefficient)
            return *model.stages[static_cast<std::size_t>(k)].seismic_coefficient;
    return model.seismic_coefficient;
}

bool has_water(const Model& model) {
    if (model.water.present()) return true;
    for (const Stage& st : model.stages)
        if (st.water && st.water->present()) return true;
    return false;
}

double LoadTable::factor(double s) const {
    if (points.empty()) return 1.0;
    if (s <= points.front()[0]) return points.front()[1];
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (s <= points[i][0]) {
            const auto& a = points[i - 1];
            const auto& b = points[i];
            return a[1] + (b[1] - a[1]) * (s - a[0]) / (b[0] - a[0]);
        }
    }
    if (!extrapolate || points.size() < 2) return points.back()[1];
    // Linear extrapolation from the last two points: a ramp keeps growing.
    const auto& a = points[points.size() - 2];
    const auto& b = points.back();
    return b[1] + (b[1] - a[1]) * (s - b[0]) / (b[0] - a[0]);
}

std::array<double, 4> Model::bounds() const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<double, 4> box{inf, inf, -inf, -inf};
    for (const Region& r : regions) {
        for (const Point2& p : r.boundary) {
            box[0] = std::min(box[0], p.x);
            box[1] = std::min(box[1], p.y);
            box[2] = std::max(box[2], p.x);
            box[3] = std::max(box[3], p.y);
        }
    }
    if (box[0] > box[2]) box = {0.0, 0.0, 0.0, 0.0};
    return box;
}

std::string joint_path(const Model& model, int joint) {
    if (joint < 0 || joint >= static_cast<int>(model.joints.size())) return "";
    const Joint& j = model.joints[joint];
    if (j.joint_set >= 0) return "/joint_sets/" + std::to_string(j.joint_set);
    return "/joints/" + std::to_string(joint);
}

double Material::parameter(const std::string& key, double fallback) const {
    const auto it = parameters.find(key);
    return it == parameters.end() ? fallback : it->second;
}

ElementType Model::element() const {
    if (mesh.element != ElementType::Automatic) return mesh.element;
    const bool may_yield = analysis.plasticity && std::any_of(materials.begin(), materials.end(),
                                                              [](const Material& m) { return m.may_yield(); });
    return may_yield ? ElementType::T6 : ElementType::T3;
}

double Stage::released(double s, const std::vector<LoadTable>& tables) const {
    if (release_table >= 0) return std::clamp(tables[release_table].factor(s), 0.0, 1.0);
    const int over = release_steps > 0 ? release_steps : analysis.steps;
    return over <= 0 ? 1.0 : std::clamp(s / over, 0.0, 1.0);
}

std::vector<int> regions_absent(const Model& model, int stage)
{
    std::vector<char> present(model.regions.size(), 1);
    auto mark = [&](const std::vector<int>& regions, char value) {
        for (int r : regions)
            if (r >= 0 && r < static_cast<int>(present.size())) present[static_cast<std::size_t>(r)] = value;
    };
    for (const Stage& st : model.stages) mark(st.activate, 0);  // built later: absent at first
    for (int k = 0; k <= stage && k < static_cast<int>(model.stages.size()); ++k) {
        mark(model.stages[static_cast<std::size_t>(k)].excavate, 0);
        mark(model.stages[static_cast<std::size_t>(k)].activate, 1);
    }
    std::vector<int> absent;
    for (std::size_t r = 0; r < present.size(); ++r)
        if (!present[r]) absent.push_back(static_cast<int>(r));
    return absent;
}

std::vector<std::string> items_absent(const Model& model, int stage)
{
    std::map<std::string, bool> present;
    for (const Stage& st : model.stages)
        for (const std::string& name : st.install) present[name] = false;  // installed later: absent at first
    for (int k = 0; k <= stage && k < static_cast<int>(model.stages.size()); ++k) {
        for (const std::string& name : model.stages[static_cast<std::size_t>(k)].remove) present[name] = false;
        for (const std::string& name : model.stages[static_cast<std::size_t>(k)].install) present[name] = true;
    }
    std::vector<std::string> absent;
    for (const auto& [name, here] : present)
        if (!here) absent.push_back(name);
    return absent;
}

}  // namespace mcdda
