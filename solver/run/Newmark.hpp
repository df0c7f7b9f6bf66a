#pragma once
/// \file Newmark.hpp
/// The time integration of the dynamic analysis and the mass term of static DDA.

namespace mcdda {

// Newmark with γ = 0.7, β = (γ + ½)²/4. Shi's DDA scheme (β = ½, γ = 1) does not damp the
// highest frequencies at all: the velocity of a stiff contact spring flips sign every step for
// ever, and in a sliding block that chatter reverses the slip and locks contacts. This member
// damps those frequencies (spectral radius about 0.67 at ωΔt → ∞) and, like every Newmark
// member, integrates a constant acceleration exactly (the sliding-block solution).
constexpr double newmark_gamma = 0.7;
constexpr double newmark_beta = (newmark_gamma + 0.5) * (newmark_gamma + 0.5) / 4.0;

struct NewmarkParameters {
    double beta, gamma;
};

/// The first dynamic step knows no acceleration yet (a0 = 0 would be wrong by the whole load and
/// that error would ring for many steps), so it uses Shi's member, which does not involve a0.
inline NewmarkParameters newmark_for(int step) {
    return step == 0 ? NewmarkParameters{0.5, 1.0} : NewmarkParameters{newmark_beta, newmark_gamma};
}

}  // namespace mcdda
