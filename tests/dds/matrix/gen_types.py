#!/usr/bin/env python3
"""Writes the interop matrix's IDL and the list of its types for matrix_peer.cc.

usage: gen_types.py OUT_DIR   -> OUT_DIR/matrix.idl (for fastddsgen) and OUT_DIR/matrix_types.h

The IDL gives each message of messages.py the type rosidl gives it on DDS: the struct
pkg::msg::dds_::Name_, its fields in order with the IDL type of each .msg type (int8 and uint8
for int8 and uint8, octet for byte, uint8 for char, float and double for float32 and float64),
`sequence<T>` for T[], `sequence<T, N>` for T[<=N], `T name[N]` for T[N], `string<N>` for
string<=N. A member named like an IDL keyword gets a trailing underscore (as rosidl does),
which changes no byte: nothing on the wire names a field.
"""
import os
import sys

import messages

IDL_TYPES = {"bool": "boolean", "byte": "octet", "char": "uint8", "int8": "int8", "uint8": "uint8",
             "int16": "int16", "uint16": "uint16", "int32": "int32", "uint32": "uint32",
             "int64": "int64", "uint64": "uint64", "float32": "float", "float64": "double",
             "string": "string"}


KEYWORDS = {"module", "struct", "string", "sequence", "boolean", "octet", "char", "short", "long",
            "float", "double", "union", "switch", "case", "default", "enum", "const", "typedef",
            "interface", "in", "out", "inout", "attribute", "readonly", "exception", "void",
            "fixed", "any", "object", "native", "local", "abstract", "custom", "factory", "private",
            "public", "supports", "valuetype", "wchar", "wstring", "map", "bitset", "bitfield",
            "unsigned", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
            "true", "false", "key"}


def dds_name(full):
    package, name = full.split("/")
    return f"{package}::msg::dds_::{name}_"


def member(f):
    base = IDL_TYPES.get(f.base) or dds_name(f.base)
    if f.string_bound:
        base = f"string<{f.string_bound}>"
    name = f.name + "_" if f.name.lower() in KEYWORDS else f.name
    if f.shape is None:
        return f"{base} {name};"
    if f.shape == "seq":
        return f"sequence<{base}> {name};"
    kind, n = f.shape
    if kind == "bounded":
        return f"sequence<{base}, {n}> {name};"
    return f"{base} {name}[{n}];"


def idl_text():
    out = ["// Written by gen_types.py from messages.py: ROS 2 messages under their DDS names."]
    for full in messages.used_in_order(messages.MATRIX):
        package, name = full.split("/")
        body = "\n".join("        " + member(f) for f in messages.fields(full))
        out.append(f"module {package} {{ module msg {{ module dds_ {{\n"
                   f"    struct {name}_ {{\n{body}\n    }};\n}}; }}; }};")
    return "\n".join(out) + "\n"


def types_header():
    rows = [f'  X({i}, "{dds_name(full)}", {dds_name(full)}, {dds_name(full)}PubSubType)'
            for i, full in enumerate(messages.MATRIX)]
    return ("// Written by gen_types.py: the matrix's types, in messages.MATRIX's order.\n"
            "#pragma once\n#define ARBC_MATRIX_TYPES(X) \\\n" + " \\\n".join(rows) + "\n")


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, text in (("matrix.idl", idl_text()), ("matrix_types.h", types_header())):
        path = os.path.join(out, name)
        old = open(path).read() if os.path.exists(path) else None
        if old != text:  # unchanged files keep their time: no rebuild
            with open(path, "w") as f:
                f.write(text)


if __name__ == "__main__":
    main()
