#include "cli/SlurmScript.h"

#include "image_files/AtomicFile.h"

#include <sys/stat.h>

#include <sstream>

namespace ivshadow {

std::string shellQuoted(const std::string& text) {
  bool plain = !text.empty();
  for (char c : text)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) ||
                      std::string("/._-+=:,@%").find(c) != std::string::npos);
  if (plain) return text;
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string shellCommand(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : " ") + shellQuoted(word);
  return out;
}

std::string SlurmScript::write(const std::string& scriptDir) const {
  const std::string logs = outputDir + "/logs";
  std::ostringstream array;
  array << "#!/bin/bash\n"
        << "# Written by `ivshadow variants ... --slurm`: one array task per shard of the sweep.\n"
        << "#SBATCH --job-name=ivshadow-variants\n"
        << "#SBATCH --array=0-" << shards - 1 << (limit > 0 ? "%" + std::to_string(limit) : "")
        << "\n"
        << "#SBATCH --ntasks=1\n"
        << "#SBATCH --cpus-per-task=" << cpusPerTask << "\n"
        << "#SBATCH --output=" << logs << "/variants-%A_%a.out\n"
        << "set -euo pipefail\n"
        << "# A rerun of a task skips the variants whose manifest is current, so resubmitting\n"
        << "# the array (or one task: sbatch --array=K) only renders what is missing or failed.\n"
        << "exec " << shellCommand(shardCommand) << " --shard \"${SLURM_ARRAY_TASK_ID}/" << shards
        << "\"\n";
  std::ostringstream merge;
  merge << "#!/bin/bash\n"
        << "# Written by `ivshadow variants ... --slurm`: the reports of every shard.\n"
        << "#SBATCH --job-name=ivshadow-variants-merge\n"
        << "#SBATCH --ntasks=1\n"
        << "#SBATCH --output=" << logs << "/merge-%j.out\n"
        << "exec " << shellCommand({mergeExecutable, "variants-merge", outputDir}) << "\n";
  const std::string arrayPath = scriptDir + "/variants.sbatch";
  const std::string mergePath = scriptDir + "/merge.sbatch";
  std::ostringstream submit;
  submit << "#!/bin/sh\n"
         << "# Submits the sweep's job array, then the merge, which runs after every task has\n"
         << "# ended, whether it succeeded or not (afterany).\n"
         << "set -e\n"
         << "mkdir -p " << shellQuoted(logs) << "\n"
         << "array=$(sbatch --parsable " << shellQuoted(arrayPath) << ")\n"
         << "array=${array%%;*}\n"
         << "merge=$(sbatch --parsable --dependency=afterany:$array " << shellQuoted(mergePath)
         << ")\n"
         << "echo \"submitted job array $array (" << shards << " tasks) and merge job $merge\"\n";
  const std::string submitPath = scriptDir + "/submit.sh";
  writeTextFileAtomically(arrayPath, array.str());
  writeTextFileAtomically(mergePath, merge.str());
  writeTextFileAtomically(submitPath, submit.str());
  for (const std::string& path : {arrayPath, mergePath, submitPath}) chmod(path.c_str(), 0755);
  return submitPath;
}

}  // namespace ivshadow
