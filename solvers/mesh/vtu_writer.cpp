// The VTK XML UnstructuredGrid format (VTK User's Guide, "VTK File Formats", XML; version 1.0 with
// 64-bit offsets), written as ASCII.
#include "mesh/vtu_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "mesh/element_topology.hpp"

namespace bb {
namespace {

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Rows of `values`, each padded to `width` components with zeros (a 2D vector gets z = 0).
void append_rows(std::string& out, const Eigen::MatrixXd& values, Eigen::Index width) {
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    for (Eigen::Index c = 0; c < width; ++c) {
      fmt::format_to(std::back_inserter(out), "{}", c < values.cols() ? values(i, c) : 0.0);
      out += c + 1 < width ? ' ' : '\n';
    }
  }
}

void append_array(std::string& out, const VtkArray& a, Eigen::Index rows) {
  if (a.values.rows() != rows)
    throw std::invalid_argument(fmt::format("VTK array '{}' has {} rows for {} points", a.name, a.values.rows(), rows));
  const Eigen::Index width = a.values.cols() == 2 ? 3 : a.values.cols();
  out += fmt::format(R"(<DataArray type="Float64" Name="{}" NumberOfComponents="{}")", xml_escape(a.name), width);
  for (size_t c = 0; c < a.component_names.size(); ++c)
    out += fmt::format(R"( ComponentName{}="{}")", c, xml_escape(a.component_names[c]));
  out += " format=\"ascii\">\n";
  append_rows(out, a.values, width);
  out += "</DataArray>\n";
}

void append_field_data(std::string& out, const VtkContent& content) {
  if (content.field_arrays.empty()) return;
  out += "<FieldData>\n";
  for (const VtkFieldArray& f : content.field_arrays) {
    out += fmt::format(R"(<DataArray type="Float64" Name="{}" NumberOfTuples="{}" format="ascii">)", xml_escape(f.name),
                       f.values.size());
    out += '\n';
    for (size_t i = 0; i < f.values.size(); ++i)
      fmt::format_to(std::back_inserter(out), "{}{}", i ? " " : "", f.values[i]);
    out += "\n</DataArray>\n";
  }
  out += "</FieldData>\n";
}

struct Cells {
  std::vector<long> connectivity, offsets, ids;
  std::vector<int> types;
};

void append_piece(std::string& out, const Eigen::MatrixXd& points, const Cells& cells, const VtkContent& content,
                  const std::vector<long>& node_ids) {
  const auto n = points.rows();
  out += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<PointData>\n", n, cells.types.size());
  if (!node_ids.empty()) {
    out += "<DataArray type=\"Int64\" Name=\"node_id\" format=\"ascii\">\n";
    for (const long id : node_ids) fmt::format_to(std::back_inserter(out), "{}\n", id);
    out += "</DataArray>\n";
  }
  for (const VtkArray& a : content.point_arrays) append_array(out, a, n);
  out += "</PointData>\n";
  if (!cells.ids.empty()) {
    out += "<CellData>\n<DataArray type=\"Int64\" Name=\"element_id\" format=\"ascii\">\n";
    for (const long id : cells.ids) fmt::format_to(std::back_inserter(out), "{}\n", id);
    out += "</DataArray>\n</CellData>\n";
  }
  out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  append_rows(out, points, 3);
  out += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const long c : cells.connectivity) fmt::format_to(std::back_inserter(out), "{}\n", c);
  out += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (const long o : cells.offsets) fmt::format_to(std::back_inserter(out), "{}\n", o);
  out += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const int t : cells.types) fmt::format_to(std::back_inserter(out), "{}\n", t);
  out += "</DataArray>\n</Cells>\n</Piece>\n";
}

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << text;
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

std::string grid(const Eigen::MatrixXd& points, const Cells& cells, const VtkContent& content,
                 const std::vector<long>& node_ids) {
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
  append_field_data(out, content);
  append_piece(out, points, cells, content, node_ids);
  out += "</UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const Mesh& mesh, const VtkContent& content) {
  Cells cells;
  long offset = 0;
  for (const ElementBlock& b : mesh.blocks) {
    const int type = topology(b.type).vtk_type;
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      for (Eigen::Index a = 0; a < b.conn.cols(); ++a) cells.connectivity.push_back(b.conn(e, a));
      offset += b.conn.cols();
      cells.offsets.push_back(offset);
      cells.types.push_back(type);
      cells.ids.push_back(b.ids[static_cast<size_t>(e)]);
    }
  }
  write_file(file, grid(mesh.coords, cells, content, mesh.node_ids));
}

void write_point_vtu(const std::filesystem::path& file, const Eigen::MatrixXd& points, const VtkContent& content) {
  constexpr int kVertex = 1;
  Cells cells;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    cells.connectivity.push_back(i);
    cells.offsets.push_back(i + 1);
    cells.types.push_back(kVertex);
  }
  write_file(file, grid(points, cells, content, {}));
}

void write_pvd(const std::filesystem::path& file, const std::vector<std::pair<double, std::string>>& steps) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n<Collection>\n";
  for (const auto& [time, name] : steps)
    out += fmt::format("<DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", time, xml_escape(name));
  out += "</Collection>\n</VTKFile>\n";
  write_file(file, out);
}

}  // namespace bb
