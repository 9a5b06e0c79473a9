// parse_web_route: every path a request may carry, hostile ones included, gives the route or the
// exact one-line refusal; no name that reaches a folder can hold "..", a slash or a hidden byte.
#include <gtest/gtest.h>

#include "daemon/web/web_route.hpp"

namespace lastcut::daemon {
namespace {

TEST(WebRoute, KnownPagesAndTheirParts) {
  EXPECT_EQ(parse_web_route("GET", "/").kind, WebRouteKind::Page);
  const WebRoute asset = parse_web_route("GET", "/assets/app.js");
  EXPECT_EQ(asset.kind, WebRouteKind::Asset);
  EXPECT_EQ(asset.name, "app.js");
  EXPECT_EQ(parse_web_route("GET", "/api/overview").kind, WebRouteKind::Overview);
  EXPECT_EQ(parse_web_route("GET", "/api/events").kind, WebRouteKind::Events);
  const WebRoute job = parse_web_route("GET", "/api/jobs/20261128-091500-001");
  EXPECT_EQ(job.kind, WebRouteKind::Job);
  EXPECT_EQ(job.job_id, "20261128-091500-001");
  const WebRoute mold = parse_web_route("GET", "/api/jobs/42/files/molds/medial.svg");
  EXPECT_EQ(mold.kind, WebRouteKind::JobFile);
  EXPECT_EQ(mold.job_id, "42");
  EXPECT_EQ(mold.name, "molds/medial.svg");
  const WebRoute piece = parse_web_route("GET", "/api/jobs/42/files/pieces/medial-quarter.svg");  // a style job's
  EXPECT_EQ(piece.kind, WebRouteKind::JobFile);
  EXPECT_EQ(piece.name, "pieces/medial-quarter.svg");
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/1/files/pieces/..").kind, WebRouteKind::Refused);
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/1/files/aama/x.dxf").kind, WebRouteKind::NotFound);  // only molds/ and pieces/
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/42/files/report.json").name, "report.json");
  EXPECT_EQ(parse_web_route("POST", "/api/jobs/42/requeue").kind, WebRouteKind::Requeue);
  const WebRoute map = parse_web_route("GET", "/api/batches/B20261128-091500-001/files/cut-map.json");
  EXPECT_EQ(map.kind, WebRouteKind::BatchFile);
  EXPECT_EQ(map.job_id, "B20261128-091500-001");
  EXPECT_EQ(map.name, "cut-map.json");
  const WebRoute hide = parse_web_route("POST", "/api/cutters/cutter-1/hides/hide-7.dxf");
  EXPECT_EQ(hide.kind, WebRouteKind::LoadHide);
  EXPECT_EQ(hide.cutter, "cutter-1");
  EXPECT_EQ(hide.name, "hide-7.dxf");
  const WebRoute pause = parse_web_route("POST", "/api/cutters/table-2/pause");
  EXPECT_EQ(pause.kind, WebRouteKind::PauseCutter);
  EXPECT_EQ(pause.cutter, "table-2");
  EXPECT_EQ(parse_web_route("POST", "/api/cutters/table-2/resume").kind, WebRouteKind::ResumeCutter);
  EXPECT_EQ(parse_web_route("GET", "/api/cutters/table-2/pause").problem, "GET is not allowed here, only POST");
  EXPECT_EQ(parse_web_route("POST", "/api/cutters/table-2/stop").kind, WebRouteKind::NotFound);
}

TEST(WebRoute, PathsThatClimbOutOfTheirFolderAreRefused) {
  // The library hands the path over decoded: %2e%2e%2f arrives as "../".
  EXPECT_EQ(parse_web_route("GET", "/assets/../../etc/passwd").problem, "not a plain name: \"..\"");
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/../files/x").problem, "not a plain name: \"..\"");
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/1/files/..").problem, "not a plain name: \"..\"");
  EXPECT_EQ(parse_web_route("GET", "/assets/.htpasswd").problem, "not a plain name: \".htpasswd\"");
  EXPECT_EQ(parse_web_route("GET", "/assets//etc/passwd").problem, "empty path segment in /assets//etc/passwd");
  EXPECT_EQ(parse_web_route("GET", "etc/passwd").problem, "the path must start with /");
  EXPECT_EQ(parse_web_route("GET", "/assets/a\\..\\b").problem, "not a plain name: \"a\\x5c..\\x5cb\"");
  EXPECT_EQ(parse_web_route("GET", std::string("/assets/a\0b", 11)).problem, "not a plain name: \"a\\x00b\"");
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/1/files/molds/../../x").kind, WebRouteKind::Refused);
  EXPECT_EQ(parse_web_route("GET", "/" + std::string(500, 'a')).problem, "the path is longer than 400 characters");
  for (const char* path : {"/assets/../x", "/assets/x/../../y", "/api/jobs/..%2f..", "/api/jobs/1/files/molds/.."}) {
    EXPECT_EQ(parse_web_route("GET", path).kind, WebRouteKind::Refused) << path;
  }
}

TEST(WebRoute, UnknownPathsAndWrongMethods) {
  EXPECT_EQ(parse_web_route("GET", "/api/nothing").problem, "no such page: /api/nothing");
  EXPECT_EQ(parse_web_route("GET", "/index.html").kind, WebRouteKind::NotFound);
  EXPECT_EQ(parse_web_route("GET", "/api/jobs/42/requeue").problem, "GET is not allowed here, only POST");
  EXPECT_EQ(parse_web_route("DELETE", "/api/overview").problem, "DELETE is not allowed here, only GET");
  EXPECT_EQ(parse_web_route("POST", "/").kind, WebRouteKind::WrongMethod);
}

TEST(WebRoute, SafeNamesAndPrintablePaths) {
  EXPECT_TRUE(safe_name("preview.svg"));
  EXPECT_TRUE(safe_name("20261128-091500-001"));
  EXPECT_FALSE(safe_name(""));
  EXPECT_FALSE(safe_name("a..b"));
  EXPECT_FALSE(safe_name("-rf"));
  EXPECT_FALSE(safe_name(std::string(101, 'a')));
  EXPECT_FALSE(safe_name("caf\xc3\xa9"));
  EXPECT_EQ(printable_path("/a\nb"), "/a\\x0ab");
  EXPECT_EQ(printable_path(std::string(200, 'x')), std::string(120, 'x') + "...");
}

}  // namespace
}  // namespace lastcut::daemon
