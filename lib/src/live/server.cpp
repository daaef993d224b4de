// The live lab's HTTP server (live/server.hpp): the only file that includes httplib.h.
#include "opspace/live/server.hpp"

// Eigen (command.hpp) before httplib.h: <resolv.h>, which httplib.h includes, defines _res, a
// name Eigen's headers use.
#include "opspace/live/command.hpp"

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

namespace opspace::live {

struct Server::Impl {
  httplib::Server http;
  std::string page;
  CommandHandler on_command;
  int port = 0;
  std::thread thread;

  std::mutex mutex;
  std::condition_variable changed;
  std::string frame;         // the latest frame
  unsigned long long sequence = 0;  // of the latest frame
  bool stopping = false;
  std::atomic<int> streams{0};
  std::atomic<bool> opened{false};  // a page has opened its event stream

  // The page's own origins: the only Host and Origin values accepted.
  bool own_host(const std::string& host) const {
    return host == "127.0.0.1:" + std::to_string(port) || host == "localhost:" + std::to_string(port);
  }
  bool own_origin(const std::string& origin) const {
    return origin == "http://127.0.0.1:" + std::to_string(port) || origin == "http://localhost:" + std::to_string(port);
  }

  // One stream: waits for a frame newer than the last one sent, or sends a comment line every
  // second so that a closed connection is noticed.
  bool stream(unsigned long long& sent, httplib::DataSink& sink) {
    std::string message;
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait_for(lock, std::chrono::seconds(1), [&] { return stopping || sequence != sent; });
      if (stopping) return false;
      if (sequence != sent) {
        sent = sequence;
        message = "data: " + frame + "\n\n";
      } else {
        message = ": idle\n\n";
      }
    }
    return sink.write(message.data(), message.size());
  }
};

Server::Server(std::string page, int port, CommandHandler on_command) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.page = std::move(page);
  s.on_command = std::move(on_command);
  s.http.set_payload_max_length(kMaxCommandBytes);
  // A page's idle connection is closed after 1 s (httplib's default is 5 s), so Ctrl-C ends the
  // program within about a second with a page open.
  s.http.set_keep_alive_timeout(1);
  s.http.set_pre_routing_handler([&s](const httplib::Request& req, httplib::Response& res) {
    const bool foreign = !s.own_host(req.get_header_value("Host")) ||
                         (req.has_header("Origin") && !s.own_origin(req.get_header_value("Origin")));
    if (!foreign) return httplib::Server::HandlerResponse::Unhandled;
    res.status = 403;
    res.set_content("{\"error\":\"this program answers its own page only (http://127.0.0.1:" + std::to_string(s.port) +
                        "/)\"}",
                    "application/json");
    return httplib::Server::HandlerResponse::Handled;
  });
  s.http.Get("/", [&s](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.page, "text/html; charset=utf-8");
  });
  s.http.Get("/events", [&s](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    auto sent = std::make_shared<unsigned long long>(0);
    ++s.streams;
    s.opened = true;
    res.set_chunked_content_provider(
        "text/event-stream", [&s, sent](std::size_t, httplib::DataSink& sink) { return s.stream(*sent, sink); },
        [&s](bool) { --s.streams; });
  });
  s.http.Post("/command", [&s](const httplib::Request& req, httplib::Response& res) {
    if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0) {
      res.status = 415;
      res.set_content("{\"error\":\"a command is application/json\"}", "application/json");
      return;
    }
    try {
      s.on_command(req.body);
      res.set_content("{\"ok\":true}", "application/json");
    } catch (const CommandError& e) {
      res.status = 400;
      const nlohmann::json answer{{"error", e.what()}};
      res.set_content(answer.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
    }
  });
  s.port = port == 0 ? s.http.bind_to_any_port("127.0.0.1") : (s.http.bind_to_port("127.0.0.1", port) ? port : -1);
  if (s.port <= 0) {
    throw std::runtime_error("the live lab cannot listen on 127.0.0.1:" + std::to_string(port) +
                             (port == 0 ? "" : " (is the port taken? --port 0 picks a free one)"));
  }
  s.thread = std::thread([&s] { s.http.listen_after_bind(); });
}

Server::~Server() {
  {
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stopping = true;
  }
  impl_->changed.notify_all();
  impl_->http.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

int Server::port() const { return impl_->port; }

void Server::publish(std::string frame) {
  {
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->frame = std::move(frame);
    ++impl_->sequence;
  }
  impl_->changed.notify_all();
}

int Server::streams() const { return impl_->streams.load(); }

bool Server::opened() const { return impl_->opened.load(); }

}  // namespace opspace::live
