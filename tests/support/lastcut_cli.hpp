#pragma once
// Running the real `lastcut` binary from a test, as an operator would: through the shell, its exit
// code, standard output and standard error. Test targets see LASTCUT_BINARY_DIR (cmake/lastcut_target.cmake).
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lastcut::test {

struct CommandRun {
  int exit_code = -1;
  bool crashed = false;  // killed by a signal (the shell reports that as 128 + signal)
  std::string out, err;
  // What an operator sees on the terminal, for messages that may go to either stream.
  std::string all() const { return out + err; }
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `lastcut ARGUMENTS` (arguments already quoted for the shell); its output goes through files in
// scratch_dir, which must exist.
inline CommandRun run_lastcut(const std::string& arguments, const std::filesystem::path& scratch_dir) {
  const std::filesystem::path out = scratch_dir / "stdout.txt", err = scratch_dir / "stderr.txt";
  const std::string command = std::string("'") + LASTCUT_BINARY_DIR + "/bin/lastcut' " + arguments + " >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CommandRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.crashed = !WIFEXITED(status) || run.exit_code > 128;
  run.out = read_text(out);
  run.err = read_text(err);
  return run;
}

}  // namespace lastcut::test
