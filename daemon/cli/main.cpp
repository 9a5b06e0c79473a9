// lastcut: the operator's command line. Each subcommand lives in its own *_command.cpp.
#include <cstdio>
#include <exception>

#include "daemon/cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"lastcut: shoe-last scans to molds, layouts and cut files"};
  app.require_subcommand(1);
  int exit_code = 0;
  lastcut::cli::add_flatten_command(app, exit_code);
  lastcut::cli::add_nest_command(app, exit_code);
  lastcut::cli::add_toolpath_command(app, exit_code);
  lastcut::cli::add_send_command(app, exit_code);
  lastcut::cli::add_status_commands(app, exit_code);
  lastcut::cli::add_generate_command(app, exit_code);
  lastcut::cli::add_subdivide_command(app, exit_code);
  lastcut::cli::add_compare_command(app, exit_code);
  lastcut::cli::add_hide_command(app, exit_code);
  lastcut::cli::add_style_command(app, exit_code);
  lastcut::cli::add_pieces_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const std::exception& error) {
    // Commands report their own failures; this is the last line of defence, still one line.
    std::fprintf(stderr, "lastcut: error: %s\n", error.what());
    return 1;
  }
  return exit_code;
}
