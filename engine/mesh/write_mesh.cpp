#include "engine/mesh/write_mesh.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <fstream>
#include <string>

#include "engine/core/decimal_text.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/text_sink.hpp"

namespace lastcut {
namespace {

std::ofstream open_binary(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw EngineError("cannot write " + path.string());
  return out;
}

void finish(std::ofstream& out, const std::filesystem::path& path) {
  out.flush();
  if (!out) throw EngineError("cannot write " + path.string() + " (disk full?)");
}

// Values are stored little endian; every platform we build for is little endian.
template <typename T>
void put(std::ofstream& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.write(bytes, sizeof(T));
}

// "x y z" of vertex v with 6 decimals (1 nm in mm), as "%.6f" writes them.
void append_vertex(std::string& text, const Eigen::MatrixXd& V, Eigen::Index v) {
  for (int c = 0; c < 3; ++c) {
    if (c > 0) text += ' ';
    append_fixed(text, V(v, c), 6);
  }
}

void append_triangle(std::string& text, const Eigen::MatrixXi& F, Eigen::Index f, int index_base) {
  for (int c = 0; c < 3; ++c) {
    text += ' ';
    append_integer(text, F(f, c) + index_base);
  }
}

void write_off_file(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out = open_binary(path);
  {
    TextSink sink(out);
    sink.text() += "OFF\n";
    append_integer(sink.text(), mesh.vertex_count());
    sink.text() += ' ';
    append_integer(sink.text(), mesh.triangle_count());
    sink.text() += " 0";
    sink.end_line();
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      append_vertex(sink.text(), mesh.V, v);
      sink.end_line();
    }
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      sink.text() += '3';
      append_triangle(sink.text(), mesh.F, f, 0);
      sink.end_line();
    }
  }
  finish(out, path);
}

void write_ply_file(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out = open_binary(path);
  out << "ply\nformat binary_little_endian 1.0\ncomment lastcut, units mm\n"
      << "element vertex " << mesh.vertex_count() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.triangle_count() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    for (int c = 0; c < 3; ++c) put(out, static_cast<float>(mesh.V(v, c)));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    put(out, static_cast<std::uint8_t>(3));
    for (int c = 0; c < 3; ++c) put(out, static_cast<std::int32_t>(mesh.F(f, c)));
  }
  finish(out, path);
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

void write_stl_binary(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out = open_binary(path);
  std::array<char, 80> header{};
  const char title[] = "lastcut binary STL, units mm";
  std::memcpy(header.data(), title, sizeof title - 1);
  out.write(header.data(), header.size());
  put(out, static_cast<std::uint32_t>(mesh.F.rows()));
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) put(out, static_cast<float>(normals(f, c)));
    for (int corner = 0; corner < 3; ++corner)
      for (int c = 0; c < 3; ++c) put(out, static_cast<float>(mesh.V(mesh.F(f, corner), c)));
    put(out, static_cast<std::uint16_t>(0));
  }
  finish(out, path);
}

void write_mesh(const std::filesystem::path& path, const TriMesh& mesh) {
  const std::string extension = lower_extension(path);
  if (extension == ".stl") return write_stl_binary(path, mesh);
  if (extension == ".obj") return write_obj(path, mesh);
  if (extension == ".ply") return write_ply_file(path, mesh);
  if (extension == ".off") return write_off_file(path, mesh);
  throw EngineError("cannot write mesh format '" + extension + "' of " + path.filename().string() +
                    " (use .stl, .obj, .ply or .off)");
}

}  // namespace lastcut
