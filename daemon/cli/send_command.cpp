// `lastcut send FILE ...`: streams a cut file to a cutter through drivers/cutter.hpp and waits
// until the machine reports it finished. `lastcut ports`: serial ports with their USB identity.
// Exit codes of `send`: 0 done, 1 failed (nothing cut, safe to retry), 3 interrupted (the
// machine may have cut part of the job: check it; lastcut never resends on its own), 2 usage.
#include <atomic>
#include <charconv>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <deque>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "daemon/cli/commands.hpp"
#include "drivers/cutter.hpp"
#include "drivers/transport/serial_ports.hpp"

namespace lastcut::cli {

namespace {

std::atomic<bool> g_cancel{false};

void on_interrupt(int) { g_cancel.store(true); }

// What was typed for one option of drivers::CutterSettings (the table gives the flags).
struct FlagInput {
  const drivers::CutterOption* option = nullptr;
  CLI::Option* cli = nullptr;
  std::string text;                // one value
  std::vector<std::string> texts;  // list options: repeated or comma-separated
  bool on = false;                 // switches
};

struct SendOptions {
  std::string file, job_id;
  std::deque<FlagInput> flags;  // a deque: CLI11 keeps pointers into the entries
};

std::string flag_name(const drivers::CutterOption& option) {
  const std::string_view flag = option.flag;
  return std::string(flag.substr(0, flag.find(',')));
}

// The typed value of one flag; nothing, with `problem` set, when the text is not of its kind.
std::optional<drivers::OptionValue> flag_value(const FlagInput& input, std::string& problem) {
  const auto whole = [](const std::string& text) -> std::optional<long long> {
    long long v = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return v;
  };
  using drivers::OptionKind;
  switch (input.option->kind) {
    case OptionKind::Text:
    case OptionKind::Choice: return input.text;
    case OptionKind::Switch: return input.on;
    case OptionKind::Texts: return input.texts;
    case OptionKind::Integer:
      if (auto v = whole(input.text)) return *v;
      problem = "must be a whole number";
      return std::nullopt;
    case OptionKind::Number: {
      char* end = nullptr;
      const double v = std::strtod(input.text.c_str(), &end);
      if (!input.text.empty() && end == input.text.c_str() + input.text.size()) return v;
      problem = "must be a number";
      return std::nullopt;
    }
    case OptionKind::Integers: {
      std::vector<long long> values;
      for (const std::string& text : input.texts) {
        auto v = whole(text);
        if (!v) {
          problem = "each entry must be a whole number";
          return std::nullopt;
        }
        values.push_back(*v);
      }
      return values;
    }
  }
  return std::nullopt;
}

// The settings from the flags given (defaults for the others); "" or one line naming the flag.
std::string settings_from_flags(const SendOptions& options, drivers::CutterSettings& settings) {
  for (const FlagInput& input : options.flags) {
    if (input.cli->count() == 0) continue;
    std::string problem;
    if (auto value = flag_value(input, problem)) problem = drivers::set_cutter_option(settings, *input.option, *value);
    if (!problem.empty()) return flag_name(*input.option) + ": " + problem;
  }
  if (!settings.modbus.empty() && settings.protocol.empty()) settings.protocol = "modbus";
  if (settings.port.empty() == settings.modbus.empty()) return "give --port (with --protocol) or --modbus";
  if (!settings.port.empty() && (settings.protocol.empty() || settings.protocol == "modbus")) {
    return "--port needs --protocol grbl or hpgl";
  }
  if (!settings.modbus.empty() && settings.protocol != "modbus") return "--modbus is for --protocol modbus";
  return "";
}

std::string bar(const drivers::SendProgress& p) {
  const double fraction = p.bytes_total == 0 ? 0.0 : static_cast<double>(p.bytes_sent) / static_cast<double>(p.bytes_total);
  const int width = 30;
  const int filled = static_cast<int>(fraction * width);
  std::string text = "[" + std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(width - filled), '.') + "] ";
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "%3.0f%% %zu/%zu bytes", fraction * 100, p.bytes_sent, p.bytes_total);
  text += numbers;
  if (p.lines_total > 0) text += " " + std::to_string(p.lines_acked) + "/" + std::to_string(p.lines_total) + " lines";
  if (!p.device_state.empty()) text += " " + p.device_state;
  return text;
}

int run_send(const SendOptions& options, const drivers::CutterSettings& settings) {
  std::ifstream in(options.file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "lastcut: error: cannot read %s\n", options.file.c_str());
    return 1;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string program = buffer.str();

  const std::string file_name = options.file.substr(options.file.find_last_of('/') + 1);
  const drivers::CutterConfig config{settings, settings.modbus.empty() ? settings.port : settings.modbus,
                                     options.job_id.empty() ? file_name.substr(0, 16) : options.job_id};

  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  double last_plain_fraction = -1;
  auto progress = [&](const drivers::SendProgress& p) {
    if (terminal) {
      std::fprintf(stderr, "\r%s\033[K", bar(p).c_str());
      return;
    }
    // Plain lines for logs and pipes: one per 10 % and at the end.
    const double fraction = p.bytes_total == 0 ? 0 : static_cast<double>(p.bytes_sent) / static_cast<double>(p.bytes_total);
    if (fraction - last_plain_fraction >= 0.1 || (fraction >= 1.0 && last_plain_fraction < 1.0)) {
      std::fprintf(stderr, "progress: %s\n", bar(p).c_str());
      last_plain_fraction = fraction;
    }
  };
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  const drivers::SendResult result = drivers::send_job(config, program, progress, g_cancel);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (terminal) std::fprintf(stderr, "\n");
  switch (result.outcome) {
    case drivers::SendOutcome::Done:
      std::printf("done: %s\n", result.reason.c_str());
      return 0;
    case drivers::SendOutcome::Failed:
      std::fprintf(stderr, "lastcut: failed (nothing was cut): %s\n", result.reason.c_str());
      break;
    case drivers::SendOutcome::Interrupted:
      std::fprintf(stderr, "lastcut: INTERRUPTED (the machine may have cut part of the job; check it, nothing is resent): %s\n",
                   result.reason.c_str());
      break;
  }
  for (const auto& line : result.device_log) std::fprintf(stderr, "  %s\n", line.c_str());
  return result.outcome == drivers::SendOutcome::Failed ? 1 : 3;
}

int run_ports() {
  const auto ports = drivers::list_serial_ports();
  if (ports.empty()) {
    std::printf("no serial ports found\n");
    return 0;
  }
  std::printf("%-16s %-28s %s\n", "DEVICE", "STABLE NAME", "DESCRIPTION");
  for (const auto& port : ports) {
    std::string description = port.description;
    if (port.usb && !port.usb_manufacturer.empty()) description += " (" + port.usb_manufacturer + ")";
    std::printf("%-16s %-28s %s\n", port.device.c_str(), port.usb ? port.stable_name().c_str() : "-", description.c_str());
    if (!port.by_id_path.empty()) std::printf("%-16s %s\n", "", port.by_id_path.c_str());
  }
  return 0;
}

}  // namespace

void add_send_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SendOptions>();
  auto* send = app.add_subcommand("send", "send a cut file to a cutter and wait until it has finished");
  send->add_option("file", options->file, "HPGL or G-code file (any file for Modbus cutters)")->required()->check(CLI::ExistingFile);
  const drivers::CutterSettings defaults;
  for (const drivers::CutterOption& option : drivers::cutter_options()) {
    FlagInput& input = options->flags.emplace_back();
    input.option = &option;
    const std::string flag(option.flag), help(option.help);
    switch (option.kind) {
      case drivers::OptionKind::Switch: input.cli = send->add_flag(flag, input.on, help); break;
      case drivers::OptionKind::Integers:
      case drivers::OptionKind::Texts: input.cli = send->add_option(flag, input.texts, help)->delimiter(','); break;
      default: input.cli = send->add_option(flag, input.text, help); break;
    }
    if (option.kind == drivers::OptionKind::Integer || option.kind == drivers::OptionKind::Integers) input.cli->type_name("INT");
    if (option.kind == drivers::OptionKind::Number) input.cli->type_name("NUMBER");
    if (const std::string shown = drivers::option_text(defaults, option); !shown.empty()) input.cli->default_str(shown);
  }
  const auto cli_option = [&](const std::string& key) {
    for (const FlagInput& input : options->flags) {
      if (input.option->key == key) return input.cli;
    }
    return static_cast<CLI::Option*>(nullptr);
  };
  cli_option("port")->excludes(cli_option("modbus"));
  cli_option("modbus_map")->check(CLI::ExistingFile);
  send->add_option("--job-id", options->job_id, "job identity written to the PLC (default: file name)");
  send->callback([options, &exit_code] {
    drivers::CutterSettings settings;
    if (std::string problem = settings_from_flags(*options, settings); !problem.empty()) {
      std::fprintf(stderr, "lastcut: error: %s\n", problem.c_str());
      exit_code = 2;
      return;
    }
    exit_code = run_send(*options, settings);
  });

  auto* ports = app.add_subcommand("ports", "list serial ports with their USB ids (for stable port names in the configuration)");
  ports->callback([&exit_code] { exit_code = run_ports(); });
}

}  // namespace lastcut::cli
