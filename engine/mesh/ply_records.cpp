#include "engine/mesh/ply_records.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/text_tokens.hpp"

namespace lastcut {
namespace {

// Size in bytes of a PLY scalar type (both the 1.0 names and the sized ones); 0 when unknown.
int scalar_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// A list length of `size` bytes at `at`, in the file's byte order. Lengths are small unsigned
// numbers in practice (uchar, int); a negative signed int reads as a huge count, which then
// cannot fit in the rest of the file and counts as the record where the file breaks.
std::uint64_t read_count(const std::string& bytes, size_t at, int size, bool big_endian) {
  std::uint64_t value = 0;
  for (int k = 0; k < size; ++k) {
    const auto byte = static_cast<unsigned char>(bytes[at + static_cast<size_t>(big_endian ? k : size - 1 - k)]);
    value = (value << 8) | byte;
  }
  return value;
}

// Complete binary records of `element` from `offset` on (advanced past them).
long long count_binary(const std::string& bytes, const PlyElement& element, bool big_endian, size_t& offset) {
  bool fixed_size = true;
  size_t record_bytes = 0;
  for (const PlyProperty& property : element.properties) {
    fixed_size = fixed_size && !property.is_list;
    record_bytes += static_cast<size_t>(property.size_bytes);
  }
  const size_t available = bytes.size() - offset;
  if (fixed_size) {
    const auto whole = record_bytes == 0 ? element.declared_count
                                         : static_cast<long long>(available / record_bytes);
    const long long records = std::min(element.declared_count, whole);
    offset += static_cast<size_t>(records) * record_bytes;
    return records;
  }
  for (long long record = 0; record < element.declared_count; ++record) {
    size_t at = offset;
    for (const PlyProperty& property : element.properties) {
      if (!property.is_list) {
        at += static_cast<size_t>(property.size_bytes);
        continue;
      }
      if (at + static_cast<size_t>(property.count_size_bytes) > bytes.size()) return record;
      const std::uint64_t items = read_count(bytes, at, property.count_size_bytes, big_endian);
      at += static_cast<size_t>(property.count_size_bytes);
      if (items > (bytes.size() - at) / static_cast<size_t>(property.size_bytes)) return record;
      at += static_cast<size_t>(items) * static_cast<size_t>(property.size_bytes);
    }
    if (at > bytes.size()) return record;
    offset = at;
  }
  return element.declared_count;
}

// Complete ASCII records of `element`: one token per scalar, a length and that many items per list.
long long count_ascii(TextTokens& tokens, const PlyElement& element) {
  for (long long record = 0; record < element.declared_count; ++record) {
    for (const PlyProperty& property : element.properties) {
      // OpenMesh reads the body as a stream of numbers: a token it reads only in part ("7-4") would
      // shift every later value, and a shifted "-4" read as a list length is 4 billion items. So
      // every value must be a number as a whole, every list length a plain count (found by the fuzzers).
      const std::string_view token = tokens.next();
      if (token.empty()) return record;
      if (!property.is_list) {
        if (!TextTokens::is_number(token)) throw EngineError("a value that is not a number: '" + std::string(token.substr(0, 20)) + "'");
        continue;
      }
      long long items = 0;
      const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), items);
      if (error != std::errc() || end != token.data() + token.size() || items < 0) return record;
      for (long long item = 0; item < items; ++item) {
        const std::string_view value = tokens.next();
        if (value.empty()) return record;
        if (!TextTokens::is_number(value)) throw EngineError("a value that is not a number: '" + std::string(value.substr(0, 20)) + "'");
      }
    }
  }
  return element.declared_count;
}

}  // namespace

PlyHeader read_ply_header(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || !(line.rfind("ply", 0) == 0 || line.rfind("PLY", 0) == 0))
    throw EngineError("not a PLY file: " + name + " does not start with 'ply'");
  PlyHeader header;
  bool has_format = false;
  for (int lines = 0; lines < 1000 && std::getline(in, line); ++lines) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      if (!has_format) throw EngineError("unreadable PLY header in " + name + " (no format line)");
      header.body_offset = static_cast<size_t>(in.tellg());
      return header;
    }
    // OpenMesh reads the header as a stream of words, not lines, and loops for ever once one of them
    // fails to read (a version or count that is not a number, a word missing, a line with a word
    // too many that shifts the rest): found by tests/fuzz/ply_fuzz.cpp. So the format line comes
    // first, every line has exactly its words, and only the header keywords are accepted.
    if (lines == 0 && keyword != "format")
      throw EngineError("unreadable PLY header in " + name + ": the line after 'ply' must be the format line");
    if (keyword.empty() || keyword == "comment") continue;
    if (keyword == "format") {
      std::string format;
      float version = 0;
      words >> format;
      if (!(words >> version))
        throw EngineError("unreadable PLY header in " + name + ": the format line has no version number");
      if (format == "ascii") header.encoding = PlyEncoding::Ascii;
      else if (format == "binary_little_endian") header.encoding = PlyEncoding::BinaryLittleEndian;
      else if (format == "binary_big_endian") header.encoding = PlyEncoding::BinaryBigEndian;
      else throw EngineError("unreadable PLY header in " + name + ": unknown format '" + format + "'");
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (!(words >> element.name >> element.declared_count) || element.declared_count < 0)
        throw EngineError("unreadable PLY header in " + name + ": element without a count");
      if (element.declared_count > std::numeric_limits<int>::max())
        throw EngineError("unreadable PLY header in " + name + ": element count " + std::to_string(element.declared_count) +
                          " is too large");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) throw EngineError("unreadable PLY header in " + name + ": property before any element");
      PlyProperty property;
      std::string type, count_type, item_type, property_name;
      words >> type;
      if (type == "list") words >> count_type >> item_type;
      if (!(words >> property_name))
        throw EngineError("unreadable PLY header in " + name + ": a property line without a name");
      if (type == "list") {
        property.is_list = true;
        property.count_size_bytes = scalar_size(count_type);
        property.size_bytes = scalar_size(item_type);
        if (property.count_size_bytes == 0 || property.count_size_bytes == 8) type = count_type;
        else if (property.size_bytes == 0) type = item_type;
      } else {
        property.size_bytes = scalar_size(type);
      }
      if (property.size_bytes == 0 || property.count_size_bytes == 8 || (property.is_list && property.count_size_bytes == 0))
        throw EngineError("unreadable PLY header in " + name + ": unknown property type '" + type + "'");
      header.elements.back().properties.push_back(property);
    } else if (keyword == "obj_info") {
      // Free text, but OpenMesh reads each of its words as a keyword.
      for (std::string word; words >> word;)
        if (word == "format" || word == "element" || word == "property" || word == "comment" || word == "end_header")
          throw EngineError("unreadable PLY header in " + name + ": '" + word + "' inside an obj_info line");
    } else {
      throw EngineError("unreadable PLY header in " + name + ": unknown header line '" + keyword.substr(0, 20) + "'");
    }
    if (std::string extra; words >> extra)
      throw EngineError("unreadable PLY header in " + name + ": '" + extra.substr(0, 20) + "' too many on a " + keyword + " line");
  }
  throw EngineError("unreadable PLY header in " + name + " (no end_header)");
}

std::vector<long long> count_ply_records(const std::string& file_bytes, const PlyHeader& header) {
  std::vector<long long> counts;
  size_t offset = std::min(header.body_offset, file_bytes.size());
  TextTokens tokens(file_bytes, false);
  tokens.seek(offset);
  bool short_element_seen = false;
  for (const PlyElement& element : header.elements) {
    long long records = 0;
    if (!short_element_seen) {
      records = header.encoding == PlyEncoding::Ascii
                    ? count_ascii(tokens, element)
                    : count_binary(file_bytes, element, header.encoding == PlyEncoding::BinaryBigEndian, offset);
    }
    short_element_seen = short_element_seen || records < element.declared_count;
    counts.push_back(records);
  }
  return counts;
}

}  // namespace lastcut
