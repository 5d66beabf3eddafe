// SPDX-License-Identifier: MIT
#include "app/worlds_dir.h"

#include <filesystem>
#include <system_error>

namespace lamina::app {

std::string WorldsDir() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        exe.parent_path().parent_path() / "share" / "lamina" / "worlds";
    if (std::filesystem::is_directory(installed, error)) return installed.string();
  }
  return LAMINA_WORLDS_DIR;
}

}  // namespace lamina::app
