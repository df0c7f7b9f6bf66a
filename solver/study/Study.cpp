#include "study/Study.hpp"

#include "io/FileKind.hpp"
#include "io/JsonText.hpp"
#include "io/NumberText.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string_view>

namespace mcdda {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A number as text that reads back to the same double: whole numbers written out, others in
/// the fewest significant digits.
std::string exact(double v)
{
    char text[40];
    if (v == std::floor(v) && std::fabs(v) < 1e15) {  // whole numbers as such: 15000, not 1.5e+04
        std::snprintf(text, sizeof text, "%.0f", v);
        return text;
    }
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::strtod(text, nullptr) == v) break;
    }
    return text;
}

/// A uniform number in [0, 1) from the raw 64 bits of the generator: the same on every machine
/// (std::uniform_real_distribution is not).
double unit(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

class Reader {
public:
    explicit Reader(std::vector<Diagnostic>& d) : d_(d) {}
    /// The first problems are listed, then that there are more: a file of 46,000 copies of one
    /// parameter once made a billion messages (24 GB).
    void error(const std::string& path, const std::string& message) {
        if (++errors_ <= most_errors) d_.push_back({Diagnostic::Severity::Error, path, message});
        else if (errors_ == most_errors + 1) d_.push_back({Diagnostic::Severity::Error, "", "more problems not listed"});
    }
    bool number(const json& j, const std::string& path, double& out) {
        if (!j.is_number()) {
            error(path, "must be a number");
            return false;
        }
        out = j.get<double>();
        if (!std::isfinite(out)) error(path, "must be finite");
        return std::isfinite(out);
    }
    std::string text(const json& o, const std::string& path, const char* key, bool required) {
        if (!o.contains(key)) {
            if (required) error(path + "/" + key, "is required");
            return {};
        }
        if (!o[key].is_string()) {
            error(path + "/" + key, "must be a text");
            return {};
        }
        return o[key].get<std::string>();
    }

private:
    static constexpr int most_errors = 50;
    std::vector<Diagnostic>& d_;
    int errors_ = 0;
};

/// A value as a message quotes it: "2", "1.5", "the text \"1\"", "a list".
std::string shown(const json& v)
{
    if (v.is_array()) return "a list";
    if (v.is_object()) return "an object";
    const std::string text = v.dump();
    const std::string cut = text.size() > 40 ? text.substr(0, 40) + "..." : text;
    return v.is_string() ? "the text " + cut : cut;
}

/// A cell of study.csv (RFC 4180: quoted when it holds a comma, quote or line break; a line
/// break becomes a space, one row per line). Text that a spreadsheet would take for a formula —
/// beginning with =, +, -, @, a tab or a carriage return, and not a number — gets a leading '
/// and quotes (OWASP's rule against CSV injection): a name or message is shown, never run.
std::string csv_cell(const std::string& text)
{
    const bool formula = !text.empty() && std::string_view("=+-@\t\r").find(text[0]) != std::string_view::npos &&
                         !decimal_number(text);
    if (!formula && text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = formula ? "\"'" : "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return quoted + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line)
{
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else cells.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            cells.emplace_back();
        } else if (c != '\r') {
            cells.back() += c;
        }
    }
    return cells;
}

}  // namespace

std::string StudyRun::folder_name() const
{
    char name[32];
    std::snprintf(name, sizeof name, "run_%04d", index);
    return name;
}

std::optional<StudyDefinition> read_study_text(const std::string& text, const std::string& folder,
                                               std::vector<Diagnostic>& diagnostics, const std::string& source)
{
    const std::size_t errors_before = diagnostics.size();
    Reader r(diagnostics);
    const std::optional<json> parsed = parse_json_text(text, source, diagnostics);
    if (!parsed) return std::nullopt;
    const json& root = *parsed;
    if (!root.is_object()) {
        r.error("", "a study file is a JSON object");
        return std::nullopt;
    }
    for (auto it = root.begin(); it != root.end(); ++it) {
        static const std::vector<std::string> known{"format", "version", "description", "model", "set", "design",
                                                    "parameters", "outputs", "threads_per_run"};
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            r.error("/" + it.key(), "unknown key (expected one of: format, version, description, model, set, design, "
                                    "parameters, outputs, threads_per_run)");
    }
    if (r.text(root, "", "format", true) != "mcdda-study" && root.contains("format"))
        r.error("/format", "must be \"mcdda-study\"");
    // One version so far; a file of a later one must not be read as if it were this one.
    if (!root.contains("version"))
        r.error("/version", "is required: 1, the version of the study format this program reads");
    else if (const json& v = root["version"]; !v.is_number() || v.get<double>() != 1.0)
        r.error("/version", "must be 1, the version of the study format this program reads (got " + shown(v) + ")");
    StudyDefinition s;
    s.model = r.text(root, "", "model", true);
    if (root.contains("model") && root["model"].is_string() && s.model.empty())
        r.error("/model", "must name the base model file");
    if (!s.model.empty() && fs::path(s.model).is_relative()) s.model = (fs::path(folder) / s.model).lexically_normal().string();
    if (root.contains("set")) {
        if (!root["set"].is_array()) r.error("/set", "must be a list of \"/pointer=value\" texts");
        else
            for (std::size_t i = 0; i < root["set"].size(); ++i) {
                const json& o = root["set"][i];
                if (!o.is_string() || o.get<std::string>().find('=') == std::string::npos)
                    r.error("/set/" + std::to_string(i), "must be a \"/pointer=value\" text");
                else s.overrides.push_back(o.get<std::string>());
            }
    }
    if (root.contains("design")) {
        const json& d = root["design"];
        const std::string type = d.is_object() ? r.text(d, "/design", "type", true) : std::string();
        if (!d.is_object()) r.error("/design", "must be an object with a type");
        else if (type == "grid") s.design = StudyDefinition::Design::Grid;
        else if (type == "latin_hypercube") s.design = StudyDefinition::Design::LatinHypercube;
        else if (type == "monte_carlo") s.design = StudyDefinition::Design::MonteCarlo;
        else if (!type.empty()) r.error("/design/type", "must be \"grid\", \"latin_hypercube\" or \"monte_carlo\", got \"" + type + "\"");
        if (d.is_object() && s.design != StudyDefinition::Design::Grid) {
            double samples = 0.0;
            if (!d.contains("samples")) r.error("/design/samples", "a sampled design needs a number of samples");
            else if (r.number(d["samples"], "/design/samples", samples)) {
                if (samples < 1 || samples > 1e6 || samples != std::floor(samples))
                    r.error("/design/samples", "must be a whole number from 1 to 1000000");
                s.samples = static_cast<int>(samples);
            }
            double seed = 1.0;
            if (d.contains("seed") && r.number(d["seed"], "/design/seed", seed)) {
                if (seed < 0 || seed != std::floor(seed)) r.error("/design/seed", "must be a whole number ≥ 0");
                s.seed = static_cast<std::uint64_t>(seed);
            }
        }
    }
    const json parameters = root.contains("parameters") ? root["parameters"] : json::array();
    if (!parameters.is_array() || parameters.empty()) r.error("/parameters", "a study varies at least one field");
    std::set<std::string> names;
    for (std::size_t i = 0; parameters.is_array() && i < parameters.size(); ++i) {
        const std::string path = "/parameters/" + std::to_string(i);
        const json& o = parameters[i];
        if (!o.is_object()) {
            r.error(path, "must be an object");
            continue;
        }
        StudyParameter p;
        p.path = r.text(o, path, "path", true);
        if (!p.path.empty() && p.path[0] != '/') r.error(path + "/path", "must be a JSON pointer such as /materials/0/cohesion");
        p.name = o.contains("name") ? r.text(o, path, "name", false) : p.path;
        if (o.contains("values")) {
            if (!o["values"].is_array() || o["values"].empty()) r.error(path + "/values", "must be a list of numbers");
            else
                for (std::size_t k = 0; k < o["values"].size(); ++k) {
                    double v = 0.0;
                    if (r.number(o["values"][k], path + "/values/" + std::to_string(k), v)) p.values.push_back(v);
                }
        } else if (o.contains("range")) {
            const json& g = o["range"];
            double a = 0, b = 0, n = 0;
            if (!g.is_array() || g.size() != 3 || !r.number(g[0], path + "/range/0", a) ||
                !r.number(g[1], path + "/range/1", b) || !r.number(g[2], path + "/range/2", n) || n < 1 ||
                n != std::floor(n) || n > 1e6)
                r.error(path + "/range", "must be [from, to, count] with a whole count ≥ 1");
            else
                for (int k = 0; k < static_cast<int>(n); ++k) p.values.push_back(n == 1 ? a : a + (b - a) * k / (n - 1));
        } else if (o.contains("uniform")) {
            const json& g = o["uniform"];
            double a = 0, b = 0;
            if (!g.is_array() || g.size() != 2 || !r.number(g[0], path + "/uniform/0", a) ||
                !r.number(g[1], path + "/uniform/1", b) || !(a <= b))
                r.error(path + "/uniform", "must be [low, high] with low ≤ high");
            else p.uniform = std::array<double, 2>{a, b};
        } else {
            r.error(path, "give the values: \"values\": [...], \"range\": [from, to, count] or \"uniform\": [low, high]");
        }
        if (s.design == StudyDefinition::Design::Grid && p.uniform)
            r.error(path + "/uniform", "a grid design needs \"values\" or \"range\" (uniform draws need latin_hypercube or monte_carlo)");
        if (!names.insert(p.name).second) r.error(path + "/name", "another parameter is called \"" + p.name + "\"");
        s.parameters.push_back(p);
    }
    const json outputs = root.contains("outputs") ? root["outputs"] : json::array();
    if (!outputs.is_array()) r.error("/outputs", "must be a list");
    for (std::size_t i = 0; outputs.is_array() && i < outputs.size(); ++i) {
        const std::string path = "/outputs/" + std::to_string(i);
        const json& o = outputs[i];
        if (!o.is_object()) {
            r.error(path, "must be an object");
            continue;
        }
        StudyOutput out;
        out.name = r.text(o, path, "name", true);
        out.summary = r.text(o, path, "summary", false);
        out.history = r.text(o, path, "history", false);
        if (out.summary.empty() == out.history.empty())
            r.error(path, "give either \"summary\": a JSON pointer into summary.json, or \"history\": a column of history.csv");
        else if (!out.summary.empty() && out.summary[0] != '/')
            r.error(path + "/summary", "must be a JSON pointer such as /collapse/carried/loads/footing");
        s.outputs.push_back(out);
    }
    if (root.contains("threads_per_run")) {
        double t = 0;
        if (r.number(root["threads_per_run"], "/threads_per_run", t)) {
            if (t < 0 || t != std::floor(t) || t > 1024) r.error("/threads_per_run", "must be a whole number from 0 to 1024");
            s.threads_per_run = static_cast<int>(t);
        }
    }
    for (std::size_t i = errors_before; i < diagnostics.size(); ++i)
        if (diagnostics[i].severity == Diagnostic::Severity::Error) return std::nullopt;
    return s;
}

std::optional<StudyDefinition> read_study_file(const std::string& path, std::vector<Diagnostic>& diagnostics)
{
    auto error = [&](const std::string& where, const std::string& message) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, message});
        return std::nullopt;
    };
    // What is not a file is refused by what it is, before reading: /dev/zero never ends.
    if (const std::string kind = not_a_regular_file(path); !kind.empty())
        return error("", "the study file " + path + " " + kind + (kind == "does not exist" ? "" : ", not a file"));
    std::ifstream in(path, std::ios::binary);
    if (!in) return error("", "cannot open the study file " + path);
    std::stringstream text;
    text << in.rdbuf();
    std::optional<StudyDefinition> study =
        read_study_text(text.str(), fs::path(path).parent_path().string(), diagnostics, path);
    if (!study) return std::nullopt;
    // Every run reads the model: it must be a file, and one whose name the system can take.
    if (study->model.find('\0') != std::string::npos)
        return error("/model", "the file name holds a NUL character (\\u0000), which no file name can");
    if (const std::string kind = not_a_regular_file(study->model); !kind.empty())
        return error("/model", study->model + " " + kind + (kind == "does not exist" ? "" : ", not a model file"));
    return study;
}

std::vector<StudyRun> expand_study(const StudyDefinition& study)
{
    const std::size_t n = study.parameters.size();
    std::vector<std::vector<double>> table;  // one row of values per run
    if (study.design == StudyDefinition::Design::Grid) {
        std::size_t count = 1;
        for (const StudyParameter& p : study.parameters) count *= std::max<std::size_t>(1, p.values.size());
        for (std::size_t r = 0; r < count; ++r) {
            std::vector<double> row(n);
            std::size_t rest = r;
            for (std::size_t k = n; k-- > 0;) {  // the last parameter varies fastest
                const std::size_t size = std::max<std::size_t>(1, study.parameters[k].values.size());
                row[k] = study.parameters[k].values.empty() ? 0.0 : study.parameters[k].values[rest % size];
                rest /= size;
            }
            table.push_back(row);
        }
    } else {
        std::mt19937_64 random(study.seed);
        const int samples = study.samples;
        table.assign(static_cast<std::size_t>(samples), std::vector<double>(n));
        for (std::size_t k = 0; k < n; ++k) {
            const StudyParameter& p = study.parameters[k];
            // Latin hypercube: one draw in each of `samples` equal strata, the strata shuffled.
            std::vector<int> strata(static_cast<std::size_t>(samples));
            std::iota(strata.begin(), strata.end(), 0);
            if (study.design == StudyDefinition::Design::LatinHypercube)
                for (std::size_t i = strata.size(); i > 1; --i)  // Fisher–Yates with the portable draws
                    std::swap(strata[i - 1], strata[static_cast<std::size_t>(unit(random) * static_cast<double>(i))]);
            for (int s = 0; s < samples; ++s) {
                const double u = study.design == StudyDefinition::Design::LatinHypercube
                                     ? (strata[static_cast<std::size_t>(s)] + unit(random)) / samples
                                     : unit(random);
                double v = 0.0;
                if (p.uniform) v = (*p.uniform)[0] + u * ((*p.uniform)[1] - (*p.uniform)[0]);
                else if (!p.values.empty())  // a list: each value equally likely
                    v = p.values[std::min(p.values.size() - 1, static_cast<std::size_t>(u * static_cast<double>(p.values.size())))];
                table[static_cast<std::size_t>(s)][k] = v;
            }
        }
    }
    std::vector<StudyRun> runs;
    for (std::size_t r = 0; r < table.size(); ++r) {
        StudyRun run;
        run.index = static_cast<int>(r) + 1;
        run.values = table[r];
        run.overrides = study.overrides;
        for (std::size_t k = 0; k < n; ++k) run.overrides.push_back(study.parameters[k].path + "=" + exact(table[r][k]));
        runs.push_back(run);
    }
    return runs;
}

StudyRow read_run_row(const StudyDefinition& study, const StudyRun& run, const std::string& folder,
                      const std::string& failure)
{
    StudyRow row;
    row.index = run.index;
    row.values = run.values;
    row.outputs.assign(study.outputs.size(), std::nullopt);
    json summary;
    {
        std::ifstream in(fs::path(folder) / "summary.json");
        try {
            if (in) summary = json::parse(in);
        } catch (const json::exception&) {
            summary = json();
        }
    }
    if (!summary.is_object() || !summary.contains("status")) {
        row.status = "failed";
        row.message = failure;
        return row;
    }
    row.status = summary.value("status", std::string("failed"));
    row.message = summary.value("message", std::string());
    std::vector<std::string> header, last;
    {
        std::ifstream in(fs::path(folder) / "history.csv");
        std::string line;
        if (in && std::getline(in, line)) header = split_csv_line(line);
        while (in && std::getline(in, line))
            if (!line.empty()) last = split_csv_line(line);
    }
    for (std::size_t k = 0; k < study.outputs.size(); ++k) {
        const StudyOutput& o = study.outputs[k];
        if (!o.summary.empty()) {
            try {
                const json& v = summary.at(json::json_pointer(o.summary));
                if (v.is_number()) row.outputs[k] = v.get<double>();
            } catch (const json::exception&) {
            }  // not in this run's summary (e.g. no collapse): an empty cell
        } else {
            const auto it = std::find(header.begin(), header.end(), o.history);
            const std::size_t column = static_cast<std::size_t>(it - header.begin());
            if (it != header.end() && column < last.size()) {
                char* end = nullptr;
                const double v = std::strtod(last[column].c_str(), &end);
                if (end != last[column].c_str()) row.outputs[k] = v;
            }
        }
    }
    return row;
}

std::string study_csv(const StudyDefinition& study, const std::vector<StudyRow>& rows)
{
    std::ostringstream out;
    out << "run,status";
    for (const StudyParameter& p : study.parameters) out << "," << csv_cell(p.name);
    for (const StudyOutput& o : study.outputs) out << "," << csv_cell(o.name);
    out << ",message\n";
    std::vector<const StudyRow*> sorted;
    for (const StudyRow& r : rows) sorted.push_back(&r);
    std::sort(sorted.begin(), sorted.end(), [](const StudyRow* a, const StudyRow* b) { return a->index < b->index; });
    for (const StudyRow* r : sorted) {
        out << r->index << "," << csv_cell(r->status);
        for (double v : r->values) out << "," << exact(v);
        for (const std::optional<double>& v : r->outputs) out << "," << (v ? exact(*v) : std::string());
        out << "," << csv_cell(r->message) << "\n";
    }
    return out.str();
}

std::string row_to_json(const StudyRow& row)
{
    json j{{"run", row.index}, {"status", row.status}, {"message", row.message}, {"values", row.values}};
    json outputs = json::array();
    for (const std::optional<double>& v : row.outputs) outputs.push_back(v ? json(*v) : json());
    j["outputs"] = outputs;
    // A message may quote a path of the command line, in whatever bytes it has: never a failure.
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::optional<StudyRow> row_from_json(const std::string& text)
{
    try {
        const json j = json::parse(text);
        StudyRow row;
        row.index = j.at("run").get<int>();
        row.status = j.at("status").get<std::string>();
        row.message = j.at("message").get<std::string>();
        row.values = j.at("values").get<std::vector<double>>();
        for (const json& v : j.at("outputs")) row.outputs.push_back(v.is_number() ? std::optional<double>(v.get<double>()) : std::nullopt);
        return row;
    } catch (const json::exception&) {
        return std::nullopt;
    }
}

bool row_is_finished(const StudyRow& row)
{
    return row.status == "completed" || row.status == "unbalanced" || row.status == "collapsed";
}

}  // namespace mcdda
