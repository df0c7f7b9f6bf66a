#pragma once
/// \file GroundShaking.hpp
/// One component of an earthquake record as the analysis uses it: accelerations in m/s² (units
/// and scale applied), baseline-corrected when asked, and its velocity and displacement, each
/// the exact integral of the piecewise-linear acceleration.

#include "model/Model.hpp"

#include <vector>

namespace mcdda {

class GroundShaking {
public:
    GroundShaking() = default;
    /// `g` must hold at least two points with increasing times (ModelValidator checks it).
    explicit GroundShaking(const GroundMotion& g);

    /// At record time t (s): zero before the first point and after the last one, when the
    /// base rests (baseline-corrected) or moves on at its last velocity (not corrected).
    double acceleration(double t) const;
    double velocity(double t) const;
    double displacement(double t) const;

    /// From the first sample to the last (s).
    double duration() const { return time_.empty() ? 0.0 : time_.back() - time_.front(); }
    double peak_acceleration() const;
    /// The linear correction a0 + a1·(t − t0) taken off the record (m/s², m/s³).
    double correction_constant() const { return correction_[0]; }
    double correction_slope() const { return correction_[1]; }

private:
    /// The segment t lies in (time_[k] ≤ t < time_[k + 1]).
    std::size_t segment(double t) const;
    std::vector<double> time_, acceleration_, velocity_, displacement_;
    double correction_[2] = {0.0, 0.0};
};

}  // namespace mcdda
