#pragma once
// The subcommands of `lastcut`. Each add_*_command registers one CLI11 subcommand whose
// callback does the work and stores the process exit code in `exit_code`
// (0 success; non-zero after printing one clear line on stderr).
#include <CLI/CLI.hpp>

namespace lastcut::cli {

void add_flatten_command(CLI::App& app, int& exit_code);   // flatten_command.cpp: scan -> molds
void add_nest_command(CLI::App& app, int& exit_code);      // nest_command.cpp: molds -> layout
void add_toolpath_command(CLI::App& app, int& exit_code);  // toolpath_command.cpp: layout -> cut file
void add_send_command(CLI::App& app, int& exit_code);      // send_command.cpp: cut file -> cutter; also `ports`
void add_status_commands(CLI::App& app, int& exit_code);   // status_command.cpp: `status`, `requeue`, `cancel`
void add_generate_command(CLI::App& app, int& exit_code);  // generate_command.cpp: parametric sample lasts
void add_subdivide_command(CLI::App& app, int& exit_code); // subdivide_command.cpp: quad mesh -> Bezier surface
void add_hide_command(CLI::App& app, int& exit_code);     // hide_command.cpp: `hide load` (a stock hide onto a cutter)
void add_compare_command(CLI::App& app, int& exit_code);   // compare_command.cpp: mold vs reference pattern
void add_style_command(CLI::App& app, int& exit_code);     // style_command.cpp: `style transfer` (lines onto a last), and the two below
void add_pieces_command(CLI::App& app, int& exit_code);    // pieces_command.cpp: `pieces` (a style's pieces on a last)
void add_style_pieces_command(CLI::App& style, int& exit_code);  // pieces_command.cpp: `style pieces`, the same
void add_style_new_command(CLI::App& style, int& exit_code);  // style_new_command.cpp: `style new` (a reference last's forme to draw a style on)
void add_style_check_command(CLI::App& style, int& exit_code);  // style_check_command.cpp: `style check` (a style tried on its reference last)

}  // namespace lastcut::cli
