// The declared number fields (model/ModelFields.hpp): every one is read, written and checked
// through its declaration, so a field declared once works in the file, the validator and the
// forms. These tests go over the lists, so a field added to them is covered without a new test.

#include "TestModels.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"
#include "model/Defaults.hpp"
#include "material/MaterialLaws.hpp"
#include "model/ModelFields.hpp"
#include "check/ModelValidator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::square_model_json;
using Severity = Diagnostic::Severity;

namespace {

/// A value inside the field's range, different from its default and from the other fields'.
double allowed_value(const NumberField& f, int k)
{
    const double step = 0.01 * (k + 1);
    double lo = f.lower ? f.lower->value : 0.0;
    double hi = f.upper ? f.upper->value : (lo + 1.0) * 1e6;
    if (f.physical_limit > 0.0) hi = std::min(hi, f.physical_limit);
    return lo + (hi - lo) * (0.2 + step);
}

/// A model with one bolt, read from the square test model.
Model bolted_model()
{
    const ReadResult r = read_model_text(
        square_model_json(),
        {"/version=2", R"(/bolts=[{"name": "b", "from": [2,2], "to": [3,8], "stiffness": 1e8}])"});
    EXPECT_TRUE(r.model.has_value()) << all_messages(r.diagnostics);
    return *r.model;
}

template <class Record>
void set_all(Record& record, const std::vector<RecordField<Record>>& fields)
{
    for (std::size_t k = 0; k < fields.size(); ++k) record.*fields[k].member = allowed_value(fields[k].field, static_cast<int>(k));
}

template <class Record>
void expect_same(const Record& a, const Record& b, const std::vector<RecordField<Record>>& fields)
{
    for (const RecordField<Record>& f : fields) EXPECT_EQ(a.*f.member, b.*f.member) << f.field.key;
}

}  // namespace

// Each declared field survives write → read exactly (angles through degrees).
TEST(ModelFields, EveryFieldRoundTripsThroughTheFile) {
    Model m = bolted_model();
    set_all(m.materials[0], material_fields());
    m.materials[0].parameters["dilation_angle"] = 0.5 * m.materials[0].parameter("friction_angle");  // ψ ≤ φ
    set_all(m.joint_materials[0], joint_material_fields());
    set_all(m.bolts[0], bolt_fields());
    set_all(m.analysis, analysis_fields());
    std::vector<Diagnostic> d;
    validate_model(m, d);
    EXPECT_FALSE(has_errors(d)) << all_messages(d);
    const ReadResult back = read_model_text(write_model_text(m));
    ASSERT_TRUE(back.model.has_value()) << all_messages(back.diagnostics);
    EXPECT_FALSE(has_errors(back.diagnostics)) << all_messages(back.diagnostics);
    expect_same(m.materials[0], back.model->materials[0], material_fields());
    expect_same(m.joint_materials[0], back.model->joint_materials[0], joint_material_fields());
    expect_same(m.bolts[0], back.model->bolts[0], bolt_fields());
    expect_same(m.analysis, back.model->analysis, analysis_fields());
}

// A value below a field's lower bound is an error at that field's place, naming the field, the
// value with its unit and, where 0 has a meaning, that meaning.
TEST(ModelFields, EveryLowerBoundIsChecked) {
    auto check = [](auto& record, const auto& fields, const std::string& prefix, Model& m) {
        for (const auto& f : fields) {
            if (!f.field.lower) continue;
            const double kept = record.*f.member;
            record.*f.member = f.field.lower->value - 1.0;
            std::vector<Diagnostic> d;
            validate_model(m, d);
            const std::string path = prefix + f.field.key;
            EXPECT_TRUE(has_diagnostic(d, Severity::Error, path, f.field.name)) << path << "\n" << all_messages(d);
            if (f.field.zero_means)
                EXPECT_TRUE(has_diagnostic(d, Severity::Error, path, std::string("0 = ") + f.field.zero_means));
            record.*f.member = kept;
        }
    };
    Model m = bolted_model();
    check(m.materials[0], material_fields(), "/materials/0/", m);
    check(m.joint_materials[0], joint_material_fields(), "/joint_materials/0/", m);
    check(m.bolts[0], bolt_fields(), "/bolts/0/", m);
    check(m.analysis, analysis_fields(), "/analysis/", m);
    std::vector<Diagnostic> d;
    validate_model(m, d);
    EXPECT_FALSE(has_errors(d)) << all_messages(d);  // and each error went away with its cause
}

// Ranges read as engineers write them, in the file's units.
TEST(ModelFields, MessagesInTheFileUnits) {
    const NumberField& phi = find_material_law("mohr-coulomb")->fields[1];
    ASSERT_STREQ(phi.key, "friction_angle");
    EXPECT_EQ(range_error(phi, 95.0 * degree), "friction angle must lie in [0°, 90°) (got 95°)");
    EXPECT_EQ(range_error(phi, 30.0 * degree), "");
    const NumberField& nu = material_fields()[1].field;
    EXPECT_EQ(range_error(nu, 0.5), "Poisson's ratio must lie in (-1, 0.5) (got 0.5)");
    EXPECT_EQ(limit_error(material_fields()[0].field, 2e15),
              "Young's modulus of 2e+15 Pa is beyond any physical value (at most 1e+14 Pa): check the units");
    EXPECT_EQ(to_file_unit(Quantity::Angle, 30.0 * degree), 30.0);
}

// A key that no declaration knows is refused and the message lists the known ones.
TEST(ModelFields, UnknownKeysListTheDeclaredOnes) {
    const ReadResult r = read_model_text(square_model_json(), {"/materials/0/young_modulu=1e9"});
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/materials/0/young_modulu", "tensile_strength")) << all_messages(r.diagnostics);
}

namespace {

/// The test model with its material under `law`, every field of the law at an allowed value.
Model model_with_law(const MaterialLaw& law)
{
    Model m = bolted_model();
    Material& mat = m.materials[0];
    mat.law = law.key;
    mat.parameters.clear();
    for (std::size_t k = 0; k < law.fields.size(); ++k)
        mat.parameters[law.fields[k].key] = allowed_value(law.fields[k], static_cast<int>(k));
    if (mat.parameters.count("friction_angle")) {  // ψ ≤ φ, in whole degrees that read back exactly
        mat.parameters["friction_angle"] = 25.0 * degree;
        mat.parameters["dilation_angle"] = 10.0 * degree;
    }
    return m;
}

}  // namespace

// Every law's own fields survive write → read exactly, under the law's key.
TEST(MaterialLaws, EveryLawsFieldsRoundTripThroughTheFile) {
    ASSERT_GE(material_laws().size(), 3u);
    for (const MaterialLaw* law : material_laws()) {
        const Model m = model_with_law(*law);
        std::vector<Diagnostic> d;
        validate_model(m, d);
        EXPECT_FALSE(has_errors(d)) << law->key << "\n" << all_messages(d);
        const std::string text = write_model_text(m);
        EXPECT_NE(text.find(std::string("\"law\": \"") + law->key + "\""), std::string::npos) << text;
        const ReadResult back = read_model_text(text);
        ASSERT_TRUE(back.model.has_value()) << all_messages(back.diagnostics);
        EXPECT_EQ(back.model->materials[0].law, law->key);
        EXPECT_EQ(back.model->materials[0].parameters, m.materials[0].parameters) << law->key;
    }
}

// A value below a law field's lower bound is an error at that field, naming it; a required
// field that is missing is named with its law.
TEST(MaterialLaws, EveryLowerBoundAndEveryRequiredFieldIsChecked) {
    for (const MaterialLaw* law : material_laws()) {
        for (const NumberField& f : law->fields) {
            Model m = model_with_law(*law);
            const std::string path = std::string("/materials/0/") + f.key;
            if (f.lower) {
                m.materials[0].parameters[f.key] = f.lower->value - 1.0;
                std::vector<Diagnostic> d;
                validate_model(m, d);
                EXPECT_TRUE(has_diagnostic(d, Severity::Error, path, f.name)) << path << "\n" << all_messages(d);
            }
            m = model_with_law(*law);
            m.materials[0].parameters.erase(f.key);
            std::vector<Diagnostic> d;
            validate_model(m, d);
            if (f.default_value) {
                EXPECT_FALSE(has_diagnostic(d, Severity::Error, path, "required")) << path << " has a default\n" << all_messages(d);
            } else {
                EXPECT_TRUE(has_diagnostic(d, Severity::Error, path, std::string("required by the ") + law->label))
                    << path << "\n" << all_messages(d);
                const ReadResult r = read_model_text(write_model_text(m));
                EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, path, "missing")) << all_messages(r.diagnostics);
            }
        }
    }
}

// "law" names the law; the earlier `"plastic": false` still reads, as elastic, strengths and all;
// both at once, an unknown law, or another law's field are refused at their place.
TEST(MaterialLaws, TheLawKeyAndTheEarlierPlasticFlag) {
    // The square model's material with `more` keys (its own: E, ν, ρ, c, φ, ψ).
    auto material = [](const std::string& more, bool strengths = true) {
        return std::string(R"(/materials/0={"name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500)") +
               (strengths ? R"(, "cohesion": 1e6, "friction_angle": 30)" : "") + more + "}";
    };
    auto law_of = [](const std::string& override) {
        const ReadResult r = read_model_text(square_model_json(), {override});
        return r.model ? r.model->materials[0].law : "(refused) " + all_messages(r.diagnostics);
    };
    EXPECT_EQ(law_of(material("")), "mohr-coulomb");
    EXPECT_EQ(law_of(material(R"(, "plastic": false)")), "elastic");
    EXPECT_EQ(law_of(material(R"(, "plastic": true)")), "mohr-coulomb");
    EXPECT_EQ(law_of(material(R"(, "law": "elastic")", false)), "elastic");
    EXPECT_EQ(law_of(material(R"(, "law": "hoek-brown", "uniaxial_strength": 50e6, "gsi": 60, "mi": 10)", false)), "hoek-brown");

    auto refusal = [](const std::string& override) {
        return read_model_text(square_model_json(), {override}).diagnostics;
    };
    const auto both = refusal(material(R"(, "plastic": false, "law": "elastic")"));
    EXPECT_TRUE(has_diagnostic(both, Severity::Error, "/materials/0", "not both")) << all_messages(both);
    const auto unknown = refusal(material(R"(, "law": "cam-clay")"));
    EXPECT_TRUE(has_diagnostic(unknown, Severity::Error, "/materials/0/law", "\"hoek-brown\"")) << all_messages(unknown);
    const auto foreign = refusal(material(R"(, "law": "hoek-brown", "uniaxial_strength": 50e6, "gsi": 60, "mi": 10)"));
    EXPECT_TRUE(has_diagnostic(foreign, Severity::Error, "/materials/0/cohesion", "unknown key")) << all_messages(foreign);
    const auto missing = refusal(material(R"(, "law": "hoek-brown", "uniaxial_strength": 50e6, "mi": 10)", false));
    EXPECT_TRUE(has_diagnostic(missing, Severity::Error, "/materials/0/gsi", "missing")) << all_messages(missing);
}
