// The VTK XML UnstructuredGrid format (VTK User's Guide, "VTK File Formats", XML; version 1.0 with
// 64-bit headers). Arrays are inline binary: base64 of a UInt64 byte count, then base64 of the
// little-endian values, each encoded on its own as VTK's writer does: bit for bit, 58 % of the size
// of ASCII, and on 20 modes of 100 000 nodes 67 ms against ASCII's 1.8 s (bench/bench_model_io.cpp).
#include "mesh/vtu_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "mesh/element_topology.hpp"

namespace bb {
namespace vtu_writer_impl {
namespace {

static_assert(std::endian::native == std::endian::little, "the .vtu files say LittleEndian");

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// RFC 4648 base64 with padding.
void append_base64(std::string& out, const unsigned char* data, size_t size) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const size_t start = out.size();
  out.resize(start + (size + 2) / 3 * 4);
  char* p = out.data() + start;
  size_t i = 0;
  for (; i + 3 <= size; i += 3) {
    const uint32_t v = (uint32_t{data[i]} << 16) | (uint32_t{data[i + 1]} << 8) | data[i + 2];
    *p++ = kAlphabet[(v >> 18) & 63];
    *p++ = kAlphabet[(v >> 12) & 63];
    *p++ = kAlphabet[(v >> 6) & 63];
    *p++ = kAlphabet[v & 63];
  }
  if (i < size) {
    const uint32_t v = (uint32_t{data[i]} << 16) | (i + 1 < size ? uint32_t{data[i + 1]} << 8 : 0u);
    *p++ = kAlphabet[(v >> 18) & 63];
    *p++ = kAlphabet[(v >> 12) & 63];
    *p++ = i + 1 < size ? kAlphabet[(v >> 6) & 63] : '=';
    *p++ = '=';
  }
}

// One DataArray: `attributes` after the type, the values as VTK's binary inline data, streamed
// through a scratch buffer (a 100 000-node file's 80 MB never sit in memory at once).
template <class T>
void append_data_array(std::ostream& out, const char* type, const std::string& attributes,
                       const std::vector<T>& values) {
  out << fmt::format("<DataArray type=\"{}\"{} format=\"binary\">\n", type, attributes);
  const uint64_t bytes = values.size() * sizeof(T);
  std::string encoded;
  append_base64(encoded, reinterpret_cast<const unsigned char*>(&bytes), sizeof bytes);
  constexpr size_t kChunk = 3 * (1 << 18);  // a multiple of 3: no padding inside the data
  const auto* data = reinterpret_cast<const unsigned char*>(values.data());
  for (size_t at = 0; at < bytes; at += kChunk) {
    append_base64(encoded, data + at, std::min<size_t>(kChunk, bytes - at));
    out << encoded;
    encoded.clear();
  }
  out << encoded << "\n</DataArray>\n";
}

// Rows of `values`, each padded to `width` components with zeros (a 2D vector gets z = 0).
std::vector<double> rows_of(const Eigen::MatrixXd& values, Eigen::Index width) {
  std::vector<double> out(static_cast<size_t>(values.rows() * width), 0.0);
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (Eigen::Index c = 0; c < std::min(width, values.cols()); ++c)
      out[static_cast<size_t>(i * width + c)] = values(i, c);
  return out;
}

void append_array(std::ostream& out, const VtkArray& a, Eigen::Index rows) {
  if (a.values.rows() != rows)
    throw std::invalid_argument(fmt::format("VTK array '{}' has {} rows for {} points", a.name, a.values.rows(), rows));
  const Eigen::Index width = a.values.cols() == 2 ? 3 : a.values.cols();
  std::string attributes = fmt::format(R"( Name="{}" NumberOfComponents="{}")", xml_escape(a.name), width);
  for (size_t c = 0; c < a.component_names.size(); ++c)
    attributes += fmt::format(R"( ComponentName{}="{}")", c, xml_escape(a.component_names[c]));
  append_data_array(out, "Float64", attributes, rows_of(a.values, width));
}

void append_field_data(std::ostream& out, const VtkContent& content) {
  if (content.field_arrays.empty()) return;
  out << "<FieldData>\n";
  for (const VtkFieldArray& f : content.field_arrays)
    append_data_array(out, "Float64",
                      fmt::format(R"( Name="{}" NumberOfTuples="{}")", xml_escape(f.name), f.values.size()), f.values);
  out << "</FieldData>\n";
}

struct Cells {
  std::vector<int64_t> connectivity, offsets, ids;
  std::vector<uint8_t> types;
};

void append_piece(std::ostream& out, const Eigen::MatrixXd& points, const Cells& cells, const VtkContent& content,
                  const std::vector<long>& node_ids) {
  const auto n = points.rows();
  out << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<PointData>\n", n, cells.types.size());
  if (!node_ids.empty())
    append_data_array(out, "Int64", R"( Name="node_id")", std::vector<int64_t>(node_ids.begin(), node_ids.end()));
  for (const VtkArray& a : content.point_arrays) append_array(out, a, n);
  out << "</PointData>\n";
  if (!cells.ids.empty()) {
    out << "<CellData>\n";
    append_data_array(out, "Int64", R"( Name="element_id")", cells.ids);
    out << "</CellData>\n";
  }
  out << "<Points>\n";
  append_data_array(out, "Float64", R"( NumberOfComponents="3")", rows_of(points, 3));
  out << "</Points>\n<Cells>\n";
  append_data_array(out, "Int64", R"( Name="connectivity")", cells.connectivity);
  append_data_array(out, "Int64", R"( Name="offsets")", cells.offsets);
  append_data_array(out, "UInt8", R"( Name="types")", cells.types);
  out << "</Cells>\n</Piece>\n";
}

void write_grid(const std::filesystem::path& file, const Eigen::MatrixXd& points, const Cells& cells,
                const VtkContent& content, const std::vector<long>& node_ids) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
  append_field_data(out, content);
  append_piece(out, points, cells, content, node_ids);
  out << "</UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

}  // namespace
}  // namespace vtu_writer_impl

void write_vtu(const std::filesystem::path& file, const Mesh& mesh, const VtkContent& content) {
  using namespace vtu_writer_impl;  // this file's helpers, in this scope only (unity builds)
  Cells cells;
  int64_t offset = 0;
  for (const ElementBlock& b : mesh.blocks) {
    const auto type = static_cast<uint8_t>(topology(b.type).vtk_type);
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      for (Eigen::Index a = 0; a < b.conn.cols(); ++a) cells.connectivity.push_back(b.conn(e, a));
      offset += b.conn.cols();
      cells.offsets.push_back(offset);
      cells.types.push_back(type);
      cells.ids.push_back(b.ids[static_cast<size_t>(e)]);
    }
  }
  write_grid(file, mesh.coords, cells, content, mesh.node_ids);
}

void write_point_vtu(const std::filesystem::path& file, const Eigen::MatrixXd& points, const VtkContent& content) {
  using namespace vtu_writer_impl;  // this file's helpers, in this scope only (unity builds)
  constexpr uint8_t kVertex = 1;
  Cells cells;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    cells.connectivity.push_back(i);
    cells.offsets.push_back(i + 1);
    cells.types.push_back(kVertex);
  }
  write_grid(file, points, cells, content, {});
}

void write_pvd(const std::filesystem::path& file, const std::vector<std::pair<double, std::string>>& steps) {
  using namespace vtu_writer_impl;  // this file's helpers, in this scope only (unity builds)
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n<Collection>\n";
  for (const auto& [time, name] : steps)
    out += fmt::format("<DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", time, xml_escape(name));
  out += "</Collection>\n</VTKFile>\n";
  std::ofstream stream(file, std::ios::binary);
  if (!stream || !(stream << out)) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace bb
