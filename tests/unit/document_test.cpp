// SPDX-License-Identifier: MIT
// WorldDocument: uids, stable references through rename, reorder, add and remove, revisions and
// dirty through edits, undo, redo and saving, loading, and edits that are refused.
#include "core/edit/document.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/edit/edit.h"
#include "core/edit/history.h"
#include "core/model/world_compare.h"
#include "tests/common/edit_support.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::ElementIndex;
using core::ElementKind;
using core::ElementRef;
using core::WorldDocument;

// a ground and boxes "a", "b", "c" at x = 0, 1, 2
core::WorldDesc BoxesWorld() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.1));
  for (const char* name : {"a", "b", "c"}) {
    core::RigidObjectDesc box =
        test::BoxObject(0.1, 1.0, core::Vec3(static_cast<double>(world.objects.size()), 0.0, 0.05));
    box.name = name;
    world.objects.push_back(box);
  }
  return world;
}

std::string FixturePath() {
  return test::DataPath("edit/arm_and_blocks.xml");
}

// the name of the object `ref` resolves to, or "" when it does not resolve
std::string NameOf(const WorldDocument& document, const ElementRef& ref) {
  const auto index = document.Resolve(ref);
  return index ? document.desc().objects[index->index].name : "";
}

bool Do(WorldDocument* document, const core::Edit& edit) {
  std::string error;
  const bool ok = core::Apply(edit, document, &error);
  EXPECT_TRUE(ok) << error;
  return ok;
}

TEST(DocumentTest, ConstructionGivesEveryElementAUidUniqueInTheDocument) {
  core::WorldDesc world = BoxesWorld();
  world.objects[1].uid = 777;
  world.objects[2].uid = 777;  // a copy: must get its own
  const WorldDocument document(world);
  std::set<core::ElementUid> uids;
  for (const auto& terrain : document.desc().terrains) uids.insert(terrain.uid);
  for (const auto& object : document.desc().objects) uids.insert(object.uid);
  EXPECT_EQ(uids.size(), 4u);
  EXPECT_EQ(uids.count(0), 0u);
  EXPECT_EQ(document.desc().objects[1].uid, 777u);
  EXPECT_NE(document.desc().objects[2].uid, 777u);
  // a second document of the same world gets uids no element had
  const WorldDocument other(BoxesWorld());
  for (const auto& object : other.desc().objects) EXPECT_EQ(uids.count(object.uid), 0u);
}

TEST(DocumentTest, ANewDocumentIsCleanAndHasNoFile) {
  const WorldDocument document(BoxesWorld());
  EXPECT_FALSE(document.dirty());
  EXPECT_EQ(document.revision(), document.saved_revision());
  EXPECT_EQ(document.path(), "");
  EXPECT_TRUE(core::CompareWorlds(document.desc(), BoxesWorld(), 0.0).empty());
}

TEST(DocumentTest, RefsSurviveRenameReorderAddAndRemove) {
  WorldDocument document(BoxesWorld());
  const ElementRef c = *document.RefOf(ElementIndex::Object(2));
  const ElementRef b = *document.RefOf(ElementIndex::Object(1));
  ASSERT_EQ(NameOf(document, c), "c");

  ASSERT_TRUE(Do(&document, *core::MakeRenameEdit(document, c, "crate")));
  EXPECT_EQ(NameOf(document, c), "crate");
  ASSERT_TRUE(Do(&document, *core::MakeMoveObjectEdit(document, c.uid, 0)));
  EXPECT_EQ(document.Resolve(c)->index, 0);
  EXPECT_EQ(NameOf(document, b), "b");
  EXPECT_EQ(document.Resolve(b)->index, 2);  // a moved up behind c

  core::RigidObjectDesc added = test::BoxObject(0.2, 2.0, core::Vec3(5, 0, 0.1));
  added.name = "new";
  ASSERT_TRUE(Do(&document, core::MakeAddObjectEdit(document, added, 0)));
  EXPECT_EQ(document.Resolve(c)->index, 1);
  EXPECT_EQ(NameOf(document, c), "crate");

  ASSERT_TRUE(Do(&document, *core::MakeRemoveObjectEdit(document, b.uid)));
  EXPECT_EQ(NameOf(document, c), "crate");
  std::string error;
  EXPECT_FALSE(document.Resolve(b, &error));
  EXPECT_EQ(error, "object #" + std::to_string(b.uid) + " is not in the world (removed)");
}

TEST(DocumentTest, ResolveAndRefOfRoundTripEveryElementOfALoadedWorld) {
  const WorldDocument document = test::ArmAndBlocksDocument();
  const core::WorldDesc& world = document.desc();
  ASSERT_EQ(world.robots.size(), 1u);
  std::vector<ElementIndex> elements = {ElementIndex::Settings(), ElementIndex::Terrain(0),
                                        ElementIndex::Robot(0)};
  for (int i = 0; i < 3; ++i) elements.push_back(ElementIndex::Object(i));
  for (int l = 0; l < world.robots[0].dof(); ++l) elements.push_back(ElementIndex::Link(0, l));
  for (int d = 0; d < static_cast<int>(world.robots[0].drivers.size()); ++d) {
    elements.push_back(ElementIndex::Driver(0, d));
  }
  for (const ElementIndex& element : elements) {
    SCOPED_TRACE(core::ElementPath(element));
    const auto ref = document.RefOf(element);
    ASSERT_TRUE(ref);
    EXPECT_EQ(ref->kind, element.kind);
    EXPECT_EQ(document.Resolve(*ref), element);
  }
}

TEST(DocumentTest, RefsToMissingElementsFailWithAMessage) {
  const WorldDocument document = test::ArmAndBlocksDocument();
  const core::RobotDesc& robot = document.desc().robots[0];
  std::string error;
  EXPECT_FALSE(document.Resolve(ElementRef::Link(robot.uid, 99), &error));
  EXPECT_EQ(error, "robot #" + std::to_string(robot.uid) +
                       " link 99: robots[0].links[99]: robot '" + robot.name + "' has " +
                       std::to_string(robot.dof()) + " links");
  EXPECT_FALSE(document.Resolve(ElementRef::Terrain(robot.uid), &error));  // a robot's uid
  EXPECT_EQ(error, "terrain #" + std::to_string(robot.uid) + " is not in the world (removed)");
  EXPECT_FALSE(document.RefOf(ElementIndex::Object(3), &error));
  EXPECT_EQ(error, "objects[3]: the world has 3 objects");
}

TEST(DocumentTest, RevisionNamesTheContentThroughUndoRedoAndSave) {
  WorldDocument document = test::ArmAndBlocksDocument();
  EXPECT_FALSE(document.dirty());
  EXPECT_EQ(document.path(), FixturePath());
  const core::Revision loaded = document.revision();
  core::History history;
  const ElementRef block = *document.RefOf(ElementIndex::Object(0));

  ASSERT_TRUE(history.Do(&document, *core::MakeParamEdit(document, block, "kFriction", {0.9})));
  const core::Revision edited = document.revision();
  EXPECT_NE(edited, loaded);
  EXPECT_TRUE(document.dirty());
  ASSERT_TRUE(history.Undo(&document));
  EXPECT_EQ(document.revision(), loaded);
  EXPECT_FALSE(document.dirty());  // back at the loaded content
  ASSERT_TRUE(history.Redo(&document));
  EXPECT_EQ(document.revision(), edited);
  EXPECT_TRUE(document.dirty());

  core::Diagnostics diagnostics;
  const std::string saved = test::ScratchDir() + "/saved.xml";
  ASSERT_TRUE(document.SaveAs(saved, diagnostics)) << diagnostics.FormatAll();
  EXPECT_FALSE(document.dirty());
  EXPECT_EQ(document.path(), saved);
  EXPECT_EQ(document.saved_revision(), edited);
  ASSERT_TRUE(history.Undo(&document));
  EXPECT_TRUE(document.dirty());  // the loaded content is not what was saved
  ASSERT_TRUE(history.Redo(&document));
  EXPECT_FALSE(document.dirty());
  ASSERT_TRUE(history.Do(&document, *core::MakeParamEdit(document, block, "kFriction", {0.3})));
  EXPECT_TRUE(document.dirty());
  ASSERT_TRUE(document.Save(diagnostics)) << diagnostics.FormatAll();
  EXPECT_FALSE(document.dirty());
}

TEST(DocumentTest, ASavedDocumentLoadsBackEqual) {
  WorldDocument document = test::ArmAndBlocksDocument();
  const ElementRef block = *document.RefOf(ElementIndex::Object(2));
  ASSERT_TRUE(Do(&document, *core::MakeParamEdit(document, block, "kRestitution", {0.75})));
  ASSERT_TRUE(Do(&document, *core::MakeRenameEdit(document, block, "moved block")));
  core::Diagnostics diagnostics;
  ASSERT_TRUE(document.SaveAs(test::ScratchDir() + "/saved.xml", diagnostics))
      << diagnostics.FormatAll();
  WorldDocument loaded;
  ASSERT_TRUE(loaded.Load(document.path(), diagnostics)) << diagnostics.FormatAll();
  const std::vector<std::string> differences =
      core::CompareWorlds(document.desc(), loaded.desc(), 0.0);
  EXPECT_TRUE(differences.empty()) << differences.front();
  EXPECT_EQ(loaded.desc().objects[2].name, "moved block");
  EXPECT_EQ(loaded.desc().objects[2].sim.surface.restitution, 0.75);
}

TEST(DocumentTest, AFailedSaveKeepsTheDocumentDirtyAndSaysWhy) {
  WorldDocument document = test::ArmAndBlocksDocument();
  const ElementRef block = *document.RefOf(ElementIndex::Object(0));
  ASSERT_TRUE(Do(&document, *core::MakeParamEdit(document, block, "kFriction", {0.9})));
  core::Diagnostics diagnostics;
  const std::string missing = test::ScratchDir() + "/no/such/dir/world.xml";
  EXPECT_FALSE(document.SaveAs(missing, diagnostics));
  EXPECT_TRUE(document.dirty());
  EXPECT_EQ(document.path(), FixturePath());
  ASSERT_EQ(diagnostics.error_count(), 1);
  EXPECT_NE(diagnostics.entries()[0].message.find("does not exist"), std::string::npos)
      << diagnostics.FormatAll();

  WorldDocument unnamed(BoxesWorld());
  core::Diagnostics unnamed_diagnostics;
  EXPECT_FALSE(unnamed.Save(unnamed_diagnostics));
  EXPECT_EQ(unnamed_diagnostics.error_count(), 1);
}

TEST(DocumentTest, AFailedLoadLeavesTheDocumentAsItWas) {
  WorldDocument document(BoxesWorld());
  const core::Revision revision = document.revision();
  core::Diagnostics diagnostics;
  EXPECT_FALSE(document.Load(test::DataPath("edit/no_such_world.xml"), diagnostics));
  EXPECT_TRUE(diagnostics.HasErrors());
  EXPECT_EQ(document.revision(), revision);
  EXPECT_TRUE(core::CompareWorlds(document.desc(), BoxesWorld(), 0.0).empty());
}

// ---- refused edits change nothing ------------------------------------------------------------

class RefusedEditTest : public ::testing::Test {
 protected:
  void ExpectRefused(const core::Edit& edit, const std::string& message) {
    const core::WorldDesc before = document_.desc();
    const core::Revision revision = document_.revision();
    std::string error;
    EXPECT_FALSE(core::Apply(edit, &document_, &error));
    EXPECT_EQ(error, message);
    EXPECT_EQ(document_.revision(), revision);
    EXPECT_TRUE(core::CompareWorlds(before, document_.desc(), 0.0).empty());
  }
  ElementRef Object(int i) const { return *document_.RefOf(ElementIndex::Object(i)); }

  WorldDocument document_{BoxesWorld()};
};

TEST_F(RefusedEditTest, AValueTheTableRefusesNamesThePathAndTheRule) {
  ExpectRefused(*core::MakeParamEdit(document_, Object(1), "kRestitution", {1.5}),
                "objects[1].kRestitution must be in [0, 1], got 1.5");
  ExpectRefused(*core::MakeParamEdit(document_, Object(1), "transform", {1, 0, 0}),
                "objects[1].transform must be 12 finite numbers: a rotation (column-major) and a "
                "translation, got 1,0,0 (3 numbers, needs 12)");
}

TEST_F(RefusedEditTest, AStaleBeforeIsRefused) {
  core::ParamEdit edit = *core::MakeParamEdit(document_, Object(0), "kFriction", {0.7});
  edit.before = {0.25};
  ExpectRefused(edit, "objects[0].kFriction: the edit expects 0.25 but the document holds 0.5");
  core::RenameEdit rename = *core::MakeRenameEdit(document_, Object(0), "x");
  rename.before = "z";
  ExpectRefused(rename, "objects[0].name: the edit expects 'z' but the document holds 'a'");
}

TEST_F(RefusedEditTest, EditsOfRemovedElementsAreRefused) {
  const core::ParamEdit edit = *core::MakeParamEdit(document_, Object(2), "kFriction", {0.7});
  ASSERT_TRUE(Do(&document_, *core::MakeRemoveObjectEdit(document_, Object(2).uid)));
  ExpectRefused(edit,
                "object #" + std::to_string(edit.element.uid) + " is not in the world (removed)");
}

TEST_F(RefusedEditTest, StructuralEditsCheckUidsIndicesAndContent) {
  core::RigidObjectDesc copy = document_.desc().objects[0];
  ExpectRefused(core::AddObjectEdit{copy, 0},
                "add object 'a': uid " + std::to_string(copy.uid) + " is already in the world");
  copy.uid = 0;
  ExpectRefused(core::AddObjectEdit{copy, 0}, "add object 'a': no uid");
  ExpectRefused(core::MakeAddObjectEdit(document_, copy, 4),
                "add object 'a': index 4 is not in [0, 3]");
  core::RemoveObjectEdit remove = *core::MakeRemoveObjectEdit(document_, Object(1).uid);
  remove.object.mass = 5.0;
  ExpectRefused(remove,
                "objects[1]: the edit's copy of the object differs from the document's "
                "(objects[0].mass: 1 vs 5)");
  remove.index = 0;
  ExpectRefused(remove, "objects[0] is not object #" + std::to_string(Object(1).uid) + " (it is #" +
                            std::to_string(Object(0).uid) + ")");
  ExpectRefused(*core::MakeMoveObjectEdit(document_, Object(1).uid, 3),
                "move object #" + std::to_string(Object(1).uid) + ": index 3 is not in [0, 2]");
  ExpectRefused(core::RenameEdit{ElementRef::Settings(), "", "x"},
                "settings: only terrains, objects and robots have names");
}

TEST_F(RefusedEditTest, AnInitialStateMustBeRigidAndFinite) {
  core::InitialState after = core::InitialStateOf(document_.desc());
  after.objects[1].pose.linear() *= 2.0;
  ExpectRefused(core::MakeInitialStateEdit(document_, after),
                "objects[1].transform must be 12 finite numbers: a rotation (column-major) and a "
                "translation, got 2,0,0,0,2,0,0,0,2,1,0,0.05");
  after = core::InitialStateOf(document_.desc());
  after.objects[2].velocity.linear.x() = std::nan("");
  ExpectRefused(core::MakeInitialStateEdit(document_, after),
                "objects[2].velocity must be 6 finite numbers: angular, then linear velocity, got "
                "0,0,0,nan,0,0");
}

}  // namespace
}  // namespace lamina
