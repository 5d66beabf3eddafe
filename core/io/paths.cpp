// SPDX-License-Identifier: MIT
#include "core/io/paths.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "core/io/text_statements.h"

namespace lamina::core {

namespace fs = std::filesystem;

std::string ResolvePath(const std::string& base_dir, const std::string& reference) {
  fs::path path(reference);
  if (path.is_relative()) path = fs::path(base_dir.empty() ? "." : base_dir) / path;
  std::error_code error;
  fs::path absolute = fs::absolute(path, error);
  if (error) absolute = path;
  return absolute.lexically_normal().string();
}

std::string DirectoryOf(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string RelativePath(const std::string& path, const std::string& from_dir) {
  const fs::path relative = fs::path(path).lexically_relative(fs::path(from_dir));
  return relative.empty() ? path : relative.string();
}

std::string LowerExtension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  if (!extension.empty() && extension[0] == '.') extension.erase(0, 1);
  return ToLower(extension);
}

std::string StemOf(const std::string& path) {
  return fs::path(path).stem().string();
}

bool ReadFileText(const std::string& path, std::string* text) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return static_cast<bool>(in) || in.eof();
}

bool WriteFileAtomically(const std::string& path, const std::string& text, std::string* error) {
  const fs::path target(path);
  // appended piece by piece: GCC 12 at -O3 flags `"." + std::string` with a false -Wrestrict
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(getpid());
  const fs::path temporary = target.parent_path() / name;
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      *error = "cannot create '" + temporary.string() + "'";
      return false;
    }
    out << text;
    out.flush();
    if (!out) {
      *error = "cannot write '" + temporary.string() + "'";
      out.close();
      std::remove(temporary.c_str());
      return false;
    }
  }
  std::error_code rename_error;
  fs::rename(temporary, target, rename_error);
  if (rename_error) {
    *error = "cannot replace '" + path + "': " + rename_error.message();
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace lamina::core
