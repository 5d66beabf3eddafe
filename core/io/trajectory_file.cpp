// SPDX-License-Identifier: MIT
// Klamp't configuration and motion files. `.config` and `.milestones` are token streams (a
// record may span lines), `.path` has one milestone per statement, MultiPath `.xml` is read
// with tinyxml2. Every problem is reported with its line; a parse with errors returns nullopt.
#include "core/io/trajectory_file.h"

#include <cmath>
#include <string>

#include <tinyxml2.h>

#include "core/io/paths.h"
#include "core/io/text_statements.h"
#include "core/io/xml_element_reader.h"

namespace lamina::core {

namespace {

// A cursor over tokens, for records that may span lines.
struct TokenCursor {
  const std::vector<Token>& tokens;
  size_t next = 0;

  bool done() const { return next >= tokens.size(); }
  size_t remaining() const { return tokens.size() - next; }
};

std::vector<Token> AllTokens(const std::string& text, const std::string& file,
                             Diagnostics& diagnostics) {
  std::vector<Token> tokens;
  for (Statement& statement : SplitStatements(text, file, &diagnostics)) {
    for (Token& token : statement.tokens) tokens.push_back(std::move(token));
  }
  return tokens;
}

SourceLocation At(const std::string& file, const Token& token) {
  return {file, token.line, 0};
}

// A finite number; reports and gives 0 otherwise (the caller fails on the error count).
double ReadFinite(const Token& token, const std::string& file, Diagnostics& diagnostics) {
  double value = 0.0;
  if (!ParseDouble(token.text, &value)) {
    diagnostics.Error(At(file, token), "'" + token.text + "' is not a number");
    return 0.0;
  }
  if (std::isinf(value)) {
    diagnostics.Error(At(file, token), "expected a finite number, got '" + token.text + "'");
    return 0.0;
  }
  return value;
}

// Reads "N v1 ... vN" at the cursor. `kind` qualifies the values in messages ("" or
// "velocity "). nullopt when the count is bad or the tokens run out (the stream cannot be
// trusted after that); bad values are reported and read as 0.
std::optional<VecX> ReadCountedVector(TokenCursor& cursor, const std::string& kind,
                                      const std::string& file, Diagnostics& diagnostics) {
  const Token& count_token = cursor.tokens[cursor.next++];
  int count = 0;
  if (!ParseInt(count_token.text, &count)) {
    diagnostics.Error(At(file, count_token),
                      "expected a " + kind + "value count, got '" + count_token.text + "'");
    return std::nullopt;
  }
  if (count < 0) {
    diagnostics.Error(At(file, count_token),
                      "value count must be >= 0, got '" + count_token.text + "'");
    return std::nullopt;
  }
  if (cursor.remaining() < static_cast<size_t>(count)) {
    diagnostics.Error(At(file, count_token), "expected " + std::to_string(count) + " " + kind +
                                                 "values, got " +
                                                 std::to_string(cursor.remaining()));
    cursor.next = cursor.tokens.size();
    return std::nullopt;
  }
  VecX values(count);
  for (int i = 0; i < count; ++i) {
    values[i] = ReadFinite(cursor.tokens[cursor.next++], file, diagnostics);
  }
  return values;
}

// "N v1 ... vN" filling `tokens` from `first` to the end exactly.
std::optional<VecX> ReadExactVector(const std::vector<Token>& tokens, size_t first,
                                    const std::string& file, Diagnostics& diagnostics) {
  TokenCursor cursor{tokens, first};
  auto values = ReadCountedVector(cursor, "", file, diagnostics);
  if (values && !cursor.done()) {
    diagnostics.Error(At(file, tokens[first]),
                      "expected " + std::to_string(values->size()) + " values, got " +
                          std::to_string(values->size() + cursor.remaining()));
    return std::nullopt;
  }
  return values;
}

// Reports a milestone whose size differs from the first one's.
void CheckSameSize(const MilestoneSequence& sequence, const VecX& config, const Token& where,
                   const std::string& file, Diagnostics& diagnostics) {
  if (sequence.configs.empty() || sequence.configs.front().size() == config.size()) return;
  diagnostics.Error(At(file, where), "milestone has " + std::to_string(config.size()) +
                                         " values, expected " +
                                         std::to_string(sequence.configs.front().size()) +
                                         " like the first milestone");
}

// The time of a `.path` line: finite and not before the previous one.
double ReadPathTime(const Token& token, const Token* previous, double previous_time,
                    const std::string& file, Diagnostics& diagnostics) {
  const int errors_before = diagnostics.error_count();
  const double time = ReadFinite(token, file, diagnostics);
  if (previous && diagnostics.error_count() == errors_before && time < previous_time) {
    diagnostics.Error(At(file, token), "time must be nondecreasing, got '" + token.text +
                                           "' after '" + previous->text + "'");
  }
  return time;
}

// One `.milestones` record "N q...  N dq..."; false when the stream cannot be followed further.
bool ReadMilestoneRecord(TokenCursor& cursor, const std::string& file, Diagnostics& diagnostics,
                         MilestoneSequence* sequence) {
  const Token& config_token = cursor.tokens[cursor.next];
  const auto config = ReadCountedVector(cursor, "", file, diagnostics);
  if (!config) return false;
  CheckSameSize(*sequence, *config, config_token, file, diagnostics);
  if (cursor.done()) {
    diagnostics.Error(At(file, cursor.tokens.back()),
                      "milestone " + std::to_string(sequence->configs.size() + 1) +
                          " has no velocity 'N dq1 ... dqN'");
    return false;
  }
  const Token& velocity_token = cursor.tokens[cursor.next];
  const auto velocity = ReadCountedVector(cursor, "velocity ", file, diagnostics);
  if (!velocity) return false;
  if (velocity->size() != config->size()) {
    diagnostics.Error(At(file, velocity_token),
                      "velocity has " + std::to_string(velocity->size()) + " values, expected " +
                          std::to_string(config->size()) + " like its configuration");
  }
  sequence->configs.push_back(*config);
  sequence->velocities.push_back(*velocity);
  return true;
}

// "N v1 ... vN" with the count and a tab first, as Klamp't writes vectors.
std::string CountedVectorText(const VecX& values) {
  std::string text = std::to_string(values.size());
  if (values.size() > 0) {
    text += '\t';
    text += FormatDoubles(values.data(), static_cast<int>(values.size()));
  }
  return text;
}

// [section] MultiPath XML

// Fields shared while reading the milestones of every section.
struct MultiPathReader {
  const std::string& file;
  Diagnostics& diagnostics;
  MilestoneSequence sequence;
  int ignored_ikgoals = 0, first_ikgoal_line = 0;
  int ignored_holds = 0, first_hold_line = 0;
};

void CountIgnored(const tinyxml2::XMLElement& element, int* count, int* first_line) {
  if ((*count)++ == 0) *first_line = element.GetLineNum();
}

// Timed and untimed milestones (or ones with and without velocity) must not mix.
bool CheckPresence(const XmlElementReader& reader, const char* attribute, bool first,
                   bool first_has) {
  const bool has = reader.Has(attribute);
  if (first || has == first_has) return true;
  reader.Error(std::string(has ? "has a '" : "has no '") + attribute + "' but the first " +
               "milestone " + (has ? "has none" : "has one"));
  return false;
}

void ReadMilestoneElement(const tinyxml2::XMLElement& element, MultiPathReader& state) {
  const XmlElementReader reader(element, state.file, state.diagnostics);
  reader.WarnUnknownAttributes({"config", "time", "velocity"});
  MilestoneSequence& sequence = state.sequence;
  const bool first = sequence.configs.empty();
  if (!reader.Has("config")) return reader.Error("missing attribute 'config'");
  const auto config = reader.CountedVector("config");
  if (!config) return;
  if (!first && config->size() != sequence.configs.front().size()) {
    return reader.Error("config", "has " + std::to_string(config->size()) + " values, expected " +
                                      std::to_string(sequence.configs.front().size()) +
                                      " like the first milestone");
  }
  if (!CheckPresence(reader, "time", first, !sequence.times.empty()) ||
      !CheckPresence(reader, "velocity", first, !sequence.velocities.empty())) {
    return;
  }
  std::optional<double> time;
  if (reader.Has("time") && !(time = reader.Number("time", false))) return;
  if (time && !sequence.times.empty() && *time < sequence.times.back()) {
    return reader.Error("time", "must be nondecreasing, got '" + FormatDouble(*time) + "' after '" +
                                    FormatDouble(sequence.times.back()) + "'");
  }
  std::optional<VecX> velocity;
  if (reader.Has("velocity") && !(velocity = reader.CountedVector("velocity"))) return;
  if (velocity && velocity->size() != config->size()) {
    return reader.Error("velocity", "has " + std::to_string(velocity->size()) +
                                        " values, expected " + std::to_string(config->size()) +
                                        " like 'config'");
  }
  sequence.configs.push_back(*config);
  if (time) sequence.times.push_back(*time);
  if (velocity) sequence.velocities.push_back(*velocity);
}

void ReadSection(const tinyxml2::XMLElement& section, MultiPathReader& state) {
  for (const tinyxml2::XMLElement* child = section.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    const std::string name = child->Name();
    if (name == "milestone") {
      ReadMilestoneElement(*child, state);
    } else if (name == "ikgoal") {
      CountIgnored(*child, &state.ignored_ikgoals, &state.first_ikgoal_line);
    } else if (name == "hold") {
      CountIgnored(*child, &state.ignored_holds, &state.first_hold_line);
    } else {
      state.diagnostics.Warning({state.file, child->GetLineNum(), 0},
                                "unknown element <" + name + "> ignored");
    }
  }
}

void NoteIgnored(const MultiPathReader& state) {
  if (state.ignored_ikgoals > 0) {
    state.diagnostics.Note({state.file, state.first_ikgoal_line, 0},
                           "ignoring " + std::to_string(state.ignored_ikgoals) +
                               " <ikgoal> elements (IK constraints are not supported)");
  }
  if (state.ignored_holds > 0) {
    state.diagnostics.Note({state.file, state.first_hold_line, 0},
                           "ignoring " + std::to_string(state.ignored_holds) +
                               " <hold> elements (contact constraints are not supported)");
  }
}

}  // namespace

std::optional<VecX> ParseConfig(const std::string& text, const std::string& file,
                                Diagnostics& diagnostics) {
  const std::vector<Token> tokens = AllTokens(text, file, diagnostics);
  if (tokens.empty()) {
    diagnostics.Error({file, 0, 0}, "expected a configuration 'N q1 ... qN', got an empty file");
    return std::nullopt;
  }
  const int errors_before = diagnostics.error_count();
  auto config = ReadExactVector(tokens, 0, file, diagnostics);
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  return config;
}

std::optional<VecX> ReadConfigFile(const std::string& path, Diagnostics& diagnostics) {
  std::string text;
  if (!ReadFileText(path, &text)) {
    diagnostics.Error({path, 0, 0}, "cannot open configuration file '" + path + "'");
    return std::nullopt;
  }
  return ParseConfig(text, path, diagnostics);
}

std::optional<MilestoneSequence> ParseLinearPath(const std::string& text, const std::string& file,
                                                 Diagnostics& diagnostics) {
  const int errors_before = diagnostics.error_count();
  MilestoneSequence path;
  const Token* previous_time = nullptr;
  const std::vector<Statement> statements = SplitStatements(text, file, &diagnostics);
  for (const Statement& statement : statements) {
    const std::vector<Token>& tokens = statement.tokens;
    if (tokens.size() < 2) {
      diagnostics.Error({file, statement.line, 0},
                        "expected a milestone 't N q1 ... qN', got '" + tokens[0].text + "'");
      continue;
    }
    const double time = ReadPathTime(
        tokens[0], previous_time, path.times.empty() ? 0.0 : path.times.back(), file, diagnostics);
    const auto config = ReadExactVector(tokens, 1, file, diagnostics);
    if (!config) continue;
    CheckSameSize(path, *config, tokens[1], file, diagnostics);
    previous_time = &tokens[0];
    path.times.push_back(time);
    path.configs.push_back(*config);
  }
  if (statements.empty()) diagnostics.Error({file, 0, 0}, "the path has no milestones");
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  return path;
}

std::optional<MilestoneSequence> ParseMilestones(const std::string& text, const std::string& file,
                                                 Diagnostics& diagnostics) {
  const int errors_before = diagnostics.error_count();
  const std::vector<Token> tokens = AllTokens(text, file, diagnostics);
  MilestoneSequence milestones;
  TokenCursor cursor{tokens};
  while (!cursor.done() && ReadMilestoneRecord(cursor, file, diagnostics, &milestones)) {
  }
  if (tokens.empty()) diagnostics.Error({file, 0, 0}, "the file has no milestones");
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  return milestones;
}

std::optional<MilestoneSequence> ParseMultiPath(const std::string& text, const std::string& file,
                                                Diagnostics& diagnostics) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    diagnostics.Error({file, document.ErrorLineNum(), 0},
                      std::string("malformed XML: ") + document.ErrorName());
    return std::nullopt;
  }
  // the same wording as the world loader's
  const tinyxml2::XMLElement* root = document.RootElement();
  if (!root || std::string(root->Name()) != "multipath") {
    diagnostics.Error(
        {file, root ? root->GetLineNum() : 1, 0},
        "root element must be <multipath>, got <" + std::string(root ? root->Name() : "") + ">");
    return std::nullopt;
  }
  const int errors_before = diagnostics.error_count();
  MultiPathReader state{file, diagnostics, {}};
  for (const tinyxml2::XMLElement* child = root->FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    const std::string name = child->Name();
    if (name == "section") {
      ReadSection(*child, state);
    } else if (name == "hold") {
      CountIgnored(*child, &state.ignored_holds, &state.first_hold_line);
    } else {
      diagnostics.Warning({file, child->GetLineNum(), 0}, "unknown element <" + name + "> ignored");
    }
  }
  NoteIgnored(state);
  if (state.sequence.configs.empty() && diagnostics.error_count() == errors_before) {
    diagnostics.Error({file, root->GetLineNum(), 0}, "<multipath> has no milestones");
  }
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  return std::move(state.sequence);
}

std::optional<MilestoneSequence> ReadMotionFile(const std::string& path, Diagnostics& diagnostics) {
  const std::string extension = LowerExtension(path);
  if (extension != "config" && extension != "path" && extension != "milestones" &&
      extension != "xml") {
    diagnostics.Error({path, 0, 0}, "unsupported motion file type '." + extension + "'");
    return std::nullopt;
  }
  std::string text;
  if (!ReadFileText(path, &text)) {
    diagnostics.Error({path, 0, 0}, "cannot open motion file '" + path + "'");
    return std::nullopt;
  }
  if (extension == "path") return ParseLinearPath(text, path, diagnostics);
  if (extension == "milestones") return ParseMilestones(text, path, diagnostics);
  if (extension == "xml") return ParseMultiPath(text, path, diagnostics);
  auto config = ParseConfig(text, path, diagnostics);
  if (!config) return std::nullopt;
  MilestoneSequence single;
  single.configs.push_back(std::move(*config));
  return single;
}

std::string WriteConfig(const VecX& config) {
  return CountedVectorText(config) + "\n";
}

// An untimed sequence is written with times 0, 1, 2, ... (a .path is always timed).
std::string WriteLinearPath(const MilestoneSequence& path) {
  std::string text;
  for (size_t i = 0; i < path.configs.size(); ++i) {
    const double time = path.times.empty() ? static_cast<double>(i) : path.times[i];
    text += FormatDouble(time) + "\t" + CountedVectorText(path.configs[i]) + "\n";
  }
  return text;
}

// Milestones without velocities are written with zero velocities (each record needs one).
std::string WriteMilestones(const MilestoneSequence& milestones) {
  std::string text;
  for (size_t i = 0; i < milestones.configs.size(); ++i) {
    const VecX& config = milestones.configs[i];
    const VecX velocity =
        milestones.velocities.empty() ? VecX::Zero(config.size()) : milestones.velocities[i];
    text += CountedVectorText(config) + "\t" + CountedVectorText(velocity) + "\n";
  }
  return text;
}

std::optional<Trajectory> LoadTrajectory(const std::string& path, Diagnostics& diagnostics,
                                         const JointLimits& limits) {
  const auto sequence = ReadMotionFile(path, diagnostics);
  if (!sequence) return std::nullopt;
  JointLimits timing_limits = limits;
  if (sequence->times.empty() && limits.dof() == 0 && !sequence->configs.empty()) {
    timing_limits =
        JointLimits::Unbounded(static_cast<int>(sequence->configs.front().size()), 1.0, 1.0);
    if (sequence->configs.size() > 1) {
      diagnostics.Note({path, 0, 0},
                       "untimed milestones are timed with unit limits (velocity 1 per s, "
                       "acceleration 1 per s^2)");
    }
  }
  std::string reason;
  auto trajectory = Trajectory::FromSequence(*sequence, timing_limits, &reason);
  if (!trajectory) diagnostics.Error({path, 0, 0}, "cannot build a trajectory: " + reason);
  return trajectory;
}

}  // namespace lamina::core
