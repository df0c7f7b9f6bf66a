#include "CommandLine.hpp"

#include "io/DxfImport.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

namespace mcdda::cli {

std::string usage_text() {
    return R"(mcdda - elastic-plastic discontinuous deformation analysis (MC-DDA)

Usage:
  mcdda check  MODEL [--set POINTER=VALUE]...
  mcdda mesh   MODEL --out DIR [--profile] [--set POINTER=VALUE]...
  mcdda render MODEL --out FILE.png [--size WxH] [--no-mesh] [--set POINTER=VALUE]...
  mcdda render MODEL --out FILE.png --results STEP.vtu [--field NAME] [--deform FACTOR|auto]
               [--contacts STEP.vtp] [--compression-positive] [--colour-map NAME] [--bands N]
               [--range MIN:MAX] [--title TEXT] [--no-axes]
               [--size WxH] [--set POINTER=VALUE]...
  mcdda run    MODEL --out DIR [--profile] [--quiet] [--threads N] [--set POINTER=VALUE]...
  mcdda study  STUDY.json --out DIR [--quiet] [--threads N]
  mpirun -n N mcdda study STUDY.json --out DIR
  mcdda import-dxf DRAWING.dxf --out MODEL.json [--units m|mm|cm|km|in|ft]
  mcdda --help | --version

Commands:
  check    validate the model: every problem is printed with its JSON pointer;
           exit status 1 when there is any error
  mesh     cut the regions into blocks, mesh every block and write DIR/<model>.vtu
           (cell data: block, material) with the mesh statistics
  render   draw blocks, joints, mesh, supports and loads with a legend into a PNG
           (starts a virtual X server through xvfb-run when DISPLAY is not set); with
           --results it draws a result .vtu of `mcdda run` of the same model instead
  run      run the analysis: DIR/<model>.pvd with one .vtu per saved step
           (displacement, velocity, stress, block, material), DIR/history.csv and
           DIR/summary.json (status, timing); Ctrl-C stops within the current step
  study    run a parameter study (docs/study.md): every run of STUDY.json in
           DIR/runs/run_NNNN, one row each in DIR/study.csv; under mpirun the runs are
           spread over the ranks; a rerun skips the runs that have their result;
           exit status 4 when a run failed
  import-dxf  make a model of a DXF drawing (docs/dxf-import.md): closed polylines are
           regions (layer = material; on a layer "holes": holes), lines and open
           polylines joints, points measurement points; the drawing's units are read
           from $INSUNITS unless --units gives them; skipped entities are reported

Options:
  --set POINTER=VALUE  override any field of the model by JSON pointer before it is
                       read, e.g. --set /materials/0/cohesion=3.45e6 (repeatable;
                       VALUE is JSON, or a string when it is not valid JSON)
  --out PATH           output directory (mesh, run) or PNG file (render)
  --profile            print a timing breakdown of the stages
  --size WxH           picture size in pixels for render (default 1600x1000)
  --no-mesh            do not draw element edges in render
  --no-axes            do not draw the rulers (x, y in m) and the scale bar in render
  --results STEP.vtu   render a result step: mesh cells coloured by --field, block
                       boundaries, joints and a colour legend
  --field NAME         plastic_state (default), plastic_strain, displacement
                       (magnitude), ux, uy, stress_xx, stress_yy, stress_xy, stress_1
                       or stress_3 (in-plane principal; kPa or MPa, tension + unless
                       --compression-positive; total stresses); with ground water also
                       pore_pressure (compression +) and effective_stress_xx, _yy, _1, _3
  --deform FACTOR      draw the mesh displaced by FACTOR x displacement (default 0); auto:
                       the largest displacement drawn as 5 % of the model's size (a warning
                       says when elements are drawn inside out)
  --compression-positive  stresses compression positive, stress_1 the major compressive
                       stress (sigma1 >= sigma3), as RS2, PLAXIS and UDEC show them
  --colour-map NAME    rainbow (default), viridis, grey or diverging (blue-white-red)
  --bands N            N colour bands (contours) instead of a smooth scale
  --range MIN:MAX      ends of the colour scale in the legend's units (default: the field's
                       range widened to round numbers)
  --title TEXT         the line over a result picture (default: field, step, stage, time)
  --contacts STEP.vtp  with --results: draw the step's contact forces (lines along the force
                       on each contact, the largest 6 % of the model long), joint slip (along
                       the joint) and opening (across it), and bolts, from the run's
                       <model>_contacts_NNNNNN.vtp
  --quiet              print errors only
  --threads N          threads for the element loops and the contact search of run (default:
                       $MCDDA_THREADS, else one per core); results are the same for any number
  --help, --version

Exit status: 0 success, 1 the model has errors, 2 bad command line, 3 could not write
output, 4 the run failed, 5 the model collapsed, 130 cancelled.
)";
}

std::optional<Request> parse_command_line(const std::vector<std::string>& args, std::string& error) {
    Request r;
    static const std::set<std::string> commands{"check", "mesh", "render", "run", "study", "import-dxf"};
    std::vector<std::string> positional;
    bool field_given = false, deform_given = false, result_option = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](const char* option) -> std::optional<std::string> {
            const std::string prefix = std::string(option) + "=";
            if (a.rfind(prefix, 0) == 0) return a.substr(prefix.size());
            if (i + 1 >= args.size()) {
                error = std::string(option) + " needs a value";
                return std::nullopt;
            }
            return args[++i];
        };
        auto is = [&](const char* option) { return a == option || a.rfind(std::string(option) + "=", 0) == 0; };
        if (a == "--help" || a == "-h") r.help = true;
        else if (a == "--version") r.version = true;
        else if (a == "--profile") r.profile = true;
        else if (a == "--quiet" || a == "-q") r.quiet = true;
        else if (a == "--no-mesh") r.show_mesh = false;
        else if (a == "--no-axes") r.show_axes = false;
        else if (a == "--compression-positive") r.compression_positive = result_option = true;
        else if (is("--colour-map") || is("--color-map")) {
            const auto v = value("--colour-map");
            if (!v) return std::nullopt;
            if (*v != "rainbow" && *v != "viridis" && *v != "grey" && *v != "gray" && *v != "diverging") {
                error = "--colour-map expects rainbow, viridis, grey or diverging, got \"" + *v + "\"";
                return std::nullopt;
            }
            r.colour_map = *v;
            result_option = true;
        } else if (is("--bands")) {
            const auto v = value("--bands");
            if (!v) return std::nullopt;
            try {
                std::size_t used = 0;
                r.bands = std::stoi(*v, &used);
                if (used != v->size()) throw std::invalid_argument("trailing");
            } catch (const std::exception&) {
                r.bands = -1;
            }
            if (r.bands < 1 || r.bands > 64) {
                error = "--bands expects a number of colour bands from 1 to 64, got \"" + *v + "\"";
                return std::nullopt;
            }
            result_option = true;
        } else if (is("--range")) {
            const auto v = value("--range");
            if (!v) return std::nullopt;
            const auto colon = v->find(':');
            try {
                if (colon == std::string::npos) throw std::invalid_argument("no colon");
                std::size_t a_used = 0, b_used = 0;
                const std::string lo = v->substr(0, colon), hi = v->substr(colon + 1);
                r.range_min = std::stod(lo, &a_used);
                r.range_max = std::stod(hi, &b_used);
                if (a_used != lo.size() || b_used != hi.size() || !(r.range_min < r.range_max) ||
                    !std::isfinite(r.range_min) || !std::isfinite(r.range_max))
                    throw std::invalid_argument("order");
            } catch (const std::exception&) {
                error = "--range expects MIN:MAX with MIN < MAX, e.g. -5:20, got \"" + *v + "\"";
                return std::nullopt;
            }
            result_option = true;
        } else if (is("--title")) {
            const auto v = value("--title");
            if (!v) return std::nullopt;
            r.title = *v;
            result_option = true;
        }
        else if (is("--set")) {
            const auto v = value("--set");
            if (!v) return std::nullopt;
            r.overrides.push_back(*v);
        } else if (is("--out") || a == "-o") {
            const auto v = value("--out");
            if (!v) return std::nullopt;
            r.out = *v;
        } else if (is("--size")) {
            const auto v = value("--size");
            if (!v) return std::nullopt;
            const auto x = v->find('x');
            try {
                if (x == std::string::npos) throw std::invalid_argument("no x");
                r.width = std::stoi(v->substr(0, x));
                r.height = std::stoi(v->substr(x + 1));
            } catch (const std::exception&) {
                error = "--size expects WIDTHxHEIGHT, e.g. 1600x1000, got \"" + *v + "\"";
                return std::nullopt;
            }
            if (r.width < 64 || r.height < 64 || r.width > 8192 || r.height > 8192) {
                error = "--size must lie between 64x64 and 8192x8192";
                return std::nullopt;
            }
        } else if (is("--threads")) {
            const auto v = value("--threads");
            if (!v) return std::nullopt;
            try {
                std::size_t used = 0;
                r.threads = std::stoi(*v, &used);
                if (used != v->size()) throw std::invalid_argument("trailing");
            } catch (const std::exception&) {
                r.threads = -1;
            }
            if (r.threads < 1 || r.threads > 256) {
                error = "--threads expects a number of threads from 1 to 256, got \"" + *v + "\"";
                return std::nullopt;
            }
        } else if (is("--units")) {
            const auto v = value("--units");
            if (!v) return std::nullopt;
            r.units = *v;
            if (metres_per_unit_named(*v) <= 0.0) {
                error = "--units expects m, mm, cm, km, in or ft, got \"" + *v + "\"";
                return std::nullopt;
            }
        } else if (is("--results")) {
            const auto v = value("--results");
            if (!v) return std::nullopt;
            r.results = *v;
        } else if (is("--contacts")) {
            const auto v = value("--contacts");
            if (!v) return std::nullopt;
            r.contacts = *v;
        } else if (is("--field")) {
            const auto v = value("--field");
            if (!v) return std::nullopt;
            r.field = *v;
            field_given = true;
        } else if (is("--deform")) {
            const auto v = value("--deform");
            if (!v) return std::nullopt;
            try {
                std::size_t used = 0;
                if (*v == "auto") {
                    r.deform_auto = true;
                } else {
                    r.deform = std::stod(*v, &used);
                    if (used != v->size() || !std::isfinite(r.deform)) throw std::invalid_argument("trailing");
                }
            } catch (const std::exception&) {
                error = "--deform expects a number or auto, got \"" + *v + "\"";
                return std::nullopt;
            }
            deform_given = true;
        } else if (!a.empty() && a[0] == '-' && a != "-") {
            error = "unknown option " + a;
            return std::nullopt;
        } else {
            positional.push_back(a);
        }
    }
    if (r.help || r.version) return r;
    if (positional.empty()) {
        error = "no command given";
        return std::nullopt;
    }
    r.command = positional[0];
    if (!commands.count(r.command)) {
        error = "unknown command \"" + r.command + "\" (expected check, mesh, render or run)";
        return std::nullopt;
    }
    if (positional.size() < 2) {
        error = r.command + ": no model file given";
        return std::nullopt;
    }
    if (positional.size() > 2) {
        error = r.command + ": unexpected argument \"" + positional[2] + "\"";
        return std::nullopt;
    }
    r.model = positional[1];
    if ((r.command == "mesh" || r.command == "render" || r.command == "run" || r.command == "study" ||
         r.command == "import-dxf") &&
        r.out.empty()) {
        error = r.command + ": --out is required";
        return std::nullopt;
    }
    if ((field_given || deform_given || !r.contacts.empty() || result_option) && r.results.empty()) {
        error = std::string(field_given ? "--field" : deform_given ? "--deform" : !r.contacts.empty() ? "--contacts"
                                                                                               : "this option") +
                " needs --results STEP.vtu";
        return std::nullopt;
    }
    if (!r.results.empty() && r.command != "render") {
        error = r.command + ": --results is for render only";
        return std::nullopt;
    }
    return r;
}

}  // namespace mcdda::cli
