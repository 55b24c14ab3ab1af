#!/usr/bin/env python3
"""Writes a damaged copy of a skybake bake file, for the bad-input tests.

corrupt_bake.py IN OUT version N      every part's skybake:format_version set to N
corrupt_bake.py IN OUT rename OLD NEW the part named OLD renamed NEW (same length)
corrupt_bake.py IN OUT flip FRACTION  one byte at FRACTION of the file inverted
corrupt_bake.py IN OUT replace OLD NEW every OLD in the headers replaced by NEW (same length)

OpenEXR header attributes are stored as name NUL, type NUL, a little-endian
int32 size, then the value; the headers are not compressed, so an attribute
can be found and rewritten in place without changing the file's layout.
"""
import struct
import sys


def attribute(name: str, type_name: str, value: bytes) -> bytes:
    return name.encode() + b"\0" + type_name.encode() + b"\0" + struct.pack("<i", len(value)) + value


def main() -> None:
    source, target, action, *args = sys.argv[1:]
    data = bytearray(open(source, "rb").read())
    if action == "version":
        prefix = attribute("skybake:format_version", "int", b"\0\0\0\0")[:-4]
        start, found = data.find(prefix), 0
        while start >= 0:
            data[start + len(prefix):start + len(prefix) + 4] = struct.pack("<i", int(args[0]))
            found += 1
            start = data.find(prefix, start + 1)
        if found == 0:
            sys.exit(f"{source}: no skybake:format_version attribute")
    elif action == "rename":
        old, new = (attribute("name", "string", name.encode()) for name in args)
        if len(old) != len(new) or data.count(old) != 1:
            sys.exit(f"{source}: no single part named {args[0]}, or the new name's length differs")
        data = data.replace(old, new)
    elif action == "replace":
        old, new = (text.encode() for text in args)
        if len(old) != len(new) or data.count(old) == 0:
            sys.exit(f"{source}: no {args[0]!r} in the file, or the replacement's length differs")
        data = data.replace(old, new)
    elif action == "flip":
        data[int(float(args[0]) * (len(data) - 1))] ^= 0xFF
    else:
        sys.exit(f"unknown action {action}")
    open(target, "wb").write(data)


if __name__ == "__main__":
    main()
