#!/usr/bin/env python3
"""Runs every shell command of the documentation as a user would paste it.

Extracts the fenced ```sh / ```shell / ```bash blocks of README.md and docs/*.md and runs
each file's blocks verbatim and in order, in one bash process (set -e: the first command
that fails stops the file and is reported with its block), from a fresh temporary directory that
looks like the repository root after `make build`: symlinks to the repository's examples/,
tests/data/, integrations/, scripts/ and the build directory as build/ (so outputs land in
the temporary directory, never in the repository). A command fails the test when it exits
non-zero.

Not run:
  - a block right after the line `<!-- docs-test: skip (REASON) -->` (the few commands that
    are deliberately not runnable here, such as `make test`, which is this test's suite);
  - `make build`, which the build under test has already done;
  - blocks with a command starting with `blender` when Blender is not installed (it runs
    headless, with --background, when it is; no documented command needs a display).

Usage: doc_commands.py SOURCE_DIR BUILD_DIR
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

SKIP_MARK = re.compile(r"^<!--\s*docs-test:\s*skip\b.*-->\s*$")
FENCE = re.compile(r"^\s*```+\s*([\w+-]*)")
SHELL = {"sh", "shell", "bash"}


def blocks(path):
    """(line number, [command lines]) for every shell block of the Markdown file."""
    lines = path.read_text().split("\n")
    out, i, skip_next = [], 0, False
    while i < len(lines):
        line = lines[i]
        if SKIP_MARK.match(line.strip()):
            skip_next = True
        m = FENCE.match(line)
        if m:
            language, start, body = m.group(1), i + 1, []
            i += 1
            while i < len(lines) and not FENCE.match(lines[i]):
                body.append(lines[i])
                i += 1
            if language in SHELL and not skip_next:
                out.append((start + 1, body))
            skip_next = False
        elif line.strip() and not SKIP_MARK.match(line.strip()):
            skip_next = False
        i += 1
    return out


def commands(body):
    """The commands of a block (for counting and skipping): continuation lines joined,
    comments and blanks dropped. The block itself runs verbatim."""
    out, current = [], ""
    for line in body:
        stripped = line.strip()
        if not current and (not stripped or stripped.startswith("#")):
            continue
        if stripped.endswith("\\"):
            current += stripped[:-1] + " "
            continue
        out.append(current + stripped)
        current = ""
    if current:
        out.append(current)
    return out


def sandbox(source, build):
    root = pathlib.Path(tempfile.mkdtemp(prefix="tessera_docs_"))
    for name in ("examples", "integrations", "scripts"):
        (root / name).symlink_to(source / name)
    (root / "tests").mkdir()
    (root / "tests" / "data").symlink_to(source / "tests" / "data")
    (root / "build").symlink_to(build)
    return root


def main():
    source, build = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    files = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    has_blender = shutil.which("blender") is not None
    failures, ran = [], 0
    for doc in files:
        # Each block verbatim (quoted strings may span lines), in order, in one bash: a
        # command that fails stops the file and names its block.
        script = ["set -eE -o pipefail", "trap 'echo \"FAILED ($BLOCK): $BASH_COMMAND\" >&2; exit 1' ERR"]
        for line_number, body in blocks(doc):
            listed = commands(body)
            if any(c.startswith("blender") for c in listed) and not has_blender:
                print("skipped (no blender): %s:%d" % (doc.relative_to(source), line_number))
                continue
            where = "%s:%d" % (doc.relative_to(source), line_number)
            script.append("BLOCK=%s; echo %s >&2" % (shlex_quote(where), shlex_quote("== " + where)))
            script.extend(line for line in body if line.strip() != "make build")
            ran += sum(1 for c in listed if c != "make build")
        if len(script) == 2:
            continue
        root = sandbox(source, build)
        try:
            result = subprocess.run(["bash", "-c", "\n".join(script)], cwd=root, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, text=True, timeout=900)
            if result.returncode != 0:
                failures.append("%s:\n%s" % (doc.relative_to(source), result.stdout[-4000:]))
        finally:
            shutil.rmtree(root, ignore_errors=True)
    print("ran %d documented commands" % ran)
    if failures:
        print("\n\n".join(failures))
        return 1
    return 0


def shlex_quote(text):
    return "'" + text.replace("'", "'\\''") + "'"


if __name__ == "__main__":
    sys.exit(main())
