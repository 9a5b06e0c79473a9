// Parser for grbl 1.1 reply lines.
#include "drivers/grbl/grbl_replies.hpp"

#include <array>
#include <charconv>

namespace lastcut::drivers::grbl {

namespace {

bool parse_int(std::string_view text, int& value) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

bool printable(std::string_view line) {
  for (unsigned char c : line) {
    if (c < 0x20 || c > 0x7e) return false;
  }
  return true;
}

// The MPos: or WPos: field of a status body ("Run|MPos:1.000,2.000,0.000|FS:..."), or "".
std::string_view position_field(std::string_view body) {
  size_t start = 0;
  while (start < body.size()) {
    size_t end = body.find('|', start);
    if (end == std::string_view::npos) end = body.size();
    const std::string_view field = body.substr(start, end - start);
    if (field.starts_with("MPos:") || field.starts_with("WPos:")) return field;
    start = end + 1;
  }
  return {};
}

constexpr std::array<std::string_view, 9> kStates{"Idle", "Run", "Hold", "Jog", "Alarm", "Door", "Check", "Home", "Sleep"};

}  // namespace

Reply classify_reply(std::string_view line) {
  Reply reply;
  reply.text = std::string(line);
  if (line.empty()) {
    reply.kind = ReplyKind::Empty;
    return reply;
  }
  if (!printable(line)) return reply;  // Garbage: binary noise or a wrong baud rate
  if (line == "ok") {
    reply.kind = ReplyKind::Ok;
    return reply;
  }
  if (line.starts_with("error:") && parse_int(line.substr(6), reply.code)) {
    reply.kind = ReplyKind::Error;
    return reply;
  }
  if (line.starts_with("ALARM:") && parse_int(line.substr(6), reply.code)) {
    reply.kind = ReplyKind::Alarm;
    return reply;
  }
  if (line.starts_with("<") && line.ends_with(">")) {
    const std::string_view body = line.substr(1, line.size() - 2);
    const std::string_view head = body.substr(0, body.find('|'));
    const auto colon = head.find(':');
    const std::string_view state = head.substr(0, colon);
    for (auto known : kStates) {
      if (state == known) {
        reply.kind = ReplyKind::Status;
        reply.state = std::string(state);
        if (colon != std::string_view::npos && !parse_int(head.substr(colon + 1), reply.substate)) reply.substate = -1;
        reply.position = std::string(position_field(body));
        return reply;
      }
    }
    return reply;
  }
  if (line.starts_with("Grbl ") || line.starts_with("GrblHAL ")) {
    reply.kind = ReplyKind::Banner;
    return reply;
  }
  if (line.starts_with("[OPT:") && line.ends_with("]")) {
    reply.kind = ReplyKind::Options;
    // [OPT:flags,planner_blocks,rx_buffer_bytes(,axes...)]
    const std::string_view fields = line.substr(5, line.size() - 6);
    const auto first = fields.find(',');
    const auto second = first == std::string_view::npos ? first : fields.find(',', first + 1);
    if (second != std::string_view::npos) {
      const auto third = fields.find(',', second + 1);
      int rx = -1;
      if (parse_int(fields.substr(second + 1, third == std::string_view::npos ? third : third - second - 1), rx) && rx > 0) {
        reply.rx_buffer_bytes = rx;
      }
      if (third != std::string_view::npos) {
        const auto fourth = fields.find(',', third + 1);
        int axes = -1;
        const auto axes_text = fields.substr(third + 1, fourth == std::string_view::npos ? fourth : fourth - third - 1);
        if (parse_int(axes_text, axes) && axes >= 1 && axes <= 9) reply.axis_count = axes;
      }
    }
    return reply;
  }
  if (line.starts_with("[") && line.ends_with("]")) {
    reply.kind = ReplyKind::Feedback;
    return reply;
  }
  if (line.starts_with("$") && line.find('=') != std::string_view::npos) {
    reply.kind = ReplyKind::Setting;
    return reply;
  }
  return reply;
}

}  // namespace lastcut::drivers::grbl
