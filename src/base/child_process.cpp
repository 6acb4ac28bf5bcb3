#include "rccm/base/child_process.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rccm {

namespace {

/// Writes all of `bytes` to `fd`; false when the reader is gone.
bool write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void child(int fd, const std::function<std::string()>& work, pid_t parent) {
  // Ended with the caller (a signal that ends it, a crash): no orphan goes on for minutes.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(1);
  // The first the kernel stops when the memory runs out, not the caller.
  if (std::FILE* oom = std::fopen("/proc/self/oom_score_adj", "w")) std::fputs("1000", oom), std::fclose(oom);
  // A signal ends the work (the caller's handler would only note it), and only its own pipe
  // stays open: a pipe of another child forked beside it (a sweep's cases) would otherwise
  // get its end of file only when this child ends.
  std::signal(SIGINT, SIG_DFL), std::signal(SIGTERM, SIG_DFL);
  if (fd != 3) ::dup2(fd, 3), fd = 3;
  ::close_range(4, ~0U, 0);
  const int null = ::open("/dev/null", O_WRONLY);
  ::dup2(null, STDOUT_FILENO), ::dup2(null, STDERR_FILENO), ::close(null);
  std::string bytes;
  bool answered = false;
  try {
    std::thread([&] {
      try {
        bytes = work(), answered = true;
      } catch (...) {
      }
    }).join();
  } catch (...) {
  }
  // _exit: the parent's buffers, atexit handlers and static objects are the parent's.
  ::_exit(answered && write_all(fd, bytes) ? 0 : 1);
}

}  // namespace

ChildOutcome run_in_child(const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot open a pipe: ") + std::strerror(errno));
  const pid_t parent = ::getpid(), pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(e));
  }
  if (pid == 0) ::close(fds[0]), child(fds[1], work, parent);
  ::close(fds[1]);
  ChildOutcome out;
  const auto reap = [pid] {
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
  return out;
}

}  // namespace rccm
