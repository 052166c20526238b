#!/usr/bin/env python3
"""clang-tidy over the translation units of a compile database, skipping those that passed before.

A translation unit's key is the SHA-256 of the clang-tidy version, the .clang-tidy file, its compile
command and its preprocessed text (clang++ -E: the file and every header it includes). A unit that
passes leaves a stamp named by its key in the stamp folder; a later run skips a unit whose key has a
stamp, so an interrupted run resumes where it stopped, and an edit to a header checks again exactly
the units that include it. Exits 1 when a unit has a finding (clang-tidy's output printed), 2 on bad
arguments.

Usage: clang_tidy_cached.py BUILD_DIR FILE_REGEX [--jobs N] [--stamps DIR]
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys

TIDY = "clang-tidy-14"
CLANG = "clang++-14"


def preprocess_arguments(entry):
    """The compile command as a clang++ -E to stdout (the output file and -c dropped)."""
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    out = [CLANG]
    skip = False
    for a in args[1:]:
        if skip:
            skip = False
            continue
        if a == "-o":
            skip = True
            continue
        if a == "-c":
            continue
        out.append(a)
    return out + ["-E", "-w", "-o", "-"]


def unit_key(entry, salt):
    result = subprocess.run(preprocess_arguments(entry), cwd=entry["directory"], capture_output=True, check=False)
    if result.returncode != 0:
        return None  # clang-tidy reports why
    h = hashlib.sha256(salt)
    h.update(json.dumps(entry.get("command", entry.get("arguments"))).encode())
    h.update(result.stdout)
    return h.hexdigest()


def check_unit(entry, build_dir, stamps, salt):
    key = unit_key(entry, salt)
    stamp = os.path.join(stamps, key) if key else None
    if stamp and os.path.exists(stamp):
        return entry["file"], "unchanged", ""
    result = subprocess.run([TIDY, "-p", build_dir, "-quiet", entry["file"]], capture_output=True, text=True, check=False)
    if result.returncode != 0:
        noise = re.compile(r"^\d+ warnings? generated\.$|^Suppressed \d+ warnings|^Use -header-filter")
        lines = (result.stdout + result.stderr).splitlines()
        return entry["file"], "failed", "\n".join(line for line in lines if not noise.match(line))
    if stamp:
        with open(stamp, "w", encoding="utf-8") as f:
            f.write(entry["file"] + "\n")
    return entry["file"], "passed", ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("file_regex")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--stamps", default=None, help="default: BUILD_DIR/clang-tidy-passed")
    options = parser.parse_args()
    database = os.path.join(options.build_dir, "compile_commands.json")
    if not os.path.isfile(database):
        print(f"clang_tidy_cached: no {database}", file=sys.stderr)
        return 2
    stamps = options.stamps or os.path.join(options.build_dir, "clang-tidy-passed")
    os.makedirs(stamps, exist_ok=True)
    with open(database, encoding="utf-8") as f:
        entries = [e for e in json.load(f) if re.search(options.file_regex, e["file"])]
    with open(".clang-tidy", "rb") as f:
        salt = subprocess.run([TIDY, "--version"], capture_output=True, check=True).stdout + f.read()

    counts = {"passed": 0, "unchanged": 0, "failed": 0}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.jobs)) as pool:
        futures = [pool.submit(check_unit, e, options.build_dir, stamps, salt) for e in entries]
        for done, future in enumerate(concurrent.futures.as_completed(futures), start=1):
            path, status, output = future.result()
            counts[status] += 1
            if status == "failed":
                print(output, flush=True)
            print(f"[{done}/{len(entries)}] {status}: {path}", flush=True)
    print(f"clang_tidy_cached: {len(entries)} units: {counts['passed']} checked and passed, "
          f"{counts['unchanged']} unchanged since they passed, {counts['failed']} with findings")
    return 1 if counts["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
