#pragma once
// FuzzInputFile: hands one fuzz input to a loader that only reads from a path (mesh readers,
// the TOML and JSON loaders). The bytes are written to a file with the extension the loader
// needs, in a folder of this process (fuzz targets may run side by side), so the real entry
// point is fuzzed and no parsing code is duplicated for the fuzzer. The folder is removed at exit.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace lastcut::fuzz {

class FuzzInputFile {
 public:
  // `file_name` decides the format the loader sees, e.g. "scan.stl" or "order.job.toml".
  explicit FuzzInputFile(const std::string& file_name)
      : folder_("fuzz"), path_(folder_ / file_name) {}
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;

  // Replaces the file's content with the input; returns its path.
  const std::filesystem::path& write(const uint8_t* data, size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    // A full /tmp would make every input look empty: stop rather than fuzz nothing.
    if (!out) throw std::runtime_error("cannot write fuzz input " + path_.string());
    return path_;
  }

 private:
  lastcut::test::TempDir folder_;  // removed with the input by its destructor
  std::filesystem::path path_;
};

}  // namespace lastcut::fuzz
