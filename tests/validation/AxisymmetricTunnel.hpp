#pragma once
// Reference for the circular tunnel in a Mohr–Coulomb medium (Salençon): a 1-D axisymmetric
// plane-strain finite-element solution in r that keeps σz in the yield condition (Salençon's
// closed form assumes σz intermediate, which it is not near the wall when σz0 = P0). Uses the
// solver's own return mapping, mcdda::MohrCoulomb, at every integration point.

#include <optional>
#include <vector>

namespace mcdda::test {

/// Outer boundary at r = b: traction σr(b) = P0, or u(b) = 0.
enum class OuterBoundary { Traction, Fixed };

/// Stresses are compression positive (Pa), angles in radians, lengths in m.
struct AxisymmetricTunnelSpec {
    double P0 = 10e6;                  ///< in-situ σr = σθ, and the outer traction
    std::optional<double> sigma_z0;    ///< in-situ σz; P0 when not given
    double Pi = 0.0;                   ///< final inner pressure (unloaded from P0)
    double young_modulus = 5000e6;
    double poisson_ratio = 0.2;
    double cohesion = 0.5e6;
    double friction_angle = 0.5235987755982988;  ///< 30°
    double dilation_angle = 0.0;
    double a = 1.0;                    ///< tunnel radius
    double b = 20.0;                   ///< outer radius
    OuterBoundary outer = OuterBoundary::Traction;
    int elements = 2000;               ///< linear elements, sizes ∝ r (uniform in log r)
    int increments = 100;              ///< equal steps of the inner pressure P0 → Pi
};

struct AxisymmetricTunnelResult {
    double wall_displacement = 0.0;  ///< inward, m
    double plastic_radius = 0.0;     ///< m; a when nothing yields
    /// At the integration points (r increasing), compression positive, Pa.
    std::vector<double> r, sigma_r, sigma_theta, sigma_z;
    std::vector<bool> yielding;      ///< on the yield surface at the end
    int newton_iterations = 0;       ///< over all increments
};

/// Solves the tunnel by Newton's method with the consistent tangent of the return mapping; each
/// increment is converged to a nodal residual of 1e-10 of max(P0, Pi, c)·a (per radian); throws
/// std::runtime_error otherwise.
AxisymmetricTunnelResult solve_axisymmetric_tunnel(const AxisymmetricTunnelSpec& spec);

/// The largest radius within the plastic zone at which σz is not strictly intermediate (it ties
/// with or passes σθ or σr, so the stress is on an edge of the yield surface); 0 when σz stays
/// intermediate throughout the plastic zone.
double sigma_z_not_intermediate_radius(const AxisymmetricTunnelResult& result);

/// Salençon's closed form for an infinite medium, σz intermediate throughout.
struct SalenconClosedForm {
    double plastic_radius;     ///< R0, m
    double wall_displacement;  ///< inward, m (non-associated flow with the spec's ψ)
};
SalenconClosedForm salencon_closed_form(const AxisymmetricTunnelSpec& spec);

/// Lamé thick cylinder (plane strain, elastic): inward wall displacement when the inner pressure
/// drops from P0 to Pi, for the spec's outer boundary.
double lame_wall_displacement(const AxisymmetricTunnelSpec& spec);

}  // namespace mcdda::test
