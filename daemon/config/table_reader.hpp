#pragma once
// Reading one TOML table of lastcutd's configuration: every read remembers its key, so
// reject_unknown() can report each key nobody asked for with its path and line (a typo must not
// silently fall back to a default). Problems are appended to a shared error list as
// "table.key (line N): why", so one run reports every mistake of the file.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace lastcut::daemon {

// "key.path (line N)" for a node of the file (without the line when the node has no source).
std::string where(const std::string& key_path, const toml::node& node);

// `value` as a path, relative ones against `base` (the configuration file's folder).
std::filesystem::path resolve(const std::filesystem::path& base, const std::string& value);

class TableReader {
 public:
  // `path` is the table's dotted name ("" for the root); errors are appended to `errors`.
  TableReader(const toml::table& table, std::string path, std::vector<std::string>& errors)
      : table_(table), path_(std::move(path)), errors_(errors) {}
  TableReader(const TableReader&) = delete;
  TableReader& operator=(const TableReader&) = delete;

  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  // The key's node (nullptr when absent), marked as read.
  const toml::node* node(const std::string& key);

  // Each reader leaves `value` as it was when the key is absent (and reports it when required) or wrong.
  void text(const std::string& key, std::string& value, bool required = false);
  void number(const std::string& key, double& value, double min_value, double max_value, bool required = false);
  void integer(const std::string& key, int& value, int min_value, int max_value, bool required = false);
  void boolean(const std::string& key, bool& value, bool required = false);
  const toml::table* subtable(const std::string& key, bool required);

  // Reports every key of the table that no read asked for.
  void reject_unknown();

 private:
  const toml::table& table_;
  std::string path_;
  std::vector<std::string>& errors_;
  std::set<std::string> used_;
};

}  // namespace lastcut::daemon
