/// @file live/server.hpp
/// The live lab's HTTP server (cpp-httplib, Debian's libcpp-httplib-dev): the page, its frames
/// as Server-Sent Events, its commands by POST. Only this library file includes httplib.h; no
/// exercise or student-facing header includes this one.
///
/// It listens on 127.0.0.1 only, and answers 403 to a request whose Host or Origin is not the
/// page's own (http://127.0.0.1:PORT or http://localhost:PORT), so that a web page elsewhere
/// cannot drive a student's program (nor a DNS name rebound to 127.0.0.1); a command must be
/// application/json, at most kMaxCommandBytes (larger: 413), and is read before anything changes
/// (refused: 400, nothing changed).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace opspace::live {

/// Reads one command body; throws CommandError (live/command.hpp) to refuse it.
using CommandHandler = std::function<void(std::string_view body)>;

/// See the file comment. Serves from its own threads from construction to destruction.
class Server {
 public:
  /// Binds 127.0.0.1:`port` (0: a free port) and starts serving `page` at /, frames at
  /// /events and commands at /command. Throws std::runtime_error when it cannot bind.
  Server(std::string page, int port, CommandHandler on_command);
  /// Ends every stream and stops serving.
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  int port() const;  ///< the port bound
  /// The next frame (one JSON object) for every open stream; a frame not yet sent is replaced
  /// (latest wins): the caller never waits on the network.
  void publish(std::string frame);
  /// Streams open now.
  int streams() const;
  /// Whether a page has opened its event stream (/events) since construction, even if it has
  /// closed it since: the live run waits for this to start (live/run.hpp).
  bool opened() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace opspace::live
