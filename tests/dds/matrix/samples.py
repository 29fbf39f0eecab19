"""Samples of the matrix's messages at their types' edges, as CDR bytes (XCDR1, little endian,
the encoding Fast-DDS 2.9 and fastddsgen's types write): the bytes the plain publisher reads into
its fastddsgen type, publishes, and the plain subscriber must receive unchanged.

Sample k of a message gives each field the k-th edge of its type, shifted by the element's index
in arrays and sequences, so that one message carries every edge: the least and greatest integer
of each width, NaN (with a payload), the infinities, -0.0, the greatest float32, the least
subnormal double, empty and long sequences, empty, long and non-ASCII strings.
"""
import struct

import messages

SAMPLES = 4
FLT_MAX = struct.unpack("<f", struct.pack("<I", 0x7f7fffff))[0]
INT_WIDTHS = {"int8": 8, "int16": 16, "int32": 32, "int64": 64}
UINT_WIDTHS = {"uint8": 8, "byte": 8, "char": 8, "uint16": 16, "uint32": 32, "uint64": 64}
FORMATS = {"bool": "<?", "byte": "<B", "char": "<B", "int8": "<b", "uint8": "<B", "int16": "<h",
           "uint16": "<H", "int32": "<i", "uint32": "<I", "int64": "<q", "uint64": "<Q"}
STRINGS = ["", "ünïcødé ✓ 日本語 — \u00e9t\u00e9", "x" * 300, "base_link"]
# The float edges as bit patterns: NaNs keep their payload only if nothing on the way converts.
FLOAT32_BITS = [0xff800000, 0x7f7fffff, 0x7fc00001, 0x80000000]        # -inf, max, NaN, -0.0
FLOAT64_BITS = [0x7ff0000000000000, 0x0000000000000001, 0x7ff8000000000123, 0x8000000000000000]


class Writer:
    def __init__(self):
        self.body = bytearray()

    def align(self, n):
        self.body += b"\0" * (-len(self.body) % n)

    def raw(self, fmt, value, size):
        self.align(size)
        self.body += struct.pack(fmt, value)

    def bytes(self):
        return b"\x00\x01\x00\x00" + bytes(self.body)  # CDR_LE encapsulation, then the body


def scalar(w, base, k, string_bound=0):
    if base == "bool":
        w.raw("<?", k % 2 == 1, 1)
    elif base in INT_WIDTHS:
        bits = INT_WIDTHS[base]
        edges = [-(1 << (bits - 1)), (1 << (bits - 1)) - 1, -1, 0]
        w.raw(FORMATS[base], edges[k % 4], bits // 8)
    elif base in UINT_WIDTHS:
        bits = UINT_WIDTHS[base]
        edges = [0, (1 << bits) - 1, (1 << bits) - 2, 1]
        w.raw(FORMATS[base], edges[k % 4], bits // 8)
    elif base == "float32":
        w.raw("<I", FLOAT32_BITS[k % 4], 4)
    elif base == "float64":
        w.raw("<Q", FLOAT64_BITS[k % 4], 8)
    elif base == "string":
        data = STRINGS[k % len(STRINGS)].encode("utf-8")
        if string_bound:  # a string<=N at its bound, cut where a character starts
            data = data[:string_bound].decode("utf-8", "ignore").encode("utf-8")
        w.raw("<I", len(data) + 1, 4)
        w.body += data + b"\0"
    else:
        message(w, base, k)


def length(f, k):
    """The number of elements field f has in sample k."""
    kind = f.shape if isinstance(f.shape, str) else f.shape[0]
    if kind == "fixed":
        return f.shape[1]
    n = [0, 3, 1, 1000 if f.base in messages.PRIMITIVES else 12][k % 4]
    return min(n, f.shape[1]) if kind == "bounded" else n


def message(w, full, k):
    for f in messages.fields(full):
        if f.shape is None:
            scalar(w, f.base, k, f.string_bound)
            continue
        n = length(f, k)
        if f.shape == "seq" or f.shape[0] == "bounded":
            w.raw("<I", n, 4)
        for i in range(n):
            scalar(w, f.base, k + i, f.string_bound)


def sample(full, k):
    """Sample k of message `full` ("pkg/Name") as a serialized payload."""
    w = Writer()
    message(w, full, k)
    return w.bytes()
