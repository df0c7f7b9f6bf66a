#pragma once
/// \file ResultScene.hpp
/// Pictures of a run's result: the mesh of one result .vtu (as written by `mcdda run`) or of a
/// snapshot in memory, coloured by one field, with block boundaries, joints and a colour legend.
/// Both go through the same grid and colouring code. VTK stays out of this header.

#include "Preprocess.hpp"
#include "view/ResultSnapshot.hpp"
#include "view/ResultProbe.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

class vtkRenderer;

namespace mcdda::view {

/// The sign of the stresses shown. The files keep the mechanics convention (tension positive);
/// rock and soil engineers read compression positive, with σ1 the major compressive stress.
enum class StressSign { TensionPositive, CompressionPositive };

/// Units the picture shows stresses and displacements in (legend, probe, query lines).
enum class StressUnit { Automatic, KPa, MPa };  ///< Automatic: MPa from 1 MPa on, else kPa
enum class LengthUnit { Metre, Millimetre };

/// Colour maps of the scalar bar.
enum class ColourMap { Rainbow, Viridis, Grey, Diverging };

/// What the result picture shows.
struct ResultOptions {
    /// One of result_field_names(): plastic_state (three categories), plastic_strain,
    /// displacement (magnitude of the point data), ux, uy (m), stress_xx, stress_yy, stress_xy,
    /// stress_1, stress_3 (in-plane principal stresses; stresses are shown in kPa, or in MPa when
    /// they reach 1 MPa, with the unit and the sign convention in the scalar bar's title).
    std::string field = "plastic_state";
    /// TensionPositive: stress_1 ≥ stress_3, the larger tension-positive principal stress.
    /// CompressionPositive: every stress negated and stress_1 the major compressive principal
    /// stress (σ1 ≥ σ3 in compression), as RS2, PLAXIS and UDEC show them.
    StressSign stress_sign = StressSign::TensionPositive;
    StressUnit stress_unit = StressUnit::Automatic;
    LengthUnit length_unit = LengthUnit::Metre;  ///< of displacements
    double deform = 0.0;      ///< points drawn at x + deform · displacement; 0 = undeformed
    /// Draw deformed with the factor that makes the largest displacement 5 % of the model's
    /// larger side (`deform` is then ignored; ResultInfo says the factor used).
    bool deform_auto = false;
    /// The colour scale's ends; NaN = the field's range, widened to round numbers.
    double range_min = std::numeric_limits<double>::quiet_NaN();
    double range_max = std::numeric_limits<double>::quiet_NaN();
    /// Number of colour bands (discrete contours); 0 = a smooth scale.
    int bands = 0;
    ColourMap colour_map = ColourMap::Rainbow;
    /// Coordinate axes on the left and bottom edges and a scale bar.
    bool show_axes = true;
    /// The line over the picture; empty = the field with the step, stage and time when known.
    std::string title;
    bool show_joints = true;  ///< joint traces of the model (only drawn undeformed)
    /// The piezometric line in force in the step's stage, blue with its ▽ symbol (runs with
    /// ground water).
    bool show_water = true;
    /// A step's contacts file of `mcdda run` (<model>_contacts_NNNNNN.vtp): its contact forces
    /// are drawn as lines from each closed contact's vertex along the force on it, the largest
    /// 6 % of the model's size long (UDEC's `plot cforce`); joint slip as lines along the joint
    /// and opening as lines across it, centred on the vertex and scaled the same way (UDEC's
    /// `plot jdisp`); its bolts as lines between their anchors. Empty: none.
    std::string contacts;
};

/// What a result picture drew, for the window to show and warn with.
struct ResultInfo {
    double deform_factor = 0.0;    ///< the deformation scale used (auto or as given)
    double max_displacement = 0.0; ///< largest displacement magnitude (m)
    /// Elements drawn with zero or reversed area: the deformation scale is too large for the
    /// picture to be read (a tunnel drawn closed).
    int inverted_elements = 0;
    double range_min = 0.0, range_max = 0.0;  ///< the colour scale's ends, in the legend's units
    std::string title;                        ///< the line drawn over the picture
    /// The rows of a legend of categories (plastic state), as drawn; empty beside a scalar bar.
    std::vector<std::string> legend;
};

/// Parses a colour map name (rainbow, viridis, grey, diverging); false when unknown.
bool parse_colour_map(const std::string& name, ColourMap* map);

/// The field was not understood or is missing from the file; the message lists the available ones.
class ResultFieldError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A result or contacts file that is not one `mcdda run` wrote, or was damaged since; what()
/// names the file (and the line) and the problem. Input refused, like a model.
class ResultFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The fields a result picture can show, in the order the help text names them.
const std::vector<std::string>& result_field_names();

/// Reads `vtu_path` and adds the result scene to `renderer`: coloured cells, block boundaries,
/// joints (undeformed only), the legend (categories for plastic_state, a scalar bar otherwise);
/// sets a white background and fits a parallel camera. Throws ResultFieldError for an unknown
/// or missing field and std::runtime_error for a missing or unreadable file or a cell count
/// that differs from the model's mesh.
/// `probe`, when given, receives what the picture shows at each point (for value queries).
void build_result_scene(vtkRenderer* renderer, const Preprocessed& model, const std::string& vtu_path,
                        const ResultOptions& options, ResultProbe* probe = nullptr, ResultInfo* info = nullptr);

/// The same scene from a snapshot of a run in memory (the mesh is the model's): what the desktop
/// program shows while it runs. Throws like the above (ResultFieldError for an unknown field,
/// std::runtime_error when the snapshot does not belong to the model's mesh).
void build_result_scene(vtkRenderer* renderer, const Preprocessed& model, const ResultSnapshot& snapshot,
                        const ResultOptions& options, ResultProbe* probe = nullptr, ResultInfo* info = nullptr);

/// Renders the result scene off-screen to a PNG at `png_path` like render_png (X display,
/// atomic write). The .vtu is read and checked before any X connection is opened.
void render_result_png(const Preprocessed& model, const std::string& vtu_path, const ResultOptions& options,
                       int width, int height, const std::string& png_path, ResultInfo* info = nullptr);

}  // namespace mcdda::view
