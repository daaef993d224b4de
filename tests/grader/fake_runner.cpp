// A runner that answers the grader's requests (fd 3 in, fd 4 out, grader/protocol/protocol.hpp)
// by echoing each request's arguments as its value, in the way OPSPACE_FAKE_RUNNER names:
//   whole    header and payload in one write (grader/untrusted/runner_main.cpp's way)
//   split    header and payload cut into pieces of 1 to 5 bytes, 5 ms apart
//   trailing each answer whole, then 16 bytes of garbage after it, in the same write
//   garbage  16 bytes that are no header, then nothing more
//   partial  the header and half the payload, then it waits, answering nothing more
//   exit     reads the request, then ends without answering
//   history  instead of the echo, what this process has seen: the requests it has read, this
//            one included, and this request's number, as a 2x2 matrix of doubles (p1a's
//            mass_matrix: [[calls, 0], [number, 0]]), written whole
// For test_runner_process.cpp: what the grader makes of an untrusted runner's writes.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "protocol/protocol.hpp"

namespace {

namespace protocol = opspace::protocol;

bool read_exact(int fd, void* data, std::size_t size) {
  auto* p = static_cast<unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

void write_all(const unsigned char* p, std::size_t size) {
  while (size > 0) {
    const ssize_t n = write(protocol::kAnswerFd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) std::exit(0);
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

}  // namespace

int main() {
  const char* mode_env = std::getenv("OPSPACE_FAKE_RUNNER");
  const std::string mode = mode_env ? mode_env : "whole";
  for (double calls = 1;; ++calls) {
    protocol::Header request;
    if (!read_exact(protocol::kRequestFd, &request, sizeof request)) return 0;
    std::vector<unsigned char> arguments(request.size);
    if (!read_exact(protocol::kRequestFd, arguments.data(), arguments.size())) return 3;
    if (mode == "exit") return 0;
    if (mode == "history") {
      const double seen[4] = {calls, static_cast<double>(request.sequence), 0.0, 0.0};
      arguments.assign(reinterpret_cast<const unsigned char*>(seen), reinterpret_cast<const unsigned char*>(seen + 4));
    }
    const protocol::Header header{protocol::kAnswerMagic, request.sequence,
                                  static_cast<std::uint32_t>(protocol::Status::kValue),
                                  static_cast<std::uint32_t>(arguments.size())};
    std::vector<unsigned char> message(sizeof header + arguments.size());
    std::memcpy(message.data(), &header, sizeof header);
    if (!arguments.empty()) std::memcpy(message.data() + sizeof header, arguments.data(), arguments.size());
    if (mode == "whole" || mode == "history") {
      write_all(message.data(), message.size());
    } else if (mode == "split") {
      for (std::size_t at = 0, piece = 1; at < message.size(); at += piece, piece = piece % 5 + 1) {
        write_all(message.data() + at, std::min(piece, message.size() - at));
        usleep(5000);
      }
    } else if (mode == "trailing") {
      message.insert(message.end(), 16, 0xab);
      write_all(message.data(), message.size());
    } else if (mode == "garbage") {
      const std::vector<unsigned char> garbage(16, 0x5a);
      write_all(garbage.data(), garbage.size());
      pause();
    } else if (mode == "partial") {
      write_all(message.data(), sizeof header + arguments.size() / 2);
      pause();
    } else {
      return 4;
    }
  }
}
