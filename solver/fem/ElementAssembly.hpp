#pragma once
/// \file ElementAssembly.hpp
/// The block interiors as one piece: for displacement increments d of a step, the stress at
/// every integration point (elastic trial σ0 + D·B·d, returned onto the yield surface by the
/// material), the internal forces ∫Bᵀσ + M d/(βΔt²), and, when asked, the element matrices
/// (the algorithmic tangent or the elastic stiffness, plus inertia) scattered into the global
/// system. Works on three- and six-node triangles alike (TriangleElement.hpp).

#include "fem/TriangleElement.hpp"
#include "linalg/SymmetricSystem.hpp"
#include "material/ConstitutiveLaw.hpp"
#include "mesh/Mesh.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

/// Stress and plastic history at every integration point (point q of element e is
/// e·points_per_element + q). Stress tension positive (Pa).
struct PointStates {
    std::vector<Eigen::Vector3d> stress;  ///< σxx, σyy, τxy
    std::vector<double> stress_zz;
    std::vector<double> plastic_strain;   ///< accumulated equivalent plastic strain
    /// 0 never yielded, 1 yielded in an earlier step but elastic now, 2 yielding now.
    std::vector<unsigned char> plastic_state;

    void resize(std::size_t n);
};

/// Which element matrices evaluate() assembles.
enum class ElementMatrix {
    None,     ///< forces only
    Elastic,  ///< ∫BᵀDB: the initial-stress (modified Newton) iteration
    Tangent,  ///< ∫BᵀCB with C the algorithmic tangent of the return mapping (unsymmetric for ψ < φ)
};

class ElementAssembly {
public:
    ElementAssembly() = default;
    ElementAssembly(const Model& model, const Mesh& mesh);

    int nodes_per_element() const { return quadratic_ ? 6 : 3; }
    int points_per_element() const { return quadratic_ ? Triangle6::points : Triangle3::points; }
    int element_count() const { return static_cast<int>(mesh_->triangles.size()); }
    /// The nodes of element e: corners, then (six-node) the midside nodes of edges 01, 12, 20.
    int node(int e, int a) const { return a < 3 ? mesh_->triangles[e][a] : mesh_->midside[e][a - 3]; }
    /// Position of integration point q of element e on coordinates `nodes`.
    Point2 point_position(const std::vector<Point2>& nodes, int e, int q) const;

    /// Element geometry on the start-of-step coordinates, the inertia coefficient 1/(βΔt²)
    /// (0: none) for this try of the step.
    void prepare(const std::vector<Point2>& nodes, double inertia);

    /// Rayleigh damping C = αM + βK (K elastic) for this try, after prepare(): the forces
    /// C·(rate·d + v_rest) — the end-of-step velocity of Newmark — and the matrix rate·C.
    void set_damping(double alpha, double beta, double rate, Eigen::VectorXd v_rest);

    /// Adds −M·a to `force` for every node moving with acceleration a (the inertial load of a
    /// model analysed relative to a shaken rigid base); coordinates `nodes`.
    void add_rigid_body_inertia(const std::vector<Point2>& nodes, const Eigen::Vector2d& a, Eigen::VectorXd& force) const;

    /// Inertia forces M·(v/(βΔt) + (½ − β)/β·a) of a dynamic step (constant over the step).
    void add_inertia_load(const Eigen::VectorXd& velocity, const Eigen::VectorXd& acceleration, double beta,
                          double dt, Eigen::VectorXd& force) const;

    /// Elements present in the model (construction stages remove and add them): an absent one
    /// has no stiffness, mass or internal force and keeps its stress. Empty: all present.
    void set_active(std::vector<char> active) { active_ = std::move(active); }
    bool active(int e) const { return active_.empty() || active_[e]; }

    /// Some material may yield: ElementMatrix::Tangent differs from the elastic matrix there.
    bool has_tangent() const { return has_tangent_; }
    /// Every material that may yield has a symmetric tangent (associated flow): the tangent
    /// matrix is symmetric; otherwise it is not (SymmetricSystem's unsymmetric mode).
    bool symmetric_tangent() const { return symmetric_tangent_; }

    /// The symmetric tangent of a yielding point is taken as (1 − share)·C + share·D (0: the
    /// consistent tangent C itself): a tangent that is not positive definite made so.
    void set_elastic_share(double share) { elastic_share_ = share; }
    double elastic_share() const { return elastic_share_; }

    struct Evaluation {
        int yielding = 0;          ///< integration points on the yield surface
        double force_scale = 0.0;  ///< largest Σ|element force| at a degree of freedom (N/m)
        /// Largest Σ|element force| / dof_length() at a degree of freedom: the stress in play
        /// (Pa), the same on a fine mesh as on a coarse one.
        double stress_scale = 0.0;
    };

    /// Per degree of freedom, the length its nodal forces act over: √(its node's share of the
    /// area of the elements around it), on the mesh's own coordinates. A nodal force divided by
    /// it is a stress, so an out-of-balance force measured that way means the same at a fine
    /// tunnel wall as in coarse far-field elements (nodal forces shrink with the element size).
    const Eigen::VectorXd& dof_length() const { return dof_length_; }

    /// Stresses of `old` advanced by increments d into `returned` (one result per point),
    /// internal forces into `internal` (resized, zeroed); element matrices into `system`
    /// (group e for element e) unless `matrix` is None. Runs on the worker threads
    /// (parallel/ParallelFor.hpp); one object evaluates one call at a time (its chunk buffers).
    Evaluation evaluate(const Eigen::VectorXd& d, const PointStates& old, std::vector<ReturnResult>& returned,
                        Eigen::VectorXd& internal, ElementMatrix matrix, SymmetricSystem* system) const;

private:
    /// One element's forces (and matrix, when `k` is not null); its points' results into
    /// `returned`. Returns the number of its points yielding. Safe to call for different
    /// elements at once.
    template <int N>
    int evaluate_element(int e, const Eigen::VectorXd& d, const PointStates& old, std::vector<ReturnResult>& returned,
                         ElementMatrix matrix, typename TriangleElement<N>::Forces& f,
                         typename TriangleElement<N>::Stiffness* k) const;
    template <int N>
    Evaluation evaluate_elements(const Eigen::VectorXd& d, const PointStates& old, std::vector<ReturnResult>& returned,
                                 Eigen::VectorXd& internal, ElementMatrix matrix, SymmetricSystem* system) const;
    template <int N>
    void prepare_elements(const std::vector<Point2>& nodes);

    const Model* model_ = nullptr;
    const Mesh* mesh_ = nullptr;
    bool quadratic_ = false;
    std::vector<std::unique_ptr<ConstitutiveLaw>> laws_;  ///< per material
    bool has_tangent_ = false;                 ///< see has_tangent()
    bool symmetric_tangent_ = true;            ///< see symmetric_tangent()
    double elastic_share_ = 0.0;                           ///< see set_elastic_share()
    std::vector<Triangle3::Geometry> linear_;  ///< per element, three-node meshes
    std::vector<Triangle6::Geometry> quadratic_geometry_;  ///< per element, six-node meshes
    /// Per-element results of one chunk of evaluate(), kept between calls: the plastic
    /// iterations evaluate hundreds of times, and a chunk of six-node matrices takes 9 MB.
    template <int N>
    struct ChunkBuffers {
        std::vector<typename TriangleElement<N>::Forces> forces;
        std::vector<typename TriangleElement<N>::Stiffness> stiffness;
        std::vector<int> yielding;
    };
    mutable ChunkBuffers<3> linear_buffers_;
    mutable ChunkBuffers<6> quadratic_buffers_;
    double inertia_ = 0.0;
    double damping_mass_ = 0.0, damping_stiffness_ = 0.0, damping_rate_ = 0.0;  ///< see set_damping
    Eigen::VectorXd damping_rest_;
    std::vector<char> active_;  ///< see set_active()
    Eigen::VectorXd dof_length_;  ///< see dof_length()
};

}  // namespace mcdda
