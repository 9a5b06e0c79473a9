#pragma once
// Fresh folders for tests, made by mkdtemp. A name built from the pid is not enough: CI runs
// thousands of processes, pids are reused, and a test process killed earlier (a CTest timeout, a
// test that kills its own child) leaves its folder or log behind for the next process with that pid
// (a leftover simulator log said "ready" before the new simulator's link existed: a CI flake).
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace lastcut::test {

// A new, empty folder `lastcut-<name>-XXXXXX` under the system temp folder; the caller removes it.
inline std::filesystem::path make_temp_dir(const std::string& name) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("lastcut-" + name + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a folder like " + pattern);
  return pattern;
}

// make_temp_dir, removed with everything in it by the destructor.
class TempDir {
 public:
  explicit TempDir(const std::string& name = "test") : path_(make_temp_dir(name)) {}
  ~TempDir() {
    std::error_code ignored;  // best effort in a destructor; a leftover folder is harmless now
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  operator const std::filesystem::path&() const { return path_; }  // implicit: a TempDir stands for its folder
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

}  // namespace lastcut::test
