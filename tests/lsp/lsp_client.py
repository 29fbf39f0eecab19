"""A small LSP client over a child process's stdio, for the protocol tests and the benchmark.

    with LspClient([arbc, "lsp", "--no-verify"]) as c:
        c.initialize(root)
        c.open(uri, text)
        diags = c.wait_diagnostics(uri)
        c.request("textDocument/hover", {...})
"""
import json
import os
import queue
import subprocess
import threading
import time


# Scratch specs are written beside the real ones (so that relative imports resolve), under a
# hidden name: a test that globs specs/*.spec while another test runs must not pick them up.
SCRATCH_PREFIX = ".lsp-scratch-"


def file_uri(path):
    return "file://" + os.path.abspath(path)


class LspClient:
    def __init__(self, command, stderr=subprocess.PIPE):
        self.proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=stderr)
        self.next_id = 1
        self.responses = {}
        self.notifications = queue.Queue()
        self.backlog = []  # notifications kept for a later wait_notification
        self.cond = threading.Condition()
        self.stderr_lines = []
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()
        self.stderr_reader = None
        if stderr == subprocess.PIPE:
            self.stderr_reader = threading.Thread(target=self._read_stderr, daemon=True)
            self.stderr_reader.start()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait(timeout=30)

    def stderr_after_exit(self, timeout=30):
        """All the server wrote on stderr; call once the process has exited."""
        self.stderr_reader.join(timeout)
        return "".join(self.stderr_lines)

    def _read_stderr(self):
        for line in self.proc.stderr:
            self.stderr_lines.append(line.decode("utf-8", "replace"))

    def _read(self):
        out = self.proc.stdout
        while True:
            length = None
            while True:
                line = out.readline()
                if not line:
                    with self.cond:
                        self.cond.notify_all()
                    return
                line = line.strip()
                if not line:
                    break
                name, _, value = line.partition(b":")
                if name.lower() == b"content-length":
                    length = int(value)
            message = json.loads(out.read(length))
            if "id" in message and "method" not in message:
                with self.cond:
                    self.responses[message["id"]] = message
                    self.cond.notify_all()
            else:
                self.notifications.put(message)

    def send_raw(self, data):
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message):
        body = json.dumps(message).encode("utf-8")
        self.send_raw(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request_async(self, method, params):
        rid = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": rid, "method": method, "params": params})
        return rid

    def response(self, rid, timeout=30):
        deadline = time.monotonic() + timeout
        with self.cond:
            while rid not in self.responses:
                left = deadline - time.monotonic()
                if left <= 0 or self.proc.poll() is not None:
                    raise TimeoutError(f"no response to request {rid}")
                self.cond.wait(left)
            return self.responses.pop(rid)

    def request(self, method, params, timeout=30):
        """The result; raises RuntimeError with the error's code and message on an error."""
        reply = self.response(self.request_async(method, params), timeout)
        if "error" in reply:
            raise RuntimeError(reply["error"]["code"], reply["error"]["message"])
        return reply["result"]

    def initialize(self, root):
        result = self.request("initialize", {"processId": os.getpid(), "rootUri": file_uri(root),
                                             "capabilities": {}})
        self.notify("initialized", {})
        return result

    def shutdown_and_exit(self, timeout=30):
        self.request("shutdown", None)
        self.notify("exit", None)
        return self.proc.wait(timeout=timeout)

    def open(self, uri, text, version=1):
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "arbc", "version": version, "text": text}})

    def change(self, uri, version, changes):
        self.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version},
                                               "contentChanges": changes})

    def wait_notification(self, accept, timeout=30, keep=None):
        """The next notification `accept` takes. Those it does not take are dropped, except
        those `keep` takes: they wait in a backlog that later calls look at first."""
        for i, message in enumerate(self.backlog):
            if accept(message):
                return self.backlog.pop(i)
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError("no matching notification")
            try:
                message = self.notifications.get(timeout=left)
            except queue.Empty:
                raise TimeoutError("no matching notification")
            if accept(message):
                return message
            if keep is not None and keep(message):
                self.backlog.append(message)

    def wait_diagnostics(self, uri, version=None, accept=None, timeout=30):
        """The diagnostics of the next publishDiagnostics for `uri` (of `version`, if given)
        that `accept` (if given) takes. Other documents' diagnostics wait for their turn."""
        def publishes(m):
            return m.get("method") == "textDocument/publishDiagnostics"

        def match(m):
            if not publishes(m):
                return False
            p = m["params"]
            if p["uri"] != uri or (version is not None and p.get("version") != version):
                return False
            return accept is None or accept(p["diagnostics"])

        def other_document(m):
            return publishes(m) and m["params"]["uri"] != uri
        return self.wait_notification(match, timeout, keep=other_document)["params"]["diagnostics"]


def position_of(text, needle, occurrence=0, offset=0):
    """The LSP position of the `occurrence`-th `needle` in text (ASCII text), plus `offset`."""
    index = -1
    for _ in range(occurrence + 1):
        index = text.index(needle, index + 1)
    index += offset
    line = text.count("\n", 0, index)
    character = index - (text.rfind("\n", 0, index) + 1)
    return {"line": line, "character": character}


def apply_edits(text, edits):
    """Applies LSP TextEdits (ASCII text) to text."""
    def offset(pos):
        lines = text.split("\n")
        return sum(len(l) + 1 for l in lines[:pos["line"]]) + pos["character"]
    for e in sorted(edits, key=lambda e: (e["range"]["start"]["line"],
                                          e["range"]["start"]["character"]), reverse=True):
        text = text[:offset(e["range"]["start"])] + e["newText"] + text[offset(e["range"]["end"]):]
    return text
