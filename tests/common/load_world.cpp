// SPDX-License-Identifier: MIT
#include "core/io/world_file.h"
#include "tests/common/test_support.h"

namespace lamina::test {

void LoadWorld(const std::string& path, LoadedWorld* out) {
  core::LoadContext context{out->diagnostics, out->meshes};
  out->ok = core::LoadWorldFile(path, context, &out->world);
}

}  // namespace lamina::test
