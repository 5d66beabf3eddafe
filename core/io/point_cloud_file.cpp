// SPDX-License-Identifier: MIT
// The `.pcd` reader: the header line by line, then the points as ascii lines or binary records.
#include "core/io/point_cloud_file.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "core/io/lzf.h"
#include "core/io/paths.h"
#include "core/number_text.h"

namespace lamina::core {

namespace {

struct PcdField {
  std::string name;
  int size = 4;     // bytes of one value
  char type = 'F';  // F, I or U
  int count = 1;    // values
  int offset = 0;   // bytes from the start of a binary point
  int column = 0;   // index of the first value on an ascii line
};

// The x, y, z and colour fields (indices into the fields; colour -1 when absent).
struct KeptFields {
  std::array<int, 3> xyz = {-1, -1, -1};
  int color = -1;
};

std::string Upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string Joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

// The whitespace-separated words of `line` before any '#'.
std::vector<std::string> LineWords(std::string_view line) {
  line = line.substr(0, std::min(line.find('#'), line.size()));
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t start = line.find_first_not_of(" \t\r\v\f", i);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r\v\f", start), line.size());
    words.emplace_back(line.substr(start, end - start));
    i = end;
  }
  return words;
}

template <typename Integer>
bool ParseWhole(const std::string& text, Integer* value) {
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, *value);
  return error == std::errc() && stop == end && !text.empty();
}

// `size` bytes at p as a little-endian unsigned number
std::uint64_t LittleEndian(const std::uint8_t* p, int size) {
  std::uint64_t value = 0;
  for (int i = size - 1; i >= 0; --i) value = (value << 8) | p[i];
  return value;
}

double BinaryScalar(const std::uint8_t* p, const PcdField& field) {
  const std::uint64_t bits = LittleEndian(p, field.size);
  if (field.type == 'F') {
    return field.size == 4 ? double(std::bit_cast<float>(static_cast<std::uint32_t>(bits)))
                           : std::bit_cast<double>(bits);
  }
  if (field.type == 'U') return static_cast<double>(bits);
  const int unused = 64 - 8 * field.size;  // sign-extend from the field's top bit
  return static_cast<double>(static_cast<std::int64_t>(bits << unused) >> unused);
}

bool IsNan(const std::string& text) {
  const std::string lower = ToLower(text);
  return lower == "nan" || lower == "-nan" || lower == "+nan";
}

// An ascii value of `field` as a double, checked against the field's TYPE and SIZE.
bool AsciiScalar(const std::string& text, const PcdField& field, double* value) {
  if (field.type == 'F') {
    if (IsNan(text)) *value = std::numeric_limits<double>::quiet_NaN();
    return IsNan(text) || ParseDouble(text, value);
  }
  const int bits = 8 * field.size;
  if (field.type == 'U') {
    std::uint64_t u = 0;
    const bool ok = ParseWhole(text, &u) && (bits == 64 || u < (std::uint64_t{1} << bits));
    *value = static_cast<double>(u);
    return ok;
  }
  std::int64_t i = 0;
  const std::int64_t limit = bits == 64 ? 0 : (std::int64_t{1} << (bits - 1));
  const bool ok = ParseWhole(text, &i) && (bits == 64 || (i >= -limit && i < limit));
  *value = static_cast<double>(i);
  return ok;
}

// An ascii colour: an integer as it is (PCL >= 1.8 writes a float rgb so), or a float's bits.
bool AsciiColor(const std::string& text, const PcdField& field, std::uint32_t* color) {
  if (ParseWhole(text, color)) return true;
  std::int32_t negative = 0;
  if (field.type == 'I' && ParseWhole(text, &negative)) {
    *color = static_cast<std::uint32_t>(negative);
    return true;
  }
  double value = 0.0;
  if (field.type != 'F' || !AsciiScalar(text, field, &value)) return false;
  *color = std::bit_cast<std::uint32_t>(static_cast<float>(value));
  return true;
}

class PcdReader {
 public:
  PcdReader(const std::string& bytes, const std::string& file, Diagnostics& diagnostics)
      : bytes_(bytes), file_(file), diagnostics_(diagnostics) {}

  std::optional<PointCloud> Read() {
    if (!ReadHeader() || !AssembleFields() || !FindKeptFields() || !CheckPointCount()) {
      return std::nullopt;
    }
    if (!ReadData()) return std::nullopt;
    return Finish();
  }

 private:
  void Error(int line, std::string message) {
    diagnostics_.Error({file_, line}, std::move(message));
    ok_ = false;
  }

  // The words of the next line; advances past it.
  std::vector<std::string> NextLine() {
    const std::size_t end = std::min(bytes_.find('\n', next_), bytes_.size());
    const std::string_view line(bytes_.data() + next_, end - next_);
    next_ = std::min(end + 1, bytes_.size());
    ++line_;
    return LineWords(line);
  }

  // ---- header ----

  bool ReadHeader() {
    while (next_ < bytes_.size() && data_line_ == 0) {
      const std::vector<std::string> words = NextLine();
      if (words.empty()) continue;
      if (!HeaderLine(Upper(words[0]), std::vector<std::string>(words.begin() + 1, words.end()))) {
        return false;
      }
    }
    if (data_line_ == 0) {
      Error(std::max(line_, 1), "missing DATA line: the header never says where the points are");
    }
    return ok_;
  }

  // false stops the header: the line is not a header line at all
  bool HeaderLine(const std::string& key, const std::vector<std::string>& values) {
    if (key == "VERSION") return true;  // 0.5 to 0.7 read alike
    if (key == "FIELDS" || key == "COLUMNS") return Keep(values, &names_, &fields_line_);
    if (key == "SIZE") return Keep(values, &sizes_, &size_line_);
    if (key == "TYPE") return Keep(values, &types_, &type_line_);
    if (key == "COUNT") return Keep(values, &counts_, &count_line_);
    if (key == "WIDTH") return ReadCount(key, values, &width_, &width_line_);
    if (key == "HEIGHT") return ReadCount(key, values, &height_, &height_line_);
    if (key == "POINTS") return ReadCount(key, values, &points_, &points_line_);
    if (key == "VIEWPOINT") return ReadViewpoint(values);
    if (key == "DATA") return ReadDataKind(values);
    Error(line_,
          "expected a PCD header line (VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, "
          "VIEWPOINT, POINTS or DATA), got '" +
              key + "'");
    return false;
  }

  bool Keep(const std::vector<std::string>& values, std::vector<std::string>* list, int* line) {
    if (*line != 0)
      diagnostics_.Warning({file_, line_},
                           "repeated header line replaces line " + std::to_string(*line));
    *list = values;
    *line = line_;
    return true;
  }

  bool ReadCount(const std::string& key, const std::vector<std::string>& values, long long* count,
                 int* line) {
    *line = line_;
    if (values.size() != 1 || !ParseWhole(values[0], count) || *count < 0) {
      Error(line_, key + " must be one whole number >= 0, got '" + Joined(values) + "'");
    }
    return true;
  }

  bool ReadViewpoint(const std::vector<std::string>& values) {
    double value = 0.0;
    const bool numbers = std::all_of(values.begin(), values.end(), [&](const std::string& v) {
      return ParseDouble(v, &value) && std::isfinite(value);
    });
    if (values.size() != 7 || !numbers) {
      Error(line_, "VIEWPOINT must be 7 finite numbers (tx ty tz qw qx qy qz), got '" +
                       Joined(values) + "'");
    }
    return true;
  }

  bool ReadDataKind(const std::vector<std::string>& values) {
    data_line_ = line_;
    data_offset_ = next_;
    data_kind_ = values.size() == 1 ? ToLower(values[0]) : "";
    if (data_kind_ != "ascii" && data_kind_ != "binary" && data_kind_ != "binary_compressed") {
      Error(line_,
            "DATA must be 'ascii', 'binary' or 'binary_compressed', got '" + Joined(values) + "'");
    }
    return true;
  }

  // ---- fields ----

  bool AssembleFields() {
    if (names_.empty()) {
      Error(data_line_, "missing FIELDS line: the header does not name the point fields");
      return false;
    }
    fields_.resize(names_.size());
    for (std::size_t i = 0; i < names_.size(); ++i) fields_[i].name = names_[i];
    const bool ascii = data_kind_ == "ascii";
    if (CheckListLength(sizes_, size_line_, "SIZE", ascii)) ReadSizes();
    if (CheckListLength(types_, type_line_, "TYPE", ascii)) ReadTypes();
    if (CheckListLength(counts_, count_line_, "COUNT", true)) ReadCounts();
    if (ok_) CheckTypeSizes();
    if (ok_) LayOutFields();
    return ok_;
  }

  // true when `list` has one value per field; a missing optional list is left at its default
  bool CheckListLength(const std::vector<std::string>& list, int line, const char* key,
                       bool optional) {
    if (line == 0) {
      if (!optional) Error(data_line_, std::string(key) + " line missing (binary data needs it)");
      return false;
    }
    if (list.size() == names_.size()) return true;
    Error(line, std::string(key) + " has " + std::to_string(list.size()) + " values for the " +
                    std::to_string(names_.size()) + " FIELDS '" + Joined(names_) + "'");
    return false;
  }

  void ReadSizes() {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      const int size = ParseWhole(sizes_[i], &fields_[i].size) ? fields_[i].size : 0;
      if (size != 1 && size != 2 && size != 4 && size != 8) {
        Error(size_line_, "SIZE of field '" + names_[i] + "' must be 1, 2, 4 or 8 bytes, got '" +
                              sizes_[i] + "'");
      }
    }
  }

  void ReadTypes() {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      const std::string type = Upper(types_[i]);
      if (type != "F" && type != "I" && type != "U") {
        Error(type_line_,
              "TYPE of field '" + names_[i] + "' must be F, I or U, got '" + types_[i] + "'");
      }
      fields_[i].type = type.empty() ? 'F' : type[0];
    }
  }

  void ReadCounts() {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      if (!ParseWhole(counts_[i], &fields_[i].count) || fields_[i].count < 1) {
        Error(count_line_, "COUNT of field '" + names_[i] + "' must be a whole number >= 1, got '" +
                               counts_[i] + "'");
      }
    }
  }

  void CheckTypeSizes() {
    for (const PcdField& field : fields_) {
      if (field.type == 'F' && field.size != 4 && field.size != 8) {
        Error(type_line_ != 0 ? type_line_ : size_line_,
              "field '" + field.name + "' of TYPE F must have SIZE 4 or 8, got " +
                  std::to_string(field.size));
      }
    }
  }

  void LayOutFields() {
    for (PcdField& field : fields_) {
      field.offset = point_bytes_;
      field.column = point_values_;
      point_bytes_ += field.size * field.count;
      point_values_ += field.count;
    }
  }

  int FieldIndex(const std::string& name) const {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      if (ToLower(fields_[i].name) == name) return static_cast<int>(i);
    }
    return -1;
  }

  bool FindKeptFields() {
    std::string missing;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string name(1, "xyz"[axis]);
      kept_.xyz[axis] = FieldIndex(name);
      if (kept_.xyz[axis] < 0) missing += (missing.empty() ? "'" : ", '") + name + "'";
    }
    if (!missing.empty()) {
      Error(fields_line_, "FIELDS '" + Joined(names_) + "' has no " + missing +
                              ": a point cloud needs x, y and z");
      return false;
    }
    FindColorField();
    if (FieldIndex("radius") >= 0) {
      diagnostics_.Note({file_, fields_line_},
                        "field 'radius' ignored: in contact every point is a ball of its body's "
                        "padding");
    }
    return true;
  }

  void FindColorField() {
    kept_.color = FieldIndex("rgb") >= 0 ? FieldIndex("rgb") : FieldIndex("rgba");
    if (kept_.color < 0 || fields_[kept_.color].size == 4) return;
    diagnostics_.Warning({file_, size_line_}, "colour field '" + fields_[kept_.color].name +
                                                  "' has SIZE " +
                                                  std::to_string(fields_[kept_.color].size) +
                                                  ", not a packed 4-byte colour; colours ignored");
    kept_.color = -1;
  }

  bool CheckPointCount() {
    if (points_line_ == 0 && width_line_ == 0) {
      Error(data_line_, "neither POINTS nor WIDTH is given: the number of points is unknown");
      return false;
    }
    if (width_line_ == 0) return true;  // POINTS alone: an unorganized cloud
    const bool overflow = height_ > 0 && width_ > std::numeric_limits<long long>::max() / height_;
    const long long product = overflow ? -1 : width_ * height_;
    if (points_line_ == 0) points_ = product;
    if (!overflow && points_ == product) return true;
    Error(points_line_ != 0 ? points_line_ : width_line_,
          "POINTS " + std::to_string(points_) + " disagrees with WIDTH x HEIGHT = " +
              std::to_string(width_) + " x " + std::to_string(height_) +
              (overflow ? " (too large)" : " = " + std::to_string(product)));
    return false;
  }

  // ---- data ----

  bool ReadData() {
    if (data_kind_ == "ascii") return ReadAscii();
    const std::size_t available = bytes_.size() - data_offset_;
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes_.data()) + data_offset_;
    if (data_kind_ == "binary") return ReadBinary(data, available);
    return ReadCompressed(data, available);
  }

  bool ReadAscii() {
    long long read = 0;
    cloud_.points.reserve(static_cast<std::size_t>(std::min<long long>(points_, 1 << 20)));
    while (read < points_ && next_ < bytes_.size()) {
      const std::vector<std::string> words = NextLine();
      if (words.empty()) continue;
      AddAsciiPoint(words);
      ++read;
    }
    if (read < points_) {
      Error(line_, "unexpected end of file: POINTS says " + std::to_string(points_) +
                       ", the data has " + std::to_string(read));
    }
    WarnExtraLines();
    return ok_;
  }

  void WarnExtraLines() {
    int extra = 0;
    const int first = line_ + 1;
    while (next_ < bytes_.size()) extra += NextLine().empty() ? 0 : 1;
    if (extra > 0) {
      diagnostics_.Warning({file_, first}, "ignoring " + std::to_string(extra) +
                                               " line(s) after the last of the POINTS");
    }
  }

  void AddAsciiPoint(const std::vector<std::string>& words) {
    if (words.size() != static_cast<std::size_t>(point_values_)) {
      Error(line_, "expected " + std::to_string(point_values_) + " values a point (FIELDS '" +
                       Joined(names_) + "'), got " + std::to_string(words.size()));
      return;
    }
    Vec3 p = Vec3::Zero();
    std::uint32_t color = 0;
    bool good = true;
    for (int f = 0; f < static_cast<int>(fields_.size()); ++f) {
      good = AsciiField(words, f, &p, &color) && good;
    }
    if (good) AddPoint(p, color);
  }

  // checks every value of field f on the line; keeps x, y, z and the colour
  bool AsciiField(const std::vector<std::string>& words, int f, Vec3* p, std::uint32_t* color) {
    bool good = true;
    for (int k = 0; k < fields_[f].count; ++k) {
      good = AsciiValue(words[fields_[f].column + k], f, k, p, color) && good;
    }
    return good;
  }

  // value k of field f, checked against the field's TYPE and SIZE; kept if x, y, z or colour
  bool AsciiValue(const std::string& text, int f, int k, Vec3* p, std::uint32_t* color) {
    const PcdField& field = fields_[f];
    double value = 0.0;
    const bool ok = (f == kept_.color && k == 0) ? AsciiColor(text, field, color)
                                                 : AsciiScalar(text, field, &value);
    if (!ok) {
      Error(line_, "'" + text + "' is not a " + TypeText(field) + " (field '" + field.name + "')");
      return false;
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (f == kept_.xyz[axis] && k == 0) (*p)[axis] = value;
    }
    return true;
  }

  static std::string TypeText(const PcdField& field) {
    if (field.type == 'F') return "number";
    return std::string(field.type == 'U' ? "whole number >= 0" : "whole number") + " of " +
           std::to_string(field.size) + " byte(s)";
  }

  bool ReadBinary(const std::uint8_t* data, std::size_t available) {
    if (!BinaryFits(available)) return false;
    const auto size = static_cast<std::size_t>(point_bytes_);
    cloud_.points.reserve(static_cast<std::size_t>(points_));
    for (long long i = 0; i < points_; ++i) AddBinaryPoint(data + i * size);
    return true;
  }

  // false (with an error) when `available` bytes hold fewer than POINTS points; warns of extra
  bool BinaryFits(std::size_t available) {
    const auto size = static_cast<std::size_t>(point_bytes_);
    if (static_cast<unsigned long long>(points_) > available / size) {
      Error(data_line_, "binary data is truncated: POINTS " + std::to_string(points_) + " of " +
                            std::to_string(size) + " bytes need " + NeededBytes() +
                            " bytes, the file has " + std::to_string(available) +
                            " after the DATA line");
      return false;
    }
    const std::size_t used = static_cast<std::size_t>(points_) * size;
    if (available > used && data_kind_ == "binary") {
      diagnostics_.Warning({file_, data_line_}, "ignoring " + std::to_string(available - used) +
                                                    " byte(s) after the last point");
    }
    return true;
  }

  // POINTS x the bytes of a point into *bytes; false when that exceeds `limit`
  bool DataBytes(unsigned long long limit, unsigned long long* bytes) const {
    const auto points = static_cast<unsigned long long>(points_);
    const auto size = static_cast<unsigned long long>(point_bytes_);
    if (points > limit / size) return false;
    *bytes = points * size;
    return true;
  }

  std::string NeededBytes() const {
    unsigned long long bytes = 0;
    if (!DataBytes(std::numeric_limits<unsigned long long>::max(), &bytes)) return "over 2^64";
    return std::to_string(bytes);
  }

  void AddBinaryPoint(const std::uint8_t* point) {
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis) {
      const PcdField& field = fields_[kept_.xyz[axis]];
      p[axis] = BinaryScalar(point + field.offset, field);
    }
    std::uint32_t color = 0;
    if (kept_.color >= 0) {
      color = static_cast<std::uint32_t>(LittleEndian(point + fields_[kept_.color].offset, 4));
    }
    AddPoint(p, color);
  }

  bool ReadCompressed(const std::uint8_t* data, std::size_t available) {
    std::size_t compressed = 0, expected = 0;
    if (!CompressedSizes(data, available, &compressed, &expected)) return false;
    std::vector<std::uint8_t> fields_first;
    std::string why;
    if (!LzfDecompress(data + 8, compressed, expected, &fields_first, &why)) {
      Error(data_line_, "binary_compressed data is corrupt: " + why);
      return false;
    }
    const std::vector<std::uint8_t> points = PointsFirst(fields_first);
    return ReadBinary(points.data(), points.size());
  }

  // The two uint32 sizes before LZF data, checked against the file and POINTS.
  bool CompressedSizes(const std::uint8_t* data, std::size_t available, std::size_t* compressed,
                       std::size_t* expected) {
    const std::string at = "binary_compressed data";
    if (available < 8) {
      Error(data_line_, at + " is truncated: " + std::to_string(available) +
                            " byte(s) after the DATA line, fewer than its 8-byte sizes");
      return false;
    }
    *compressed = LittleEndian(data, 4);
    *expected = LittleEndian(data + 4, 4);
    if (*compressed > available - 8) {
      Error(data_line_, at + " is truncated: its header says " + std::to_string(*compressed) +
                            " compressed bytes, the file has " + std::to_string(available - 8));
      return false;
    }
    unsigned long long needed = 0;
    if (DataBytes(std::numeric_limits<std::uint32_t>::max(), &needed) && needed == *expected) {
      return true;
    }
    Error(data_line_, at + " decompresses to " + std::to_string(*expected) + " bytes, POINTS " +
                          std::to_string(points_) + " of " + std::to_string(point_bytes_) +
                          " bytes need " + NeededBytes());
    return false;
  }

  // PCL compresses every point's first field, then every point's second, ...: interleave them
  std::vector<std::uint8_t> PointsFirst(const std::vector<std::uint8_t>& fields_first) const {
    std::vector<std::uint8_t> out(fields_first.size());
    const auto n = static_cast<std::size_t>(points_);
    std::size_t block = 0;
    for (const PcdField& field : fields_) {
      const std::size_t width = static_cast<std::size_t>(field.size) * field.count;
      for (std::size_t i = 0; i < n; ++i) {
        std::memcpy(&out[i * point_bytes_ + field.offset], &fields_first[block + i * width], width);
      }
      block += n * width;
    }
    return out;
  }

  void AddPoint(const Vec3& p, std::uint32_t color) {
    if (!p.allFinite()) {
      ++skipped_;
      return;
    }
    cloud_.points.push_back(p);
    if (kept_.color >= 0) cloud_.colors.push_back(color & 0xFFFFFFu);
  }

  std::optional<PointCloud> Finish() {
    const std::string total = std::to_string(points_);
    if (cloud_.points.empty()) {
      Error(data_line_, skipped_ > 0 ? "all " + total + " points have NaN or infinite coordinates"
                                     : std::string("the point cloud has no points"));
      return std::nullopt;
    }
    if (skipped_ > 0) {
      diagnostics_.Note({file_, data_line_},
                        "skipped " + std::to_string(skipped_) + " of " + total +
                            " points with NaN or infinite coordinates (PCL's \"no return\")");
    }
    return std::move(cloud_);
  }

  const std::string& bytes_;
  const std::string& file_;
  Diagnostics& diagnostics_;
  std::size_t next_ = 0;  // the first byte not read yet
  int line_ = 0;          // the line last read
  bool ok_ = true;
  // header lines as given (0: absent)
  std::vector<std::string> names_, sizes_, types_, counts_;
  int fields_line_ = 0, size_line_ = 0, type_line_ = 0, count_line_ = 0;
  int width_line_ = 0, height_line_ = 0, points_line_ = 0, data_line_ = 0;
  long long width_ = 0, height_ = 1, points_ = 0;
  std::string data_kind_;
  std::size_t data_offset_ = 0;
  // the layout
  std::vector<PcdField> fields_;
  KeptFields kept_;
  int point_bytes_ = 0;
  int point_values_ = 0;
  // the result
  PointCloud cloud_;
  long long skipped_ = 0;
};

}  // namespace

std::optional<PointCloud> ParsePcd(const std::string& bytes, const std::string& file,
                                   Diagnostics& diagnostics) {
  return PcdReader(bytes, file, diagnostics).Read();
}

std::optional<PointCloud> ReadPointCloudFile(const std::string& path, const SourceLocation& where,
                                             Diagnostics& diagnostics) {
  std::string bytes;
  if (!ReadFileText(path, &bytes)) {
    const SourceLocation at = where.file.empty() ? SourceLocation{path, 0} : where;
    diagnostics.Error(at, "cannot open point cloud file '" + path + "'");
    return std::nullopt;
  }
  return ParsePcd(bytes, path, diagnostics);
}

bool IsPointCloudExtension(const std::string& lower_extension) {
  return lower_extension == "pcd";
}

}  // namespace lamina::core
