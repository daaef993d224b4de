// Each grading's groups (grading_group.hpp). cgroup v1: under each controller's own mount, a
// folder beside the grader's own group: cpu (the grader and all it starts, default cpu.shares
// 1024 like every group there), memory and pids (the programs it starts). cgroup v2, from the
// root of the grader's view only (elsewhere its own group holds processes and may not hand
// controllers to children): a folder for the grader (cpu, default cpu.weight) and a sibling for
// its programs (cpu, memory.max, pids.max). Programs enter by the grader writing their pid into
// cgroup.procs; their children inherit the group. At exit the grader moves back and removes
// its folders.
#include "sandbox/grading_group.hpp"

#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/process_ended.hpp"

namespace opspace::grading {

namespace {

constexpr const char* kPrefix = "opspace-grading-";

struct State {
  std::string cpu_parent, cpu_own;     // the grader's CPU group, and where it is left to
  std::vector<std::string> programs;   // the programs' groups (v1: memory, pids; v2: one)
  std::string kills_file;              // memory.oom_control (v1) or memory.events (v2)
  unsigned long long memory_budget = 0;  // enforced by a group
  unsigned long long requested = 0;      // asked for (address_space_within_budget)
};
State groups;

bool write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.flush();
  return static_cast<bool>(out);
}

bool exists(const std::string& path) {
  struct stat s {};
  return stat(path.c_str(), &s) == 0;
}

void leave() {
  if (!groups.cpu_own.empty()) {
    write_text(groups.cpu_parent + "/cgroup.procs", std::to_string(getpid()));
    rmdir(groups.cpu_own.c_str());
  }
  for (const std::string& group : groups.programs) rmdir(group.c_str());
}

// This process's group under `controller` ("cpu" for v1, "" for v2's single hierarchy), from
// /proc/self/cgroup ("1:cpu,cpuacct:/path", "0::/path").
std::string own_group(const std::string& controller) {
  std::ifstream in("/proc/self/cgroup");
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    std::stringstream names(line.substr(first + 1, second - first - 1));
    for (std::string name; std::getline(names, name, ',');)
      if (name == controller || (controller.empty() && line.compare(0, 3, "0::") == 0)) return line.substr(second + 1);
  }
  return "";
}

// The folder of this process's v1 group under `controller`'s mount, if that controller is
// mounted with `probe` in it.
std::string v1_parent(const std::vector<std::string>& mounts, const std::string& controller, const std::string& probe) {
  const std::string group = own_group(controller);
  if (group.empty()) return "";
  for (const std::string& mount : mounts)
    if (exists(mount + "/" + probe)) return mount + (group == "/" ? "" : group);
  return "";
}

// The groups of graders that have ended, left behind by a kill: removed (empty groups only).
void remove_stale(const std::string& parent) {
  DIR* dir = opendir(parent.c_str());
  if (!dir) return;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name.compare(0, std::char_traits<char>::length(kPrefix), kPrefix) != 0) continue;
    const long pid = std::strtol(name.c_str() + std::char_traits<char>::length(kPrefix), nullptr, 10);
    if (process_ended(pid)) rmdir((parent + "/" + name).c_str());
  }
  closedir(dir);
}

// A new folder `name` under `parent` (stale siblings removed first); empty if none can be made.
std::string make_group(const std::string& parent, const std::string& name) {
  remove_stale(parent);
  const std::string own = parent + "/" + name;
  if (mkdir(own.c_str(), 0755) != 0 && errno != EEXIST) return "";
  return own;
}

std::string own_name(const char* suffix = "") { return kPrefix + std::to_string(getpid()) + suffix; }

bool join_cpu(const std::string& parent) {
  const std::string own = make_group(parent, own_name());
  if (own.empty()) return false;
  if (!write_text(own + "/cgroup.procs", std::to_string(getpid()))) {
    rmdir(own.c_str());
    return false;
  }
  groups.cpu_parent = parent;
  groups.cpu_own = own;
  return true;
}

std::string mib(unsigned long long bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// A programs' group with `limit_file` set to `value`; kept in groups.programs. Empty if none.
std::string limited_group(const std::string& parent, const char* suffix, const std::string& limit_file,
                          unsigned long long value) {
  if (parent.empty() || value == 0) return "";
  const std::string own = make_group(parent, own_name(suffix));
  if (own.empty()) return "";
  if (!write_text(own + "/" + limit_file, std::to_string(value))) {
    rmdir(own.c_str());
    return "";
  }
  groups.programs.push_back(own);
  return own;
}

GradingGroups join_v1(const GradingBudget& budget) {
  GradingGroups where;
  const std::string cpu = v1_parent({"/sys/fs/cgroup/cpu", "/sys/fs/cgroup/cpu,cpuacct"}, "cpu", "cpu.shares");
  if (!cpu.empty() && join_cpu(cpu)) where.cpu = "cgroup v1 cpu:" + groups.cpu_own.substr(groups.cpu_own.rfind('/'));
  const std::string memory = limited_group(v1_parent({"/sys/fs/cgroup/memory"}, "memory", "memory.limit_in_bytes"), "",
                                           "memory.limit_in_bytes", budget.memory_bytes);
  if (!memory.empty()) {
    // With swap, the same bound on memory and swap together (a file only where swap is counted).
    if (exists(memory + "/memory.memsw.limit_in_bytes"))
      write_text(memory + "/memory.memsw.limit_in_bytes", std::to_string(budget.memory_bytes));
    groups.kills_file = memory + "/memory.oom_control";
    groups.memory_budget = budget.memory_bytes;
    where.memory = "cgroup v1 memory:" + memory.substr(memory.rfind('/')) + ", " + mib(budget.memory_bytes);
  }
  const std::string pids =
      limited_group(v1_parent({"/sys/fs/cgroup/pids"}, "pids", "cgroup.procs"), "", "pids.max", budget.processes);
  if (!pids.empty()) where.pids = "cgroup v1 pids:" + pids.substr(pids.rfind('/')) + ", " + std::to_string(budget.processes);
  return where;
}

GradingGroups join_v2(const GradingBudget& budget) {
  GradingGroups where;
  const std::string root = "/sys/fs/cgroup";
  if (!exists(root + "/cgroup.controllers") || own_group("") != "/") return where;
  for (const char* controller : {"+cpu", "+memory", "+pids"}) write_text(root + "/cgroup.subtree_control", controller);
  if (exists(root + "/cgroup.subtree_control") && join_cpu(root)) where.cpu = "cgroup v2:/" + own_name();
  const std::string programs = make_group(root, own_name("-programs"));
  if (programs.empty()) return where;
  groups.programs.push_back(programs);
  if (budget.memory_bytes > 0 && write_text(programs + "/memory.max", std::to_string(budget.memory_bytes))) {
    write_text(programs + "/memory.swap.max", "0");
    groups.kills_file = programs + "/memory.events";
    groups.memory_budget = budget.memory_bytes;
    where.memory = "cgroup v2:/" + own_name("-programs") + " memory.max, " + mib(budget.memory_bytes);
  }
  if (budget.processes > 0 && write_text(programs + "/pids.max", std::to_string(budget.processes)))
    where.pids = "cgroup v2:/" + own_name("-programs") + " pids.max, " + std::to_string(budget.processes);
  return where;
}

}  // namespace

GradingGroups join_grading_groups(const GradingBudget& budget) {
  static bool joined = false;
  if (joined) return {};
  groups.requested = budget.memory_bytes;
  if (geteuid() != 0) return {};
  joined = true;
  std::atexit(leave);
  GradingGroups where = join_v1(budget);
  if (where.cpu.empty() && where.memory.empty() && where.pids.empty()) where = join_v2(budget);
  return where;
}

void admit_to_grading_groups(pid_t pid) {
  for (const std::string& group : groups.programs)
    // A program that has already ended (ESRCH) needs no group.
    if (!write_text(group + "/cgroup.procs", std::to_string(pid)) && kill(pid, 0) == 0)
      throw std::runtime_error("the grader could not put a program in its grading's group " + group);
}

unsigned long long grading_memory_kills() {
  if (groups.kills_file.empty()) return 0;
  std::ifstream in(groups.kills_file);
  for (std::string name; in >> name;) {
    unsigned long long count = 0;
    if (!(in >> count)) break;
    if (name == "oom_kill") return count;
  }
  return 0;
}

unsigned long long grading_memory_group_budget() { return groups.memory_budget; }

unsigned long long address_space_within_budget(unsigned long long own) {
  // 0 stays 0: a program without an address-space limit (a sanitized runner reserves terabytes).
  if (groups.memory_budget > 0 || groups.requested == 0 || own == 0) return own;
  return std::min(own, groups.requested);
}

unsigned long long machine_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? static_cast<unsigned long long>(pages) * static_cast<unsigned long long>(size) : 0;
}

GradingBudget grading_budget(unsigned long long memory_mib) {
  GradingBudget budget;
  budget.memory_bytes = memory_mib > 0 ? memory_mib << 20 : machine_memory();
  budget.processes = (64 + 16) * static_cast<unsigned long long>(std::max(1u, std::thread::hardware_concurrency()));
  return budget;
}

}  // namespace opspace::grading
