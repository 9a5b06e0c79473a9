// Fuzz target: what the operator page reads from a request itself (daemon/web/web_route.hpp,
// web_guard.hpp): the route from the method and the decoded path, and the token from the
// Authorization header. Input: "METHOD PATH\nAUTHORIZATION" (the first space and newline split).
//
// What counts as fine: any bytes give a route; a name handed on (asset, job id, file, cutter)
// always passes safe_name(), a file of a job is NAME or molds/NAME, and a refusal says why.
// Anything else aborts.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "daemon/web/web_guard.hpp"
#include "daemon/web/web_route.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace lastcut::daemon;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t space = input.find(' ');
  const std::size_t newline = input.find('\n');
  const std::string method = space == std::string::npos ? input : input.substr(0, space);
  const std::string path = space == std::string::npos ? "" : input.substr(space + 1, newline == std::string::npos ? std::string::npos : newline - space - 1);
  const WebRoute route = parse_web_route(method, path);
  switch (route.kind) {
    case WebRouteKind::Asset:
    case WebRouteKind::BatchFile:
    case WebRouteKind::LoadHide:
      if (!safe_name(route.name)) std::abort();
      break;
    case WebRouteKind::JobFile: {
      const std::string file = route.name.rfind("molds/", 0) == 0 ? route.name.substr(6) : route.name;
      if (!safe_name(file)) std::abort();
      break;
    }
    case WebRouteKind::Refused:
    case WebRouteKind::NotFound:
    case WebRouteKind::WrongMethod:
      if (route.problem.empty()) std::abort();
      break;
    case WebRouteKind::Page:
    case WebRouteKind::Overview:
    case WebRouteKind::Events:
    case WebRouteKind::Job:
    case WebRouteKind::Requeue:
      break;
    case WebRouteKind::CancelBatch:  // the batch's id: checked below with every id
      if (route.job_id.empty()) std::abort();
      break;
    case WebRouteKind::PauseCutter:
    case WebRouteKind::ResumeCutter:
      if (route.cutter.empty()) std::abort();
      break;
  }
  if (!route.job_id.empty() && !safe_name(route.job_id)) std::abort();
  if (!route.cutter.empty() && !safe_name(route.cutter)) std::abort();
  if (newline != std::string::npos) {
    static const std::map<std::string, std::string> tokens = {{"anna", "0123456789abcdef-anna"}};
    const std::string who = token_name(tokens, input.substr(newline + 1));
    if (!who.empty() && input.substr(newline + 1) != "Bearer 0123456789abcdef-anna") std::abort();
  }
  return 0;
}
