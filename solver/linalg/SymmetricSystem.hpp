#pragma once
/// \file SymmetricSystem.hpp
/// The global system K d = F: a fixed sparsity pattern assembled by scattering small dense
/// blocks into precomputed slots (no sorting per step), factorised by CHOLMOD (Cholesky;
/// CHOLMOD picks the simplicial or the supernodal method from the factor's density). The
/// symbolic analysis is kept while the pattern is unchanged, the numeric factor for any number of
/// right-hand sides (the plastic iterations) and, on request, for later matrices close to its own
/// (solved by conjugate gradients preconditioned by it).
///
/// An unsymmetric matrix (the consistent tangent of non-associated Mohr–Coulomb flow) uses the
/// same pattern: in unsymmetric mode add() also keeps the upper triangle, and factorize() forms
/// the whole matrix and factorises it by LU (UMFPACK), keeping UMFPACK's symbolic analysis
/// while the pattern is unchanged.

#include "linalg/FreedMemoryReuse.hpp"
#include "linalg/LowRankCorrection.hpp"

#include <Eigen/Sparse>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace mcdda {

class CholmodFactor;
class LuFactor;

/// The matrix could not be factorised: it is not positive definite (a mechanism).
struct SingularSystem : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A set of equations coupled densely (an element's or a contact's degrees of freedom, at most
/// six nodes); entries are equation numbers, −1 for a fixed degree of freedom.
struct CouplingGroup {
    static constexpr int capacity = 12;
    int size = 0;
    int equation[capacity] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
};

class SymmetricSystem {
public:
    SymmetricSystem();
    ~SymmetricSystem();

    /// Sets the pattern from coupling groups (the lower triangle of their union) plus
    /// `pattern_only` couplings reserved for later groups. Group g's slots are then addressed by
    /// `g` in add(). Forces a new symbolic analysis.
    void set_pattern(int equations, const std::vector<CouplingGroup>& groups,
                     const std::vector<CouplingGroup>& pattern_only = {});

    /// Replaces the groups after the first `keep` (their slots) without touching the pattern,
    /// which must contain them: the symbolic analysis stays valid.
    void set_groups(const std::vector<CouplingGroup>& groups, int keep = 0);

    /// set_groups(groups, keep) when the pattern holds every coupling of the groups, and true;
    /// otherwise false, and nothing changed (set_pattern is then needed). One look-up per
    /// coupling either way.
    bool set_groups_if_in_pattern(const std::vector<CouplingGroup>& groups, int keep);

    int equations() const { return equations_; }
    int group_count() const { return static_cast<int>(group_slot_offset_.size()) - 1; }

    /// Zeroes the matrix values (the pattern stays).
    void clear_values();

    /// Unsymmetric mode for the matrix assembled next (set before clear_values and add): add()
    /// reads the whole block, factorize() uses LU. Off: the lower part is read, Cholesky.
    void set_unsymmetric(bool on) { unsymmetric_ = on; }
    bool unsymmetric() const { return unsymmetric_; }

    /// Adds the dense block `k` (size×size, column-major) of group `g`: its lower part when the
    /// system is symmetric, all of it in unsymmetric mode.
    void add(int g, const double* k);

    /// Saves and restores the matrix values (e.g. the element part kept across iterations).
    void save_values(std::vector<double>& out) const;
    void restore_values(const std::vector<double>& saved);

    /// Adds `value` on the diagonal of equation `e` (e ≥ 0).
    void add_diagonal(int e, double value);

    /// Factorises the current matrix; throws SingularSystem when it is not positive definite
    /// (unsymmetric mode: when LU finds it singular).
    ///
    /// With `may_reuse` the factor held (of an earlier matrix of the same kind: the elastic
    /// matrix on a slightly moved geometry, a few contacts changed; the tangent of an earlier
    /// Newton iterate) is kept while that pays: solve() then iterates against the current matrix
    /// — conjugate gradients preconditioned by the held factor — and the matrix is factorised
    /// once those iterations have cost as many flops as a factorisation (CHOLMOD's count), or
    /// when they do not converge; after such a misfit the next few matrices (3, then 15 and 63
    /// after misfits in a row) are factorised at once. Where the matrix differs from the held
    /// factor's in a few large entries (contacts that changed state) besides a small drift
    /// everywhere, the factor is first corrected for those (LowRankCorrection), at one solve per
    /// direction. A matrix equal, bit for bit, to the one
    /// the Cholesky factor held is of is solved directly with it, with or without `may_reuse`.
    void factorize(bool may_reuse = false);

    /// Solves with the current matrix: directly with its factor, or iterating with a held one
    /// (preconditioned by its copy in single precision, SinglePrecisionFactor) until the residual
    /// is within `tolerance` of the right-hand side. The default, `exact`, is
    /// far below any force tolerance of the equilibrium iterations, which check every solution
    /// against their own; an inexact Newton correction asks for much less. The matrix values must
    /// not change between factorize() and solve().
    static constexpr double exact = 1e-10;
    Eigen::VectorXd solve(const Eigen::VectorXd& rhs, double tolerance = exact);

    /// True when a factorisation succeeded since the pattern was last set: solve() may be used
    /// (set_groups and add do not change it).
    bool has_factor() const { return has_factor_; }

    int factorizations() const { return factorizations_; }
    int symbolic_analyses() const { return analyses_; }
    /// The fill-reducing ordering the last symbolic analysis of the Cholesky factor chose ("AMD"
    /// or "METIS"; empty before one), and the flops of one factorisation with it.
    const char* ordering() const;
    double factorization_flops() const;
    /// factorize(true) calls that kept the held factor, and the iterations their solves took.
    int reused_factors() const { return reused_factors_; }
    int refinement_iterations() const { return refinement_iterations_; }
    /// Seconds spent in numeric factorisations (also those a solve() falls back to).
    double factorization_seconds() const { return factorization_seconds_; }
    const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

private:
    /// First member, so the last destroyed: the factors' memory is free when it trims the heap.
    FreedMemoryReuse memory_reuse_;
    int equations_ = 0;
    Eigen::SparseMatrix<double> matrix_;   ///< lower triangle, CSC
    std::vector<int> group_size_;
    std::vector<int> group_slot_offset_{0};
    /// Per group: lower-triangle pairs (a ≥ b), −1 if fixed; else the value's position times two,
    /// plus one when equation a < equation b (the block's (a, b) entry is then above the diagonal).
    std::vector<int> slots_;
    std::vector<int> diagonal_slot_;
    std::vector<int> new_slots_;  ///< set_groups_if_in_pattern's slots before they are taken

    int slot_of(int i, int j) const;  ///< position of entry (i, j) in the values, or −1
    std::unique_ptr<CholmodFactor> factor_;
    bool analysed_ = false;
    bool has_factor_ = false;
    bool llt_valid_ = false;       ///< the Cholesky factor held is of some earlier matrix of this pattern
    bool stale_ = false;           ///< the factor is of an earlier matrix: solves iterate
    double refinement_flops_ = 0;  ///< spent iterating since the last factorisation
    int last_refinement_iterations_ = 0;  ///< of the last solve with the current (stale) matrix
    int factorizations_ = 0;
    int analyses_ = 0;
    int reused_factors_ = 0;
    int refinement_iterations_ = 0;
    int held_misfits_ = 0;     ///< held factors in a row whose iterations did not converge
    int held_skips_left_ = 0;  ///< matrices still to factorise at once after the last misfit
    double factorization_seconds_ = 0.0;
    std::uint64_t factored_digest_ = 0;  ///< values_digest() of the matrix the Cholesky factor is of
    std::vector<double> factored_values_;  ///< the values of that matrix
    /// The held factor corrected for the current matrix's few large changes (built by the first
    /// solve of a held matrix).
    LowRankCorrection correction_;
    bool correction_built_ = false;
    std::uint64_t values_digest() const;
    void factorize_now();

    bool unsymmetric_ = false;
    std::vector<double> upper_;  ///< unsymmetric mode: per lower slot (i > j), the entry (j, i)
    /// Unsymmetric mode: the whole matrix (CSC) and, per entry, its source: lower slot × 2, plus
    /// one for an entry above the diagonal (read from upper_). Built once per pattern.
    Eigen::SparseMatrix<double> full_;
    std::vector<int> full_source_;
    std::unique_ptr<LuFactor> lu_;
    bool lu_analysed_ = false;
    bool lu_current_ = false;  ///< the factor held is the LU one
    void factorize_lu();
};

}  // namespace mcdda
