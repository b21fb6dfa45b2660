#include "cli/VariantRenders.h"

#include "cli/RenderProcesses.h"
#include "cli/RenderWorkers.h"

#include <cstdlib>
#include <string>

namespace ivshadow {

std::unique_ptr<VariantRenders> VariantRenders::create(int jobs) {
  const char* workers = std::getenv("IVSHADOW_VARIANTS_WORKERS");
  if (workers != nullptr && std::string(workers) == "0")
    return std::make_unique<RenderProcesses>(jobs);
  return std::make_unique<RenderWorkers>(jobs);
}

}  // namespace ivshadow
