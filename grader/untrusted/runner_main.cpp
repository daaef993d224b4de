// The runner's loop: read a request on fd 3, evaluate it, answer on fd 4, until the grader
// closes fd 3. An exception thrown by the student's code is sent back as text; anything else
// (a crash, an exit) is the grader's to notice.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "serve.hpp"

namespace {

using opspace::protocol::Header;

// The requests' bytes, read as many at a time as the pipe holds: the grader writes a request
// whole, so that its header and its arguments come in one read.
class Inbox {
 public:
  explicit Inbox(int fd) : fd_(fd), bytes_(sizeof(Header) + opspace::protocol::kMaxPayload) {}

  bool read_exact(void* data, std::size_t size) {
    auto* p = static_cast<unsigned char*>(data);
    while (size > 0) {
      if (begin_ == end_) {
        const ssize_t n = read(fd_, bytes_.data(), bytes_.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        begin_ = 0;
        end_ = static_cast<std::size_t>(n);
      }
      const std::size_t take = std::min(size, end_ - begin_);
      std::memcpy(p, bytes_.data() + begin_, take);
      begin_ += take;
      p += take;
      size -= take;
    }
    return true;
  }

 private:
  int fd_;
  std::vector<unsigned char> bytes_;
  std::size_t begin_ = 0, end_ = 0;
};

bool write_exact(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The header and the payload in one write (`message`, reused): a pipe delivers a write of up to
// PIPE_BUF bytes whole, so the grader reads the answer in one read, where two writes cost it a
// second poll and read, and could wake it for the header alone (issue 50: the system calls of
// the control ticks' exchanges were most of a simulated test's time).
bool answer(std::uint32_t sequence, opspace::protocol::Status status, const std::vector<unsigned char>& payload,
            std::vector<unsigned char>& message) {
  const Header header{opspace::protocol::kAnswerMagic, sequence, static_cast<std::uint32_t>(status),
                      static_cast<std::uint32_t>(payload.size())};
  message.resize(sizeof header + payload.size());
  std::memcpy(message.data(), &header, sizeof header);
  if (!payload.empty()) std::memcpy(message.data() + sizeof header, payload.data(), payload.size());
  return write_exact(opspace::protocol::kAnswerFd, message.data(), message.size());
}

}  // namespace

int main() {
  namespace protocol = opspace::protocol;
  std::vector<unsigned char> payload, message;
  Inbox requests(protocol::kRequestFd);
  for (;;) {
    Header request;
    if (!requests.read_exact(&request, sizeof request)) return 0;  // the grader is done
    if (request.magic != protocol::kRequestMagic || request.size > protocol::kMaxPayload) return 3;
    payload.resize(request.size);
    if (!requests.read_exact(payload.data(), payload.size())) return 3;
    protocol::Reader in(payload.data(), payload.size());
    protocol::Writer out;
    protocol::Status status = protocol::Status::kValue;
    try {
      if (!opspace::runner::dispatch(static_cast<protocol::Function>(request.code), in, out))
        status = protocol::Status::kUnknownFunction;
    } catch (const std::exception& e) {
      status = protocol::Status::kException;
      const std::string text = std::string(e.what()).substr(0, protocol::kMaxExceptionText);
      out = protocol::Writer();
      out.raw(text.data(), text.size());
    } catch (...) {
      status = protocol::Status::kException;
      const std::string text = "an exception that is not a std::exception";
      out = protocol::Writer();
      out.raw(text.data(), text.size());
    }
    const std::vector<unsigned char> none;
    if (!answer(request.sequence, status, status == protocol::Status::kUnknownFunction ? none : out.bytes(), message))
      return 0;
  }
}
