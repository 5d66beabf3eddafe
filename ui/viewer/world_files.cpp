// SPDX-License-Identifier: MIT
#include "ui/viewer/world_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace lamina::ui {

namespace {

constexpr std::size_t kHeadBytes = 64 * 1024;

// position after the declaration, processing instructions, comments and blanks
std::size_t FirstElement(const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[at]))) {
      ++at;
    } else if (text.compare(at, 2, "<?") == 0) {
      const std::size_t end = text.find("?>", at);
      if (end == std::string::npos) return std::string::npos;
      at = end + 2;
    } else if (text.compare(at, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", at);
      if (end == std::string::npos) return std::string::npos;
      at = end + 3;
    } else if (text.compare(at, 2, "<!") == 0) {  // <!DOCTYPE ...>
      const std::size_t end = text.find('>', at);
      if (end == std::string::npos) return std::string::npos;
      at = end + 1;
    } else {
      return at;
    }
  }
  return std::string::npos;
}

}  // namespace

bool IsWorldFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string head(kHeadBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.compare(0, 3, "\xEF\xBB\xBF") == 0) head.erase(0, 3);  // UTF-8 byte order mark
  const std::size_t at = FirstElement(head);
  if (at == std::string::npos || head.compare(at, 6, "<world") != 0) return false;
  const std::size_t after = at + 6;
  return after < head.size() && (std::isspace(static_cast<unsigned char>(head[after])) ||
                                 head[after] == '>' || head[after] == '/');
}

std::vector<std::string> WorldFilesUnder(const std::string& directory) {
  std::vector<std::string> files;
  std::error_code error;
  if (directory.empty() || !std::filesystem::is_directory(directory, error)) return files;
  for (auto it = std::filesystem::recursive_directory_iterator(directory, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    if (it->is_regular_file(error) && it->path().extension() == ".xml" &&
        IsWorldFile(it->path().string())) {
      files.push_back(it->path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace lamina::ui
