#pragma once
// A libmosquitto client set up from [status]: the library initialised once per process,
// credentials and TLS applied. Used by the status publisher and by `lastcutd --check-config`.
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "engine/core/status.hpp"

struct mosquitto;

namespace lastcut::daemon {

// A new client (clean session) with `client_id`; `user_data` is handed to its callbacks.
// The caller owns it (mosquitto_destroy).
Result<mosquitto*> new_mqtt_client(const StatusConfig& config, const std::string& client_id, void* user_data);

// Connects once and waits up to `timeout_s` for the broker's answer: success, or one line
// saying why not ("connection refused", "not authorised", "no answer within 3 s").
Status check_broker(const StatusConfig& config, double timeout_s);

// libmosquitto's error text; for MOSQ_ERR_ERRNO the system's (e.g. "Connection refused").
std::string mqtt_error_text(int code);

}  // namespace lastcut::daemon
