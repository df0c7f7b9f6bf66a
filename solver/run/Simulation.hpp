#pragma once
/// \file Simulation.hpp
/// The MC-DDA time-stepping driver. One call of advance() is one accepted time step, following
/// the paper's Table 1:
///   1. contact detection (candidates carried over with their states)
///   2. open–close loop:
///        assemble K = Σ elastic + M/(βΔt²) + contact springs; F = loads − ∫Bᵀσ0 + inertia + contacts
///        factorise K (CHOLMOD)
///        solve; plastic loop: return mapping of every element, the difference between trial and
///          returned stress as a body load, re-solve with the same factor, until the increments
///          settle (or report collapse)
///        check the displacement limit (cut Δt and repeat the step if exceeded)
///        check every contact; stop when no state changed
///   3. commit: coordinates += d, stresses += D·B·d, velocities, contact springs.

#include "Preprocess.hpp"
#include "contact/Contact.hpp"
#include "fem/BoundaryConditions.hpp"
#include "fem/MeshTopology.hpp"
#include "fem/PlaneStrain.hpp"
#include "linalg/SymmetricSystem.hpp"
#include "material/MohrCoulomb.hpp"

#include <Eigen/Dense>

#include <stdexcept>
#include <string>
#include <vector>

namespace mcdda {

/// Seconds spent in each part of the computation, summed over all steps.
struct RunTimings {
    double assembly = 0.0, factorization = 0.0, solve = 0.0, contact = 0.0, plasticity = 0.0, total = 0.0;
    int factorizations = 0;
    int symbolic_analyses = 0;
};

/// The evolving state of a run: coordinates, displacements, velocities, stresses, contacts.
struct SimulationState {
    int step = 0;            ///< accepted steps so far
    double time = 0.0;       ///< s
    double time_step = 0.0;  ///< Δt to try next (s)
    std::vector<Point2> nodes;          ///< current coordinates (m)
    Eigen::VectorXd displacement;       ///< total since the start (m), 2 per node
    Eigen::VectorXd velocity;           ///< (m/s), 2 per node
    Eigen::VectorXd acceleration;       ///< (m/s²), 2 per node (dynamic analysis)
    std::vector<Eigen::Vector3d> stress;  ///< per element (σxx, σyy, τxy), Pa, tension positive
    std::vector<double> stress_zz;        ///< per element σzz (plane strain), Pa
    std::vector<double> plastic_strain;   ///< per element accumulated equivalent plastic strain
    /// Per element: 0 never yielded, 1 yielded in an earlier step but elastic now, 2 yielding now.
    std::vector<unsigned char> plastic_state;
    std::vector<Contact> contacts;
};

/// The plastic iterations of a step did not converge: the model collapsed (static analysis) or
/// the load exceeds what it can carry.
struct PlasticCollapse : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// What one accepted step did.
struct StepReport {
    int step = 0;
    double time = 0.0, time_step = 0.0;
    int open_close_iterations = 0;
    int time_step_cuts = 0;
    int open = 0, sliding = 0, locked = 0;
    int plastic_iterations = 0;  ///< summed over the open–close iterations of the step
    int yielding = 0;            ///< elements yielding in this step
    double max_increment = 0.0;  ///< largest nodal displacement increment (m)
};

class Simulation {
public:
    /// Sets up a run of a preprocessed (meshed) model. Throws std::runtime_error naming the
    /// problem when the model cannot be solved (supports that catch no node, …).
    explicit Simulation(const Preprocessed& model);

    /// Advances one accepted step. Throws PlasticCollapse when the plastic iterations do not
    /// converge, std::runtime_error when the step cannot be completed otherwise (Δt cut below its
    /// floor, a singular matrix, a diverging solution); the state then stays that of the last
    /// accepted step.
    StepReport advance();

    const SimulationState& state() const { return state_; }
    const RunTimings& timings() const { return timings_; }
    const Model& model() const { return model_; }
    const Mesh& mesh() const { return mesh_; }
    const MeshTopology& topology() const { return topology_; }
    const BoundaryConditions& boundary_conditions() const { return bc_; }
    double penalty() const { return penalty_; }

    /// Current magnitude of each point load and edge pressure, in model order.
    std::vector<std::pair<std::string, double>> load_magnitudes() const;

private:
    Eigen::VectorXd solve_increments(const Eigen::VectorXd& external, double dt, std::vector<Contact>& contacts,
                                     int& iterations);
    Eigen::VectorXd solve_reduced(const Eigen::VectorXd& rhs);  ///< back-substitution, full-size result
    /// Elastic trial stresses of every element for increments `d`, returned onto the yield surface
    /// where plastic (into returned_); adds Σ A Bᵀ(σtrial − σ) to `plastic_load`. Returns the
    /// number of yielding elements.
    int update_stresses(const Eigen::VectorXd& d, Eigen::VectorXd* plastic_load);
    void rebuild_pattern_if_needed(const std::vector<Contact>& contacts);
    CouplingGroup coupling(std::initializer_list<int> nodes) const;  ///< equations of up to 3 nodes
    void commit(const Eigen::VectorXd& d, double dt, const std::vector<Contact>& contacts);

    Model model_;
    Mesh mesh_;
    MeshTopology topology_;
    BoundaryConditions bc_;
    std::vector<Eigen::Matrix3d> elasticity_;  ///< per material
    double penalty_ = 0.0;                     ///< contact spring (N/m)
    double displacement_limit_ = 0.0;          ///< largest increment per step (m)
    double contact_tolerance_ = 0.0;           ///< slip (m) above which a new contact starts sliding
    SimulationState state_;
    SymmetricSystem system_;
    std::vector<double> element_values_;       ///< matrix values of elements and inertia, per step
    std::vector<TriangleShape> shapes_;        ///< element shapes on the start-of-step geometry
    std::vector<MohrCoulomb> yield_criteria_;  ///< per material
    std::vector<char> plastic_material_;       ///< per material: may yield in this analysis
    std::vector<ReturnResult> returned_;       ///< per element, for the last increments solved
    int plastic_iterations_ = 0;               ///< of the current step  ///< the contact groups the pattern was built for
    RunTimings timings_;
    std::string last_singular_;  ///< why the last try's matrix could not be factorised
};

/// Initial stress of every element from the model's in-situ stress (tension positive).
void initial_stresses(const Model& model, const Mesh& mesh, std::vector<Eigen::Vector3d>& stress,
                      std::vector<double>& stress_zz);

}  // namespace mcdda
