// Hundreds of mutated example files through the whole pre-processing pipeline and, where they
// mesh small enough, one step of the solver: whatever the input, problems are reported as the
// project's own diagnostics or errors (never an "internal failure" of a library), and nothing
// crashes, throws anything else, or hangs (ctest's timeout).

#include "TestModels.hpp"
#include "io/ModelReader.hpp"
#include "run/Simulation.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

using namespace mcdda;
using nlohmann::json;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A random node of the document (the root included) to mutate.
json* random_node(json& root, std::mt19937& rng) {
    json* node = &root;
    std::uniform_int_distribution<int> stop(0, 3);
    while ((node->is_object() || node->is_array()) && !node->empty() && stop(rng) != 0) {
        std::uniform_int_distribution<std::size_t> pick(0, node->size() - 1);
        const std::size_t i = pick(rng);
        if (node->is_array()) {
            node = &(*node)[i];
        } else {
            auto it = node->begin();
            std::advance(it, i);
            node = &it.value();
        }
    }
    return node;
}

json random_value(std::mt19937& rng) {
    static const std::vector<json> values = {
        nullptr, true, false, 0, -1, 1, 0.5, 90, 1e308, -1e308, 1e-300, 3.7e12, "", "rock", "x", json::array(),
        json::object(), json::array({1}), json::array({0, 0}), json::array({json::array({0, 0})}),
        json::array({json::array({0, 0}), json::array({1, 0}), json::array({0, 1})}),
        json{{"circle", {{"center", {0, 0}}, {"radius", 1}}}}, json{{"arc", {{"radius", -1}}}}};
    std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
    return values[pick(rng)];
}

/// Kinds of document mutation, for the summary line.
const char* const document_mutations[] = {"replace a value", "drop a member", "duplicate an element",
                                          "scale a number", "unknown key", "nudge a number", "swap two points"};
int mutation_counts[7] = {};

/// Mutates the parsed document in one of several ways.
void mutate_document(json& doc, std::mt19937& rng) {
    json* node = random_node(doc, rng);
    const int kind = std::uniform_int_distribution<int>(0, 6)(rng);
    ++mutation_counts[kind];
    switch (kind) {
        case 0: *node = random_value(rng); break;
        case 1:  // drop a member or element
            if ((node->is_object() || node->is_array()) && !node->empty()) {
                const std::size_t i = std::uniform_int_distribution<std::size_t>(0, node->size() - 1)(rng);
                if (node->is_array()) node->erase(i);
                else { auto it = node->begin(); std::advance(it, i); node->erase(it); }
            }
            break;
        case 2:  // duplicate an element
            if (node->is_array() && !node->empty()) node->push_back((*node)[0]);
            break;
        case 3:  // scale a number
            if (node->is_number()) {
                static const double factors[] = {-1.0, 0.0, 1e6, 1e-6, 1.0000001, 1e12, 1e-12, 1e300, 1e-300};
                *node = node->get<double>() * factors[std::uniform_int_distribution<int>(0, 8)(rng)];
            }
            break;
        case 4:  // an unknown key
            if (node->is_object()) (*node)["unexpected_key"] = 1;
            break;
        case 5:  // nudge a number by a hair (slivers, nearly coincident vertices)
            if (node->is_number()) {
                static const double nudges[] = {1e-9, -1e-9, 1e-15, 5e-324};
                *node = node->get<double>() + nudges[std::uniform_int_distribution<int>(0, 3)(rng)];
            }
            break;
        default:  // move one vertex of some ring or joint onto another place
            if (node->is_array() && node->size() >= 2 && (*node)[0].is_array()) std::swap((*node)[0], (*node)[1]);
            break;
    }
}

/// Mutates the raw text: truncation, deleted or inserted characters.
std::string mutate_text(std::string text, std::mt19937& rng) {
    if (text.empty()) return text;
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
    static const std::string noise = "{}[],:\"0-.e9 \\n";
    switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
        case 0: return text.substr(0, at);
        case 1: return text.erase(at, 1);
        default: return text.insert(at, 1, noise[std::uniform_int_distribution<std::size_t>(0, noise.size() - 1)(rng)]);
    }
}

}  // namespace

TEST(LoaderFuzz, MutatedExamplesNeverCrashTheLoader) {
    std::mt19937 rng(20261121);
    int runs = 0, rejected = 0, meshed = 0, solved = 0;
    // Meshing is capped so a mutation that asks for a huge mesh is refused quickly.
    const std::vector<std::string> cap = {"/mesh/max_elements=30000"};
    // 80 mutants per shipped example; MCDDA_FUZZ_PER_EXAMPLE=1000 for a long run.
    const char* per_example_text = std::getenv("MCDDA_FUZZ_PER_EXAMPLE");
    const int per_example = per_example_text ? std::max(1, std::atoi(per_example_text)) : 80;
    int text_mutations = 0;
    for (const std::string& file : mcdda::test::example_files()) {
        const std::string original = read_text(file);
        const json parsed = json::parse(original);
        for (int i = 0; i < per_example; ++i, ++runs) {
            std::string text;
            if (i % 4 == 3) {
                ++text_mutations;
                text = mutate_text(original, rng);
            } else {
                json doc = parsed;
                for (int k = 0, n = 1 + i % 3; k < n; ++k) mutate_document(doc, rng);
                text = doc.dump(2);
            }
            Preprocessed p;
            ASSERT_NO_THROW({
                ReadResult r = read_model_text(text, cap, file);
                if (r.model) p = preprocess_model(*r.model, PreprocessStage::Mesh);
                else p.diagnostics = r.diagnostics;
            }) << file << " mutation " << i << ":\n" << text;
            // Every message is the project's own (a library's exception text is no answer).
            for (const Diagnostic& d : p.diagnostics)
                EXPECT_EQ(d.message.find("internal failure"), std::string::npos)
                    << file << " mutation " << i << ": " << d.message << "\n" << text.substr(0, 4000);
            if (!p.ok) {
                ++rejected;
                // A rejected model always says why.
                EXPECT_TRUE(has_errors(p.diagnostics)) << file << " mutation " << i;
                for (const Diagnostic& d : p.diagnostics) EXPECT_FALSE(d.message.empty());
            } else {
                ++meshed;
                EXPECT_GT(p.mesh.triangles.size(), 0u);
                // One step of the small ones: set-up refusals and step failures are errors with a
                // message; any other exception (or a crash) fails the test.
                if (p.statistics.elements > 6000 || i % 2 != 0) continue;
                ++solved;
                try {
                    Simulation s(p);
                    s.advance();
                } catch (const std::runtime_error& e) {  // PlasticCollapse is one too
                    EXPECT_GT(std::string(e.what()).size(), 10u) << file << " mutation " << i;
                } catch (const std::exception& e) {
                    ADD_FAILURE() << file << " mutation " << i << ": unexpected " << e.what() << "\n" << text.substr(0, 4000);
                }
            }
        }
    }
    EXPECT_GE(runs, 500);
    EXPECT_GT(rejected, runs / 4);  // the mutations do hit real problems
    EXPECT_GT(meshed, 10);          // and some survive to be meshed
    EXPECT_GT(solved, 10);
    std::cout << runs << " mutated models: " << rejected << " rejected with messages, " << meshed << " meshed, "
              << solved << " solved one step\n  byte-level text mutations " << text_mutations;
    for (int k = 0; k < 7; ++k) std::cout << "; " << document_mutations[k] << " " << mutation_counts[k];
    std::cout << "\n";
}

// Random cracks (joints ending in the rock) in a square with an opening: tips a hair from an
// edge or a vertex, cracks through vertices, crossing each other at tiny angles, touching other
// cracks, from the outline into the rock. Every model meshes or is refused with the project's own
// message, and one step of the small ones neither crashes nor throws anything unexpected.
TEST(LoaderFuzz, RandomCracksNeverCrashOrHang) {
    std::mt19937 rng(20261125);
    const char* count_text = std::getenv("MCDDA_FUZZ_CRACK_MODELS");
    const int models = count_text ? std::max(1, std::atoi(count_text)) : 240;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<Point2> vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}};
    const double hairs[] = {0.0, 1e-12, 1e-7, 1e-5, 1e-3, 0.05};
    int rejected = 0, meshed = 0, solved = 0;
    for (int m = 0; m < models; ++m) {
        std::vector<std::pair<Point2, Point2>> cracks;
        const int count = 1 + static_cast<int>(unit(rng) * 5);
        auto inside_point = [&] {
            for (;;) {
                const Point2 p{0.5 + 9 * unit(rng), 0.5 + 9 * unit(rng)};
                if (p.x < 3.5 || p.x > 6.5 || p.y < 3.5 || p.y > 6.5) return p;
            }
        };
        for (int c = 0; c < count; ++c) {
            Point2 a = inside_point(), b = inside_point();
            const double hair = hairs[std::uniform_int_distribution<int>(0, 5)(rng)];
            switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
                case 0: break;  // free in the rock
                case 1: a = {hair, a.y}; break;  // tip a hair from the left edge (0: on it, the mouth)
                case 2: a = vertices[std::uniform_int_distribution<int>(0, 7)(rng)]; a.x += hair; break;  // at or near a vertex
                case 3:  // through a vertex: from the point past the vertex on
                    a = vertices[std::uniform_int_distribution<int>(0, 3)(rng)];
                    b = {a.x + (5 - a.x) * 0.6, a.y + (5 - a.y) * 0.3 + hair};
                    a = {a.x - (b.x - a.x) * 0.2, a.y - (b.y - a.y) * 0.2};
                    break;
                case 4:  // crossing or touching the last crack at a tiny angle
                    if (!cracks.empty()) {
                        const auto [p, q] = cracks.back();
                        const double angle = hair * 10;
                        const Point2 mid{(p.x + q.x) / 2, (p.y + q.y) / 2}, d{(q.x - p.x) / 2, (q.y - p.y) / 2};
                        a = {mid.x - d.x * std::cos(angle) + d.y * std::sin(angle), mid.y - d.y * std::cos(angle) - d.x * std::sin(angle)};
                        b = {mid.x + d.x * std::cos(angle) - d.y * std::sin(angle), mid.y + d.y * std::cos(angle) + d.x * std::sin(angle)};
                    }
                    break;
                default:  // ending on (or a hair from) the last crack
                    if (!cracks.empty()) {
                        const auto [p, q] = cracks.back();
                        const double t = unit(rng);
                        b = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) + hair};
                    }
                    break;
            }
            cracks.push_back({a, b});
        }
        json doc = json::parse(mcdda::test::square_model_json());
        doc["regions"][0]["holes"] = json::array({json::array({{4, 4}, {4, 6}, {6, 6}, {6, 4}})});
        for (const auto& [a, b] : cracks)
            doc["joints"].push_back({{"points", {{a.x, a.y}, {b.x, b.y}}}, {"joint_material", "joint"}});
        doc["mesh"]["max_elements"] = 30000;
        const std::string text = doc.dump(1);
        // MCDDA_FUZZ_DUMP=FILE: each model written there before it is tried (the last one is the
        // culprit of a crash).
        if (const char* dump = std::getenv("MCDDA_FUZZ_DUMP")) std::ofstream(dump) << text;
        Preprocessed p;
        ASSERT_NO_THROW({
            ReadResult r = read_model_text(text, {});
            if (r.model) p = preprocess_model(*r.model, PreprocessStage::Mesh);
            else p.diagnostics = r.diagnostics;
        }) << text;
        for (const Diagnostic& d : p.diagnostics)
            EXPECT_EQ(d.message.find("internal failure"), std::string::npos) << d.message << "\n" << text;
        if (!p.ok) {
            ++rejected;
            EXPECT_TRUE(has_errors(p.diagnostics)) << text;
            if (std::getenv("MCDDA_FUZZ_VERBOSE"))
                for (const Diagnostic& d : p.diagnostics) std::cout << "refused: " << d.message << "\n";
            continue;
        }
        ++meshed;
        if (p.statistics.elements > 8000 || m % 2 != 0) continue;
        ++solved;
        try {
            Simulation s(p);
            s.advance();
        } catch (const std::runtime_error& e) {
            EXPECT_GT(std::string(e.what()).size(), 10u) << text;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "unexpected " << e.what() << "\n" << text;
        }
    }
    EXPECT_GT(meshed, models / 3);  // many random cracks are fine models (the hairs below the
                                    // smallest feature are refused)
    std::cout << models << " models with random cracks: " << rejected << " refused with messages, " << meshed
              << " meshed, " << solved << " solved one step\n";
}
