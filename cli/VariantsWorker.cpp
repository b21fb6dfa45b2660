#include "cli/VariantsWorker.h"

#include "cli/RenderSession.h"

#include <fcntl.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>

namespace ivshadow {
namespace {

void writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the sweep went away; the next read of stdin ends the worker
    done += std::size_t(n);
  }
}

std::optional<RenderOptions> renderOptions(const nlohmann::json& request, std::string& logPath) {
  if (!request.is_object()) return std::nullopt;
  try {
    RenderOptions options;
    options.scene = request.at("scene").get<std::string>();
    options.output = request.at("output").get<std::string>();
    options.size = request.at("size").get<std::string>();
    options.frames = request.at("frames").get<int>();
    options.statsPath = request.at("stats").get<std::string>();
    options.assignments = request.at("sets").get<std::vector<std::string>>();
    options.transparency = request.at("transparency").get<std::string>();
    logPath = request.at("log").get<std::string>();
    return options;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// Whether every line a render said is one of Coin's infos (the choice `renderer AUTO` made).
// A warning may have been said as the scene's nodes read or built what they keep (a shape
// the tracer leaves out, a defective shape): the next render then reads the scene afresh and
// says it again, as a render process of its own would (RenderSession.h). An info a node says
// once in its life is not said again by a render of the kept scene; `variants` reads none
// from a log, and Python's render() shows a log only when the render failed.
bool onlyInfos(const std::string& logPath) {
  std::ifstream log(logPath);
  if (!log) return false;
  for (std::string line; std::getline(log, line);)
    if (line.rfind("Coin info in ", 0) != 0) return false;
  return true;
}

}  // namespace

std::string workerRequest(const RenderOptions& options, const std::string& logPath) {
  const nlohmann::json request = {{"scene", options.scene},
                                  {"output", options.output},
                                  {"size", options.size},
                                  {"frames", options.frames},
                                  {"stats", options.statsPath},
                                  {"sets", options.assignments},
                                  {"transparency", options.transparency},
                                  {"log", logPath}};
  return request.dump() + "\n";
}

std::optional<WorkerAnswer> WorkerAnswer::parse(const std::string& line) {
  const nlohmann::json answer = nlohmann::json::parse(line, nullptr, false);
  if (!answer.is_object() || !answer.contains("exit") || !answer["exit"].is_number_integer())
    return std::nullopt;
  WorkerAnswer parsed;
  parsed.exitCode = answer["exit"].get<int>();
  parsed.last = answer.value("last", false);
  return parsed;
}

int runVariantsWorker() {
  // The answers take stdout's place; what a render prints there ("wrote ...") goes nowhere,
  // as it did from a render process under `variants`.
  const int answers = fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  const int nowhere = open("/dev/null", O_WRONLY | O_CLOEXEC);
  const int between = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
  if (answers < 0 || nowhere < 0 || between < 0) {
    std::cerr << "ivshadow: error: variants-worker: cannot set up its output\n";
    return 1;
  }
  dup2(nowhere, STDOUT_FILENO);
  RenderSession session;
  for (std::string line; std::getline(std::cin, line);) {
    std::string logPath;
    const std::optional<RenderOptions> options =
        renderOptions(nlohmann::json::parse(line, nullptr, false), logPath);
    if (!options) {
      std::cerr << "ivshadow: error: variants-worker: not a request: " << line << '\n';
      return 1;
    }
    const int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) {
      std::cerr << "ivshadow: error: cannot write " << logPath << ": " << std::strerror(errno)
                << '\n';
      writeAll(answers, nlohmann::json({{"exit", 1}, {"last", true}}).dump() + "\n");
      return 1;
    }
    dup2(log, STDERR_FILENO);
    close(log);
    const int status = session.render(*options);
    std::cout.flush();
    if (!onlyInfos(logPath)) session.forgetScene();
    dup2(between, STDERR_FILENO);
    // Bad input is refused before anything is drawn; any other failure may have stopped a
    // frame midway.
    const bool last = status != 0 && status != 2;
    writeAll(answers, nlohmann::json({{"exit", status}, {"last", last}}).dump() + "\n");
    if (last) return status;
  }
  return 0;
}

}  // namespace ivshadow
