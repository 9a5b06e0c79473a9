#pragma once
// WebRoute: what one request to the operator's page asks for, read from its method and its
// (percent-decoded) path alone. This is the one place a request's path is interpreted: every
// name that later reaches the filesystem (an asset, a job's id, a file of a job) has passed
// safe_name() here, so no "..", slash, backslash, NUL or absolute path from a request is ever
// joined to a folder. Pure and total: any bytes give a route, Refused with its reason if need be
// (tests/fuzz/web_route_fuzz.cpp).
#include <string>
#include <string_view>

namespace lastcut::daemon {

enum class WebRouteKind {
  Page,        // GET /                      the page
  Asset,       // GET /assets/NAME            one of the page's files
  Overview,    // GET /api/overview           the store's overview, as `lastcut status --json` plus live cutters
  Events,      // GET /api/events             Server-Sent Events: job and cutter changes
  Job,         // GET /api/jobs/ID            one job: state, report, files
  JobFile,     // GET /api/jobs/ID/files/F    one file of a job: F is NAME or molds/NAME
  BatchFile,   // GET /api/batches/B/files/F  one file of a batch or hide (cut-map.json, preview.svg, layout.json)
  Requeue,     // POST /api/jobs/ID/requeue   hand a held or failed job back (token)
  LoadHide,    // POST /api/cutters/C/hides/NAME   the body is a hide file for cutter C's table (token)
  CancelBatch,   // POST /api/batches/B/cancel  a batch that waits for its cutter is held with its jobs (token)
  PauseCutter,   // POST /api/cutters/C/pause   cutter C starts no new batch until resumed (token)
  ResumeCutter,  // POST /api/cutters/C/resume  (token)
  NotFound,    // a well-formed path the page does not have (404)
  Refused,     // a path that tries to leave its folder or is not text (400)
  WrongMethod  // a known path with another method (405)
};

struct WebRoute {
  WebRouteKind kind = WebRouteKind::NotFound;
  std::string job_id;   // Job, JobFile, Requeue; BatchFile, CancelBatch: the batch's id
  std::string name;     // Asset: file name; JobFile: "NAME" or "molds/NAME"; LoadHide: hide file name
  std::string cutter;   // LoadHide, PauseCutter, ResumeCutter
  std::string problem;  // Refused, NotFound, WrongMethod: one line for the answer and the log
};

// 1 to 100 of letters, digits, '.', '_', '-', starting with a letter or digit, no "..".
bool safe_name(std::string_view name);

// `method`: "GET", "POST", ...; `path`: the request's path as decoded, without the query.
WebRoute parse_web_route(std::string_view method, std::string_view path);

// The path as the log shows it: printable ASCII only (others as \xNN), at most 120 characters.
std::string printable_path(std::string_view path);

}  // namespace lastcut::daemon
