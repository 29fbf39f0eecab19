#!/usr/bin/env python3
"""Every file arbc writes for another tool is read by a reader that is not arbc's (issue 40).

usage: check_artifacts.py ARBC LUAC PLUGIN     write every artifact, read each with its reader
       check_artifacts.py --repo ROOT          the repository's schemas and JSON inputs
       check_artifacts.py --self-test          each reader refuses a broken file

ARBC's commands are run from one scratch folder on inputs copied into another, every path
absolute, so that a path of the build machine would show in the artifacts: the default and
the YARP build, `arbc docs`, a run with its report and trace, `arbc test --junit` (passing and
failing), `arbc verify --format sarif|json` (proved and refuted). Then every file written is
read by the reader for its kind:

  .xml (YARP application)    xmllint --noout (well-formed XML: the comment that held "--")
  .xml (JUnit)               xmllint --schema junit.xsd (this folder)
  .svg                       xmllint --noout, root element <svg>
  app.json                   docs/app.schema.json (python3-jsonschema)
  other .json, .sarif        Python's JSON parser, strict: no NaN, no key twice
  .sarif                     sarif-2.1.0-subset.schema.json (this folder; why a subset: there),
                             and every artifactLocation.uri an RFC 3986 URI reference (the
                             official schema: sarif_official.py, over the verify goldens)
  .lua                       luac5.4 -p
  .dot                       Graphviz's dot
  .md                        every relative link names a file that was written
  .html                      Python's HTML parser: elements close in order (tests/report opens
                             the same report in headless Chromium)
  .trace                     one JSON object per line, each with a time and a type
  .mmd                       no offline Mermaid reader: its first line names a flowchart

A file of any other kind fails the test: a new artifact needs a reader here. And no file
holds the scratch folders' absolute paths (docs/app-json.md#paths-in-artifacts).
"""
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


class Bad(Exception):
    pass


def run(cmd, cwd, want=(0,)):
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600)
    if done.returncode not in want:
        raise Bad(f"`{' '.join(cmd)}` exited {done.returncode}, expected {want}:\n"
                  f"{done.stdout}{done.stderr}")
    return done.stdout


def strict_json(path):
    def no_twice(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)):
            raise Bad(f"{path}: a key appears twice in one object: {keys}")
        return dict(pairs)

    def no_constant(name):
        raise Bad(f"{path}: {name} is not JSON")

    with open(path, encoding="utf-8") as f:
        try:
            return json.load(f, object_pairs_hook=no_twice, parse_constant=no_constant)
        except json.JSONDecodeError as e:
            raise Bad(f"{path}: not JSON: {e}")


def validate(path, schema_path, document=None):
    import jsonschema
    schema = strict_json(schema_path)
    errors = sorted(jsonschema.Draft202012Validator(schema).iter_errors(
        strict_json(path) if document is None else document), key=lambda e: list(e.path))
    if errors:
        e = errors[0]
        raise Bad(f"{path}: does not follow {os.path.relpath(schema_path, ROOT)}: at "
                  f"/{'/'.join(map(str, e.path))}: {e.message}")


def xmllint(path, *extra):
    done = subprocess.run(["xmllint", "--noout", *extra, path], capture_output=True, text=True)
    if done.returncode != 0:
        raise Bad(f"{path}: xmllint refuses it:\n{done.stderr}")


# RFC 3986 relative-ref or URI, as characters: unreserved, sub-delims, ":@/?#" and %XX.
URI_REFERENCE = re.compile(r"^(?:[A-Za-z0-9\-._~!$&'()*+,;=:@/?#]|%[0-9A-Fa-f]{2})*$")


def read_sarif(path):
    log = strict_json(path)
    validate(path, os.path.join(HERE, "sarif-2.1.0-subset.schema.json"), log)

    def uris(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "uri":
                    yield value
                else:
                    yield from uris(value)
        elif isinstance(node, list):
            for item in node:
                yield from uris(item)

    for uri in uris(log):
        first = uri.split("/")[0]
        if not URI_REFERENCE.match(uri) or (":" in first and not re.match(r"^[A-Za-z][\w+.-]*:", uri)):
            raise Bad(f"{path}: artifactLocation.uri {uri!r} is not a URI reference (RFC 3986)")


def read_xml(path):
    xmllint(path)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "<testsuites" in text:
        xmllint(path, "--schema", os.path.join(HERE, "junit.xsd"))


def read_svg(path):
    xmllint(path)
    done = subprocess.run(["xmllint", "--xpath", "local-name(/*)", path], capture_output=True,
                          text=True)
    if done.stdout.strip() != "svg":
        raise Bad(f"{path}: its root element is {done.stdout.strip()!r}, not svg")


def read_json(path):
    if os.path.basename(path) == "app.json":
        validate(path, os.path.join(ROOT, "docs", "app.schema.json"))
    else:
        strict_json(path)


def read_lua(path, luac):
    done = subprocess.run([luac, "-p", path], capture_output=True, text=True)
    if done.returncode != 0:
        raise Bad(f"{path}: luac -p refuses it: {done.stderr}")


def read_dot(path):
    done = subprocess.run(["dot", "-Tsvg", "-o", os.devnull, path], capture_output=True, text=True)
    if done.returncode != 0 or done.stderr.strip():
        raise Bad(f"{path}: dot refuses it: {done.stderr}")


def read_markdown(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
            continue
        page = target.split("#")[0]
        if not os.path.exists(os.path.join(os.path.dirname(path), page)):
            raise Bad(f"{path}: links to {target}, which was not written")


class Balance(html.parser.HTMLParser):
    VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
            "track", "wbr"}

    def __init__(self):
        super().__init__()
        self.open, self.bad = [], []

    def handle_starttag(self, tag, attrs):
        if tag not in self.VOID:
            self.open.append(tag)

    def handle_startendtag(self, tag, attrs):
        pass

    def handle_endtag(self, tag):
        if self.open and self.open[-1] == tag:
            self.open.pop()
        else:
            self.bad.append(f"</{tag}> at line {self.getpos()[0]}")


def read_html(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if not text.lstrip().lower().startswith("<!doctype html>"):
        raise Bad(f"{path}: no <!doctype html>")
    b = Balance()
    b.feed(text)
    b.close()
    if b.bad or b.open:
        raise Bad(f"{path}: elements do not close in order: {b.bad[:3]} open: {b.open[-3:]}")


def read_trace(path):
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, start=1):
            try:
                record = json.loads(line)
            except json.JSONDecodeError as e:
                raise Bad(f"{path}:{number}: not a JSON line: {e}")
            if not isinstance(record, dict) or "t" not in record or "type" not in record:
                raise Bad(f"{path}:{number}: a record without a time and a type")


def read_mermaid(path):
    with open(path, encoding="utf-8") as f:
        first = f.readline()
    if not re.match(r"^(flowchart|graph) (LR|TB|TD|RL|BT)\b", first):
        raise Bad(f"{path}: does not start with a Mermaid flowchart line: {first!r}")


def reader_for(path, luac):
    name = os.path.basename(path)
    ext = os.path.splitext(name)[1]
    readers = {".xml": read_xml, ".svg": read_svg, ".json": read_json, ".sarif": read_sarif,
               ".lua": lambda p: read_lua(p, luac), ".dot": read_dot, ".md": read_markdown,
               ".html": read_html, ".trace": read_trace, ".mmd": read_mermaid}
    return readers.get(ext)


def write_artifacts(arbc, plugin, inputs, out, cwd):
    """Every kind of file arbc writes for another tool, from absolute paths."""
    spec = os.path.join(inputs, "table_clean.spec")
    run([arbc, "build", spec, "-o", os.path.join(out, "build")], cwd)
    # YARP cannot carry table_clean's delivery events: its own spec (docs/yarp.md).
    run([arbc, "build", os.path.join(inputs, "table_clean_yarp.spec"), "--target", "yarp", "-o",
         os.path.join(out, "yarp")], cwd)
    # A YARP monitor with runtime checks (an assert over `emitted`, a list bound).
    run([arbc, "build", os.path.join(inputs, "checks.spec"), "--target", "yarp", "-o",
         os.path.join(out, "yarp")], cwd)
    # Types declared by `use ros2` from a .msg file: app.json names each one's message.
    run([arbc, "build", os.path.join(inputs, "use_ros2_ok.spec"), "--msg-path",
         os.path.join(inputs, "msg"), "-o", os.path.join(out, "ros2")], cwd)
    run([arbc, "docs", spec, "-o", os.path.join(out, "docs")], cwd)
    run([arbc, "run", os.path.join(out, "build", "table_clean"), "--plugin", plugin,
         "--scenario", "mixed", "--seed", "1", "--duration", "60s",
         "--report", os.path.join(out, "run.html"), "--trace", os.path.join(out, "run.trace")], cwd)
    run([arbc, "test", os.path.join(inputs, "gaze.test.spec"),
         "--junit", os.path.join(out, "pass.xml")], cwd)
    run([arbc, "test", os.path.join(inputs, "gaze_wrong.test.spec"),
         "--junit", os.path.join(out, "fail.xml")], cwd, want=(1,))
    for name, want in (("table_clean", 0), ("table_clean_take_mutant", 1)):
        for fmt in ("sarif", "json"):
            text = run([arbc, "verify", "--format", fmt, os.path.join(inputs, name + ".spec")],
                       cwd, want=(want,))
            with open(os.path.join(out, f"{name}.{fmt}"), "w", encoding="utf-8") as f:
                f.write(text)


def copy_inputs(inputs):
    for rel in ("specs/table_clean.spec", "specs/table_clean_yarp.spec", "specs/testing/gaze.spec",
                "specs/testing/gaze.test.spec", "tests/verify/table_clean_take_mutant.spec",
                "tests/yarp_real/checks.spec", "tests/check/use_ros2_ok/use_ros2_ok.spec"):
        shutil.copy(os.path.join(ROOT, rel), inputs)
    shutil.copytree(os.path.join(ROOT, "tests/check/use_ros2_ok/msg"), os.path.join(inputs, "msg"))
    with open(os.path.join(inputs, "gaze.test.spec"), encoding="utf-8") as f:
        text = f.read()
    wrong = text.replace("receives vec3(1.0, 0.0, 0.0) at 1.2s", "receives vec3(1.0, 0.0, 0.0) at 1.1s")
    if wrong == text:
        raise Bad("specs/testing/gaze.test.spec changed: update the failing copy here")
    with open(os.path.join(inputs, "gaze_wrong.test.spec"), "w", encoding="utf-8") as f:
        f.write(wrong)


def check_all(arbc, luac, plugin):
    scratch = tempfile.mkdtemp(prefix="arbc-artifacts-")
    try:
        inputs, out, cwd = (os.path.join(scratch, d) for d in ("inputs", "out", "cwd"))
        for d in (inputs, out, cwd):
            os.makedirs(d)
        copy_inputs(inputs)
        write_artifacts(arbc, plugin, inputs, out, cwd)
        problems, kinds = [], {}
        for folder, _, names in os.walk(out):
            for name in sorted(names):
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, out)
                with open(path, "rb") as f:
                    if scratch.encode() in f.read():
                        problems.append(f"{rel}: holds the absolute path {scratch}")
                reader = reader_for(path, luac)
                if reader is None:
                    problems.append(f"{rel}: no reader for this kind of file: add one to "
                                    f"{os.path.relpath(__file__, ROOT)}")
                    continue
                try:
                    reader(path)
                    ext = os.path.splitext(name)[1]
                    kinds[ext] = kinds.get(ext, 0) + 1
                except Bad as e:
                    problems.append(str(e).replace(out + os.sep, ""))
        for p in problems:
            print("FAIL", p)
        print("read:", ", ".join(f"{n} {k}" for k, n in sorted(kinds.items())))
        return 1 if problems else 0
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def check_repo(root):
    """The schemas are valid JSON Schemas, and the repository's inputs follow them."""
    import jsonschema
    problems = []
    for schema in ("app.schema.json", "deployment.schema.json"):
        try:
            jsonschema.Draft202012Validator.check_schema(strict_json(os.path.join(root, "docs", schema)))
        except (jsonschema.SchemaError, Bad) as e:
            problems.append(f"docs/{schema}: not a valid JSON Schema: {str(e).splitlines()[0]}")
    listed = subprocess.run(["git", "-C", root, "ls-files", "*.json"], capture_output=True,
                            text=True)
    files = listed.stdout.split()
    if listed.returncode != 0:  # not a checkout (mutate.sh's scratch copy): the tree's files
        files = []
        for d, dirs, names in os.walk(root):
            if d == root:  # what a build or the demo writes, not the repository's inputs
                dirs[:] = [x for x in dirs if x not in ("build", "out", ".git")]
            files += [os.path.relpath(os.path.join(d, f), root) for f in names
                      if f.endswith(".json")]
    checked = 0
    for rel in files:
        schema = ("deployment.schema.json" if rel.endswith(".deploy.json") else
                  "app.schema.json" if os.path.basename(rel).endswith("app.json") and
                  "malformed" not in rel else None)
        if schema is None:
            continue
        try:
            validate(os.path.join(root, rel), os.path.join(root, "docs", schema))
            checked += 1
        except Bad as e:
            problems.append(str(e))
    for p in problems:
        print("FAIL", p)
    print(f"{checked} files follow their schema")
    return 1 if problems or checked == 0 else 0


def self_test(luac):
    """Each reader refuses a broken file of its kind (so a passing run means something)."""
    broken = {
        "a.xml": '<?xml version="1.0"?>\n<!-- arbc build --target yarp -->\n<application/>\n',
        "junit.xml": '<testsuites><testsuite name="s"><testcase/></testsuite></testsuites>\n',
        "a.svg": "<html></html>\n",
        "app.json": '{"schema_version": 2}\n',
        "b.json": '{"a": 1, "a": 2}\n',
        "c.sarif": '{"version": "2.1.0", "runs": [{"tool": {"driver": {"name": "arbc", "rules":'
                   ' [{"id": "x", "helpUri": "docs/checks.html#x"}]}}}]}\n',
        "d.sarif": '{"version": "2.1.0", "runs": [{"tool": {"driver": {"name": "arbc"}}, '
                   '"results": [{"message": {"text": "m"}, "locations": [{"physicalLocation":'
                   ' {"artifactLocation": {"uri": "my specs/a.spec"}}}]}]}]}\n',
        "a.lua": "local x = \n",
        "a.dot": "digraph { a -> }\n",
        "a.md": "[x](missing.md)\n",
        "a.html": "<!doctype html><div><p></div>\n",
        "a.trace": '{"t": 0.0}\n',
        "a.mmd": "hello\n",
    }
    problems = []
    with tempfile.TemporaryDirectory() as d:
        for name, text in broken.items():
            path = os.path.join(d, name)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            try:
                reader_for(path, luac)(path)
                problems.append(f"{name}: accepted, but it is broken")
            except Bad:
                pass
    for p in problems:
        print("FAIL", p)
    print(f"self-test: {len(broken)} broken files, {len(problems)} accepted")
    return 1 if problems else 0


def main():
    args = sys.argv[1:]
    if len(args) == 2 and args[0] == "--self-test":
        return self_test(args[1])
    if len(args) == 2 and args[0] == "--repo":
        return check_repo(args[1])
    if len(args) != 3:
        sys.exit(__doc__)
    return check_all(*args)


if __name__ == "__main__":
    sys.exit(main())
