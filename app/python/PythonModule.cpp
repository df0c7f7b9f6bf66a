// The Python module `mcdda`: the library interface <mcdda/Analysis.hpp> with NumPy arrays for
// meshes and fields, dicts for diagnostics and history, and the GIL released while solving.

#include <mcdda/Analysis.hpp>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace mcdda;

namespace {

/// A NumPy array of `rows` × `columns` (or 1-D when columns is 0) holding a copy of `values`.
template <class T>
py::array_t<T> array(const std::vector<T>& values, py::ssize_t columns = 0)
{
    if (columns == 0) return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
    const py::ssize_t rows = static_cast<py::ssize_t>(values.size()) / columns;
    return py::array_t<T>({rows, columns}, values.data());
}

py::list diagnostics_list(const std::vector<Diagnostic>& diagnostics)
{
    py::list out;
    for (const Diagnostic& d : diagnostics) {
        py::dict item;
        item["severity"] = d.severity == Diagnostic::Severity::Error ? "error" : "warning";
        item["path"] = d.path;
        item["message"] = d.message;
        out.append(item);
    }
    return out;
}

/// check() or mesh() with the GIL released (meshing a large model takes seconds).
py::list preprocess(Analysis& a, std::vector<Diagnostic> (Analysis::*stage)())
{
    std::vector<Diagnostic> d;
    {
        py::gil_scoped_release released;
        d = (a.*stage)();
    }
    return diagnostics_list(d);
}

/// Overrides as `mcdda run --set` takes them, from a dict {pointer: value} (values written as
/// JSON) or a list of "pointer=json" strings.
std::vector<std::string> overrides_of(const py::object& changes)
{
    std::vector<std::string> out;
    if (changes.is_none()) return out;
    if (py::isinstance<py::dict>(changes)) {
        const py::object dumps = py::module_::import("json").attr("dumps");
        for (const auto& [key, value] : changes.cast<py::dict>())
            out.push_back(py::str(key).cast<std::string>() + "=" + dumps(value).cast<std::string>());
        return out;
    }
    for (const py::handle item : changes) out.push_back(py::str(item).cast<std::string>());
    return out;
}

py::dict fields_dict(const StepFields& f)
{
    py::dict d;
    d["step"] = f.step;
    d["stage"] = f.stage;
    d["time"] = f.time;
    d["displacement"] = array(f.displacement, 2);
    d["stress"] = array(f.stress, 4);
    d["effective_stress"] = array(f.effective_stress, 4);
    d["pore_pressure"] = array(f.pore_pressure);
    d["plastic_strain"] = array(f.plastic_strain);
    d["plastic_state"] = array(f.plastic_state);
    return d;
}

py::dict history_dict(const std::vector<HistoryRow>& rows, const Model& model)
{
    auto column = [&](auto member) {
        using T = std::decay_t<decltype(rows.front().*member)>;
        std::vector<T> values;
        values.reserve(rows.size());
        for (const HistoryRow& r : rows) values.push_back(r.*member);
        return array(values);
    };
    py::dict d;
    d["step"] = column(&HistoryRow::step);
    d["stage"] = column(&HistoryRow::stage);
    d["time"] = column(&HistoryRow::time);
    d["unbalanced_ratio"] = column(&HistoryRow::unbalanced_ratio);
    d["max_displacement"] = column(&HistoryRow::max_displacement);
    d["yielding"] = column(&HistoryRow::yielding);
    d["iterations"] = column(&HistoryRow::iterations);
    // Per measurement point (and the base's record with a base motion) the motion's columns,
    // named as in history.csv ("<point>:ux", "base:ax"): the dict stays one DataFrame.
    auto motion = [&](const std::string& prefix, auto pick) {
        for (const auto& [key, member] : {std::pair{"ux", &HistoryRow::PointMotion::ux}, {"uy", &HistoryRow::PointMotion::uy},
                                          {"vx", &HistoryRow::PointMotion::vx}, {"vy", &HistoryRow::PointMotion::vy},
                                          {"ax", &HistoryRow::PointMotion::ax}, {"ay", &HistoryRow::PointMotion::ay}}) {
            std::vector<double> values;
            values.reserve(rows.size());
            for (const HistoryRow& r : rows) values.push_back(pick(r).*member);
            d[py::str(prefix + ":" + key)] = array(values);
        }
    };
    for (std::size_t i = 0; i < model.measurement_points.size(); ++i)
        motion(model.measurement_points[i].name, [i](const HistoryRow& r) {
            return i < r.points.size() ? r.points[i] : HistoryRow::PointMotion{};
        });
    if (model.base_motion.present()) motion("base", [](const HistoryRow& r) { return r.base; });
    return d;
}

/// Runs with the GIL released; the progress callback takes it back for each call. An exception
/// raised in the callback, or Ctrl-C, stops the run after the step and is raised here.
py::object run(Analysis& analysis, const std::optional<std::string>& output_folder, const std::string& name,
               int keep_every, const py::object& progress, int threads)
{
    RunOptions options;
    options.output_folder = output_folder.value_or(std::string());
    options.name = name;
    options.keep_every = keep_every;
    options.threads = threads;
    std::optional<py::error_already_set> raised;
    options.on_step = [&](const StepProgress& p) {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {  // Ctrl-C
            raised.emplace();
            return false;
        }
        if (progress.is_none()) return true;
        try {
            py::dict info;
            info["step"] = p.step;
            info["planned_steps"] = p.planned_steps;
            info["stage"] = p.stage;
            info["time"] = p.time;
            info["unbalanced_ratio"] = p.unbalanced_ratio;
            info["max_displacement"] = p.max_displacement;
            info["yielding"] = p.yielding;
            const py::object answer = progress(info);
            return answer.is_none() || answer.cast<bool>();  // None: go on
        } catch (py::error_already_set& e) {
            raised.emplace(std::move(e));
            return false;
        }
    };
    RunResult r;
    {
        py::gil_scoped_release released;
        r = analysis.run(options);
    }
    if (raised) throw std::move(*raised);
    py::dict out;
    out["status"] = r.status;
    out["message"] = r.message;
    out["exit_code"] = r.exit_code;
    out["steps"] = r.steps;
    out["time"] = r.time;
    out["unbalanced_ratio"] = r.unbalanced_ratio;
    out["collapse_carried"] = r.collapse_carried;
    out["collapse_not_carried"] = r.collapse_not_carried;
    out["seconds"] = r.seconds;
    out["history"] = history_dict(r.history, analysis.model());
    if (r.shaken) {
        py::dict permanent;
        permanent["largest"] = r.permanent_displacement;
        py::dict points;
        const auto& names = analysis.model().measurement_points;
        for (std::size_t i = 0; i < names.size() && i < r.permanent_displacement_points.size(); ++i)
            points[py::str(names[i].name)] = py::make_tuple(r.permanent_displacement_points[i][0],
                                                            r.permanent_displacement_points[i][1]);
        permanent["points"] = points;
        out["permanent_displacement"] = permanent;
    }
    py::list saved;
    for (const StepFields& f : r.saved) saved.append(fields_dict(f));
    out["fields"] = saved;
    if (r.strength_reduction) {
        py::dict f;
        f["value"] = r.factor_of_safety;
        f["converged"] = r.factor_converged;
        f["not_converged"] = r.factor_not_converged;
        f["non_associated_flow"] = r.non_associated_flow;
        f["trials"] = static_cast<int>(r.trials.size());
        f["found"] = r.factor_found;
        py::list table;
        for (const RunResult::StrengthTrial& t : r.trials) {
            py::dict row;
            row["trial"] = t.number;
            row["factor"] = t.factor;
            row["stands"] = t.stands;
            row["status"] = t.status;
            row["steps"] = t.steps;
            row["iterations"] = t.iterations;
            row["max_displacement"] = t.max_displacement;
            row["message"] = t.message;
            table.append(row);
        }
        f["table"] = table;
        out["factor_of_safety"] = f;
    }
    return std::move(out);
}

/// pybind11 reads NumPy's array descriptors itself; before 2.12 (Debian 12 has 2.10) it knows
/// only NumPy 1's layout.
constexpr bool reads_numpy_2 = PYBIND11_VERSION_MAJOR > 2 || PYBIND11_VERSION_MINOR >= 12;

/// Meshes and results are NumPy arrays: without a NumPy it can use, say so at import with the
/// remedy rather than fail at the first array (a virtual environment made without
/// --system-site-packages does not see Debian's python3-numpy). Raised as import_error, not as
/// a Python error, which PYBIND11_MODULE would bury under "initialization failed".
void require_numpy()
{
    const std::string python = py::str(py::module_::import("sys").attr("executable"));
    const std::string remedy = std::string(". Install it into this environment (python3 -m pip install ") +
                               (reads_numpy_2 ? "numpy" : "'numpy<2'") +
                               "), or create the virtual environment with `python3 -m venv "
                               "--system-site-packages` so that it sees Debian's python3-numpy.";
    py::module_ numpy;
    try {
        numpy = py::module_::import("numpy");
    } catch (py::error_already_set& e) {
        if (!e.matches(PyExc_ImportError)) throw;
        const std::string reason = py::str(e.value());
        throw py::import_error("mcdda needs NumPy, which this Python (" + python + ") cannot import (" + reason +
                               ")" + remedy);
    }
    const std::string version = py::str(numpy.attr("__version__"));
    if (!reads_numpy_2 && version.rfind("1.", 0) != 0)
        throw py::import_error("mcdda needs NumPy 1 (it was built with pybind11 " +
                               std::to_string(PYBIND11_VERSION_MAJOR) + "." + std::to_string(PYBIND11_VERSION_MINOR) +
                               ", which predates NumPy 2), and this Python (" + python + ") has NumPy " + version +
                               remedy);
}

}  // namespace

PYBIND11_MODULE(mcdda, m)
{
    require_numpy();

    m.doc() = "mcdda: elastic-plastic discontinuous deformation analysis (docs/python.md)";
    m.attr("__version__") = library_version();
    py::register_exception<ModelError>(m, "ModelError", PyExc_ValueError);

    py::class_<Analysis>(m, "Analysis", "A model, its blocks and mesh, and its runs")
        .def_static("from_file", &Analysis::from_file, py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
                    "Reads a model file; overrides as `mcdda run --set` (\"/pointer=json\")")
        .def_static("from_json", &Analysis::from_text, py::arg("text"), py::arg("overrides") = std::vector<std::string>{},
                    "Reads the text of a model file")
        .def_static(
            "from_dict",
            [](const py::dict& model) {
                return Analysis::from_text(py::module_::import("json").attr("dumps")(model).cast<std::string>());
            },
            py::arg("model"), "Builds a model from a dict laid out as the model file (docs/model-format.md)")
        .def(
            "set", [](Analysis& a, const py::object& changes) { a.set(overrides_of(changes)); }, py::arg("changes"),
            "Changes fields: {\"/materials/0/cohesion\": 2e5} or [\"/materials/0/cohesion=2e5\"]")
        .def("to_json", &Analysis::to_json, "The model as the text of a model file")
        .def(
            "to_dict", [](const Analysis& a) { return py::module_::import("json").attr("loads")(a.to_json()); },
            "The model as a dict")
        .def(
            "check", [](Analysis& a) { return preprocess(a, &Analysis::check); },
            "Checks the model and cuts its blocks: a list of {severity, path, message}")
        .def(
            "mesh", [](Analysis& a) { return preprocess(a, &Analysis::mesh); },
            "Checks, cuts and meshes: a list of {severity, path, message}")
        .def_property_readonly("ok", &Analysis::ok, "True when the last check or mesh found no error")
        .def_property_readonly(
            "diagnostics", [](const Analysis& a) { return diagnostics_list(a.diagnostics()); })
        .def(
            "mesh_arrays",
            [](Analysis& a) {
                MeshArrays mesh;
                {
                    py::gil_scoped_release released;
                    mesh = a.mesh_arrays();
                }
                py::dict d;
                d["nodes"] = array(mesh.nodes, 2);
                d["triangles"] = array(mesh.triangles, 3);
                d["block"] = array(mesh.block);
                d["region"] = array(mesh.region);
                d["material"] = array(mesh.material);
                d["area"] = array(mesh.area);
                d["crack_faces"] = py::array_t<int>({static_cast<py::ssize_t>(mesh.crack_faces.size() / 2), py::ssize_t{2}},
                                                    mesh.crack_faces.data());
                d["crack_face_joint"] = array(mesh.crack_face_joint);
                return d;
            },
            "The mesh as NumPy arrays: nodes (n, 2), triangles (e, 3), block, region, material, area (e,), "
            "crack_faces (f, 2): the node pairs of the edges on the faces of cracks (joints ending in the rock), "
            "crack_face_joint (f,): their joints")
        .def("run", &run, py::arg("output_folder") = py::none(), py::arg("name") = "model", py::arg("keep_every") = 0,
             py::arg("progress") = py::none(), py::arg("threads") = 0,
             "Runs the analysis with the GIL released. progress(info) is called after every step; "
             "returning False stops the run. Returns a dict: status, message, exit_code, steps, time, "
             "history (dict of arrays), fields (list of dicts of arrays, every keep_every-th step and the last); "
             "a strength reduction analysis also factor_of_safety: value, converged, not_converged, trials, "
             "found, table (a dict per trial)")
        .def("cancel", &Analysis::cancel, "Stops a run in progress (from another thread) after its current step");
}
