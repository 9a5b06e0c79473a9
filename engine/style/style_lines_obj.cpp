#include "engine/style/style_lines_obj.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

std::string at(const std::filesystem::path& path, int line_number) {
  return path.filename().string() + " line " + std::to_string(line_number) + ": ";
}

double number(const std::string& word, const std::filesystem::path& path, int line_number) {
  double value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
    throw EngineError(at(path, line_number) + "'" + word + "' is not a number");
  return value;
}

}  // namespace

std::vector<StyleLine> read_style_lines_obj(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw EngineError("cannot read style lines " + path.string());
  std::vector<Eigen::Vector3d> vertices;
  std::vector<StyleLine> lines;
  std::set<std::string> names;
  std::string current_name, text;
  int line_number = 0;
  while (std::getline(in, text)) {
    ++line_number;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string record;
    if (!(words >> record) || record[0] == '#') continue;
    if (record == "v") {
      std::string x, y, z;
      if (!(words >> x >> y >> z)) throw EngineError(at(path, line_number) + "a vertex needs three coordinates");
      vertices.emplace_back(number(x, path, line_number), number(y, path, line_number), number(z, path, line_number));
    } else if (record == "o" || record == "g") {
      current_name.clear();  // a bare `o` names nothing: the lines after it are numbered
      std::getline(words >> std::ws, current_name);
      while (!current_name.empty() && std::isspace(static_cast<unsigned char>(current_name.back()))) current_name.pop_back();
    } else if (record == "f") {
      throw EngineError(at(path, line_number) + "a face: style lines are polylines (l records), not a surface");
    } else if (record == "l") {
      StyleLine line;
      line.name = current_name.empty() ? "line " + std::to_string(lines.size() + 1) : current_name;
      std::string word;
      while (words >> word) {
        const std::string index_text = word.substr(0, word.find('/'));  // "l 1/1 2/2" carries texture indices
        const double index = number(index_text, path, line_number);
        const long long count = static_cast<long long>(vertices.size());
        // Checked as a number before it becomes an integer: 1e300 fits no long long (undefined behaviour).
        if (index != std::floor(index) || index == 0 || std::abs(index) > static_cast<double>(count))
          throw EngineError(at(path, line_number) + "vertex index " + index_text + " is not one of the " +
                            std::to_string(count) + " vertices so far");
        const long long resolved = index < 0 ? count + static_cast<long long>(index) : static_cast<long long>(index) - 1;
        line.points_mm.push_back(vertices[static_cast<std::size_t>(resolved)]);
      }
      if (line.points_mm.size() < 2) throw EngineError(at(path, line_number) + "a line needs at least two points");
      if (!names.insert(line.name).second)
        throw EngineError(at(path, line_number) + "a second line named " + line.name + ": each line needs its own name");
      lines.push_back(std::move(line));
    }
  }
  if (lines.empty()) throw EngineError(path.filename().string() + ": no lines (l records) in the file");
  return lines;
}

void write_style_lines_obj(const std::filesystem::path& path, const std::vector<StyleLine>& lines) {
  std::string text = "# lastcut style lines (mm)\n";
  std::size_t written = 0;
  char number_text[96];
  for (const StyleLine& line : lines) {
    text += "o " + line.name + "\n";
    for (const Eigen::Vector3d& p : line.points_mm) {
      std::snprintf(number_text, sizeof number_text, "v %.4f %.4f %.4f\n", p.x(), p.y(), p.z());
      text += number_text;
    }
    text += "l";
    for (std::size_t i = 0; i < line.points_mm.size(); ++i) text += " " + std::to_string(written + i + 1);
    text += "\n";
    written += line.points_mm.size();
  }
  if (const Status status = write_file_durably(path, text); !status) throw EngineError(status.error());
}

}  // namespace lastcut
