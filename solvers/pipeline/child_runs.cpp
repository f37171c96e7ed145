#include "pipeline/child_runs.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace bb {
namespace {

struct Child {
  size_t index;
  pid_t pid;
  int out_fd;
  std::string output;
};

Child start(size_t index, const std::vector<std::string>& command) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  std::vector<char*> argv;
  for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // A child is a process of its own, not a rank of the MPI job that may have started this one.
  std::vector<char*> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMPI_", 5) != 0 && std::strncmp(*e, "PMIX_", 5) != 0 && std::strncmp(*e, "PMI_", 4) != 0)
      env.push_back(*e);
  env.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (rc != 0) {
    ::close(fds[0]);
    throw std::runtime_error("cannot start " + command[0] + ": " + std::strerror(rc));
  }
  return {index, pid, fds[0], {}};
}

ChildResult finish(Child& c) {
  ::close(c.out_fd);
  int status = 0;
  while (::waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
  }
  ChildResult r;
  r.output = std::move(c.output);
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

}  // namespace

void run_children(const std::vector<std::vector<std::string>>& commands, int jobs,
                  const std::function<void(size_t, const ChildResult&)>& done) {
  jobs = std::max(1, jobs);
  std::vector<Child> running;
  size_t next = 0;
  while (next < commands.size() || !running.empty()) {
    while (next < commands.size() && static_cast<int>(running.size()) < jobs) {
      running.push_back(start(next, commands[next]));
      ++next;
    }
    std::vector<pollfd> fds;
    for (const Child& c : running) fds.push_back({c.out_fd, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    }
    for (size_t k = running.size(); k-- > 0;) {
      if (fds[k].revents == 0) continue;
      char buffer[4096];
      const ssize_t n = ::read(running[k].out_fd, buffer, sizeof buffer);
      if (n > 0) {
        running[k].output.append(buffer, static_cast<size_t>(n));
        continue;
      }
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      Child c = std::move(running[k]);  // end of output: the process has closed its pipe
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
      const ChildResult r = finish(c);
      done(c.index, r);
    }
  }
}

}  // namespace bb
