// The front end's contract with lowering: a checked spec has every name resolved, every
// expression typed, every constraint built and every duration in seconds (ast.h "sema:").
#include "compiler/frontend/frontend.h"

#include <gtest/gtest.h>

#include <thread>

#include "tests/support/tree_paths.h"

namespace arbc::frontend {

using namespace std::chrono_literals;
namespace {

using ast::Expr;
using ast::NameKind;
using ast::Stmt;

std::string ids(const CheckResult& r) {
  std::string s;
  for (const Diagnostic& d : r.diagnostics) s += d.id + " ";
  return s;
}

TEST(Frontend, TableCleanChecksAndIsAnnotated) {
  CheckResult r = check_file(arbc::testing::source_dir() + "/specs/table_clean.spec");
  ASSERT_TRUE(r.ok()) << render_diagnostics(r.diagnostics, nullptr);
  const ast::Spec& spec = *r.spec;
  ASSERT_TRUE(spec.app);
  EXPECT_EQ(spec.app->name, "table_clean");
  EXPECT_EQ(spec.modules.size(), 8u);
  EXPECT_EQ(spec.arbitrations.size(), 4u);
  EXPECT_EQ(spec.asserts.size(), 3u);

  // Events: status flags and derived events, with lifetimes in seconds.
  const ast::EventSymbol* taken = spec.find_event("e_taken");
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->kind, ast::EventSymbol::Kind::Status);
  EXPECT_EQ(taken->source, "PickAndPlace.status");
  EXPECT_EQ(taken->flag, "e_taken");
  EXPECT_EQ(*taken->lifetime, 500ms);
  const ast::EventSymbol* face = spec.find_event("e_face_detected");
  ASSERT_TRUE(face);
  EXPECT_EQ(face->kind, ast::EventSymbol::Kind::Derived);
  EXPECT_EQ(*face->lifetime, 1s);
  const ast::EventSymbol* unreachable = spec.find_event("e_unreachable");
  ASSERT_TRUE(unreachable);
  EXPECT_FALSE(unreachable->lifetime);

  // Constraints are runtime Constraint trees.
  const ast::ArbitrateDecl* pick = spec.find_arbitration("PickAndPlace.cmd");
  ASSERT_TRUE(pick);
  EXPECT_EQ(pick->rules[0].name, "take");
  EXPECT_EQ(
      pick->rules[0].constraint.to_string(),
      "not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling and not e_arm_picking");
  EXPECT_EQ(pick->rules[0].message_name, "objects");
  EXPECT_EQ(pick->rules[0].source.port_decl->name, "objects");
  EXPECT_EQ(pick->rules[0].port, pick);

  const ast::ArbitrateDecl* head = spec.find_arbitration("HeadControl.gaze");
  ASSERT_TRUE(head);
  EXPECT_TRUE(head->by_priority);
  ASSERT_TRUE(head->rules[0].hold);
  EXPECT_EQ(head->rules[0].hold->nanos, 1s);
  EXPECT_FALSE(head->rules[1].hold);
  EXPECT_FALSE(head->rules[1].has_body);

  // The take body: names resolve to the message, lets, lambda parameters and constants.
  const ast::Block& body = pick->rules[0].body;
  ASSERT_EQ(body.size(), 4u);
  const Stmt& let_obj = *body[1];
  ASSERT_EQ(let_obj.kind, Stmt::Kind::Let);
  EXPECT_EQ(let_obj.expr->type->to_string(), "{pos: vec3, dist: float}");
  const Expr& min_by = *let_obj.expr;
  EXPECT_EQ(min_by.builtin, ast::Builtin::MinBy);
  EXPECT_EQ(min_by.args[0]->name_kind, NameKind::Message);
  const Expr& lambda = *min_by.args[1];
  ASSERT_EQ(lambda.kind, Expr::Kind::Lambda);
  const Expr& o_dist = *lambda.args[0];
  EXPECT_EQ(o_dist.args[0]->name_kind, NameKind::Param);
  EXPECT_EQ(o_dist.args[0]->lambda, &lambda);

  const Stmt& accept_near = *body[2];
  const Expr& compare = *accept_near.expr;
  EXPECT_EQ(compare.type->kind, Type::Kind::Bool);
  EXPECT_EQ(compare.args[0]->args[0]->name_kind, NameKind::Let);
  EXPECT_EQ(compare.args[0]->args[0]->local, &let_obj);
  EXPECT_EQ(compare.args[1]->name_kind, NameKind::Const);
  EXPECT_EQ(compare.args[1]->constant->name, "HAND_REACHABLE");
  EXPECT_DOUBLE_EQ(compare.args[1]->constant->number, 0.40);

  const Stmt& emit = *body[3];
  EXPECT_EQ(emit.kind, Stmt::Kind::Emit);
  EXPECT_EQ(emit.expr->kind, Expr::Kind::Record);
  ASSERT_EQ(emit.expr->names.size(), 2u);
  EXPECT_EQ(emit.expr->names[0].name, "verb");
  EXPECT_EQ(emit.expr->names[1].name, "pos");

  // The throttle's duration constant is folded to seconds.
  const ast::ArbitrateDecl* speak = spec.find_arbitration("Speak.text");
  ASSERT_TRUE(speak);
  const Stmt& throttle = *speak->rules[0].body[0];
  ASSERT_EQ(throttle.kind, Stmt::Kind::Throttle);
  EXPECT_EQ(throttle.duration->nanos, 5s);

  // Asserts point at their rule.
  EXPECT_EQ(spec.asserts[0].rule_decl, &pick->rules[0]);
  EXPECT_EQ(spec.asserts[0].constraint.to_string(), "not e_taken");
}

TEST(Frontend, LocationsAreOneBasedWithRanges) {
  CheckResult r = check_text("app t;\nmodule A { out x: flot; }\n", "mem.spec");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.id, "unknown-type");
  EXPECT_EQ(d.loc.file, "mem.spec");
  EXPECT_EQ(d.loc.line, 2);
  EXPECT_EQ(d.loc.column, 19);
  EXPECT_EQ(d.loc.end_column, 23);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'float'?");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.spec);  // semantic errors keep the AST (for tools), but it must not be lowered
}

TEST(Frontend, SyntaxErrorsAreOnePerDeclarationAndInWords) {
  CheckResult r = check_text(
      "app t\nmodule A { out x: float }\nmodule B { in y: ; }\nmodule C { in z: float; }\n",
      "s.spec");
  EXPECT_FALSE(r.spec);
  ASSERT_EQ(r.diagnostics.size(), 3u) << render_diagnostics(r.diagnostics, nullptr);
  EXPECT_EQ(r.diagnostics[0].message, "expected ';' after the app declaration");
  EXPECT_EQ(r.diagnostics[1].message, "expected ';' after the port declaration, found '}'");
  EXPECT_EQ(r.diagnostics[2].message, "expected a type such as float, vec3 or list<T>, found ';'");
  for (const Diagnostic& d : r.diagnostics) {
    EXPECT_EQ(d.id, "syntax");
    EXPECT_EQ(d.message.find("T__"), std::string::npos);  // never a token dump
  }
}

// A syntax error elsewhere must not split `assume E only after R;` at its `only` (which also
// starts `only R after O;`): that gave two more errors on a line without one.
TEST(Frontend, ASyntaxErrorDoesNotBreakAnAssumeOnlyAfter) {
  CheckResult r = check_text(
      "app t;\nmodule A { out x: float; in y: float; out s: list<string>; }\n"
      "events from A.s { e };\narbitrate A.y { r: from A.x { let v = x } }\n"
      "assume e only after r;\n",
      "s.spec");
  ASSERT_EQ(r.diagnostics.size(), 1u) << render_diagnostics(r.diagnostics, nullptr);
  EXPECT_EQ(r.diagnostics[0].loc.line, 4);
}

// A misspelt module or port is pointed at alone, not the whole `Module.port`: an editor's
// quick fix replaces what is pointed at with the name the note suggests.
TEST(Frontend, AMisspeltModuleOrPortIsPointedAtAlone) {
  CheckResult r = check_text(
      "app t;\nmodule Head { in gaze: vec3; }\nmodule Look { out gaze: vec3; }\n"
      "connect Lok.gaze -> Head.gaz;\n",
      "m.spec");
  ASSERT_EQ(r.diagnostics.size(), 2u) << render_diagnostics(r.diagnostics, nullptr);
  EXPECT_EQ(r.diagnostics[0].id, "unknown-module");
  EXPECT_EQ(r.diagnostics[0].loc.column, 9);
  EXPECT_EQ(r.diagnostics[0].loc.end_column, 12);  // `Lok`
  EXPECT_EQ(r.diagnostics[1].id, "unknown-port");
  EXPECT_EQ(r.diagnostics[1].loc.column, 26);
  EXPECT_EQ(r.diagnostics[1].loc.end_column, 29);  // `gaz`
}

TEST(Frontend, SearchAndTrackAndFaceFilterCheckClean) {
  for (const char* name : {"search_and_track", "face_filter"}) {
    CheckResult r = check_file(arbc::testing::source_dir() + "/specs/" + name + ".spec");
    EXPECT_TRUE(r.ok()) << name << "\n" << render_diagnostics(r.diagnostics, nullptr);
  }
  CheckResult r = check_file(arbc::testing::source_dir() + "/specs/search_and_track.spec");
  const ast::Rule& track = r.spec->arbitrations[0].rules[0];
  EXPECT_EQ(track.constraint.to_string(), "true");
  ASSERT_EQ(track.body[0]->kind, Stmt::Kind::Set);
  EXPECT_EQ(track.body[0]->duration->nanos, 1s);
  EXPECT_EQ(r.spec->arbitrations[0].rules[1].constraint.to_string(), "not e_face_detected");
}

TEST(Frontend, OtherwiseIsRecordedNotTranslated) {
  CheckResult r = check_text(
      "app t;\nmodule A { out x: float; }\nmodule B { out y: float; }\nmodule C { in z: float; }\n"
      "event e;\narbitrate C.z { a: from A.x when e; b: from B.y when otherwise; }\n",
      "o.spec");
  ASSERT_TRUE(r.ok()) << render_diagnostics(r.diagnostics, nullptr);
  EXPECT_FALSE(r.spec->arbitrations[0].rules[0].otherwise);
  EXPECT_TRUE(r.spec->arbitrations[0].rules[1].otherwise);
}

TEST(Frontend, StatusFlagsMapToEvents) {
  CheckResult r = check_text(
      "app t;\nmodule A { out s: list<string>; }\n"
      "events from A.s { e_taken = \"taken\", e_idle } lifetime 500ms;\n",
      "f.spec");
  ASSERT_TRUE(r.ok()) << render_diagnostics(r.diagnostics, nullptr);
  EXPECT_EQ(r.spec->find_event("e_taken")->flag, "taken");
  EXPECT_EQ(r.spec->find_event("e_idle")->flag, "e_idle");
  EXPECT_EQ(*r.spec->find_event("e_idle")->lifetime, 500ms);
}

TEST(Frontend, IntWidensToFloatButNotTheOtherWay) {
  std::string head =
      "app t;\nmodule A { out x: float; }\nmodule B { in y: int; }\nmodule C { in z: float; }\n";
  EXPECT_TRUE(check_text(head + "connect A.x -> C.z { emit 1; }\n", "w.spec").ok());
  CheckResult r = check_text(head + "connect A.x -> B.y { emit x; }\n", "w.spec");
  EXPECT_EQ(ids(r), "emit-type ");
}

// The items of a list literal join as numbers do at every depth, whichever comes first: a
// counterexample's test step `[{ f: 0 }, { f: nan }]` of a list of {f: float} was refused
// (tests/drt, seed 38, spec 175) because the first item made the list's records of ints.
TEST(Frontend, ListItemsJoinTheirNumbersInsideRecordsAndLists) {
  std::string head =
      "app t;\nmodule A { out x: {f: float, g: list<float>}[2]; }\n"
      "module B { in y: {f: float, g: list<float>}[2]; }\n";
  EXPECT_TRUE(check_text(head + "connect A.x -> B.y { emit [{f: 0, g: [1]}, {f: 0.5, g: []}]; }\n"
                                "test \"t\" { at 0s A.x <- [{f: 0, g: [2]}, {f: nan, g: [0.5]}];"
                                " expect B.y receives; }\n",
                         "w.spec")
                  .ok());
  // Shapes that differ still do not share a list; nor does a uint64 with another number.
  CheckResult r = check_text(
      "app t;\nmodule A { out x: uint64; }\n"
      "module B { in y: list<{f: float}>; in z: list<{f: float}>; }\n"
      "connect A.x -> B.y { emit [{f: 0}, {g: 0.5}]; }\n"
      "connect A.x -> B.z { let u = [{f: x}, {f: 1}]; emit [{f: 1.0}]; }\n",
      "w.spec");
  EXPECT_EQ(ids(r), "type-mismatch type-mismatch ") << r.diagnostics.size();
}

// A misspelt field in a record literal is reported at the name, with "did you mean" among the
// fields the literal does not give, inside lists and nested records too.
TEST(Frontend, AStrayFieldOfARecordLiteralIsReportedAtItsName) {
  std::string head =
      "app t;\ntype Cmd = { verb: string, pos: vec3 };\nmodule A { out p: vec3; }\n"
      "module B { in c: Cmd; in cs: list<Cmd>; in n: { cmd: Cmd }; }\n";
  struct Case {
    std::string body;
    std::string stray;  // on line 5
    std::string meant;
  };
  for (const Case& c :
       {Case{"connect A.p -> B.c { emit { verb: \"x\", poss: p }; }", "poss", "pos"},
        Case{"connect A.p -> B.cs { emit [{ verb: \"x\", pso: p }]; }", "pso", "pos"},
        Case{"connect A.p -> B.n { emit { cmd: { vreb: \"x\", pos: p } }; }", "vreb", "verb"},
        // `pos` is given already: no suggestion for the other name.
        Case{"connect A.p -> B.c { emit { pos: p, poss: p, verb: \"\" }; }", "poss", ""}}) {
    CheckResult r = check_text(head + c.body + "\n", "r.spec");
    ASSERT_EQ(ids(r), "emit-type ") << c.body;
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.loc.line, 5) << c.body;
    EXPECT_EQ(d.loc.column, static_cast<int>(c.body.find(c.stray + ":")) + 1) << c.body;
    if (c.meant.empty()) {
      EXPECT_TRUE(d.notes.empty()) << c.body;
    } else {
      ASSERT_EQ(d.notes.size(), 1u) << c.body;
      EXPECT_EQ(d.notes[0].message, "did you mean '" + c.meant + "'?");
    }
  }
}

// The literal bound first (`let c = { poss: p }; emit c;`) is traced through its name: the
// error is at the field in the `let`, with a note at the use; a `var`'s initializer too, since
// it gives the var its type.
TEST(Frontend, AStrayFieldOfALetBoundRecordIsReportedAtItsName) {
  std::string head =
      "app t;\ntype Cmd = { verb: string, pos: vec3 };\nmodule A { out p: vec3; }\n"
      "module B { in c: Cmd; in cs: list<Cmd>; in n: { cmd: Cmd }; }\n";
  struct Case {
    std::string body;
    std::string stray;  // on line 5
    std::string meant;
    std::string use;  // where the note points: the last occurrence of this text
  };
  for (const Case& c :
       {Case{"connect A.p -> B.c { let c = { verb: \"x\", poss: p }; emit c; }", "poss", "pos",
             "c;"},
        // A `let` of a `let`: the note is at the name emitted.
        Case{"connect A.p -> B.c { let a = { verb: \"x\", poss: p }; let b = a; emit b; }", "poss",
             "pos", "b;"},
        // Nested in a record or a list literal.
        Case{"connect A.p -> B.n { let m = { vreb: \"x\", pos: p }; emit { cmd: m }; }", "vreb",
             "verb", "m }"},
        Case{"connect A.p -> B.cs { let m = { verb: \"x\", pso: p }; emit [m]; }", "pso", "pos",
             "m]"},
        Case{"connect A.p -> B.c { var last = { verb: \"x\", poss: p }; emit last; }", "poss",
             "pos", "last;"}}) {
    CheckResult r = check_text(head + c.body + "\n", "r.spec");
    ASSERT_EQ(ids(r), "emit-type ") << c.body;
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.loc.line, 5) << c.body;
    EXPECT_EQ(d.loc.column, static_cast<int>(c.body.find(c.stray + ":")) + 1) << c.body;
    EXPECT_NE(d.message.find("has no field '" + c.stray + "'"), std::string::npos) << d.message;
    ASSERT_EQ(d.notes.size(), 2u) << c.body;
    EXPECT_EQ(d.notes[0].message, "did you mean '" + c.meant + "'?");
    EXPECT_EQ(d.notes[1].loc.line, 5) << c.body;
    EXPECT_EQ(d.notes[1].loc.column, static_cast<int>(c.body.rfind(c.use)) + 1) << c.body;
  }
  // One literal emitted on two paths: one error at it, a note at each `emit`.
  std::string body =
      "connect A.p -> B.c { let c = { verb: \"x\", poss: p }; if p.x > 0.0 { emit c; } else { "
      "emit c; } }";
  CheckResult r = check_text(head + body + "\n", "r.spec");
  ASSERT_EQ(ids(r), "emit-type ");
  ASSERT_EQ(r.diagnostics[0].notes.size(), 3u);
  EXPECT_EQ(r.diagnostics[0].notes[1].loc.column, static_cast<int>(body.find("c; }")) + 1);
  EXPECT_EQ(r.diagnostics[0].notes[2].loc.column, static_cast<int>(body.rfind("c; }")) + 1);
  // A value with no literal behind it (the message) is still reported over the whole value.
  r = check_text(head + "connect A.p -> B.c { let c = p; emit c; }\n", "r.spec");
  ASSERT_EQ(ids(r), "emit-type ");
  EXPECT_TRUE(r.diagnostics[0].notes.empty());
}

TEST(Frontend, EveryErrorIsReportedNotJustTheFirst) {
  CheckResult r = check_text(
      "app t;\nmodule A { out x: flot; }\nmodule B { in y: vec; }\nconnect Q.x -> B.y;\n",
      "m.spec");
  EXPECT_EQ(ids(r), "unknown-type unknown-type unknown-module ");
}

TEST(Frontend, NonAsciiTextKeepsItsBytesAndColumnsCountCharacters) {
  CheckResult r = check_text(
      "app t \"caf\xC3\xA9 \xE2\x82\xAC\";\nmodule M \"\xC3\xA9t\xC3\xA9\" { out x: flot; }\n",
      "u.spec");
  ASSERT_TRUE(r.spec);
  EXPECT_EQ(r.spec->app->doc, "caf\xC3\xA9 \xE2\x82\xAC");
  EXPECT_EQ(r.spec->modules[0].doc, "\xC3\xA9t\xC3\xA9");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].loc.column, 25);  // characters, not bytes (which would be 27)
}

TEST(Frontend, AByteOrderMarkIsNotPartOfTheText) {
  CheckResult r = check_text(
      "\xEF\xBB\xBF"
      "app t; module M { out x: flot; }\n",
      "bom.spec");
  ASSERT_TRUE(r.spec);
  EXPECT_EQ(r.spec->app->name, "t");
  ASSERT_EQ(r.diagnostics.size(), 1u) << ids(r);
  EXPECT_EQ(r.diagnostics[0].id, "unknown-type");
  EXPECT_EQ(r.diagnostics[0].loc.column, 26);  // counted from after the mark
  EXPECT_EQ(r.source.substr(0, 3), "app");
}

TEST(Frontend, RenderCapsTheNumberOfErrors) {
  std::vector<Diagnostic> many(60);
  for (Diagnostic& d : many) d.message = "x";
  std::string text = render_diagnostics(many, nullptr, 50);
  EXPECT_NE(text.find("... and 10 more errors (only the first 50 are shown)"), std::string::npos);
}

// The lexer and the parser predict over DFA caches of their thread's own (thread_dfa.h), each
// built as it goes: specs checked on several threads at once come out as on one.
TEST(Frontend, SpecsCheckedOnSeveralThreadsAtOnceComeOutAsOnOne) {
  auto summary = [](const std::string& name) {
    CheckResult r = check_file(arbc::testing::source_dir() + "/specs/" + name + ".spec");
    std::string s = ids(r);
    if (r.spec)
      for (const ast::ArbitrateDecl& a : r.spec->arbitrations)
        for (const ast::Rule& rule : a.rules)
          s += rule.name + ": " + rule.constraint.to_string() + "\n";
    return s;
  };
  const std::vector<std::string> names = {"table_clean", "search_and_track", "face_filter"};
  std::vector<std::string> expected;
  for (const std::string& name : names) expected.push_back(summary(name));
  std::vector<std::vector<std::string>> got(4);
  std::vector<std::thread> threads;
  for (auto& out : got)
    threads.emplace_back([&names, &summary, &out] {
      for (int round = 0; round < 3; ++round)
        for (const std::string& name : names) out.push_back(summary(name));
    });
  for (std::thread& t : threads) t.join();
  for (const auto& out : got)
    for (size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], expected[i % names.size()]);
  EXPECT_NE(expected[0].find("search: "), std::string::npos);  // the rules are really there
}

}  // namespace
}  // namespace arbc::frontend
