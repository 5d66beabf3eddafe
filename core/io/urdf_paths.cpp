// SPDX-License-Identifier: MIT
// URDF mesh file names: relative, file:// and package:// references.
#include <filesystem>
#include <string>

#include <tinyxml2.h>

#include "core/io/paths.h"
#include "core/io/urdf_xml.h"

namespace lamina::core::urdf_io {

namespace {

namespace fs = std::filesystem;

constexpr char kPackageScheme[] = "package://";
constexpr char kFileScheme[] = "file://";

bool StartsWith(const std::string& text, const char* prefix) {
  return text.rfind(prefix, 0) == 0;
}

// true when `directory` has a package.xml whose <name> is `name`
bool PackageXmlNames(const fs::path& directory, const std::string& name) {
  std::error_code error;
  const fs::path manifest = directory / "package.xml";
  if (!fs::is_regular_file(manifest, error)) return false;
  tinyxml2::XMLDocument document;
  if (document.LoadFile(manifest.c_str()) != tinyxml2::XML_SUCCESS) return false;
  const tinyxml2::XMLElement* package = document.RootElement();
  const tinyxml2::XMLElement* element = package ? package->FirstChildElement("name") : nullptr;
  const char* text = element ? element->GetText() : nullptr;
  return text != nullptr && std::string(text) == name;
}

// the package directory NAME found from `start` upward: the directory itself, a child
// directory called NAME, or a child (or itself) whose package.xml names NAME; "" if none
std::string FindPackage(const std::string& name, const std::string& start) {
  for (fs::path directory = fs::path(start);; directory = directory.parent_path()) {
    std::error_code error;
    if (directory.filename() == name || PackageXmlNames(directory, name)) return directory;
    if (fs::is_directory(directory / name, error)) return directory / name;
    // incremented with an error code: an unreadable directory ends its scan, never throws
    std::error_code scan_error;
    for (fs::directory_iterator it(directory, scan_error), end; !scan_error && it != end;
         it.increment(scan_error)) {
      if (it->is_directory(error) && PackageXmlNames(it->path(), name)) return it->path();
    }
    if (directory == directory.parent_path()) return "";
  }
}

// `directory` absolute and normalized, without a trailing separator
std::string CleanDirectory(const std::string& directory) {
  fs::path path(ResolvePath(directory, "."));
  if (path.filename().empty()) path = path.parent_path();
  return path.string();
}

}  // namespace

std::string ResolveMeshFile(const std::string& filename, const std::string& urdf_dir,
                            const std::string& package_root, std::string* error) {
  if (StartsWith(filename, kFileScheme)) {
    return ResolvePath(urdf_dir, filename.substr(sizeof(kFileScheme) - 1));
  }
  if (!StartsWith(filename, kPackageScheme)) return ResolvePath(urdf_dir, filename);
  const std::string reference = filename.substr(sizeof(kPackageScheme) - 1);
  const size_t slash = reference.find('/');
  const std::string name = reference.substr(0, slash);
  const std::string rest = slash == std::string::npos ? "" : reference.substr(slash + 1);
  // Klamp't's <klampt package_root>: the directory that holds the packages
  if (!package_root.empty()) return ResolvePath(package_root, reference);
  const std::string start = CleanDirectory(urdf_dir);
  const std::string package = FindPackage(name, start);
  if (package.empty()) {
    *error = "cannot find package '" + name + "' for '" + filename + "' (searched upward from '" +
             start + "')";
    return "";
  }
  return ResolvePath(package, rest);
}

}  // namespace lamina::core::urdf_io
