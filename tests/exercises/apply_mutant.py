#!/usr/bin/env python3
"""Makes a mutant from its patch: a unified diff against a reference solution.

  apply_mutant.py PATCH OUT_FILE    write the mutant PATCH describes to OUT_FILE

A mutant is tests/exercises/mutants/EXERCISE/NAME.patch (docs/exercises.md): `diff -u` of
references/python/EXERCISE.py (the '---' line, relative to tests/exercises/) and the mutant (the
'+++' line, mutants/EXERCISE/NAME.py). Each hunk must apply exactly where it says, every context
and removed line as written: no offset, no fuzz. A patch that does not apply is an error that names
the patch, the hunk and the first line that differs, never a mutant made from a guess.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
HUNK = re.compile(r"^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@")


class PatchError(Exception):
    pass


def parse(patch_text):
    """The reference path (from '---') and the hunks: (old_start, old_count, lines)."""
    lines = patch_text.splitlines(keepends=True)
    if len(lines) < 3 or not lines[0].startswith("--- ") or not lines[1].startswith("+++ "):
        raise PatchError("not a unified diff: it must start with a '---' and a '+++' line")
    reference = lines[0][4:].split("\t")[0].strip()
    hunks = []
    for line in lines[2:]:
        match = HUNK.match(line)
        if match:
            old_start, old_count = int(match[1]), int(match[2] or 1)
            hunks.append((old_start, old_count, [], line.strip()))
        elif not hunks:
            raise PatchError(f"a line before the first hunk: {line.rstrip()}")
        elif line.startswith("\\"):  # "\ No newline at end of file": the line before has none
            hunks[-1][2][-1] = hunks[-1][2][-1].rstrip("\n")
        elif line[:1] in (" ", "-", "+"):
            hunks[-1][2].append(line)
        elif line in ("\n", ""):  # an empty context line whose space was stripped
            hunks[-1][2].append(" \n")
        else:
            raise PatchError(f"not a hunk line: {line.rstrip()}")
    if not hunks:
        raise PatchError("no hunk")
    return reference, hunks


def apply(reference_text, hunks):
    """The reference with each hunk applied exactly; PatchError names the first that does not fit."""
    old = reference_text.splitlines(keepends=True)
    out = []
    at = 0  # lines of `old` copied or consumed so far
    for number, (old_start, old_count, body, header) in enumerate(hunks, start=1):
        start = old_start if old_count == 0 else old_start - 1
        if start < at:
            raise PatchError(f"hunk {number} ({header}) overlaps the hunk before it")
        out.extend(old[at:start])
        at = start
        expected = [line[1:] for line in body if line[0] in " -"]
        if len(expected) != old_count:
            raise PatchError(f"hunk {number} ({header}) has {len(expected)} old lines, its header says {old_count}")
        for offset, want in enumerate(expected):
            have = old[at + offset] if at + offset < len(old) else "<end of file>"
            if have != want:
                raise PatchError(f"hunk {number} ({header}) does not apply at line {at + offset + 1}: "
                                 f"the reference has {have.rstrip()!r}, the patch expects {want.rstrip()!r}")
        out.extend(line[1:] for line in body if line[0] in " +")
        at += old_count
    out.extend(old[at:])
    return "".join(out)


def make_mutant(patch_path, out_path):
    """Writes the mutant of PATCH to OUT_PATH; exits naming the patch when it does not apply."""
    try:
        with open(patch_path, encoding="utf-8") as patch:
            reference, hunks = parse(patch.read())
        reference_path = os.path.join(HERE, reference)
        if not os.path.isfile(reference_path):
            raise PatchError(f"its reference {reference} (from tests/exercises/) does not exist")
        with open(reference_path, encoding="utf-8") as source:
            text = apply(source.read(), hunks)
    except PatchError as error:
        sys.exit(f"the mutant patch {patch_path} does not apply: {error}")
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    with open(out_path, "w", encoding="utf-8") as mutant:
        mutant.write(text)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    make_mutant(sys.argv[1], sys.argv[2])
