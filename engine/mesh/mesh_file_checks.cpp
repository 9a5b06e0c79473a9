#include "engine/mesh/mesh_file_checks.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/ply_records.hpp"
#include "engine/mesh/text_tokens.hpp"

namespace lastcut {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw EngineError("cannot read " + path.string() + ": " + std::strerror(errno));
  std::string text(static_cast<size_t>(in.tellg()), '\0');
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  return text;
}

// A vertex value as a float, correctly rounded as OpenMesh's reader (istream >> float) rounds it; a
// leading '+' is allowed as there. "" when read, else why not (in the words of a refusal).
const char* read_float(std::string_view token, float& value) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (end != token.data() + token.size() || error == std::errc::invalid_argument) return "is not a number";
  if (error == std::errc::result_out_of_range) return "is out of range";
  return "";
}

std::string read_prefix(const std::filesystem::path& path, size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read " + path.string() + ": " + std::strerror(errno));
  std::string prefix(bytes, '\0');
  in.read(prefix.data(), static_cast<std::streamsize>(bytes));
  prefix.resize(static_cast<size_t>(in.gcount()));
  return prefix;
}

void check_cap(long long faces, int max_triangles, const std::filesystem::path& path) {
  if (faces > max_triangles)
    throw EngineError("too many triangles in " + path.filename().string() + ": " + std::to_string(faces) + " (limit " +
                      std::to_string(max_triangles) + ")");
}

bool starts_with_solid(const std::string& prefix) {
  size_t start = 0;
  while (start < prefix.size() && std::isspace(static_cast<unsigned char>(prefix[start]))) ++start;
  return lower(prefix.substr(start, 5)) == "solid";
}

// OpenMesh drops the faces of a NaN corner silently; an operator must hear the file is broken.
void check_binary_stl_numbers(const std::filesystem::path& path, std::uint32_t count) {
  const std::string bytes = read_all(path);  // size already checked: 84 + 50 count
  for (std::uint32_t f = 0; f < count; ++f) {
    const char* record = bytes.data() + 84 + 50 * static_cast<size_t>(f);
    for (int k = 3; k < 12; ++k) {
      float value = 0.0f;
      std::memcpy(&value, record + 4 * k, 4);
      if (!std::isfinite(value))
        throw EngineError("coordinates that are not numbers (NaN or infinite) in triangle " + std::to_string(f + 1) + " of " +
                          path.filename().string());
    }
  }
}

// Counts the ASCII STL keywords; a complete file has as many endfacet as facet, three vertex
// lines per facet and an endsolid.
long long check_ascii_stl(const std::filesystem::path& path, int max_triangles) {
  const std::string text = read_all(path);
  long long facets = 0, endfacets = 0, vertices = 0;
  bool endsolid = false;
  size_t i = 0;
  const size_t n = text.size();
  while (i < n) {
    while (i < n && !std::isalpha(static_cast<unsigned char>(text[i]))) ++i;
    const size_t start = i;
    while (i < n && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const size_t length = i - start;
    if (length < 3 || length > 8) continue;
    const std::string word = lower(text.substr(start, length));
    if (word == "facet") {
      ++facets;
      check_cap(facets, max_triangles, path);
    } else if (word == "endfacet") {
      ++endfacets;
    } else if (word == "vertex") {
      ++vertices;
    } else if (word == "endsolid") {
      endsolid = true;
    }
    if (length <= 4 && (word == "nan" || word == "inf" || word == "-nan" || word == "-inf"))
      throw EngineError("coordinates that are not numbers (NaN or infinite) in ASCII STL " + path.filename().string());
  }
  if (facets == 0) throw EngineError("no triangles in ASCII STL " + path.filename().string());
  if (!endsolid || endfacets != facets || vertices != 3 * facets)
    throw EngineError("truncated ASCII STL " + path.filename().string() + ": ends inside facet " +
                      std::to_string(endfacets + 1) + (endsolid ? "" : " (no endsolid)"));
  return facets;
}

// "truncated PLY scan.ply: 120 of 120 vertices, 80 of 236 faces"
EngineError truncated_error(const char* format_name, const std::filesystem::path& path, const MeshFileFacts& facts,
                            long long vertices_read, long long faces_read) {
  return EngineError(std::string("truncated ") + format_name + " " + path.filename().string() + ": " +
                     std::to_string(vertices_read) + " of " + std::to_string(facts.declared_vertices) + " vertices, " +
                     std::to_string(faces_read) + " of " + std::to_string(facts.declared_faces) + " faces");
}

MeshFileFacts facts_of(MeshFileFormat format) {
  static constexpr const char* kNames[] = {"binary STL", "ASCII STL", "OBJ", "PLY", "OFF"};
  MeshFileFacts facts;
  facts.format = format;
  facts.format_name = kNames[static_cast<int>(format)];
  return facts;
}

MeshFileFacts check_stl(const std::filesystem::path& path, std::uintmax_t size, int max_triangles) {
  const std::string prefix = read_prefix(path, 84);
  if (size >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, prefix.data() + 80, 4);
    if (size == 84 + 50ull * count) {
      MeshFileFacts facts = facts_of(MeshFileFormat::BinaryStl);
      facts.declared_faces = count;
      if (count == 0) throw EngineError("no triangles in binary STL " + path.filename().string());
      check_cap(count, max_triangles, path);
      check_binary_stl_numbers(path, count);
      return facts;
    }
    if (!starts_with_solid(prefix)) {
      check_cap(count, max_triangles, path);
      if (size < 84 + 50ull * count)
        throw EngineError("truncated binary STL " + path.filename().string() + ": " + std::to_string((size - 84) / 50) +
                          " of " + std::to_string(count) + " triangles");
      throw EngineError("binary STL " + path.filename().string() + " is longer than its " + std::to_string(count) +
                        " triangles (" + std::to_string(size) + " bytes)");
    }
  } else if (!starts_with_solid(prefix)) {
    throw EngineError("truncated binary STL " + path.filename().string() + ": " + std::to_string(size) +
                      " bytes, the header alone is 84");
  }
  MeshFileFacts facts = facts_of(MeshFileFormat::AsciiStl);
  facts.declared_faces = check_ascii_stl(path, max_triangles);
  return facts;
}

// True for a face record ("f ...", leading blanks allowed) with a corner whose vertex number is
// missing ("/2", "//3"). The OBJ format requires it; OpenMesh's reader asserts on it and aborts
// the whole process (found by tests/fuzz/obj_fuzz.cpp), so it never gets such a line.
bool face_corner_without_vertex(const std::string& line) {
  auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  size_t at = 0;
  while (at < line.size() && blank(line[at])) ++at;
  if (at + 1 >= line.size() || line[at] != 'f' || !blank(line[at + 1])) return false;
  for (at += 1; at < line.size(); ++at) {
    if (!blank(line[at - 1]) || blank(line[at])) continue;  // not the start of a corner
    if (line[at] == '/') return true;
  }
  return false;
}

MeshFileFacts check_obj(const std::filesystem::path& path, int max_triangles) {
  MeshFileFacts facts = facts_of(MeshFileFormat::Obj);
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long faces = 0, vertices = 0, line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.size() >= 2 && line[0] == 'f' && std::isspace(static_cast<unsigned char>(line[1]))) ++faces;
    if (line.size() >= 2 && line[0] == 'v' && std::isspace(static_cast<unsigned char>(line[1]))) ++vertices;
    if (face_corner_without_vertex(line))
      throw EngineError("a face on line " + std::to_string(line_number) + " of OBJ " + path.filename().string() +
                        " has a corner without a vertex number (like '/1')");
  }
  check_cap(faces, max_triangles, path);
  if (faces == 0) throw EngineError("no faces in OBJ " + path.filename().string());
  facts.declared_faces = faces;
  facts.declared_vertices = vertices;
  return facts;
}

MeshFileFacts check_ply(const std::filesystem::path& path, int max_triangles) {
  MeshFileFacts facts = facts_of(MeshFileFormat::Ply);
  const PlyHeader header = read_ply_header(path);
  for (const PlyElement& element : header.elements) {
    if (element.name == "face") facts.declared_faces = element.declared_count;
    if (element.name == "vertex") facts.declared_vertices = element.declared_count;
  }
  if (facts.declared_faces <= 0) throw EngineError("no faces in PLY " + path.filename().string());
  check_cap(facts.declared_faces, max_triangles, path);
  std::vector<long long> records;
  try {
    records = count_ply_records(read_all(path), header);
  } catch (const EngineError& error) {
    throw EngineError("unreadable PLY " + path.filename().string() + ": " + error.what());
  }
  long long vertices = 0, faces = 0;
  bool complete = true;
  for (size_t e = 0; e < header.elements.size(); ++e) {
    complete = complete && records[e] == header.elements[e].declared_count;
    if (header.elements[e].name == "vertex") vertices = records[e];
    if (header.elements[e].name == "face") faces = records[e];
  }
  if (!complete) throw truncated_error("PLY", path, facts, vertices, faces);
  return facts;
}

// Reads the vertex and face records after the OFF header into `records` (counts them only when it
// is null), reading the whole file at once: line-by-line streams are far too slow here.
void check_off_records(const std::filesystem::path& path, const MeshFileFacts& facts, SoupImporter* records) {
  const std::string name = path.filename().string();
  const std::string text = read_all(path);
  TextTokens tokens(text, true);
  // The header line, then the three counts.
  tokens.skip_line();
  for (int k = 0; k < 3; ++k) tokens.next();
  // A file must mean one thing to every reader (OpenMesh reads the rest as one stream of numbers
  // with no per-line structure, where a value read only in part, "7-4", shifts everything after
  // it, found by tests/fuzz/off_fuzz.cpp). So every vertex value must be a number as a whole, the
  // rest of a vertex line is skipped (a colour), every face is a plain corner count (at most the
  // vertex count), as many plain vertex numbers and nothing else.
  // Room for what the file can hold, not for what its header claims: "OFF 444444202 7 2" made the reader
  // reserve 10 GB (found by tests/fuzz/off_fuzz.cpp). The shortest vertex line is "0 0 0\n", the shortest
  // face "3 0 1 2\n"; a header that claims more is refused as truncated below.
  constexpr long long kShortestVertexBytes = 6, kShortestFaceBytes = 8;
  const long long size = static_cast<long long>(text.size());
  if (records != nullptr)
    records->reserve(static_cast<unsigned>(std::min(facts.declared_vertices, size / kShortestVertexBytes)), 0,
                     static_cast<unsigned>(std::min(facts.declared_faces, size / kShortestFaceBytes)));
  const long long values_needed = 3 * facts.declared_vertices;
  long long values = 0;
  OpenMesh::Vec3f point;
  for (std::string_view value; values < values_needed && !(value = tokens.next()).empty();) {
    if (const std::string_view refusal = read_float(value, point[static_cast<int>(values % 3)]); !refusal.empty())
      throw EngineError("unreadable OFF " + name + ": vertex value '" + std::string(value.substr(0, 20)) + "' " +
                        std::string(refusal));
    if (++values % 3 == 0) {
      if (records != nullptr) records->add_vertex(point);
      tokens.skip_line();
    }
  }
  long long faces = 0;
  SoupImporter::VHandles corners;
  for (; faces < facts.declared_faces; ++faces) {
    const std::string_view corners_text = tokens.next();
    if (corners_text.empty()) break;
    const std::string face = "unreadable OFF " + name + ": face " + std::to_string(faces + 1);
    long long corner_count = 0;
    if (!TextTokens::read_count(corners_text, facts.declared_vertices, corner_count))
      throw EngineError(face + " has '" + std::string(corners_text.substr(0, 20)) + "' for its number of corners");
    corners.clear();
    long long read = 0;
    for (std::string_view corner; read < corner_count && !(corner = tokens.next()).empty(); ++read) {
      long long index = 0;
      if (!TextTokens::read_count(corner, std::numeric_limits<int>::max(), index))
        throw EngineError(face + " has '" + std::string(corner.substr(0, 20)) + "' for a vertex number");
      corners.emplace_back(static_cast<int>(index));
    }
    if (read < corner_count) break;
    const std::string_view rest = tokens.rest_of_line();
    const size_t used = rest.find_first_not_of(" \t\r\v\f");
    if (used != std::string_view::npos && rest[used] != '#')
      throw EngineError(face + " has more values than its corners (face colours are not read)");
    if (records != nullptr) records->add_face(corners);
  }
  if (values < values_needed || faces < facts.declared_faces)
    throw truncated_error("OFF", path, facts, values / 3, faces);
}

MeshFileFacts check_off(const std::filesystem::path& path, int max_triangles, SoupImporter* records) {
  MeshFileFacts facts = facts_of(MeshFileFormat::Off);
  std::ifstream in(path, std::ios::binary);
  // OpenMesh takes the whole first line as the header and reads the counts after it, as unsigned
  // ints: a count on the header line is never read, and "-3" becomes 4294967293 vertices to reserve
  // (found by tests/fuzz/off_fuzz.cpp). So the counts are taken from the same place here.
  std::string header_line, keyword;
  std::getline(in, header_line);
  std::istringstream header_words(header_line);
  if (!(header_words >> keyword) || keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    throw EngineError("not an OFF file: " + path.filename().string() + " does not start with 'OFF'");
  if (header_line.find("BINARY") != std::string::npos)
    throw EngineError("binary OFF is not read (" + path.filename().string() + "): export ASCII OFF, PLY or STL");
  // Variants (COFF, NOFF, STOFF, ...) carry more values per vertex, which the record check below
  // does not count.
  if (keyword != "OFF")
    throw EngineError("OFF variant '" + keyword.substr(0, 20) + "' is not read (" + path.filename().string() +
                      "): export plain OFF, PLY or STL");
  std::vector<long long> counts;
  std::string token;
  while (counts.size() < 3 && in >> token) {
    if (token[0] == '#') {
      std::getline(in, token);
      continue;
    }
    size_t used = 0;
    long long count = -1;
    try {
      count = std::stoll(token, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != token.size() || count < 0 || count > std::numeric_limits<int>::max())
      throw EngineError("unreadable OFF header in " + path.filename().string() + ": '" + token + "' is not a count");
    counts.push_back(count);
  }
  if (counts.size() < 2) throw EngineError("unreadable OFF header in " + path.filename().string());
  facts.declared_vertices = counts[0];
  facts.declared_faces = counts[1];
  if (facts.declared_faces <= 0) throw EngineError("no faces in OFF " + path.filename().string());
  check_cap(facts.declared_faces, max_triangles, path);
  // OpenMesh pads a short OFF with made-up faces: check every record is there.
  check_off_records(path, facts, records);
  facts.records_read = records != nullptr;
  return facts;
}

}  // namespace

MeshFileFacts inspect_mesh_file(const std::filesystem::path& path, int max_triangles, SoupImporter* records) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw EngineError("cannot read " + path.string() + ": no such file");
  if (!std::filesystem::is_regular_file(status)) throw EngineError("cannot read " + path.string() + ": not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw EngineError("cannot read " + path.string() + ": " + error.message());
  const std::string extension = lower(path.extension().string());
  if (extension != ".stl" && extension != ".obj" && extension != ".ply" && extension != ".off")
    throw EngineError("unknown mesh format '" + extension + "' of " + path.filename().string() +
                      " (lastcut reads .stl, .obj, .ply and .off)");
  if (size == 0) throw EngineError("empty file " + path.filename().string());
  if (extension == ".stl") return check_stl(path, size, max_triangles);
  if (extension == ".obj") return check_obj(path, max_triangles);
  if (extension == ".ply") return check_ply(path, max_triangles);
  return check_off(path, max_triangles, records);
}

}  // namespace lastcut
