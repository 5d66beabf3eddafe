// SPDX-License-Identifier: MIT
// Samplers of Monte-Carlo batches: the random initial conditions and arguments of each run.
//
// Determinism: run i of a batch draws from its own generator, seeded by (seed, i) only
// (RunRandom: std::mt19937_64 seeded with a SplitMix64 mix of both), so a run's values depend on
// neither the thread that runs it, nor the runs before it, nor the shard it is in. The
// transforms from the generator's 64-bit words to numbers are written here (53-bit uniform,
// Box-Muller normal, choice by rejection), not taken from <random>'s distributions, whose
// algorithms are implementation-defined: the same (seed, i) gives the same bits with every
// compiler and standard library. A run's samplers draw in the spec's order.
//
// Differences from Klamp't's monteCarloSim: Klamp't calls Python functions (random.uniform, ...)
// from one global generator, so a run's values depend on every draw before it; here the
// samplers are data (uniform, normal, choice, list) and each run has its own stream.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace lamina::core {

/// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix of 64 bits.
std::uint64_t SplitMix64(std::uint64_t x);

/// The generator of run `index` of a batch with `seed`.
class RunRandom {
 public:
  RunRandom(std::uint64_t seed, std::uint64_t index);
  /// The next 64 random bits.
  std::uint64_t Bits() { return engine_(); }
  /// Uniform in [0, 1): the top 53 bits times 2^-53.
  double Uniform01();
  /// Uniform in [lo, hi): lo + (hi - lo) * Uniform01() (lo when lo == hi).
  double Uniform(double lo, double hi);
  /// Normal(mean, std) by Box-Muller (two uniforms per value; the second value is not kept, so
  /// every call consumes the same number of words).
  double Normal(double mean, double std);
  /// Uniform whole number in [0, n) without modulo bias (rejection); n >= 1.
  std::uint64_t Below(std::uint64_t n);

 private:
  std::mt19937_64 engine_;
};

/// One sampler of a spec. Values are vectors of doubles (a scalar is a vector of one).
struct Sampler {
  enum class Kind { kFixed, kUniform, kNormal, kChoice, kList };
  Kind kind = Kind::kFixed;
  std::vector<double> a;  ///< fixed: the value; uniform: lo; normal: mean (per component)
  std::vector<double> b;  ///< uniform: hi; normal: std (per component)
  std::vector<std::vector<double>> options;  ///< choice: the options; list: run i's values

  /// The number of components every value has.
  size_t size() const;
  /// The value of run `index`, drawing from `random` (list: element `index`, no draw).
  /// std::out_of_range when a list has no element `index`.
  std::vector<double> Draw(RunRandom* random, int index) const;
  /// None when the sampler can give values for runs [0, runs); else why not ("list has 3
  /// values, the batch has 100 runs").
  std::optional<std::string> Check(int runs) const;
};

Sampler FixedSampler(std::vector<double> value);
/// Per-component ranges; lo.size() == hi.size(), lo <= hi, finite (Check says otherwise).
Sampler UniformSampler(std::vector<double> lo, std::vector<double> hi);
Sampler NormalSampler(std::vector<double> mean, std::vector<double> std);
Sampler ChoiceSampler(std::vector<std::vector<double>> options);
Sampler ListSampler(std::vector<std::vector<double>> values);

}  // namespace lamina::core
