#pragma once
// The operator's log. Under systemd (JOURNAL_STREAM set, stderr connected to the journal) each
// line goes to stderr with the syslog priority prefix "<N>" that journald turns into the
// entry's PRIORITY (sd-daemon(3)), so `journalctl -p warning -u lastcutd` shows exactly the
// problems. Elsewhere lines go to stderr with a UTC time stamp and the level in words.
#include <string>

namespace lastcut::daemon {

// Installs the default spdlog logger. `level`: trace | debug | info | warn | error.
void setup_operator_log(const std::string& level);
// Changes the level (SIGHUP reload).
void set_operator_log_level(const std::string& level);
// True when stderr is the journal stream of this process (JOURNAL_STREAM matches stderr).
bool stderr_is_journal();

}  // namespace lastcut::daemon
