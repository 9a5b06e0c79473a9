#pragma once
// Classifying one line grbl sends back (without its "\r\n").
// Formats from the grbl 1.1 interface documentation: "ok", "error:N", "ALARM:N",
// "<State|MPos:...|Bf:15,128|...>", "[OPT:V,15,128]", "[MSG:...]", "Grbl 1.1h ['$' for help]".
#include <string>
#include <string_view>

namespace lastcut::drivers::grbl {

enum class ReplyKind { Ok, Error, Alarm, Status, Banner, Options, Feedback, Setting, Empty, Garbage };

struct Reply {
  ReplyKind kind = ReplyKind::Garbage;
  int code = 0;                 // error:N / ALARM:N
  std::string state;            // Status: "Idle", "Run", "Hold", "Jog", "Alarm", "Door", "Check", "Home", "Sleep"
  int substate = -1;            // Status: Hold:0 -> 0, Hold:1 -> 1; -1 when absent
  std::string position;         // Status: the "MPos:x,y,z" or "WPos:x,y,z" field as sent; empty when absent
  int rx_buffer_bytes = -1;     // Options: the serial RX buffer size from [OPT:flags,blocks,rx]; -1 when absent
  int axis_count = -1;          // Options: grblHAL's 4th field [OPT:flags,blocks,rx,axes,...]; -1 when absent (grbl 1.1: X Y Z)
  std::string text;             // the raw line
};

Reply classify_reply(std::string_view line);

}  // namespace lastcut::drivers::grbl
