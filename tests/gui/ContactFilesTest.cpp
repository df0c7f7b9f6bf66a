// The staged jointed tunnel with roof bolts (examples/jointed-tunnel-staged.json) runs through all
// its stages, and what it writes opens in VTK as ParaView would open it: the contacts and bolts
// of every saved step as poly data, the steps with the excavated elements flagged and the stage
// in their field data, the bolt forces in the history.

#include "Preprocess.hpp"
#include "run/RunLoop.hpp"
#include "run/RunOutput.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

using namespace mcdda;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> collection_files(const fs::path& pvd) {
    const std::string text = slurp(pvd);
    std::vector<std::string> files;
    for (std::size_t at = text.find("file=\""); at != std::string::npos; at = text.find("file=\"", at + 1)) {
        const std::size_t begin = at + 6;
        files.push_back(text.substr(begin, text.find('"', begin) - begin));
    }
    return files;
}

}  // namespace

TEST(ContactFiles, StagedJointedTunnelWithBoltsOpensInVtk) {
    const Preprocessed p = preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/jointed-tunnel-staged.json", {});
    ASSERT_TRUE(p.ok);
    ASSERT_EQ(p.model.stages.size(), 4u);
    ASSERT_EQ(p.model.bolts.size(), 5u);
    Simulation simulation(p);
    const fs::path dir = fs::temp_directory_path() / ("mcdda-contact-files-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    RunEnd end;
    {
        RunOutput output(dir.string(), "tunnel");
        end = run_steps(simulation, &output, nullptr, nullptr);
        output.write_summary(&simulation, end.status, end.message);
    }
    ASSERT_TRUE(end.status == RunStatus::Completed || end.status == RunStatus::Unbalanced) << end.message;
    EXPECT_TRUE(simulation.finished());

    // Summary: every stage ran.
    const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
    ASSERT_EQ(summary["stages"].size(), 4u);
    for (const auto& stage : summary["stages"]) EXPECT_EQ(stage["status"], "completed") << stage.dump();

    // Contacts and bolts: every saved step's poly data reads, with the documented arrays.
    const auto files = collection_files(dir / "tunnel_contacts.pvd");
    ASSERT_GE(files.size(), 5u);
    double last_bolt_force = 0.0, largest_opening = 0.0;
    for (std::size_t k = 0; k < files.size(); ++k) {
        const std::string path = (dir / files[k]).string();
        vtkNew<vtkXMLPolyDataReader> reader;
        ASSERT_TRUE(reader->CanReadFile(path.c_str())) << path;
        reader->SetFileName(path.c_str());
        reader->Update();
        vtkPolyData* data = reader->GetOutput();
        ASSERT_NE(data, nullptr);
        if (k > 0) EXPECT_GT(data->GetNumberOfVerts(), 100) << path;  // the joints' contacts (none found before step 1)
        EXPECT_EQ(data->GetNumberOfLines(), 5) << path;    // the bolts
        for (const char* name : {"normal_force", "shear_force", "opening", "slip", "state", "vertex_block", "edge_block", "joint"})
            EXPECT_NE(data->GetPointData()->GetArray(name), nullptr) << name << " in " << path;
        // Contacts along the joints name them (the joint index of their edge).
        if (vtkDataArray* joints = data->GetPointData()->GetArray("joint"); joints && k > 0) {
            int on_joint = 0;
            for (vtkIdType i = 0; i < data->GetNumberOfVerts(); ++i) on_joint += joints->GetTuple1(i) >= 0;
            EXPECT_GT(on_joint, 100) << path;
        }
        // An open contact's opening is what it opened since it was found, not the gap of the
        // geometry it was found across (vertices at joint junctions face other blocks' edges up
        // to the search distance away): no more than the two faces moved apart. The tunnel's
        // rock moves less than 5 mm in all; before, openings of 0.2 m were reported.
        if (vtkDataArray* opening = data->GetPointData()->GetArray("opening")) {
            double widest = 0.0;
            for (vtkIdType i = 0; i < data->GetNumberOfVerts(); ++i) widest = std::max(widest, opening->GetTuple1(i));
            largest_opening = std::max(largest_opening, widest);
        }
        vtkDataArray* force = data->GetPointData()->GetArray("force");
        ASSERT_NE(force, nullptr);
        EXPECT_EQ(force->GetNumberOfComponents(), 3);
        vtkDataArray* bolts = data->GetCellData()->GetArray("bolt_force");
        ASSERT_NE(bolts, nullptr);
        const vtkIdType verts = data->GetNumberOfVerts();
        double largest = 0.0;
        for (vtkIdType b = 0; b < 5; ++b) largest = std::max(largest, bolts->GetTuple1(verts + b));
        if (k == 0) EXPECT_EQ(largest, 0.0);  // not installed yet
        last_bolt_force = largest;
    }
    double moved = 0.0;
    const Eigen::VectorXd& u = simulation.state().displacement;
    for (Eigen::Index i = 0; i + 1 < u.size(); i += 2) moved = std::max(moved, std::hypot(u[i], u[i + 1]));
    std::cout << "largest joint opening " << largest_opening << " m, largest displacement " << moved << " m\n";
    EXPECT_LE(largest_opening, 2.0 * moved + 1e-6);
    std::cout << "largest roof bolt force at the end: " << last_bolt_force << " N/m\n";
    EXPECT_GT(last_bolt_force, 0.0);  // the bench's excavation loads the bolts

    // The last step: the heading and bench gone, stage 4 in the field data.
    const auto steps = collection_files(dir / "tunnel.pvd");
    vtkNew<vtkXMLUnstructuredGridReader> grid_reader;
    grid_reader->SetFileName((dir / steps.back()).string().c_str());
    grid_reader->Update();
    vtkUnstructuredGrid* grid = grid_reader->GetOutput();
    vtkDataArray* present = grid->GetCellData()->GetArray("present");
    ASSERT_NE(present, nullptr);
    int absent = 0;
    for (vtkIdType c = 0; c < present->GetNumberOfTuples(); ++c) absent += present->GetTuple1(c) == 0.0;
    EXPECT_GT(absent, 50);
    vtkDataArray* stage = grid->GetFieldData()->GetArray("stage");
    ASSERT_NE(stage, nullptr);
    EXPECT_EQ(stage->GetTuple1(0), 4.0);

    // History: a force column per bolt, and the stage column reaching 4.
    std::istringstream history(slurp(dir / "history.csv"));
    std::string header, row, last;
    std::getline(history, header);
    EXPECT_NE(header.find("roof bolt 1:force"), std::string::npos) << header;
    while (std::getline(history, row)) last = row;
    EXPECT_EQ(last.substr(last.find(',', last.find(',') + 1) + 1, 2), "4,") << last;
    fs::remove_all(dir);
}
