// parse_web_route (web_route.hpp): the operator page's paths, split on '/' and checked piece by piece.
#include "daemon/web/web_route.hpp"

#include <vector>

namespace lastcut::daemon {
namespace {

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
}

WebRoute refused(std::string why) { return {WebRouteKind::Refused, "", "", "", std::move(why)}; }
WebRoute not_found(std::string_view path) { return {WebRouteKind::NotFound, "", "", "", "no such page: " + printable_path(path)}; }

WebRoute with_method(WebRoute route, std::string_view method, std::string_view wanted) {
  if (method == wanted) return route;
  return {WebRouteKind::WrongMethod, "", "", "", std::string(method) + " is not allowed here, only " + std::string(wanted)};
}

}  // namespace

bool safe_name(std::string_view name) {
  if (name.empty() || name.size() > 100 || !(name_char(name[0]) && name[0] != '.' && name[0] != '-' && name[0] != '_'))
    return false;
  for (char c : name)
    if (!name_char(c)) return false;
  return name.find("..") == std::string_view::npos;
}

std::string printable_path(std::string_view path) {
  std::string out;
  for (char c : path) {
    if (out.size() >= 120) {
      out += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && c != '\\') {
      out += c;
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  }
  return out;
}

WebRoute parse_web_route(std::string_view method, std::string_view path) {
  if (path.empty() || path[0] != '/') return refused("the path must start with /");
  if (path.size() > 400) return refused("the path is longer than 400 characters");
  std::vector<std::string_view> parts;
  for (std::size_t start = 1; start <= path.size();) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    parts.push_back(path.substr(start, slash - start));
    start = slash + 1;
  }
  if (parts.size() == 1 && parts[0].empty()) return with_method({WebRouteKind::Page}, method, "GET");
  for (std::string_view part : parts) {
    // Every piece is a plain name: nothing here may climb out of a folder or hide a byte.
    if (part.empty()) return refused("empty path segment in " + printable_path(path));
    if (!safe_name(part)) return refused("not a plain name: \"" + printable_path(part) + "\"");
  }
  const auto is = [&](std::size_t i, std::string_view word) { return i < parts.size() && parts[i] == word; };
  if (parts.size() == 2 && is(0, "assets"))
    return with_method({WebRouteKind::Asset, "", std::string(parts[1])}, method, "GET");
  if (!is(0, "api")) return not_found(path);
  if (parts.size() == 2 && is(1, "overview")) return with_method({WebRouteKind::Overview}, method, "GET");
  if (parts.size() == 2 && is(1, "events")) return with_method({WebRouteKind::Events}, method, "GET");
  if (is(1, "jobs") && parts.size() >= 3) {
    const std::string id(parts[2]);
    if (parts.size() == 3) return with_method({WebRouteKind::Job, id}, method, "GET");
    if (parts.size() == 4 && is(3, "requeue")) return with_method({WebRouteKind::Requeue, id}, method, "POST");
    if (parts.size() == 5 && is(3, "files")) return with_method({WebRouteKind::JobFile, id, std::string(parts[4])}, method, "GET");
    if (parts.size() == 6 && is(3, "files") && (is(4, "molds") || is(4, "pieces")))
      return with_method({WebRouteKind::JobFile, id, std::string(parts[4]) + "/" + std::string(parts[5])}, method, "GET");
  }
  if (is(1, "batches") && parts.size() == 4 && is(3, "cancel"))
    return with_method({WebRouteKind::CancelBatch, std::string(parts[2])}, method, "POST");
  if (is(1, "batches") && parts.size() == 5 && is(3, "files"))
    return with_method({WebRouteKind::BatchFile, std::string(parts[2]), std::string(parts[4])}, method, "GET");
  if (is(1, "cutters") && parts.size() == 4 && (is(3, "pause") || is(3, "resume"))) {
    const auto kind = is(3, "pause") ? WebRouteKind::PauseCutter : WebRouteKind::ResumeCutter;
    return with_method({kind, "", "", std::string(parts[2])}, method, "POST");
  }
  if (is(1, "cutters") && parts.size() == 5 && is(3, "hides"))
    return with_method({WebRouteKind::LoadHide, "", std::string(parts[4]), std::string(parts[2])}, method, "POST");
  return not_found(path);
}

}  // namespace lastcut::daemon
