// Setting up a construction stage (Model.hpp, Stage): what is present, the stage's view of the
// model, its elements, supports and bolts, and the out-of-balance force its changes leave,
// which it releases over its steps.

#include "run/Simulation.hpp"

#include "material/StrengthReduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdda {

namespace {

/// Whether a support, load or bolt is present at stage `s`: an item some stage installs is
/// absent before it, one a stage removes is absent from then on.
bool item_present(const Model& model, const std::string& name, int s) {
    bool present = true;
    for (const Stage& st : model.stages)
        if (std::find(st.install.begin(), st.install.end(), name) != st.install.end()) present = false;
    for (int t = 0; t <= s; ++t) {
        const Stage& st = model.stages[t];
        if (std::find(st.install.begin(), st.install.end(), name) != st.install.end()) present = true;
        if (std::find(st.remove.begin(), st.remove.end(), name) != st.remove.end()) present = false;
    }
    return present;
}

}  // namespace

void Simulation::begin_stage(int s) {
    const Stage& stage = base_model_.stages[s];
    stage_ = s;
    stage_start_step_ = state_.step;
    state_.stage = s;
    StageRecord& record = stages_[s];
    record.started = true;
    record.first_step = record.last_step = state_.step;
    if (s > 0) pending_events_.push_back("stage " + std::to_string(s + 1) + " \"" + stage.name + "\" begins at step " +
                                         std::to_string(state_.step));
    const StageRegions regions = stage_regions(s);
    set_stage_model(s, regions.material);
    activate_stage_elements(regions);
    locate_stage_supports(stage);
    drop_absent(state_.contacts);
    set_stage_bolts(s);
    // The new numbering needs a new pattern and factor.
    pattern_stale_ = true;
    held_ = HeldFactor{};
    // What the stage's changes leave out of balance is held, then released over its steps.
    holding_.resize(0);
    holding_ = -out_of_balance().residual;
    set_stage_dashpots();
}

Simulation::StageRegions Simulation::stage_regions(int s) const {
    // Regions present and their materials: those some stage activates are absent before it.
    const std::size_t regions = base_model_.regions.size();
    StageRegions out{std::vector<char>(regions, 1), std::vector<int>(regions)};
    for (std::size_t r = 0; r < regions; ++r) out.material[r] = base_model_.regions[r].material;
    for (const Stage& st : base_model_.stages)
        for (int r : st.activate) out.present[r] = 0;
    for (int t = 0; t <= s; ++t) {
        const Stage& st = base_model_.stages[t];
        for (int r : st.excavate) out.present[r] = 0;
        for (int r : st.activate) out.present[r] = 1;
        for (const auto& [r, m] : st.materials) out.material[r] = m;
    }
    return out;
}

void Simulation::set_stage_model(int s, const std::vector<int>& material) {
    // The stage's view of the model: its settings and materials; absent supports and loads
    // cleared in place, so that indices (history columns, reactions) stay those of the file.
    const Stage& stage = base_model_.stages[s];
    model_ = base_model_;
    model_.analysis = stage.analysis;
    model_.water = water_of_stage(base_model_, s);
    model_.seismic_coefficient = seismic_of_stage(base_model_, s);
    if (stage.analysis.strength_reduction) {
        // A safety stage: reduced strengths, solved as a small-strain equilibrium problem.
        reduce_strength(model_, strength_factor_);
        model_.analysis.geometry = AnalysisSettings::Geometry::Initial;
    }
    if (stage.reset_displacements || stage.analysis.strength_reduction) state_.displacement_reference = state_.displacement;
    for (std::size_t r = 0; r < material.size(); ++r) model_.regions[r].material = material[r];
    model_.fixed_points.clear();
    for (const FixedPoint& f : base_model_.fixed_points)
        if (item_present(base_model_, f.name, s)) model_.fixed_points.push_back(f);
    for (Roller& r : model_.rollers)
        if (!item_present(base_model_, r.name, s)) r.fix_x = r.fix_y = false;
    for (PointLoad& l : model_.point_loads)
        if (!item_present(base_model_, l.name, s)) l.force = {0.0, 0.0};
    for (EdgePressure& l : model_.edge_pressures)
        if (!item_present(base_model_, l.name, s)) l.pressure = 0.0;
}

void Simulation::activate_stage_elements(const StageRegions& regions) {
    const int blocks = mesh_.block_count();
    const std::vector<char> was_active = element_active_;
    block_active_.assign(blocks, 1);
    for (int b = 0; b < blocks; ++b) block_active_[b] = regions.present[block_region_[b]];
    const std::size_t elements = mesh_.triangles.size();
    element_active_.assign(elements, 1);
    const int per_element = elements_.points_per_element();
    for (std::size_t e = 0; e < elements; ++e) {
        mesh_.triangle_material[e] = regions.material[block_region_[mesh_.triangle_block[e]]];
        element_active_[e] = block_active_[mesh_.triangle_block[e]];
        // Material built in this stage (backfill, a liner) starts free of stress.
        if (element_active_[e] && !was_active.empty() && !was_active[e])
            for (int q = 0; q < per_element; ++q) {
                const std::size_t p = e * per_element + q;
                state_.points.stress[p].setZero();
                state_.points.stress_zz[p] = 0.0;
                state_.points.plastic_strain[p] = 0.0;
                state_.points.plastic_state[p] = 0;
            }
    }
    element_averages(state_.points, per_element, state_);
    elements_ = ElementAssembly(model_, mesh_);
    elements_.set_active(element_active_);
    std::vector<int> in_use;
    for (std::size_t r = 0; r < regions.present.size(); ++r)
        if (regions.present[r]) in_use.push_back(regions.material[r]);
    set_material_scales(in_use);
    state_.time_step = model_.analysis.time_step;
}

void Simulation::locate_stage_supports(const Stage& stage) {
    // Supports on the stage's blocks; the nodes of absent blocks are held where they are.
    std::vector<Diagnostic> diagnostics;
    bc_ = locate_boundary_conditions(model_, mesh_, topology_, diagnostics);
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error)
            throw std::runtime_error("stage \"" + stage.name + "\": " + (d.path.empty() ? "" : d.path + ": ") + d.message);
    const std::size_t n = mesh_.nodes.size();
    auto node_active = [&](int node) { return block_active_[mesh_.node_block[node]] != 0; };
    bc_.equation_count = 0;
    for (std::size_t dof = 0; dof < 2 * n; ++dof) {
        const bool free = bc_.equation[dof] >= 0 && node_active(static_cast<int>(dof / 2));
        bc_.equation[dof] = free ? bc_.equation_count++ : -1;
    }
    for (auto& nodes : bc_.roller_nodes)
        nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](int node) { return !node_active(node); }), nodes.end());
    bc_.pressure_edges.erase(std::remove_if(bc_.pressure_edges.begin(), bc_.pressure_edges.end(),
                                            [&](const BoundaryConditions::PressureEdge& p) {
                                                return !block_active_[topology_.edges[p.edge].block];
                                            }),
                             bc_.pressure_edges.end());
    // A measurement point on removed material follows the nearest node still present.
    for (std::size_t i = 0; i < bc_.measurement_nodes.size(); ++i) {
        int& node = bc_.measurement_nodes[i];
        if (node < 0 || node_active(node)) continue;
        const Point2 p = model_.measurement_points[i].point;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < n; ++k)
            if (node_active(static_cast<int>(k))) {
                const double dist = std::hypot(mesh_.nodes[k].x - p.x, mesh_.nodes[k].y - p.y);
                if (dist < best) {
                    best = dist;
                    node = static_cast<int>(k);
                }
            }
    }
    state_.roller_reactions.assign(model_.rollers.size(), Point2{0.0, 0.0});
}

void Simulation::set_stage_bolts(int s) {
    // Installed bolts start with their pretension, removed ones carry nothing.
    for (std::size_t i = 0; i < base_model_.bolts.size(); ++i) {
        const bool present = item_present(base_model_, base_model_.bolts[i].name, s);
        if (present && !bolt_present_[i]) state_.bolt_force[i] = base_model_.bolts[i].pretension;
        if (!present) state_.bolt_force[i] = 0.0;
        bolt_present_[i] = present;
    }
    if (s == 0)
        for (std::size_t i = 0; i < base_model_.bolts.size(); ++i)
            if (bolt_present_[i]) state_.bolt_force[i] = base_model_.bolts[i].pretension;
}

void Simulation::drop_absent(std::vector<Contact>& contacts) const {
    if (block_active_.empty()) return;
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const Contact& c) {
                                      return !block_active_[mesh_.node_block[c.node]] || !block_active_[c.edge_block];
                                  }),
                   contacts.end());
}

Eigen::VectorXd Simulation::applied_forces(double position, double time) const {
    Eigen::VectorXd f = external_forces(model_, mesh_, element_nodes(), topology_, bc_, position, time, element_active_);
    if (holding_.size() == f.size()) {
        const double released = base_model_.stages[stage_].released(position - stage_start_step_, base_model_.load_tables);
        if (released < 1.0) f += (1.0 - released) * holding_;
        if (!held_for_good_.empty() && released > 0.0)
            for (Eigen::Index dof = 0; dof < f.size(); ++dof)
                if (held_for_good_[dof]) f[dof] += released * holding_[dof];
    }
    add_base_loads(time, f);
    return f;
}

}  // namespace mcdda
