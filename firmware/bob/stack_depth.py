#!/usr/bin/env python3
"""Deepest call chain of a bob firmware image, from the compiler's own stack figures.

The firmware build compiles the bob core and main.cpp with -fstack-usage -fcallgraph-info=su, so
each object has a .ci file: every function with its frame in bytes, and every call it makes (after
inlining). This script walks the calls from the reset handler and prints the chain whose frames add
up to the most: the figure STACK_BYTES in cortex_m4.ld is based on (docs/bob-firmware.md). It is an
upper bound over the code linked in, whether or not the image's options can reach it.

usage: firmware/bob/stack_depth.py [BUILD_DIR] [TARGET]
       (defaults: build/cortex-m bob_firmware_map_aware)
"""
import pathlib
import re
import sys

NODE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
FRAME = re.compile(r"\\n(\d+) bytes \((static|dynamic|dynamic,bounded)\)")


def main():
    build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build/cortex-m")
    target = sys.argv[2] if len(sys.argv) > 2 else "bob_firmware_map_aware"
    files = sorted(build.glob("src/bob/CMakeFiles/tessera_bob.dir/*.ci"))
    files += sorted(build.glob(f"firmware/bob/CMakeFiles/{target}.dir/*.ci"))
    if not files:
        sys.exit(f"no .ci files for {target} under {build}: build the cortex-m preset first")
    frame, calls, label = {}, {}, {}
    for path in files:
        for line in path.read_text().splitlines():
            if m := NODE.match(line):
                title, text = m.groups()
                if f := FRAME.search(text):
                    frame[title] = int(f.group(1))
                    label[title] = text.split("\\n")[0]
                    if f.group(2) != "static":
                        print(f"warning: {label[title]}: {f.group(2)} frame", file=sys.stderr)
            elif m := EDGE.match(line):
                calls.setdefault(m.group(1), set()).add(m.group(2))

    def resolve(name):  # a call to another file names the function without the file prefix
        return name if name in frame else name.split(":")[-1]

    best = {}

    def deepest(name, path=()):
        name = resolve(name)
        if name in path:
            sys.exit(f"recursion through {label.get(name, name)}: no static bound")
        if name not in best:
            if name not in frame:
                print(f"warning: no stack figure for {name}, counted as 0", file=sys.stderr)
            tail = max((deepest(c, path + (name,)) for c in calls.get(name, ())),
                       key=lambda chain: chain[0], default=(0, []))
            best[name] = (frame.get(name, 0) + tail[0], [name] + tail[1])
        return best[name]

    total, chain = deepest("reset_handler")
    for name in chain:
        print(f"{frame.get(name, 0):5d}  {label.get(name, name)}")
    print(f"{total:5d}  bytes in all ({target})")


if __name__ == "__main__":
    main()
