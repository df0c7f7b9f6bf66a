#pragma once
/// \file Model.hpp
/// The in-memory description of an MC-DDA model: what the model file holds, after units and
/// signs are converted (see docs/model-format.md). Plain values only: no geometry library types,
/// so every layer (reader, GUI document, solver) can share it cheaply.
///
/// Conventions (one place for all of them):
///  - SI units: m, N, Pa, kg, s. Angles in radians.
///  - Stress: tension positive. The file's compressive magnitudes (in-situ stress, pressures)
///    are converted once, in the reader.
///  - Voigt order of plane stress components: (xx, yy, xy).

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mcdda {

/// A point in the model plane (m).
struct Point2 {
    double x = 0.0;
    double y = 0.0;
};

/// Distance from `p` to the segment [a, b] (m).
double distance_to_segment(Point2 p, Point2 a, Point2 b);

/// A closed ring of vertices; the closing edge (last → first) is implicit.
using Ring = std::vector<Point2>;

/// Rock or soil of a region: its elasticity and weight, and the constitutive law that says what
/// stress it can carry. The law's own numbers (c and φ for Mohr–Coulomb, σci and GSI for
/// Hoek–Brown) are kept by their keys in the model file; the law declares which they are, their
/// units, ranges and defaults (material/MaterialLaw.hpp), so this record does not change when a
/// law is added.
struct Material {
    std::string name;
    std::string law = "mohr-coulomb";  ///< key of its constitutive law (material/MaterialLaws.hpp)
    double young_modulus = 0.0;     ///< E (Pa), > 0
    double poisson_ratio = 0.0;     ///< ν, in (−1, 0.5)
    double density = 0.0;           ///< ρ (kg/m³); from unit weight as γ/g when given so
    /// ρsat (kg/m³) below the piezometric line (Water); 0: the density everywhere.
    double saturated_density = 0.0;
    /// The law's parameters by key, in the model's units (Pa, radians): for Mohr–Coulomb
    /// "cohesion", "friction_angle", "dilation_angle", "tensile_strength".
    std::map<std::string, double> parameters;
    bool reduce = true;             ///< strength reduction divides its strength (false: a footing, a lining)

    /// The parameter `key`, or `fallback` when the material does not give it.
    double parameter(const std::string& key, double fallback = 0.0) const;
    /// Whether its law can yield: every law but "elastic" (the law that never leaves the elastic range).
    bool may_yield() const { return law != "elastic"; }
    /// The density at a point below the piezometric line (`wet`) or above it.
    double density_at(bool wet) const { return wet && saturated_density > 0.0 ? saturated_density : density; }
};

/// Strength and stiffness of the contacts along a joint (or a region interface).
struct JointMaterial {
    std::string name;
    double friction_angle = 0.0;    ///< φj (rad)
    double cohesion = 0.0;          ///< cj (Pa), multiplied by the contact length
    double tensile_strength = 0.0;  ///< tj (Pa)
    double normal_stiffness = 0.0;  ///< kn (N/m per m thickness); 0 = analysis penalty
    double shear_stiffness = 0.0;   ///< ks (N/m); 0 = analysis penalty / 2.5 … set by solver
    bool reduce = true;             ///< strength reduction divides its strength
};

/// A region of one material: an outer ring with optional holes (openings).
struct Region {
    std::string name;
    int material = -1;  ///< index into Model::materials
    Ring boundary;
    std::vector<Ring> holes;
    /// Element size inside the region (m), uniform: the model's size field (global size, local
    /// refinements) does not reach into it; 0 = the model's size field.
    double mesh_size = 0.0;
};

/// A joint trace: a straight segment or a polyline that cuts regions into blocks.
struct Joint {
    std::string name;
    std::vector<Point2> points;  ///< ≥ 2 vertices
    int joint_material = -1;     ///< index into Model::joint_materials; −1 = the default
    int joint_set = -1;          ///< index of the joint set that generated it, −1 = explicit
};

/// A family of parallel joints. Fully persistent (persistence 1) each trace is one joint;
/// otherwise each trace is cut into joint segments of `trace_length` separated by rock bridges,
/// repeating with period trace_length / persistence along the trace (UDEC's jset trace/gap).
struct JointSet {
    std::string name;
    double angle = 0.0;      ///< trace direction, counter-clockwise from +x (rad)
    double spacing = 0.0;    ///< normal distance between traces (m), > 0
    Point2 origin;           ///< one trace passes through this point; its segment pattern starts here
    std::optional<std::array<double, 4>> extent;  ///< xmin, ymin, xmax, ymax; default: model box
    int joint_material = -1;
    double persistence = 1.0;   ///< fraction of each trace that is joint, in (0, 1]
    double trace_length = 0.0;  ///< length of one joint segment (m); > 0 when persistence < 1
    double stagger = 0.5;       ///< shift of the pattern from one trace to the next, fraction of the period, [0, 1)
};

/// What one joint set may generate: the validator refuses more, the expander skips such a set.
/// Short segments cost the block cutter far less than traces across the model, hence the two limits.
constexpr long max_joint_set_traces = 5000;
constexpr long max_joint_set_segments = 50000;

/// A table of (abscissa, factor) pairs, linearly interpolated; abscissa is the step number or
/// the time. Beyond the last point the factor is either held or extrapolated linearly.
struct LoadTable {
    enum class Variable { Step, Time };
    std::string name;
    Variable variable = Variable::Step;
    std::vector<std::array<double, 2>> points;  ///< strictly increasing abscissa
    bool extrapolate = false;                   ///< false: hold the last value

    /// Factor at step number or time `s`.
    double factor(double s) const;
};

/// A displacement constraint on the mesh node nearest to a point (both directions fixed).
struct FixedPoint {
    std::string name;
    Point2 point;
};

/// A roller: every boundary node on the segment [from, to] has the chosen directions fixed.
struct Roller {
    std::string name;
    Point2 from, to;
    bool fix_x = false;
    bool fix_y = false;
    /// Prescribed displacement of the fixed directions (m), times the table's factor: the
    /// support moves (displacement control, e.g. a footing pushed down). Zero: a fixed support.
    Point2 displacement{0.0, 0.0};
    int table = -1;  ///< index into Model::load_tables; −1 = constant factor 1
    bool moves() const { return displacement.x != 0.0 || displacement.y != 0.0; }
};

/// A point load (N per m thickness) applied at the node nearest to `point`.
struct PointLoad {
    std::string name;
    Point2 point;
    Point2 force;        ///< reference force vector (N/m), multiplied by the table factor
    int table = -1;      ///< index into Model::load_tables; −1 = constant factor 1
};

/// A normal pressure on the block boundary lying along [from, to].
struct EdgePressure {
    std::string name;
    Point2 from, to;
    double pressure = 0.0;  ///< reference magnitude (Pa); positive pushes into the material
    int table = -1;
};

/// Initial (in-situ) stress. Stored tension positive.
struct InitialStress {
    enum class Kind { None, Uniform, Gravity };
    Kind kind = Kind::None;
    std::array<double, 3> stress{0.0, 0.0, 0.0};  ///< Uniform: (σxx, σyy, τxy), tension positive
    std::optional<double> stress_zz;  ///< Uniform: σzz, tension positive; default ν(σxx + σyy)
    double surface_y = 0.0;  ///< Gravity: ground surface elevation (m)
    double k0 = 1.0;         ///< Gravity: σh/σv
};

/// Ground water as RS2's piezometric line: below the line the pore pressure at a point is γw
/// times the height of the line above it (hydrostatic along verticals), above it zero. Beyond its
/// end points the line continues horizontally. Pore pressure is positive in compression (the
/// water pushes); the blocks' stresses are effective, σ′ = σ + u·m with σ, σ′ tension positive
/// (docs/model-format.md, "Water").
struct Water {
    std::vector<Point2> piezometric_line;  ///< x strictly increasing; empty: dry
    double unit_weight = 9810.0;           ///< γw (N/m³), > 0

    bool present() const { return piezometric_line.size() >= 2; }
    /// Height of the line at abscissa x (m).
    double level(double x) const;
    /// Pore pressure at `p` (Pa, compression positive); 0 above the line or without water.
    double pore_pressure(Point2 p) const;
};

/// An earthquake acceleration record (one component): a two-column CSV file, a PEER NGA `.AT2`
/// file or points given in the model. The reader loads a file's points (ModelReader.hpp); the
/// writer writes the file's name back, not its points.
struct GroundMotion {
    enum class Units { G, MetresPerSecondSquared };
    std::string name;
    std::string file;  ///< as given in the model (relative to the model file's folder); empty: `points`
    /// (time s, acceleration in `units`) before scaling: the file's or the model's points.
    std::vector<std::array<double, 2>> points;
    Units units = Units::G;
    double scale = 1.0;  ///< factor on the accelerations (a record scaled to a design peak)
    /// A linear correction of the acceleration, a0 + a1·t, chosen so that the base ends at rest
    /// where it began: the integrated record does not drift (docs/model-format.md, "Earthquakes").
    bool baseline_correction = true;
};

/// How an earthquake enters the model.
/// Rigid: the supports move together with the record (a rigid base, a shaking table). The
/// analysis runs relative to them: every block feels the inertial body force −m·a(t) and the
/// displacements are those relative to the base, which is the permanent displacement engineers ask for.
/// Compliant: the boundary [from, to] is not supported but carries Lysmer–Kuhlemeyer dashpots
/// and the input stress 2ρVs·v(t) (horizontal) and 2ρVp·v(t) (vertical), with v the record's
/// velocity: the upward-travelling wave enters and the waves the model sends down leave.
struct BaseMotion {
    enum class Kind { None, Rigid, Compliant };
    Kind kind = Kind::None;
    int x = -1, y = -1;  ///< indices into Model::ground_motions (−1: no motion in that direction)
    Point2 from, to;     ///< compliant base: the boundary segment
    bool present() const { return kind != Kind::None; }
};

/// Viscous (Lysmer–Kuhlemeyer) dashpots on the model boundary along [from, to]: normal ρVp,
/// shear ρVs of the material beside each edge, so that waves leave instead of reflecting.
struct AbsorbingBoundary {
    std::string name;
    Point2 from, to;
};

/// A pseudo-static earthquake load: every block carries kh·g horizontally (+x for kh > 0) and
/// kv·g vertically (+y for kv > 0) per unit mass, with g the magnitude of gravity.
struct SeismicCoefficient {
    double kh = 0.0, kv = 0.0;
    bool present() const { return kh != 0.0 || kv != 0.0; }
};

/// A named point whose displacement history is recorded.
struct MeasurementPoint {
    std::string name;
    Point2 point;
};

/// Local mesh refinement near a point (from == to) or a segment.
struct LocalSize {
    Point2 from, to;
    double size = 0.0;    ///< target element edge length at the feature (m)
    double radius = 0.0;  ///< distance within which `size` applies (m)
};

/// Finite element of the block interiors.
enum class ElementType {
    Automatic,  ///< six-node where any material may yield, three-node otherwise
    T3,         ///< three-node constant-strain triangle
    T6,         ///< six-node linear-strain triangle (straight edges)
};

struct MeshControls {
    ElementType element = ElementType::Automatic;
    double size = 0.0;              ///< global target edge length (m); 0 = 1/20 of the model
    double min_angle = 25.0 * 3.14159265358979323846 / 180.0;  ///< (rad)
    double grading = 0.3;           ///< growth of the size with distance beyond a local radius
    std::vector<LocalSize> local;
    long max_elements = 500000;     ///< refuse to mesh beyond this estimate
};

struct AnalysisSettings {
    enum class Kind { Static, Dynamic };
    Kind kind = Kind::Static;
    int steps = 100;
    double time_step = 0.01;              ///< initial/maximum Δt (s)
    double max_displacement_ratio = 0.005;///< Shi's g2: max step displacement / model size
    double penalty = 0.0;                 ///< contact spring (N/m); 0 = automatic (from E)
    double dynamic_ratio = 1.0;           ///< velocity carried into the next step (dynamic)
    int max_open_close_iterations = 10;
    int max_plastic_iterations = 200;     ///< equilibrium iterations of one load increment
    double plastic_tolerance = 1e-4;      ///< out-of-balance force relative to the force scale
    /// Static analysis: a load increment that does not converge is halved down to this fraction
    /// of one step; failing there is a collapse between the last load carried and this one.
    double min_load_fraction = 1.0 / 64.0;
    /// Updated: element strains and loads on the shape at the start of each step (DDA, large
    /// displacements and rotations). Initial: on the undeformed shape, the geometrically linear
    /// (small-strain) theory of the closed-form plasticity solutions. Contacts always follow the
    /// deformed shape.
    enum class Geometry { Updated, Initial };
    Geometry geometry = Geometry::Updated;
    int output_every = 10;                ///< save every n-th step (the last always saved)
    /// A run (or its last stage) whose unbalanced-force ratio — the largest out-of-balance nodal
    /// force over the largest applied force, UDEC's `solve ratio` — ends above this is reported
    /// as not in equilibrium.
    double equilibrium_ratio = 1e-2;
    bool plasticity = true;               ///< false: every material stays elastic
    /// Strength reduction ("type": "strength_reduction"): a static, small-strain analysis
    /// repeated with c, tan φ and the tensile strengths divided by trial factors F; the largest F
    /// at which the model still stands is its factor of safety (run/StrengthReduction.hpp).
    bool strength_reduction = false;
    /// The search stops once the bracket [stands, does not stand] is narrower than this fraction
    /// of the factor.
    double factor_tolerance = 0.005;
    int max_trials = 40;                  ///< trials the search may take
    /// How a strength reduction treats reduced materials with non-associated flow (ψ < φ).
    /// Davis: each trial's reduced c and φ are lowered further by Davis's factor
    /// β = cos ψ cos φ / (1 − sin ψ sin φ) (of the reduced φ and ψ) and solved with associated
    /// flow (Davis 1968; Tschuchnigg et al., Géotechnique 2015): a factor that converges with
    /// the mesh and does not depend on the iteration. Direct: ψ as given, the factor of the
    /// non-associated law itself, which has no unique limit load and may depend on the mesh and
    /// the iteration where much of the ground yields (docs/plasticity.md).
    enum class NonAssociatedFlow { Davis, Direct };
    NonAssociatedFlow non_associated_flow = NonAssociatedFlow::Davis;
    /// Newmark's γ of the dynamic analysis (β = (γ + ½)²/4): 0.7 damps the highest frequencies
    /// (run/Newmark.hpp), ½ is the average acceleration rule with no numerical damping.
    double newmark_gamma = 0.7;
    /// Rayleigh damping C = αM + βK: `damping_ratio` of critical at `damping_frequency` (Hz),
    /// there its least (α = ξω, β = ξ/ω), or between it and `damping_frequency_2` (the ratio
    /// at both). 0: none.
    double damping_ratio = 0.0;
    double damping_frequency = 1.0;
    double damping_frequency_2 = 0.0;
};

/// "davis" or "direct": `non_associated_flow` in the model file.
const char* non_associated_flow_name(AnalysisSettings::NonAssociatedFlow f);

/// "static", "dynamic" or "strength_reduction": the analysis "type" in the model file.
const char* analysis_type_name(const AnalysisSettings& a);

/// A rock bolt or cable (Shi's bolt, UDEC's cable): an axial spring between two points, each
/// anchored in the element it lies in (moving with that element's corner nodes).
struct Bolt {
    std::string name;
    Point2 from, to;
    double stiffness = 0.0;   ///< axial stiffness EA per metre of model thickness (N/m), > 0; the
                              ///< spring is EA/L with L the bolt's length
    double strength = 0.0;    ///< tensile force at which it breaks (N/m); 0 = unbreakable
    double pretension = 0.0;  ///< axial force when installed (N/m), ≥ 0, pulls the ends together
};

/// One construction stage (RS2's stage, PLAXIS's phase). Stages run in order; each continues
/// from the state the previous one left. Names refer to regions, supports, loads and bolts of
/// the model: an item named in some stage's `install` list is absent before that stage, one
/// named in a `remove` list absent from that stage on; a region named in `activate` is absent
/// before that stage, one named in `excavate` from it on.
struct Stage {
    std::string name;
    std::vector<int> excavate;   ///< regions removed at the start of the stage
    std::vector<int> activate;   ///< regions added (backfill, liners)
    /// Region materials changed at the start of the stage: (region, material) indices.
    std::vector<std::array<int, 2>> materials;
    std::vector<std::string> install;  ///< supports, loads and bolts added, by name
    std::vector<std::string> remove;   ///< and removed
    AnalysisSettings analysis;         ///< the stage's settings (the model's, with overrides)
    /// Release of the forces that removed material (or any other change of the stage) leaves out
    /// of balance: fraction released after stage step s. Linear over `release_steps` steps
    /// (0 = all the stage's steps) unless `release_table` (abscissa: step within the stage) is set.
    int release_steps = 0;
    int release_table = -1;
    /// Static stages: the stage ends early once the unbalanced-force ratio falls below this
    /// (0 = run all its steps).
    double target_ratio = 0.0;
    /// Displacements are reported from this stage's start (RS2's and PLAXIS's reset): the
    /// settlement of switching gravity on no longer shows in later stages' pictures.
    bool reset_displacements = false;
    /// Ground water from this stage on (drawdown, dewatering, a rising reservoir); none: as the
    /// stage before (the model's `water` for the first). An empty line makes the ground dry.
    std::optional<Water> water;
    /// Pseudo-static earthquake load from this stage on; none: as the stage before.
    std::optional<SeismicCoefficient> seismic_coefficient;

    /// Fraction of the stage's out-of-balance force released after `s` (fractional) stage steps.
    double released(double s, const std::vector<LoadTable>& tables) const;
};

/// The whole model.
struct Model {
    std::string name;
    std::string description;
    std::vector<Material> materials;
    std::vector<JointMaterial> joint_materials;
    int default_joint_material = -1;  ///< used for region interfaces and unassigned joints
    std::vector<Region> regions;
    std::vector<Joint> joints;        ///< explicit joints and those expanded from joint sets
    std::vector<JointSet> joint_sets;
    std::vector<LoadTable> load_tables;
    std::vector<FixedPoint> fixed_points;
    std::vector<Roller> rollers;
    std::vector<PointLoad> point_loads;
    std::vector<EdgePressure> edge_pressures;
    Point2 gravity{0.0, 0.0};         ///< acceleration (m/s²)
    /// Gravity times this load table's factor (a ramp over the first steps); -1: gravity acts in full.
    int gravity_table = -1;
    InitialStress initial_stress;
    Water water;                      ///< ground water before any stage changes it
    std::vector<GroundMotion> ground_motions;
    /// The earthquake of the dynamic stages: its record time 0 is the start of the first dynamic
    /// stage (of the run without stages).
    BaseMotion base_motion;
    std::vector<AbsorbingBoundary> absorbing_boundaries;
    SeismicCoefficient seismic_coefficient;  ///< before any stage changes it
    std::vector<MeasurementPoint> measurement_points;
    MeshControls mesh;
    AnalysisSettings analysis;
    std::vector<Bolt> bolts;
    /// Construction stages (format version 2); empty: one stage with everything present from
    /// the start and the model's analysis settings (version 1 behaviour).
    std::vector<Stage> stages;

    /// Axis-aligned box of all region boundaries: xmin, ymin, xmax, ymax.
    std::array<double, 4> bounds() const;

    /// The element the analysis uses: `mesh.element`, with Automatic resolved to T6 when
    /// plasticity is on and some material may yield (T3 locks under plastic flow), T3 otherwise.
    ElementType element() const;
};

/// The ground water while stage `stage` runs: the last water given by it or an earlier stage, else
/// the model's (`stage` < 0: the model's).
const Water& water_of_stage(const Model& model, int stage);

/// Whether the model has ground water in any stage (results then carry pore pressures).
bool has_water(const Model& model);

/// Speeds of shear and pressure waves in a material (m/s; plane strain, its E, ν and density).
double shear_wave_speed(const Material& m);
double pressure_wave_speed(const Material& m);

/// Whether the analysis of stage `stage` (the model's without stages) is dynamic, and whether
/// any is.
bool stage_is_dynamic(const Model& model, int stage);
bool has_dynamic_stage(const Model& model);

/// The pseudo-static load while stage `stage` runs (as water_of_stage).
const SeismicCoefficient& seismic_of_stage(const Model& model, int stage);

/// JSON pointer of a joint: "/joints/i" for explicit joints, "/joint_sets/k" for generated ones.
std::string joint_path(const Model& model, int joint);

/// The regions absent while stage `stage` runs, after its own excavations and activations: those
/// excavated by it or an earlier stage and not activated again since, and those a later stage
/// activates. `stage` < 0: the model before the first stage (only the later-activated ones).
std::vector<int> regions_absent(const Model& model, int stage);

/// The supports, loads and bolts (by name) absent while stage `stage` runs, in the same sense:
/// removed by it or an earlier stage and not installed again since, or installed only later.
std::vector<std::string> items_absent(const Model& model, int stage);

}  // namespace mcdda
