#pragma once
// The files of assets/ compiled into the programs (cmake/embed_assets.cmake), so the CLI,
// the viewer and the tests find the marker-set tables, keypoint layouts and the default
// model wherever they are run from. Names are paths relative to assets/ with '/'
// ("models/real-walkers.ewm"); assets/README.md is documentation and not embedded.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

struct EmbeddedAsset {
  std::string_view name;   // relative to assets/, '/' separated
  std::string_view bytes;  // the file's bytes exactly (binary files too)
};

// Every embedded file, sorted by name.
const std::vector<EmbeddedAsset>& embeddedAssets();

// The bytes of one asset, or nullopt when no asset has that name.
std::optional<std::string_view> findEmbeddedAsset(std::string_view name);

// The bytes of one asset; throws Error(Io) naming "assets/<name>" when it is missing (a
// build without the file: a packaging mistake, not a user error).
std::string_view embeddedAsset(std::string_view name);

// The names of the embedded assets under a folder ("marker-sets/"), sorted.
std::vector<std::string> embeddedAssetNames(std::string_view folderPrefix);

}  // namespace ew
