// SPDX-License-Identifier: MIT
// Reading the statements of a `.rob` file: the keyword tables, numbers with their lines, and
// the split of numeric statements that a trailing backslash ran into the next keyword.
#include "core/io/rob_statements.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/io/text_statements.h"
#include "core/io/xml_element_reader.h"

namespace lamina::core::rob {

namespace {

// a keyword whose values are numbers collected into a list
struct NumberKeyword {
  const char* name;  // lower case
  NumberList RobStatements::*list;
  int group;  // numbers per entry (checked per statement)
  bool degrees;
  bool integers;
};

constexpr NumberKeyword kNumberKeywords[] = {
    {"parents", &RobStatements::parents, 1, false, true},
    {"q", &RobStatements::q, 1, false, false},
    {"qdeg", &RobStatements::q, 1, true, false},
    {"qmin", &RobStatements::q_min, 1, false, false},
    {"qmindeg", &RobStatements::q_min, 1, true, false},
    {"qmax", &RobStatements::q_max, 1, false, false},
    {"qmaxdeg", &RobStatements::q_max, 1, true, false},
    {"velmin", &RobStatements::velocity_min, 1, false, false},
    {"velmindeg", &RobStatements::velocity_min, 1, true, false},
    {"velmax", &RobStatements::velocity_max, 1, false, false},
    {"velmaxdeg", &RobStatements::velocity_max, 1, true, false},
    {"accmax", &RobStatements::acceleration_max, 1, false, false},
    {"accmaxdeg", &RobStatements::acceleration_max, 1, true, false},
    {"torquemax", &RobStatements::torque_max, 1, false, false},
    {"powermax", &RobStatements::power_max, 1, false, false},
    {"mass", &RobStatements::mass, 1, false, false},
    {"com", &RobStatements::com, 3, false, false},
    {"inertia", &RobStatements::inertia, 9, false, false},
    {"inertiadiag", &RobStatements::inertia_diag, 3, false, false},
    {"alpha", &RobStatements::alpha, 1, false, false},
    {"alphadeg", &RobStatements::alpha, 1, true, false},
    {"a", &RobStatements::a, 1, false, false},
    {"d", &RobStatements::d, 1, false, false},
    {"theta", &RobStatements::theta, 1, false, false},
    {"thetadeg", &RobStatements::theta, 1, true, false},
    {"tparent", &RobStatements::tparent, 12, false, false},
    {"axis", &RobStatements::axis, 3, false, false},
    {"geomscale", &RobStatements::geom_scale, 1, false, false},
    {"geommargin", &RobStatements::geom_margin, 1, false, false},
    {"servop", &RobStatements::servo_p, 1, false, false},
    {"servoi", &RobStatements::servo_i, 1, false, false},
    {"servod", &RobStatements::servo_d, 1, false, false},
    {"dryfriction", &RobStatements::dry_friction, 1, false, false},
    {"viscousfriction", &RobStatements::viscous_friction, 1, false, false},
};

class StatementReader {
 public:
  StatementReader(const std::string& text, const std::string& path, Diagnostics& diagnostics,
                  RobStatements& out)
      : text_(text), path_(path), diagnostics_(diagnostics), out_(out) {}

  void Read(const Statement& statement);

  // the readers of kSpecialKeywords
  void ReadLinkNames(const Statement& s) { ReadWords(s, &out_.link_names); }
  void ReadDriverNames(const Statement& s) { ReadWords(s, &out_.driver_names); }
  void ReadGeometry(const Statement& s) { ReadWords(s, &out_.geometry_files); }
  void ReadJointTypes(const Statement& statement);
  void ReadTranslation(const Statement& statement);
  void ReadRotation(const Statement& statement);
  void ReadScale(const Statement& statement);
  void ReadAutomass(const Statement& statement);
  void ReadAutotorque(const Statement& statement);
  void ReadGeomTransform(const Statement& statement);
  void ReadJoint(const Statement& s) { ReadJointStatement(s, path_, diagnostics_, out_); }
  void ReadDriver(const Statement& s) { ReadDriverStatement(s, path_, diagnostics_, out_); }
  void ReadMount(const Statement& s) { ReadMountStatement(s, path_, diagnostics_, out_); }
  void ReadProperty(const Statement& statement);
  void ReadSelfCollision(const Statement& s) { ReadPairs(s, &out_.self_collision); }
  void ReadNoSelfCollision(const Statement& s) { ReadPairs(s, &out_.no_self_collision); }
  void ReadUnsupported(const Statement& statement);

 private:
  void Error(int line, std::string message) {
    diagnostics_.Error({path_, line, 0}, std::move(message));
  }
  // `keyword` names the statement in the message ("'nan' in 'servoP' is not a number")
  bool Number(const Token& token, const std::string& keyword, double* value);
  bool Integer(const Token& token, int* value);
  // the values of tokens [first, end) as numbers; false (after reporting) on a bad one
  bool Numbers(const Statement& statement, size_t first, std::vector<double>* values);
  std::string RawText(const Statement& statement, size_t first) const;
  void ReadNumbers(const Statement& statement, const NumberKeyword& keyword);
  void ReadWords(const Statement& statement, WordList* list);
  void ReadPairs(const Statement& statement, std::vector<PairStatement>* pairs);

  const std::string& text_;
  const std::string& path_;
  Diagnostics& diagnostics_;
  RobStatements& out_;
};

// keywords with their own reader; `numeric` ones take only numbers (or r/p letters)
struct SpecialKeyword {
  const char* name;
  bool numeric;
  void (StatementReader::*read)(const Statement&);
};

constexpr SpecialKeyword kSpecialKeywords[] = {
    {"links", false, &StatementReader::ReadLinkNames},
    {"drivers", false, &StatementReader::ReadDriverNames},
    {"geometry", false, &StatementReader::ReadGeometry},
    {"jointtype", true, &StatementReader::ReadJointTypes},
    {"translation", true, &StatementReader::ReadTranslation},
    {"rotation", true, &StatementReader::ReadRotation},
    {"scale", true, &StatementReader::ReadScale},
    {"automass", true, &StatementReader::ReadAutomass},
    {"autotorque", true, &StatementReader::ReadAutotorque},
    {"geomtransform", true, &StatementReader::ReadGeomTransform},
    {"joint", false, &StatementReader::ReadJoint},
    {"driver", false, &StatementReader::ReadDriver},
    {"mount", false, &StatementReader::ReadMount},
    {"property", false, &StatementReader::ReadProperty},
    {"selfcollision", false, &StatementReader::ReadSelfCollision},
    {"noselfcollision", false, &StatementReader::ReadNoSelfCollision},
    {"collision", false, &StatementReader::ReadUnsupported},
    {"nocollision", false, &StatementReader::ReadUnsupported},
};

const NumberKeyword* FindNumberKeyword(const std::string& lower) {
  for (const NumberKeyword& keyword : kNumberKeywords) {
    if (lower == keyword.name) return &keyword;
  }
  return nullptr;
}

const SpecialKeyword* FindSpecialKeyword(const std::string& lower) {
  for (const SpecialKeyword& keyword : kSpecialKeywords) {
    if (lower == keyword.name) return &keyword;
  }
  return nullptr;
}

bool IsKeyword(const std::string& lower) {
  return FindNumberKeyword(lower) != nullptr || FindSpecialKeyword(lower) != nullptr;
}

bool ExpectsNumbers(const std::string& lower) {
  const SpecialKeyword* special = FindSpecialKeyword(lower);
  return FindNumberKeyword(lower) != nullptr || (special != nullptr && special->numeric);
}

std::vector<std::string> AllKeywordNames() {
  std::vector<std::string> names;
  for (const NumberKeyword& keyword : kNumberKeywords) names.emplace_back(keyword.name);
  for (const SpecialKeyword& keyword : kSpecialKeywords) names.emplace_back(keyword.name);
  return names;
}

// Splits a numeric statement at an unquoted keyword among its values. Klamp't reads such a
// keyword as a bad number and silently drops the rest of the statement (athlete.rob's servoI
// line after a trailing backslash); we read it as the start of a new statement.
std::vector<Statement> SplitAtKeywords(std::vector<Statement> statements, const std::string& path,
                                       Diagnostics& diagnostics) {
  std::vector<Statement> out;
  for (Statement& statement : statements) {
    Statement current = std::move(statement);
    while (true) {
      const std::string keyword = ToLower(current.tokens.front().text);
      if (!ExpectsNumbers(keyword)) break;
      double unused = 0.0;
      const auto split =
          std::find_if(current.tokens.begin() + 1, current.tokens.end(), [&](const Token& token) {
            return !token.quoted && !ParseDouble(token.text, &unused) &&
                   IsKeyword(ToLower(token.text));
          });
      if (split == current.tokens.end()) break;
      const Token& previous = *(split - 1);
      const std::string how =
          split->line != previous.line
              ? "continues the '" + current.tokens.front().text +
                    "' statement through a trailing backslash"
              : "follows the '" + current.tokens.front().text + "' values on the same line";
      diagnostics.Warning({path, split->line, 0},
                          "'" + split->text + "' " + how + "; read as a new statement");
      Statement rest;
      rest.tokens.assign(std::make_move_iterator(split),
                         std::make_move_iterator(current.tokens.end()));
      rest.line = rest.tokens.front().line;
      current.tokens.erase(split, current.tokens.end());
      out.push_back(std::move(current));
      current = std::move(rest);
    }
    out.push_back(std::move(current));
  }
  return out;
}

void StatementReader::Read(const Statement& statement) {
  const Token& first = statement.tokens.front();
  const std::string keyword = ToLower(first.text);
  if (const NumberKeyword* number_keyword = FindNumberKeyword(keyword)) {
    ReadNumbers(statement, *number_keyword);
    return;
  }
  if (const SpecialKeyword* special = FindSpecialKeyword(keyword)) {
    (this->*special->read)(statement);
    return;
  }
  std::string message = "unknown keyword '" + first.text + "'";
  const std::string suggestion = SuggestName(keyword, AllKeywordNames());
  if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
  Error(first.line, message);
}

bool StatementReader::Number(const Token& token, const std::string& keyword, double* value) {
  if (ParseDouble(token.text, value)) return true;
  Error(token.line, "'" + token.text + "' in '" + keyword + "' is not a number");
  return false;
}

bool StatementReader::Integer(const Token& token, int* value) {
  if (ParseInt(token.text, value)) return true;
  Error(token.line, "'" + token.text + "' is not an integer");
  return false;
}

bool StatementReader::Numbers(const Statement& statement, size_t first,
                              std::vector<double>* values) {
  bool ok = true;
  for (size_t i = first; i < statement.tokens.size(); ++i) {
    double value = 0.0;
    ok = Number(statement.tokens[i], statement.tokens.front().text, &value) && ok;
    values->push_back(value);
  }
  return ok;
}

// the text of tokens [first, end) as written: spacing kept within a line, lines joined by '\n'
std::string StatementReader::RawText(const Statement& statement, size_t first) const {
  if (first + 1 == statement.tokens.size()) return statement.tokens[first].text;
  std::string out;
  size_t line_start = 0;  // offset of the current token's physical line in text_
  int line = 1;
  size_t i = first;
  while (i < statement.tokens.size()) {
    const int segment_line = statement.tokens[i].line;
    while (line < segment_line) {
      line_start = text_.find('\n', line_start) + 1;
      ++line;
    }
    size_t last = i;
    while (last + 1 < statement.tokens.size() && statement.tokens[last + 1].line == segment_line) {
      ++last;
    }
    const Token& begin = statement.tokens[i];
    const Token& end = statement.tokens[last];
    const size_t from = line_start + begin.column - 1;
    const size_t to = line_start + end.column - 1 + end.text.size() + (end.quoted ? 2 : 0);
    if (!out.empty()) out += '\n';
    out += text_.substr(from, std::min(to, text_.find('\n', from)) - from);
    i = last + 1;
  }
  return out;
}

void StatementReader::ReadNumbers(const Statement& statement, const NumberKeyword& keyword) {
  NumberList& list = out_.*keyword.list;
  if (list.keyword.empty()) {
    list.keyword = statement.tokens.front().text;
    list.line = statement.line;
  }
  const int count = static_cast<int>(statement.tokens.size()) - 1;
  if (count % keyword.group != 0) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects a multiple of " +
                              std::to_string(keyword.group) + " numbers, got " +
                              std::to_string(count));
  }
  for (size_t i = 1; i < statement.tokens.size(); ++i) {
    const Token& token = statement.tokens[i];
    double value = 0.0;
    int integer = 0;
    const std::string& name = statement.tokens.front().text;
    if (keyword.integers ? Integer(token, &integer) : Number(token, name, &value)) {
      if (keyword.integers) value = integer;
    }
    // a bad value keeps its place (as 0) so that it does not also cause a count error
    list.values.push_back(value);
    list.lines.push_back(token.line);
    list.degrees.push_back(keyword.degrees);
  }
}

void StatementReader::ReadWords(const Statement& statement, WordList* list) {
  if (list->keyword.empty()) {
    list->keyword = statement.tokens.front().text;
    list->line = statement.line;
  }
  for (size_t i = 1; i < statement.tokens.size(); ++i) {
    list->values.push_back(statement.tokens[i].text);
  }
}

void StatementReader::ReadJointTypes(const Statement& statement) {
  ReadWords(statement, &out_.joint_types);
  for (size_t i = 1; i < statement.tokens.size(); ++i) {
    const std::string letter = ToLower(statement.tokens[i].text);
    if (letter != "r" && letter != "p") {
      Error(statement.tokens[i].line,
            "invalid joint type '" + statement.tokens[i].text + "', expected 'r' or 'p'");
    }
  }
}

void StatementReader::ReadTranslation(const Statement& statement) {
  std::vector<double> values;
  if (!Numbers(statement, 1, &values)) return;
  if (values.size() != 3) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects 3 numbers, got " +
                              std::to_string(values.size()));
    return;
  }
  out_.translation = {{values[0], values[1], values[2]}, statement.line};
}

void StatementReader::ReadRotation(const Statement& statement) {
  std::vector<double> values;
  if (!Numbers(statement, 1, &values)) return;
  if (values.size() != 9) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects 9 numbers, got " +
                              std::to_string(values.size()));
    return;
  }
  Mat3 rotation;
  rotation << values[0], values[1], values[2], values[3], values[4], values[5], values[6],
      values[7], values[8];
  out_.rotation = {rotation, statement.line};
}

void StatementReader::ReadScale(const Statement& statement) {
  std::vector<double> values;
  if (!Numbers(statement, 1, &values)) return;
  if (values.size() != 1) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects 1 number, got " +
                              std::to_string(values.size()));
  } else if (values[0] != 1.0) {
    Error(statement.line, "'" + statement.tokens.front().text +
                              "' other than 1 is not supported, got '" + statement.tokens[1].text +
                              "'");
  }
}

void StatementReader::ReadAutomass(const Statement& statement) {
  out_.automass = true;
  out_.automass_line = statement.line;
  std::vector<double> values;
  if (!Numbers(statement, 1, &values)) return;
  if (values.size() > 1) {
    Error(statement.line, "'" + statement.tokens.front().text +
                              "' expects at most 1 number (the surface fraction), got " +
                              std::to_string(values.size()));
  } else if (values.size() == 1 && !(values[0] >= 0.0 && values[0] <= 1.0)) {
    Error(statement.line, "'" + statement.tokens.front().text +
                              "' surface fraction must be in [0, 1], got '" +
                              statement.tokens[1].text + "'");
  } else if (values.size() == 1) {
    out_.surface_fraction = values[0];
  }
}

void StatementReader::ReadAutotorque(const Statement& statement) {
  std::vector<double> values;
  if (!Numbers(statement, 1, &values)) return;
  if (values.size() != 1) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects 1 number, got " +
                              std::to_string(values.size()));
    return;
  }
  out_.autotorque = values[0];
}

void StatementReader::ReadGeomTransform(const Statement& statement) {
  const std::string& keyword = statement.tokens.front().text;
  const int count = static_cast<int>(statement.tokens.size()) - 1;
  if (count != 17) {
    Error(statement.line, "'" + keyword + "' expects a link index and 16 numbers, got " +
                              std::to_string(std::max(count - 1, 0)) + " numbers");
    return;
  }
  GeomTransformStatement entry;
  entry.line = statement.line;
  std::vector<double> values;
  if (!Integer(statement.tokens[1], &entry.link) || !Numbers(statement, 2, &values)) return;
  Mat4 matrix;
  for (int i = 0; i < 16; ++i) matrix(i / 4, i % 4) = values[i];
  if (matrix.row(3) != Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0)) {
    Error(statement.line, "'" + keyword + "' matrix must end with the row '0 0 0 1'");
    return;
  }
  entry.matrix = Affine(matrix);
  out_.geom_transforms.push_back(entry);
}

void StatementReader::ReadUnsupported(const Statement& statement) {
  Error(statement.line, "'" + statement.tokens.front().text + "' is not supported");
}

void StatementReader::ReadProperty(const Statement& statement) {
  if (statement.tokens.size() < 3) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects a name and a value");
    return;
  }
  out_.properties.push_back({statement.tokens[1].text, RawText(statement, 2), statement.line});
}

void StatementReader::ReadPairs(const Statement& statement, std::vector<PairStatement>* pairs) {
  const size_t count = statement.tokens.size() - 1;
  if (count % 2 != 0) {
    Error(statement.line, "'" + statement.tokens.front().text + "' expects pairs of links, got " +
                              std::to_string(count) + " names");
    return;
  }
  for (size_t i = 1; i + 1 < statement.tokens.size(); i += 2) {
    pairs->push_back(
        {statement.tokens[i].text, statement.tokens[i + 1].text, statement.tokens[i].line});
  }
}

}  // namespace

void ReadRobStatements(const std::string& text, const std::string& path, Diagnostics& diagnostics,
                       RobStatements* out) {
  StatementReader reader(text, path, diagnostics, *out);
  for (const Statement& statement :
       SplitAtKeywords(SplitStatements(text, path, &diagnostics), path, diagnostics)) {
    reader.Read(statement);
  }
}

}  // namespace lamina::core::rob
