// SPDX-License-Identifier: MIT
// Access paths (access_path.h): the parser, the resolver against a WorldDesc, and get/set of
// the table's rows on a description.
#include "core/model/access_path.h"

#include <cctype>
#include <climits>

#include "core/diagnostics.h"
#include "core/number_text.h"
#include "core/suggest.h"

namespace lamina::core {

namespace {

std::string Trim(std::string_view text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  const size_t last = text.find_last_not_of(" \t");
  return std::string(text.substr(first, last - first + 1));
}

bool IsIdentifierStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool IsIdentifierChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

bool AllDigits(const std::string& text) {
  if (text.empty()) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

// ---- parsing ------------------------------------------------------------------------------

class PathParser {
 public:
  explicit PathParser(std::string_view text) { path_.text = Trim(text); }

  std::optional<AccessPath> Parse(std::string* error) {
    const bool ok = ParseSegments();
    if (!ok && error) *error = error_;
    if (!ok) return std::nullopt;
    return std::move(path_);
  }

 private:
  const std::string& text() const { return path_.text; }
  bool AtEnd() const { return pos_ >= text().size(); }

  bool Fail(const std::string& what, size_t column) {
    error_ = text() + ": " + what + " at column " + std::to_string(column + 1);
    return false;
  }

  bool ParseSegments() {
    if (text().empty()) {
      error_ = "empty access path";
      return false;
    }
    while (ParseSegment()) {
      if (AtEnd()) return true;
      if (text()[pos_] != '.') return Fail("expected '.' or '['", pos_);
      ++pos_;
    }
    return false;
  }

  bool ParseSegment() {
    if (AtEnd() || !IsIdentifierStart(text()[pos_])) return Fail("expected a name", pos_);
    AccessSegment segment;
    const size_t start = pos_;
    while (!AtEnd() && IsIdentifierChar(text()[pos_])) ++pos_;
    segment.name = text().substr(start, pos_ - start);
    segment.end = pos_;
    while (!AtEnd() && text()[pos_] == '[') {
      AccessSelector selector;
      if (!ParseSelector(&selector)) return false;
      segment.selectors.push_back(std::move(selector));
    }
    path_.segments.push_back(std::move(segment));
    return true;
  }

  void SkipBlanks() {
    while (!AtEnd() && (text()[pos_] == ' ' || text()[pos_] == '\t')) ++pos_;
  }

  bool ParseSelector(AccessSelector* selector) {
    ++pos_;  // '['
    SkipBlanks();
    const bool quoted = !AtEnd() && (text()[pos_] == '\'' || text()[pos_] == '"');
    if (!(quoted ? ParseQuotedName(selector) : ParsePlainSelector(selector))) return false;
    selector->end = pos_;
    return true;
  }

  bool ParseQuotedName(AccessSelector* selector) {
    const size_t open = pos_;
    const size_t close = text().find(text()[open], open + 1);
    if (close == std::string::npos) return Fail("unterminated quote", open);
    selector->name = text().substr(open + 1, close - open - 1);
    pos_ = close + 1;
    SkipBlanks();
    if (AtEnd() || text()[pos_] != ']') return Fail("expected ']' after the quoted name", pos_);
    ++pos_;
    return true;
  }

  bool ParsePlainSelector(AccessSelector* selector) {
    const size_t close = text().find(']', pos_);
    if (close == std::string::npos) return Fail("expected ']'", text().size());
    const std::string raw = Trim(std::string_view(text()).substr(pos_, close - pos_));
    if (raw.empty()) return Fail("empty []", close);
    if (AllDigits(raw)) {
      selector->is_index = true;
      if (!ParseInt(raw, &selector->index)) return Fail("index " + raw + " is too large", pos_);
    } else {
      selector->name = raw;
    }
    pos_ = close + 1;
    return true;
  }

  AccessPath path_;
  size_t pos_ = 0;
  std::string error_;
};

// ---- words ---------------------------------------------------------------------------------

// what owns an item: an element kind, or a robot's controller
enum class Owner { kSettings, kTerrain, kObject, kRobot, kLink, kDriver, kController, kNone };

struct OwnerWords {
  Owner owner;
  const char* article;
  const char* singular;
  const char* plural;
  const char* example_item;
};

constexpr OwnerWords kOwnerWords[] = {
    {Owner::kSettings, "the ", "settings", "settings", "gravity"},
    {Owner::kTerrain, "a ", "terrain", "terrains", "kFriction"},
    {Owner::kObject, "an ", "object", "objects", "kFriction"},
    {Owner::kRobot, "a ", "robot", "robots", "config"},
    {Owner::kLink, "a ", "link", "links", "jointLimits"},
    {Owner::kDriver, "a ", "driver", "drivers", "servoP"},
    {Owner::kController, "a robot's ", "controller", "controllers", "commandedConfig"},
};

const OwnerWords& WordsOf(Owner owner) {
  for (const OwnerWords& words : kOwnerWords) {
    if (words.owner == owner) return words;
  }
  return kOwnerWords[0];
}

// ---- items ---------------------------------------------------------------------------------

struct StateItemSpec {
  std::string_view name;
  Owner owner;
  StateItem item;
  bool read_only;
};

constexpr StateItemSpec kStateItems[] = {
    {"transform", Owner::kObject, StateItem::kObjectTransform, false},
    {"velocity", Owner::kObject, StateItem::kObjectVelocity, false},
    {"config", Owner::kRobot, StateItem::kRobotConfig, false},
    {"actualConfig", Owner::kRobot, StateItem::kRobotConfig, false},
    {"velocity", Owner::kRobot, StateItem::kRobotVelocity, false},
    {"actualVelocity", Owner::kRobot, StateItem::kRobotVelocity, false},
    {"torques", Owner::kRobot, StateItem::kRobotTorques, true},
    {"actualTorques", Owner::kRobot, StateItem::kRobotTorques, true},
    {"transform", Owner::kLink, StateItem::kLinkTransform, true},
    {"velocity", Owner::kLink, StateItem::kLinkVelocity, true},
    {"commandedConfig", Owner::kController, StateItem::kCommandedConfig, true},
    {"commandedVelocity", Owner::kController, StateItem::kCommandedVelocity, true},
    {"sensedConfig", Owner::kController, StateItem::kSensedConfig, true},
    {"sensedVelocity", Owner::kController, StateItem::kSensedVelocity, true},
};

// Klamp't's labels of the servo gains
struct RowAlias {
  std::string_view alias;
  std::string_view key;
};
constexpr RowAlias kDriverAliases[] = {{"kP", "servoP"}, {"kI", "servoI"}, {"kD", "servoD"}};

// the row whose layout a state item's value has
const ParamSpec* LayoutRow(StateItem item) {
  switch (item) {
    case StateItem::kNone:
      return nullptr;
    case StateItem::kTime:
      return FindParam("timestep", ElementKind::kSettings);
    case StateItem::kObjectTransform:
    case StateItem::kLinkTransform:
      return FindParam("transform", ElementKind::kObject);
    case StateItem::kObjectVelocity:
    case StateItem::kLinkVelocity:
      return FindParam("velocity", ElementKind::kObject);
    default:
      return FindParam("config", ElementKind::kRobot);
  }
}

struct FoundItem {
  const ParamSpec* row = nullptr;
  StateItem state = StateItem::kNone;
  bool read_only = false;
};

std::optional<FoundItem> FindStateItem(Owner owner, std::string_view name) {
  for (const StateItemSpec& spec : kStateItems) {
    if (spec.owner == owner && spec.name == name) {
      return FoundItem{LayoutRow(spec.item), spec.item, spec.read_only};
    }
  }
  return std::nullopt;
}

std::string_view RowKey(Owner owner, std::string_view name) {
  if (owner != Owner::kDriver) return name;
  for (const RowAlias& alias : kDriverAliases) {
    if (alias.alias == name) return alias.key;
  }
  return name;
}

std::optional<FoundItem> FindItem(Owner owner, ElementKind kind, std::string_view name,
                                  AccessContext context) {
  if (context == AccessContext::kSimulation) {
    if (auto found = FindStateItem(owner, name)) return found;
  }
  if (owner == Owner::kController) return std::nullopt;
  if (const ParamSpec* row = FindParam(RowKey(owner, name), kind)) return FoundItem{row};
  return std::nullopt;
}

// every item name of `owner` in `context`, for suggestions
std::vector<std::string> ItemNames(Owner owner, ElementKind kind, AccessContext context) {
  std::vector<std::string> names;
  if (context == AccessContext::kSimulation) {
    for (const StateItemSpec& spec : kStateItems) {
      if (spec.owner == owner) names.emplace_back(spec.name);
    }
  }
  if (owner == Owner::kController) return names;
  for (const ParamSpec* row : ParamsOf(kind)) names.emplace_back(row->key);
  if (owner == Owner::kDriver) {
    for (const RowAlias& alias : kDriverAliases) names.emplace_back(alias.alias);
  }
  return names;
}

bool HasComponents(const ParamSpec& row) {
  switch (row.type) {
    case ParamType::kReal:
    case ParamType::kInteger:
    case ParamType::kBool:
    case ParamType::kChoice:
      return false;
    default:
      return true;
  }
}

// ---- resolving ------------------------------------------------------------------------------

std::string DidYouMean(const std::string& name, const std::vector<std::string>& known) {
  const std::string suggestion = SuggestName(name, known);
  return suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)";
}

// CheckElement's message with the path as written
std::optional<std::string> CheckWritten(const WorldDesc& world, const ElementIndex& element,
                                        const std::string& written) {
  std::optional<std::string> problem = CheckElement(world, element);
  if (!problem) return std::nullopt;
  const size_t colon = problem->find(": ");
  return written + (colon == std::string::npos ? ": " + *problem : problem->substr(colon));
}

class Resolver {
 public:
  Resolver(const WorldDesc& world, const AccessPath& path, AccessContext context)
      : world_(world), path_(path), context_(context) {}

  std::optional<AccessTarget> Resolve(std::string* error) {
    const bool ok = ResolveRoot();
    if (!ok && error) *error = error_;
    if (!ok) return std::nullopt;
    return target_;
  }

 private:
  const std::vector<AccessSegment>& segments() const { return path_.segments; }

  bool Fail(size_t end, const std::string& what) {
    error_ = path_.Prefix(end) + ": " + what;
    return false;
  }

  bool ResolveRoot() {
    const AccessSegment& root = segments()[0];
    if (root.name == "settings") return NoSelector(root) && ResolveItem(1, Owner::kSettings);
    if (root.name == "time") return ResolveTime(root);
    if (root.name == "terrains") {
      return ResolveElement(root, ElementKind::kTerrain, Owner::kTerrain);
    }
    if (root.name == "objects" || root.name == "rigidObjects") {
      return ResolveElement(root, ElementKind::kObject, Owner::kObject);
    }
    if (root.name == "robots") return ResolveElement(root, ElementKind::kRobot, Owner::kRobot);
    if (root.name == "controllers") return ResolveControllers(root);
    return UnknownRoot(root);
  }

  bool UnknownRoot(const AccessSegment& root) {
    std::vector<std::string> roots = {"settings", "terrains", "objects", "rigidObjects", "robots"};
    if (context_ == AccessContext::kSimulation) roots.insert(roots.end(), {"controllers", "time"});
    std::string known;
    for (const std::string& name : roots) known += (known.empty() ? "" : ", ") + name;
    return Fail(root.end, "no such root (roots: " + known + ")" + DidYouMean(root.name, roots));
  }

  bool SimulationOnly(const AccessSegment& segment) {
    if (context_ == AccessContext::kSimulation) return true;
    return Fail(segment.end, "exists only on a running simulation");
  }

  bool NoSelector(const AccessSegment& segment) {
    if (segment.selectors.empty()) return true;
    return Fail(segment.selectors[0].end, segment.name + " takes no [selector]");
  }

  bool ResolveTime(const AccessSegment& root) {
    if (!SimulationOnly(root) || !NoSelector(root)) return false;
    if (segments().size() > 1) return Fail(segments()[1].end, "time has no members");
    target_.state = StateItem::kTime;
    target_.row = LayoutRow(StateItem::kTime);
    target_.read_only = true;
    target_.path = path_.text;
    return true;
  }

  bool ResolveControllers(const AccessSegment& root) {
    if (!SimulationOnly(root)) return false;
    int robot = -1;
    if (!SelectIn(root, RobotNames(), Owner::kRobot, "", &robot)) return false;
    target_.element = ElementIndex::Robot(robot);
    return CheckSelected(root) && ResolveItem(1, Owner::kController);
  }

  bool ResolveElement(const AccessSegment& segment, ElementKind kind, Owner owner) {
    int index = -1;
    if (!SelectIn(segment, Names(kind), owner, "", &index)) return false;
    target_.element = {kind, index, -1};
    if (!CheckSelected(segment)) return false;
    if (kind == ElementKind::kRobot) return ResolveRobotMember();
    return ResolveItem(1, owner);
  }

  // `links[...]` or `drivers[...]` under a robot, or the robot's own item
  bool ResolveRobotMember() {
    if (segments().size() < 2) return ResolveItem(1, Owner::kRobot);
    const AccessSegment& member = segments()[1];
    const bool link = member.name == "links";
    if (!link && member.name != "drivers") return ResolveItem(1, Owner::kRobot);
    const Owner owner = link ? Owner::kLink : Owner::kDriver;
    const RobotDesc& robot = world_.robots[target_.element.index];
    int sub = -1;
    if (!SelectIn(member, MemberNames(robot, link), owner, " of robot '" + robot.name + "'",
                  &sub)) {
      return false;
    }
    const int r = target_.element.index;
    target_.element = link ? ElementIndex::Link(r, sub) : ElementIndex::Driver(r, sub);
    return CheckSelected(member) && ResolveItem(2, owner);
  }

  bool CheckSelected(const AccessSegment& segment) {
    const std::string written = path_.Prefix(segment.selectors[0].end);
    std::optional<std::string> problem = CheckWritten(world_, target_.element, written);
    if (!problem) return true;
    error_ = *problem;
    return false;
  }

  std::vector<std::string> RobotNames() const { return Names(ElementKind::kRobot); }

  std::vector<std::string> Names(ElementKind kind) const {
    std::vector<std::string> names;
    if (kind == ElementKind::kTerrain) {
      for (const TerrainDesc& terrain : world_.terrains) names.push_back(terrain.name);
    } else if (kind == ElementKind::kObject) {
      for (const RigidObjectDesc& object : world_.objects) names.push_back(object.name);
    } else {
      for (const RobotDesc& robot : world_.robots) names.push_back(robot.name);
    }
    return names;
  }

  static std::vector<std::string> MemberNames(const RobotDesc& robot, bool links) {
    std::vector<std::string> names;
    if (links) {
      for (const LinkDesc& link : robot.links) names.push_back(link.name);
    } else {
      for (const DriverDesc& driver : robot.drivers) names.push_back(driver.name);
    }
    return names;
  }

  // the index the one selector of `segment` names among `names`
  bool SelectIn(const AccessSegment& segment, const std::vector<std::string>& names, Owner owner,
                const std::string& of, int* index) {
    const OwnerWords& words = WordsOf(owner);
    if (segment.selectors.empty()) {
      return Fail(segment.end, std::string("select ") + words.article + words.singular +
                                   " by index or name: " + segment.name + "[0] or " + segment.name +
                                   "[name]");
    }
    if (segment.selectors.size() > 1) {
      return Fail(segment.selectors[1].end,
                  std::string("one [index or name] selects ") + words.article + words.singular);
    }
    const AccessSelector& selector = segment.selectors[0];
    if (selector.is_index) {
      *index = selector.index;
      return true;
    }
    return SelectByName(selector, names, words, of, index);
  }

  bool SelectByName(const AccessSelector& selector, const std::vector<std::string>& names,
                    const OwnerWords& words, const std::string& of, int* index) {
    std::vector<int> matches;
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == selector.name) matches.push_back(static_cast<int>(i));
    }
    if (matches.size() == 1) {
      *index = matches[0];
      return true;
    }
    const std::string quoted = "'" + selector.name + "'";
    if (matches.empty()) {
      return Fail(selector.end, std::string("no ") + words.singular + of + " is named " + quoted +
                                    DidYouMean(selector.name, names));
    }
    std::string which;
    for (int i : matches) which += (which.empty() ? "" : ", ") + std::to_string(i);
    return Fail(selector.end, std::to_string(matches.size()) + " " + words.plural + of +
                                  " are named " + quoted + " (indices " + which +
                                  "); select one by index");
  }

  bool ResolveItem(size_t at, Owner owner) {
    if (at >= segments().size()) {
      const std::string& whole = path_.text;
      const OwnerWords& words = WordsOf(owner);
      return Fail(whole.size(), std::string("names ") + words.article + words.singular +
                                    ", not a value; add an item, e.g. " + whole + "." +
                                    words.example_item);
    }
    const AccessSegment& item = segments()[at];
    if (at + 1 < segments().size()) {
      return Fail(segments()[at + 1].end, item.name + " has no members");
    }
    std::optional<FoundItem> found = FindItem(owner, target_.element.kind, item.name, context_);
    if (!found) return UnknownItem(item, owner);
    target_.row = found->row;
    target_.state = found->state;
    target_.read_only = found->read_only;
    target_.path = path_.text;
    return ResolveComponent(item);
  }

  bool UnknownItem(const AccessSegment& item, Owner owner) {
    if (context_ == AccessContext::kDescription &&
        FindItem(owner, target_.element.kind, item.name, AccessContext::kSimulation)) {
      return Fail(item.end, "exists only on a running simulation");
    }
    const std::vector<std::string> known = ItemNames(owner, target_.element.kind, context_);
    return Fail(item.end, std::string(WordsOf(owner).plural) + " have no '" + item.name + "'" +
                              DidYouMean(item.name, known));
  }

  bool ResolveComponent(const AccessSegment& item) {
    if (item.selectors.empty()) return true;
    const AccessSelector& selector = item.selectors[0];
    if (item.selectors.size() > 1) {
      return Fail(item.selectors[1].end, "one [index] selects a component");
    }
    if (!HasComponents(*target_.row) || target_.state == StateItem::kTime) {
      return Fail(selector.end, item.name + " is one number; it has no components");
    }
    if (!selector.is_index) return Fail(selector.end, "a component is selected by its index");
    const int size = AccessValueSize(world_, target_);
    if (selector.index >= size) {
      return Fail(selector.end, item.name + " has " + std::to_string(size) + " components");
    }
    target_.component = selector.index;
    return true;
  }

  const WorldDesc& world_;
  const AccessPath& path_;
  AccessContext context_;
  AccessTarget target_;
  std::string error_;
};

// ---- assignment -----------------------------------------------------------------------------

// position of the first '=' outside selectors and quotes, or npos
size_t AssignmentSign(std::string_view text) {
  char quote = 0;
  bool in_selector = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (in_selector && (c == '\'' || c == '"')) {
      quote = c;
    } else if (c == '[' || c == ']') {
      in_selector = c == '[';
    } else if (c == '=' && !in_selector) {
      return i;
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::optional<AccessPath> ParseAccessPath(std::string_view text, std::string* error) {
  return PathParser(text).Parse(error);
}

std::optional<AccessTarget> ResolveAccessPath(const WorldDesc& world, const AccessPath& path,
                                              AccessContext context, std::string* error) {
  return Resolver(world, path, context).Resolve(error);
}

std::optional<AccessTarget> ResolveAccessPath(const WorldDesc& world, std::string_view path,
                                              AccessContext context, std::string* error) {
  std::optional<AccessPath> parsed = ParseAccessPath(path, error);
  if (!parsed) return std::nullopt;
  return ResolveAccessPath(world, *parsed, context, error);
}

int AccessValueSize(const WorldDesc& world, const AccessTarget& target) {
  switch (target.state) {
    case StateItem::kNone:
      return ParamSize(*target.row, world, target.element);
    case StateItem::kTime:
      return 1;
    case StateItem::kObjectTransform:
    case StateItem::kLinkTransform:
      return 12;
    case StateItem::kObjectVelocity:
    case StateItem::kLinkVelocity:
      return 6;
    case StateItem::kRobotTorques:
      return static_cast<int>(world.robots[target.element.index].drivers.size());
    default:
      return world.robots[target.element.index].dof();
  }
}

std::optional<ParamValue> ParseAccessValue(const AccessTarget& target, std::string_view text,
                                           std::string* error) {
  const std::string rule =
      target.component >= 0 ? "must be one number (a component)" : ParamRule(*target.row);
  const std::string refusal = target.path + ": cannot read '" + Trim(text) + "': " + rule;
  std::optional<ParamValue> value = ParseParamValue(*target.row, text, nullptr);
  if (!value || (target.component >= 0 && value->size() != 1)) {
    FailWith(error, refusal);
    return std::nullopt;
  }
  return value;
}

std::string FormatAccessValue(const AccessTarget& target, const ParamValue& value) {
  return FormatParamValue(*target.row, value);
}

ParamValue SelectComponent(const AccessTarget& target, const ParamValue& whole) {
  if (target.component < 0) return whole;
  return {whole[static_cast<size_t>(target.component)]};
}

ParamValue ReplaceComponent(const AccessTarget& target, ParamValue whole, const ParamValue& value) {
  if (target.component < 0) return value;
  whole[static_cast<size_t>(target.component)] = value.empty() ? 0.0 : value[0];
  return whole;
}

std::optional<std::string> CheckAccessValue(const WorldDesc& world, const AccessTarget& target,
                                            const ParamValue& whole) {
  std::optional<std::string> problem =
      CheckParam(*target.row, whole, AccessValueSize(world, target));
  if (!problem) return std::nullopt;
  const std::string_view key = target.row->key;
  if (problem->compare(0, key.size(), key) == 0) return target.path + problem->substr(key.size());
  return target.path + ": " + *problem;
}

std::optional<ParamValue> GetPath(const WorldDesc& world, const AccessTarget& target,
                                  std::string* error) {
  if (target.state != StateItem::kNone) {
    FailWith(error, target.path + ": exists only on a running simulation");
    return std::nullopt;
  }
  std::optional<ParamValue> whole = GetParam(world, target.element, *target.row, error);
  if (!whole) return std::nullopt;
  return SelectComponent(target, *whole);
}

std::optional<ParamValue> GetPath(const WorldDesc& world, std::string_view path,
                                  std::string* error) {
  std::optional<AccessTarget> target =
      ResolveAccessPath(world, path, AccessContext::kDescription, error);
  if (!target) return std::nullopt;
  return GetPath(world, *target, error);
}

bool SetPath(WorldDesc* world, const AccessTarget& target, const ParamValue& value,
             std::string* error) {
  if (target.read_only) return FailWith(error, target.path + ": read-only");
  if (target.state != StateItem::kNone) {
    return FailWith(error, target.path + ": exists only on a running simulation");
  }
  if (target.component >= 0 && value.size() != 1) {
    return FailWith(
        error, target.path + ": a component takes one number, got " + std::to_string(value.size()));
  }
  std::optional<ParamValue> whole = GetParam(*world, target.element, *target.row, error);
  if (!whole) return false;
  const ParamValue full = ReplaceComponent(target, *whole, value);
  if (auto problem = CheckAccessValue(*world, target, full)) return FailWith(error, *problem);
  return SetParam(world, target.element, *target.row, full, error);
}

bool SetPath(WorldDesc* world, std::string_view path, const ParamValue& value, std::string* error) {
  std::optional<AccessTarget> target =
      ResolveAccessPath(*world, path, AccessContext::kDescription, error);
  return target && SetPath(world, *target, value, error);
}

bool SetPathText(WorldDesc* world, std::string_view path, std::string_view value_text,
                 std::string* error) {
  std::optional<AccessTarget> target =
      ResolveAccessPath(*world, path, AccessContext::kDescription, error);
  if (!target) return false;
  std::optional<ParamValue> value = ParseAccessValue(*target, value_text, error);
  return value && SetPath(world, *target, *value, error);
}

bool SplitAssignment(std::string_view text, std::string* path, std::string* value,
                     std::string* error) {
  const size_t sign = AssignmentSign(text);
  const std::string whole = "'" + std::string(text) + "'";
  if (sign == std::string_view::npos) return FailWith(error, whole + ": expected PATH=VALUE");
  *path = Trim(text.substr(0, sign));
  *value = Trim(text.substr(sign + 1));
  if (path->empty()) return FailWith(error, whole + ": no path before '='");
  if (value->empty()) return FailWith(error, whole + ": no value after '='");
  return true;
}

}  // namespace lamina::core
