// What the harness tests share: an app compiled from spec text, and a scratch folder.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "compiler/lower/compile_spec.h"
#include "tests/support/tree_paths.h"

namespace arbc::harness::testing {

// The spec text compiled (the test fails on an error).
inline std::shared_ptr<const lower::LoweredApp> compiled(const std::string& text) {
  lower::CompiledSpec c = lower::compile_spec_text(text, "t.spec");
  EXPECT_TRUE(c.ok);
  for (const Diagnostic& d : c.diagnostics) ADD_FAILURE() << render(d, &c.sources);
  return c.lowered;
}

// A fresh folder in the build tree for this test.
inline std::string scratch() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string dir = arbc::testing::binary_dir() + "/harness_test_scratch/" +
                    info->test_suite_name() + "." + info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The look-around app of docs/testing.md: a face wins over looking around for a hold.
inline constexpr const char* kGaze =
    "app gaze;\n"
    "type Face = { pos: vec3, certainty: float };\n"
    "module FaceDetector { out face: Face; }\n"
    "module LookAround { out gaze: vec3; }\n"
    "module HeadControl { in gaze: vec3; }\n"
    "event e_face = FaceDetector.face : face.certainty >= 0.8 for 500ms;\n"
    "arbitrate HeadControl.gaze by priority {\n"
    "  track: from FaceDetector.face when e_face hold 1s { emit face.pos; }\n"
    "  search: from LookAround.gaze;\n"
    "}\n";

}  // namespace arbc::harness::testing
