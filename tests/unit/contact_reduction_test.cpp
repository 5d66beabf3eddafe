// SPDX-License-Identifier: MIT
// Flat contact patches reduced to their outline's corners: which patches qualify, which corners
// stay (collinear points and small chamfers go), and the weights that keep the patch's total
// pressure weight and its centre of pressure.
#include "core/contact/contact_reduction.h"

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kFloor = 1e-9;
// sums and centres of a few dozen values of order 1: rounding only
constexpr double kRounding = 1e-12;

Contact MakeContact(const Vec3& position, double depth, const Vec3& normal = Vec3::UnitZ()) {
  Contact contact;
  contact.position = position;
  contact.normal = normal;
  contact.depth = depth;
  return contact;
}

// a sole of 0.2 x 0.1 m at height z: a 5 x 4 lattice, depth from `depth(x, y)`
template <typename Depth>
ContactList Sole(Depth depth, double z = 0.0) {
  ContactList contacts;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 5; ++i) {
      const Vec3 p(0.05 * i, 0.1 / 3 * j, z);
      contacts.push_back(MakeContact(p, depth(p.x(), p.y())));
    }
  }
  return contacts;
}

double TotalWeight(const ContactList& contacts) {
  double total = 0.0;
  for (const Contact& c : contacts) total += PressureWeight(c, kFloor);
  return total;
}

Vec3 PressureCentre(const ContactList& contacts) {
  Vec3 centre = Vec3::Zero();
  for (const Contact& c : contacts) centre += PressureWeight(c, kFloor) * c.position;
  return centre / TotalWeight(contacts);
}

TEST(ContactReductionTest, AnEvenSoleKeepsItsFourCornersWithAQuarterEach) {
  ContactList contacts = Sole([](double, double) { return 2e-3; });
  const double total = TotalWeight(contacts);
  ASSERT_TRUE(ReduceFlatPatch(kFloor, &contacts));
  ASSERT_EQ(contacts.size(), 4u);
  // input order: (0,0), (0.2,0), (0,0.1), (0.2,0.1)
  EXPECT_EQ(contacts[0].position, Vec3(0, 0, 0));
  EXPECT_EQ(contacts[1].position, Vec3(0.2, 0, 0));
  EXPECT_NEAR(contacts[2].position.y(), 0.1, kRounding);
  EXPECT_NEAR(contacts[3].position.x(), 0.2, kRounding);
  for (const Contact& c : contacts) {
    EXPECT_NEAR(c.weight, total / 4, total * kRounding);
    EXPECT_EQ(c.depth, 2e-3);
    EXPECT_EQ(c.normal, Vec3::UnitZ());
  }
}

// A sole tilted about y (depth rising with x) and twisted (with y): the corners carry the same
// total weight through the same centre of pressure as the 20 contacts did.
TEST(ContactReductionTest, ATiltedSoleKeepsItsTotalAndItsCentreOfPressure) {
  ContactList contacts = Sole([](double x, double y) { return 1e-3 + 4e-3 * x + 2e-3 * y; }, 0.3);
  const double total = TotalWeight(contacts);
  const Vec3 centre = PressureCentre(contacts);
  ASSERT_TRUE(ReduceFlatPatch(kFloor, &contacts));
  ASSERT_EQ(contacts.size(), 4u);
  EXPECT_NEAR(TotalWeight(contacts), total, total * kRounding);
  EXPECT_LE((PressureCentre(contacts) - centre).norm(), 1e-12);
  // the centre moved towards the deep corner: the corners' shares differ
  EXPECT_GT(contacts[3].weight, contacts[0].weight);
}

TEST(ContactReductionTest, PatchesThatAreNotFlatAreLeftToTheClustering) {
  const auto even = [](double, double) { return 1e-3; };
  ContactList tilted = Sole(even);
  tilted[7].normal = Vec3(std::sin(2e-3), 0, std::cos(2e-3));  // 2 mrad off
  const ContactList tilted_before = tilted;
  EXPECT_FALSE(ReduceFlatPatch(kFloor, &tilted));
  EXPECT_EQ(tilted.size(), tilted_before.size());

  ContactList bumpy = Sole(even);
  bumpy[12].position.z() += 5e-3;  // 5 mm off a 0.22 m patch's plane
  EXPECT_FALSE(ReduceFlatPatch(kFloor, &bumpy));
  EXPECT_EQ(bumpy.size(), 20u);

  ContactList broken = Sole(even);
  broken[3].position.x() = std::nan("");
  EXPECT_FALSE(ReduceFlatPatch(kFloor, &broken));

  const ContactList sole = Sole(even);
  ContactList few(sole.begin(), sole.begin() + 4);
  EXPECT_FALSE(ReduceFlatPatch(kFloor, &few));
}

// An octagonal outline of 0.2 x 0.1 m: dropping one corner of a 2 mm chamfer cuts a sliver of
// 0.5 · 2 mm · 96 mm along the short side (0.48 % of the area), four of them 1.9 %: four corners
// stay. A 30 mm chamfer's sliver is 3 % on its own: all eight corners stay.
TEST(ContactReductionTest, SmallChamfersGoAndLargeOnesStay) {
  for (const auto& [chamfer, corners] : {std::pair{0.002, 4u}, std::pair{0.03, 8u}}) {
    SCOPED_TRACE(chamfer);
    const double a = 0.2, b = 0.1;
    const std::vector<Vec3> outline = {{chamfer, 0, 0},     {a - chamfer, 0, 0}, {a, chamfer, 0},
                                       {a, b - chamfer, 0}, {a - chamfer, b, 0}, {chamfer, b, 0},
                                       {0, b - chamfer, 0}, {0, chamfer, 0}};
    ContactList contacts;
    for (const Vec3& p : outline) contacts.push_back(MakeContact(p, 1e-3));
    contacts.push_back(MakeContact(Vec3(0.1, 0.05, 0), 1e-3));
    ASSERT_TRUE(ReduceFlatPatch(kFloor, &contacts));
    EXPECT_EQ(contacts.size(), corners);
  }
}

// A cylinder lying on a plane touches along a line: its two ends stay, weighted so that the
// centre of pressure stays where it was.
TEST(ContactReductionTest, ALineContactKeepsItsTwoEnds) {
  ContactList contacts;
  for (int i = 0; i < 6; ++i)
    contacts.push_back(MakeContact(Vec3(0.02 * i, 0.1, 0), 1e-3 * (1 + i)));
  const Vec3 centre = PressureCentre(contacts);
  ASSERT_TRUE(ReduceFlatPatch(kFloor, &contacts));
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(contacts[0].position.x(), 0.0);
  EXPECT_NEAR(contacts[1].position.x(), 0.1, kRounding);
  EXPECT_LE((PressureCentre(contacts) - centre).norm(), 1e-12);
}

}  // namespace
}  // namespace lamina::core
