#include "run/GroundShaking.hpp"

#include "model/Defaults.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// Velocity and displacement at the samples: the exact integrals of the linear acceleration
/// between them, from rest at the first.
void integrate(const std::vector<double>& t, const std::vector<double>& a, std::vector<double>& v,
               std::vector<double>& u) {
    v.assign(t.size(), 0.0);
    u.assign(t.size(), 0.0);
    for (std::size_t k = 1; k < t.size(); ++k) {
        const double h = t[k] - t[k - 1];
        v[k] = v[k - 1] + 0.5 * h * (a[k - 1] + a[k]);
        u[k] = u[k - 1] + h * v[k - 1] + h * h * (a[k - 1] / 3.0 + a[k] / 6.0);
    }
}

}  // namespace

GroundShaking::GroundShaking(const GroundMotion& g) {
    const double unit = g.units == GroundMotion::Units::G ? standard_gravity : 1.0;
    for (const auto& p : g.points) {
        time_.push_back(p[0]);
        acceleration_.push_back(p[1] * unit * g.scale);
    }
    integrate(time_, acceleration_, velocity_, displacement_);
    if (g.baseline_correction && time_.size() >= 2) {
        // a − (c0 + c1 τ), τ = t − t0 over the record's length L, such that the base ends at rest
        // where it began: ∫(c0 + c1 τ) = v(L) and ∫(L − τ)(c0 + c1 τ) = u(L). A linear correction of
        // a piecewise-linear record is exact at the samples.
        const double L = time_.back() - time_.front(), V = velocity_.back(), D = displacement_.back();
        // c0 L + c1 L²/2 = V;  c0 L²/2 + c1 L³/6 = D.
        const double c1 = (V * L / 2.0 - D) / (L * L * L / 4.0 - L * L * L / 6.0);
        const double c0 = (V - c1 * L * L / 2.0) / L;
        correction_[0] = c0;
        correction_[1] = c1;
        for (std::size_t k = 0; k < time_.size(); ++k) acceleration_[k] -= c0 + c1 * (time_[k] - time_.front());
        integrate(time_, acceleration_, velocity_, displacement_);
    }
}

std::size_t GroundShaking::segment(double t) const {
    const auto it = std::upper_bound(time_.begin(), time_.end(), t);
    return static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - time_.begin() - 1));
}

double GroundShaking::acceleration(double t) const {
    if (time_.size() < 2 || t < time_.front() || t > time_.back()) return 0.0;
    const std::size_t k = std::min(segment(t), time_.size() - 2);
    const double s = (t - time_[k]) / (time_[k + 1] - time_[k]);
    return acceleration_[k] + s * (acceleration_[k + 1] - acceleration_[k]);
}

double GroundShaking::velocity(double t) const {
    if (time_.size() < 2 || t <= time_.front()) return 0.0;
    if (t >= time_.back()) return velocity_.back();
    const std::size_t k = segment(t);
    const double h = t - time_[k], slope = (acceleration_[k + 1] - acceleration_[k]) / (time_[k + 1] - time_[k]);
    return velocity_[k] + h * acceleration_[k] + 0.5 * h * h * slope;
}

double GroundShaking::displacement(double t) const {
    if (time_.size() < 2 || t <= time_.front()) return 0.0;
    if (t >= time_.back()) return displacement_.back() + (t - time_.back()) * velocity_.back();
    const std::size_t k = segment(t);
    const double h = t - time_[k], slope = (acceleration_[k + 1] - acceleration_[k]) / (time_[k + 1] - time_[k]);
    return displacement_[k] + h * velocity_[k] + 0.5 * h * h * acceleration_[k] + h * h * h * slope / 6.0;
}

double GroundShaking::peak_acceleration() const {
    double peak = 0.0;
    for (double a : acceleration_) peak = std::max(peak, std::fabs(a));
    return peak;
}

}  // namespace mcdda
