// SPDX-License-Identifier: MIT
#include "core/io/mesh_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/io/paths.h"
#include "core/io/text_statements.h"

namespace lamina::core {

namespace {

// Reads the statements of an OFF file in order, reporting every problem with its line.
class OffReader {
 public:
  OffReader(const std::string& text, const std::string& file, Diagnostics& diagnostics)
      : statements_(SplitStatements(text, file, &diagnostics)),
        file_(file),
        diagnostics_(diagnostics) {
    last_line_ = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    if (!text.empty() && text.back() != '\n') ++last_line_;
    last_line_ = std::max(last_line_, 1);
  }

  std::optional<TriangleMesh> Read() {
    if (!ReadHeaderAndCounts()) return std::nullopt;
    mesh_.vertices.reserve(std::min<size_t>(vertex_count_, statements_.size()));
    mesh_.triangles.reserve(std::min<size_t>(face_count_, statements_.size()));
    if (ReadVertices()) ReadFaces();
    if (ok_ && next_ < statements_.size()) {
      diagnostics_.Warning({file_, statements_[next_].line},
                           "ignoring " + std::to_string(statements_.size() - next_) +
                               " extra line(s) after the last face");
    }
    if (!ok_) return std::nullopt;
    return std::move(mesh_);
  }

 private:
  void Error(int line, std::string message) {
    diagnostics_.Error({file_, line}, std::move(message));
    ok_ = false;
  }

  // "OFF" possibly with the ST/C/N prefixes of the geomview variants (COFF, NOFF, STCNOFF...).
  static bool IsOffKeyword(const std::string& token) {
    if (token.size() < 3 || token.compare(token.size() - 3, 3, "OFF") != 0) return false;
    const std::string prefix = token.substr(0, token.size() - 3);
    return prefix.find_first_not_of("STCN") == std::string::npos;
  }

  bool ReadHeaderAndCounts() {
    if (statements_.empty()) {
      Error(1, "missing 'OFF' header (the file is empty)");
      return false;
    }
    const Statement& header = statements_[next_++];
    if (!IsOffKeyword(header.tokens[0].text)) {
      Error(header.line, "expected 'OFF' header, got '" + header.tokens[0].text + "'");
      return false;
    }
    if (header.tokens.size() > 1) return ReadCounts(header, 1);
    if (next_ >= statements_.size()) {
      Error(last_line_, "unexpected end of file: expected the vertex, face and edge counts");
      return false;
    }
    return ReadCounts(statements_[next_++], 0);
  }

  bool ReadCounts(const Statement& statement, size_t first) {
    const std::vector<Token>& tokens = statement.tokens;
    if (tokens.size() < first + 2) {
      Error(statement.line, "expected vertex, face and edge counts, got " +
                                std::to_string(tokens.size() - first) + " value(s)");
      return false;
    }
    const bool vertices_ok =
        ReadCount(statement.line, tokens[first].text, "vertex", &vertex_count_);
    const bool faces_ok = ReadCount(statement.line, tokens[first + 1].text, "face", &face_count_);
    return vertices_ok && faces_ok;
  }

  bool ReadCount(int line, const std::string& text, const char* what, int* count) {
    if (!ParseInt(text, count) || *count < 0) {
      Error(line, std::string(what) + " count must be a non-negative integer, got '" + text + "'");
      return false;
    }
    return true;
  }

  bool ReadVertices() {
    for (int i = 0; i < vertex_count_; ++i) {
      if (next_ >= statements_.size()) {
        Error(last_line_, "unexpected end of file: expected " + std::to_string(vertex_count_) +
                              " vertices, read " + std::to_string(i));
        return false;
      }
      ReadVertex(statements_[next_++], i);
    }
    return true;
  }

  void ReadVertex(const Statement& statement, int index) {
    Vec3 v = Vec3::Zero();
    if (statement.tokens.size() < 3) {
      Error(statement.line, "vertex " + std::to_string(index) + " expects 3 coordinates, got " +
                                std::to_string(statement.tokens.size()));
    } else {
      for (int k = 0; k < 3; ++k) {
        const std::string& text = statement.tokens[k].text;
        if (!ParseDouble(text, &v[k])) {
          Error(statement.line, "'" + text + "' is not a number");
        } else if (!std::isfinite(v[k])) {
          Error(statement.line, "vertex coordinate must be finite, got '" + text + "'");
        }
      }
    }
    mesh_.vertices.push_back(v);
  }

  void ReadFaces() {
    for (int i = 0; i < face_count_; ++i) {
      if (next_ >= statements_.size()) {
        Error(last_line_, "unexpected end of file: expected " + std::to_string(face_count_) +
                              " faces, read " + std::to_string(i));
        return;
      }
      ReadFace(statements_[next_++]);
    }
  }

  void ReadFace(const Statement& statement) {
    const std::vector<Token>& tokens = statement.tokens;
    int n = 0;
    if (!ParseInt(tokens[0].text, &n)) {
      Error(statement.line, "'" + tokens[0].text + "' is not a face vertex count");
      return;
    }
    if (n < 3) {
      Error(statement.line, "face with " + std::to_string(n) + " vertices, expected at least 3");
      return;
    }
    if (tokens.size() < static_cast<size_t>(n) + 1) {
      Error(statement.line, "face expects " + std::to_string(n) + " vertex indices, got " +
                                std::to_string(tokens.size() - 1));
      return;
    }
    face_.clear();
    for (int k = 1; k <= n; ++k) {
      int index = 0;
      if (!ParseInt(tokens[k].text, &index)) {
        Error(statement.line, "'" + tokens[k].text + "' is not a vertex index");
      } else if (index < 0 || index >= vertex_count_) {
        Error(statement.line, "vertex index " + tokens[k].text + " is out of range (the file has " +
                                  std::to_string(vertex_count_) + " vertices)");
      }
      face_.push_back(index);
    }
    if (!ok_) return;
    for (int k = 1; k + 1 < n; ++k) mesh_.triangles.emplace_back(face_[0], face_[k], face_[k + 1]);
  }

  std::vector<Statement> statements_;
  const std::string& file_;
  Diagnostics& diagnostics_;
  size_t next_ = 0;
  int last_line_ = 1;
  int vertex_count_ = 0;
  int face_count_ = 0;
  bool ok_ = true;
  std::vector<int> face_;
  TriangleMesh mesh_;
};

// Appends the triangles of one (pre-transformed) assimp mesh.
void AppendAssimpMesh(const aiMesh& source, TriangleMesh* mesh) {
  // SortByPType left one primitive type per mesh: skip point and line meshes whole
  if ((source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) return;
  const int offset = mesh->vertex_count();
  for (unsigned i = 0; i < source.mNumVertices; ++i) {
    const aiVector3D& v = source.mVertices[i];
    mesh->vertices.emplace_back(v.x, v.y, v.z);
  }
  for (unsigned i = 0; i < source.mNumFaces; ++i) {
    const aiFace& face = source.mFaces[i];
    if (face.mNumIndices != 3) continue;
    mesh->triangles.emplace_back(offset + static_cast<int>(face.mIndices[0]),
                                 offset + static_cast<int>(face.mIndices[1]),
                                 offset + static_cast<int>(face.mIndices[2]));
  }
}

std::optional<TriangleMesh> ReadWithAssimp(const std::string& path, Diagnostics& diagnostics) {
  Assimp::Importer importer;
  // keep COLLADA files in their authored axes (the robotics convention: URDF meshes are
  // Z-up); assimp would otherwise rotate Z-up scenes to Y-up
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // only positions are kept, so drop the other vertex attributes first: otherwise per-face
  // normals (every STL) stop JoinIdenticalVertices from welding corners into a connected mesh
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                              aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                  aiComponent_COLORS | aiComponent_TEXCOORDS);
  constexpr unsigned kFlags = aiProcess_RemoveComponent | aiProcess_Triangulate |
                              aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                              aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path, kFlags);
  if (scene == nullptr) {
    diagnostics.Error({path, 0}, std::string("cannot read mesh: ") + importer.GetErrorString());
    return std::nullopt;
  }
  TriangleMesh mesh;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) AppendAssimpMesh(*scene->mMeshes[i], &mesh);
  if (mesh.triangles.empty()) {
    diagnostics.Error({path, 0}, "mesh file has no triangles");
    return std::nullopt;
  }
  return mesh;
}

}  // namespace

std::optional<TriangleMesh> ParseOff(const std::string& text, const std::string& file,
                                     Diagnostics& diagnostics) {
  return OffReader(text, file, diagnostics).Read();
}

std::optional<TriangleMesh> ReadMeshFile(const std::string& path, const SourceLocation& where,
                                         Diagnostics& diagnostics) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    const SourceLocation at =
        where.file.empty() ? SourceLocation{path, 0} : SourceLocation{where.file, where.line};
    diagnostics.Error(at, "cannot open mesh file '" + path + "'");
    return std::nullopt;
  }
  if (LowerExtension(path) != "off") return ReadWithAssimp(path, diagnostics);
  std::string text;
  if (!ReadFileText(path, &text)) {
    diagnostics.Error({path, 0}, "cannot read mesh file '" + path + "'");
    return std::nullopt;
  }
  return ParseOff(text, path, diagnostics);
}

bool IsMeshExtension(const std::string& lower_extension) {
  static constexpr std::array<const char*, 13> kExtensions = {
      "off", "obj", "stl", "dae", "ply", "3ds", "fbx", "gltf", "glb", "x", "ase", "lwo", "ms3d"};
  return std::any_of(kExtensions.begin(), kExtensions.end(),
                     [&](const char* e) { return lower_extension == e; });
}

}  // namespace lamina::core
