// Joint cohesion and tensile strength act per unit length of the joint, once: a block hanging from
// a fixed block by a bonded joint (tensile strength = cohesion; without cohesion a joint in tension
// has no shear strength, slides at the first shear and loses its bond) holds when it is strong
// enough and falls freely when it is not.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mcdda;

namespace {

/// A 2 m × 1 m block (weight 2500·9.81·2 = 49,050 N/m) hanging under a fixed block; the joint
/// between them is 2 m long: a mean tension of 24.5 kPa, peaking at the ends of the joint where
/// the elastic blocks meet at corners (it unzips from there at 40 kPa; it holds at 60 kPa).
std::string hanging_block(double tensile_strength) {
    return R"({
  "format": "mcdda-model", "version": 1, "name": "hanging block",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "plastic": false } ],
  "joint_materials": [ { "name": "glued", "friction_angle": 30, "tensile_strength": )" +
           std::to_string(tensile_strength) + R"(, "cohesion": )" + std::to_string(tensile_strength) + R"( } ],
  "regions": [ { "name": "roof", "material": "rock", "boundary": [[0,1],[2,1],[2,2],[0,2]] },
               { "name": "hanging", "material": "rock", "boundary": [[0,0],[2,0],[2,1],[0,1]] } ],
  "rollers": [ { "name": "top", "from": [0,2], "to": [2,2], "fixed": "xy" } ],
  "gravity": [0, -9.81],
  "measurement_points": [ { "name": "bottom", "point": [1, 0] } ],
  "mesh": { "size": 0.25 },
  "analysis": { "type": "dynamic", "steps": 50, "time_step": 0.01 }
})";
}

}  // namespace

TEST(ContactStrength, TensileStrengthHoldsAHangingBlockOnlyWhenStrongEnough) {
    auto strong = mcdda::test::run_text(hanging_block(60e3));  // 2.4 × the mean tension of 24.5 kPa
    ASSERT_TRUE(strong.simulation);
    const double held = -strong.history.points.back()[0].y;
    auto weak = mcdda::test::run_text(hanging_block(15e3));  // below the mean tension
    ASSERT_TRUE(weak.simulation);
    const double fell = -weak.history.points.back()[0].y;
    const double free_fall = 0.5 * 9.81 * std::pow(weak.simulation->state().time, 2);
    std::cout << "hanging block: held " << held * 1000 << " mm with tj = 60 kPa; fell " << fell << " m with 15 kPa (free fall "
              << free_fall << " m)\n";
    EXPECT_LT(held, 1e-3);
    EXPECT_NEAR(fell, free_fall, 0.02 * free_fall);
}
