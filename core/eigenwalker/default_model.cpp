#include "core/eigenwalker/default_model.h"

#include <mutex>

#include "core/assets/embedded_assets.h"
#include "core/eigenwalker/model_file.h"

namespace ew {
namespace {

// Parsed on first use, not at start-up: a program that never reconstructs pays nothing.
// Not a function-local static initialiser: one that throws would be retried anyway, but a
// mutex makes "parsed once, retried after a failure" explicit.
struct DefaultModelCache {
  std::mutex mutex;
  std::optional<EigenwalkerModel> model;
};

DefaultModelCache& cache() {
  static DefaultModelCache c;
  return c;
}

}  // namespace

const EigenwalkerModel& defaultRealModel() {
  DefaultModelCache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  if (!c.model) {
    const std::string_view bytes = embeddedAsset(kDefaultRealModelAsset);
    c.model = parseModel(bytes, std::string("assets/") + kDefaultRealModelAsset);
  }
  return *c.model;
}

std::string defaultRealModelName() {
  return std::to_string(defaultRealModel().walkerCount()) + " real walkers (default)";
}

}  // namespace ew
