// SPDX-License-Identifier: MIT
// Readers of the `.rob` statements with structure: `joint`, `driver` and `mount`.
#include <string>
#include <vector>

#include "core/io/rob_statements.h"
#include "core/io/text_statements.h"

namespace lamina::core::rob {

namespace {

struct JointTypeName {
  const char* name;
  JointType type;
  bool has_base;
};

constexpr JointTypeName kJointTypes[] = {
    {"normal", JointType::kNormal, false},
    {"spin", JointType::kSpin, false},
    {"weld", JointType::kWeld, false},
    {"floating", JointType::kFloating, true},
    {"floatingplanar", JointType::kFloatingPlanar, true},
    {"ballandsocket", JointType::kBallAndSocket, true},
};

struct DriverTypeName {
  const char* name;
  DriverType type;
  int links;  // link indices that follow; 0 for affine
};

constexpr DriverTypeName kDriverTypes[] = {
    {"normal", DriverType::kNormal, 1},
    {"affine", DriverType::kAffine, 0},
    {"translation", DriverType::kTranslation, 2},
    {"rotation", DriverType::kRotation, 2},
};

std::string Values(size_t count) {
  return CountOf(static_cast<int>(count), "value");
}

class PartReader {
 public:
  PartReader(const Statement& statement, const std::string& path, Diagnostics& diagnostics)
      : statement_(statement), path_(path), diagnostics_(diagnostics) {}

  const std::vector<Token>& tokens() const { return statement_.tokens; }
  void Error(int line, const std::string& message) const {
    diagnostics_.Error({path_, line, 0}, message);
  }
  void Error(const std::string& message) const { Error(statement_.line, message); }

  // tokens [first, first + count) as integers / numbers; false after reporting a bad one
  bool Integers(size_t first, size_t count, std::vector<int>* values) const {
    bool ok = true;
    for (size_t i = first; i < first + count; ++i) {
      int value = 0;
      if (!ParseInt(tokens()[i].text, &value)) {
        Error(tokens()[i].line, "'" + tokens()[i].text + "' is not an integer");
        ok = false;
      }
      values->push_back(value);
    }
    return ok;
  }
  bool Numbers(size_t first, size_t count, std::vector<double>* values) const {
    bool ok = true;
    for (size_t i = first; i < first + count; ++i) {
      double value = 0.0;
      if (!ParseDouble(tokens()[i].text, &value)) {
        Error(tokens()[i].line,
              "'" + tokens()[i].text + "' in '" + tokens()[0].text + "' is not a number");
        ok = false;
      }
      values->push_back(value);
    }
    return ok;
  }

 private:
  const Statement& statement_;
  const std::string& path_;
  Diagnostics& diagnostics_;
};

// affine: n, n links, n scales, n offsets, then optionally qmin qmax vmin vmax tmin tmax
bool ReadAffine(const PartReader& reader, DriverDesc* driver) {
  const auto& tokens = reader.tokens();
  const size_t given = tokens.size() - 2;
  int count = 0;
  const bool count_ok = given > 0 && ParseInt(tokens[2].text, &count) && count >= 1;
  const size_t needed = count_ok ? 1 + 3 * static_cast<size_t>(count) : 0;
  if (!count_ok || (given != needed && given != needed + 6)) {
    reader.Error("'" + tokens[0].text + " " + tokens[1].text +
                 "' expects a count n >= 1, then n links, n scales, n offsets and optionally "
                 "6 limits, got " +
                 Values(given));
    return false;
  }
  const size_t n = static_cast<size_t>(count);
  std::vector<double> numbers;
  if (!reader.Integers(3, n, &driver->links) || !reader.Numbers(3 + n, given - 1 - n, &numbers)) {
    return false;
  }
  driver->affine_scale.assign(numbers.begin(), numbers.begin() + count);
  driver->affine_offset.assign(numbers.begin() + count, numbers.begin() + 2 * count);
  if (given == needed + 6) {
    const double* limits = numbers.data() + 2 * n;
    driver->q_min = limits[0];
    driver->q_max = limits[1];
    driver->velocity_min = limits[2];
    driver->velocity_max = limits[3];
    driver->torque_min = limits[4];
    driver->torque_max = limits[5];
  }
  return true;
}

}  // namespace

void ReadJointStatement(const Statement& statement, const std::string& path,
                        Diagnostics& diagnostics, RobStatements& out) {
  const PartReader reader(statement, path, diagnostics);
  const auto& tokens = statement.tokens;
  if (tokens.size() < 3) {
    reader.Error("'" + tokens[0].text + "' expects a type and a link index");
    return;
  }
  const std::string type = ToLower(tokens[1].text);
  for (const JointTypeName& entry : kJointTypes) {
    if (type != entry.name) continue;
    const size_t given = tokens.size() - 2;
    if (given > (entry.has_base ? 2u : 1u)) {
      const std::string expected =
          entry.has_base ? "a link index and an optional base link" : "1 link index";
      reader.Error("'" + tokens[0].text + " " + tokens[1].text + "' expects " + expected +
                   ", got " + Values(given));
      return;
    }
    std::vector<int> indices;
    if (!reader.Integers(2, given, &indices)) return;
    JointStatement joint;
    joint.joint.type = entry.type;
    joint.joint.link = indices[0];
    joint.joint.base = given == 2 ? indices[1] : -1;
    joint.line = statement.line;
    out.joints.push_back(joint);
    return;
  }
  reader.Error(tokens[1].line,
               "unknown joint type '" + tokens[1].text +
                   "', expected normal, spin, weld, floating, floatingplanar or ballandsocket");
}

void ReadDriverStatement(const Statement& statement, const std::string& path,
                         Diagnostics& diagnostics, RobStatements& out) {
  const PartReader reader(statement, path, diagnostics);
  const auto& tokens = statement.tokens;
  if (tokens.size() < 3) {
    reader.Error("'" + tokens[0].text + "' expects a type and link indices");
    return;
  }
  const std::string type = ToLower(tokens[1].text);
  for (const DriverTypeName& entry : kDriverTypes) {
    if (type != entry.name) continue;
    DriverStatement driver;
    driver.driver.type = entry.type;
    driver.line = statement.line;
    if (entry.type == DriverType::kAffine) {
      if (!ReadAffine(reader, &driver.driver)) return;
    } else {
      const size_t given = tokens.size() - 2;
      if (given != static_cast<size_t>(entry.links)) {
        const std::string expected =
            entry.links == 1 ? "1 link index" : std::to_string(entry.links) + " link indices";
        reader.Error("'" + tokens[0].text + " " + tokens[1].text + "' expects " + expected +
                     ", got " + Values(given));
        return;
      }
      if (!reader.Integers(2, given, &driver.driver.links)) return;
    }
    out.drivers.push_back(driver);
    return;
  }
  reader.Error(tokens[1].line, "unknown driver type '" + tokens[1].text +
                                   "', expected normal, affine, translation or rotation");
}

void ReadMountStatement(const Statement& statement, const std::string& path,
                        Diagnostics& diagnostics, RobStatements& out) {
  const PartReader reader(statement, path, diagnostics);
  const auto& tokens = statement.tokens;
  if (tokens.size() < 3) {
    reader.Error("'" + tokens[0].text + "' expects a link and a file name");
    return;
  }
  MountStatement mount;
  mount.link = tokens[1].text;
  mount.file = tokens[2].text;
  mount.line = statement.line;
  // an optional transform: the numbers right after the file name
  size_t next = 3;
  double unused = 0.0;
  while (next < tokens.size() && !tokens[next].quoted && ParseDouble(tokens[next].text, &unused)) {
    ++next;
  }
  const size_t numbers = next - 3;
  if (numbers != 0 && numbers != 12) {
    reader.Error("'" + tokens[0].text + "' transform expects 12 numbers, got " +
                 std::to_string(numbers));
    return;
  }
  if (numbers == 12) {
    std::vector<double> values;
    reader.Numbers(3, 12, &values);
    mount.transform = PoseFromKlamptNumbers(values.data());
  }
  // then an optional "as PREFIX"
  const size_t rest = tokens.size() - next;
  if (rest == 2 && ToLower(tokens[next].text) == "as") {
    mount.prefix = tokens[next + 1].text;
  } else if (rest != 0) {
    reader.Error(tokens[next].line, "unexpected '" + tokens[next].text + "' in '" + tokens[0].text +
                                        "', expected 'as PREFIX'");
    return;
  }
  out.mounts.push_back(mount);
}

}  // namespace lamina::core::rob
