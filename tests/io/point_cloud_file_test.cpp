// SPDX-License-Identifier: MIT
// The `.pcd` reader: ascii and binary data of every SIZE/TYPE, binary_compressed (LZF), colours,
// NaN points, and a file:line error for every malformed input; the LZF decoder on its own; and
// point clouds in worlds (loading, sharing, automass, summaries).
#include "core/io/point_cloud_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/mass_properties.h"
#include "core/io/lzf.h"
#include "core/io/world_file.h"
#include "core/model/world_summary.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Diagnostics;
using core::PointCloud;
using core::Severity;
using core::Vec3;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr const char* kFile = "cloud.pcd";

std::optional<PointCloud> Parse(const std::string& bytes, Diagnostics* diagnostics) {
  return core::ParsePcd(bytes, kFile, *diagnostics);
}

template <typename T>
void Put(std::string* bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // the test machine is little-endian, as PCD data is
  bytes->append(raw, sizeof(T));
}

// a little LZF compressor (greedy, brute-force search) so that tests can write LZF data
std::vector<std::uint8_t> LzfCompress(const std::vector<std::uint8_t>& in) {
  std::vector<std::uint8_t> out, literal;
  const auto flush = [&] {
    for (std::size_t i = 0; i < literal.size(); i += 32) {
      const std::size_t n = std::min<std::size_t>(32, literal.size() - i);
      out.push_back(static_cast<std::uint8_t>(n - 1));
      out.insert(out.end(), literal.begin() + i, literal.begin() + i + n);
    }
    literal.clear();
  };
  for (std::size_t i = 0; i < in.size();) {
    std::size_t best = 0, offset = 0;
    for (std::size_t back = 1; back <= std::min<std::size_t>(i, 8192); ++back) {
      std::size_t n = 0;
      while (i + n < in.size() && n < 264 && in[i + n] == in[i + n - back]) ++n;
      if (n > best) std::tie(best, offset) = std::make_pair(n, back);
    }
    if (best < 3) {
      literal.push_back(in[i++]);
      continue;
    }
    flush();
    const std::size_t length = best - 2, o = offset - 1;
    out.push_back(static_cast<std::uint8_t>((std::min<std::size_t>(length, 7) << 5) | (o >> 8)));
    if (length >= 7) out.push_back(static_cast<std::uint8_t>(length - 7));
    out.push_back(static_cast<std::uint8_t>(o & 0xFF));
    i += best;
  }
  flush();
  return out;
}

// ---- LZF ----

TEST(LzfTest, LiteralsAndAnOverlappingBackReference) {
  // "abc", then 9 bytes copied from 3 back (overlapping what it writes): "abcabcabcabc"
  const std::vector<std::uint8_t> data = {2, 'a', 'b', 'c', 0xE0, 0, 2};
  std::vector<std::uint8_t> out;
  std::string error;
  ASSERT_TRUE(core::LzfDecompress(data.data(), data.size(), 12, &out, &error)) << error;
  EXPECT_EQ(std::string(out.begin(), out.end()), "abcabcabcabc");
}

TEST(LzfTest, RoundTripsWhatTheTestCompressorWrites) {
  std::vector<std::uint8_t> input;
  for (int i = 0; i < 5000; ++i)
    input.push_back(static_cast<std::uint8_t>((i * i / 7) % 13 + i / 600));
  const std::vector<std::uint8_t> packed = LzfCompress(input);
  EXPECT_LT(packed.size(), input.size() / 2);  // the test compressor really made references
  std::vector<std::uint8_t> out;
  std::string error;
  ASSERT_TRUE(core::LzfDecompress(packed.data(), packed.size(), input.size(), &out, &error));
  EXPECT_EQ(out, input);
}

TEST(LzfTest, CorruptDataIsRefusedWithAReason) {
  const struct {
    std::vector<std::uint8_t> data;
    std::size_t size;
    const char* reason;
  } cases[] = {
      {{0x20, 0}, 3, "a back reference points before the start"},
      {{4, 'a', 'b'}, 5, "a literal run passes the end of the data"},
      {{0, 'a', 0xE0}, 20, "a back reference passes the end of the data"},
      {{2, 'a', 'b', 'c'}, 2, "the data decompresses too long"},
      {{0, 'a'}, 2, "decompressed to 1 bytes, expected 2"},
  };
  for (const auto& c : cases) {
    std::vector<std::uint8_t> out;
    std::string error;
    EXPECT_FALSE(core::LzfDecompress(c.data.data(), c.data.size(), c.size, &out, &error));
    EXPECT_EQ(error, c.reason);
  }
}

// ---- ascii ----

TEST(PcdAsciiTest, ReadsV07WithPackedColours) {
  // rgb as PCL >= 1.8 writes it (an integer) and as older PCL did (the float with those bits)
  const float packed = std::bit_cast<float>(std::uint32_t{0x00FF8000});
  char old_style[64];
  std::snprintf(old_style, sizeof(old_style), "%.9g", packed);
  const std::string text = std::string(
                               "# .PCD v0.7 - Point Cloud Data file format\n"
                               "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\n"
                               "COUNT 1 1 1 1\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
                               "POINTS 2\nDATA ascii\n0.5 -1.25 3 4278190335\n1e-3 2 -0.75 ") +
                           old_style + "\n";
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud = Parse(text, &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.entries().size(), 0u) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(0.5, -1.25, 3), Vec3(1e-3, 2, -0.75)));
  // 0xFF0000FF: alpha dropped
  EXPECT_THAT(cloud->colors, ElementsAre(0x0000FFu, 0xFF8000u));
}

TEST(PcdAsciiTest, ReadsTheOldHeaderWithoutVersionCountOrPoints) {
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud =
      Parse("COLUMNS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nDATA ascii\n1 2 3\n\n4 5 6\n7 8 9\n",
            &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(7, 8, 9)));
  EXPECT_FALSE(cloud->has_colors());
}

TEST(PcdAsciiTest, SkipsNanPointsWithANote) {
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud = Parse(
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\nPOINTS 4\nDATA ascii\n"
      "nan nan nan\n1 2 3\n4 NaN 6\n7 8 9\n",
      &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(1, 2, 3), Vec3(7, 8, 9)));
  EXPECT_THAT(diagnostics.Messages(Severity::kNote),
              ElementsAre("cloud.pcd:8: note: skipped 2 of 4 points with NaN or infinite "
                          "coordinates (PCL's \"no return\")"));
}

TEST(PcdAsciiTest, SkipsFieldsWithCountAboveOne) {
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud = Parse(
      "FIELDS normal x y intensity z\nSIZE 4 4 4 2 8\nTYPE F F F U F\nCOUNT 3 1 1 2 1\n"
      "WIDTH 1\nDATA ascii\n9 9 9 1 2 7 7 3\n",
      &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(1, 2, 3)));
}

// ---- binary ----

struct TypeCase {
  const char* type;
  int size;
  double value;  // what x holds
};

class PcdBinaryTypeTest : public ::testing::TestWithParam<TypeCase> {};

void PutTyped(std::string* bytes, const TypeCase& c) {
  const std::string t = c.type;
  if (t == "F") return c.size == 4 ? Put(bytes, float(c.value)) : Put(bytes, c.value);
  const auto i = static_cast<std::int64_t>(c.value);
  if (c.size == 1) return Put(bytes, static_cast<std::int8_t>(i));
  if (c.size == 2) return Put(bytes, static_cast<std::int16_t>(i));
  if (c.size == 4) return Put(bytes, static_cast<std::int32_t>(i));
  Put(bytes, i);
}

// x of every SIZE/TYPE, behind a 3-value field and before an rgba field
TEST_P(PcdBinaryTypeTest, ReadsXOfEveryType) {
  const TypeCase c = GetParam();
  std::string bytes = "VERSION .7\nFIELDS normal x y z rgba\nSIZE 4 " + std::to_string(c.size) +
                      " 4 8 4\nTYPE F " + c.type +
                      " F F U\nCOUNT 3 1 1 1 1\nWIDTH 2\nHEIGHT 1\n"
                      "POINTS 2\nDATA binary\n";
  for (int point = 0; point < 2; ++point) {
    for (int k = 0; k < 3; ++k) Put(&bytes, 99.0f);
    PutTyped(&bytes, c);
    Put(&bytes, 0.25f * point);
    Put(&bytes, -2.5);
    Put(&bytes, std::uint32_t{0x80123456});
  }
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud = Parse(bytes, &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(c.value, 0, -2.5), Vec3(c.value, 0.25, -2.5)));
  EXPECT_THAT(cloud->colors, ElementsAre(0x123456u, 0x123456u));
}

INSTANTIATE_TEST_SUITE_P(Types, PcdBinaryTypeTest,
                         ::testing::Values(TypeCase{"F", 4, 1.5}, TypeCase{"F", 8, -0.1},
                                           TypeCase{"I", 1, -7}, TypeCase{"I", 2, -300},
                                           TypeCase{"I", 4, -70000}, TypeCase{"I", 8, -5e9},
                                           TypeCase{"U", 1, 200}, TypeCase{"U", 2, 65000},
                                           TypeCase{"U", 4, 4e9}, TypeCase{"U", 8, 1e12}));

// x y z rgb (F4, rgb packed) for `points`
std::string BinaryPoints(const std::vector<Vec3>& points, std::uint32_t rgb) {
  std::string bytes;
  for (const Vec3& p : points) {
    for (int k = 0; k < 3; ++k) Put(&bytes, static_cast<float>(p[k]));
    Put(&bytes, std::bit_cast<float>(rgb));
  }
  return bytes;
}

const char* const kXyzRgbHeader =
    "FIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 1\n"
    "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n";

TEST(PcdBinaryTest, SkipsNanPointsAndReadsPackedFloatColours) {
  const std::vector<Vec3> points = {Vec3(1, 2, 3), Vec3(NAN, NAN, NAN), Vec3(-1, 0.5, 0)};
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud =
      Parse(std::string(kXyzRgbHeader) + "DATA binary\n" + BinaryPoints(points, 0x00A0B0C0),
            &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_THAT(cloud->points, ElementsAre(Vec3(1, 2, 3), Vec3(-1, 0.5, 0)));
  EXPECT_THAT(cloud->colors, ElementsAre(0xA0B0C0u, 0xA0B0C0u));
  EXPECT_THAT(diagnostics.Messages(Severity::kNote), ElementsAre(HasSubstr("skipped 1 of 3")));
}

// PCL's binary_compressed: each field of every point in turn, LZF-compressed
std::string CompressedPoints(const std::vector<Vec3>& points, std::uint32_t rgb) {
  std::vector<std::uint8_t> fields_first;
  for (int field = 0; field < 4; ++field) {
    for (const Vec3& p : points) {
      const float value = field < 3 ? static_cast<float>(p[field]) : std::bit_cast<float>(rgb);
      const auto* raw = reinterpret_cast<const std::uint8_t*>(&value);
      fields_first.insert(fields_first.end(), raw, raw + 4);
    }
  }
  const std::vector<std::uint8_t> packed = LzfCompress(fields_first);
  std::string bytes;
  Put(&bytes, static_cast<std::uint32_t>(packed.size()));
  Put(&bytes, static_cast<std::uint32_t>(fields_first.size()));
  return bytes + std::string(packed.begin(), packed.end());
}

TEST(PcdBinaryTest, ReadsBinaryCompressedAsPclWritesIt) {
  const std::vector<Vec3> points = {Vec3(1, 2, 3), Vec3(1, 2, 3.5), Vec3(-4, 0, 0.125)};
  Diagnostics diagnostics;
  const std::optional<PointCloud> cloud = Parse(
      std::string(kXyzRgbHeader) + "DATA binary_compressed\n" + CompressedPoints(points, 0x0A0B0C),
      &diagnostics);
  ASSERT_TRUE(cloud) << diagnostics.FormatAll();
  EXPECT_EQ(cloud->points, points);
  EXPECT_THAT(cloud->colors, ElementsAre(0x0A0B0Cu, 0x0A0B0Cu, 0x0A0B0Cu));
}

// ---- every malformed input: one error naming the file and line ----

struct BadCase {
  const char* name;
  std::string bytes;
  const char* error;
};

class PcdErrorTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(PcdErrorTest, GivesOneErrorAtTheLineAtFault) {
  Diagnostics diagnostics;
  EXPECT_FALSE(Parse(GetParam().bytes, &diagnostics));
  EXPECT_THAT(diagnostics.Messages(Severity::kError), ElementsAre(GetParam().error));
}

const std::string kXyzAscii = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\n";

std::string Truncated() {
  std::string data = BinaryPoints({Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(7, 8, 9)}, 0);
  return std::string(kXyzRgbHeader) + "DATA binary\n" + data.substr(0, data.size() - 6);
}

std::string CorruptCompressed() {
  std::string bytes(kXyzRgbHeader);
  bytes += "DATA binary_compressed\n";
  Put(&bytes, std::uint32_t{3});
  Put(&bytes, std::uint32_t{48});
  return bytes + std::string("\x20\x05\x00", 3);  // a reference before the start
}

std::string CompressedSizeMismatch() {
  std::string bytes(kXyzRgbHeader);
  bytes += "DATA binary_compressed\n";
  Put(&bytes, std::uint32_t{0});
  Put(&bytes, std::uint32_t{40});
  return bytes;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, PcdErrorTest,
    ::testing::Values(
        BadCase{"MissingXAndZ", "VERSION 0.7\nFIELDS a y b\nWIDTH 1\nDATA ascii\n1 2 3\n",
                "cloud.pcd:2: error: FIELDS 'a y b' has no 'x', 'z': a point cloud needs x, y "
                "and z"},
        BadCase{"TruncatedBinary", Truncated(),
                "cloud.pcd:9: error: binary data is truncated: POINTS 3 of 16 bytes need 48 "
                "bytes, the file has 42 after the DATA line"},
        BadCase{"PointsDisagreeWithWidthTimesHeight",
                kXyzAscii + "HEIGHT 2\nPOINTS 5\nDATA ascii\n",
                "cloud.pcd:6: error: POINTS 5 disagrees with WIDTH x HEIGHT = 2 x 2 = 4"},
        BadCase{"BadNumber", kXyzAscii + "DATA ascii\n1 2 3\n4 five 6\n",
                "cloud.pcd:7: error: 'five' is not a number (field 'y')"},
        BadCase{"TrailingGarbage", kXyzAscii + "DATA ascii\n1 2 3x\n4 5 6\n",
                "cloud.pcd:6: error: '3x' is not a number (field 'z')"},
        BadCase{"UnknownType", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nWIDTH 1\nDATA ascii\n1 2 3\n",
                "cloud.pcd:3: error: TYPE of field 'z' must be F, I or U, got 'Q'"},
        BadCase{"FloatOfTwoBytes",
                "FIELDS x y z\nSIZE 4 2 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n1 2 3\n",
                "cloud.pcd:3: error: field 'y' of TYPE F must have SIZE 4 or 8, got 2"},
        BadCase{"SizeOfThreeBytes",
                "FIELDS x y z\nSIZE 4 3 4\nTYPE F U F\nWIDTH 1\nDATA ascii\n1 2 3\n",
                "cloud.pcd:2: error: SIZE of field 'y' must be 1, 2, 4 or 8 bytes, got '3'"},
        BadCase{"SizeListTooShort", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n",
                "cloud.pcd:2: error: SIZE has 2 values for the 3 FIELDS 'x y z'"},
        BadCase{"ValueOutOfRange",
                "FIELDS x y z\nSIZE 1 4 4\nTYPE U F F\nWIDTH 1\nDATA ascii\n300 2 3\n",
                "cloud.pcd:6: error: '300' is not a whole number >= 0 of 1 byte(s) (field 'x')"},
        BadCase{"TooFewValues", kXyzAscii + "DATA ascii\n1 2\n4 5 6\n",
                "cloud.pcd:6: error: expected 3 values a point (FIELDS 'x y z'), got 2"},
        BadCase{"TooFewPoints", kXyzAscii + "DATA ascii\n1 2 3\n",
                "cloud.pcd:6: error: unexpected end of file: POINTS says 2, the data has 1"},
        BadCase{"MissingData", kXyzAscii,
                "cloud.pcd:4: error: missing DATA line: the header never says where the points "
                "are"},
        BadCase{"EmptyFile", "",
                "cloud.pcd:1: error: missing DATA line: the header never says where the points "
                "are"},
        BadCase{"UnknownDataKind", kXyzAscii + "DATA text\n",
                "cloud.pcd:5: error: DATA must be 'ascii', 'binary' or 'binary_compressed', got "
                "'text'"},
        BadCase{"NotAHeaderLine", "FIELDS x y z\n0.5 0.5 0.5\nDATA ascii\n",
                "cloud.pcd:2: error: expected a PCD header line (VERSION, FIELDS, SIZE, TYPE, "
                "COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS or DATA), got '0.5'"},
        BadCase{"NoFields", "WIDTH 1\nDATA ascii\n1 2 3\n",
                "cloud.pcd:2: error: missing FIELDS line: the header does not name the point "
                "fields"},
        BadCase{"NoPointCount", "FIELDS x y z\nDATA ascii\n1 2 3\n",
                "cloud.pcd:2: error: neither POINTS nor WIDTH is given: the number of points is "
                "unknown"},
        BadCase{"NegativeWidth", "FIELDS x y z\nWIDTH -3\nDATA ascii\n",
                "cloud.pcd:2: error: WIDTH must be one whole number >= 0, got '-3'"},
        BadCase{"BadViewpoint", kXyzAscii + "VIEWPOINT 0 0 0 1 0 0\nDATA ascii\n",
                "cloud.pcd:5: error: VIEWPOINT must be 7 finite numbers (tx ty tz qw qx qy qz), "
                "got '0 0 0 1 0 0'"},
        BadCase{"BinaryWithoutSize", "FIELDS x y z\nTYPE F F F\nWIDTH 1\nDATA binary\n",
                "cloud.pcd:4: error: SIZE line missing (binary data needs it)"},
        BadCase{"AllNan", kXyzAscii + "DATA ascii\nnan nan nan\nnan 1 1\n",
                "cloud.pcd:5: error: all 2 points have NaN or infinite coordinates"},
        BadCase{"NoPoints", "FIELDS x y z\nWIDTH 0\nDATA ascii\n",
                "cloud.pcd:3: error: the point cloud has no points"},
        BadCase{"CorruptCompressed", CorruptCompressed(),
                "cloud.pcd:9: error: binary_compressed data is corrupt: a back reference points "
                "before the start"},
        BadCase{"CompressedSizeDisagrees", CompressedSizeMismatch(),
                "cloud.pcd:9: error: binary_compressed data decompresses to 40 bytes, POINTS 3 "
                "of 16 bytes need 48"}),
    [](const ::testing::TestParamInfo<BadCase>& param) { return param.param.name; });

TEST(PcdErrorTest, SeveralHeaderProblemsAreAllReported) {
  Diagnostics diagnostics;
  EXPECT_FALSE(
      Parse("FIELDS x y z\nSIZE 4 4 5\nTYPE F F W\nWIDTH 1\nDATA ascii\n1 2 3\n", &diagnostics));
  EXPECT_EQ(diagnostics.error_count(), 2) << diagnostics.FormatAll();
}

TEST(PcdFileTest, AMissingFileIsReportedWhereItIsNamed) {
  Diagnostics diagnostics;
  EXPECT_FALSE(core::ReadPointCloudFile("/nonexistent/a.pcd", {"world.xml", 7}, diagnostics));
  EXPECT_THAT(diagnostics.Messages(Severity::kError),
              ElementsAre("world.xml:7: error: cannot open point cloud file '/nonexistent/a.pcd'"));
}

// ---- in worlds ----

TEST(PointCloudWorldTest, TheExampleWorldLoadsBothClouds) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/point_clouds.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::GeometryDesc& cube = loaded.world.objects[0].geometry;
  const core::GeometryDesc& ball = loaded.world.objects[1].geometry;
  ASSERT_EQ(cube.kind, core::GeometryKind::kPointCloud);
  ASSERT_EQ(ball.kind, core::GeometryKind::kPointCloud);
  EXPECT_EQ(cube.point_count(), 1016);
  EXPECT_EQ(ball.point_count(), 800);
  EXPECT_TRUE(cube.point_cloud->has_colors());
  EXPECT_EQ(ball.point_cloud->colors.front(), 0x9467BDu);  // the top band, as written
  EXPECT_EQ(cube.point_cloud->Bounds().min(), Vec3::Constant(-0.1));
  EXPECT_EQ(loaded.meshes.point_cloud_count(), 2);
  const std::string summary = core::WorldSummaryText(loaded.world);
  EXPECT_THAT(summary, HasSubstr("object 1 'cube_cloud': mass 1 kg, 1016 points"));
  EXPECT_THAT(core::WorldSummaryJson(loaded.world), HasSubstr("\"points\": 800"));
}

// Klamp't's automass of a point cloud: an equal mass at every point
TEST(PointCloudWorldTest, AutomassPutsAnEqualMassAtEveryPoint) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/point_clouds.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::RigidObjectDesc& cube = loaded.world.objects[0];
  core::Mat3 expected = core::Mat3::Zero();
  for (const Vec3& p : cube.geometry.point_cloud->points) {
    expected += cube.mass / 1016.0 * (p.squaredNorm() * core::Mat3::Identity() - p * p.transpose());
  }
  EXPECT_LT(cube.com.norm(), 1e-15);  // the grid is symmetric about the origin
  EXPECT_TRUE(cube.inertia.isApprox(expected, 1e-12)) << cube.inertia;
  // every axis alike: 0.011181 kg m^2 (sum of y^2 + z^2 over the grid / 1016; a uniform shell
  // would give 5/18 m a^2 = 0.011111, the grid's shared edges weigh a little more)
  EXPECT_NEAR(cube.inertia(0, 0), cube.inertia(2, 2), 1e-15);
  EXPECT_NEAR(cube.inertia(0, 0), 0.0111811, 1e-7);
}

TEST(PointCloudWorldTest, AutomassOfCollinearPointsIsAnError) {
  const std::string dir = test::ScratchDir();
  test::WriteScratchFile("line.pcd", "FIELDS x y z\nWIDTH 3\nDATA ascii\n0 0 0\n1 0 0\n2 0 0\n");
  const std::string world = test::WriteScratchFile(
      "line.xml",
      "<world>\n  <rigidObject name=\"line\">\n    <geometry mesh=\"line.pcd\"/>\n"
      "    <physics mass=\"1\" automass=\"1\"/>\n  </rigidObject>\n</world>\n");
  test::LoadedWorld loaded;
  test::LoadWorld(world, &loaded);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError),
              ElementsAre(HasSubstr("line.xml:4: error: <physics>: automass: cannot compute mass "
                                    "properties from degenerate geometry")));
}

TEST(PointCloudWorldTest, OneFileIsLoadedOnceAndAPcdAloneIsATerrain) {
  const std::string cloud = test::WorldsPath("examples/point_clouds/ball_binary.pcd");
  const std::string world = test::WriteScratchFile(
      "twice.xml", "<world>\n  <rigidObject name=\"a\"><geometry mesh=\"" + cloud +
                       "\"/><physics mass=\"1\" automass=\"1\"/></rigidObject>\n"
                       "  <rigidObject name=\"b\"><geometry mesh=\"" +
                       cloud +
                       "\" scale=\"2\"/><physics mass=\"1\" automass=\"1\"/></rigidObject>\n"
                       "</world>\n");
  test::LoadedWorld loaded;
  test::LoadWorld(world, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.world.objects[0].geometry.point_cloud,
            loaded.world.objects[1].geometry.point_cloud);
  // scaled by 2: the inertia of the same masses at twice the distance, 4 times larger
  EXPECT_TRUE(
      loaded.world.objects[1].inertia.isApprox(4.0 * loaded.world.objects[0].inertia, 1e-12));
  test::LoadedWorld alone;
  test::LoadWorld(cloud, &alone);
  ASSERT_TRUE(alone.ok) << alone.diagnostics.FormatAll();
  ASSERT_EQ(alone.world.terrains.size(), 1u);
  EXPECT_EQ(alone.world.terrains[0].geometry.point_count(), 800);
}

TEST(PointCloudWorldTest, ABadCloudIsReportedAtItsLineAndTheWorldFails) {
  test::WriteScratchFile("bad.pcd",
                         "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nDATA ascii\n1 2\n");
  const std::string world =
      test::WriteScratchFile("bad.xml", "<world>\n  <terrain file=\"bad.pcd\"/>\n</world>\n");
  test::LoadedWorld loaded;
  test::LoadWorld(world, &loaded);
  EXPECT_FALSE(loaded.ok);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError),
              ::testing::Contains(HasSubstr("bad.pcd:6: error: expected 3 values a point")));
}

}  // namespace
}  // namespace lamina
