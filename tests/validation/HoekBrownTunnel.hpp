#pragma once
// References for a circular tunnel of radius R in a Hoek–Brown rock mass: hydrostatic in-situ
// stress p0, internal pressure pi, plane strain, linear elasticity (E, ν), perfect plasticity with
// the generalised criterion σ1 = σ3 + σci (mb σ3/σci + s)^a and the plastic potential of constant
// dilation, εr^p + Kψ εθ^p = 0 with Kψ = (1 + sin ψ)/(1 − sin ψ); σz is taken as the intermediate
// stress throughout (σθ ≥ σz ≥ σr), and the elastic strains of the plastic zone are those of the
// stress change from the in-situ state. Two independent references:
//  (a) the closed form of Carranza-Torres & Fairhurst (The elasto-plastic response of underground
//      excavations in rock masses that satisfy the Hoek–Brown failure criterion, Int. J. Rock Mech.
//      Min. Sci. 36 (1999) 777–809), for a = 1/2 only;
//  (b) a radial integration for any a: RK4 on a fine grid in log r, for the stresses outward from
//      the wall and for the displacement inward from the elastic–plastic boundary.
// Stresses compression positive (Pa), displacements inward (m), angles in radians.

#include <vector>

namespace mcdda::test {

struct HoekBrownTunnelSpec {
    double p0 = 15e6;             ///< hydrostatic in-situ stress
    double pi = 0.0;              ///< internal pressure at the wall, ≤ p0
    double radius = 1.0;          ///< R
    double young_modulus = 5e9;
    double poisson_ratio = 0.25;
    double sigma_ci = 50e6;       ///< uniaxial compressive strength of the intact rock
    double mb = 1.6768, s = 0.0038659, a = 0.5;  ///< about GSI 50, mi 10, D 0 (a = 0.5057 there)
    double dilation_angle = 0.0;  ///< ψ
};

struct HoekBrownTunnelSolution {
    double critical_pressure = 0.0;  ///< σr at the elastic–plastic boundary: yield starts when pi drops below it
    double plastic_radius = 0.0;     ///< R_pl; R when nothing yields
    double wall_displacement = 0.0;  ///< inward
};

/// Stresses at one radius.
struct HoekBrownTunnelStresses {
    double sigma_r = 0.0, sigma_theta = 0.0;
};

/// (a) Carranza-Torres & Fairhurst (1999), a = 1/2: in the scaled stresses S = σ/(mb σci) + s/mb²
/// the criterion is S1 = S3 + √S3. Throws std::invalid_argument when a ≠ 1/2.
HoekBrownTunnelSolution carranza_torres_fairhurst(const HoekBrownTunnelSpec& spec);

/// (a)'s stresses at radius r ≥ R.
HoekBrownTunnelStresses carranza_torres_fairhurst_stresses(const HoekBrownTunnelSpec& spec, double r);

/// The radial stress σre at the elastic–plastic boundary for any a: the root of
/// 2 (p0 − σ) = σci (mb σ/σci + s)^a (σθ = 2 p0 − σr in the elastic zone), by bisection.
double hoek_brown_critical_pressure(const HoekBrownTunnelSpec& spec);

/// The plastic zone of (b), sampled from the wall (r = R) to R_pl: inward displacement u.
struct HoekBrownTunnelProfile {
    std::vector<double> r, sigma_r, sigma_theta, displacement;
};

/// (b) The radial integration, `steps` RK4 steps per unit of ln r. With `profile` not null it
/// receives the plastic zone (empty when nothing yields). Throws std::invalid_argument for a spec
/// out of range (pi > p0, pi below the tensile strength −s σci/mb, parameters ≤ 0).
HoekBrownTunnelSolution hoek_brown_tunnel_integration(const HoekBrownTunnelSpec& spec, int steps = 2000,
                                                      HoekBrownTunnelProfile* profile = nullptr);

}  // namespace mcdda::test
