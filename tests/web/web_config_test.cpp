// [web]: read and checked like every table of lastcutd's configuration; the shipped files turn the
// page on for this machine only (the package read-only, the demo with its token).
#include <gtest/gtest.h>

#include <fstream>

#include "daemon/config/config_loader.hpp"
#include "tests/support/minimal_daemon_config.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::daemon {
namespace {

ConfigLoadResult load(const std::string& web_table) {
  lastcut::test::TempDir folder("web-config");
  std::ofstream(folder.path() / "lastcut.toml") << lastcut::testing::kMinimalDaemonConfig << web_table;
  return load_daemon_config(folder.path() / "lastcut.toml");
}

TEST(WebConfig, AbsentMeansNoPage) {
  const auto result = load("");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_FALSE(result.config->web);
}

TEST(WebConfig, DefaultsListenOnThisMachineOnly) {
  const auto result = load("[web]\n");
  ASSERT_TRUE(result.config) << result.error;
  const WebConfig& web = *result.config->web;
  EXPECT_EQ(web.host, "127.0.0.1");
  EXPECT_EQ(web.port, 8631);
  EXPECT_TRUE(web.tokens.empty());
  EXPECT_EQ(web.max_body_bytes, 8u << 20);
}

TEST(WebConfig, ListenTokensAndLimitsAreRead) {
  const auto result = load("[web]\nlisten = \"[::1]:9000\"\nmax_body_mib = 2\nrequests_per_s = 10\n"
                           "[web.tokens]\nanna = \"0123456789abcdef\"\n");
  ASSERT_TRUE(result.config) << result.error;
  const WebConfig& web = *result.config->web;
  EXPECT_EQ(web.host, "::1");
  EXPECT_EQ(web.port, 9000);
  EXPECT_EQ(web.tokens.at("anna"), "0123456789abcdef");
  EXPECT_EQ(web.max_body_bytes, 2u << 20);
  EXPECT_EQ(web.requests_per_s, 10);
}

TEST(WebConfig, MistakesAreRefusedWithTheKeyAndWhy) {
  EXPECT_NE(load("[web]\nlisten = \"8631\"\n").error.find("web.listen: \"8631\" must be HOST:PORT"), std::string::npos);
  EXPECT_NE(load("[web]\nlisten = \"127.0.0.1:99999\"\n").error.find("the port must be a number from 0 to 65535"),
            std::string::npos);
  EXPECT_NE(load("[web]\n[web.tokens]\nanna = \"short\"\n").error.find("a token must be at least 16 characters"),
            std::string::npos);
  EXPECT_NE(load("[web]\nlisen = \"127.0.0.1:1\"\n").error.find("web.lisen"), std::string::npos);
}

TEST(WebConfig, TheShippedFilesTurnThePageOnForThisMachine) {
  const std::filesystem::path source = LASTCUT_SOURCE_DIR;
  const auto package = load_daemon_config(source / "config/lastcut.toml");
  ASSERT_TRUE(package.config) << package.error;
  ASSERT_TRUE(package.config->web);
  EXPECT_EQ(package.config->web->listen, "127.0.0.1:8631");
  EXPECT_TRUE(package.config->web->tokens.empty()) << "the package's page is read-only until the admin adds a token";
  const auto demo = load_daemon_config(source / "config/demo/lastcut.toml");
  ASSERT_TRUE(demo.config) << demo.error;
  ASSERT_TRUE(demo.config->web);
  EXPECT_EQ(demo.config->web->host, "127.0.0.1");
  EXPECT_TRUE(std::filesystem::exists(demo.config->web->assets_dir / "index.html"));
}

}  // namespace
}  // namespace lastcut::daemon
