// SPDX-License-Identifier: MIT
// Values of the parameter table (core/model/params.h) as the files spell them: numbers
// separated by whitespace (world XML attributes, `.rob` and `.obj` statements) rather than the
// commas of ParseParamValue; bools as 1 or 0 (true/false read too); choices by index for
// Klamp't's rows (preshrink="1", as Klamp't reads it) and by name for Lamina's
// (solver="quick"); `inf`/`-inf` as ParseDouble reads them, `nan` refused as text. The readers
// check what this gives them with ParamAccepts and report ParamRule; this file does only the
// text, so that reader and writer spell a value the same way.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/params.h"

namespace lamina::core {

/// The rows of a body's contact surface as the files name them: kRestitution, kFriction,
/// kRollingFriction, kSpinningFriction, kStiffness, kDamping (`<physics>`, `.obj` keys; the
/// writer leaves Lamina's rolling and spinning friction out while they are 0).
std::vector<const ParamSpec*> SurfaceRows();
/// The rows of `<simulation>`'s `<geometry>`: padding, preshrink and the surface rows.
std::vector<const ParamSpec*> BodyGeometryRows();

/// `text` split at whitespace.
std::vector<std::string> SplitWords(const std::string& text);

/// The value that `words` spell for row `spec`: one word "true"/"false" for a bool, a choice's
/// name for a choice, otherwise one number per word. nullopt with `*bad_word` set when a word
/// is not a number (NaN included); the count and the range are not checked here.
std::optional<ParamValue> ParamFromWords(const ParamSpec& spec,
                                         const std::vector<std::string>& words,
                                         std::string* bad_word);

/// The text ParamFromWords reads back to exactly `value`: components with FormatDouble
/// separated by single spaces; a Lamina choice with a valid index as its name.
std::string ParamWords(const ParamSpec& spec, const ParamValue& value);

/// How much a file's inertia may differ from its transpose and still be read: off-diagonal pairs
/// within this fraction of the matrix's largest |entry| differ by the rounding of the printed
/// digits (HRP-2's .rob: 1e-8 on entries of 1e-2, 3e-6 of the largest). The table itself allows
/// only 1e-9 (params.cpp); more than this is a real asymmetry and stays an error.
inline constexpr double kInertiaRoundingTolerance = 1e-4;

/// A value a file spells slightly outside the table's rule that the reader takes anyway, with the
/// warning it gives ("is not symmetric ...").
struct LenientValue {
  ParamValue value;
  std::string warning;
};
/// For an inertia (9 numbers, row-major) that the table refuses only because it is asymmetric by
/// rounding (kInertiaRoundingTolerance): (I + I^T) / 2, which Klamp't would use as given, and
/// the warning. nullopt for anything else: another row, an accepted value, a real asymmetry, a
/// matrix that is not positive semi-definite once symmetrised.
std::optional<LenientValue> LenientInertia(const ParamSpec& spec, const ParamValue& value);

/// What a reader says when the table refuses a value: "<ParamRule>, got '<text>'".
std::string ParamRefusal(const ParamSpec& spec, const std::string& text);
/// None when the row `key` of elements of `kind` accepts `value` (with as many components as it
/// has: one entry of a kVector row is checked like the whole); else the refusal with the value
/// in ParamWords.
std::optional<std::string> RefuseRow(std::string_view key, ElementKind kind,
                                     const ParamValue& value);

}  // namespace lamina::core
