#!/usr/bin/env python3
"""clang-tidy over the translation units of a compile database, in batches, skipping what passed before.

Most of clang-tidy 14's time on a unit goes to matching over the Qt, Eigen and standard headers it
includes, not over the unit's own code. Units of one folder that share a compile command are
therefore checked together, up to --batch of them in one generated unit that includes each (the
header filter widened to those files, so that their findings are reported as in a unit of their own).
A batch that does not compile as one unit (two files define the same file-scope name) is split in
halves until it does, down to single units (and remembered as such, so that a rerun splits it at once).

A check's key is the SHA-256 of the clang-tidy version, the .clang-tidy file, its compile command and
its preprocessed text (clang++ -E: the files and every header they include). A check that passes
leaves a stamp named by its key in the stamp folder; a later run skips a check whose key has a stamp,
so an interrupted run resumes where it stopped, and an edit to a header checks again exactly the
batches that include it. Exits 1 when a unit has a finding (clang-tidy's output printed), 2 on bad
arguments.

Usage: clang_tidy_cached.py BUILD_DIR FILE_REGEX [--jobs N] [--batch N] [--stamps DIR]
"""
import argparse
import concurrent.futures
import hashlib
import itertools
import json
import os
import re
import shlex
import subprocess
import sys

TIDY = "clang-tidy-14"
CLANG = "clang++-14"
NOISE = re.compile(r"^\d+ warnings?( and \d+ errors?)? generated\.$|^Suppressed \d+ warnings|^Use -header-filter")


def command_arguments(entry):
    return shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])


def shared_command(entry):
    """The compile command without its source and output file: equal for units compiled alike."""
    args = command_arguments(entry)
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a not in ("-c", entry["file"]):
            out.append(a)
    return tuple(out)


def preprocessed(entry):
    """The unit's text after the preprocessor (clang++ -E), or None when that fails."""
    args = [CLANG, *shared_command(entry)[1:], entry["file"], "-E", "-w", "-o", "-"]
    result = subprocess.run(args, cwd=entry["directory"], capture_output=True, check=False)
    return result.stdout if result.returncode == 0 else None


def unit_identity(entry):
    """What clang-tidy's result on a unit depends on: its preprocessed text and the flags other than
    the include paths and defines (already applied to the text)."""
    flags, skip = [], False
    for a in shared_command(entry)[1:]:
        if skip:
            skip = False
        elif a in ("-I", "-isystem", "-D"):
            skip = True
        elif not a.startswith(("-I", "-isystem", "-D")):
            flags.append(a)
    text = preprocessed(entry)
    return None if text is None else hashlib.sha256(json.dumps(flags).encode() + text).hexdigest()


def distinct_units(entries, pool):
    """The entries without the repeats of a file compiled alike into several programs (the one test
    main of every test program): one entry for each different preprocessed text of a file."""
    by_file = {}
    for e in entries:
        by_file.setdefault(e["file"], []).append(e)
    repeated = [e for same in by_file.values() if len(same) > 1 for e in same]
    identities = dict(zip(map(id, repeated), pool.map(unit_identity, repeated)))
    out, seen = [], set()
    for e in entries:
        identity = identities.get(id(e))
        if identity is not None and (e["file"], identity) in seen:
            continue
        seen.add((e["file"], identity))
        out.append(e)
    return out


def ere_escape(text):
    """`text` as a literal in the POSIX extended regular expressions of clang-tidy's header filter."""
    return re.sub(r"([.\[\]()*+?{}|^$\\])", r"\\\1", text)


class Checker:
    def __init__(self, build_dir, stamps, salt, header_filter, batch_dir):
        self.build_dir = build_dir
        self.stamps = stamps
        self.salt = salt
        self.header_filter = header_filter
        self.batch_dir = batch_dir

    def batch_entry(self, entries):
        """One entry for all of `entries`: a generated unit that includes each, with their command."""
        if len(entries) == 1:
            return entries[0]
        files = [e["file"] for e in entries]
        name = hashlib.sha256("\n".join(files).encode()).hexdigest()[:16]
        path = os.path.join(self.batch_dir, f"batch_{name}.cpp")
        with open(path, "w", encoding="utf-8") as f:
            f.writelines(f'#include "{p}" // NOLINT(bugprone-suspicious-include)\n' for p in files)
        return {"directory": entries[0]["directory"], "file": path,
                "arguments": list(shared_command(entries[0])) + ["-c", path]}

    def key(self, entry):
        text = preprocessed(entry)
        if text is None:
            return None  # clang-tidy reports why
        h = hashlib.sha256(self.salt)
        h.update(json.dumps(shared_command(entry)).encode())
        h.update(text)
        return h.hexdigest()

    def tidy(self, entry, members):
        database = self.build_dir
        extra = []
        if entry["file"].startswith(self.batch_dir):
            database = os.path.join(self.batch_dir, os.path.basename(entry["file"]) + ".d")
            os.makedirs(database, exist_ok=True)
            with open(os.path.join(database, "compile_commands.json"), "w", encoding="utf-8") as f:
                json.dump([entry], f)
            members_regex = "|".join("^" + ere_escape(e["file"]) + "$" for e in members)
            extra = [f"--header-filter=({self.header_filter})|{members_regex}"]
        result = subprocess.run([TIDY, "-p", database, "-quiet"] + extra + [entry["file"]], capture_output=True, text=True, check=False)
        return result.returncode, [line for line in (result.stdout + result.stderr).splitlines() if not NOISE.match(line)]

    @staticmethod
    def write_stamp(path, files):
        with open(path, "w", encoding="utf-8") as f:
            f.writelines(p + "\n" for p in files)

    def check(self, entries):
        """Checks `entries` as one batch, or in halves when they do not compile as one: a list of
        (files, status, output), one for each batch checked."""
        entry = self.batch_entry(entries)
        key = self.key(entry)
        stamp = os.path.join(self.stamps, key) if key else None
        files = [e["file"] for e in entries]
        if stamp and os.path.exists(stamp):
            return [(files, "unchanged", "")]
        half = len(entries) // 2
        if stamp and os.path.exists(stamp + ".split"):
            return self.check(entries[:half]) + self.check(entries[half:])
        code, lines = self.tidy(entry, entries)
        if code != 0 and len(entries) > 1 and any("[clang-diagnostic-error]" in line for line in lines):
            print(f"split a batch of {len(entries)} that does not compile as one unit: "
                  + "; ".join(line for line in lines if "[clang-diagnostic-error]" in line), flush=True)
            if stamp:
                self.write_stamp(stamp + ".split", files)
            return self.check(entries[:half]) + self.check(entries[half:])
        if code != 0:
            return [(files, "failed", "\n".join(lines))]
        if stamp:
            self.write_stamp(stamp, files)
        return [(files, "passed", "")]


def batches(entries, size):
    """The entries in groups of at most `size` of one folder and one shared command."""
    def group(e):
        return (e["directory"], os.path.dirname(e["file"]), shared_command(e))

    out = []
    for _, members in itertools.groupby(sorted(entries, key=lambda e: (group(e), e["file"])), key=group):
        members = list(members)
        out += [members[i:i + size] for i in range(0, len(members), size)]
    return out


def header_filter_of(config_text):
    match = re.search(r"^HeaderFilterRegex:\s*'(.*)'\s*$", config_text, re.MULTILINE)
    return match.group(1) if match else "$^"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("file_regex")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--batch", type=int, default=8, help="units checked together at most (1: one by one)")
    parser.add_argument("--stamps", default=None, help="default: BUILD_DIR/clang-tidy-passed")
    options = parser.parse_args()
    database = os.path.join(options.build_dir, "compile_commands.json")
    if options.batch < 1:
        print(f"clang_tidy_cached: --batch = {options.batch}: must be 1 or more", file=sys.stderr)
        return 2
    if not os.path.isfile(database):
        print(f"clang_tidy_cached: no {database}", file=sys.stderr)
        return 2
    build_dir = os.path.abspath(options.build_dir)
    stamps = options.stamps or os.path.join(build_dir, "clang-tidy-passed")
    batch_dir = os.path.join(build_dir, "clang-tidy-batches")
    os.makedirs(stamps, exist_ok=True)
    os.makedirs(batch_dir, exist_ok=True)
    with open(database, encoding="utf-8") as f:
        entries = [e for e in json.load(f) if re.search(options.file_regex, e["file"])]
    with open(".clang-tidy", "rb") as f:
        config = f.read()
    salt = subprocess.run([TIDY, "--version"], capture_output=True, check=True).stdout + config
    checker = Checker(build_dir, stamps, salt, header_filter_of(config.decode()), batch_dir)

    counts = {"passed": 0, "unchanged": 0, "failed": 0}
    done = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.jobs)) as pool:
        compiled = len(entries)
        entries = distinct_units(entries, pool)
        groups = batches(entries, options.batch)
        print(f"clang_tidy_cached: {compiled} compiled units, {len(entries)} different, in {len(groups)} batches",
              flush=True)
        for future in concurrent.futures.as_completed([pool.submit(checker.check, g) for g in groups]):
            for files, status, output in future.result():
                done += len(files)
                counts[status] += len(files)
                if status == "failed":
                    print(output, flush=True)
                print(f"[{done}/{len(entries)}] {status}: {', '.join(files)}", flush=True)
    print(f"clang_tidy_cached: {len(entries)} units in {len(groups)} batches: {counts['passed']} checked and passed, "
          f"{counts['unchanged']} unchanged since they passed, {counts['failed']} in a batch with findings")
    return 1 if counts["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
