#include "rccm/base/child_process.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <spawn.h>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rccm {

namespace {

/// The programs being waited for, for signal_children: a slot holds a pid from its start until
/// just before it is reaped (so the pid cannot be another process's yet).
std::atomic<pid_t> children[16];

/// Holds `pid` in a free slot while it lives (none free: it is not signalled).
class Registered {
 public:
  explicit Registered(pid_t pid) {
    for (auto& c : children) {
      pid_t free = 0;
      if (c.compare_exchange_strong(free, pid)) {
        slot_ = &c;
        return;
      }
    }
  }
  ~Registered() {
    if (slot_) slot_->store(0);
  }
  Registered(const Registered&) = delete;
  Registered& operator=(const Registered&) = delete;

 private:
  std::atomic<pid_t>* slot_ = nullptr;
};

}  // namespace

void signal_children(int signal) {
  for (const auto& c : children)
    if (const pid_t pid = c.load(); pid > 0) ::kill(pid, signal);
}

ChildOutcome run_program(const std::string& program, const std::vector<std::string>& args) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot open a pipe: ") + std::strerror(errno));
  // posix_spawn (a vfork and exec): safe from a threaded caller, and no fork handler runs
  // (OpenBLAS's joins its threads at a fork, which hung a sweep whose other cases used them).
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 3);  // the answer (dup2 drops O_CLOEXEC)
  for (int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO})
    posix_spawn_file_actions_addopen(&actions, fd, "/dev/null", fd == STDIN_FILENO ? O_RDONLY : O_WRONLY, 0);
  // Nothing else of the caller's (an MPI socket, a pipe without close-on-exec from its parent).
  posix_spawn_file_actions_addclosefrom_np(&actions, 4);
  // SIGINT and SIGTERM at their default in the program (one the caller ignores, as a shell's
  // background job does, too), none blocked: Ctrl-C to the process group ends it.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, ending;
  sigemptyset(&none);
  sigemptyset(&ending);
  sigaddset(&ending, SIGINT);
  sigaddset(&ending, SIGTERM);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &ending);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int started = ::posix_spawn(&pid, program.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(fds[1]);
  if (started != 0) {
    ::close(fds[0]);
    throw std::runtime_error("cannot start " + program + ": " + std::strerror(started));
  }
  ChildOutcome out;
  std::optional<Registered> registered(std::in_place, pid);
  const auto reap = [pid, &registered] {
    registered.reset();
    int status = 0;
    pid_t r;
    while ((r = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
    return r == pid ? status : -1;
  };
  try {
    char buffer[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      out.bytes.append(buffer, static_cast<std::size_t>(n));
    }
  } catch (...) {  // no memory for the answer: the child ended, not left waiting to write
    ::kill(pid, SIGKILL), ::close(fds[0]), reap();
    throw;
  }
  ::close(fds[0]);
  const int status = reap();
  out.finished = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  out.signal = status != -1 && WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  out.status = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

bool follow_caller(long caller) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != static_cast<pid_t>(caller)) return false;  // ended before the line above
  if (std::FILE* oom = std::fopen("/proc/self/oom_score_adj", "w")) std::fputs("1000", oom), std::fclose(oom);
  return true;
}

}  // namespace rccm
