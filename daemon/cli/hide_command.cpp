// `lastcut hide load ID --cutter X [-c CONFIG]`: a hide kept in stock (paths.hide_stock, digitized
// elsewhere) is named as lying on cutter X's table. It takes the same path as a hide file dropped
// by a digitizer: the stock file is checked, then copied into paths.hides with a sidecar naming
// the cutter (written first, so lastcutd never sees the hide without it). The stock copy stays.
#include <cstdio>
#include <memory>
#include <string>

#include "daemon/cli/commands.hpp"
#include "daemon/config/config_loader.hpp"
#include "daemon/hides/hide_placement.hpp"

namespace lastcut::cli {
namespace {

struct HideLoadArguments {
  std::string config_file = "/etc/lastcut/lastcut.toml";
  std::string hide_id;
  std::string cutter;
};

Status load_hide(const HideLoadArguments& a) {
  const auto loaded = daemon::load_daemon_config(a.config_file);
  if (!loaded.config) return Status::failure(loaded.error);
  const daemon::DaemonConfig& config = *loaded.config;
  if (config.paths.hide_stock_dir.empty()) return Status::failure(a.config_file + " names no paths.hide_stock folder");
  if (config.paths.hides_dir.empty()) return Status::failure(a.config_file + " names no paths.hides folder");
  if (!config.cutters.count(a.cutter)) return Status::failure("cutter \"" + a.cutter + "\" is not configured");
  if (a.hide_id.empty() || a.hide_id.find('/') != std::string::npos || a.hide_id.front() == '.')
    return Status::failure("\"" + a.hide_id + "\" is not a hide ID (a file name without folder or extension)");
  std::filesystem::path stock;
  std::error_code error;
  for (const char* extension : {".dxf", ".json"}) {
    const auto candidate = config.paths.hide_stock_dir / (a.hide_id + extension);
    if (std::filesystem::is_regular_file(candidate, error)) stock = candidate;
  }
  if (stock.empty())
    return Status::failure("no hide " + a.hide_id + " (.dxf or .json) in the stock folder " +
                           config.paths.hide_stock_dir.string());
  const auto placed = daemon::place_hide(config, stock, stock.filename().string(), a.cutter,
                                         "`lastcut hide load " + a.hide_id + " --cutter " + a.cutter + "`");
  if (!placed) return placed.status();
  std::printf("%s\n", placed->c_str());
  return Status::success();
}

}  // namespace

void add_hide_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<HideLoadArguments>();
  auto* hide = app.add_subcommand("hide", "leather hides for lastcutd (docs/hides.md)");
  hide->require_subcommand(1);
  auto* load = hide->add_subcommand("load", "name a hide from stock (paths.hide_stock) as lying on a cutter's table");
  load->add_option("id", arguments->hide_id, "the hide's ID: its file name in the stock folder, without extension")
      ->required();
  load->add_option("--cutter", arguments->cutter, "the cutter whose table the hide lies on")->required();
  load->add_option("-c,--config", arguments->config_file, "lastcutd configuration (paths.hide_stock, paths.hides)");
  load->callback([arguments, &exit_code] {
    const Status loaded = load_hide(*arguments);
    if (!loaded) {
      std::fprintf(stderr, "lastcut hide load: %s\n", loaded.error().c_str());
      exit_code = 1;
    }
  });
}

}  // namespace lastcut::cli
