#include "cli/RenderWorkers.h"

#include "cli/ChildProcesses.h"
#include "cli/ChildSpawn.h"
#include "cli/InterruptGuard.h"
#include "cli/VariantsWorker.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace ivshadow {

RenderWorkers::RenderWorkers(int jobs)
    : workers_(std::size_t(jobs < 1 ? 1 : jobs)), executable_(currentExecutable()) {}

RenderWorkers::~RenderWorkers() {
  for (Worker& worker : workers_) {
    if (worker.pid < 0) continue;
    // A worker still rendering (the sweep ended by an error) is not waited for; an idle one
    // ends at the end of its stdin.
    if (worker.id >= 0) kill(worker.pid, SIGTERM);
    reap(worker);
  }
}

bool RenderWorkers::full() const {
  for (const Worker& worker : workers_)
    if (worker.id < 0) return false;
  return true;
}

bool RenderWorkers::empty() const {
  for (const Worker& worker : workers_)
    if (worker.id >= 0) return false;
  return true;
}

void RenderWorkers::spawn(Worker& worker) {
  // One socket serves as the worker's stdin and stdout: sending to a worker that died fails
  // with EPIPE (MSG_NOSIGNAL) instead of killing this process with SIGPIPE.
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
    throw std::runtime_error(std::string("cannot start a render worker: ") + std::strerror(errno));
  pid_t pid = -1;
  try {
    // Between variants a worker has nothing to say: a render process's last words (at its
    // exit) went to its log, deleted once read, never to the terminal.
    pid = spawnChild({executable_, "variants-worker"},
                     {ChildStream::descriptor(0, ends[1]), ChildStream::descriptor(1, ends[1]),
                      ChildStream::writeTo(2, "/dev/null")});
  } catch (const std::runtime_error&) {
    close(ends[0]);
    close(ends[1]);
    throw;
  }
  close(ends[1]);
  worker.pid = pid;
  worker.socket = ends[0];
  worker.received.clear();
  worker.last = false;
}

void RenderWorkers::send(Worker& worker) {
  const int log = open(worker.logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log >= 0) close(log);
  std::size_t done = 0;
  while (done < worker.request.size()) {
    const ssize_t n = ::send(worker.socket, worker.request.data() + done,
                             worker.request.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    // A worker that died before reading it is found at its end of file (readFrom).
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

void RenderWorkers::start(int id, const RenderOptions& options, const std::string& logPath) {
  Worker* chosen = nullptr;
  // A running idle worker first: its context is made and its driver warm.
  for (Worker& worker : workers_)
    if (worker.id < 0 && worker.pid >= 0 && !worker.last) {
      chosen = &worker;
      break;
    }
  if (chosen == nullptr) {
    for (Worker& worker : workers_)
      if (worker.id < 0) {
        chosen = &worker;
        break;
      }
  }
  if (chosen == nullptr) throw std::logic_error("RenderWorkers::start: every worker is busy");
  if (chosen->pid >= 0 && chosen->last) reap(*chosen);
  if (chosen->pid < 0) spawn(*chosen);
  chosen->id = id;
  chosen->retried = false;
  chosen->request = workerRequest(options, logPath);
  chosen->logPath = logPath;
  send(*chosen);
}

int RenderWorkers::reap(Worker& worker) {
  if (worker.socket >= 0) close(worker.socket);
  worker.socket = -1;
  int status = 0;
  pid_t pid;
  do {
    pid = waitpid(worker.pid, &status, 0);
  } while (pid < 0 && errno == EINTR);
  worker.pid = -1;
  if (pid < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::optional<VariantRenders::Finished> RenderWorkers::readFrom(Worker& worker) {
  char buffer[4096];
  ssize_t n;
  do {
    n = recv(worker.socket, buffer, sizeof buffer, 0);
  } while (n < 0 && errno == EINTR);
  if (n > 0) {
    worker.received.append(buffer, std::size_t(n));
    const std::size_t end = worker.received.find('\n');
    if (end == std::string::npos) return std::nullopt;
    const std::optional<WorkerAnswer> answer = WorkerAnswer::parse(worker.received.substr(0, end));
    worker.received.erase(0, end + 1);
    if (!answer || worker.id < 0)
      throw std::runtime_error("a render worker answered what it was not asked");
    const Finished finished{worker.id, answer->exitCode, worker.retried};
    worker.id = -1;
    worker.last = answer->last;
    return finished;
  }
  // The worker ended, or its socket broke, which it does not survive.
  const int exitCode = reap(worker);
  if (worker.id < 0) return std::nullopt;
  // A worker Ctrl-C reached before the sweep saw the signal is not started again either.
  if (!worker.retried && !stopping_ && !InterruptGuard::interrupted()) {
    // Whatever killed it may have been left by an earlier variant (or come from outside):
    // the variant gets a fresh process before it is called failed.
    spawn(worker);
    worker.retried = true;
    send(worker);
    return std::nullopt;
  }
  const Finished finished{worker.id, exitCode, worker.retried};
  worker.id = -1;
  return finished;
}

std::optional<VariantRenders::Finished> RenderWorkers::waitAny() {
  if (empty()) throw std::logic_error("RenderWorkers::waitAny: nothing is rendering");
  for (;;) {
    std::vector<pollfd> watched;
    std::vector<Worker*> owners;
    // Idle workers too: one that ends between variants is reaped now, not left a zombie.
    for (Worker& worker : workers_)
      if (worker.socket >= 0) {
        watched.push_back({worker.socket, POLLIN, 0});
        owners.push_back(&worker);
      }
    if (poll(watched.data(), nfds_t(watched.size()), -1) < 0) {
      if (errno == EINTR) return std::nullopt;
      throw std::runtime_error(std::string("waiting for the render workers: ") +
                               std::strerror(errno));
    }
    for (std::size_t k = 0; k < watched.size(); ++k) {
      if (watched[k].revents == 0) continue;
      if (const std::optional<Finished> finished = readFrom(*owners[k])) return finished;
    }
  }
}

void RenderWorkers::signalAll(int signal) {
  stopping_ = true;
  for (const Worker& worker : workers_)
    if (worker.pid >= 0) kill(worker.pid, signal);
}

}  // namespace ivshadow
