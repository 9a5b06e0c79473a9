#include "daemon/watch/scan_completeness.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <vector>

namespace lastcut::daemon {
namespace {

std::string lower_extension(const std::filesystem::path& scan) {
  std::string extension = scan.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

std::string read_tail(std::ifstream& in, std::uintmax_t size, std::size_t count) {
  const std::size_t take = static_cast<std::size_t>(std::min<std::uintmax_t>(size, count));
  std::string tail(take, '\0');
  in.clear();
  in.seekg(static_cast<std::streamoff>(size - take));
  in.read(tail.data(), static_cast<std::streamsize>(take));
  return tail;
}

std::string stl_incompleteness(std::ifstream& in, std::uintmax_t size) {
  if (size < 84) {
    // Could still be a tiny ASCII STL.
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    return text.find("endsolid") != std::string::npos ? "" : "the file is cut off (too short for an STL)";
  }
  unsigned char header[84];
  in.read(reinterpret_cast<char*>(header), 84);
  const uint32_t triangles = uint32_t(header[80]) | (uint32_t(header[81]) << 8) | (uint32_t(header[82]) << 16) |
                             (uint32_t(header[83]) << 24);
  if (84 + 50 * static_cast<std::uintmax_t>(triangles) == size) return {};
  // Not a consistent binary STL: accept it when it is a finished ASCII STL.
  std::string tail = read_tail(in, size, 256);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
  if (tail.find("endsolid") != std::string::npos) return {};
  const std::uintmax_t held = size >= 84 ? (size - 84) / 50 : 0;
  return "the file is cut off (binary STL announces " + std::to_string(triangles) + " triangles, holds " +
         std::to_string(held) + ")";
}

}  // namespace

std::string scan_incompleteness(const std::filesystem::path& scan) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(scan, error);
  if (error) return "the file cannot be read (" + error.message() + ")";
  if (size == 0) return "the file is empty";
  std::ifstream in(scan, std::ios::binary);
  if (!in) return "the file cannot be opened";
  const std::string extension = lower_extension(scan);
  if (extension == ".stl") return stl_incompleteness(in, size);
  if (extension == ".ply") {
    std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 4096)), '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    if (head.find("end_header") == std::string::npos) return "the file is cut off (PLY header incomplete)";
    return {};
  }
  if (extension == ".dxf") {  // a pattern set (DXF-AAMA): every DXF ends with the group "0 / EOF"
    if (read_tail(in, size, 16).find("EOF") == std::string::npos) return "the file is cut off (a DXF file ends with EOF)";
    return {};
  }
  const std::string tail = read_tail(in, size, 1);
  if (tail != "\n") return "the file is cut off (last line unfinished)";
  return {};
}

}  // namespace lastcut::daemon
