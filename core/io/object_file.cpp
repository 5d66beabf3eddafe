// SPDX-License-Identifier: MIT
// Klamp't rigid-object `.obj` and terrain `.env` files: "key values" statements read with the
// shared tokenizer, applied in Klamp't's order (RigidObjectModel::Load, TerrainModel::Load),
// with mass properties from the geometry when the file asks for `autoMass`.
#include "core/io/object_file.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/mass_properties.h"
#include "core/io/geometry_file.h"
#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/text_statements.h"
#include "core/io/xml_element_reader.h"
#include "core/model/params.h"

namespace lamina::core {

namespace {

// Klamp't's default surface fraction (RigidObjectModel::SetMassFromGeometry): a thin shell.
// Used by `autoMass` without a value and for objects loaded from a bare mesh.
constexpr double kDefaultSurfaceFraction = 1.0;
// LooksLikeKlamptObject decides on the first meaningful statement, which is near the top;
// reading this much is plenty and keeps large Wavefront files cheap to sniff.
constexpr size_t kSniffBytes = 64 * 1024;

// keys in Klamp't's spelling (matched case-insensitively, reported as spelled here), then
// Lamina's kRollingFriction and kSpinningFriction (docs/file-formats.md)
const std::vector<std::string> kObjectKeys = [] {
  std::vector<std::string> keys = {"mesh",       "geomscale", "geomtranslate",   "T",
                                   "position",   "velocity",  "angularVelocity", "mass",
                                   "com",        "inertia",   "kFriction",       "kRestitution",
                                   "kStiffness", "kDamping",  "autoMass"};
  keys.insert(keys.end(), {"kRollingFriction", "kSpinningFriction"});
  return keys;
}();
// `friction` is what Klamp't's TerrainModel::Save writes (its Load ignores it); we read it.
const std::vector<std::string> kTerrainKeys = {"mesh", "kFriction", "friction"};
const std::vector<std::string> kWavefrontKeys = {
    "v",      "vn",     "vt",     "vp",  "f",    "l",     "p",    "o",    "g",  "s",
    "mtllib", "usemtl", "cstype", "deg", "curv", "curv2", "surf", "parm", "end"};

bool ContainsIgnoringCase(const std::vector<std::string>& words, const std::string& word) {
  const std::string lower = ToLower(word);
  return std::any_of(words.begin(), words.end(),
                     [&](const std::string& w) { return ToLower(w) == lower; });
}

std::string CountsText(std::initializer_list<int> counts) {
  std::string text;
  for (const int count : counts) {
    if (!text.empty()) text += " or ";
    text += std::to_string(count);
  }
  const bool singular = counts.size() == 1 && *counts.begin() == 1;
  return text + (singular ? " value" : " values");
}

// The statements of a key-value file by key. Keys are matched case-insensitively against a
// known list; unknown keys warn (with a suggestion) and a repeated key replaces the earlier one
// as in Klamp't's SimpleFile, with a warning.
class KeyValueFile {
 public:
  KeyValueFile(const std::string& text, const std::string& file,
               const std::vector<std::string>& keys, Diagnostics& diagnostics)
      : file_(file), diagnostics_(diagnostics) {
    for (Statement& statement : SplitStatements(text, file, &diagnostics)) {
      Add(std::move(statement), keys);
    }
  }

  const Statement* Find(const std::string& key) const {
    const auto it = statements_.find(key);
    return it == statements_.end() ? nullptr : &it->second;
  }
  SourceLocation At(const Statement& statement) const { return {file_, statement.line, 0}; }
  const std::string& file() const { return file_; }
  Diagnostics& diagnostics() const { return diagnostics_; }

  void Error(const Statement& statement, const std::string& message) const {
    diagnostics_.Error(At(statement), message);
  }

  // The values after `key`, one of `counts` of them, each a number (finite unless
  // `allow_infinite`). nullopt when the key is absent or invalid (then reported).
  std::optional<std::vector<double>> Numbers(const std::string& key,
                                             std::initializer_list<int> counts,
                                             bool allow_infinite) const;

  // The values after `key` (one of `counts` of them) as a value of row `spec` with `size`
  // components, checked against the table: "'key' <rule>, got '<values>'" when it refuses.
  // `expand` turns the numbers as written into the row's layout (an inertia's 3 diagonal values).
  std::optional<ParamValue> Param(const std::string& key, const ParamSpec& spec,
                                  std::initializer_list<int> counts, int size,
                                  ParamValue (*expand)(const ParamValue&) = nullptr) const;
  // Checks a value of row `spec` assembled from several keys; reported at the first of them.
  bool CheckAssembled(const ParamSpec& spec, const ParamValue& value,
                      std::initializer_list<const char*> keys) const;

  // Reports "'key' must be <requirement>, got '<value>'" for the first value failing `ok`.
  template <typename Predicate>
  bool Check(const std::string& key, const std::vector<double>& values, Predicate ok,
             const std::string& requirement) const {
    const Statement& statement = *Find(key);
    for (size_t i = 0; i < values.size(); ++i) {
      if (ok(values[i])) continue;
      Error(statement, "'" + key + "' must be " + requirement + ", got '" +
                           statement.tokens[i + 1].text + "'");
      return false;
    }
    return true;
  }

 private:
  void Add(Statement statement, const std::vector<std::string>& keys);

  std::string file_;
  Diagnostics& diagnostics_;
  std::map<std::string, Statement> statements_;
};

void KeyValueFile::Add(Statement statement, const std::vector<std::string>& keys) {
  const std::string& word = statement.tokens.front().text;
  const auto known = std::find_if(keys.begin(), keys.end(), [&](const std::string& key) {
    return ToLower(key) == ToLower(word);
  });
  if (known == keys.end()) {
    std::string message = "unknown key '" + word + "' ignored";
    const std::string suggestion = SuggestName(word, keys);
    if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
    diagnostics_.Warning(At(statement), message);
    return;
  }
  if (const Statement* earlier = Find(*known)) {
    diagnostics_.Warning(At(statement), "'" + *known + "' given again (first at line " +
                                            std::to_string(earlier->line) +
                                            "); the last one is used");
  }
  statements_[*known] = std::move(statement);
}

std::optional<std::vector<double>> KeyValueFile::Numbers(const std::string& key,
                                                         std::initializer_list<int> counts,
                                                         bool allow_infinite) const {
  const Statement* statement = Find(key);
  if (!statement) return std::nullopt;
  std::vector<double> values;
  for (size_t i = 1; i < statement->tokens.size(); ++i) {
    const std::string& text = statement->tokens[i].text;
    double value = 0.0;
    if (!ParseDouble(text, &value)) {
      Error(*statement, "'" + text + "' in '" + key + "' is not a number");
      return std::nullopt;
    }
    if (!allow_infinite && std::isinf(value)) {
      Error(*statement, "'" + key + "' must be finite, got '" + text + "'");
      return std::nullopt;
    }
    values.push_back(value);
  }
  const int count = static_cast<int>(values.size());
  if (std::find(counts.begin(), counts.end(), count) == counts.end()) {
    Error(*statement,
          "'" + key + "' expects " + CountsText(counts) + ", got " + std::to_string(count));
    return std::nullopt;
  }
  return values;
}

std::optional<ParamValue> KeyValueFile::Param(const std::string& key, const ParamSpec& spec,
                                              std::initializer_list<int> counts, int size,
                                              ParamValue (*expand)(const ParamValue&)) const {
  const auto numbers = Numbers(key, counts, true);
  if (!numbers) return std::nullopt;
  const ParamValue value = expand ? expand(*numbers) : *numbers;
  if (ParamAccepts(spec, value, size)) return value;
  const Statement& statement = *Find(key);
  if (const auto lenient = LenientInertia(spec, value)) {
    diagnostics_.Warning(At(statement), "'" + key + "' " + lenient->warning);
    return lenient->value;
  }
  std::string text;
  for (size_t i = 1; i < statement.tokens.size(); ++i) {
    text += (i > 1 ? " " : "") + statement.tokens[i].text;
  }
  Error(statement, "'" + key + "' " + ParamRefusal(spec, text));
  return std::nullopt;
}

bool KeyValueFile::CheckAssembled(const ParamSpec& spec, const ParamValue& value,
                                  std::initializer_list<const char*> keys) const {
  if (ParamAccepts(spec, value, static_cast<int>(value.size()))) return true;
  std::string names;
  const Statement* first = nullptr;
  for (const char* key : keys) {
    if (!Find(key)) continue;
    names += (first ? "', '" : "") + std::string(key);
    if (!first) first = Find(key);
  }
  if (first) {
    Error(*first, "'" + names + "' (" + std::string(spec.key) + ") " +
                      ParamRefusal(spec, ParamWords(spec, value)));
  }
  return false;
}

// an `.obj` inertia of 3 values is the diagonal
ParamValue InertiaLayout(const ParamValue& values) {
  if (values.size() != 3) return values;
  return {values[0], 0, 0, 0, values[1], 0, 0, 0, values[2]};
}

bool IsPositive(double value) {
  return value > 0.0;
}
bool IsFraction(double value) {
  return value >= 0.0 && value <= 1.0;
}

// `mesh "file"`: the geometry, relative to the file's directory. False when missing or bad.
bool LoadMeshKey(const KeyValueFile& file, LoadContext& context, GeometryDesc* geometry) {
  const Statement* mesh = file.Find("mesh");
  if (!mesh) {
    context.diagnostics.Error({file.file(), 0, 0}, "missing 'mesh' (the geometry file)");
    return false;
  }
  if (mesh->tokens.size() != 2) {
    file.Error(*mesh, "'mesh' expects 1 file name, got " + std::to_string(mesh->tokens.size() - 1));
    return false;
  }
  const std::string geometry_path = ResolvePath(DirectoryOf(file.file()), mesh->tokens[1].text);
  return LoadGeometryFile(geometry_path, file.At(*mesh), context, geometry);
}

// `geomscale` then `geomtranslate`: the geometry is scaled first, then translated.
void ApplyGeometryPlacement(const KeyValueFile& file, GeometryDesc* geometry) {
  if (const auto scale = file.Numbers("geomscale", {1, 3}, false)) {
    if (file.Check("geomscale", *scale, IsPositive, "> 0")) {
      geometry->scale = scale->size() == 1 ? Vec3::Constant((*scale)[0])
                                           : Vec3((*scale)[0], (*scale)[1], (*scale)[2]);
    }
  }
  if (const auto offset = file.Numbers("geomtranslate", {3}, false)) {
    geometry->transform.translation() = Vec3((*offset)[0], (*offset)[1], (*offset)[2]);
  }
}

// `T`: 12 numbers (rotation row-major, then translation) or a row-major 4x4 matrix.
void ApplyTransformKey(const KeyValueFile& file, Pose* pose) {
  const auto values = file.Numbers("T", {12, 16}, false);
  if (!values) return;
  const Statement& statement = *file.Find("T");
  const std::vector<double>& v = *values;
  Pose parsed = Pose::Identity();
  if (v.size() == 12) {
    parsed = PoseFromKlamptNumbers(v.data());
  } else {
    if (v[12] != 0.0 || v[13] != 0.0 || v[14] != 0.0 || v[15] != 1.0) {
      file.Error(statement, "'T' 4x4 matrix must end with the row '0 0 0 1', got '" +
                                FormatDoubles(v.data() + 12, 4) + "'");
      return;
    }
    Mat3 rotation;
    rotation << v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10];
    parsed.linear() = rotation;
    parsed.translation() = Vec3(v[3], v[7], v[11]);
  }
  *pose = parsed;
}

// `T`, then `position` (replaces the translation), `velocity` and `angularVelocity`.
// Klamp't keeps the velocities in the model but never copies them into the simulation; Lamina
// uses them as the object's initial velocity (a deliberate fix, see klampt-internals §9.16).
// Both are checked as the table's `transform` and `velocity` rows once assembled.
void ApplyPoseAndVelocity(const KeyValueFile& file, RigidObjectDesc* out) {
  Pose pose = out->pose;
  ApplyTransformKey(file, &pose);
  if (const auto position = file.Numbers("position", {3}, false)) {
    pose.translation() = Vec3((*position)[0], (*position)[1], (*position)[2]);
  }
  if (file.CheckAssembled(*FindParam("transform", ElementKind::kObject), PoseToValue(pose),
                          {"T", "position"})) {
    out->pose = pose;
  }
  Twist twist = out->initial_velocity;
  if (const auto linear = file.Numbers("velocity", {3}, false)) {
    twist.linear = Vec3((*linear)[0], (*linear)[1], (*linear)[2]);
  }
  if (const auto angular = file.Numbers("angularVelocity", {3}, false)) {
    twist.angular = Vec3((*angular)[0], (*angular)[1], (*angular)[2]);
  }
  if (file.CheckAssembled(*FindParam("velocity", ElementKind::kObject), TwistToValue(twist),
                          {"velocity", "angularVelocity"})) {
    out->initial_velocity = twist;
  }
}

// `mass`, `com` and `inertia` (3 diagonal values or 9 row-major), checked as the table's rows.
// True when `com` was given.
bool ApplyMassKeys(const KeyValueFile& file, RigidObjectDesc* out) {
  const auto row = [](const char* key) { return *FindParam(key, ElementKind::kObject); };
  if (const auto mass = file.Param("mass", row("mass"), {1}, 1)) out->mass = (*mass)[0];
  const auto com = file.Param("com", row("com"), {3}, 3);
  if (com) out->com = Vec3((*com)[0], (*com)[1], (*com)[2]);
  if (const auto inertia = file.Param("inertia", row("inertia"), {3, 9}, 9, InertiaLayout)) {
    out->inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(inertia->data());
  }
  return com.has_value();
}

// `kFriction`, `kRestitution`, `kStiffness`, `kDamping` (and Lamina's `kRollingFriction`,
// `kSpinningFriction`): the table's surface rows, set through them on the object lent to a world
// of its own (the rows address elements of a world).
void ApplySurfaceKeys(const KeyValueFile& file, RigidObjectDesc* out) {
  WorldDesc lent;
  lent.objects.push_back(std::move(*out));
  for (const ParamSpec* spec : SurfaceRows()) {
    const std::string key(spec->key);
    if (const auto value = file.Param(key, *spec, {1}, 1)) {
      spec->set(&lent, ElementIndex::Object(0), *value);
    }
  }
  *out = std::move(lent.objects.front());
}

// Inertia about `point` from the inertia about the centre of mass (parallel-axis theorem).
Mat3 InertiaAbout(const MassProperties& properties, double mass, const Vec3& point) {
  const Vec3 d = point - properties.com;
  return properties.inertia + mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

// `autoMass [surfaceFraction]`: COM and inertia from the geometry; with an explicit `com` only
// the inertia (about that point), as Klamp't does.
void ApplyAutoMass(const KeyValueFile& file, bool has_com, bool has_geometry,
                   RigidObjectDesc* out) {
  const Statement* statement = file.Find("autoMass");
  if (!statement) return;
  const auto fraction = file.Numbers("autoMass", {0, 1}, false);
  if (!fraction || !file.Check("autoMass", *fraction, IsFraction, "in [0, 1]")) return;
  if (!has_geometry) return;  // the geometry error has been reported
  if (const Statement* inertia = file.Find("inertia")) {
    file.diagnostics().Warning(file.At(*inertia), "'inertia' is replaced by 'autoMass'");
  }
  const double surface_fraction = fraction->empty() ? kDefaultSurfaceFraction : (*fraction)[0];
  const MassProperties properties =
      ComputeMassProperties(out->geometry, out->mass, surface_fraction);
  if (!properties.valid) {
    file.Error(*statement,
               "'autoMass' cannot compute mass properties: the geometry has no "
               "volume or area");
    return;
  }
  out->inertia = has_com ? InertiaAbout(properties, out->mass, out->com) : properties.inertia;
  if (!has_com) out->com = properties.com;
}

void ParseKlamptObject(const std::string& text, const std::string& path, LoadContext& context,
                       RigidObjectDesc* out) {
  const KeyValueFile file(text, path, kObjectKeys, context.diagnostics);
  // Klamp't's default inertia for .obj files is the identity
  out->inertia = Mat3::Identity();
  const bool has_geometry = LoadMeshKey(file, context, &out->geometry);
  ApplyGeometryPlacement(file, &out->geometry);
  ApplyPoseAndVelocity(file, out);
  const bool has_com = ApplyMassKeys(file, out);
  ApplySurfaceKeys(file, out);
  ApplyAutoMass(file, has_com, has_geometry, out);
}

// Any geometry file as an object: mass 1, COM and inertia of a thin shell (Klamp't).
void LoadBareObject(const std::string& path, const SourceLocation& where, LoadContext& context,
                    RigidObjectDesc* out) {
  if (!LoadGeometryFile(path, where, context, &out->geometry)) return;
  out->mass = 1.0;
  const MassProperties properties =
      ComputeMassProperties(out->geometry, out->mass, kDefaultSurfaceFraction);
  if (!properties.valid) {
    context.diagnostics.Error({path, 0, 0},
                              "cannot compute mass properties: the geometry has no volume or area");
    return;
  }
  out->com = properties.com;
  out->inertia = properties.inertia;
}

// `kFriction` (or Klamp't's saved spelling `friction`): one value, or one per triangle as
// Klamp't allows; a terrain keeps a single friction.
void ApplyTerrainFriction(const KeyValueFile& file, TerrainDesc* out) {
  const Statement* alias = file.Find("friction");
  if (alias && file.Find("kFriction")) {
    file.diagnostics().Warning(file.At(*alias), "'friction' ignored: 'kFriction' is given");
  } else if (alias) {
    file.diagnostics().Note(file.At(*alias),
                            "'friction' read as 'kFriction' (Klamp't writes it but ignores it)");
  }
  const std::string key = file.Find("kFriction") ? "kFriction" : "friction";
  const Statement* statement = file.Find(key);
  if (!statement) return;
  const int given = static_cast<int>(statement->tokens.size()) - 1;
  const bool per_triangle = given > 1 && given == out->geometry.triangle_count();
  const auto values = file.Numbers(key, {per_triangle ? given : 1}, true);
  if (!values) return;
  const ParamSpec& spec = *FindParam("kFriction", ElementKind::kTerrain);
  for (size_t i = 0; i < values->size(); ++i) {
    if (ParamAccepts(spec, {(*values)[i]}, 1)) continue;
    file.Error(*statement, "'" + key + "' " + ParamRefusal(spec, statement->tokens[i + 1].text));
    return;
  }
  const bool uniform =
      std::all_of(values->begin(), values->end(), [&](double f) { return f == values->front(); });
  if (!uniform) {
    file.diagnostics().Warning(file.At(*statement), "per-triangle '" + key +
                                                        "' is not supported; using the first "
                                                        "value '" +
                                                        statement->tokens[1].text + "'");
  }
  out->sim.surface.friction = values->front();
}

}  // namespace

bool LooksLikeKlamptObject(const std::string& text) {
  size_t length = text.size();
  if (length > kSniffBytes) {
    const size_t last_newline = text.rfind('\n', kSniffBytes);
    length = last_newline == std::string::npos ? kSniffBytes : last_newline + 1;
  }
  for (const Statement& statement : SplitStatements(text.substr(0, length))) {
    const std::string& word = statement.tokens.front().text;
    if (ContainsIgnoringCase(kObjectKeys, word)) return true;
    if (ContainsIgnoringCase(kWavefrontKeys, word)) return false;
  }
  // nothing recognisable: read it as an object file, whose diagnostics name the keys
  return true;
}

bool LoadRigidObjectFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                         RigidObjectDesc* out) {
  const int errors_before = context.diagnostics.error_count();
  *out = RigidObjectDesc();
  out->name = StemOf(path);
  out->sim = DefaultObjectSimParams();
  // a .obj is a Klamp't object file or a Wavefront mesh; tell them apart by content
  std::string text;
  if (LowerExtension(path) == "obj") {
    if (!ReadFileText(path, &text)) {
      context.diagnostics.Error(where, "cannot open object file '" + path + "'");
      return false;
    }
    if (LooksLikeKlamptObject(text)) {
      ParseKlamptObject(text, path, context, out);
      return context.diagnostics.error_count() == errors_before;
    }
  }
  LoadBareObject(path, where, context, out);
  return context.diagnostics.error_count() == errors_before;
}

bool LoadTerrainFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                     TerrainDesc* out) {
  const int errors_before = context.diagnostics.error_count();
  *out = TerrainDesc();
  out->name = StemOf(path);
  out->sim = DefaultTerrainSimParams();
  const std::string extension = LowerExtension(path);
  std::string text;
  if ((extension == "env" || extension == "obj") && !ReadFileText(path, &text)) {
    context.diagnostics.Error(where, "cannot open terrain file '" + path + "'");
    return false;
  }
  if (extension == "env") {
    const KeyValueFile file(text, path, kTerrainKeys, context.diagnostics);
    LoadMeshKey(file, context, &out->geometry);
    ApplyTerrainFriction(file, out);
  } else if (extension == "obj" && LooksLikeKlamptObject(text)) {
    context.diagnostics.Error(
        where, "'" + path + "' is a Klamp't rigid-object file, not a " + "terrain mesh");
  } else {
    LoadGeometryFile(path, where, context, &out->geometry);
  }
  return context.diagnostics.error_count() == errors_before;
}

}  // namespace lamina::core
