#pragma once
// The meaning of grbl 1.1 `error:N` and `ALARM:N` codes, for the log and the operator.
// Source: grbl 1.1 interface documentation (gnea/grbl wiki, "Interface" and the
// error_codes_en_US.csv / alarm_codes_en_US.csv tables shipped with grbl 1.1).
#include <string>

namespace lastcut::drivers::grbl {

// "Undefined feed rate: feed rate has not yet been set or is undefined." or "unknown error code N".
std::string error_meaning(int code);
// "Hard limit triggered: machine position is likely lost; re-homing is highly recommended." ...
std::string alarm_meaning(int code);

}  // namespace lastcut::drivers::grbl
