#pragma once
/// \file Simulation.hpp
/// The MC-DDA time-stepping driver. One call of advance() is one accepted step, following the
/// paper's Table 1:
///   1. contact detection (candidates carried over with their states)
///   2. open–close loop, warm-started from the last increments:
///        equilibrium iterations (equilibrate): stresses of every integration point by the
///          return mapping, out-of-balance force R = F − ∫Bᵀσ − contacts − inertia, and a
///          correction K δ = R: Newton with the algorithmic tangent for associated flow
///          (refactorised only while convergence is slow), the elastic matrix with Anderson
///          acceleration for non-associated flow, finished by Newton with the exact unsymmetric
///          tangent (LU) where that stalls, until R and δ are within tolerance
///        check every contact; stop when no state changed
///      In a small-strain static analysis the factor of the last converged increment starts the
///      next one when the closed contacts are the same: it is that increment's tangent (a far
///      better first correction than the elastic matrix) or, for the elastic matrix, exact.
///   3. commit: coordinates += d, stresses as returned, velocities, contact springs.
/// A static step whose equilibrium iterations fail is retried with a smaller load increment
/// (bisection to analysis.min_load_fraction of a step); failing there is a collapse between the
/// last load carried and the first not carried. In a small-strain static analysis Δt is never
/// cut for plasticity: inertia (M/βΔt²) must not carry load there. Static DDA (deformed
/// geometry) cuts Δt where a wrong contact guess sets a block loose, and every static DDA step
/// ends by relaxing to equilibrium at its loads (StaticStep.cpp). Dynamic steps cut Δt (Shi).
/// The parts live in their own files: StaticStep, DynamicStep, OpenCloseIteration (one try),
/// EquilibriumIterations (and ConvergenceMonitor), StageSetup; this file sets a run up, commits
/// steps and measures the out-of-balance force.

#include "Preprocess.hpp"
#include "contact/Contact.hpp"
#include "contact/ContactLaw.hpp"
#include "contact/ContactSet.hpp"
#include "fem/BoltLink.hpp"
#include "fem/BoundaryConditions.hpp"
#include "fem/MeshTopology.hpp"
#include "fem/PlaneStrain.hpp"
#include "fem/ViscousBoundary.hpp"
#include "linalg/SymmetricSystem.hpp"
#include "fem/ElementAssembly.hpp"
#include "linalg/AndersonMixing.hpp"
#include "run/ConvergenceMonitor.hpp"
#include "run/GroundShaking.hpp"
#include "run/Newmark.hpp"

#include <Eigen/Dense>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mcdda {

/// Seconds spent in each part of the computation, summed over all steps.
struct RunTimings {
    /// `plasticity`: stress updates (return mapping) and internal forces of every iteration.
    double assembly = 0.0, factorization = 0.0, solve = 0.0, contact = 0.0, plasticity = 0.0, total = 0.0;
    int factorizations = 0;
    int symbolic_analyses = 0;
    int reused_factors = 0;         ///< elastic matrices solved with a held factor instead
    int refinement_iterations = 0;  ///< the conjugate-gradient iterations those solves took
    int iterations = 0;        ///< equilibrium iterations of all accepted steps
    int max_iterations = 0;    ///< the most in one accepted step
    int load_cuts = 0;         ///< load increments halved (static)
    int steps_at_rest = 0;     ///< static steps in equilibrium at unchanged loads: nothing solved
    std::string ordering;             ///< of the Cholesky factor (SymmetricSystem::ordering)
    double factorization_flops = 0.0;  ///< of one Cholesky factorisation with it
};

/// The evolving state of a run: coordinates, displacements, velocities, stresses, contacts.
struct SimulationState {
    int step = 0;            ///< accepted steps so far
    double time = 0.0;       ///< s
    double time_step = 0.0;  ///< Δt to try next (s)
    std::vector<Point2> nodes;          ///< current coordinates (m)
    Eigen::VectorXd displacement;       ///< total since the start (m), 2 per node
    /// The displacement at the last reset (a stage with reset_displacements, a safety stage):
    /// results report displacement − displacement_reference. Empty: none.
    Eigen::VectorXd displacement_reference;
    /// The displacement results report: since the last reset.
    Eigen::VectorXd reported_displacement() const {
        return displacement_reference.size() == displacement.size() ? Eigen::VectorXd(displacement - displacement_reference)
                                                                     : displacement;
    }
    Eigen::VectorXd velocity;           ///< (m/s), 2 per node
    Eigen::VectorXd acceleration;       ///< (m/s²), 2 per node (dynamic analysis)
    /// Static analysis: the part of the next step's load increment already applied, in [0, 1).
    double step_fraction = 0.0;
    /// Per element, for output (averages of the element's integration points; the plastic state
    /// is the highest of them):
    std::vector<Eigen::Vector3d> stress;  ///< (σxx, σyy, τxy), Pa, tension positive
    std::vector<double> stress_zz;        ///< σzz (plane strain), Pa
    std::vector<double> plastic_strain;   ///< accumulated equivalent plastic strain
    /// 0 never yielded, 1 yielded in an earlier step but elastic now, 2 yielding now.
    std::vector<unsigned char> plastic_state;
    PointStates points;                   ///< the same at every integration point
    std::vector<Contact> contacts;
    /// Per Model::rollers entry: the force (N/m) the support exerts on the model, x and y.
    std::vector<Point2> roller_reactions;
    /// Per Model::bolts entry: axial force (N/m, tension positive; 0 before it is installed or
    /// once broken) and whether it broke.
    std::vector<double> bolt_force;
    std::vector<char> bolt_broken;
    /// Out-of-balance force after the last step, of the block where it is largest: the sum over
    /// the block's nodes of the out-of-balance nodal forces (free directions) over the sum of
    /// its nodal forces in play (the applied loads, or the internal forces of the stresses
    /// where larger). Sums, not largest values: a largest nodal force shrinks with the element
    /// size, so the same state read differently on a finer mesh. The inertia of a static DDA
    /// increment does not count as balancing.
    double unbalanced_ratio = 0.0;
    int stage = 0;  ///< construction stage of the last step (index into Model::stages)
};

/// The equilibrium iterations of a step did not converge even for the smallest load increment:
/// the model cannot carry the load. The state stays at the last load carried.
struct PlasticCollapse : std::runtime_error {
    PlasticCollapse(const std::string& what, double carried_at, double failed_at, Eigen::VectorXd failed_motion = {})
        : std::runtime_error(what), carried(carried_at), not_carried(failed_at), motion(std::move(failed_motion)) {}
    double carried = 0.0;      ///< load position (steps, fractional) of the last state carried
    double not_carried = 0.0;  ///< the smallest position tried beyond it that could not be carried
    /// Where the last try that failed went from the state carried (2 per node), where that is
    /// the motion of a mechanism (Simulation::mechanism_motion); empty otherwise.
    Eigen::VectorXd motion;
};

/// A stop was requested (Ctrl-C, a batch system's SIGTERM, Cancel) while a step was being solved:
/// the step is abandoned and the state stays that of the last load increment accepted.
struct StepInterrupted : std::runtime_error {
    StepInterrupted() : std::runtime_error("stopped during the step") {}
};

/// What one accepted step did.
struct StepReport {
    int step = 0;
    double time = 0.0, time_step = 0.0;
    int open_close_iterations = 0;
    int time_step_cuts = 0;
    int open = 0, sliding = 0, locked = 0;
    int plastic_iterations = 0;  ///< equilibrium iterations, summed over open–close iterations and load increments
    int load_increments = 1;     ///< increments the step's load was applied in (static)
    int relaxation_increments = 0;  ///< increments at the step's loads that settled it (static, see relax)
    int yielding = 0;            ///< elements yielding in this step
    double max_increment = 0.0;  ///< largest nodal displacement increment (m)
    double unbalanced_ratio = 0.0;  ///< see SimulationState::unbalanced_ratio
    int stage = 0;
    std::vector<std::string> events;  ///< things a user must hear of: a stage begun, a bolt broken
};

/// Where a step stands while it iterates: what a long step shows instead of silence.
struct IterationInfo {
    int step = 0;                 ///< the step being computed (accepted steps + 1)
    int iteration = 0;            ///< equilibrium iterations of this step so far (all tries)
    double out_of_balance = 0.0;  ///< largest out-of-balance nodal force over the force scale
    double tolerance = 0.0;       ///< what out_of_balance must fall below
    int yielding = 0;             ///< integration points yielding at this iteration
    double load_fraction = 1.0;   ///< end of the load increment tried, as a fraction of the step
};

/// How each construction stage went (a model without stages has one).
struct StageRecord {
    std::string name;
    int planned_steps = 0;
    int first_step = 0, last_step = 0;  ///< global steps it ran, (first_step, last_step]
    bool started = false, finished = false;
    bool reached_target = false;        ///< ended early on its target ratio
    double unbalanced_ratio = 0.0;      ///< after its last step
};

/// What a run needs to go back to a state: the strength reduction search starts every trial of a
/// safety stage from the state the stages before it left (Simulation::checkpoint).
struct SimulationCheckpoint {
    SimulationState state;
    Model model;
    std::vector<char> element_active, block_active, bolt_present;
    std::vector<int> triangle_material;
    std::vector<StageRecord> stages;
    int stage = 0, stage_start_step = 0;
};

class Simulation {
public:
    /// Sets up a run of a preprocessed (meshed) model. Throws std::runtime_error naming the
    /// problem when the model cannot be solved (supports that catch no node, …).
    /// `strength_factor`: the factor a strength reduction analysis (or safety stage) divides
    /// the strengths by (see set_strength_factor).
    explicit Simulation(const Preprocessed& model, double strength_factor = 1.0);
    Simulation(const Simulation&) = delete;  // elements_ points into model_ and mesh_
    Simulation& operator=(const Simulation&) = delete;

    /// Advances one accepted step. Throws PlasticCollapse when the plastic iterations do not
    /// converge, std::runtime_error when the step cannot be completed otherwise (Δt cut below its
    /// floor, a singular matrix, a diverging solution); the state then stays that of the last
    /// accepted step.
    StepReport advance();

    /// Called at every equilibrium iteration, on the thread that runs advance(): a progress
    /// report inside long steps (keep it cheap; throttle in the observer).
    void set_iteration_observer(std::function<void(const IterationInfo&)> observer) {
        iteration_observer_ = std::move(observer);
    }
    /// Asked at every equilibrium iteration; when it answers true, advance() throws
    /// StepInterrupted, so that a stop does not wait for a long step to end.
    void set_stop_check(std::function<bool()> stop) { stop_check_ = std::move(stop); }

    /// The state at this moment, and a return to it (the next advance() then begins the stage
    /// after the checkpoint's, with the strength factor in force then).
    SimulationCheckpoint checkpoint() const;
    void restore(const SimulationCheckpoint& c);
    /// The factor a strength reduction stage divides the strengths by (1 until set).
    void set_strength_factor(double factor) { strength_factor_ = factor; }
    /// Index of the stage running now (0 without stages).
    int current_stage() const { return stage_; }

    /// True once the last stage has run its steps (or reached its target ratio).
    bool finished() const;
    /// True when the current stage has run its steps: the next advance() begins the next one.
    bool stage_complete() const;
    /// The steps all stages plan (a stage may end early on its target ratio).
    int planned_steps() const;
    const std::vector<StageRecord>& stages() const { return stages_; }
    /// The analysis settings of the current stage (the model's without stages).
    const AnalysisSettings& analysis() const { return model_.analysis; }
    /// The largest displacement increment a step may take (m): `max_displacement_ratio` of the
    /// model's size.
    double displacement_limit() const { return displacement_limit_; }
    /// Largest nodal displacement of increments d (2 per node).
    static double largest_increment(const Eigen::VectorXd& d);
    /// The model as given (model() is the current stage's view of it: absent supports and loads
    /// cleared, the stage's materials and settings).
    const Model& full_model() const { return base_model_; }
    /// Elements present in the current stage (empty: all).
    const std::vector<char>& active_elements() const { return element_active_; }

    /// Where bolt `i`'s anchors are now.
    std::array<Point2, 2> bolt_ends(int i) const;

    const SimulationState& state() const { return state_; }
    const RunTimings& timings() const { return timings_; }
    const Model& model() const { return model_; }
    const Mesh& mesh() const { return mesh_; }
    const MeshTopology& topology() const { return topology_; }
    const BoundaryConditions& boundary_conditions() const { return bc_; }
    double penalty() const { return penalty_; }

    /// Pore pressure of each element now (Pa, compression positive; fem/PorePressure.hpp): the
    /// current stage's water, weighing with gravity's load factor.
    std::vector<double> pore_pressures() const;

    /// The earthquake's base motion at analysis time `time` (m/s², m/s, m; x and y): the
    /// record's, from the start of the first dynamic stage; zero without a base motion.
    struct BaseState {
        Eigen::Vector2d acceleration = Eigen::Vector2d::Zero(), velocity = Eigen::Vector2d::Zero(),
                        displacement = Eigen::Vector2d::Zero();
    };
    BaseState base_state(double time) const;
    /// A rigid base: the analysis runs relative to it (displacements and velocities relative,
    /// accelerations absolute once the base's is added).
    bool relative_to_base() const { return base_model_.base_motion.kind == BaseMotion::Kind::Rigid; }
    const ViscousBoundary& dashpots() const { return dashpots_; }
    /// Displacements since the first dynamic stage began, relative to the base (zero before).
    Eigen::VectorXd displacement_since_shaking() const;

    /// Current magnitude of each point load and edge pressure, in model order.
    std::vector<std::pair<std::string, double>> load_magnitudes() const;
    /// The same at a load position (steps, fractional) of a static analysis.
    std::vector<std::pair<std::string, double>> load_magnitudes_at(double position) const;

    /// After advance() threw PlasticCollapse: the load positions (steps) of the bracket
    /// [last carried, first not carried]; empty otherwise.
    struct CollapseBracket {
        double carried = 0.0, not_carried = 0.0;
        Eigen::VectorXd motion;  ///< PlasticCollapse::motion
    };
    const std::optional<CollapseBracket>& collapse() const { return collapse_; }

private:
    /// How one try of a load increment ended.
    enum class Outcome { Converged, NotConverged, Unsettled, Singular };
    struct Attempt {
        Outcome outcome = Outcome::Converged;
        Eigen::VectorXd d;
        int open_close_iterations = 0;
        int iterations = 0;  ///< equilibrium iterations
        int yielding = 0;
        /// Largest displacement the try's converged solves reached: what a smaller Δt is to
        /// reduce where contacts do not settle (Simulation::time_step_futile).
        double motion = 0.0;
        std::string why;     ///< for failures
        /// Failed: its iterate flowed past the mechanism limit with material yielding
        /// (ConvergenceMonitor's mechanism rule).
        bool mechanism = false;
        /// In: equilibrate may return once the force balances, before the displacement settles,
        /// when the contact states would then change (the open–close loop goes on from there).
        bool may_stop_unsettled = false;
        /// In: with may_stop_unsettled, equilibrate may also return so when the friction forces
        /// of sliding contacts would then change by more than ContactSet::friction_agreement of
        /// them (a friction round goes on from there).
        bool may_stop_for_friction = false;
        /// Out: equilibrate returned at a balanced iterate before it settled.
        bool stopped_unsettled = false;
        /// In: a round that moves a node far beyond a step's reach ends the try unsettled
        /// (open_close): where a smaller Δt has been shown not to help.
        bool ends_beyond_reach = false;
        Eigen::VectorXd residual;  ///< out-of-balance force at d (converged: the support reactions, negated)
        std::vector<Contact> contacts;  ///< with the states the try ended with
        std::vector<BoltLink> bolts;  ///< the bolts that held (those that broke in the try left out)
    };

    // Setting up (Simulation.cpp).
    void locate_supports();
    /// Penalty, displacement limit and whether anything may yield, from the materials in use.
    void set_material_scales(const std::vector<int>& materials);
    void initial_state();
    void anchor_bolts();

    // A construction stage (StageSetup.cpp).
    /// Sets up stage `s`: presence of regions, supports, loads and bolts, materials, settings,
    /// and the out-of-balance force its start leaves, which it releases over its steps.
    void begin_stage(int s);
    struct StageRegions {
        std::vector<char> present;  ///< per region
        std::vector<int> material;  ///< per region
    };
    StageRegions stage_regions(int s) const;
    void set_stage_model(int s, const std::vector<int>& material);
    void activate_stage_elements(const StageRegions& regions);
    void locate_stage_supports(const Stage& stage);
    void set_stage_bolts(int s);
    /// Removes the contacts of blocks absent in this stage (excavated, not yet built).
    void drop_absent(std::vector<Contact>& contacts) const;
    /// Applied forces at a load position: the loads plus the part of the stage's start
    /// out-of-balance force not yet released.
    Eigen::VectorXd applied_forces(double position, double time) const;

    // Earthquakes (Earthquake.cpp).
    /// The base motion's records, once.
    void set_up_shaking();
    /// The dashpots of the stage beginning (none in a static stage); the forces its start leaves
    /// at their nodes (the reactions of supports they replace) stay for good.
    void set_stage_dashpots();
    /// The earthquake's loads at analysis time `time`: −M·a of a rigid base.
    void add_base_loads(double time, Eigen::VectorXd& f) const;
    /// Newmark's end-of-step velocity for a dynamic try of Δt (rate·d + rest), Rayleigh damping
    /// into the elements, the incident wave of a compliant base.
    void prepare_damping(double dt);
    double record_time(double time) const { return shaking_start_ < 0.0 ? -1.0 : time - shaking_start_; }

    // Steps (StaticStep.cpp, DynamicStep.cpp).
    StepReport advance_static();
    StepReport advance_dynamic();
    /// Contacts for the step from the deformed shape, the last step's carried over (`predicted`:
    /// the displacement expected over the step, dynamic).
    std::vector<Contact> detect_step_contacts(const Eigen::VectorXd& predicted);
    /// The last contact detection's inputs and what it found: a try after a cut Δt or a smaller
    /// load increment, and the relaxation's tries, start from the state the last one did.
    struct DetectionMemo {
        std::vector<Point2> nodes;
        std::vector<Contact> previous;
        Eigen::VectorXd predicted;
        double search_distance = -1.0;
        double tolerance = -1.0;
        std::vector<Contact> found;
    };
    DetectionMemo detection_;
    /// The factor Δt is cut by after a try that failed (`singular_factor` for a singular matrix)
    /// or moved too far.
    double time_step_cut(const Attempt& attempt, double largest, double singular_factor) const;
    /// What a static step does after a try.
    enum class StaticResponse { Accept, SmallerLoad, Collapse, SmallerTimeStep };
    StaticResponse judge_static(const Attempt& attempt, double increment, double dt, double largest) const;
    /// The load stepping within one static step.
    struct LoadSteps {
        double increment = 1.0;    ///< of the step's load, this try
        double failed_end = -1.0;  ///< load position where the last try failed (negative: none)
        int time_step_cuts = 0;
        /// Motion of the try whose contacts did not settle and that cut Δt last, at this load
        /// increment (0: none, or another failure since).
        double cut_motion = 0.0;
        /// A Δt cut at this step left the motion as it was: failures are load questions for the
        /// rest of the step.
        bool time_step_futile = false;
    };
    /// Whether a smaller Δt is no answer to the `attempt` whose contacts did not settle: the Δt
    /// cut after such a try before it did not make it move less. Records the motion in `steps`.
    static bool time_step_futile(const Attempt& attempt, LoadSteps& steps);
    /// `load_question`: a smaller Δt has been shown not to help in this step (LoadSteps).
    Attempt try_static_increment(double increment, bool load_question);
    void cut_static_time_step(const Attempt& attempt, double largest, StepReport& report, LoadSteps& steps);
    /// Commits an increment; true when it completed the step.
    bool accept_static(const Attempt& attempt, double largest, double dt, StepReport& report, LoadSteps& steps);
    /// Static DDA (deformed geometry): settles the state at the step's loads (see StaticStep.cpp).
    void relax(StepReport& report);
    /// The next static step's loads are those of the state reached and it is in equilibrium
    /// under them, so the step has nothing to do (see StaticStep.cpp): the state's
    /// unbalanced-force ratio then, nothing otherwise.
    std::optional<double> at_rest_under_unchanged_loads();
    /// Completes such a step without a try; `ratio`: the state's unbalanced-force ratio.
    StepReport hold_static_step(double ratio);
    /// The motion of a try that failed, where it is a mechanism's (PlasticCollapse::motion;
    /// see StaticStep.cpp); empty otherwise.
    static Eigen::VectorXd mechanism_motion(const Attempt& attempt);
    /// On the updated shape (`"geometry": "updated"`): the first active element that the
    /// increments d turn inside out, or −1.
    int inverted_element(const Eigen::VectorXd& d) const;

    // One try of a load increment (OpenCloseIteration.cpp).
    /// Solves the increments of one try: loads `external`; a static increment applies only the
    /// share `lambda` of the out-of-balance force found at its start (`start_external` there).
    /// `ends_beyond_reach`: Attempt::ends_beyond_reach.
    Attempt solve_increments(const Eigen::VectorXd& external, const Eigen::VectorXd* start_external, double lambda,
                             double dt, std::vector<Contact> contacts, const Eigen::VectorXd& prescribed,
                             bool ends_beyond_reach = false);
    /// Bolts, matrix pattern and element matrices for the try; the loads with inertia.
    Eigen::VectorXd prepare_try(const Eigen::VectorXd& external, double dt, Attempt& attempt);
    ContactSet contact_set(std::vector<Contact> contacts);
    bool held_factor_usable(const ContactSet& contacts, const std::vector<BoltLink>& bolts) const;
    /// The open–close loop: equilibrium iterations, bolts that break, contact states, friction.
    void open_close(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const Eigen::VectorXd& shift, ContactSet& contacts,
                    Attempt& attempt);
    /// equilibrate, with a singular matrix turned into the try's outcome.
    bool equilibrate_or_fail(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                             bool& factor_valid, Attempt& attempt);
    /// Bolts pulled beyond their strength break (true: some did; attempt.bolts without them).
    bool break_overloaded_bolts(const Eigen::VectorXd& d, Attempt& attempt);
    /// Whether an open–close round with `changes` contact changes ends its try as not settling;
    /// keeps the fewest changes of the try's rounds after the first.
    bool gives_up_unsettled(int changes, std::size_t contacts, int round, int& fewest_changes) const;
    /// The end of a try whose contacts settled.
    void settle_try(const ContactSet::Update& update, bool equilibrium_only, Attempt& attempt);

    // The equilibrium iterations (EquilibriumIterations.cpp).
    /// The out-of-balance force at increments d: loads − ∫Bᵀσ − contact forces − bolt forces,
    /// with the stresses returned into `returned`; element matrices of `matrix` into the system
    /// on the way. The one place this balance is written.
    Eigen::VectorXd residual(const Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                             const std::vector<BoltLink>& bolts, std::vector<ReturnResult>& returned,
                             ElementMatrix matrix, ElementAssembly::Evaluation* evaluation = nullptr,
                             Eigen::VectorXd* internal_forces = nullptr);
    /// The equilibrium iterations of a pure equilibrium problem (is_equilibrium_only) measure
    /// forces as stresses: each nodal force over the length it acts over
    /// (ElementAssembly::dof_length), against the largest stress in play. Their last iterate is
    /// the answer, and nodal forces shrink with the element size: against the largest nodal
    /// force, an imbalance at a wall meshed 60 times finer than the far field was allowed 60
    /// times more in stress (docs/running.md). A static DDA step (deformed geometry, a mass
    /// term) keeps nodal forces: its relaxation judges equilibrium block by block
    /// (unbalanced_ratio), and the stricter measure drove a wedge held by inertia to Δt's floor
    /// (docs/benchmarks.md, "The out-of-balance force as a stress").
    bool out_of_balance_as_stress() const { return is_equilibrium_only(); }
    /// Component dof of a force vector as the iterations measure it (out_of_balance_as_stress).
    double measured(const Eigen::VectorXd& force, Eigen::Index dof) const {
        if (!out_of_balance_as_stress()) return force[dof];
        const double length = elements_.dof_length()[dof];
        return length > 0.0 ? force[dof] / length : 0.0;
    }
    /// Norms of an out-of-balance force R over the free directions, as measured().
    struct ResidualNorms {
        double norm = 0.0, norm2 = 0.0;  ///< largest |R| and Σ R²
    };
    ResidualNorms residual_norms(const Eigen::VectorXd& r) const;
    /// The largest load, as measured().
    double load_scale(const Eigen::VectorXd& loads) const;
    /// The residual of an iteration with its reduced right-hand side and norms.
    struct Balance : ResidualNorms {
        Eigen::VectorXd residual, rhs;
        ElementAssembly::Evaluation evaluation;
    };
    Balance balance_at(const Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                       const std::vector<BoltLink>& bolts, ElementMatrix matrix);
    Balance balance_of(Eigen::VectorXd residual, const ElementAssembly::Evaluation& evaluation);
    /// An iteration's numbers for the ConvergenceMonitor; with `flow_counts` its flow (the
    /// increment's largest displacement) counts as progress (Iteration::flow).
    ConvergenceMonitor::Iteration iteration_of(int k, const Balance& b, const Eigen::VectorXd& d, double load_scale,
                                               double last_correction, bool newton, bool plain,
                                               bool flow_counts) const;
    /// Equilibrium iterations for fixed contact states (see the file comment); true when
    /// converged, d updated in place.
    bool equilibrate(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                     const std::vector<BoltLink>& bolts, bool& factor_valid, Attempt& attempt);
    /// Contacts and bolts into the matrix and the factorisation; false for a tangent that is not
    /// positive definite.
    bool factorize(ElementMatrix matrix, const ContactSet& contacts, const std::vector<BoltLink>& bolts);
    /// The correction of an iteration: K⁻¹R, Anderson-mixed for the elastic iteration.
    Eigen::VectorXd correction(const Eigen::VectorXd& d, const Balance& b, bool newton, double force_tolerance,
                               bool any_closed, AndersonMixing& anderson);
    /// The share of a Newton correction to take, and whether it lowered the sum of squares of the
    /// out-of-balance force (backtracking: whether any share tried did; else the smallest share
    /// is returned untested).
    struct LineSearch {
        double step = 1.0;
        bool lowered = true;
        bool minimised_energy = false;  ///< the energy line search chose the share
        /// The balance at the share taken when the search evaluated it there: the next iteration
        /// starts from it unless it needs a new matrix (one return mapping of every point saved).
        std::optional<Balance> balance;
    };
    /// What the line search asks of a share of the correction (see line_search).
    enum class Merit { LargestForce, SumOfSquares, Energy };
    LineSearch line_search(const Eigen::VectorXd& d, const Eigen::VectorXd& delta, const Eigen::VectorXd& loads,
                           const ContactSet& contacts, const std::vector<BoltLink>& bolts, const Balance& at,
                           double tolerance, double scale, Merit merit);
    /// The energy line search (see line_search); nothing when δ does not descend the energy.
    std::optional<LineSearch> energy_line_search(const Eigen::VectorXd& d, const Eigen::VectorXd& delta,
                                                 const Eigen::VectorXd& loads, const ContactSet& contacts,
                                                 const std::vector<BoltLink>& bolts, const Balance& at,
                                                 double tolerance, double scale);
    void observe_iteration(double out_of_balance, double tolerance, int yielding);
    /// K⁻¹rhs, full size; an iterative solve with a held factor stops at `tolerance` (relative).
    Eigen::VectorXd solve_reduced(const Eigen::VectorXd& rhs, double tolerance);

    // Loads, supports, matrices, commits (Simulation.cpp).
    /// Increments of the degrees of freedom held by moving rollers that take them to their
    /// prescribed displacement at load position `position` (zero elsewhere).
    Eigen::VectorXd prescribed_increments(double position, double time) const;
    /// Sums the support reactions of every roller from the out-of-balance force of a converged try.
    void record_reactions(const Eigen::VectorXd& residual);
    void rebuild_pattern_if_needed(const std::vector<Contact>& contacts, const std::vector<BoltLink>& bolts);
    CouplingGroup coupling(std::initializer_list<int> nodes) const;  ///< equations of up to 6 nodes
    CouplingGroup element_coupling(int e) const;
    void commit(const Eigen::VectorXd& d, double dt, const std::vector<Contact>& contacts,
                const std::vector<BoltLink>& bolts);
    /// Contact geometry at the start of the step (analysis.geometry).
    ContactKinematics kinematics_of(const Contact& c) const;
    /// The coordinates element strains and loads are taken on (analysis.geometry).
    const std::vector<Point2>& element_nodes() const {
        return model_.analysis.geometry == AnalysisSettings::Geometry::Initial ? mesh_.nodes : state_.nodes;
    }
    /// A small-strain static analysis: a pure equilibrium problem, no mass term, Δt plays no part.
    bool is_equilibrium_only() const {
        return model_.analysis.kind == AnalysisSettings::Kind::Static &&
               model_.analysis.geometry == AnalysisSettings::Geometry::Initial;
    }
    /// Newton's line search minimises the potential energy along the correction (see
    /// line_search and the .cpp).
    bool minimises_energy(const ContactSet& contacts, bool polishing) const;
    /// Raises the elastic matrix's share in the symmetric tangent after a tangent that was not
    /// positive definite; false when it is already at its largest.
    bool stiffen_tangent();
    /// Plasticity somewhere: Newton with the algorithmic tangent (see equilibrate).
    bool uses_newton() const { return may_yield_ && elements_.has_tangent() && elements_.symmetric_tangent(); }
    /// Non-associated plasticity somewhere: the elastic iteration, finished by Newton with the
    /// unsymmetric tangent when it stalls (see equilibrate).
    bool uses_unsymmetric_newton() const {
        return may_yield_ && elements_.has_tangent() && !elements_.symmetric_tangent();
    }
    /// The forces of the committed state (no increments, no inertia): adds nothing to any state.
    struct ForceBalance {
        Eigen::VectorXd applied, internal;  ///< loads (with the part held by a stage), ∫Bᵀσ
        Eigen::VectorXd residual;           ///< applied − internal − contact − bolt forces
    };
    ForceBalance out_of_balance();
    /// The committed state's SimulationState::unbalanced_ratio (of `residual` when given: a
    /// converged try's).
    double unbalanced_ratio(const Eigen::VectorXd* residual = nullptr);
    /// Bolts present, linearised on the step's start geometry.
    std::vector<BoltLink> bolt_links() const;
    /// Completes the report of an accepted step; `residual`: the out-of-balance force of its
    /// last converged try; `ratio`: the state's unbalanced-force ratio when known already.
    void finish_report(StepReport& report, double largest, const Eigen::VectorXd& residual,
                       std::optional<double> ratio = std::nullopt);

    Model model_;
    Mesh mesh_;
    MeshTopology topology_;
    BoundaryConditions bc_;
    double penalty_ = 0.0;                     ///< contact spring (N/m)
    double displacement_limit_ = 0.0;          ///< largest increment per step (m)
    double contact_tolerance_ = 0.0;           ///< slip (m) above which a new contact starts sliding
    SimulationState state_;
    SymmetricSystem system_;
    ElementAssembly elements_;
    bool may_yield_ = false;                   ///< some material may yield in this analysis
    std::vector<ReturnResult> returned_;       ///< per integration point, for the last increments solved
    RunTimings timings_;
    std::string last_singular_;  ///< why the last try's matrix could not be factorised
    /// What the factor held by system_ was computed from, for the next increment (see the file
    /// comment): with the same closed contacts; a tangent only after a converged try.
    struct HeldFactor {
        bool usable = false;   ///< the last try converged
        bool tangent = false;  ///< the algorithmic tangent, not the elastic matrix
        std::vector<long long> closed;  ///< per closed contact: node, edge and state, packed
    };
    HeldFactor held_;
    /// The contraction of plain elastic corrections measured so far in this step (0: none):
    /// ConvergenceMonitor::set_step_contraction.
    double step_contraction_ = 0.0;
    /// What the matrix depends on besides the elements: closed contacts and bolts holding.
    std::vector<long long> closed_signature(const std::vector<Contact>& contacts, const std::vector<BoltLink>& bolts) const;
    void record_solver_counts();  ///< the system's factorisation counts and time into timings_
    std::optional<CollapseBracket> collapse_;

    Model base_model_;                  ///< as given; model_ is the current stage's view
    std::vector<int> block_region_;     ///< region of each block
    std::vector<char> element_active_;  ///< per element in this stage (empty: all)
    std::vector<char> block_active_;    ///< per block in this stage (empty: all)
    std::vector<char> bolt_present_;    ///< per Model::bolts entry in this stage
    std::vector<std::optional<BoltAnchor>> bolt_anchors_[2];  ///< per bolt: from, to (undeformed mesh)
    std::vector<char> bolt_broken_try_; ///< bolts broken by the try in progress
    Eigen::VectorXd holding_;           ///< out-of-balance force at the stage's start, negated
    std::vector<char> held_for_good_;   ///< per dof: holding_ there is not released (see set_stage_dashpots)
    GroundShaking shaking_[2];          ///< the base motion's x and y records
    bool shaken_[2] = {false, false};
    double shaking_start_ = -1.0;       ///< analysis time of record time 0 (−1: not yet)
    Eigen::VectorXd shaking_start_displacement_;  ///< the displacements then
    ViscousBoundary dashpots_;
    bool viscous_try_ = false;          ///< a dynamic try in progress: the dashpots act
    bool relaxing_ = false;             ///< a relaxation increment in progress (StaticStep.cpp, relax)
    double velocity_rate_ = 0.0;        ///< see prepare_damping
    Eigen::VectorXd velocity_rest_;
    Eigen::Vector2d incident_ = Eigen::Vector2d::Zero();
    int stage_ = 0;
    int stage_start_step_ = 0;
    double strength_factor_ = 1.0;      ///< see set_strength_factor
    bool pattern_stale_ = false;        ///< the equation numbering changed (a stage began)
    std::vector<StageRecord> stages_;
    std::vector<std::string> pending_events_;
    std::function<void(const IterationInfo&)> iteration_observer_;
    std::function<bool()> stop_check_;
    IterationInfo iterating_;  ///< the step in progress, for the observer
};

/// Initial stress of every integration point from the model's in-situ stress (tension positive).
void initial_stresses(const Model& model, const Mesh& mesh, const ElementAssembly& elements, PointStates& points);
/// Element values for output: the mean of the element's points, the highest plastic state.
void element_averages(const PointStates& points, int per_element, SimulationState& state);

}  // namespace mcdda
