// Test support: compiles spec text through the real front end and lowering.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"

namespace arbc::lower::testing {

// Compiles `text`; fails the test (with the diagnostics) if it does not compile.
inline CompiledSpec compile_ok(const std::string& text, const std::string& script_dir = ".") {
  CompiledSpec c = compile_spec_text(text, "test.spec", script_dir);
  EXPECT_TRUE(c.ok) << frontend::render_diagnostics(c.diagnostics, &c.sources);
  return c;
}

inline const model::Connection* find_connection(const model::App& app, const std::string& port,
                                                const std::string& name) {
  for (const model::Connection& c : app.connections)
    if (c.destination == port && c.name == name) return &c;
  return nullptr;
}

}  // namespace arbc::lower::testing
