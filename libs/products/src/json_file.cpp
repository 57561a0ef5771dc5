#include "pmap/products/json_file.h"

#include "pmap/common/atomic_file.h"

namespace pmap::products {

void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& doc) {
  writeTextFileAtomically(path, doc.dump(2) + "\n");
}

}  // namespace pmap::products
