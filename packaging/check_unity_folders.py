#!/usr/bin/env python3
"""Compiles each test program's sources as ONE translation unit (syntax only), to find file-scope names
that two test files of a folder both define.

The test command builds the test programs in unity batches of a few files (cmake/UnityBatches.cmake),
so two files that define the same name in their anonymous namespaces break the build only once they
land in the same batch, which adding one file anywhere in the folder can cause. This check puts every
file of the program in one unit, so any such pair fails now, naming both files. It reads the unity
units and the compile command of BUILD_DIR (a build with MX_UNITY_TESTS=ON, built, so that the moc
files exist). Exits 1 when a program fails, 2 on bad arguments.

Usage: check_unity_folders.py BUILD_DIR [PROGRAM ...]   (PROGRAM: tests_gui, ...; default all)
"""
import glob
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def syntax_command(entry, unit):
    """The unity unit's compile command, syntax only, on `unit` instead."""
    args = shlex.split(entry["command"])
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a in ("-o", "-MF", "-MT"):
            skip = True
        elif a not in ("-c", "-MD", entry["file"]):
            out.append(a)
    return out + ["-fsyntax-only", unit]


def check_program(build_dir, program, entries, scratch):
    units = sorted(glob.glob(os.path.join(build_dir, "tests", "CMakeFiles", program + ".dir", "Unity", "unity_*_cxx.cxx")))
    entry = next((e for e in entries if f"/{program}.dir/Unity/" in e["file"]), None)
    if not units or entry is None:
        return None
    sources = []
    for unit in units:
        with open(unit, encoding="utf-8") as f:
            sources += re.findall(r'#include "([^"]+)"', f.read())
    whole = os.path.join(scratch, program + ".cxx")
    with open(whole, "w", encoding="utf-8") as f:
        f.writelines(f'#include "{s}"\n' for s in sources)
    result = subprocess.run(syntax_command(entry, whole), cwd=entry["directory"], capture_output=True, text=True, check=False)
    errors = [line for line in result.stderr.splitlines() if "error:" in line]
    return len(sources), result.returncode, errors


def main():
    if len(sys.argv) < 2 or not os.path.isfile(os.path.join(sys.argv[1], "compile_commands.json")):
        print(__doc__)
        return 2
    build_dir = sys.argv[1]
    with open(os.path.join(build_dir, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    programs = sys.argv[2:] or sorted(
        os.path.basename(d)[: -len(".dir")] for d in glob.glob(os.path.join(build_dir, "tests", "CMakeFiles", "tests_*.dir")))
    failed = 0
    with tempfile.TemporaryDirectory() as scratch:
        for program in programs:
            checked = check_program(build_dir, program, entries, scratch)
            if checked is None:
                print(f"{program}: no unity units (configure with MX_UNITY_TESTS=ON and build)")
                failed += 1
                continue
            count, code, errors = checked
            print(f"{program}: {count} files as one unit: {'ok' if code == 0 else 'FAILED'}", flush=True)
            for line in errors or ([] if code == 0 else ["(no error line; the compiler's exit code was %d)" % code]):
                print("   ", line)
            failed += code != 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
