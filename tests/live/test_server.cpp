// The live lab's server over HTTP (lib/src/live/server.cpp): its page, its frames, and the
// requests it refuses without changing anything.
#include <doctest/doctest.h>

// Eigen (command.hpp) before httplib.h, whose <resolv.h> defines _res, a name Eigen uses.
#include "opspace/live/command.hpp"
#include "opspace/live/server.hpp"

#include <httplib.h>

#include <atomic>
#include <string>
#include <thread>

using opspace::live::CommandError;
using opspace::live::Server;

namespace {

// A server whose command handler counts what it accepted and refuses "bad".
struct Fixture {
  std::atomic<int> accepted{0};
  Server server{"<p>page</p>", 0, [this](std::string_view body) {
                  if (body == "bad") throw CommandError("bad command");
                  ++accepted;
                }};
  httplib::Client client{"127.0.0.1", server.port()};
  std::string own() const { return "http://127.0.0.1:" + std::to_string(server.port()); }
};

}  // namespace

TEST_CASE("the server gives its page and accepts its own page's commands") {
  Fixture f;
  const auto page = f.client.Get("/");
  REQUIRE(page);
  CHECK(page->status == 200);
  CHECK(page->body == "<p>page</p>");
  const auto ok = f.client.Post("/command", {{"Origin", f.own()}}, "good", "application/json");
  REQUIRE(ok);
  CHECK(ok->status == 200);
  CHECK(f.accepted == 1);
}

TEST_CASE("the server refuses foreign origins and hosts, malformed and oversized commands, and changes nothing") {
  Fixture f;
  const auto foreign = f.client.Post("/command", {{"Origin", "http://evil.example"}}, "good", "application/json");
  REQUIRE(foreign);
  CHECK_MESSAGE(foreign->status == 403, "a page elsewhere must not drive the student's program");
  const auto rebound = f.client.Get("/", {{"Host", "evil.example:" + std::to_string(f.server.port())}});
  REQUIRE(rebound);
  CHECK_MESSAGE(rebound->status == 403, "a DNS name rebound to 127.0.0.1 is not the page's host");
  const auto malformed = f.client.Post("/command", {{"Origin", f.own()}}, "bad", "application/json");
  REQUIRE(malformed);
  CHECK(malformed->status == 400);
  CHECK(malformed->body.find("bad command") != std::string::npos);
  const auto huge = f.client.Post("/command", {{"Origin", f.own()}}, std::string(100000, 'x'), "application/json");
  CHECK_MESSAGE((!huge || huge->status == 413), "a body over the cap is refused before it is read");
  const auto form = f.client.Post("/command", {{"Origin", f.own()}}, "good", "text/plain");
  REQUIRE(form);
  CHECK_MESSAGE(form->status == 415, "a command is JSON: a cross-site form cannot send one");
  CHECK_MESSAGE(f.accepted == 0, "no refused request reached the session");
}

TEST_CASE("the server streams the latest frame as a Server-Sent Event") {
  Fixture f;
  std::string received;
  std::atomic<bool> stop{false};
  std::thread publisher([&] {
    while (!stop) {
      f.server.publish("{\"frame\":1}");
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
  f.client.Get("/events", [&](const char* data, std::size_t size) {
    received.append(data, size);
    return received.find("\n\n") == std::string::npos;  // one event is enough
  });
  stop = true;
  publisher.join();
  CHECK(received.rfind("data: {\"frame\":1}\n\n", 0) == 0);
}

TEST_CASE("the server counts its page as opened once the event stream opens, not at GET /") {
  // The live run waits for opened() (live/run.hpp): the page's script opens /events once it can
  // draw, so the run's t = 0 is the page's.
  Fixture f;
  CHECK_FALSE(f.server.opened());
  REQUIRE(f.client.Get("/"));
  CHECK_MESSAGE(!f.server.opened(), "the page's HTML alone is not a page that draws the run");
  f.server.publish("{\"frame\":1}");
  std::string received;
  f.client.Get("/events", [&](const char* data, std::size_t size) {
    received.append(data, size);
    return received.find("\n\n") == std::string::npos;
  });
  CHECK(f.server.opened());
  CHECK(received.rfind("data: {\"frame\":1}\n\n", 0) == 0);
}
