#pragma once
// A TCP port on 127.0.0.1 that nobody listens on now: the kernel's choice for port 0, bound and
// released at once. The server a test starts binds it right after (a race another program could
// win, so a harness that starts a server retries with a new port when the bind fails).

namespace lastcut::test {

// 0 when no socket can be made or bound.
int free_loopback_port();

}  // namespace lastcut::test
