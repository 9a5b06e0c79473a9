// Fuzz target: grbl's replies and status lines (drivers/grbl/grbl_replies.hpp). The input is what
// a controller sends back over the serial line, cut into lines at '\n' with a trailing '\r'
// removed as the grbl session does; each line goes through classify_reply, and error and alarm
// codes through error_meaning / alarm_meaning, as the session logs them. A cutter on a wrong baud
// rate, a noisy USB cable or a grbl fork sends anything at all.
//
// What counts as fine: every line is classified (Garbage at worst). classify_reply documents no
// exception, so none is caught: any throw (e.g. std::out_of_range from a number conversion),
// crash or sanitizer report surfaces as a libFuzzer crash.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/grbl/grbl_codes.hpp"
#include "drivers/grbl/grbl_replies.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace grbl = lastcut::drivers::grbl;
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  while (!rest.empty()) {
    const size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const grbl::Reply reply = grbl::classify_reply(line);
    if (reply.kind == grbl::ReplyKind::Error) (void)grbl::error_meaning(reply.code);
    if (reply.kind == grbl::ReplyKind::Alarm) (void)grbl::alarm_meaning(reply.code);
  }
  return 0;
}
