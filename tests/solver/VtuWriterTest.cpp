// VTU output: a well-formed file with the mesh and its cell data, written atomically.

#include "TestModels.hpp"
#include "io/AtomicFile.hpp"
#include "io/VtuWriter.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mcdda;
namespace fs = std::filesystem;

TEST(VtuWriter, WritesMeshWithBlockAndMaterialData) {
    const Preprocessed p = mcdda::test::preprocess_text(mcdda::test::square_model_json(),
                                                        {"/joints=[{\"points\": [[0,5],[10,5]]}]"});
    ASSERT_TRUE(p.ok);
    const fs::path dir = fs::temp_directory_path() / "mcdda-vtu-test";
    fs::create_directories(dir);
    const std::string path = (dir / "square.vtu").string();
    VtuFields fields;
    fields.point_data.push_back({"displacement", 3, std::vector<double>(3 * p.mesh.nodes.size(), 0.5)});
    write_vtu(path, p.mesh, fields);
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(p.mesh.nodes.size()) + "\""), std::string::npos);
    EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(p.mesh.triangles.size()) + "\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"block\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"material\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
    EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "temporary left behind";
    fs::remove_all(dir);
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileIntact) {
    const fs::path dir = fs::temp_directory_path() / "mcdda-atomic-test";
    fs::create_directories(dir);
    const std::string path = (dir / "model.json").string();
    write_file_atomically(path, [](std::ostream& out) { out << "original"; });
    EXPECT_THROW(write_file_atomically(path, [](std::ostream& out) {
                     out << "half-writ";
                     throw std::runtime_error("disk full");
                 }),
                 std::runtime_error);
    std::ifstream in(path);
    std::string content;
    std::getline(in, content);
    EXPECT_EQ(content, "original");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_THROW(write_file_atomically("/nonexistent-dir/x.vtu", [](std::ostream&) {}), std::runtime_error);
    fs::remove_all(dir);
}
