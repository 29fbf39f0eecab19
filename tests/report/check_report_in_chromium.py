#!/usr/bin/env python3
"""Opens an `arbc run --report` page in headless Chromium (issue 7).

Runs the table-cleaning app (scenario mixed, seed 1, 60 s) with --report, then checks that
  - the report is one self-contained file under 2 MB whose elements all close in order;
  - Chromium logs no console message at all while loading it (the report logs nothing, so any
    message is an error: an uncaught exception, a blocked resource);
  - the report's inline script ran to its end (its time cursors are in the DOM: --dump-dom);
  - the screenshot is not blank: many colours, enough non-background pixels, and pixels of the
    exact delivery colour, so the timeline itself was drawn.
The screenshot is kept as OUT/table_clean_report.png (printed at the end).

With --inject-error it first appends a script that throws to a copy of the report and passes
only if the checks above catch it: proof that the console check detects real errors.

Usage: check_report_in_chromium.py --arbc ARBC --plugin LIB --spec SPEC --out DIR [--inject-error]
"""
import argparse
import html.parser
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

MAX_REPORT_BYTES = 2 * 1024 * 1024
WINDOW = (1400, 1000)
DELIVERY_RGB = (0x00, 0x9E, 0x73)  # kDeliveryColor in report/svg_timeline.h


class CheckFailed(Exception):
    pass


def run_arbc(args, report):
    cmd = [args.arbc, "run", args.spec, "--plugin", args.plugin, "--scenario", "mixed",
           "--seed", "1", "--duration", "60s", "--report", report]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        raise CheckFailed("`%s` exited %d:\n%s%s" % (" ".join(cmd), done.returncode,
                                                     done.stdout, done.stderr))
    size = os.path.getsize(report)
    if size > MAX_REPORT_BYTES:
        raise CheckFailed("%s is %d bytes, over the %d byte budget" % (report, size,
                                                                     MAX_REPORT_BYTES))
    html = open(report, encoding="utf-8").read()
    for reference in ("http://", "https://", "<script src", "<link", "@import", "url("):
        if reference in html:
            raise CheckFailed("%s is not self-contained: it contains %r" % (report, reference))
    check_balanced(report, html)
    return size


class TagBalance(html.parser.HTMLParser):
    """Records end tags that do not close the innermost open element."""
    VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
            "track", "wbr"}

    def __init__(self):
        super().__init__()
        self.open, self.mismatches = [], []

    def handle_starttag(self, tag, attrs):
        if tag not in self.VOID:
            self.open.append(tag)

    def handle_endtag(self, tag):
        if self.open and self.open[-1] == tag:
            self.open.pop()
        else:
            self.mismatches.append("</%s> at line %d while %s is open" %
                                   (tag, self.getpos()[0], self.open[-1:] or "nothing"))


def check_balanced(report, html):
    balance = TagBalance()
    balance.feed(html)
    balance.close()
    if balance.mismatches or balance.open:
        raise CheckFailed("%s: elements do not nest: %s; left open: %s" %
                          (report, balance.mismatches[:5], balance.open))


def chromium(extra, page):
    exe = shutil.which("chromium")
    if not exe:
        raise CheckFailed("chromium is not installed; the test setup installs it: "
                          "scripts/install-deps.sh --test (Debian package `chromium`)")
    with tempfile.TemporaryDirectory(prefix="arbc-chromium-") as profile:
        cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu",
               "--disable-background-networking", "--no-first-run",
               "--user-data-dir=" + profile] + extra + ["file://" + os.path.abspath(page)]
        try:
            return subprocess.run(cmd, capture_output=True, text=True, timeout=180)
        except subprocess.TimeoutExpired:
            raise CheckFailed("chromium did not finish within 180 s: " + " ".join(cmd))


def console_messages(page, png):
    """Loads the page with logging on and a screenshot; returns its console lines."""
    done = chromium(["--enable-logging=stderr", "--v=0", "--screenshot=" + png,
                     "--window-size=%d,%d" % WINDOW, "--hide-scrollbars"], page)
    if done.returncode != 0 or not os.path.exists(png):
        raise CheckFailed("chromium --screenshot failed (exit %d):\n%s" % (done.returncode,
                                                                          done.stderr[-3000:]))
    # Chromium logs every console message as `[...:INFO:CONSOLE:LINE] "text", source: URL`
    # (older builds: `CONSOLE(LINE)`), whatever its level.
    return [line for line in done.stderr.splitlines() if re.search(r":CONSOLE[:(]", line)]


def script_completed(page, html):
    """True if the page's inline script added one cursor per timeline (it runs last)."""
    done = chromium(["--dump-dom"], page)
    if done.returncode != 0:
        raise CheckFailed("chromium --dump-dom failed (exit %d):\n%s" % (done.returncode,
                                                                        done.stderr[-3000:]))
    timelines = html.count('<svg class="timeline"')
    cursors = len(re.findall(r'<line class="cursor"', done.stdout))
    return timelines >= 2 and cursors == timelines, timelines, cursors


def png_pixels(path):
    """Decodes an 8-bit RGB or RGBA, non-interlaced PNG: (width, height, rows of bytes, bpp)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise CheckFailed(path + " is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        raise CheckFailed("%s: unexpected PNG format (depth %d, colour type %d, interlace %d)" %
                          (path, depth, colour, interlace))
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for x in range(bpp, stride):
                line[x] = (line[x] + line[x - bpp]) & 0xFF
        elif kind == 2:
            for x in range(stride):
                line[x] = (line[x] + previous[x]) & 0xFF
        elif kind == 3:
            for x in range(stride):
                left = line[x - bpp] if x >= bpp else 0
                line[x] = (line[x] + ((left + previous[x]) >> 1)) & 0xFF
        elif kind == 4:
            for x in range(stride):
                a = line[x - bpp] if x >= bpp else 0
                b = previous[x]
                c = previous[x - bpp] if x >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pred) & 0xFF
        rows.append(line)
        previous = line
    return width, height, rows, bpp


def check_screenshot(png):
    width, height, rows, bpp = png_pixels(png)
    if (width, height) != WINDOW:
        raise CheckFailed("%s is %dx%d, expected %dx%d" % ((png, width, height) + WINDOW))
    counts = {}
    for line in rows:
        for x in range(0, len(line), bpp):
            rgb = bytes(line[x:x + 3])
            counts[rgb] = counts.get(rgb, 0) + 1
    total = width * height
    background = max(counts.values())
    drawn = 1 - background / total
    delivery = counts.get(bytes(DELIVERY_RGB), 0)
    if len(counts) < 16 or drawn < 0.03 or delivery < 20:
        raise CheckFailed("%s looks blank: %d colours, %.1f%% non-background pixels, %d pixels "
                          "of the delivery colour" % (png, len(counts), 100 * drawn, delivery))
    return len(counts), drawn, delivery


def check_page(page, png):
    html = open(page, encoding="utf-8").read()
    problems = []
    messages = console_messages(page, png)
    if messages:
        problems.append("console messages while loading %s:\n  %s" % (page, "\n  ".join(messages)))
    completed, timelines, cursors = script_completed(page, html)
    if not completed:
        problems.append("the report's inline script did not run to its end: %d timelines, %d "
                        "cursors in the DOM" % (timelines, cursors))
    colours, drawn, delivery = check_screenshot(png)
    return problems, (colours, drawn, delivery)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--arbc", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--spec", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--inject-error", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    report = os.path.join(args.out, "table_clean_report.html")
    png = os.path.join(args.out, "table_clean_report.png")
    try:
        size = run_arbc(args, report)
        print("report: %s (%d bytes)" % (report, size))
        if args.inject_error:
            injected = os.path.join(args.out, "injected_error.html")
            html = open(report, encoding="utf-8").read()
            html = html.replace("</body>", "<script>arbcReportNoSuchFunction();</script>\n</body>")
            open(injected, "w", encoding="utf-8").write(html)
            problems, _ = check_page(injected, os.path.join(args.out, "injected_error.png"))
            if not any("arbcReportNoSuchFunction" in p for p in problems):
                raise CheckFailed("the console check missed an injected script error in %s; "
                                  "found only: %s" % (injected, problems or "nothing"))
            print("the injected script error was detected:\n" + "\n".join(problems))
            return 0
        problems, (colours, drawn, delivery) = check_page(report, png)
        if problems:
            raise CheckFailed("\n".join(problems))
        print("no console messages; the inline script ran; screenshot: %d colours, %.1f%% "
              "non-background pixels, %d delivery-colour pixels" % (colours, 100 * drawn,
                                                                    delivery))
        print("screenshot kept at " + png)
        return 0
    except CheckFailed as failure:
        print("FAILED: %s" % failure, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
