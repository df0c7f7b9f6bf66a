#pragma once
// Field-by-field comparison of two Models for round-trip tests. Header only and free of any
// test framework, so the solver and the GUI document tests share it.

#include "model/Model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace mcdda::test {

/// Collects the differences between two models; doubles compare with a relative tolerance.
class ModelComparer {
public:
    explicit ModelComparer(double relative_tolerance = 1e-12) : tol_(relative_tolerance) {}

    /// An empty string when the models are equal, otherwise one line per difference.
    void water(const std::string& p, const Water& x, const Water& y) {
        points(p + "/piezometric_line", x.piezometric_line, y.piezometric_line);
        eq(p + "/unit_weight", x.unit_weight, y.unit_weight);
    }

    void seismic(const std::string& p, const SeismicCoefficient& x, const SeismicCoefficient& y) {
        eq(p + "/kh", x.kh, y.kh);
        eq(p + "/kv", x.kv, y.kv);
    }

    std::string compare(const Model& a, const Model& b) {
        out_.str({});
        eq("name", a.name, b.name);
        eq("description", a.description, b.description);
        list("/materials", a.materials, b.materials, [this](const std::string& p, const Material& x, const Material& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/young_modulus", x.young_modulus, y.young_modulus);
            eq(p + "/poisson_ratio", x.poisson_ratio, y.poisson_ratio);
            eq(p + "/density", x.density, y.density);
            eq(p + "/saturated_density", x.saturated_density, y.saturated_density);
            eq(p + "/law", x.law, y.law);
            eq(p + "/parameters", static_cast<long>(x.parameters.size()), static_cast<long>(y.parameters.size()));
            for (const auto& [key, value] : x.parameters) eq(p + "/" + key, value, y.parameter(key, -1.0));
            eq(p + "/reduce", x.reduce, y.reduce);
        });
        list("/joint_materials", a.joint_materials, b.joint_materials,
             [this](const std::string& p, const JointMaterial& x, const JointMaterial& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/friction_angle", x.friction_angle, y.friction_angle);
                 eq(p + "/cohesion", x.cohesion, y.cohesion);
                 eq(p + "/tensile_strength", x.tensile_strength, y.tensile_strength);
                 eq(p + "/normal_stiffness", x.normal_stiffness, y.normal_stiffness);
                 eq(p + "/shear_stiffness", x.shear_stiffness, y.shear_stiffness);
             });
        eq("/default_joint_material", a.default_joint_material, b.default_joint_material);
        list("/regions", a.regions, b.regions, [this](const std::string& p, const Region& x, const Region& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/material", x.material, y.material);
            points(p + "/boundary", x.boundary, y.boundary);
            list(p + "/holes", x.holes, y.holes,
                 [this](const std::string& q, const Ring& r, const Ring& s) { points(q, r, s); });
            eq(p + "/mesh_size", x.mesh_size, y.mesh_size);
        });
        list("/joints", a.joints, b.joints, [this](const std::string& p, const Joint& x, const Joint& y) {
            eq(p + "/name", x.name, y.name);
            points(p + "/points", x.points, y.points);
            eq(p + "/joint_material", x.joint_material, y.joint_material);
            eq(p + "/joint_set", x.joint_set, y.joint_set);
        });
        list("/joint_sets", a.joint_sets, b.joint_sets, [this](const std::string& p, const JointSet& x, const JointSet& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/angle", x.angle, y.angle);
            eq(p + "/spacing", x.spacing, y.spacing);
            eq(p + "/origin", x.origin, y.origin);
            eq(p + "/extent?", x.extent.has_value(), y.extent.has_value());
            if (x.extent && y.extent)
                for (int k = 0; k < 4; ++k) eq(p + "/extent/" + std::to_string(k), (*x.extent)[k], (*y.extent)[k]);
            eq(p + "/joint_material", x.joint_material, y.joint_material);
            eq(p + "/persistence", x.persistence, y.persistence);
            eq(p + "/trace_length", x.trace_length, y.trace_length);
            eq(p + "/stagger", x.stagger, y.stagger);
        });
        list("/load_tables", a.load_tables, b.load_tables, [this](const std::string& p, const LoadTable& x, const LoadTable& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/variable", static_cast<int>(x.variable), static_cast<int>(y.variable));
            list(p + "/points", x.points, y.points,
                 [this](const std::string& q, const std::array<double, 2>& r, const std::array<double, 2>& s) {
                     eq(q + "/0", r[0], s[0]);
                     eq(q + "/1", r[1], s[1]);
                 });
            eq(p + "/extrapolate", x.extrapolate, y.extrapolate);
        });
        list("/fixed_points", a.fixed_points, b.fixed_points,
             [this](const std::string& p, const FixedPoint& x, const FixedPoint& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/point", x.point, y.point);
             });
        list("/rollers", a.rollers, b.rollers, [this](const std::string& p, const Roller& x, const Roller& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/from", x.from, y.from);
            eq(p + "/to", x.to, y.to);
            eq(p + "/fix_x", x.fix_x, y.fix_x);
            eq(p + "/fix_y", x.fix_y, y.fix_y);
        });
        list("/point_loads", a.point_loads, b.point_loads, [this](const std::string& p, const PointLoad& x, const PointLoad& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/point", x.point, y.point);
            eq(p + "/force", x.force, y.force);
            eq(p + "/table", x.table, y.table);
        });
        list("/edge_pressures", a.edge_pressures, b.edge_pressures,
             [this](const std::string& p, const EdgePressure& x, const EdgePressure& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/from", x.from, y.from);
                 eq(p + "/to", x.to, y.to);
                 eq(p + "/pressure", x.pressure, y.pressure);
                 eq(p + "/table", x.table, y.table);
             });
        eq("/gravity", a.gravity, b.gravity);
        const InitialStress& s = a.initial_stress;
        const InitialStress& t = b.initial_stress;
        eq("/initial_stress/kind", static_cast<int>(s.kind), static_cast<int>(t.kind));
        for (int k = 0; k < 3; ++k) eq("/initial_stress/stress/" + std::to_string(k), s.stress[k], t.stress[k]);
        eq("/initial_stress/szz?", s.stress_zz.has_value(), t.stress_zz.has_value());
        if (s.stress_zz && t.stress_zz) eq("/initial_stress/szz", *s.stress_zz, *t.stress_zz);
        eq("/initial_stress/surface_y", s.surface_y, t.surface_y);
        eq("/initial_stress/k0", s.k0, t.k0);
        water("/water", a.water, b.water);
        list("/ground_motions", a.ground_motions, b.ground_motions,
             [this](const std::string& p, const GroundMotion& x, const GroundMotion& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/file", x.file, y.file);
                 eq(p + "/points", static_cast<long>(x.points.size()), static_cast<long>(y.points.size()));
                 for (std::size_t k = 0; k < std::min(x.points.size(), y.points.size()); ++k) {
                     eq(p + "/points/" + std::to_string(k) + "/0", x.points[k][0], y.points[k][0]);
                     eq(p + "/points/" + std::to_string(k) + "/1", x.points[k][1], y.points[k][1]);
                 }
                 eq(p + "/units", static_cast<int>(x.units), static_cast<int>(y.units));
                 eq(p + "/scale", x.scale, y.scale);
                 eq(p + "/baseline_correction", x.baseline_correction, y.baseline_correction);
             });
        eq("/base_motion/kind", static_cast<int>(a.base_motion.kind), static_cast<int>(b.base_motion.kind));
        eq("/base_motion/x", a.base_motion.x, b.base_motion.x);
        eq("/base_motion/y", a.base_motion.y, b.base_motion.y);
        eq("/base_motion/from", a.base_motion.from, b.base_motion.from);
        eq("/base_motion/to", a.base_motion.to, b.base_motion.to);
        list("/absorbing_boundaries", a.absorbing_boundaries, b.absorbing_boundaries,
             [this](const std::string& p, const AbsorbingBoundary& x, const AbsorbingBoundary& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/from", x.from, y.from);
                 eq(p + "/to", x.to, y.to);
             });
        seismic("/seismic_coefficient", a.seismic_coefficient, b.seismic_coefficient);
        list("/measurement_points", a.measurement_points, b.measurement_points,
             [this](const std::string& p, const MeasurementPoint& x, const MeasurementPoint& y) {
                 eq(p + "/name", x.name, y.name);
                 eq(p + "/point", x.point, y.point);
             });
        eq("/mesh/element", static_cast<int>(a.mesh.element), static_cast<int>(b.mesh.element));
        eq("/mesh/size", a.mesh.size, b.mesh.size);
        eq("/mesh/min_angle", a.mesh.min_angle, b.mesh.min_angle);
        eq("/mesh/grading", a.mesh.grading, b.mesh.grading);
        eq("/mesh/max_elements", a.mesh.max_elements, b.mesh.max_elements);
        list("/mesh/local", a.mesh.local, b.mesh.local, [this](const std::string& p, const LocalSize& x, const LocalSize& y) {
            eq(p + "/from", x.from, y.from);
            eq(p + "/to", x.to, y.to);
            eq(p + "/size", x.size, y.size);
            eq(p + "/radius", x.radius, y.radius);
        });
        const AnalysisSettings& u = a.analysis;
        const AnalysisSettings& v = b.analysis;
        eq("/analysis/kind", static_cast<int>(u.kind), static_cast<int>(v.kind));
        eq("/analysis/steps", u.steps, v.steps);
        eq("/analysis/time_step", u.time_step, v.time_step);
        eq("/analysis/max_displacement_ratio", u.max_displacement_ratio, v.max_displacement_ratio);
        eq("/analysis/penalty", u.penalty, v.penalty);
        eq("/analysis/dynamic_ratio", u.dynamic_ratio, v.dynamic_ratio);
        eq("/analysis/open_close_iterations", u.max_open_close_iterations, v.max_open_close_iterations);
        eq("/analysis/plastic_iterations", u.max_plastic_iterations, v.max_plastic_iterations);
        eq("/analysis/plastic_tolerance", u.plastic_tolerance, v.plastic_tolerance);
        eq("/analysis/min_load_fraction", u.min_load_fraction, v.min_load_fraction);
        eq("/analysis/output_every", u.output_every, v.output_every);
        eq("/analysis/plasticity", u.plasticity, v.plasticity);
        eq("/analysis/equilibrium_ratio", u.equilibrium_ratio, v.equilibrium_ratio);
        eq("/analysis/newmark_gamma", u.newmark_gamma, v.newmark_gamma);
        eq("/analysis/damping_ratio", u.damping_ratio, v.damping_ratio);
        eq("/analysis/damping_frequency", u.damping_frequency, v.damping_frequency);
        eq("/analysis/damping_frequency_2", u.damping_frequency_2, v.damping_frequency_2);
        list("/bolts", a.bolts, b.bolts, [this](const std::string& p, const Bolt& x, const Bolt& y) {
            eq(p + "/name", x.name, y.name);
            eq(p + "/from", x.from, y.from);
            eq(p + "/to", x.to, y.to);
            eq(p + "/stiffness", x.stiffness, y.stiffness);
            eq(p + "/strength", x.strength, y.strength);
            eq(p + "/pretension", x.pretension, y.pretension);
        });
        list("/stages", a.stages, b.stages, [this](const std::string& p, const Stage& x, const Stage& y) {
            eq(p + "/name", x.name, y.name);
            ints(p + "/excavate", x.excavate, y.excavate);
            ints(p + "/activate", x.activate, y.activate);
            eq(p + "/materials", static_cast<long>(x.materials.size()), static_cast<long>(y.materials.size()));
            for (std::size_t k = 0; k < std::min(x.materials.size(), y.materials.size()); ++k) {
                eq(p + "/materials/" + std::to_string(k) + "/region", x.materials[k][0], y.materials[k][0]);
                eq(p + "/materials/" + std::to_string(k) + "/material", x.materials[k][1], y.materials[k][1]);
            }
            eq(p + "/install", join(x.install), join(y.install));
            eq(p + "/remove", join(x.remove), join(y.remove));
            eq(p + "/analysis/steps", x.analysis.steps, y.analysis.steps);
            eq(p + "/analysis/kind", static_cast<int>(x.analysis.kind), static_cast<int>(y.analysis.kind));
            eq(p + "/analysis/time_step", x.analysis.time_step, y.analysis.time_step);
            eq(p + "/analysis/plastic_tolerance", x.analysis.plastic_tolerance, y.analysis.plastic_tolerance);
            eq(p + "/analysis/equilibrium_ratio", x.analysis.equilibrium_ratio, y.analysis.equilibrium_ratio);
            eq(p + "/release_steps", x.release_steps, y.release_steps);
            eq(p + "/release_table", x.release_table, y.release_table);
            eq(p + "/target_ratio", x.target_ratio, y.target_ratio);
            eq(p + "/water?", x.water.has_value(), y.water.has_value());
            if (x.water && y.water) water(p + "/water", *x.water, *y.water);
            eq(p + "/seismic_coefficient?", x.seismic_coefficient.has_value(), y.seismic_coefficient.has_value());
            if (x.seismic_coefficient && y.seismic_coefficient)
                seismic(p + "/seismic_coefficient", *x.seismic_coefficient, *y.seismic_coefficient);
        });
        return out_.str();
    }

private:
    static std::string join(const std::vector<std::string>& names) {
        std::string all;
        for (const std::string& n : names) all += n + "|";
        return all;
    }
    void ints(const std::string& path, const std::vector<int>& x, const std::vector<int>& y) {
        eq(path, static_cast<long>(x.size()), static_cast<long>(y.size()));
        for (std::size_t k = 0; k < std::min(x.size(), y.size()); ++k) eq(path + "/" + std::to_string(k), x[k], y[k]);
    }
    void eq(const std::string& path, double x, double y) {
        const double scale = std::max(std::fabs(x), std::fabs(y));
        if (std::fabs(x - y) <= tol_ * scale) return;  // also x == y == 0
        out_.precision(17);
        out_ << path << ": " << x << " != " << y << "\n";
    }
    void eq(const std::string& path, Point2 x, Point2 y) {
        eq(path + "/x", x.x, y.x);
        eq(path + "/y", x.y, y.y);
    }
    void eq(const std::string& path, const std::string& x, const std::string& y) {
        if (x != y) out_ << path << ": \"" << x << "\" != \"" << y << "\"\n";
    }
    void eq(const std::string& path, long x, long y) {
        if (x != y) out_ << path << ": " << x << " != " << y << "\n";
    }
    void eq(const std::string& path, int x, int y) { eq(path, static_cast<long>(x), static_cast<long>(y)); }
    void eq(const std::string& path, bool x, bool y) { eq(path, static_cast<long>(x), static_cast<long>(y)); }
    void points(const std::string& path, const std::vector<Point2>& x, const std::vector<Point2>& y) {
        list(path, x, y, [this](const std::string& p, Point2 a, Point2 b) { eq(p, a, b); });
    }
    template <class T, class F>
    void list(const std::string& path, const std::vector<T>& x, const std::vector<T>& y, F each) {
        if (x.size() != y.size()) {
            out_ << path << ": " << x.size() << " items != " << y.size() << " items\n";
            return;
        }
        for (std::size_t i = 0; i < x.size(); ++i) each(path + "/" + std::to_string(i), x[i], y[i]);
    }

    double tol_;
    std::ostringstream out_;
};

/// Differences between two models (empty when equal within `relative_tolerance`).
inline std::string model_differences(const Model& a, const Model& b, double relative_tolerance = 1e-12) {
    return ModelComparer(relative_tolerance).compare(a, b);
}

}  // namespace mcdda::test
