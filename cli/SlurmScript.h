#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// `ivshadow variants ... --slurm DIR`: the batch scripts of a sweep on a Slurm cluster.
// DIR/variants.sbatch is a job array with one task per shard (task K runs `--shard K/N`);
// DIR/merge.sbatch runs variants-merge; DIR/submit.sh submits the array and the merge with
// --dependency=afterany on it, so the reports are written even when some task failed.
struct SlurmScript {
  std::vector<std::string> shardCommand;  // the variants command without --shard
  std::string mergeExecutable;
  std::string outputDir;  // absolute, as the tasks see it on a shared file system
  int shards = 1;
  int limit = 0;  // array tasks running at once; 0: as many as Slurm allows
  int cpusPerTask = 1;

  // Writes the three files (atomically) and returns the path of submit.sh.
  std::string write(const std::string& scriptDir) const;
};

// `text` quoted for a POSIX shell: as it is when it has only safe characters, otherwise in
// single quotes.
std::string shellQuoted(const std::string& text);
std::string shellCommand(const std::vector<std::string>& words);

}  // namespace ivshadow
