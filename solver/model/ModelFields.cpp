#include "model/ModelFields.hpp"

#include "model/Defaults.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace mcdda {

namespace {

constexpr Bound above(double v) { return {v, false}; }
constexpr Bound from(double v) { return {v, true}; }
constexpr Bound below(double v) { return {v, false}; }

}  // namespace

const std::vector<RecordField<Material>>& material_fields()
{
    static const std::vector<RecordField<Material>> fields{
        {{"young_modulus", "Young's modulus", MCDDA_TRANSLATABLE("ModelFields", "Young's modulus E"), Quantity::Modulus, std::nullopt, above(0.0),
          std::nullopt, max_modulus, nullptr, MCDDA_TRANSLATABLE("ModelFields", "Young's modulus E of the intact rock, > 0")},
         &Material::young_modulus},
        {{"poisson_ratio", "Poisson's ratio", MCDDA_TRANSLATABLE("ModelFields", "Poisson's ratio ν"), Quantity::Ratio, std::nullopt, above(-1.0),
          below(0.5), 0.0, nullptr, MCDDA_TRANSLATABLE("ModelFields", "Poisson's ratio ν, in (−1, 0.5)")},
         &Material::poisson_ratio},
        {{"density", "density", MCDDA_TRANSLATABLE("ModelFields", "Unit weight γ"), Quantity::Density, 0.0, from(0.0), std::nullopt, max_density,
          nullptr, MCDDA_TRANSLATABLE("ModelFields", "Unit weight γ = ρ g (the density is γ / 9.81 m/s²); loads the model through gravity")},
         &Material::density},
        {{"saturated_density", "saturated density", MCDDA_TRANSLATABLE("ModelFields", "Saturated unit weight γsat"), Quantity::Density, 0.0, from(0.0),
          std::nullopt, max_density, MCDDA_TRANSLATABLE("ModelFields", "the unit weight"),
          MCDDA_TRANSLATABLE("ModelFields", "Unit weight below the piezometric line; 0 = the unit weight γ there too")},
         &Material::saturated_density},
    };
    return fields;
}

const std::vector<RecordField<JointMaterial>>& joint_material_fields()
{
    static const std::vector<RecordField<JointMaterial>> fields{
        {{"friction_angle", "joint friction angle", MCDDA_TRANSLATABLE("ModelFields", "Friction angle φj"), Quantity::Angle, std::nullopt, from(0.0),
          below(pi / 2), 0.0, nullptr, MCDDA_TRANSLATABLE("ModelFields", "Coulomb friction angle of the joint surfaces, in [0°, 90°)")},
         &JointMaterial::friction_angle},
        {{"cohesion", "joint cohesion", MCDDA_TRANSLATABLE("ModelFields", "Cohesion cj"), Quantity::Stress, 0.0, from(0.0), std::nullopt, max_stress,
          nullptr, MCDDA_TRANSLATABLE("ModelFields", "Cohesion of the joint, ≥ 0; lost once the joint has slipped or opened")},
         &JointMaterial::cohesion},
        {{"tensile_strength", "joint tensile strength", MCDDA_TRANSLATABLE("ModelFields", "Tensile strength tj"), Quantity::Stress, 0.0, from(0.0),
          std::nullopt, max_stress, nullptr, MCDDA_TRANSLATABLE("ModelFields", "Tensile strength of the joint, ≥ 0; 0 = the joint opens under any tension")},
         &JointMaterial::tensile_strength},
        {{"normal_stiffness", "normal stiffness", MCDDA_TRANSLATABLE("ModelFields", "Normal stiffness kn"), Quantity::Stiffness, 0.0, from(0.0),
          std::nullopt, 0.0, MCDDA_TRANSLATABLE("ModelFields", "automatic"), MCDDA_TRANSLATABLE("ModelFields", "Normal stiffness per metre of thickness; 0 = the analysis penalty")},
         &JointMaterial::normal_stiffness},
        {{"shear_stiffness", "shear stiffness", MCDDA_TRANSLATABLE("ModelFields", "Shear stiffness ks"), Quantity::Stiffness, 0.0, from(0.0),
          std::nullopt, 0.0, MCDDA_TRANSLATABLE("ModelFields", "automatic"), MCDDA_TRANSLATABLE("ModelFields", "Shear stiffness; 0 = automatic")},
         &JointMaterial::shear_stiffness},
    };
    return fields;
}

const std::vector<RecordField<Bolt>>& bolt_fields()
{
    static const std::vector<RecordField<Bolt>> fields{
        {{"stiffness", "bolt stiffness EA", MCDDA_TRANSLATABLE("ModelFields", "Axial stiffness EA"), Quantity::Stiffness, std::nullopt, above(0.0),
          std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Axial stiffness EA of the bolt per metre of model thickness (bolt EA over the spacing out of plane), > 0")},
         &Bolt::stiffness},
        {{"strength", "bolt strength", MCDDA_TRANSLATABLE("ModelFields", "Strength"), Quantity::Force, 0.0, from(0.0), std::nullopt, 0.0,
          MCDDA_TRANSLATABLE("ModelFields", "unbreakable"), MCDDA_TRANSLATABLE("ModelFields", "Axial force at which the bolt breaks, per metre of model thickness; 0 = unbreakable")},
         &Bolt::strength},
        {{"pretension", "pretension", MCDDA_TRANSLATABLE("ModelFields", "Pretension"), Quantity::Force, 0.0, from(0.0), std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Axial force when installed, per metre of model thickness, pulling the ends together; ≥ 0")},
         &Bolt::pretension},
    };
    return fields;
}

const std::vector<RecordField<AnalysisSettings>>& analysis_fields()
{
    const AnalysisSettings defaults;
    static const std::vector<RecordField<AnalysisSettings>> fields{
        {{"time_step", "time step", MCDDA_TRANSLATABLE("ModelFields", "Time step Δt"), Quantity::Time,
          defaults.time_step, above(0.0), std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Initial and largest time step; it is cut automatically when a step moves too far or does not converge. In a static analysis time only orders the load steps")},
         &AnalysisSettings::time_step},
        {{"max_displacement_ratio", "max displacement ratio", MCDDA_TRANSLATABLE("ModelFields", "Max displacement ratio"),
          Quantity::Ratio, defaults.max_displacement_ratio, above(0.0), Bound{0.1, true}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Largest displacement in one step divided by the model size (Shi's g2)")},
         &AnalysisSettings::max_displacement_ratio},
        {{"penalty", "penalty", MCDDA_TRANSLATABLE("ModelFields", "Penalty"), Quantity::Stiffness, defaults.penalty,
          from(0.0), std::nullopt, 0.0, MCDDA_TRANSLATABLE("ModelFields", "automatic"),
          MCDDA_TRANSLATABLE("ModelFields", "Contact spring stiffness; 0 = automatic (from E)")},
         &AnalysisSettings::penalty},
        {{"dynamic_ratio", "dynamic ratio", MCDDA_TRANSLATABLE("ModelFields", "Dynamic ratio"), Quantity::Ratio,
          defaults.dynamic_ratio, from(0.0), Bound{1.0, true}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Fraction of the velocity carried into the next step of a dynamic analysis (1: none lost)")},
         &AnalysisSettings::dynamic_ratio},
        {{"plastic_tolerance", "plastic tolerance", MCDDA_TRANSLATABLE("ModelFields", "Equilibrium tolerance"),
          Quantity::Ratio, defaults.plastic_tolerance, above(0.0), std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Out-of-balance force, relative to the force scale, below which a step's equilibrium iterations stop")},
         &AnalysisSettings::plastic_tolerance},
        {{"min_load_fraction", "min load fraction", MCDDA_TRANSLATABLE("ModelFields", "Smallest load increment"),
          Quantity::Ratio, defaults.min_load_fraction, above(0.0), Bound{1.0, true}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "A static step that does not converge is halved down to this fraction of a step; failing there is a collapse")},
         &AnalysisSettings::min_load_fraction},
        {{"equilibrium_ratio", "equilibrium ratio", MCDDA_TRANSLATABLE("ModelFields", "Equilibrium ratio"),
          Quantity::Ratio, defaults.equilibrium_ratio, above(0.0), std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "A run whose unbalanced-force ratio ends above this is reported as not in equilibrium")},
         &AnalysisSettings::equilibrium_ratio},
        {{"factor_tolerance", "factor tolerance", MCDDA_TRANSLATABLE("ModelFields", "Factor of safety tolerance"),
          Quantity::Ratio, defaults.factor_tolerance, above(0.0), Bound{0.1, true}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Strength reduction: the search for the factor of safety stops once the factors that stand and that do not differ by less than this fraction")},
         &AnalysisSettings::factor_tolerance},
        {{"newmark_gamma", "Newmark gamma", MCDDA_TRANSLATABLE("ModelFields", "Newmark γ"), Quantity::Ratio,
          defaults.newmark_gamma, Bound{0.5, true}, Bound{1.0, true}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Dynamic analysis: Newmark's γ (β = (γ + ½)²/4). 0.7 damps the highest frequencies; 0.5 adds no numerical damping")},
         &AnalysisSettings::newmark_gamma},
        {{"damping_ratio", "damping ratio", MCDDA_TRANSLATABLE("ModelFields", "Damping ratio"), Quantity::Ratio,
          defaults.damping_ratio, from(0.0), Bound{1.0, false}, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Dynamic analysis: Rayleigh damping as a fraction of critical damping (0: none)")},
         &AnalysisSettings::damping_ratio},
        {{"damping_frequency", "damping frequency", MCDDA_TRANSLATABLE("ModelFields", "Damping frequency"),
          Quantity::Frequency, defaults.damping_frequency, above(0.0), std::nullopt, 0.0, nullptr,
          MCDDA_TRANSLATABLE("ModelFields", "Frequency at which the Rayleigh damping has the damping ratio (its least when no second frequency is given)")},
         &AnalysisSettings::damping_frequency},
        {{"damping_frequency_2", "second damping frequency", MCDDA_TRANSLATABLE("ModelFields", "Second damping frequency"),
          Quantity::Frequency, defaults.damping_frequency_2, from(0.0), std::nullopt, 0.0,
          MCDDA_TRANSLATABLE("ModelFields", "none"),
          MCDDA_TRANSLATABLE("ModelFields", "A second frequency with the same damping ratio (less damping between the two); 0: one frequency")},
         &AnalysisSettings::damping_frequency_2},
    };
    return fields;
}

double to_file_unit(Quantity quantity, double model_value)
{
    if (quantity != Quantity::Angle) return model_value;
    const double nearest = model_value / degree;
    char text[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, nearest);
        const double candidate = std::strtod(text, nullptr);
        if (candidate * degree == model_value) return candidate;
    }
    return nearest;
}

double from_file_unit(Quantity quantity, double file_value)
{
    return quantity == Quantity::Angle ? file_value * degree : file_value;
}

std::string value_text(Quantity quantity, double model_value)
{
    std::ostringstream out;
    out << to_file_unit(quantity, model_value);
    switch (quantity) {
    case Quantity::Ratio: break;
    case Quantity::Modulus:
    case Quantity::Stress: out << " Pa"; break;
    case Quantity::Density: out << " kg/m³"; break;
    case Quantity::Angle: out << "°"; break;
    case Quantity::Stiffness:
    case Quantity::Force: out << " N/m"; break;
    case Quantity::Time: out << " s"; break;
    case Quantity::Frequency: out << " Hz"; break;
    }
    return out.str();
}

std::string range_error(const NumberField& field, double value)
{
    const bool above_lower = !field.lower || (field.lower->inclusive ? value >= field.lower->value : value > field.lower->value);
    const bool below_upper = !field.upper || (field.upper->inclusive ? value <= field.upper->value : value < field.upper->value);
    if (above_lower && below_upper && std::isfinite(value)) return {};
    std::string rule;
    if (field.lower && field.upper) {
        auto end = [&](double v) {
            return field.quantity == Quantity::Angle ? value_text(Quantity::Angle, v) : value_text(Quantity::Ratio, v);
        };
        rule = std::string("must lie in ") + (field.lower->inclusive ? "[" : "(") + end(field.lower->value) + ", " +
               end(field.upper->value) + (field.upper->inclusive ? "]" : ")");
    } else if (field.lower && field.lower->value == 0.0) {
        rule = field.lower->inclusive ? "must not be negative" : "must be positive";
    } else if (field.lower) {
        rule = std::string("must be ") + (field.lower->inclusive ? "at least " : "more than ") +
               value_text(field.quantity, field.lower->value);
    } else {
        rule = std::string("must be ") + (field.upper->inclusive ? "at most " : "less than ") +
               value_text(field.quantity, field.upper->value);
    }
    std::string got = "got " + value_text(field.quantity, value);
    if (field.zero_means) got += std::string("; 0 = ") + field.zero_means;
    return std::string(field.name) + " " + rule + " (" + got + ")";
}

std::string limit_error(const NumberField& field, double value)
{
    if (!(field.physical_limit > 0.0) || !std::isfinite(value) || std::fabs(value) <= field.physical_limit) return {};
    return std::string(field.name) + " of " + value_text(field.quantity, value) +
           " is beyond any physical value (at most " + value_text(field.quantity, field.physical_limit) +
           "): check the units";
}

}  // namespace mcdda
