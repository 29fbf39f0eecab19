#!/usr/bin/env python3
"""Command-line input a new user gets wrong: each case runs arbc and checks the exit code and
the words of the message (issue 13, "Smaller things a new user hit", and `arbc verify` on input
with errors).

usage: check_cli_input.py ARBC TEST_PLUGIN CASE        (run from the repository root)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

PINGPONG = "runtime/testdata/pingpong"


def run(arbc, *args, cwd=None):
    proc = subprocess.run([arbc, *args], capture_output=True, text=True, timeout=120, cwd=cwd)
    return proc.returncode, proc.stdout, proc.stderr


def expect(cond, what, out="", err=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


def expect_bad_input(result, *words):
    code, out, err = result
    expect(code == 2, f"exit {code}, expected 2", out, err)
    for w in words:
        expect(w in err, f"stderr lacks {w!r}", out, err)
    expect(len(err) < 400, "the message is not short", out, err)


def case_seed_negative(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--seed", "-1"),
                     "--seed '-1' is not a whole number from 0 to 18446744073709551615")


def case_seed_too_large(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin,
                         "--seed", "18446744073709551616"), "--seed '18446744073709551616'")


def case_duration_without_unit(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--duration", "5"),
                     "--duration '5' is not a positive duration with its unit",
                     "(write 5s for seconds)")


def case_duration_in_hours(arbc, plugin):
    code, out, err = run(arbc, "run", "specs/face_filter.spec", "--stub", "--duration", "0.001h")
    expect(code == 0 and "simulated time 3.600 s" in out, f"exit {code}", out, err)


def case_run_line_fits_a_short_run(arbc, plugin):
    # In the unit of the run's length, as the run report writes it ("0.500 s" before).
    code, out, err = run(arbc, "run", "specs/face_filter.spec", "--stub", "--duration", "500ms")
    expect(code == 0 and "simulated time 500.0 ms" in out, f"exit {code}", out, err)


def case_stub_publishes_the_flags_feeds_read(arbc, plugin):
    """A stand-in status port publishes the flag a feed maps (`e_idle = "idle"`), not the event's
    name, which no feed reads: before, nothing was delivered and the run said success (issue 39)."""
    with tempfile.TemporaryDirectory() as d:
        spec = os.path.join(d, "flag.spec")
        with open(spec, "w") as f:
            f.write('app stub_flag;\n'
                    'module Arm { out status: list<string>; }\n'
                    'module Planner { out cmd: float; }\n'
                    'module Base { in cmd: float; }\n'
                    'events from Arm.status { e_idle = "idle" } lifetime 500ms;\n'
                    'arbitrate Base.cmd { go: from Planner.cmd when e_idle; }\n')
        code, out, err = run(arbc, "run", spec, "--stub", "--duration", "3s")
        row = next((ln.split() for ln in out.splitlines() if ln.startswith("go ")), None)
        expect(code == 0 and row is not None, f"exit {code}, no row for go", out, err)
        arrived, delivered = int(row[1]), int(row[2])
        # Each flag holds in half of the samples (runtime/stand_in.cc), so with 10 Hz samples and a
        # 500 ms lifetime nearly every command finds e_idle present: more than a third delivered.
        expect(3 * delivered > arrived > 0, f"go delivered {delivered} of {arrived}", out, err)


def case_stub_reaches_the_thresholds_conditions_test(arbc, plugin):
    """--stub draws a compared part around the spec's constants: a 45 dB threshold is crossed in
    a few seconds, both ways, the same in every run of a seed (issue 39: floats stayed in [0, 1)
    and e_loud was never set)."""
    with tempfile.TemporaryDirectory() as d:
        spec = os.path.join(d, "loud.spec")
        with open(spec, "w") as f:
            f.write('app stub_loud;\n'
                    'module Mic { out level: { db: float, source: string }; }\n'
                    'module Planner { out cmd: float; }\n'
                    'module Base { in cmd: float; }\n'
                    'event e_loud = Mic.level : level.db > 45.0;\n'
                    'event e_voice = Mic.level : level.source == "voice";\n'
                    'arbitrate Base.cmd { go: from Planner.cmd when not e_loud and not e_voice; }\n')
        traces = []
        for name in ("a.jsonl", "b.jsonl"):
            trace = os.path.join(d, name)
            code, out, err = run(arbc, "run", spec, "--stub", "--duration", "3s", "--trace", trace)
            expect(code == 0, f"exit {code}", out, err)
            traces.append(open(trace).read())
        expect(traces[0] == traces[1], "two runs of one seed differ", out, err)
        records = [json.loads(line) for line in traces[0].splitlines()]
        levels = [r["value"] for r in records
                  if r["type"] == "publish" and r["port"] == "Mic.level"]
        sets = {r["event"] for r in records if r["type"] == "event" and r["op"] == "set"}
        expect({"e_loud", "e_voice"} <= sets, f"events set: {sorted(sets)}", out, err)
        expect(any(v["db"] <= 45 for v in levels) and any(v["db"] > 45 for v in levels),
               "db not drawn on both sides of 45", out, err)
        row = next((ln.split() for ln in out.splitlines() if ln.startswith("go ")), None)
        expect(row is not None and int(row[2]) > 0, "go never delivered", out, err)


def case_duration_unit_unknown(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--duration", "3d"),
                     "--duration '3d' is not a positive duration with its unit: 'd' is not a "
                     "unit of time; the units are ms, s, min or h")


def case_times_share_one_parser(arbc, plugin):
    """The other options that take a time take the same units, and say the same of a bad one."""
    code, out, err = run(arbc, "verify", "--timeout", "2min", "tests/verify/table_clean.app.json")
    expect(code == 0, f"verify --timeout 2min: exit {code}", out, err)
    for command in (["verify", "tests/verify/table_clean.app.json"], ["lsp"],
                    ["run", PINGPONG, "--plugin", plugin, "--transport", "dds"]):
        option = "--wait-peers" if command[0] == "run" else "--timeout"
        expect_bad_input(run(arbc, *command, option, "3d"),
                         f"{option}: '3d' is not a ",
                         "'d' is not a unit of time; the units are ms, s, min or h")
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--transport", "dds",
                         "--wait-peers", "2h"), "--wait-peers must be from 0 to 3600 seconds")


def case_timeout_zero(arbc, plugin):
    expect_bad_input(run(arbc, "verify", "--timeout", "0", "tests/verify/table_clean.app.json"),
                     "--timeout: '0' is not a positive number of seconds")


def case_ros_domain_id_not_a_domain(arbc, plugin):
    # Refused before any DDS entity exists, so no DDS traffic: atoi read "abc" as domain 0.
    spec = "tests/dds/interop/teleop.spec"
    for value in ("abc", "7x", "300"):
        env = dict(os.environ, ROS_DOMAIN_ID=value)
        proc = subprocess.run([arbc, "run", spec, "--transport", "dds", "--host", "none",
                               "--duration", "1s"], capture_output=True, text=True, env=env,
                              timeout=120)
        expect_bad_input((proc.returncode, proc.stdout, proc.stderr),
                         f"ROS_DOMAIN_ID='{value}' is not a DDS domain, a whole number from 0 "
                         "to 232 (give --domain N, or unset ROS_DOMAIN_ID for domain 0)")
    expect_bad_input(run(arbc, "run", spec, "--transport", "dds", "--domain", "233"),
                     "--domain 233 is not a DDS domain, a whole number from 0 to 232")


def case_no_peer_after_not_a_time(arbc, plugin):
    # Refused before any DDS entity exists: the variable only sets when topics without a peer
    # are first reported.
    for value in ("abc", "0", "-1", "5s"):
        env = dict(os.environ, ARBC_DDS_NO_PEER_AFTER=value)
        proc = subprocess.run([arbc, "run", PINGPONG, "--plugin", plugin, "--transport", "dds",
                               "--duration", "1s"], capture_output=True, text=True, env=env,
                              timeout=120)
        expect_bad_input((proc.returncode, proc.stdout, proc.stderr),
                         f"ARBC_DDS_NO_PEER_AFTER='{value}' is not a number of seconds above 0")


def case_run_errors_name_what_they_are_about(arbc, plugin):
    """An error of creating the run names what it is about; only one about app.json's content
    names app.json (it used to prefix them all: "DIR/app.json: DDS: ...")."""
    with tempfile.TemporaryDirectory() as d:
        trace = os.path.join(d, "no", "such", "dir", "trace.jsonl")
        code, out, err = run(arbc, "run", PINGPONG, "--plugin", plugin, "--trace", trace)
        expect_bad_input((code, out, err), f"arbc run: error: cannot write trace file {trace}")
        expect("app.json" not in err, "a trace file error names app.json", out, err)

        code, out, err = run(arbc, "run", PINGPONG, "--plugin", plugin, "--scenario", "nope")
        expect_bad_input((code, out, err), "arbc run: error: unknown scenario 'nope'")
        expect("app.json" not in err, "an unknown scenario names app.json", out, err)

        # No environment to play a scenario (stand-ins only): refused, not ignored.
        code, out, err = run(arbc, "run", PINGPONG, "--stub", "--scenario", "stuck")
        expect_bad_input((code, out, err), "arbc run: error: --scenario 'stuck': this run has "
                         "no environment to play it (no plugin registers one); load the plugin")

        # A profile that is not there: refused when the transport opens, before any DDS entity.
        env = dict(os.environ, FASTRTPS_DEFAULT_PROFILES_FILE=os.path.join(d, "missing.xml"))
        proc = subprocess.run([arbc, "run", PINGPONG, "--plugin", plugin, "--transport", "dds",
                               "--duration", "1s"], capture_output=True, text=True, env=env,
                              timeout=120)
        result = (proc.returncode, proc.stdout, proc.stderr)
        expect_bad_input(result, "arbc run: error: DDS: FASTRTPS_DEFAULT_PROFILES_FILE names")
        expect("app.json" not in proc.stderr, "a DDS error names app.json", *result[1:])

        # A connection from a port the app lacks is about app.json's content: it names app.json.
        app = os.path.join(d, "app")
        shutil.copytree(PINGPONG, app)
        with open(os.path.join(app, "app.json")) as f:
            text = f.read()
        with open(os.path.join(app, "app.json"), "w") as f:
            f.write(text.replace('"source": "Ticker.count"', '"source": "Ticker.counter"'))
        code, out, err = run(arbc, "run", app, "--plugin", plugin, "--no-verify")
        expect_bad_input((code, out, err), f"arbc run: error: {app}/app.json: connection 'go': "
                         "source Ticker.counter is not an output port of a module in the app")


def case_run_takes_app_json(arbc, plugin):
    code, out, err = run(arbc, "run", PINGPONG + "/app.json", "--plugin", plugin)
    expect(code == 0 and "result: success" in out, f"exit {code}", out, err)


def case_malformed_app_json(arbc, plugin):
    with tempfile.TemporaryDirectory() as d:
        os.mkdir(os.path.join(d, "monitors"))
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write('{\n  "schema_version": 1,\n  "name": "x",,\n}\n')
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        # As a compiler reports a spec: file:line:col, the line quoted, a caret at the fault.
        expect_bad_input((code, out, err), f"{d}/app.json:3:15: error: not valid JSON: syntax "
                         "error while parsing object key",
                         '\n    "name": "x",,\n                ^\n')
        expect(err.count("rebuild") == 1, "the rebuild hint is not given exactly once", out, err)
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write(json.dumps({"schema_version": 99}))
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        expect_bad_input((code, out, err), f"{d}/app.json:1:20: error: schema_version: this arbc "
                         "reads version 2, the file has 99")
        expect(err.count("rebuild") == 1, "the rebuild hint is not given exactly once", out, err)
        # A value of the wrong kind is pointed at; a key given twice is refused at the second.
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write('{\n  "schema_version": 2,\n  "name": 5\n}\n')
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        expect_bad_input((code, out, err), f"{d}/app.json:3:11: error: name: expected a string",
                         "\n    \"name\": 5\n            ^\n")
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write('{\n  "schema_version": 2,\n  "name": "x",\n  "name": "y"\n}\n')
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        expect_bad_input((code, out, err), f"{d}/app.json:4:3: error: key \"name\" repeated in "
                         "one object (the first is at line 3)")


def case_script_error_cites_the_script(arbc, plugin):
    code, out, err = run(arbc, "run", "tests/cli_input/script_error/script_error.spec",
                         "--plugin", plugin, "--duration", "3s")
    expect(code == 3, f"exit {code}, expected 3 (a quarantined connection)", out, err)
    expect("accept failed: tests/cli_input/script_error/go.lua:3: too many: 3" in err,
           "the error does not cite go.lua:3", out, err)
    expect("monitors/" not in err, "an error cites the generated monitor", out, err)


def case_dds_placement_mistakes(arbc, plugin):
    """A newcomer's --host and --mediate: a misspelt module is named with the one meant, and
    a process that would run nothing (--host none without --mediate) is refused, not left to
    run its whole duration idle."""
    spec = "tests/dds/interop/teleop.spec"
    expect_bad_input(run(arbc, "run", spec, "--transport", "dds", "--host", "Jog"),
                     "--host 'Jog': 'Jog' is not a module of app teleop; did you mean 'Joy'? "
                     "(its modules: Joy, Nav, Base; or write all, none)")
    expect_bad_input(run(arbc, "run", spec, "--transport", "dds", "--host", "none",
                         "--mediate", "Bsae"),
                     "--mediate 'Bsae': 'Bsae' is not a module of app teleop; did you mean "
                     "'Base'?")
    expect_bad_input(run(arbc, "run", spec, "--transport", "dds", "--host", "none",
                         "--duration", "1s"),
                     "arbc run: error: this process hosts no module and mediates none, so it "
                     "would do nothing; give --mediate all (or the modules whose connections "
                     "run here) for a mediator, or --host the modules it runs")
    # Simulated time is read from /clock, which only a DDS run has.
    expect_bad_input(run(arbc, "run", spec, "--use-sim-time", "--duration", "1s"),
                     "--use-sim-time needs --transport dds (the in-process transport runs "
                     "every module here)")


def case_dds_field_order(arbc, plugin):
    """A spec Twist with geometry_msgs/msg/Twist's fields in another order: both are Vector3,
    so every sample would decode, each rule reading `angular` for `linear`. Refused at the
    deployment's mapping, before any DDS entity exists."""
    folder = tempfile.mkdtemp(prefix="arbc-field-order-")
    spec = os.path.join(folder, "teleop.spec")
    text = open("tests/dds/interop/teleop.spec").read()
    swapped = text.replace("type Twist = { linear: vec3, angular: vec3 };",
                           "type Twist = { angular: vec3, linear: vec3 };")
    expect(swapped != text, "teleop.spec no longer declares Twist as this case expects")
    open(spec, "w").write(swapped)
    deploy = "tests/dds/interop/teleop.deploy.json"
    code, out, err = run(arbc, "run", spec, "--transport", "dds", "--host", "none", "--mediate",
                         "all", "--deploy", deploy, "--duration", "1s")
    shutil.rmtree(folder)
    expect(code == 2, f"exit {code}, expected 2", out, err)
    line = next(i for i, t in enumerate(open(deploy).read().splitlines(), 1) if '"Twist":' in t)
    expect(f"{deploy}:{line}:14: error: types: \"Twist\": the spec's Twist does not lay out as "
           "geometry_msgs/msg/Twist: the spec lists its fields angular, linear, but "
           "geometry_msgs/msg/Twist has them in the order linear, angular; the bytes come in the "
           "message's order and nothing on the wire names a field, so each would be read as "
           "another: list them in the message's order" in err,
           "the field order is not named at the mapping", out, err)


STAMPED_SPEC = """app stamped;
type Time = { sec: int, nanosec: int };
type Header = { stamp: Time, frame_id: string };
type Twist = { linear: vec3, angular: vec3 };
type TwistStamped = { header: Header, twist: Twist };
module Nav { out cmd_vel: TwistStamped; }
module Base { in cmd_vel: TwistStamped; }
arbitrate Base.cmd_vel { nav: from Nav.cmd_vel; }
"""


def case_dds_stamp_of_ints(arbc, plugin):
    """Issue 41: a TwistStamped whose stamp is declared with `int` fields is 16 bytes where ROS 2's
    is 8: refused at the mapping, against arbc's own definitions; and against a .msg file on
    --msg-path, which comes first (here a Time of two int64s, which the spec then matches)."""
    folder = tempfile.mkdtemp(prefix="arbc-stamp-")
    spec = os.path.join(folder, "stamped.spec")
    open(spec, "w").write(STAMPED_SPEC)
    deploy = os.path.join(folder, "stamped.deploy.json")
    open(deploy, "w").write('{\n  "ros2": true,\n  "types": {\n    "TwistStamped": '
                            '"geometry_msgs/msg/TwistStamped"\n  }\n}\n')
    args = ["run", spec, "--transport", "dds", "--host", "none", "--mediate", "all", "--deploy",
            deploy, "--duration", "1s"]
    code, out, err = run(arbc, *args)
    expect(code == 2, f"exit {code}, expected 2", out, err)
    expect(f"{deploy}:4:21: error: types: \"TwistStamped\": the spec's TwistStamped does not "
           "lay out as geometry_msgs/msg/TwistStamped: header.stamp.sec is int (int64, 8 bytes) "
           "in the spec and int32 (4 bytes) in the message: declare it int32"
           in err, "the stamp's width is not named at the mapping", out, err)
    msgs = os.path.join(folder, "msgs")
    os.makedirs(os.path.join(msgs, "builtin_interfaces", "msg"))
    open(os.path.join(msgs, "builtin_interfaces", "msg", "Time.msg"), "w").write(
        "# not ROS 2's: two int64\nint64 sec\nint64 nanosec\n")
    sys.path.insert(0, "tests/dds")
    from dds_domain import Domain  # a domain of its own while the mediator runs
    held = Domain()
    code, out, err = run(arbc, *args, "--msg-path", msgs, "--domain", str(held.id))
    del held
    shutil.rmtree(folder)
    expect(code == 0 and "does not lay out" not in err,
           f"exit {code}: the .msg file on --msg-path was not read", out, err)


RANGE_MSG = """# sensor_msgs/msg/Range
uint8 ULTRASOUND=0
std_msgs/Header header
uint8 radiation_type
float32 field_of_view
float32 min_range
float32 max_range
float32 range
"""

RANGE_SPEC = """app sonar;
use ros2 sensor_msgs/msg/Range;
module Sonar { out range: Range; }
module Base { in range: Range; }
arbitrate Base.range { near: from Sonar.range { accept range.range < 0.5; } }
"""


def msg_folder(folder):
    """A folder of packages holding sensor_msgs/msg/Range.msg."""
    msgs = os.path.join(folder, "msgs")
    os.makedirs(os.path.join(msgs, "sensor_msgs", "msg"))
    open(os.path.join(msgs, "sensor_msgs", "msg", "Range.msg"), "w").write(RANGE_MSG)
    return msgs


def case_use_ros2_msg_path(arbc, plugin):
    """Issue 41: `use ros2` finds a message on --msg-path, on every command that reads a spec;
    without the folder, the error says where it looked and how to add one."""
    folder = tempfile.mkdtemp(prefix="arbc-use-ros2-")
    spec = os.path.join(folder, "sonar.spec")
    open(spec, "w").write(RANGE_SPEC)
    msgs = msg_folder(folder)
    env_backup = {k: os.environ.pop(k) for k in ("ARBC_MSG_PATH", "AMENT_PREFIX_PATH")
                  if k in os.environ}
    try:
        code, out, err = run(arbc, "check", spec)
        expect(code == 2 and "sonar.spec:2:10: error: no definition of sensor_msgs/msg/Range on "
               "the message path; the message path is empty: give the folder that holds "
               "sensor_msgs/msg/ with --msg-path DIR" in err, f"exit {code}, or not said", out, err)
        expect(err.count("error:") == 1, "the ports of the type are errors too", out, err)
        for command in (["check"], ["verify"], ["docs", "-o", os.path.join(folder, "docs")]):
            code, out, err = run(arbc, *command, spec, "--msg-path", msgs)
            expect(code == 0, f"arbc {command[0]} --msg-path: exit {code}", out, err)
        out_dir = os.path.join(folder, "out")
        code, out, err = run(arbc, "build", spec, "--msg-path", msgs, "-o", out_dir)
        expect(code == 0, f"arbc build --msg-path: exit {code}", out, err)
        types = {t["name"]: t for t in json.load(open(os.path.join(out_dir, "sonar", "app.json")))
                 ["types"]}
        expect(types["Range"].get("ros2") == "sensor_msgs/msg/Range" and
               types["Header"].get("ros2") == "std_msgs/msg/Header" and
               types["Range"]["type"].startswith("{header: {stamp: {sec: int32, nanosec: uint32}"),
               f"app.json's types do not name their messages: {types}", out, err)
        os.environ["ARBC_MSG_PATH"] = msgs  # the environment alone does as well
        code, out, err = run(arbc, "check", spec)
        expect(code == 0, f"arbc check with ARBC_MSG_PATH: exit {code}", out, err)
    finally:
        os.environ.pop("ARBC_MSG_PATH", None)
        os.environ.update(env_backup)
        shutil.rmtree(folder)


def case_import_ros2_msg(arbc, plugin):
    """Issue 41: `arbc import ros2-msg` writes the records `use ros2` declares, which check as a
    spec; a folder with no .msg file, or a .msg file that does not parse, writes nothing."""
    folder = tempfile.mkdtemp(prefix="arbc-import-ros2-")
    msgs = msg_folder(folder)
    types = os.path.join(folder, "types.spec")
    for given in (msgs, os.path.join(msgs, "sensor_msgs"),
                  os.path.join(msgs, "sensor_msgs", "msg", "Range.msg")):
        code, out, err = run(arbc, "import", "ros2-msg", given, "-o", types)
        expect(code == 0, f"arbc import ros2-msg {given}: exit {code}", out, err)
        text = open(types).read()
        for line in ("type Time = { sec: int32, nanosec: uint32 };",
                     "type Header = { stamp: Time, frame_id: string };",
                     "type Range = { header: Header, radiation_type: uint8, field_of_view: float32, "
                     "min_range: float32, max_range: float32, range: float32 };"):
            expect(line in text, f"the import of {given} lacks {line!r}", text, err)
        expect(text.index("type Time") < text.index("type Header") < text.index("type Range"),
               "a message comes before one it uses", text, err)
        expect(folder not in text, "the written spec holds a path of this machine", text, err)
    spec = os.path.join(folder, "sonar.spec")
    open(spec, "w").write(RANGE_SPEC.replace("use ros2 sensor_msgs/msg/Range;\n", text))
    code, out, err = run(arbc, "check", spec)
    expect(code == 0, f"the imported types do not check: exit {code}", out, err)
    os.remove(types)
    expect_bad_input(run(arbc, "import", "ros2-msg", folder + "/nothing", "-o", types),
                     "no such file or folder", "nothing written")
    open(os.path.join(msgs, "sensor_msgs", "msg", "Bad.msg"), "w").write("float64 x\nint32\n")
    expect_bad_input(run(arbc, "import", "ros2-msg", msgs, "-o", types),
                     "sensor_msgs/msg/Bad cannot be read (", "Bad.msg:2", "nothing written")
    expect(not os.path.exists(types), "a failed import wrote its output")
    shutil.rmtree(folder)


def case_misspelt_command(arbc, plugin):
    # `arbc verfy`: the command meant, then the usage; a word close to none gets the usage alone.
    code, out, err = run(arbc, "verfy", "specs/table_clean.spec")
    expect(code == 2, f"exit {code}, expected 2", out, err)
    expect(err.startswith("arbc: unknown command 'verfy': did you mean 'verify'?\n\nusage: "),
           "no suggestion above the usage", out, err)
    code, out, err = run(arbc, "frobnicate")
    expect(code == 2 and err.startswith("arbc: unknown command 'frobnicate'\n\nusage: "),
           "a far word gets more than the usage", out, err)


def case_misspelt_option(arbc, plugin):
    # `--frmat`: the option meant, in the command's name; its value may come along as an extra.
    code, out, err = run(arbc, "check", "--frmat", "json", "specs/table_clean.spec")
    expect_bad_input((code, out, err),
                     "arbc check: there is no option --frmat: did you mean '--format'?\n")
    code, out, err = run(arbc, "run", "specs/table_clean.spec", "--seeed", "3")
    expect_bad_input((code, out, err), "arbc run: there is no option --seeed: did you mean '--seed'?")
    code, out, err = run(arbc, "verify", "--zzzzzz", "specs/table_clean.spec")
    expect_bad_input((code, out, err), "--zzzzzz")
    expect("did you mean" not in err, "a suggestion for a word close to no option", out, err)


def case_duration_beyond_a_run(arbc, plugin):
    # `--duration 1e12h` ran until killed (issue 40): beyond 30 days the clock is too coarse.
    expect_bad_input(run(arbc, "run", "specs/face_filter.spec", "--stub", "--duration", "1e12h"),
                     "--duration '1e12h' is longer than a run can be: at most 720h (30 days)")
    code, out, err = run(arbc, "run", "specs/face_filter.spec", "--stub", "--duration", "721h")
    expect(code == 2, f"721h: exit {code}", out, err)


def case_stub_rate_beyond_a_run(arbc, plugin):
    # `--stub-rate P=1e9` ran until killed (issue 40): a rate beyond one sample per microsecond,
    # and more samples than a run works through, are refused before the run.
    spec = "specs/face_filter.spec"
    expect_bad_input(run(arbc, "run", spec, "--stub", "--stub-rate", "FaceDetector.face=1e9"),
                     "--stub-rate FaceDetector.face=1e9: at most 1000000 samples per second")
    expect_bad_input(run(arbc, "run", spec, "--stub", "--stub-rate", "FaceDetector.face=1000000",
                         "--duration", "1h"),
                     "--stub: the stand-ins would publish about 3.6e+09 samples in this run",
                     "shorten --duration or lower --stub-rate")


def case_inputs_int_beyond_int64(arbc, plugin):
    # 2^63 became -2^63 (issue 40): refused at the line and column of the value.
    with tempfile.TemporaryDirectory() as tmp:
        spec = os.path.join(tmp, "count.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write('app count "x";\nmodule Counter { out n: int; }\nmodule Show { in n: int; }\n'
                    "connect Counter.n -> Show.n;\n")
        inputs = os.path.join(tmp, "in.jsonl")
        with open(inputs, "w", encoding="utf-8") as f:
            f.write('{"t": 0, "port": "Counter.n", "value": 1}\n'
                    '{"t": 1, "port": "Counter.n", "value": 9223372036854775808}\n')
        expect_bad_input(run(arbc, "run", spec, "--inputs", inputs),
                         f"{inputs}:2:40: field 'value': 9223372036854775808 is beyond the range "
                         "of int, a 64-bit integer")


def case_trace_nan_inf_reads_back(arbc, plugin):
    # A NaN or an infinity was written to the trace as null, which --inputs refused (issue 39):
    # the trace writes "nan", "inf", "-inf", and the trace given back as --inputs replays them.
    with tempfile.TemporaryDirectory() as tmp:
        spec = os.path.join(tmp, "range.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write('app range "x";\nmodule Lidar { out d: float; }\nmodule Show { in d: float; }\n'
                    "connect Lidar.d -> Show.d;\n")
        inputs = os.path.join(tmp, "in.jsonl")
        with open(inputs, "w", encoding="utf-8") as f:
            for t, v in ((0.1, '"nan"'), (0.2, '"inf"'), (0.3, '"-inf"'), (0.4, "1.5")):
                f.write(f'{{"t": {t}, "port": "Lidar.d", "value": {v}}}\n')
        traces = [os.path.join(tmp, "run1.jsonl"), os.path.join(tmp, "run2.jsonl")]
        code, out, err = run(arbc, "run", spec, "--inputs", inputs, "--duration", "1s",
                             "--trace", traces[0])
        expect(code == 0, f"run exit {code}", out, err)
        code, out, err = run(arbc, "run", spec, "--inputs", traces[0], "--duration", "1s",
                             "--trace", traces[1])
        expect(code == 0, f"the trace as --inputs: exit {code}", out, err)
        for trace in traces:
            with open(trace, encoding="utf-8") as f:
                values = [json.loads(line).get("value") for line in f
                          if '"deliver"' in line]
            expect(values == ["nan", "inf", "-inf", 1.5], f"{trace} delivered {values}")


def case_inputs_directory(arbc, plugin):
    # A folder was read as zero messages, exit 0 (issue 40).
    with tempfile.TemporaryDirectory() as tmp:
        expect_bad_input(run(arbc, "run", "specs/face_filter.spec", "--inputs", tmp),
                         f"{tmp}: a directory; --inputs takes a file of JSON lines (or a trace)")


def case_counterexamples_file(arbc, plugin):
    # docs/cli.md: exit 2 for bad input; a file given as the folder gave 3, after the proof.
    with tempfile.NamedTemporaryFile() as f:
        expect_bad_input(run(arbc, "verify", "tests/verify/table_clean_hold_mutant.spec",
                             "--counterexamples", f.name),
                         f"--counterexamples {f.name}: not a folder")


def case_status_bad_input(arbc, plugin):
    # `arbc status` (issue 42): what is not a domain, a wait or a topic is refused at once, before
    # listening; an empty topic once reached the DDS reader.
    expect_bad_input(run(arbc, "status", "--domain", "999"), "--domain 999 is not a DDS domain")
    expect_bad_input(run(arbc, "status", "--topic", ""), "--topic needs a topic name")
    expect_bad_input(run(arbc, "status", "--wait", "2h"), "--wait must be at most 1h")
    expect_bad_input(run(arbc, "status", "--wait", "0"), "is not a positive number of seconds")
    expect_bad_input(run(arbc, "run", "specs/face_filter.spec", "--no-status-topics"),
                     "--no-status-topics needs --transport dds")


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}

if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[3] not in CASES:
        sys.exit(__doc__ + "cases: " + ", ".join(sorted(CASES)))
    CASES[sys.argv[3]](os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]))
    print("ok")
