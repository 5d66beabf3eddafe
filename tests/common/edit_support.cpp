// SPDX-License-Identifier: MIT
#include "tests/common/edit_support.h"

#include <stdexcept>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina::test {

core::WorldDocument ArmAndBlocksDocument() {
  core::WorldDocument document;
  core::Diagnostics diagnostics;
  EXPECT_TRUE(document.Load(DataPath("edit/arm_and_blocks.xml"), diagnostics))
      << diagnostics.FormatAll();
  return document;
}

core::ParamEdit ParamEditOf(const core::WorldDocument& document, const core::ElementIndex& element,
                            std::string_view key, core::ParamValue after) {
  const auto ref = document.RefOf(element);
  if (!ref) throw std::runtime_error("ParamEditOf: no such element");
  std::string error;
  auto edit = core::MakeParamEdit(document, *ref, key, std::move(after), &error);
  if (!edit) throw std::runtime_error("ParamEditOf: " + error);  // gtest reports it as a failure
  return *edit;
}

}  // namespace lamina::test
