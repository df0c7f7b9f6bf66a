// The constitutive-law interface: which law a material gets, and that both laws agree on the
// elastic stiffness and behave as laws (trial stress kept inside the surface, tangent D there).

#include "fem/PlaneStrain.hpp"
#include "material/ConstitutiveLaw.hpp"
#include "material/MaterialLaws.hpp"
#include "material/ElasticLaw.hpp"
#include "material/MohrCoulomb.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

Material rock(bool plastic, double friction_deg, double dilation_deg) {
    Material m;
    m.name = "rock";
    m.young_modulus = 5e9;
    m.poisson_ratio = 0.2;
    m.law = plastic ? "mohr-coulomb" : "elastic";
    m.parameters = {{"cohesion", 0.5e6}, {"friction_angle", friction_deg * M_PI / 180.0},
                    {"dilation_angle", dilation_deg * M_PI / 180.0}};
    return m;
}

}  // namespace

TEST(ConstitutiveLaw, FactoryPicksMohrCoulombOnlyForPlasticMaterialsWithPlasticityOn) {
    const auto plastic = make_constitutive_law(rock(true, 30, 0), true);
    EXPECT_NE(dynamic_cast<const MohrCoulomb*>(plastic.get()), nullptr);
    EXPECT_TRUE(plastic->may_yield());
    EXPECT_FALSE(plastic->symmetric_tangent());  // ψ < φ
    EXPECT_TRUE(make_constitutive_law(rock(true, 30, 30), true)->symmetric_tangent());
    for (const auto& law : {make_constitutive_law(rock(false, 30, 0), true), make_constitutive_law(rock(true, 30, 0), false)}) {
        EXPECT_NE(dynamic_cast<const ElasticLaw*>(law.get()), nullptr);
        EXPECT_FALSE(law->may_yield());
    }
}

TEST(ConstitutiveLaw, BothLawsShareThePlaneStrainStiffnessAndKeepElasticTrials) {
    const Eigen::Matrix3d D = plane_strain_elasticity(5e9, 0.2);
    const PlaneStress inside{-1e6, -1.2e6, 0.1e6, -0.5e6};  // far inside the surface (c = 0.5 MPa)
    for (const auto& law : {make_constitutive_law(rock(true, 30, 0), true), make_constitutive_law(rock(false, 30, 0), true)}) {
        EXPECT_LT((law->elasticity() - D).norm(), 1e-9 * D.norm());
        Eigen::Matrix3d tangent;
        const ReturnResult r = law->return_map(inside, &tangent);
        EXPECT_FALSE(r.plastic);
        EXPECT_EQ(r.stress.xx, inside.xx);
        EXPECT_EQ(r.stress.zz, inside.zz);
        EXPECT_LT((tangent - D).norm(), 1e-9 * D.norm());
    }
    // Far outside: only Mohr–Coulomb returns; the elastic law keeps the stress.
    const PlaneStress outside{-20e6, -1e6, 0.0, -5e6};
    EXPECT_TRUE(make_constitutive_law(rock(true, 30, 0), true)->return_map(outside, nullptr).plastic);
    EXPECT_FALSE(make_constitutive_law(rock(false, 30, 0), true)->return_map(outside, nullptr).plastic);
}
