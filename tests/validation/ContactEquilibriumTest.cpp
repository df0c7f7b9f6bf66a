// A block resting on a fixed base under gravity: the contacts carry exactly its weight.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

const char* resting_block = R"({
  "format": "mcdda-model", "version": 1, "name": "resting block",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "plastic": false } ],
  "joint_materials": [ { "name": "interface", "friction_angle": 30 } ],
  "regions": [ { "name": "base", "material": "rock", "boundary": [[0,0],[4,0],[4,1],[0,1]] },
               { "name": "block", "material": "rock", "boundary": [[1,1],[3,1],[3,2],[1,2]] } ],
  "rollers": [ { "name": "bottom", "from": [0,0], "to": [4,0], "fixed": "xy" } ],
  "gravity": [0, -9.81],
  "mesh": { "size": 0.25, "min_angle": 30 },
  "analysis": { "type": "static", "steps": 30, "time_step": 1.0, "max_displacement_ratio": 0.01 }
})";

}  // namespace

TEST(ContactEquilibrium, RestingBlockContactsCarryItsWeight) {
    auto run = mcdda::test::run_text(resting_block);
    ASSERT_TRUE(run.simulation);
    const Simulation& s = *run.simulation;
    double total = 0.0;
    int closed = 0;
    for (const Contact& c : s.state().contacts) {
        if (c.state == ContactState::Open) continue;
        ++closed;
        // Contacts here are horizontal: the normal force is vertical.
        total += c.normal_force;
    }
    const double weight = 2500.0 * 9.81 * 2.0;  // ρ g A of the 2 m × 1 m block, N/m
    std::cout << "resting block: " << closed << " closed contacts carry " << total << " N/m, weight " << weight
              << " N/m, error " << 100.0 * (total - weight) / weight << " %\n";
    EXPECT_GT(closed, 4);
    EXPECT_NEAR(total, weight, 0.01 * weight);
    for (const Contact& c : s.state().contacts) EXPECT_NE(c.state, ContactState::Sliding);
}
