#include "core/assets/embedded_assets.h"

#include "core/common/errors.h"

namespace ew {

std::optional<std::string_view> findEmbeddedAsset(std::string_view name) {
  for (const EmbeddedAsset& asset : embeddedAssets())
    if (asset.name == name) return asset.bytes;
  return std::nullopt;
}

std::string_view embeddedAsset(std::string_view name) {
  if (const auto bytes = findEmbeddedAsset(name)) return *bytes;
  throw Error(ErrorKind::Io, "assets/" + std::string(name), "",
              "this build does not contain the asset (rebuild after adding it to assets/)");
}

std::vector<std::string> embeddedAssetNames(std::string_view folderPrefix) {
  std::vector<std::string> names;
  for (const EmbeddedAsset& asset : embeddedAssets())
    if (asset.name.starts_with(folderPrefix)) names.emplace_back(asset.name);
  return names;
}

}  // namespace ew
