#pragma once
/// \file AndersonMixing.hpp
/// Anderson acceleration of a fixed-point iteration x ← x + f(x) (Walker & Ni, SIAM J. Numer.
/// Anal. 49, 2011, "type II"): the next correction combines the last few iterates and corrections
/// so that the mixed correction is as small as possible in the least-squares sense. It needs no
/// symmetry, so it accelerates the initial-stress iteration of non-associated plasticity.

#include <Eigen/Dense>

#include <deque>

namespace mcdda {

class AndersonMixing {
public:
    explicit AndersonMixing(int depth) : depth_(depth) {}

    /// Forgets the history (the iteration matrix or the problem changed).
    void reset() {
        dx_.clear();
        df_.clear();
        has_last_ = false;
    }

    /// Whether the last correction went through next() (since the last reset).
    bool mixing() const { return has_last_; }

    /// Given the iterate x and its plain correction f, the accelerated correction.
    Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
        if (has_last_) {
            dx_.push_back(x - last_x_);
            df_.push_back(f - last_f_);
            if (static_cast<int>(dx_.size()) > depth_) {
                dx_.pop_front();
                df_.pop_front();
            }
        }
        last_x_ = x;
        last_f_ = f;
        has_last_ = true;
        const int m = static_cast<int>(df_.size());
        if (m == 0) return f;
        Eigen::MatrixXd F(f.size(), m);
        for (int j = 0; j < m; ++j) F.col(j) = df_[j];
        // γ = argmin ‖f − F γ‖, by QR (column-pivoted: nearly dependent columns are common).
        const Eigen::VectorXd gamma = F.colPivHouseholderQr().solve(f);
        Eigen::VectorXd mixed = f;
        for (int j = 0; j < m; ++j) mixed -= gamma[j] * (dx_[j] + df_[j]);
        return mixed;
    }

private:
    int depth_;
    std::deque<Eigen::VectorXd> dx_, df_;
    Eigen::VectorXd last_x_, last_f_;
    bool has_last_ = false;
};

}  // namespace mcdda
