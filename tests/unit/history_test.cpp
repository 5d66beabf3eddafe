// SPDX-License-Identifier: MIT
// History on a document alone: groups (one slider drag is one undo step), coalescing, the redo
// stack, and undo/redo of every kind of edit restoring the description bit for bit.
#include "core/edit/history.h"

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/edit/document.h"
#include "core/edit/edit.h"
#include "core/model/world_compare.h"
#include "tests/common/edit_support.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::ExpectSameWorld;

using core::ElementIndex;
using core::ElementRef;
using core::WorldDocument;

class HistoryTest : public ::testing::Test {
 protected:
  ElementRef Object(int i) const { return *document_.RefOf(ElementIndex::Object(i)); }
  core::ParamEdit Param(const ElementRef& ref, std::string_view key, core::ParamValue value) {
    std::string error;
    const auto edit = core::MakeParamEdit(document_, ref, key, std::move(value), &error);
    EXPECT_TRUE(edit) << error;
    return *edit;
  }
  bool Do(const core::Edit& edit) {
    std::string error;
    const bool ok = history_.Do(&document_, edit, &error);
    EXPECT_TRUE(ok) << error;
    return ok;
  }
  double Friction(int object) const {
    return document_.desc().objects[object].sim.surface.friction;
  }

  WorldDocument document_ = test::ArmAndBlocksDocument();
  core::History history_;
};

TEST_F(HistoryTest, FiftyEditsOfOneRowInAGroupAreOneUndoStep) {
  const core::WorldDesc original = document_.desc();
  const core::Revision revision = document_.revision();
  history_.BeginGroup("drag friction");
  for (int k = 1; k <= 50; ++k) ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.5 + 0.01 * k})));
  history_.EndGroup();
  EXPECT_EQ(history_.undo_count(), 1);
  EXPECT_EQ(history_.UndoLabel(), "drag friction");
  ASSERT_EQ(history_.undo_stack().back().edits.size(), 1u);
  const auto& merged = std::get<core::ParamEdit>(history_.undo_stack().back().edits[0]);
  EXPECT_EQ(merged.before, core::ParamValue{0.5});
  EXPECT_EQ(merged.after, core::ParamValue{0.5 + 0.01 * 50});
  EXPECT_EQ(Friction(0), 0.5 + 0.01 * 50);
  ASSERT_TRUE(history_.Undo(&document_));
  EXPECT_EQ(Friction(0), 0.5);
  EXPECT_EQ(document_.revision(), revision);
  ExpectSameWorld(original, document_.desc());
  EXPECT_FALSE(history_.CanUndo());
  ASSERT_TRUE(history_.Redo(&document_));
  EXPECT_EQ(Friction(0), 0.5 + 0.01 * 50);
}

TEST_F(HistoryTest, OnlyConsecutiveEditsOfTheSameRowCoalesce) {
  const core::WorldDesc original = document_.desc();
  history_.BeginGroup("three rows");
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.6})));
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.7})));
  ASSERT_TRUE(Do(Param(Object(0), "kRestitution", {0.3})));
  ASSERT_TRUE(Do(Param(Object(1), "kFriction", {0.9})));
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.8})));
  history_.EndGroup();
  ASSERT_EQ(history_.undo_count(), 1);
  EXPECT_EQ(history_.undo_stack().back().edits.size(), 4u);  // 0.6 and 0.7 merged
  ASSERT_TRUE(history_.Undo(&document_));
  ExpectSameWorld(original, document_.desc());
  ASSERT_TRUE(history_.Redo(&document_));
  EXPECT_EQ(Friction(0), 0.8);
  EXPECT_EQ(Friction(1), 0.9);
  EXPECT_EQ(document_.desc().objects[0].sim.surface.restitution, 0.3);
}

TEST_F(HistoryTest, WithoutAGroupEveryEditIsItsOwnStep) {
  for (int k = 1; k <= 3; ++k) ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.5 + 0.1 * k})));
  EXPECT_EQ(history_.undo_count(), 3);
  ASSERT_TRUE(history_.Undo(&document_));
  EXPECT_EQ(Friction(0), 0.5 + 0.1 * 2);
}

TEST_F(HistoryTest, GroupsNestAndTheOutermostLabelNamesTheEntry) {
  history_.BeginGroup("outer");
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.6})));
  history_.BeginGroup("inner");
  ASSERT_TRUE(Do(Param(Object(1), "kFriction", {0.6})));
  history_.EndGroup();
  EXPECT_TRUE(history_.in_group());
  ASSERT_TRUE(Do(Param(Object(2), "kFriction", {0.6})));
  history_.EndGroup();
  EXPECT_FALSE(history_.in_group());
  history_.EndGroup();  // unmatched: ignored
  ASSERT_EQ(history_.undo_count(), 1);
  EXPECT_EQ(history_.UndoLabel(), "outer");
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.1})));  // after the group: a new step
  EXPECT_EQ(history_.undo_count(), 2);
  EXPECT_EQ(history_.UndoLabel(), "kFriction of base_block");
}

TEST_F(HistoryTest, EntriesNameElementsAsTheWorldDoes) {
  ASSERT_TRUE(Do(Param(Object(1), "padding", {0.01})));
  EXPECT_EQ(history_.UndoLabel(), "padding of top_block");
  const ElementRef driver = *document_.RefOf(ElementIndex::Driver(0, 0));
  ASSERT_TRUE(Do(Param(driver, "servoP", {20.0})));
  const core::RobotDesc& arm = document_.desc().robots[0];
  EXPECT_EQ(history_.UndoLabel(), "servoP of arm driver '" + arm.drivers[0].name + "'");
  // without a world to name them, elements go by uid
  EXPECT_EQ(core::Describe(Param(Object(1), "padding", {0.02})),
            "padding of object #" + std::to_string(Object(1).uid));
}

TEST_F(HistoryTest, AnEmptyOrRefusedGroupRecordsNothing) {
  history_.BeginGroup("nothing");
  history_.EndGroup();
  history_.BeginGroup("refused");
  std::string error;
  EXPECT_FALSE(history_.Do(&document_, Param(Object(0), "kFriction", {-1.0}), &error));
  EXPECT_EQ(error, "objects[0].kFriction must be >= 0 (inf allowed), got -1");
  history_.EndGroup();
  EXPECT_FALSE(history_.CanUndo());
  EXPECT_FALSE(document_.dirty());
}

TEST_F(HistoryTest, DoClearsTheRedoStack) {
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.6})));
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.7})));
  ASSERT_TRUE(history_.Undo(&document_));
  ASSERT_TRUE(history_.Undo(&document_));
  EXPECT_EQ(history_.redo_count(), 2);
  ASSERT_TRUE(Do(Param(Object(1), "kFriction", {0.1})));
  EXPECT_FALSE(history_.CanRedo());
  std::string error;
  EXPECT_FALSE(history_.Redo(&document_, &error));
  EXPECT_EQ(error, "nothing to redo");
}

TEST_F(HistoryTest, UndoEndsAnOpenGroup) {
  history_.BeginGroup("left open");
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.6})));
  ASSERT_TRUE(history_.Undo(&document_));
  EXPECT_FALSE(history_.in_group());
  EXPECT_EQ(Friction(0), 0.5);
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.7})));
  ASSERT_TRUE(Do(Param(Object(0), "kFriction", {0.8})));
  EXPECT_EQ(history_.undo_count(), 2);  // not coalesced into the closed group
}

TEST_F(HistoryTest, NothingToUndoSaysSo) {
  std::string error;
  EXPECT_FALSE(history_.Undo(&document_, &error));
  EXPECT_EQ(error, "nothing to undo");
}

// ---- every kind of edit --------------------------------------------------------------------

struct EditCase {
  std::string name;
  std::function<core::Edit(const WorldDocument&)> make;
};

core::Pose Moved(const core::Pose& pose) {
  core::Pose moved = pose;
  moved.translation() += core::Vec3(0.1, -0.2, 0.3);
  moved.linear() = Eigen::AngleAxisd(0.3, core::Vec3::UnitZ()).toRotationMatrix();
  return moved;
}

std::vector<EditCase> EveryKindOfEdit() {
  const auto object = [](int i) { return ElementIndex::Object(i); };
  return {
      {"live row",
       [object](auto& d) { return test::ParamEditOf(d, object(0), "kFriction", {0.1}); }},
      {"geometry row",
       [object](auto& d) { return test::ParamEditOf(d, object(1), "padding", {0.01}); }},
      {"simulator row",
       [object](auto& d) { return test::ParamEditOf(d, object(2), "mass", {3.0}); }},
      {"initial row",
       [object](auto& d) {
         return test::ParamEditOf(d, object(2), "transform",
                                  core::PoseToValue(Moved(d.desc().objects[2].pose)));
       }},
      {"driver row",
       [](auto& d) { return test::ParamEditOf(d, ElementIndex::Driver(0, 0), "servoP", {250.0}); }},
      {"settings row",
       [](auto& d) {
         return test::ParamEditOf(d, ElementIndex::Settings(), "gravity", {0, 0, -1.6});
       }},
      {"rename",
       [](auto& d) {
         return *core::MakeRenameEdit(d, core::ElementRef::Robot(d.desc().robots[0].uid), "crane");
       }},
      {"add",
       [](auto& d) {
         core::RigidObjectDesc box = test::BoxObject(0.2, 2.0, core::Vec3(3, 0, 0.5));
         return core::MakeAddObjectEdit(d, box, 1);
       }},
      {"remove", [](auto& d) { return *core::MakeRemoveObjectEdit(d, d.desc().objects[1].uid); }},
      {"move", [](auto& d) { return *core::MakeMoveObjectEdit(d, d.desc().objects[2].uid, 0); }},
      {"initial state",
       [](auto& d) {
         core::InitialState state = core::InitialStateOf(d.desc());
         for (auto& o : state.objects) o.pose = Moved(o.pose);
         for (auto& r : state.robots) r.config.setConstant(0.25);
         return core::MakeInitialStateEdit(d, state);
       }},
  };
}

TEST_F(HistoryTest, UndoAndRedoOfEveryKindOfEditRestoreTheDescriptionBitForBit) {
  for (const EditCase& c : EveryKindOfEdit()) {
    SCOPED_TRACE(c.name);
    const core::WorldDesc before = document_.desc();
    const core::Revision revision = document_.revision();
    ASSERT_TRUE(Do(c.make(document_)));
    EXPECT_FALSE(core::CompareWorlds(before, document_.desc(), 0.0).empty())
        << "the edit changed nothing";
    const core::WorldDesc after = document_.desc();
    ASSERT_TRUE(history_.Undo(&document_));
    ExpectSameWorld(before, document_.desc());
    EXPECT_EQ(document_.revision(), revision);
    ASSERT_TRUE(history_.Redo(&document_));
    ExpectSameWorld(after, document_.desc());
    ASSERT_TRUE(history_.Undo(&document_));
  }
}

TEST(EditTest, InversesSwapAddAndRemoveAndBeforeAndAfter) {
  core::RigidObjectDesc box = test::BoxObject(0.2, 2.0, core::Vec3(3, 0, 0.5));
  box.uid = 42;
  const core::Edit add = core::AddObjectEdit{box, 1};
  const core::Edit remove = core::Inverse(add);
  ASSERT_TRUE(std::holds_alternative<core::RemoveObjectEdit>(remove));
  EXPECT_EQ(std::get<core::RemoveObjectEdit>(remove).index, 1);
  EXPECT_EQ(std::get<core::RemoveObjectEdit>(remove).object.uid, 42u);
  EXPECT_TRUE(std::holds_alternative<core::AddObjectEdit>(core::Inverse(remove)));
  const core::MoveObjectEdit move = core::MoveObjectEdit{7, 0, 2}.Inverse();
  EXPECT_EQ(move.from, 2);
  EXPECT_EQ(move.to, 0);
  EXPECT_TRUE(core::ChangesStructure(add));
  EXPECT_FALSE(core::ChangesStructure(core::ParamEdit{}));
  EXPECT_FALSE(core::ChangesStructure(core::InitialStateEdit{}));
  EXPECT_EQ(core::Describe(add), "add object 'box'");
}

}  // namespace
}  // namespace lamina
