#pragma once
/// \file Newmark.hpp
/// The time integration of the dynamic analysis and the mass term of static DDA.

namespace mcdda {

// Newmark with γ = 0.7 by default (analysis.newmark_gamma), β = (γ + ½)²/4. Shi's DDA scheme (β = ½, γ = 1) does not damp the
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
/// Later steps use γ (β = (γ + ½)²/4: unconditionally stable, second order at γ = ½).
inline NewmarkParameters newmark_for(int step, double gamma = newmark_gamma) {
    return step == 0 ? NewmarkParameters{0.5, 1.0} : NewmarkParameters{(gamma + 0.5) * (gamma + 0.5) / 4.0, gamma};
}

/// Newmark's end-of-step velocity as rate·d + rest for increments d: rate = γ/(βΔt), rest =
/// (1 − γ/β)·v0 + Δt(1 − γ/(2β))·a0 (dashpots and Rayleigh damping act on it).
inline double newmark_velocity_rate(NewmarkParameters p, double dt) { return p.gamma / (p.beta * dt); }

}  // namespace mcdda
