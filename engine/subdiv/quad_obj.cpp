#include "engine/subdiv/quad_obj.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/decimal_text.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/text_sink.hpp"

namespace lastcut {
namespace {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

double parse_coordinate(std::string_view word, const std::string& where) {
  const std::string text(word);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw EngineError(where + ": '" + text + "' is not a finite coordinate");
  }
  return value;
}

// "12", "12/3", "12//4", "-1": the vertex index (0-based) of a face corner.
int parse_corner(std::string_view word, long long vertex_count, const std::string& where) {
  const std::string_view index_text = word.substr(0, word.find('/'));
  long long index = 0;
  const auto [end, error] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
  if (error != std::errc() || end != index_text.data() + index_text.size() || index == 0) {
    throw EngineError(where + ": '" + std::string(word) + "' is not a vertex index");
  }
  const long long zero_based = index > 0 ? index - 1 : vertex_count + index;
  if (zero_based < 0 || zero_based >= vertex_count) {
    throw EngineError(where + ": vertex " + std::to_string(index) + " does not exist (" + std::to_string(vertex_count) +
                      " vertices so far)");
  }
  return static_cast<int>(zero_based);
}

}  // namespace

QuadMesh read_quad_obj(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read " + path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<double> positions;
  std::vector<int> corners;
  long long line_number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line_number;
    const std::vector<std::string_view> words = split_words(std::string_view(text).substr(start, end - start));
    start = end + 1;
    if (words.empty()) continue;
    const std::string where = path.filename().string() + " line " + std::to_string(line_number);
    if (words[0] == "v") {
      if (words.size() < 4) throw EngineError(where + ": a vertex needs x y z");
      for (int c = 1; c <= 3; ++c) positions.push_back(parse_coordinate(words[static_cast<size_t>(c)], where));
    } else if (words[0] == "f") {
      if (words.size() != 5) {
        throw EngineError(where + ": a face with " + std::to_string(words.size() - 1) +
                          " corners; subdivide needs a quad mesh (4 corners per face)");
      }
      const auto vertex_count = static_cast<long long>(positions.size() / 3);
      for (size_t c = 1; c <= 4; ++c) corners.push_back(parse_corner(words[c], vertex_count, where));
    }
  }
  if (corners.empty()) throw EngineError(path.filename().string() + " has no quads");
  QuadMesh mesh;
  mesh.V = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      positions.data(), static_cast<Eigen::Index>(positions.size() / 3), 3);
  mesh.Q = Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>>(
      corners.data(), static_cast<Eigen::Index>(corners.size() / 4), 4);
  return mesh;
}

void write_quad_obj(const std::filesystem::path& path, const QuadMesh& mesh) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw EngineError("cannot write " + path.string());
  {
    TextSink sink(out);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      sink.text() += 'v';
      for (int c = 0; c < 3; ++c) {
        sink.text() += ' ';
        append_fixed(sink.text(), mesh.V(v, c), 6);
      }
      sink.end_line();
    }
    for (Eigen::Index q = 0; q < mesh.Q.rows(); ++q) {
      sink.text() += 'f';
      for (int c = 0; c < 4; ++c) {
        sink.text() += ' ';
        append_integer(sink.text(), mesh.Q(q, c) + 1);
      }
      sink.end_line();
    }
  }
  out.flush();
  if (!out) throw EngineError("cannot write " + path.string() + " (disk full?)");
}

}  // namespace lastcut
