#include "io/VtuWriter.hpp"

#include "io/AtomicFile.hpp"

#include <algorithm>
#include <charconv>
#include <ostream>
#include <string>
#include <type_traits>

namespace mcdda {

namespace {

/// Text output through a buffer with std::to_chars: the same characters as an ostream with
/// setprecision(10) (%.10g), several times faster (large result files are written every few
/// steps).
class TextBuffer {
public:
    explicit TextBuffer(std::ostream& out) : out_(out) { buffer_.reserve(capacity + 64); }
    ~TextBuffer() { flush(); }
    TextBuffer& operator<<(const char* text) {
        buffer_.append(text);
        return spill();
    }
    TextBuffer& operator<<(const std::string& text) {
        buffer_.append(text);
        return spill();
    }
    TextBuffer& operator<<(double value) {
        char digits[32];
        const auto end = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, 10).ptr;
        buffer_.append(digits, end);
        return spill();
    }
    template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
    TextBuffer& operator<<(Integer value) {
        char digits[24];
        const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
        buffer_.append(digits, end);
        return spill();
    }
    void flush() {
        out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }

private:
    static constexpr std::size_t capacity = 1 << 16;
    std::ostream& out_;
    std::string buffer_;
    TextBuffer& spill() {
        if (buffer_.size() >= capacity) flush();
        return *this;
    }
};

template <typename T>
void write_ints(TextBuffer& out, const char* name, const std::vector<T>& values) {
    out << "        <DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < values.size(); ++i)
        out << (i % 12 ? " " : "          ") << values[i] << (i % 12 == 11 ? "\n" : "");
    out << "\n        </DataArray>\n";
}

void write_field(TextBuffer& out, const VtuField& f) {
    out << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"" << f.components
        << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < f.values.size(); ++i)
        out << (i % 6 ? " " : "          ") << f.values[i] << (i % 6 == 5 ? "\n" : "");
    out << "\n        </DataArray>\n";
}

void write_field_data(TextBuffer& out, const std::vector<VtuField>& fields) {
    if (fields.empty()) return;
    out << "    <FieldData>\n";
    for (const VtuField& f : fields) {
        out << "      <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfTuples=\""
            << f.values.size() / std::max(1, f.components) << "\" NumberOfComponents=\"" << f.components
            << "\" format=\"ascii\">\n       ";
        for (double v : f.values) out << " " << v;
        out << "\n      </DataArray>\n";
    }
    out << "    </FieldData>\n";
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields) {
    write_file_atomically(path, [&](std::ostream& stream) {
        TextBuffer out(stream);
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            << "  <UnstructuredGrid>\n";
        write_field_data(out, fields.field_data);
        out << "    <Piece NumberOfPoints=\"" << mesh.nodes.size() << "\" NumberOfCells=\"" << mesh.triangles.size() << "\">\n"
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
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            out << (i % 12 ? " " : "          ") << points_per_cell * (i + 1) << (i % 12 == 11 ? "\n" : "");
        out << "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            out << (i % 24 ? " " : "          ") << cell_type << (i % 24 == 23 ? "\n" : "");
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

void write_vtp(const std::string& path, const PolyData& data) {
    write_file_atomically(path, [&](std::ostream& stream) {
        TextBuffer out(stream);
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            << "  <PolyData>\n";
        write_field_data(out, data.fields.field_data);
        out << "    <Piece NumberOfPoints=\"" << data.points.size() << "\" NumberOfVerts=\"" << data.vertices.size()
            << "\" NumberOfLines=\"" << data.lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
            << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const Point2& p : data.points) out << "          " << p.x << " " << p.y << " 0\n";
        out << "        </DataArray>\n      </Points>\n";
        auto cells = [&](const char* kind, std::size_t count, int per_cell, auto&& node) {
            out << "      <" << kind << ">\n        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
            for (std::size_t i = 0; i < count; ++i) {
                out << "         ";
                for (int k = 0; k < per_cell; ++k) out << " " << node(i, k);
                out << "\n";
            }
            out << "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
            for (std::size_t i = 0; i < count; ++i) out << "          " << per_cell * (i + 1) << "\n";
            out << "        </DataArray>\n      </" << kind << ">\n";
        };
        cells("Verts", data.vertices.size(), 1, [&](std::size_t i, int) { return data.vertices[i]; });
        cells("Lines", data.lines.size(), 2, [&](std::size_t i, int k) { return data.lines[i][k]; });
        out << "      <PointData>\n";
        for (const VtuField& f : data.fields.point_data) write_field(out, f);
        out << "      </PointData>\n      <CellData>\n";
        for (const VtuField& f : data.fields.cell_data) write_field(out, f);
        out << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
    });
}

}  // namespace mcdda
