#pragma once
// PLY files (Turk's polygon file format, as written by scanners, MeshLab, Blender and OpenMesh):
// the header's encoding and elements, and how many complete records the body really holds.
// OpenMesh reads a PLY that ends early without a word (the missing faces are simply absent),
// so intake counts the records itself: binary bodies by their byte sizes (list lengths read in
// the file's byte order), ASCII bodies by their tokens.
#include <filesystem>
#include <string>
#include <vector>

namespace lastcut {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyProperty {
  bool is_list = false;
  int size_bytes = 0;        // scalar: its size; list: the size of one item
  int count_size_bytes = 0;  // list only: the size of the length in front of the items
};

struct PlyElement {
  std::string name;  // "vertex", "face", ...
  long long declared_count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;  // in file order
  size_t body_offset = 0;            // bytes from the start of the file to the first record
};

// Reads only the header. Throws EngineError (one line naming the file) when the file does not start
// with "ply", has no end_header, an unknown format or property type, or an element without a count.
PlyHeader read_ply_header(const std::filesystem::path& path);

// Complete records of each element (header order) in the file's bytes; an element after a short
// one counts 0. Never more than its declared count. Throws EngineError for an ASCII value that is
// not a number as a whole ("7-4"): OpenMesh would read it in part and shift the rest.
std::vector<long long> count_ply_records(const std::string& file_bytes, const PlyHeader& header);

}  // namespace lastcut
