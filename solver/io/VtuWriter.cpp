#include "io/VtuWriter.hpp"

#include "io/AtomicFile.hpp"

#include <iomanip>
#include <ostream>

namespace mcdda {

namespace {

template <typename T>
void write_ints(std::ostream& out, const char* name, const std::vector<T>& values) {
    out << "        <DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < values.size(); ++i) out << (i % 12 ? " " : "          ") << values[i] << (i % 12 == 11 ? "\n" : "");
    out << "\n        </DataArray>\n";
}

void write_field(std::ostream& out, const VtuField& f) {
    out << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"" << f.components
        << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < f.values.size(); ++i) out << (i % 6 ? " " : "          ") << f.values[i] << (i % 6 == 5 ? "\n" : "");
    out << "\n        </DataArray>\n";
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << std::setprecision(10);
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            << "  <UnstructuredGrid>\n"
            << "    <Piece NumberOfPoints=\"" << mesh.nodes.size() << "\" NumberOfCells=\"" << mesh.triangles.size() << "\">\n"
            << "      <Points>\n"
            << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const Point2& p : mesh.nodes) out << "          " << p.x << " " << p.y << " 0\n";
        out << "        </DataArray>\n      </Points>\n      <Cells>\n"
            << "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
        // Six-node triangles are VTK_QUADRATIC_TRIANGLE (22): corners, then the midside nodes of
        // edges 0-1, 1-2, 2-0, which is Mesh::midside's order. Three-node ones are VTK_TRIANGLE (5).
        const bool quadratic = mesh.quadratic();
        const int points_per_cell = quadratic ? 6 : 3, cell_type = quadratic ? 22 : 5;
        for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
            const auto& t = mesh.triangles[e];
            out << "          " << t[0] << " " << t[1] << " " << t[2];
            if (quadratic) out << " " << mesh.midside[e][0] << " " << mesh.midside[e][1] << " " << mesh.midside[e][2];
            out << "\n";
        }
        out << "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) out << (i % 12 ? " " : "          ") << points_per_cell * (i + 1) << (i % 12 == 11 ? "\n" : "");
        out << "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) out << (i % 24 ? " " : "          ") << cell_type << (i % 24 == 23 ? "\n" : "");
        out << "\n        </DataArray>\n      </Cells>\n";
        out << "      <PointData>\n";
        for (const VtuField& f : fields.point_data) write_field(out, f);
        out << "      </PointData>\n      <CellData Scalars=\"block\">\n";
        write_ints(out, "block", mesh.triangle_block);
        write_ints(out, "material", mesh.triangle_material);
        for (const VtuField& f : fields.cell_data) write_field(out, f);
        out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    });
}

}  // namespace mcdda
