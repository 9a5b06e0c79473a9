// PLACEHOLDER: replaced by the module that owns this command.
#include <cstdio>

#include "daemon/cli/commands.hpp"

namespace lastcut::cli {

void add_nest_command(CLI::App& app, int& exit_code) {
  auto* command = app.add_subcommand("nest", "(not built yet)");
  command->allow_extras();
  command->callback([&exit_code] {
    std::fprintf(stderr, "lastcut: error: 'nest' is not built yet\n");
    exit_code = 2;
  });
}

}  // namespace lastcut::cli
