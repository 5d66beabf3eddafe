// SPDX-License-Identifier: MIT
#include "core/batch/sampler.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/math_types.h"
namespace lamina::core {

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

RunRandom::RunRandom(std::uint64_t seed, std::uint64_t index)
    : engine_(SplitMix64(SplitMix64(seed) ^ SplitMix64(index + 0x632BE59BD9B4E019ull))) {}

double RunRandom::Uniform01() {
  return static_cast<double>(Bits() >> 11) * 0x1.0p-53;
}

double RunRandom::Uniform(double lo, double hi) {
  return lo + (hi - lo) * Uniform01();
}

double RunRandom::Normal(double mean, double std) {
  // 1 - u is in (0, 1]: the logarithm is finite
  const double u1 = 1.0 - Uniform01();
  const double u2 = Uniform01();
  return mean + std * std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

std::uint64_t RunRandom::Below(std::uint64_t n) {
  // the largest multiple of n that fits: words at or above it are drawn again
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t word = Bits();
  while (word >= limit) word = Bits();
  return word % n;
}

size_t Sampler::size() const {
  if (kind == Kind::kChoice || kind == Kind::kList) {
    return options.empty() ? 0 : options.front().size();
  }
  return a.size();
}

std::vector<double> Sampler::Draw(RunRandom* random, int index) const {
  std::vector<double> value(a.size());
  switch (kind) {
    case Kind::kFixed:
      return a;
    case Kind::kUniform:
      for (size_t k = 0; k < a.size(); ++k) value[k] = random->Uniform(a[k], b[k]);
      return value;
    case Kind::kNormal:
      for (size_t k = 0; k < a.size(); ++k) value[k] = random->Normal(a[k], b[k]);
      return value;
    case Kind::kChoice:
      return options[random->Below(options.size())];
    case Kind::kList:
      if (index < 0 || static_cast<size_t>(index) >= options.size()) {
        throw std::out_of_range("list has " + std::to_string(options.size()) + " values, run " +
                                std::to_string(index) + " needs one more");
      }
      return options[index];
  }
  return value;
}

namespace {

bool AllFiniteValues(const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

std::optional<std::string> CheckOptions(const std::vector<std::vector<double>>& options) {
  if (options.empty()) return "needs at least one value";
  for (const auto& option : options) {
    if (option.size() != options.front().size()) return "values must all have the same size";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> Sampler::Check(int runs) const {
  if (kind == Kind::kChoice) return CheckOptions(options);
  if (kind == Kind::kList) {
    if (auto problem = CheckOptions(options)) return problem;
    if (options.size() < static_cast<size_t>(runs)) {
      return "list has " + std::to_string(options.size()) + " values, the batch has " +
             std::to_string(runs) + " runs";
    }
    return std::nullopt;
  }
  if (a.empty()) return "needs a value";
  if (kind == Kind::kFixed) return std::nullopt;
  if (a.size() != b.size()) return "needs as many components in both bounds";
  if (!AllFiniteValues(a) || !AllFiniteValues(b)) return "needs finite numbers";
  for (size_t k = 0; k < a.size(); ++k) {
    if (kind == Kind::kUniform && a[k] > b[k]) return "needs lo <= hi";
    if (kind == Kind::kNormal && b[k] < 0) return "needs std >= 0";
  }
  return std::nullopt;
}

Sampler FixedSampler(std::vector<double> value) {
  Sampler s;
  s.a = std::move(value);
  return s;
}

Sampler UniformSampler(std::vector<double> lo, std::vector<double> hi) {
  Sampler s;
  s.kind = Sampler::Kind::kUniform;
  s.a = std::move(lo);
  s.b = std::move(hi);
  return s;
}

Sampler NormalSampler(std::vector<double> mean, std::vector<double> std) {
  Sampler s;
  s.kind = Sampler::Kind::kNormal;
  s.a = std::move(mean);
  s.b = std::move(std);
  return s;
}

Sampler ChoiceSampler(std::vector<std::vector<double>> options) {
  Sampler s;
  s.kind = Sampler::Kind::kChoice;
  s.options = std::move(options);
  return s;
}

Sampler ListSampler(std::vector<std::vector<double>> values) {
  Sampler s;
  s.kind = Sampler::Kind::kList;
  s.options = std::move(values);
  return s;
}

}  // namespace lamina::core
