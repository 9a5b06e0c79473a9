// WebServer (web_server.hpp): the HTTP side. cpp-httplib (Debian's libcpp-httplib) parses the
// requests; everything a request names goes through parse_web_route() first, and every refusal
// is one log line written by the server's logger from the answer's own first line.
#include "daemon/web/web_server.hpp"

#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <httplib.h>
#include <spdlog/spdlog.h>

#include "daemon/hides/hide_placement.hpp"
#include "daemon/web/web_guard.hpp"
#include "daemon/web/web_route.hpp"
#include "daemon/web/web_store.hpp"
#include "engine/core/durable_file.hpp"

#ifndef LASTCUT_WEB_ASSETS_DIR
#define LASTCUT_WEB_ASSETS_DIR "/usr/share/lastcut/web"
#endif

namespace lastcut::daemon {
namespace {

// No script of another origin, no framing; the page itself needs nothing else.
constexpr const char* kPagePolicy =
    "default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; connect-src 'self'; "
    "frame-ancestors 'none'; base-uri 'none'; form-action 'none'";
// A job's files (SVG pictures among them) are shown, never run.
constexpr const char* kFilePolicy = "sandbox; default-src 'none'; style-src 'unsafe-inline'; img-src data:";
constexpr auto kStreamWait = std::chrono::seconds(10);

std::string content_type(const std::string& name) {
  const std::string extension = std::filesystem::path(name).extension().string();
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".js") return "text/javascript; charset=utf-8";
  if (extension == ".css") return "text/css; charset=utf-8";
  if (extension == ".svg") return "image/svg+xml";
  if (extension == ".png") return "image/png";
  if (extension == ".json") return "application/json";
  if (extension == ".ico") return "image/x-icon";
  return "text/plain; charset=utf-8";  // DXF, G-code, HPGL, OBJ: shown as text
}

// The answer's one line; a refusal's is also kept in a header for the log line (the body may be
// compressed by the time the logger sees it).
void answer(httplib::Response& res, int status, const std::string& line) {
  res.status = status;
  if (status >= 400) res.set_header("X-Lastcut-Refusal", printable_path(line.substr(0, 200)));
  res.set_content(line + "\n", "text/plain; charset=utf-8");
}

void answer_json(httplib::Response& res, const nlohmann::json& json) {
  res.set_header("Cache-Control", "no-store");
  res.set_content(json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

bool send_file(httplib::Response& res, const std::filesystem::path& file, const char* policy) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  res.set_header("Content-Security-Policy", policy);
  res.set_content(bytes.str(), content_type(file.filename().string()));
  return true;
}

}  // namespace

struct WebServer::Impl {
  Impl(std::shared_ptr<const DaemonConfig> config_in, LiveEvents& events_in, CutterPauses& pauses_in)
      : config(std::move(config_in)), web(*config->web), events(events_in), pauses(pauses_in), store(config),
        limiter(web.requests_per_s),
        assets(web.assets_dir.empty() ? std::filesystem::path(LASTCUT_WEB_ASSETS_DIR) : web.assets_dir) {}

  void routes();
  void serve_events(const httplib::Request& req, httplib::Response& res);
  // The token's name, or "" after answering 401/403.
  std::string actor(const httplib::Request& req, httplib::Response& res) const;
  void requeue(const WebRoute& route, const httplib::Request& req, httplib::Response& res);
  void load_hide(const WebRoute& route, const httplib::Request& req, httplib::Response& res);
  void pause_or_resume(const WebRoute& route, const httplib::Request& req, httplib::Response& res);
  void cancel_batch(const WebRoute& route, const httplib::Request& req, httplib::Response& res);
  void get(const WebRoute& route, const httplib::Request& req, httplib::Response& res);

  std::shared_ptr<const DaemonConfig> config;
  const WebConfig& web;
  LiveEvents& events;
  CutterPauses& pauses;
  WebStore store;
  RateLimiter limiter;
  std::filesystem::path assets;
  httplib::Server http;
  std::thread thread;
  int port = 0;
  std::atomic<int> watchers{0};
  std::atomic<unsigned> uploads{0};
};

std::string WebServer::Impl::actor(const httplib::Request& req, httplib::Response& res) const {
  if (web.tokens.empty()) {
    answer(res, 403, "this page is read-only: the configuration names no [web.tokens]");
    return "";
  }
  if (!req.has_header("Authorization")) {
    answer(res, 401, "this action needs a token (Authorization: Bearer TOKEN)");
    return "";
  }
  std::string name = token_name(web.tokens, req.get_header_value("Authorization"));
  if (name.empty()) answer(res, 403, "the token is not one of [web.tokens]");
  return name;
}

void WebServer::Impl::requeue(const WebRoute& route, const httplib::Request& req, httplib::Response& res) {
  const std::string who = actor(req, res);
  if (who.empty()) return;
  const auto done = store.requeue(route.job_id);
  if (!done) return answer(res, 409, "requeue " + route.job_id + " refused: " + done.error());
  spdlog::info("web: {} (token {}) requeued job {}: {}", req.remote_addr, who, route.job_id, *done);
  answer(res, 200, *done);
}

void WebServer::Impl::load_hide(const WebRoute& route, const httplib::Request& req, httplib::Response& res) {
  const std::string who = actor(req, res);
  if (who.empty()) return;
  if (req.body.empty()) return answer(res, 400, "hide " + route.name + " refused: the upload is empty");
  // The upload is checked by the same reader as a hide dropped by a digitizer, from a private
  // copy in the spool; only a hide that reads is placed on the table.
  // A folder of its own per upload, so the hide keeps the name it was uploaded as (its id).
  const auto staging = config->paths.spool_dir / "web-uploads" /
                       (std::to_string(::getpid()) + "-" + std::to_string(uploads.fetch_add(1)));
  std::error_code error;
  std::filesystem::create_directories(staging, error);
  const auto staged = staging / route.name;
  if (Status written = write_file_durably(staged, req.body, WriteSync::AtomicOnly); !written) {
    std::filesystem::remove_all(staging, error);
    return answer(res, 500, "hide " + route.name + " not stored: " + written.error());
  }
  const auto placed = place_hide(*config, staged, route.name, route.cutter, "the operator page (token " + who + ")");
  std::filesystem::remove_all(staging, error);
  if (!placed) {
    // The reader names the file it read: the operator knows it by the name it was uploaded as.
    std::string why = placed.error();
    for (std::size_t at; (at = why.find(staged.string())) != std::string::npos;) why.replace(at, staged.string().size(), route.name);
    return answer(res, 422, "hide " + route.name + " refused: " + why);
  }
  spdlog::info("web: {} (token {}) loaded {}", req.remote_addr, who, *placed);
  answer(res, 200, *placed);
}

void WebServer::Impl::cancel_batch(const WebRoute& route, const httplib::Request& req, httplib::Response& res) {
  const std::string who = actor(req, res);
  if (who.empty()) return;
  const auto done = store.cancel_batch(route.job_id, who);
  if (!done) return answer(res, 409, "cancel of batch " + route.job_id + " refused: " + done.error());
  spdlog::info("web: {} (token {}): {}", req.remote_addr, who, *done);
  answer(res, 200, *done);
}

void WebServer::Impl::pause_or_resume(const WebRoute& route, const httplib::Request& req, httplib::Response& res) {
  const std::string who = actor(req, res);
  if (who.empty()) return;
  const bool pause = route.kind == WebRouteKind::PauseCutter;
  const std::string refused = std::string(pause ? "pause" : "resume") + " refused: ";
  if (!config->cutters.contains(route.cutter))
    return answer(res, 404, refused + "no cutter " + route.cutter + " in this station's configuration");
  // A node's workers cut only for the cutters cabled to it: another node's page holds the switch.
  if (config->ledger && !config->ledger->owns_cutter(route.cutter))
    return answer(res, 409, refused + "cutter " + route.cutter + " is cabled to another station; use that station's page");
  const auto done = pause ? pauses.pause(route.cutter, who) : pauses.resume(route.cutter, who);
  if (!done) return answer(res, 409, refused + done.error());
  spdlog::info("web: {} (token {}): {}", req.remote_addr, who, *done);
  answer(res, 200, *done);
}

void WebServer::Impl::get(const WebRoute& route, const httplib::Request& req, httplib::Response& res) {
  switch (route.kind) {
    case WebRouteKind::Page:
    case WebRouteKind::Asset: {
      const std::string name = route.kind == WebRouteKind::Page ? "index.html" : route.name;
      if (!send_file(res, assets / name, kPagePolicy)) answer(res, 404, "no page file " + name);
      return;
    }
    case WebRouteKind::Overview: {
      auto overview = store.overview();
      if (!overview) return answer(res, 503, "the store cannot be read: " + overview.error());
      nlohmann::json out = *overview;
      out["live_cutters"] = events.cutters();
      out["paused_cutters"] = pauses.paused();
      out["event_id"] = events.newest_id();
      return answer_json(res, out);
    }
    case WebRouteKind::Events: return serve_events(req, res);
    case WebRouteKind::Job: {
      auto job = store.job(route.job_id);
      if (!job) return answer(res, 404, job.error());
      return answer_json(res, *job);
    }
    case WebRouteKind::JobFile: {
      auto file = store.job_file(route.job_id, route.name);
      if (!file || !send_file(res, *file, kFilePolicy))
        answer(res, 404, file ? "job " + route.job_id + ": " + route.name + " unreadable" : file.error());
      return;
    }
    case WebRouteKind::BatchFile: {
      auto file = store.batch_file(route.job_id, route.name);
      if (!file || !send_file(res, *file, kFilePolicy))
        answer(res, 404, file ? "batch " + route.job_id + ": " + route.name + " unreadable" : file.error());
      return;
    }
    case WebRouteKind::Requeue:
    case WebRouteKind::LoadHide:
    case WebRouteKind::PauseCutter:
    case WebRouteKind::ResumeCutter:
    case WebRouteKind::CancelBatch:
    case WebRouteKind::NotFound:
    case WebRouteKind::Refused:
    case WebRouteKind::WrongMethod: return answer(res, 404, "no such page");
  }
}

void WebServer::Impl::serve_events(const httplib::Request& req, httplib::Response& res) {
  if (watchers.fetch_add(1) >= web.max_watchers) {
    watchers.fetch_sub(1);
    return answer(res, 503, "too many pages are watching (web.max_watchers = " + std::to_string(web.max_watchers) + ")");
  }
  // A reconnecting page says which event it saw last; a new one starts from now (it has just
  // read the overview).
  std::uint64_t after = events.newest_id();
  if (req.has_header("Last-Event-ID")) {
    try {
      after = std::stoull(req.get_header_value("Last-Event-ID"));
    } catch (const std::exception&) {
      // not a number: start from now, as a new page does
    }
  }
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, after, first = true](std::size_t, httplib::DataSink& sink) mutable {
        std::string out = first ? "retry: 1000\n\n" : "";
        first = false;
        const auto frames = events.next(after, kStreamWait);
        if (frames.closed) return false;
        if (frames.resync) out += "event: resync\ndata: {}\n\n";
        for (const std::string& frame : frames.frames) out += frame;
        if (out.empty()) out = ": still here\n\n";  // keeps proxies and the browser's connection open
        after = frames.last_id;
        return sink.write(out.data(), out.size());
      },
      [this](bool) { watchers.fetch_sub(1); });
}

void WebServer::Impl::routes() {
  http.new_task_queue = [this] { return new httplib::ThreadPool(static_cast<std::size_t>(web.max_watchers) + 4); };
  http.set_payload_max_length(web.max_body_bytes);
  http.set_read_timeout(5, 0);
  http.set_write_timeout(5, 0);
  http.set_keep_alive_timeout(5);
  http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Referrer-Policy", "no-referrer"},
                            {"X-Frame-Options", "DENY"}});
  // Before any body is read: the rate, then the path. A refused request never reaches a handler.
  http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!limiter.allow(req.remote_addr, std::chrono::steady_clock::now())) {
      answer(res, 429, "too many requests from " + req.remote_addr + " (web.requests_per_s = " +
                           std::to_string(web.requests_per_s) + ")");
      return httplib::Server::HandlerResponse::Handled;
    }
    const WebRoute route = parse_web_route(req.method, req.path);
    const int status = route.kind == WebRouteKind::Refused   ? 400
                       : route.kind == WebRouteKind::NotFound ? 404
                       : route.kind == WebRouteKind::WrongMethod ? 405 : 0;
    if (status == 0) return httplib::Server::HandlerResponse::Unhandled;
    answer(res, status, route.problem);
    return httplib::Server::HandlerResponse::Handled;
  });
  const auto dispatch = [this](const httplib::Request& req, httplib::Response& res) {
    const WebRoute route = parse_web_route(req.method, req.path);
    if (route.kind == WebRouteKind::Requeue) return requeue(route, req, res);
    if (route.kind == WebRouteKind::LoadHide) return load_hide(route, req, res);
    if (route.kind == WebRouteKind::PauseCutter || route.kind == WebRouteKind::ResumeCutter)
      return pause_or_resume(route, req, res);
    if (route.kind == WebRouteKind::CancelBatch) return cancel_batch(route, req, res);
    get(route, req, res);
  };
  http.Get(".*", dispatch);
  http.Post(".*", dispatch);
  http.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr failure) {
    std::string why = "unknown error";
    try {
      std::rethrow_exception(failure);
    } catch (const std::exception& error) {
      why = error.what();
    }
    answer(res, 500, "internal error on " + printable_path(req.path) + ": " + why);
  });
  // One line per refused request, from the answer's own first line; successful reads stay quiet.
  // Refusals of the HTTP library itself come before the request is known (no path, no address).
  http.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    if (res.status < 400) return;
    std::string line = res.get_header_value("X-Lastcut-Refusal");
    if (line.empty()) {
      line = res.status == 413   ? "the body is larger than web.max_body_mib"
             : res.status == 414 ? "the request line is longer than 8 KiB"
                                 : "a malformed, incomplete or too large request head (8 KiB per line), or a client "
                                   "that stopped sending for 5 s";
    }
    spdlog::warn("web: refused {} {} from {}: {}", res.status,
                 req.remote_addr.empty() ? std::string("(request not read)") : printable_path(req.method) + " " + printable_path(req.path),
                 req.remote_addr.empty() ? "?" : req.remote_addr, line);
  });
}

WebServer::WebServer(std::shared_ptr<const DaemonConfig> config, LiveEvents& events, CutterPauses& pauses)
    : impl_(std::make_unique<Impl>(std::move(config), events, pauses)) {}

WebServer::~WebServer() { stop(); }

Status WebServer::start() {
  impl_->routes();
  const WebConfig& web = impl_->web;
  if (web.port == 0) {
    impl_->port = impl_->http.bind_to_any_port(web.host);
  } else if (impl_->http.bind_to_port(web.host, web.port)) {
    impl_->port = web.port;
  } else {
    impl_->port = -1;
  }
  if (impl_->port <= 0) return Status::failure("web page: cannot listen on " + web.listen + " (address in use or not this machine's)");
  impl_->thread = std::thread([this] { impl_->http.listen_after_bind(); });
  const bool local = web.host == "127.0.0.1" || web.host == "::1" || web.host == "localhost";
  spdlog::info("operator page on http://{}:{}/{}", web.host.find(':') != std::string::npos ? "[" + web.host + "]" : web.host,
               impl_->port, local ? "" : " (reachable from the network: put a TLS proxy in front, docs/operator-page.md)");
  return Status::success();
}

int WebServer::port() const { return impl_->port; }

void WebServer::stop() {
  if (!impl_->thread.joinable()) return;
  impl_->events.close();
  impl_->http.stop();
  impl_->thread.join();
}

}  // namespace lastcut::daemon
