#include "daemon/config/table_reader.hpp"

#include <sstream>

namespace lastcut::daemon {

std::string where(const std::string& key_path, const toml::node& node) {
  std::ostringstream out;
  out << key_path;
  if (node.source().begin.line > 0) out << " (line " << node.source().begin.line << ")";
  return out.str();
}

std::filesystem::path resolve(const std::filesystem::path& base, const std::string& value) {
  std::filesystem::path path(value);
  return path.is_absolute() ? path.lexically_normal() : (base / path).lexically_normal();
}

const toml::node* TableReader::node(const std::string& key) {
  used_.insert(key);
  return table_.get(key);
}

void TableReader::text(const std::string& key, std::string& value, bool required) {
  const toml::node* found = node(key);
  if (!found) {
    if (required) errors_.push_back(key_path(key) + ": missing (required)");
    return;
  }
  if (auto s = found->value<std::string>(); s && found->is_string()) {
    value = *s;
  } else {
    errors_.push_back(where(key_path(key), *found) + ": must be a text in quotes");
  }
}

void TableReader::number(const std::string& key, double& value, double min_value, double max_value, bool required) {
  const toml::node* found = node(key);
  if (!found) {
    if (required) errors_.push_back(key_path(key) + ": missing (required)");
    return;
  }
  if (!found->is_number()) {
    errors_.push_back(where(key_path(key), *found) + ": must be a number");
    return;
  }
  const double v = *found->value<double>();
  if (!(v >= min_value && v <= max_value)) {  // TOML has nan, which no comparison is true for
    std::ostringstream out;
    out << where(key_path(key), *found) << ": " << v << " is outside " << min_value << " .. " << max_value;
    errors_.push_back(out.str());
    return;
  }
  value = v;
}

void TableReader::boolean(const std::string& key, bool& value, bool required) {
  const toml::node* found = node(key);
  if (!found) {
    if (required) errors_.push_back(key_path(key) + ": missing (required)");
    return;
  }
  if (!found->is_boolean()) {
    errors_.push_back(where(key_path(key), *found) + ": must be true or false");
    return;
  }
  value = *found->value<bool>();
}

void TableReader::integer(const std::string& key, int& value, int min_value, int max_value, bool required) {
  const toml::node* found = node(key);
  if (!found) {
    if (required) errors_.push_back(key_path(key) + ": missing (required)");
    return;
  }
  if (!found->is_integer()) {
    errors_.push_back(where(key_path(key), *found) + ": must be a whole number");
    return;
  }
  const auto v = *found->value<int64_t>();
  if (v < min_value || v > max_value) {
    std::ostringstream out;
    out << where(key_path(key), *found) << ": " << v << " is outside " << min_value << " .. " << max_value;
    errors_.push_back(out.str());
    return;
  }
  value = static_cast<int>(v);
}

const toml::table* TableReader::subtable(const std::string& key, bool required) {
  const toml::node* found = node(key);
  if (!found) {
    if (required) errors_.push_back(key_path(key) + ": missing table [" + key_path(key) + "]");
    return nullptr;
  }
  if (!found->is_table()) {
    errors_.push_back(where(key_path(key), *found) + ": must be a table [" + key_path(key) + "]");
    return nullptr;
  }
  return found->as_table();
}

void TableReader::reject_unknown() {
  for (auto&& [key, value] : table_) {
    const std::string name(key.str());
    if (!used_.count(name)) errors_.push_back(where(key_path(name), value) + ": unknown key");
  }
}

}  // namespace lastcut::daemon
