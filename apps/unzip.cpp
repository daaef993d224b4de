// hw2-unzip: a zip a student uploaded, opened as hostile, for scripts/regrade (through
// deploy/collect_submission.sh).
//   hw2-unzip ZIP DEST
// DEST must not exist: it is made, and holds the zip's folders and regular files, or nothing.
// Two processes: the archive is parsed by libarchive (Debian's libarchive13) in a child started in
// the grader's sandbox (grader/trusted/sandbox/sandbox.hpp: another user when root, namespaces, no
// network, the seccomp filter, limits on memory and CPU), which writes nothing: it sends each
// entry's kind, path and bytes down a pipe. This process, which parses nothing, checks each one
// before it writes it into DEST and stops at the first one refused:
// - kinds: a folder or a regular file; a symbolic link, a hard link, a device or a FIFO is refused;
// - paths: relative, no '..' or '.' or empty part, no control character, at most kLongestPath
//   bytes and kDeepestPath parts, each written once (O_EXCL, O_NOFOLLOW);
// - at most kMostEntries entries and kLargestTotal bytes in all (counted as they arrive: a zip
//   bomb is stopped at the bound, not after), within kLongestSeconds;
// - a zip inside the zip is not opened: it is left out, with a note.
// The protections the machine lacks are left off (sandbox.hpp) and named on stderr.
// Exit 0: DEST written; stdout the notes, one a line. Exit 1: refused or unreadable; stdout one
// line saying why, DEST removed. Exit 2: usage.
#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sandbox/sandbox.hpp"

namespace {

namespace fs = std::filesystem;
using opspace::grading::SandboxSpec;

// The largest zip opened (bytes): Gradescope's uploads are far smaller; the exercise files are 1 MiB at most each.
constexpr std::uintmax_t kLargestZip = std::uintmax_t{64} << 20;
// All its files together, uncompressed (bytes): five exercise files of 1 MiB at most (the grader
// refuses larger ones) and room for a student's other files (a report, pictures).
constexpr std::uintmax_t kLargestTotal = std::uintmax_t{64} << 20;
// Entries: deploy/collect_submission.sh reads at most 500 files of a submission.
constexpr std::size_t kMostEntries = 1000;
// A path's bytes and parts: collect_submission.sh looks 6 folders deep; a name is at most 255.
constexpr std::size_t kLongestPath = 1024, kDeepestPath = 16;
// The whole extraction: libarchive inflates hundreds of MB a second; 64 MiB takes well under one.
constexpr int kLongestSeconds = 30;
// The child's memory (libarchive's zip reader keeps a window and the central directory).
constexpr unsigned long long kChildMemory = 256ull << 20;

// --- the child: parses, writes nothing but the stream ------------------------------------------
// The stream: per entry "KIND PATHLENGTH\nPATH" (KIND f: a regular file, d: a folder, l: a
// symbolic link, h: a hard link, o: anything else), then for a file its bytes as "N\nBYTES"
// chunks ending with "0\n"; at the end "end\n", or "error N\nMESSAGE".
bool put(const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(1, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w, n -= static_cast<std::size_t>(w);
  }
  return true;
}
bool put(const std::string& s) { return put(s.data(), s.size()); }

int child() {
  archive* a = archive_read_new();
  archive_read_support_format_zip(a);
  archive_read_support_filter_none(a);
  const auto error = [&] {
    const std::string why = archive_error_string(a) ? archive_error_string(a) : "not a zip";
    put("error " + std::to_string(why.size()) + "\n" + why);
    return 1;
  };
  if (archive_read_open_fd(a, 0, 1 << 16) != ARCHIVE_OK) return error();
  archive_entry* e = nullptr;
  for (;;) {
    const int r = archive_read_next_header(a, &e);
    if (r == ARCHIVE_EOF) break;
    if (r != ARCHIVE_OK && r != ARCHIVE_WARN) return error();
    const char* path = archive_entry_pathname(e);
    const std::string name = path ? path : "";
    const auto type = archive_entry_filetype(e);
    const char kind = archive_entry_hardlink(e) ? 'h' : type == AE_IFREG ? 'f' : type == AE_IFDIR ? 'd' : type == AE_IFLNK ? 'l' : 'o';
    if (!put(std::string(1, kind) + " " + std::to_string(name.size()) + "\n" + name)) return 1;
    if (kind != 'f') continue;
    char buffer[1 << 16];
    for (;;) {
      const la_ssize_t n = archive_read_data(a, buffer, sizeof buffer);
      if (n < 0) return error();
      if (!put(std::to_string(n) + "\n") || !put(buffer, static_cast<std::size_t>(n))) return 1;
      if (n == 0) break;
    }
  }
  put("end\n");
  archive_read_free(a);
  return 0;
}

// --- the parent: checks and writes ------------------------------------------------------------
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads from the child's pipe within the deadline.
class Stream {
 public:
  Stream(int fd, std::chrono::steady_clock::time_point deadline) : fd_(fd), deadline_(deadline) {}
  void exact(char* out, std::size_t n) {
    while (n > 0) {
      if (at_ == size_) fill();
      const std::size_t k = std::min(n, size_ - at_);
      std::memcpy(out, buffer_ + at_, k);
      at_ += k, out += k, n -= k;
    }
  }
  std::string line() {  // up to '\n', at most 32 bytes (a kind and a number)
    std::string s;
    for (char c = 0; exact(&c, 1), c != '\n';) {
      s += c;
      if (s.size() > 32) throw Refused("the archive reader sent what it should not (a bug, or a broken reader)");
    }
    return s;
  }

 private:
  void fill() {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - std::chrono::steady_clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) == 0)
      throw Refused("opening it took more than " + std::to_string(kLongestSeconds) + " s");
    const ssize_t n = ::read(fd_, buffer_, sizeof buffer_);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return fill();
    if (n <= 0) throw Refused("the archive reader stopped (beyond its memory or CPU time, or crashed): a broken zip");
    at_ = 0, size_ = static_cast<std::size_t>(n);
  }
  int fd_;
  std::chrono::steady_clock::time_point deadline_;
  char buffer_[1 << 16];
  std::size_t at_ = 0, size_ = 0;
};

std::size_t number(const std::string& text) {
  if (text.empty() || text.size() > 12 || text.find_first_not_of("0123456789") != std::string::npos)
    throw Refused("the archive reader sent what it should not (a bug, or a broken reader)");
  return std::stoull(text);
}

// A path as shown in a note: printable ASCII, at most 120 characters.
std::string shown(const std::string& path) {
  std::string out;
  for (const char c : path.substr(0, 120)) out += c >= 0x20 && c < 0x7f ? c : '?';
  return "'" + out + "'";
}

// The parts of an entry's path, or Refused.
std::vector<std::string> parts_of(const std::string& path, char kind) {
  if (path.empty()) throw Refused("an entry has no name");
  if (path.size() > kLongestPath) throw Refused("an entry's path is longer than " + std::to_string(kLongestPath) + " bytes");
  if (path[0] == '/') throw Refused("an entry's path is absolute: " + shown(path));
  std::vector<std::string> parts;
  std::string part;
  for (std::size_t i = 0; i <= path.size(); ++i) {
    if (i < path.size() && path[i] != '/') {
      if (static_cast<unsigned char>(path[i]) < 0x20 || path[i] == 0x7f) throw Refused("an entry's path holds a control character: " + shown(path));
      part += path[i];
      continue;
    }
    const bool trailing = i == path.size() && kind == 'd';
    if (part == "..") throw Refused("an entry's path leaves the folder: " + shown(path));
    if ((part.empty() || part == ".") && !(trailing && part.empty())) throw Refused("an entry's path has an empty or '.' part: " + shown(path));
    if (!part.empty()) parts.push_back(part);
    part.clear();
  }
  if (parts.size() > kDeepestPath) throw Refused("an entry's path is deeper than " + std::to_string(kDeepestPath) + " folders");
  return parts;
}

bool zip_name(const std::string& name) {
  if (name.size() < 4) return false;
  std::string end = name.substr(name.size() - 4);
  for (char& c : end) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return end == ".zip" || end == ".jar";
}

// Reads the stream into the folder `dest` (a descriptor), checking each entry. Returns the notes.
std::vector<std::string> extract(Stream& in, int dest) {
  std::vector<std::string> notes;
  std::size_t entries = 0;
  std::uintmax_t total = 0;
  for (;;) {
    const std::string head = in.line();
    if (head == "end") return notes;
    const std::size_t space = head.find(' ');
    if (space == std::string::npos) throw Refused("the archive reader sent what it should not (a bug, or a broken reader)");
    const std::size_t length = number(head.substr(space + 1));
    if (length > kLongestPath + 1) throw Refused("an entry's path is longer than " + std::to_string(kLongestPath) + " bytes");
    std::string text(length, '\0');
    in.exact(text.data(), length);
    if (head.compare(0, space, "error") == 0) throw Refused("not a zip it can read: " + shown(text));
    const char kind = head[0];
    if (space != 1 || std::string("fdlho").find(kind) == std::string::npos)
      throw Refused("the archive reader sent what it should not (a bug, or a broken reader)");
    if (++entries > kMostEntries) throw Refused("more than " + std::to_string(kMostEntries) + " entries");
    if (kind == 'l') throw Refused("it holds a symbolic link: " + shown(text));
    if (kind == 'h') throw Refused("it holds a hard link: " + shown(text));
    if (kind == 'o') throw Refused("it holds an entry that is neither a file nor a folder (a device?): " + shown(text));
    const std::vector<std::string> parts = parts_of(text, kind);
    int at = dest;  // the folders on the way, made as needed; never a link (O_NOFOLLOW)
    std::vector<int> opened;
    const auto close_all = [&] {
      for (const int fd : opened) ::close(fd);
    };
    const std::size_t folders = kind == 'd' ? parts.size() : parts.size() - 1;
    for (std::size_t k = 0; k < folders; ++k) {
      if (::mkdirat(at, parts[k].c_str(), 0700) != 0 && errno != EEXIST) {
        close_all();
        throw Refused("a folder cannot be made for " + shown(text) + ": " + std::strerror(errno));
      }
      const int next = ::openat(at, parts[k].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
      if (next < 0) {
        close_all();
        throw Refused("a folder cannot be made for " + shown(text) + " (a file of that name came first)");
      }
      opened.push_back(next), at = next;
    }
    int out = -1;
    bool nested = false;
    if (kind == 'f') {
      nested = zip_name(parts.back());
      if (nested) notes.push_back(shown(text) + " is a zip inside the zip: not opened (upload the files, or one zip of them)");
      else if ((out = ::openat(at, parts.back().c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600)) < 0) {
        close_all();
        throw Refused("an entry cannot be written, or is there twice: " + shown(text));
      }
      for (;;) {  // its chunks, counted as they come; or the reader's error, part way
        const std::string line = in.line();
        if (line.rfind("error ", 0) == 0) {
          std::string why(std::min<std::size_t>(number(line.substr(6)), kLongestPath), '\0');
          in.exact(why.data(), why.size());
          if (out >= 0) ::close(out);
          close_all();
          throw Refused("not a zip it can read: " + shown(why));
        }
        const std::size_t n = number(line);
        if (n == 0) break;
        total += n;
        if (total > kLargestTotal) {
          if (out >= 0) ::close(out);
          close_all();
          throw Refused("more than " + std::to_string(kLargestTotal >> 20) + " MiB uncompressed (a zip bomb?)");
        }
        std::vector<char> chunk(n);
        in.exact(chunk.data(), n);
        if (out >= 0 && ::write(out, chunk.data(), n) != static_cast<ssize_t>(n)) {
          ::close(out);
          close_all();
          throw Refused("writing " + shown(text) + " failed");
        }
      }
      if (out >= 0) ::close(out);
    }
    close_all();
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--child") return child();
  if (argc != 3 || argv[1][0] == '-') {
    std::cerr << "usage: hw2-unzip ZIP DEST\n  extracts a student's zip into the new folder DEST, refusing what is unsafe\n";
    return 2;
  }
  const std::string zip = argv[1], dest = argv[2];
  using namespace opspace::grading;
  try {
    const int zip_fd = ::open(zip.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st {};
    if (zip_fd < 0 || ::fstat(zip_fd, &st) != 0 || !S_ISREG(st.st_mode)) throw Refused("it cannot be read as a regular file");
    if (static_cast<std::uintmax_t>(st.st_size) > kLargestZip)
      throw Refused("it is larger than " + std::to_string(kLargestZip >> 20) + " MiB");
    if (::mkdir(dest.c_str(), 0700) != 0) {
      std::cout << "hw2-unzip: " << dest << " cannot be made (it must not exist): " << std::strerror(errno) << "\n";
      return 2;
    }
    const int dest_fd = ::open(dest.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    try {
      int pipe_fds[2];
      if (dest_fd < 0 || ::pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error("no pipe");
      become_subreaper();
      SandboxSpec spec;
      const std::string self = fs::canonical("/proc/self/exe").string();
      spec.argv = {self, "--child"};
      spec.work_dir = fs::absolute(dest).string();  // empty, and read-only to it
      spec.visible = {self};
      spec.limits.address_space = kChildMemory, spec.limits.cpu_seconds = kLongestSeconds, spec.limits.file_size = 1;
      spec.limits.open_files = 16, spec.limits.processes = 1;
      spec.fds = {{0, zip_fd}, {1, pipe_fds[1]}};
      spec.account = grading_account("");  // as root: an unprivileged account (none otherwise)
      const Sandboxed reader = spawn(spec);
      // What the machine did not allow (no namespaces without root or user namespaces): said, on stderr.
      if (!reader.protections.missing().empty()) std::cerr << "hw2-unzip: the archive reader ran without: " << reader.protections.missing() << "\n";
      ::close(pipe_fds[1]);
      Stream in(pipe_fds[0], std::chrono::steady_clock::now() + std::chrono::seconds(kLongestSeconds));
      std::vector<std::string> notes;
      try {
        notes = extract(in, dest_fd);
      } catch (...) {
        kill_all(reader);
        throw;
      }
      kill_all(reader);
      for (const std::string& n : notes) std::cout << n << "\n";
      return 0;
    } catch (...) {
      if (dest_fd >= 0) ::close(dest_fd);
      std::error_code ec;
      fs::remove_all(dest, ec);
      throw;
    }
  } catch (const std::exception& e) {
    std::cout << e.what() << "\n";
    return 1;
  }
}
