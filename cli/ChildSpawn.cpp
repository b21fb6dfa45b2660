#include "cli/ChildSpawn.h"

#include <fcntl.h>
#include <spawn.h>

#include <cstring>
#include <stdexcept>

extern char** environ;

namespace ivshadow {

pid_t spawnChild(const std::vector<std::string>& arguments,
                 const std::vector<ChildStream>& streams) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (const ChildStream& stream : streams) {
    if (stream.from >= 0)
      posix_spawn_file_actions_adddup2(&actions, stream.from, stream.fd);
    else if (stream.truncate)
      posix_spawn_file_actions_addopen(&actions, stream.fd, stream.path.c_str(),
                                       O_WRONLY | O_CREAT | O_TRUNC, 0644);
    else
      posix_spawn_file_actions_addopen(&actions, stream.fd, stream.path.c_str(), O_WRONLY, 0);
  }
  pid_t pid = 0;
  const int status = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status != 0)
    throw std::runtime_error("cannot start " + arguments[0] + ": " + std::strerror(status));
  return pid;
}

}  // namespace ivshadow
