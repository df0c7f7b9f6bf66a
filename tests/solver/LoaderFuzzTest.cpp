// Hundreds of mutated example files through the whole pre-processing pipeline: whatever the
// input, the loader reports problems as diagnostics and never crashes or throws.

#include "TestModels.hpp"
#include "io/ModelReader.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

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

/// Mutates the parsed document in one of several ways.
void mutate_document(json& doc, std::mt19937& rng) {
    json* node = random_node(doc, rng);
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
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
                static const double factors[] = {-1.0, 0.0, 1e6, 1e-6, 1.0000001};
                *node = node->get<double>() * factors[std::uniform_int_distribution<int>(0, 4)(rng)];
            }
            break;
        case 4:  // an unknown key
            if (node->is_object()) (*node)["unexpected_key"] = 1;
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
    int runs = 0, rejected = 0, meshed = 0;
    // Meshing is capped so a mutation that asks for a huge mesh is refused quickly.
    const std::vector<std::string> cap = {"/mesh/max_elements=30000"};
    for (const std::string& file : mcdda::test::example_files()) {
        const std::string original = read_text(file);
        const json parsed = json::parse(original);
        for (int i = 0; i < 80; ++i, ++runs) {
            std::string text;
            if (i % 4 == 3) {
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
            if (!p.ok) {
                ++rejected;
                // A rejected model always says why.
                EXPECT_TRUE(has_errors(p.diagnostics)) << file << " mutation " << i;
                for (const Diagnostic& d : p.diagnostics) EXPECT_FALSE(d.message.empty());
            } else {
                ++meshed;
                EXPECT_GT(p.mesh.triangles.size(), 0u);
            }
        }
    }
    EXPECT_GE(runs, 500);
    EXPECT_GT(rejected, runs / 4);  // the mutations do hit real problems
    EXPECT_GT(meshed, 10);          // and some survive to be meshed
    std::cout << runs << " mutated models: " << rejected << " rejected with messages, " << meshed << " meshed\n";
}
