#!/usr/bin/env python3
"""Protocol-level tests of `arbc lsp`: a real server process driven over stdio.

usage: test_protocol.py ARBC [unittest args]   (run from the repository root)
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lsp_client import SCRATCH_PREFIX, LspClient, apply_edits, file_uri, position_of  # noqa: E402

ARBC = None
ROOT = os.getcwd()
SPEC = os.path.join(ROOT, "specs", "table_clean.spec")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def check_json(text):
    """`arbc check --format json` of text saved as a file next to the spec (same script dir)."""
    return check_json_at(text, SPEC)


def check_json_at(text, path):
    """`arbc check --format json` of text saved beside `path` (so that relative paths hold)."""
    with tempfile.NamedTemporaryFile("w", prefix=SCRATCH_PREFIX, suffix=".spec",
                                     dir=os.path.dirname(path),
                                     delete=False) as f:
        f.write(text)
    try:
        proc = subprocess.run([ARBC, "check", "--format", "json", f.name], capture_output=True,
                              text=True, timeout=60)
        return json.loads(proc.stdout)["diagnostics"]
    finally:
        os.unlink(f.name)


class Session(unittest.TestCase):
    verify = False

    def setUp(self):
        command = [ARBC, "lsp"] + ([] if self.verify else ["--no-verify"])
        self.c = LspClient(command)
        self.init = self.c.initialize(ROOT)
        self.text = read(SPEC)
        self.uri = file_uri(SPEC)

    def tearDown(self):
        self.c.close()

    def open_spec(self, text=None, uri=None):
        uri = uri or self.uri
        self.c.open(uri, text if text is not None else self.text)
        return self.c.wait_diagnostics(uri, version=1)

    def at(self, needle, occurrence=0, offset=0, text=None):
        return {"textDocument": {"uri": self.uri},
                "position": position_of(text or self.text, needle, occurrence, offset)}


class Lifecycle(Session):
    def test_capabilities_name_every_feature(self):
        caps = self.init["capabilities"]
        self.assertEqual(caps["textDocumentSync"]["change"], 2)  # incremental
        for feature in ("hoverProvider", "definitionProvider", "referencesProvider",
                        "documentSymbolProvider", "completionProvider", "codeActionProvider",
                        "renameProvider"):
            self.assertIn(feature, caps)
        self.assertEqual(caps["completionProvider"]["triggerCharacters"], ["."])

    def test_shutdown_then_exit_exits_0(self):
        self.assertEqual(self.c.shutdown_and_exit(), 0)

    def test_exit_without_shutdown_exits_1(self):
        self.c.notify("exit", None)
        self.assertEqual(self.c.proc.wait(timeout=30), 1)

    def test_end_of_input_ends_the_server(self):
        self.c.proc.stdin.close()
        self.assertEqual(self.c.proc.wait(timeout=30), 1)

    def test_requests_after_shutdown_are_refused(self):
        self.c.request("shutdown", None)
        with self.assertRaises(RuntimeError) as e:
            self.c.request("textDocument/hover", self.at("take"))
        self.assertEqual(e.exception.args[0], -32600)


class BeforeInitialize(unittest.TestCase):
    def test_a_request_before_initialize_is_refused(self):
        with LspClient([ARBC, "lsp", "--no-verify"]) as c:
            with self.assertRaises(RuntimeError) as e:
                c.request("textDocument/hover", {"textDocument": {"uri": "file:///x.spec"},
                                                 "position": {"line": 0, "character": 0}})
            self.assertEqual(e.exception.args[0], -32002)


class Diagnostics(Session):
    def test_a_clean_spec_has_no_diagnostics(self):
        self.assertEqual(self.open_spec(), [])

    def test_diagnostics_are_those_of_arbc_check(self):
        self.open_spec()
        start = position_of(self.text, "not e_taken and e_arm_idle", 0, len("not "))
        end = dict(start, character=start["character"] + len("e_taken"))
        self.c.change(self.uri, 2, [{"range": {"start": start, "end": end}, "text": "e_tken"}])
        diags = self.c.wait_diagnostics(self.uri, version=2)
        broken = self.text.replace("not e_taken and e_arm_idle", "not e_tken and e_arm_idle", 1)
        expected = check_json(broken)
        self.assertEqual([(d["code"], d["message"]) for d in diags],
                         [(d["id"], d["message"]) for d in expected])
        d = diags[0]
        self.assertEqual(d["code"], "unknown-event")
        self.assertEqual(d["range"]["start"], start)
        self.assertEqual(d["range"]["end"]["character"], start["character"] + len("e_tken"))
        self.assertEqual(d["relatedInformation"][0]["message"], "did you mean 'e_taken'?")
        self.assertEqual(d["source"], "arbc")

    def test_a_test_expectation_over_two_containers_is_shown(self):
        # Lowering's error (compiler/lower/test_containers.h) is `arbc check`'s and the editor's:
        # e_taken is fed into two ports, so a bare event state over it must name one.
        self.open_spec()
        named = "expect not e_taken in PickAndPlace.cmd at 500ms;"
        start = position_of(self.text, named, 0, len("expect not e_taken"))
        end = dict(start, character=start["character"] + len(" in PickAndPlace.cmd"))
        self.c.change(self.uri, 2, [{"range": {"start": start, "end": end}, "text": ""}])
        diags = self.c.wait_diagnostics(self.uri, version=2)
        broken = self.text.replace(named, "expect not e_taken at 500ms;", 1)
        self.assertEqual([(d["code"], d["message"]) for d in diags],
                         [(d["id"], d["message"]) for d in check_json(broken)])
        self.assertIn("test-container", [d["code"] for d in diags])

    def test_a_syntax_error_and_its_repair(self):
        self.open_spec()
        end = position_of(self.text, "module Speak")
        self.c.change(self.uri, 2, [{"range": {"start": end, "end": end}, "text": "modle X { }\n"}])
        diags = self.c.wait_diagnostics(self.uri, version=2)
        self.assertTrue(diags and diags[0]["severity"] == 1, diags)
        self.c.change(self.uri, 3, [{"text": self.text}])  # a full-text change
        self.assertEqual(self.c.wait_diagnostics(self.uri, version=3), [])


class MisspeltSourcePort(Session):
    def test_only_the_misspelt_port_is_flagged_not_the_body_that_reads_the_right_one(self):
        """`from Camera.things` (no port close to it): one diagnostic, on `things`, as
        `arbc check` gives; the body's `objects`, the name meant, is not flagged."""
        text = read(os.path.join(ROOT, "tests", "check", "unknown_port_source_far",
                                 "unknown_port_source_far.spec"))
        diags = self.open_spec(text)
        self.assertEqual([(d["code"], d["range"]) for d in diags],
                         [("unknown-port", {"start": position_of(text, "things {"),
                                            "end": position_of(text, "things {", 0, 6)})])
        self.assertEqual([d["id"] for d in check_json(text)], ["unknown-port"])


class Navigation(Session):
    def setUp(self):
        super().setUp()
        self.open_spec()

    def definition_line(self, needle, occurrence=0, offset=0):
        loc = self.c.request("textDocument/definition", self.at(needle, occurrence, offset))
        self.assertIsNotNone(loc, needle)
        self.assertEqual(loc["uri"], self.uri)
        return loc["range"]["start"]

    def test_definitions(self):
        cases = [  # (use, occurrence, offset into it) -> declaration
            ("not e_taken", 0, 4, "e_taken, e_arm_idle }"),
            ("HAND_REACHABLE;", 0, 0, "HAND_REACHABLE = 0.40"),
            ("list<Object>", 0, 5, "Object = {"),
            ("arbitrate PickAndPlace.cmd", 0, 10, "PickAndPlace    {"),
            ("arbitrate PickAndPlace.cmd", 0, 23, "cmd: Cmd; out status"),
            ("take -> not", 0, 0, "take: from"),
            ("obj.dist <= HAND", 0, 0, "obj = min_by"),
            ("SPEAK_PERIOD;", 0, 0, "SPEAK_PERIOD   = 5s"),
        ]
        for use, occurrence, offset, decl in cases:
            with self.subTest(use=use):
                self.assertEqual(self.definition_line(use, occurrence, offset),
                                 position_of(self.text, decl))

    def test_references_of_an_event(self):
        refs = self.c.request("textDocument/references",
                              dict(self.at("e_pull_idle }"), context={"includeDeclaration": True}))
        lines = sorted(r["range"]["start"]["line"] for r in refs)
        # The declaration, take, track and search's `when`s, one assert and the tests' `set`s;
        # not the flags in the tests' status messages ("e_pull_idle": a string).
        expected = sorted(i for i, l in enumerate(self.text.split("\n"))
                          for _ in re.finditer(r'(?<!")\be_pull_idle\b(?!")', l.split("//")[0]))
        self.assertGreaterEqual(len([l for l in expected if l > position_of(
            self.text, "test ")["line"]]), 2)  # the tests' `set e_pull_idle;`
        self.assertEqual(lines, expected)
        for r in refs:
            s, e = r["range"]["start"], r["range"]["end"]
            self.assertEqual(self.text.split("\n")[s["line"]][s["character"]:e["character"]],
                             "e_pull_idle")

    def test_outline(self):
        symbols = self.c.request("textDocument/documentSymbol", {"textDocument": {"uri": self.uri}})
        names = [s["name"] for s in symbols]
        for name in ("table_clean", "Object", "HAND_REACHABLE", "ObjectDetector", "e_taken",
                     "arbitrate PickAndPlace.cmd", "arbitrate HeadControl.gaze"):
            self.assertIn(name, names)
        pick = symbols[names.index("arbitrate PickAndPlace.cmd")]
        self.assertEqual([c["name"] for c in pick["children"]], ["take", "put"])
        module = symbols[names.index("PickAndPlace")]
        self.assertEqual([c["name"] for c in module["children"]], ["cmd", "status"])
        self.assertIn('test "put after take"', names)
        on_take = symbols[names.index('test "take picks the closest object within hand reach"')]
        self.assertEqual(on_take["detail"], "on take")

    def test_references_of_a_rule_reach_into_the_tests(self):
        refs = self.c.request("textDocument/references",
                              dict(self.at("take: from"), context={"includeDeclaration": False}))
        lines = self.text.split("\n")
        quoted = [lines[r["range"]["start"]["line"]].strip() for r in refs]
        for start in ('expect take drops "not', 'test "take picks the c', "assert PickAndPlace.cmd"):
            self.assertTrue(any(q.startswith(start) for q in quoted), (start, quoted))

    def test_definition_from_a_test_step(self):
        self.assertEqual(self.definition_line("BucketDetector.bucket <-", 0, len("BucketDetector.")),
                         position_of(self.text, "bucket: vec3"))
        self.assertEqual(self.definition_line("set e_pull_idle;", 0, len("set ")),
                         position_of(self.text, "e_pull_idle }"))


class SameRuleNameInTwoPorts(Session):
    """Rule names are unique only within a port: two `arbitrate` blocks may each have a rule
    `track`, and each name leads to its own rule (the index keyed rules by name alone, so both
    were one symbol: the second `track` led to the first, and a rename renamed both)."""

    TEXT = ("app two_tracks;\n"
            "event e_a, e_b;\n"
            "module Cam  { out face: vec3; out ball: vec3; }\n"
            "module Head { in gaze: vec3; }\n"
            "module Arm  { in target: vec3; }\n"
            "arbitrate Head.gaze {\n"
            "  track: from Cam.face when e_a { let f = face; emit f; }\n"
            "  look: from Cam.ball when not e_a;\n"
            "}\n"
            "arbitrate Arm.target {\n"
            "  track: from Cam.ball when e_b { let b = ball; emit b; }\n"
            "  rest: from Cam.face when not e_b;\n"
            "}\n"
            "assert Head.gaze: track -> e_a;\n"
            "assert Arm.target: track -> e_b;\n")

    def setUp(self):
        super().setUp()
        self.text = self.TEXT
        self.uri = file_uri(os.path.join(os.path.dirname(SPEC), "two_tracks.spec"))
        self.assertEqual(self.open_spec(), [])

    def test_each_use_leads_to_its_own_port_s_rule(self):
        for use, decl in ((self.at("track ->", 0), self.at("track: from", 0)),
                          (self.at("track ->", 1), self.at("track: from", 1))):
            loc = self.c.request("textDocument/definition", use)
            self.assertEqual(loc["range"]["start"], decl["position"])

    def test_references_stay_in_the_port(self):
        for occurrence in (0, 1):
            refs = self.c.request("textDocument/references", dict(
                self.at("track: from", occurrence), context={"includeDeclaration": True}))
            self.assertEqual(sorted(r["range"]["start"]["line"] for r in refs),
                             sorted([self.at("track: from", occurrence)["position"]["line"],
                                     self.at("track ->", occurrence)["position"]["line"]]))

    def test_rename_one_leaves_the_other(self):
        edit = self.c.request("textDocument/rename", dict(self.at("track ->", 1), newName="grab"))
        renamed = apply_edits(self.text, edit["changes"][self.uri])
        self.assertEqual(renamed, self.text
                         .replace("track: from Cam.ball", "grab: from Cam.ball")
                         .replace("Arm.target: track", "Arm.target: grab"))
        self.assertEqual(check_json(renamed), [])

    def test_completion_offers_the_locals_of_the_rule_it_is_in(self):
        p = position_of(self.text, "emit b;", 0, len("emit "))
        labels = {i["label"] for i in self.c.request(
            "textDocument/completion", {"textDocument": {"uri": self.uri}, "position": p})["items"]}
        self.assertIn("b", labels)
        self.assertNotIn("f", labels)  # the first `track`'s

    def test_hover_names_the_rule_s_own_port(self):
        hover = self.c.request("textDocument/hover", self.at("track: from", 1))
        self.assertIn("into `Arm.target` from `Cam.ball`", hover["contents"]["value"])


class TestsFile(Session):
    """A tests file (`tests for "gaze.spec";`): checked against its app; names declared in the
    app's spec lead there."""

    def setUp(self):
        super().setUp()
        self.path = os.path.join(ROOT, "specs", "testing", "gaze.test.spec")
        self.app = os.path.join(ROOT, "specs", "testing", "gaze.spec")
        self.text, self.uri = read(self.path), file_uri(self.path)

    def test_checked_against_its_app(self):
        self.assertEqual(self.open_spec(), [])
        loc = self.c.request("textDocument/definition",
                             self.at("HeadControl.gaze receives", 0, len("HeadControl.")))
        self.assertEqual(loc["uri"], file_uri(self.app))
        self.assertEqual(loc["range"]["start"], position_of(read(self.app), "in gaze: vec3", 0, 3))
        names = [s["name"] for s in self.c.request("textDocument/documentSymbol",
                                                   {"textDocument": {"uri": self.uri}})]
        self.assertTrue(names and all(n.startswith("test ") for n in names), names)

    def test_an_error_is_at_its_place_in_the_tests_file(self):
        broken = self.text.replace("HeadControl.gaze receives", "HeadControl.gaze_x receives", 1)
        diags = self.open_spec(broken)
        self.assertEqual([(d["code"], d["range"]["start"]) for d in diags], [(
            check_json_at(broken, self.path)[0]["id"],
            position_of(broken, "gaze_x receives", 0, 0))])  # the misspelt port alone


RENAME_APP = """// The app a rename starts in.
app look "Look at a face when one is seen, else look around.";

const LONG = 1s;

module Face { out face: vec3; }
module Scan { out gaze: vec3; }
module Head { in gaze: vec3; }

event e_face = Face.face : face.x > 0.5 for 500ms;

arbitrate Head.gaze by priority {
  track:  from Face.face when e_face hold LONG;
  search: from Scan.gaze;
}

test "looks around" {
  at 0s Scan.gaze <- vec3(1.0, 0.0, 0.0);
  expect Head.gaze receives vec3(1.0, 0.0, 0.0) at 0s;
}
"""

RENAME_TESTS = """// Tests of app.spec in a file of their own: Scan, LONG, e_face and search are the app's.
tests for "%s";

test "a face holds the head" {
  at 0s set e_face;
  at 100ms Face.face <- vec3(1.0, 0.0, 0.0);
  at 500ms Scan.gaze <- vec3(0.0, 1.0, 0.0);
  expect search drops "not-selected" within 0s..LONG;
}
"""


class RenameReachesTestsFiles(Session):
    """A rename in an app's spec reaches its tests files: an open one as the editor holds it
    (unsaved), one on disk two folders below, not another app's, not a hidden scratch file,
    not one whose text does not parse."""

    def setUp(self):
        super().setUp()
        self.dir = tempfile.mkdtemp(prefix="arbc-rename-")
        self.paths = {
            "app": os.path.join(self.dir, "app.spec"),
            "open": os.path.join(self.dir, "app.test.spec"),
            "below": os.path.join(self.dir, "more", "deeper", "app_more.test.spec"),
            "other": os.path.join(self.dir, "other.test.spec"),
            "hidden": os.path.join(self.dir, ".scratch.test.spec"),
        }
        os.makedirs(os.path.dirname(self.paths["below"]))
        self.texts = {
            "app": RENAME_APP,
            "open": RENAME_TESTS % "app.spec",
            "below": RENAME_TESTS % "../../app.spec",
            "other": (RENAME_TESTS % "other.spec").replace("app.spec", "other.spec"),
            "hidden": RENAME_TESTS % "app.spec",
        }
        for key, path in self.paths.items():
            with open(path, "w", encoding="utf-8") as f:
                f.write(self.texts[key])
        with open(os.path.join(self.dir, "other.spec"), "w", encoding="utf-8") as f:
            f.write(RENAME_APP)
        self.on_disk = dict(self.texts)
        # The open tests file has an unsaved test: its edits are computed on the editor's text.
        self.texts["open"] += '\ntest "unsaved" {\n  at LONG Scan.gaze <- vec3(1.0, 0.0, 0.0);\n' \
                              '  expect Head.gaze receives at LONG;\n}\n'
        self.uris = {key: file_uri(path) for key, path in self.paths.items()}
        self.open_spec(self.texts["app"], self.uris["app"])
        self.open_spec(self.texts["open"], self.uris["open"])

    def tearDown(self):
        super().tearDown()
        shutil.rmtree(self.dir, ignore_errors=True)

    def rename(self, needle, offset, name):
        at = {"textDocument": {"uri": self.uris["app"]},
              "position": position_of(self.texts["app"], needle, 0, offset)}
        return self.c.request("textDocument/rename", dict(at, newName=name))["changes"]

    def check_renamed(self, changes, old, new):
        """Each renamed file is clean for arbc check and names `new`, not `old`, outside its
        comments."""
        self.assertEqual(sorted(changes), sorted(self.uris[k] for k in ("app", "open", "below")))
        renamed = {k: apply_edits(self.texts[k], changes[self.uris[k]])
                   for k in ("app", "open", "below")}
        for key, text in renamed.items():
            with open(self.paths[key], "w", encoding="utf-8") as f:
                f.write(text)
        for key, text in renamed.items():
            with self.subTest(file=key):
                code = re.sub(r"//.*", "", text)
                self.assertIsNone(re.search(r"\b%s\b" % old, code), text)
                self.assertRegex(code, r"\b%s\b" % new)
                proc = subprocess.run([ARBC, "check", self.paths[key]], capture_output=True,
                                      text=True, timeout=60)
                self.assertEqual((proc.returncode, proc.stderr), (0, ""))
        # The unsaved test's uses too: as many as there were, outside comments.
        self.assertEqual(len(re.findall(r"\b%s\b" % new, re.sub(r"//.*", "", renamed["open"]))),
                         len(re.findall(r"\b%s\b" % old, re.sub(r"//.*", "", self.texts["open"]))))

    def test_a_constant_a_module_an_event_and_a_rule(self):
        for needle, offset, old, new in (("const LONG", len("const "), "LONG", "HOLD"),
                                         ("module Scan", len("module "), "Scan", "Looker"),
                                         ("event e_face", len("event "), "e_face", "e_seen"),
                                         ("search: from", 0, "search", "roam")):
            with self.subTest(name=old):
                changes = self.rename(needle, offset, new)
                self.check_renamed(changes, old, new)
                for key in ("app", "open", "below"):  # as they were, for the next name
                    with open(self.paths[key], "w", encoding="utf-8") as f:
                        f.write(self.on_disk[key])

    def test_a_tests_file_that_does_not_parse_is_left_alone(self):
        broken = self.texts["open"].replace("at 0s set e_face;", "at 0s set e_face", 1)
        self.c.change(self.uris["open"], 2, [{"text": broken}])
        self.c.wait_diagnostics(self.uris["open"], version=2)
        changes = self.rename("const LONG", len("const "), "HOLD")
        self.assertEqual(sorted(changes), sorted([self.uris["app"], self.uris["below"]]))

    def test_a_name_of_the_app_is_renamed_in_the_app_not_from_a_tests_file(self):
        at = {"textDocument": {"uri": self.uris["open"]},
              "position": position_of(self.texts["open"], "within 0s..LONG", 0, len("within 0s.."))}
        with self.assertRaises(RuntimeError) as e:
            self.c.request("textDocument/rename", dict(at, newName="HOLD"))
        self.assertIn("'LONG' is declared in %s: rename it there (its tests files are renamed "
                      "with it)" % self.paths["app"], e.exception.args[1])


ROS2_SPEC = """app teleop;
use ros2 geometry_msgs/msg/TwistStamped;
module Nav { out cmd_vel: TwistStamped; }
module Base { in cmd_vel: TwistStamped; }
arbitrate Base.cmd_vel { nav: from Nav.cmd_vel { accept cmd_vel.header.stamp.sec >= 0; } }
"""


class Ros2Types(Session):
    """Types declared by `use ros2` (issue 41): hover says which message and where it was read;
    a `use` that cannot be read is a diagnostic at the `use`."""

    def test_hover_names_the_message(self):
        self.text = ROS2_SPEC
        self.assertEqual(self.open_spec(), [])
        h = self.c.request("textDocument/hover", self.at("TwistStamped; }", 0))
        self.assertIn("ROS 2 message `geometry_msgs/msg/TwistStamped`, arbc's built-in definition",
                      h["contents"]["value"])
        h = self.c.request("textDocument/hover", self.at("stamp.sec", 0, len("stamp.")))
        self.assertIn("`int32`", h["contents"]["value"])
        # From arbc's built-in definitions, it has no file: its definition is its `use`.
        loc = self.c.request("textDocument/definition", self.at("TwistStamped; }", 0))
        self.assertEqual(loc["uri"], self.uri)
        self.assertEqual(loc["range"]["start"], position_of(self.text, "TwistStamped;"))

    def test_a_message_not_found_is_an_error_at_the_use(self):
        self.text = ROS2_SPEC.replace("geometry_msgs/msg/TwistStamped", "nav_msgs/msg/Nothing")
        diagnostics = self.open_spec()
        self.assertIn("ros2-message", [d.get("code") for d in diagnostics])
        first = next(d for d in diagnostics if d.get("code") == "ros2-message")
        self.assertEqual(first["range"]["start"], position_of(self.text, "nav_msgs/msg/Nothing"))


class Ros2TypesFromFiles(Session):
    """A type `use ros2` read from a .msg file (given with --msg-path): go to definition opens
    the file, hover says where it was read."""

    def setUp(self):
        self.msgs = tempfile.mkdtemp(prefix=SCRATCH_PREFIX)
        os.makedirs(os.path.join(self.msgs, "sensor_msgs", "msg"))
        self.msg = os.path.join(self.msgs, "sensor_msgs", "msg", "Range.msg")
        with open(self.msg, "w") as f:
            f.write("std_msgs/Header header\nfloat32 range\n")
        self.c = LspClient([ARBC, "lsp", "--no-verify", "--msg-path", self.msgs])
        self.init = self.c.initialize(ROOT)
        self.text = ("app sonar;\nuse ros2 sensor_msgs/msg/Range;\n"
                     "module Sonar { out range: Range; }\nmodule Base { in range: Range; }\n"
                     "arbitrate Base.range { near: from Sonar.range; }\n")
        self.uri = file_uri(os.path.join(ROOT, "sonar.spec"))

    def tearDown(self):
        super().tearDown()
        shutil.rmtree(self.msgs)

    def test_definition_opens_the_msg_file(self):
        self.assertEqual(self.open_spec(), [])
        loc = self.c.request("textDocument/definition", self.at("Range; }", 0))
        self.assertEqual(loc["uri"], file_uri(self.msg))
        self.assertEqual(loc["range"]["start"], {"line": 0, "character": 0})
        h = self.c.request("textDocument/hover", self.at("Range; }", 1))
        self.assertIn("read from `%s`" % self.msg, h["contents"]["value"])


class Hover(Session):
    def setUp(self):
        super().setUp()
        self.open_spec()

    def hover(self, needle, occurrence=0, offset=0):
        h = self.c.request("textDocument/hover", self.at(needle, occurrence, offset))
        self.assertIsNotNone(h, needle)
        self.assertEqual(h["contents"]["kind"], "markdown")
        return h["contents"]["value"]

    def test_a_rule_shows_its_effective_guard_and_decision_table(self):
        text = self.hover("take: from")
        self.assertIn("**rule** `take` into `PickAndPlace.cmd`", text)
        self.assertIn("effective guard: `not e_taken and e_arm_idle and e_pull_idle and "
                      "not e_arm_pulling and not e_arm_picking`", text)
        self.assertIn("| e_arm_idle | e_arm_picking | e_arm_pulling | e_pull_idle | e_take_open "
                      "| e_taken | selects |", text)
        self.assertIn("| 1 | 0 | 0 | 1 | 0 | 0 | take |", text)

    def test_a_by_priority_rule_shows_its_activity_event(self):
        self.assertIn("act_track", self.hover("track:  from"))

    def test_an_event_shows_where_it_comes_from(self):
        text = self.hover("not e_taken", 0, 4)
        self.assertIn("status flag `\"e_taken\"` of `PickAndPlace.status`", text)
        self.assertIn("lifetime 500ms", text)
        self.assertIn("in the `when` of: `take`, `put`, `pull`", text)
        self.assertIn("derived from `FaceDetector.face`", self.hover("e_face_detected ="))

    def test_an_event_set_by_a_rule_names_it(self):
        path = os.path.join(ROOT, "specs", "search_and_track.spec")
        text, uri = read(path), file_uri(path)
        self.c.open(uri, text)
        self.assertEqual(self.c.wait_diagnostics(uri, version=1), [])
        h = self.c.request("textDocument/hover", {
            "textDocument": {"uri": uri},
            "position": position_of(text, "not e_face_detected", 0, len("not "))})
        value = h["contents"]["value"]
        self.assertIn("set by monitor code", value)  # not fed by a stream
        self.assertIn("set by: `track`", value)
        self.assertIn("in the `when` of: `search`", value)

    def test_types_of_names_and_fields(self):
        self.assertIn("`obj`: `Object = {pos: vec3, dist: float}`", self.hover("obj.dist <= HAND"))
        self.assertIn(": `float`", self.hover("obj.dist <= HAND", 0, 5))
        self.assertIn("**const** `HAND_REACHABLE`: `float` = `0.40`", self.hover("HAND_REACHABLE;"))
        self.assertIn("**in port** `PickAndPlace.cmd`: `Cmd = {verb: string, pos: vec3}`",
                      self.hover("arbitrate PickAndPlace.cmd", 0, 23))

    def test_a_builtin_shows_its_signature(self):
        # From core/builtins.h, the table the checker reads.
        text = self.hover("min_by(objects", 0, 2)
        self.assertIn("**builtin** `min_by(list<T>, x => number) -> T`", text)
        self.assertIn("smallest key", text)

    def test_nothing_under_a_comment(self):
        self.assertIsNone(self.c.request("textDocument/hover", self.at("// never take")))


class Editing(Session):
    def setUp(self):
        super().setUp()
        self.open_spec()

    def test_completion_after_a_dot(self):
        # `obj.` inside take's body: the text does not parse, the last version that did helps.
        where = position_of(self.text, "emit { verb: \"take\"")
        self.c.change(self.uri, 2, [{"range": {"start": where, "end": where}, "text": "obj."}])
        self.c.wait_diagnostics(self.uri, version=2)
        p = dict(where, character=where["character"] + 4)
        items = self.c.request("textDocument/completion",
                               {"textDocument": {"uri": self.uri}, "position": p})["items"]
        self.assertEqual(sorted(i["label"] for i in items), ["dist", "pos"])

    def test_completion_of_ports_names_and_keywords(self):
        p = position_of(self.text, "arbitrate PickAndPlace.cmd", 0, len("arbitrate PickAndPlace."))
        items = self.c.request("textDocument/completion",
                               {"textDocument": {"uri": self.uri}, "position": p})["items"]
        self.assertEqual(sorted(i["label"] for i in items), ["cmd", "status"])
        p = position_of(self.text, "accept obj.dist <= HAND", 0, len("accept "))
        labels = {i["label"] for i in self.c.request(
            "textDocument/completion", {"textDocument": {"uri": self.uri}, "position": p})["items"]}
        for expected in ("arbitrate", "when", "e_taken", "HAND_REACHABLE", "Object", "obj"):
            self.assertIn(expected, labels)

    def test_completion_of_builtins_with_their_signatures(self):
        p = position_of(self.text, "accept obj.dist <= HAND", 0, len("accept "))
        items = self.c.request("textDocument/completion",
                               {"textDocument": {"uri": self.uri}, "position": p})["items"]
        builtins = {i["label"]: i["detail"] for i in items if i["kind"] == 3}
        self.assertEqual(builtins["len"], "len(list or string) -> int")
        self.assertEqual(builtins["vec3"], "vec3(x, y, z) -> vec3")
        self.assertEqual(len([b for b in builtins if b in ("min", "max", "norm", "dist")]), 4)

    def test_a_did_you_mean_quick_fix(self):
        start = position_of(self.text, "e_arm_idle and e_pull_idle and not e_arm_pulling and")
        end = dict(start, character=start["character"] + len("e_arm_idle"))
        self.c.change(self.uri, 2, [{"range": {"start": start, "end": end}, "text": "e_arm_idel"}])
        diags = self.c.wait_diagnostics(self.uri, version=2)
        actions = self.c.request("textDocument/codeAction", {
            "textDocument": {"uri": self.uri}, "range": diags[0]["range"],
            "context": {"diagnostics": diags}})
        self.assertEqual(len(actions), 1)
        self.assertEqual(actions[0]["title"], "Change to 'e_arm_idle'")
        edits = actions[0]["edit"]["changes"][self.uri]
        broken = self.text.replace("e_arm_idle and e_pull_idle and not", "e_arm_idel and e_pull_idle and not", 1)
        self.assertEqual(apply_edits(broken, edits), self.text)

    def test_the_quick_fix_of_a_misspelt_module_or_port_keeps_the_rest(self):
        # The diagnostic used to cover the whole `Module.port`, and the fix replaced all of it
        # with the module's (or the port's) name alone: `from BucketDetector when`.
        version = 0
        for good, bad in (("put: from BucketDetector.bucket", "put: from BucketDetektor.bucket"),
                          ("put: from BucketDetector.bucket", "put: from BucketDetector.buckt"),
                          ("events from PickAndPlace.status", "events from PikAndPlace.status")):
            version += 2
            broken = self.text.replace(good, bad, 1)
            self.c.change(self.uri, version, [{"text": broken}])
            diags = [d for d in self.c.wait_diagnostics(self.uri, version=version)
                     if d.get("code") in ("unknown-module", "unknown-port")]
            self.assertEqual(len(diags), 1, bad)
            actions = self.c.request("textDocument/codeAction", {
                "textDocument": {"uri": self.uri}, "range": diags[0]["range"],
                "context": {"diagnostics": diags}})
            self.assertEqual(len(actions), 1, bad)
            self.assertEqual(apply_edits(broken, actions[0]["edit"]["changes"][self.uri]),
                             self.text, bad)
            self.c.change(self.uri, version + 1, [{"text": self.text}])
            self.c.wait_diagnostics(self.uri, version=version + 1)

    def test_rename_an_event_keeps_its_status_flag(self):
        edit = self.c.request("textDocument/rename", dict(self.at("not e_taken", 0, 4),
                                                          newName="e_holding"))
        renamed = apply_edits(self.text, edit["changes"][self.uri])
        self.assertIn('events from PickAndPlace.status { e_holding = "e_taken", e_arm_idle }',
                      renamed)
        self.assertNotIn("e_taken and", renamed)
        self.assertEqual([d for d in check_json(renamed) if d["severity"] == "error"], [])

    def test_rename_a_rule(self):
        edit = self.c.request("textDocument/rename", dict(self.at("take: from"), newName="grab"))
        renamed = apply_edits(self.text, edit["changes"][self.uri])
        self.assertIn("grab: from", renamed)
        self.assertIn("PickAndPlace.cmd: grab -> not e_taken", renamed)
        self.assertIn("expect only put after grab;", renamed)  # a test's property too
        self.assertEqual(check_json(renamed), [])

    def test_rename_a_rule_reaches_properties_over_time(self):
        text = self.text + ("\nnever two take within 1s;\nonly put after take;\n"
                            "never take while e_taken;\n")
        uri = file_uri(os.path.join(os.path.dirname(SPEC), "never_rename.spec"))
        self.open_spec(text, uri)
        where = {"textDocument": {"uri": uri}, "position": position_of(text, "take: from", 0, 0)}
        edit = self.c.request("textDocument/rename", dict(where, newName="grab"))
        renamed = apply_edits(text, edit["changes"][uri])
        self.assertIn("never two grab within 1s;", renamed)
        self.assertIn("only put after grab;", renamed)
        self.assertIn("never grab while e_taken;", renamed)
        self.assertEqual([d for d in check_json(renamed) if d["severity"] == "error"], [])

    def test_rename_a_constant_everywhere_it_is_used(self):
        """Each constant of each spec in specs/, renamed: every use goes with it (a duration
        in `within D` too), and arbc check says what it said before."""
        for path in sorted(glob.glob(os.path.join(ROOT, "specs", "*.spec"))):
            text, uri = read(path), file_uri(path)
            if uri != self.uri:
                self.open_spec(text, uri)
            names = re.findall(r"^const (\w+)", text, re.M)
            for name in names:
                with self.subTest(spec=os.path.basename(path), const=name):
                    at = {"textDocument": {"uri": uri},
                          "position": position_of(text, "const " + name, 0, len("const "))}
                    self.assertEqual(self.c.request("textDocument/prepareRename", at),
                                     {"range": {"start": at["position"],
                                                "end": position_of(text, "const " + name, 0,
                                                                   len("const " + name))},
                                      "placeholder": name})
                    edit = self.c.request("textDocument/rename", dict(at, newName="RENAMED"))
                    renamed = apply_edits(text, edit["changes"][uri])
                    code = re.sub(r"//.*", "", renamed)
                    self.assertIsNone(re.search(r"\b%s\b" % name, code), name)
                    self.assertEqual(len(edit["changes"][uri]),
                                     len(re.findall(r"\b%s\b" % name, re.sub(r"//.*", "", text))))
                    self.assertEqual(check_json_at(renamed, path), check_json_at(text, path))
        self.assertIn("never two ask within SPEAK_PERIOD;", self.text)  # what is reached

    def test_rename_a_module_in_every_module_port_with_a_warning(self):
        """A module's name is written in every `Module.port`; all go (from a use as from the
        declaration), comments stay, and a warning says that its plugin keeps the old name."""
        self.open_spec()
        code = re.sub(r"//.*", "", self.text)
        uses = len(re.findall(r"\bPickAndPlace\b", code))
        for needle, offset in (("module PickAndPlace", len("module ")),
                               ("arbitrate PickAndPlace.cmd", len("arbitrate "))):
            with self.subTest(at=needle):
                edit = self.c.request("textDocument/rename",
                                      dict(self.at(needle, 0, offset), newName="Arm"))
                self.assertEqual(list(edit["changes"]), [self.uri])
                renamed = apply_edits(self.text, edit["changes"][self.uri])
                self.assertEqual(len(edit["changes"][self.uri]), uses)
                self.assertIsNone(re.search(r"\bPickAndPlace\b", re.sub(r"//.*", "", renamed)))
                self.assertIn("arbitrate Arm.cmd {", renamed)
                self.assertIn('at 0s     Arm.status <- ["e_arm_idle"];', renamed)
                self.assertEqual(check_json(renamed), [])
                warning = self.c.wait_notification(
                    lambda m: m.get("method") == "window/showMessage")["params"]
                self.assertEqual(warning["type"], 2)
                self.assertIn("module 'PickAndPlace' is now 'Arm' in the spec; its plugin still "
                              "registers it as 'PickAndPlace' (ARBC_REGISTER_MODULE)",
                              warning["message"])

    def test_a_port_is_refused_with_the_reason_before_and_at_the_rename(self):
        at = self.at("PickAndPlace.cmd", 0, len("PickAndPlace."))
        for method, params in (("textDocument/prepareRename", at),
                               ("textDocument/rename", dict(at, newName="command"))):
            with self.subTest(method=method):
                with self.assertRaises(RuntimeError) as e:
                    self.c.request(method, params)
                self.assertEqual(e.exception.args[0], -32803)
                self.assertIn("port 'PickAndPlace.cmd' is not renamed here: its module's plugin",
                              e.exception.args[1])

    def test_prepare_rename_says_why_for_each_kind_it_refuses(self):
        for needle, offset, why in [("PickAndPlace.cmd", len("PickAndPlace."), "port 'PickAndPlace.cmd'"),
                                    ("type Cmd", len("type "), "type 'Cmd'"),
                                    ("app table_clean", len("app "), "the app's name"),
                                    ("let obj", len("let "), "'obj' is a local name")]:
            with self.subTest(needle=needle):
                with self.assertRaises(RuntimeError) as e:
                    self.c.request("textDocument/prepareRename", self.at(needle, 0, offset))
                self.assertIn(why, e.exception.args[1])
        # Where there is no name at all: nothing to rename, not an error.
        self.assertIsNone(self.c.request("textDocument/prepareRename", self.at("arbitrate")))

    def test_rename_refuses_keywords_and_taken_names(self):
        for needle, name, why in [("take: from", "when", "not a name"),
                                  ("take: from", "put", "already rule 'put'"),
                                  ("HAND_REACHABLE", "e_taken", "already event 'e_taken'"),
                                  ("HAND_REACHABLE", "obj", "already local name 'obj'"),
                                  ("HAND_REACHABLE", "TOOL_REACHABLE", "already const"),
                                  ("module PickAndPlace", "PullObject",
                                   "already module 'PullObject'"),
                                  ("module PickAndPlace", "e_taken", "already event 'e_taken'")]:
            with self.subTest(name=name):
                with self.assertRaises(RuntimeError) as e:
                    offset = len("module ") if needle.startswith("module") else 0
                    self.c.request("textDocument/rename", dict(self.at(needle, 0, offset),
                                                               newName=name))
                self.assertIn(why, e.exception.args[1])


class Verification(Session):
    verify = True

    def test_a_counterexample_lands_on_both_rules(self):
        text = self.text.replace("when not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling",
                                 "when e_arm_idle and e_pull_idle and not e_arm_pulling", 1)
        self.c.open(self.uri, text)
        diags = self.c.wait_diagnostics(
            self.uri, accept=lambda ds: any(d.get("code") == "exclusive" for d in ds), timeout=120)
        exclusive = [d for d in diags if d.get("code") == "exclusive"]
        lines = sorted(d["range"]["start"]["line"] for d in exclusive)
        self.assertEqual(lines, sorted([position_of(text, "take: from")["line"],
                                        position_of(text, "put: from")["line"]]))
        for d in exclusive:
            self.assertIn("rules 'take' and 'put' of PickAndPlace.cmd can both be selected",
                          d["message"])
            self.assertIn("event state: e_arm_idle, e_pull_idle, e_take_open, e_taken present",
                          d["message"])

    def test_a_resource_finding_lands_on_each_rule_in_its_own_port(self):
        # Both ports have a rule 'move'. e_a is fed into each port by a feed of its own, so it is
        # two facts (docs/design.md#feeds) and the resource is refuted for every pair of a Left
        # rule and a Right rule: each finding is at the resource and on its two rules, found by
        # port and name (by name alone, each finding naming a 'move' would land on both).
        text = ("app two_moves;\n"
                "module Cam { out target: vec3; out ball: vec3; out status: list<string>; }\n"
                "module Left { in arm: vec3; }\n"
                "module Right { in arm: vec3; }\n"
                "events from Cam.status { e_a } lifetime 1s;\n"
                "arbitrate Left.arm {\n"
                "  move: from Cam.target when e_a;\n"
                "  rest: from Cam.ball when not e_a;\n"
                "}\n"
                "arbitrate Right.arm {\n"
                "  grab: from Cam.ball when e_a;\n"
                "  move: from Cam.target when not e_a;\n"
                "}\n"
                "resource arm { Left.arm, Right.arm };\n")
        uri = file_uri(os.path.join(os.path.dirname(SPEC), "two_moves.spec"))
        self.c.open(uri, text)
        diags = self.c.wait_diagnostics(
            uri, accept=lambda ds: any(d.get("code") == "resource" for d in ds), timeout=120)
        self.assertEqual([d for d in diags if d.get("code") != "resource"], [])
        line = lambda needle, n=0: position_of(text, needle, n)["line"]  # noqa: E731
        resource = line("resource arm")
        rules = {line("move: from"): ("move", "Left.arm"), line("rest: from"): ("rest", "Left.arm"),
                 line("grab: from"): ("grab", "Right.arm"),
                 line("move: from", 1): ("move", "Right.arm")}
        self.assertEqual(sorted(d["range"]["start"]["line"] for d in diags),
                         sorted([resource] * 4 + list(rules) * 2))
        for d in diags:
            at = d["range"]["start"]["line"]
            if at == resource:
                continue
            name, port = rules[at]
            with self.subTest(rule=name, port=port):
                self.assertIn(f"'{name}' (into {port})", d["message"])
                # The note names the other rule of the pair, at its own line.
                other = d["relatedInformation"][0]
                self.assertIn("the other rule", other["message"])
                self.assertIn(f"'{rules[other['location']['range']['start']['line']][0]}'",
                              other["message"])

    # A gripper: the planner may deliver any force, the pendant only what its accept allows.
    GRIPPER = ("app gripper;\n"
               "type Grip = { width: float, force: float };\n"
               "module Pendant { out grip: Grip; }\n"
               "module Planner { out grip: Grip; }\n"
               "module Gripper { in cmd: Grip; }\n"
               "event e_pendant;\n"
               "arbitrate Gripper.cmd {\n"
               "  pendant: from Pendant.grip { set e_pendant for 2s; accept grip.force <= 60.0; }\n"
               "  plan: from Planner.grip when not e_pendant;\n"
               "}\n")

    def open_gripper(self, extra, code):
        text = self.GRIPPER + extra
        # Never saved: the proof and its replays work from the editor's text.
        uri = file_uri(os.path.join(os.path.dirname(SPEC), SCRATCH_PREFIX + "gripper.spec"))
        self.c.open(uri, text)
        diags = self.c.wait_diagnostics(
            uri, accept=lambda ds: any(d.get("code") == code for d in ds), timeout=120)
        return text, diags

    def test_an_assert_that_can_fail_lands_on_its_rule_too(self):
        text, diags = self.open_gripper("assert Gripper.cmd: plan -> emitted.force <= 60.0;\n",
                                        "assert")
        asserts = [d for d in diags if d.get("code") == "assert"]
        self.assertEqual(sorted(d["range"]["start"]["line"] for d in asserts),
                         sorted([position_of(text, "assert Gripper")["line"],
                                 position_of(text, "plan: from")["line"]]))
        for d in asserts:
            self.assertIn("'plan' can deliver a value for which the property is false",
                          d["message"])
            related = " | ".join(r["message"] for r in d["relatedInformation"])
            # Replayed through the generated monitor, as `arbc verify` does.
            self.assertIn("replayed through the Lua monitors: 'plan' accepts it", related)

    def test_a_violated_property_over_time_shows_its_replayed_trace(self):
        text, diags = self.open_gripper("never two plan within 1s;\n", "temporal")
        [d] = [d for d in diags if d.get("code") == "temporal"]
        self.assertEqual(d["severity"], 1)
        self.assertEqual(d["range"]["start"]["line"], position_of(text, "never two")["line"])
        self.assertIn("never two plan within 1s", d["message"])
        self.assertIn("violated: a shortest trace of 2 messages into Gripper.cmd", d["message"])
        self.assertIn("replayed on the runtime in simulated time", d["message"])
        # One line per step and sentence, for the editor's float to wrap; the file:line is the
        # diagnostic's place, not text; the replayed tests file is there to copy.
        self.assertRegex(d["message"], r"(?m)^at \S+: \S+ -> plan: accepted, delivered$")
        self.assertNotIn("\n    ", d["message"])
        self.assertNotIn("gripper.spec:", d["message"])
        self.assertIn('tests for "', d["message"])

    def test_a_proofs_summary_goes_to_the_clients_log_not_stderr(self):
        # Neovim records each line of a server's stderr as an [ERROR] in its lsp.log.
        self.open_spec()
        logged = self.c.wait_notification(
            lambda m: m.get("method") == "window/logMessage", timeout=120)["params"]
        self.assertEqual(logged["type"], 4)
        self.assertIn("proved: 4 arbitrated ports, 0 errors", logged["message"])
        self.assertEqual(self.c.shutdown_and_exit(), 0)
        self.assertEqual(self.c.stderr_after_exit(), "")

    def test_a_proved_spec_gets_no_findings_on_save(self):
        self.assertEqual(self.open_spec(), [])
        self.c.notify("textDocument/didSave", {"textDocument": {"uri": self.uri}})
        # The proof publishes again; still nothing.
        self.assertEqual(self.c.wait_diagnostics(self.uri, timeout=120), [])


class Robustness(Session):
    def test_garbage_gets_errors_and_the_server_goes_on(self):
        self.c.send_raw(b"Content-Length: 5\r\n\r\n{nope")
        self.c.send_raw(b"X-Nothing: 1\r\n\r\n")  # no Content-Length: skipped
        self.c.send({"jsonrpc": "2.0", "id": 99, "method": "textDocument/nosuch", "params": {}})
        self.assertEqual(self.c.response(99)["error"]["code"], -32601)
        with self.assertRaises(RuntimeError) as e:
            self.c.request("textDocument/hover", {"textDocument": {"uri": 5}})
        self.assertEqual(e.exception.args[0], -32602)
        with self.assertRaises(RuntimeError) as e:
            self.c.request("textDocument/hover", {"textDocument": {"uri": "file:///not/open.spec"},
                                                  "position": {"line": 0, "character": 0}})
        self.assertEqual(e.exception.args[0], -32602)
        self.c.notify("textDocument/didChange", {"textDocument": {"uri": 7}})
        self.c.send_raw(b"Content-Length: 7\r\n\r\n[1,2,3]")  # a batch: not supported
        self.assertEqual(self.c.response(None)["error"]["code"], -32700)
        self.c.send({"jsonrpc": "2.0", "id": 98, "method": 12})
        self.assertEqual(self.c.response(98)["error"]["code"], -32600)
        not_utf8 = b'{"id": 1, "x": "\xff"}'
        self.c.send_raw(b"Content-Length: %d\r\n\r\n" % len(not_utf8) + not_utf8)
        self.assertEqual(self.c.response(None)["error"]["code"], -32700)
        self.assertEqual(self.open_spec(), [])
        # Requests on the open document with parameters of the wrong shape.
        for method, params in [
                ("textDocument/hover", {"textDocument": {"uri": self.uri}, "position": "x"}),
                ("textDocument/hover", {"textDocument": {"uri": self.uri},
                                        "position": {"line": 10**12, "character": -5}}),
                ("textDocument/codeAction", {"textDocument": {"uri": self.uri}, "range": {}}),
                ("textDocument/codeAction", {"textDocument": {"uri": self.uri}, "range": 3}),
                ("textDocument/rename", {"textDocument": {"uri": self.uri},
                                         "position": {"line": 0, "character": 0}}),
                ("textDocument/references", {"textDocument": {"uri": self.uri},
                                             "position": {"line": 3}, "context": 5})]:
            with self.subTest(method=method, params=params):
                try:
                    self.c.request(method, params)
                except RuntimeError as e:
                    self.assertIn(e.args[0], (-32602, -32803))
        self.assertIn("**rule**", self.c.request("textDocument/hover",
                                                 self.at("take: from"))["contents"]["value"])
        self.assertIsNone(self.c.proc.poll())

    def test_a_huge_document_does_not_stop_the_others(self):
        # 20000 lines (a table_clean is 100): checked, and the small spec opened after it
        # still gets its diagnostics and hover.
        huge = 'app huge "x";\nmodule M { in p: int; }\n' + "".join(
            f"event e{i};\n" for i in range(20000)) + "event e0;\n"
        big_uri = file_uri(os.path.join(ROOT, "specs", "huge.spec"))
        self.c.open(big_uri, huge)
        self.assertEqual(self.open_spec(), [])
        self.assertIn("**rule**", self.c.request("textDocument/hover",
                                                 self.at("take: from"))["contents"]["value"])
        big = self.c.wait_diagnostics(big_uri, timeout=300)
        self.assertEqual([(d["code"], d["range"]["start"]["line"]) for d in big],
                         [("duplicate", 20002)])

    def test_every_request_at_every_position_answers(self):
        """Every position request at every other column of table_clean, and of a copy with a
        syntax error (the index is then of the last text that parsed): an answer each time."""
        broken = self.text.replace("module Speak", "modle Speak", 1)
        for version, text in ((1, self.text), (2, broken)):
            if version == 1:
                self.open_spec()
            else:
                self.c.change(self.uri, 2, [{"text": broken}])
                self.assertTrue(self.c.wait_diagnostics(self.uri, version=2))
            answered = 0
            for line, content in enumerate(text.split("\n")):
                for character in range(0, len(content) + 2, 2):
                    where = {"textDocument": {"uri": self.uri},
                             "position": {"line": line, "character": character}}
                    ids = [self.c.request_async(m, where) for m in (
                        "textDocument/hover", "textDocument/definition",
                        "textDocument/documentHighlight", "textDocument/completion",
                        "textDocument/prepareRename")]
                    ids.append(self.c.request_async("textDocument/references",
                                                    dict(where, context={})))
                    for rid in ids:
                        answer = self.c.response(rid)
                        # prepareRename refuses some names (a module's), saying why.
                        if rid == ids[4] and "error" in answer:
                            self.assertEqual(answer["error"]["code"], -32803, (line, character))
                            self.assertTrue(answer["error"]["message"], (line, character))
                        else:
                            self.assertNotIn("error", answer, (line, character))
                        answered += 1
            self.assertGreater(answered, 5000)

    def test_rename_waits_for_text_that_parses(self):
        self.open_spec()
        self.c.change(self.uri, 2, [{"text": self.text + "modle X { }\n"}])
        self.assertTrue(self.c.wait_diagnostics(self.uri, version=2))
        at = self.at("take: from")  # the index of the last text that parsed still knows it
        self.assertIsNotNone(self.c.request("textDocument/hover", at))
        for method, params in (("textDocument/prepareRename", at),
                               ("textDocument/rename", dict(at, newName="grab"))):
            with self.assertRaises(RuntimeError) as e:
                self.c.request(method, params)
            self.assertIn("does not parse now", e.exception.args[1])

    def test_a_document_over_the_limit_is_an_io_diagnostic(self):
        huge = "// " + "x" * (64 << 20) + "\n"  # 64 MiB and a bit: arbc check's limit
        big_uri = file_uri(os.path.join(ROOT, "specs", "too_big.spec"))
        self.c.open(big_uri, huge)
        diags = self.c.wait_diagnostics(big_uri, timeout=120)
        self.assertEqual([d["code"] for d in diags], ["io"])
        self.assertIn("larger than 64 MiB", diags[0]["message"])
        self.assertEqual(self.open_spec(), [])

    def test_deep_nesting_is_a_diagnostic(self):
        text = self.text + "\nconst DEEP = " + "(" * 5000 + "1" + ")" * 5000 + ";\n"
        diags = self.open_spec(text)
        self.assertTrue(diags)

    def test_the_parser_cache_is_reset_between_documents(self):
        self.open_spec()
        other = file_uri(os.path.join(ROOT, "specs", "face_filter.spec"))
        self.open_spec(read(os.path.join(ROOT, "specs", "face_filter.spec")), uri=other)
        status = self.c.request("arbc/status", None)
        self.assertGreaterEqual(status["parserCacheResets"], 1)


def close_quietly(proc):
    """Closes a finished server's pipes. Bytes a broken pipe left in stdin's buffer are dropped:
    the server is gone, so flushing them raises BrokenPipeError (seen in CI)."""
    for stream in (proc.stdin, proc.stdout, proc.stderr):
        try:
            stream.close()
        except BrokenPipeError:
            pass


class ClientGone(unittest.TestCase):
    """A client that disappears: the server exits 1 (no `shutdown`), never hangs or dies of a
    signal, and says why on stderr."""

    def start(self, process_id=None):
        proc = subprocess.Popen([ARBC, "lsp", "--no-verify"], stdin=subprocess.PIPE,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        body = json.dumps({"jsonrpc": "2.0", "id": 1, "method": "initialize",
                           "params": {"processId": process_id, "capabilities": {}}}).encode()
        proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        proc.stdin.flush()
        header = proc.stdout.readline()
        self.assertTrue(header.startswith(b"Content-Length:"), header)
        return proc

    def finish(self, proc, why):
        try:
            code = proc.wait(timeout=30)
        finally:
            if proc.poll() is None:
                proc.kill()
        err = proc.stderr.read().decode()
        close_quietly(proc)
        self.assertEqual(code, 1, err)
        self.assertIn(why, err)

    def test_input_ends_inside_a_message(self):
        proc = self.start()
        proc.stdin.write(b"Content-Length: 100\r\n\r\n{\"jsonrpc\"")
        proc.stdin.close()
        self.finish(proc, "the input ended inside a message body")

    def test_the_client_stops_reading(self):
        proc = self.start()
        proc.stdout.close()
        body = json.dumps({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}).encode()
        for _ in range(3):  # the first answer may still fit in the pipe's buffer
            try:
                proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
                proc.stdin.flush()
            except BrokenPipeError:
                break
        self.finish(proc, "the client stopped reading")

    def test_the_client_process_is_gone(self):
        client = subprocess.Popen(["sleep", "0.5"])
        proc = self.start(process_id=client.pid)
        client.wait()  # gone and reaped; the server's pipes stay open
        self.finish(proc, "the client's process %d is gone" % client.pid)


if __name__ == "__main__":
    ARBC = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
