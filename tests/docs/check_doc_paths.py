#!/usr/bin/env python3
"""Every repository path the README and docs/ cite must exist.

    check_doc_paths.py ROOT [FILE.md ...]    check the files given (default: ROOT/README.md and
                                             ROOT/docs/*.md); exit 1 listing each missing path
    check_doc_paths.py --self-test ROOT FIXTURE.md
                                             check FIXTURE.md and pass only when the paths reported
                                             missing are exactly those its comment
                                             "<!-- expected missing: PATH ... -->" lists (so the
                                             check can fail, and fails only there)

What counts as a cited path:
  - a Markdown link or image target, [text](TARGET): resolved from the citing file's folder, unless
    it is a URL or only an #anchor (anchors are not checked);
  - a word of an inline code span, `...`, that starts with one of ROOT's top-level folders and a
    '/' (`labs/cli/main.cpp`), resolved from ROOT;
  - a word of an inline code span without a '/' that ends in a source file's extension
    (`gauss_elimination.hpp`): some file of that name must exist under ROOT's top-level folders.
In a cited path, '...' stands for any folders (`linalg/.../gauss_seidel.hpp`), '*' is a glob
(`mechanisms/models/*.toml`: at least one match), and a placeholder word stands for any name
(`tests/exercises/mutants/EXERCISE/`, `labs/lessons/lab_NAME.cpp`, `fuzz/corpus/<parser>/`: the
capital words are listed in PLACEHOLDER). Fenced code blocks (transcripts of runs) are not read.
"""

import fnmatch
import glob
import os
import re
import sys

SOURCE_EXTENSIONS = (".hpp", ".cpp", ".h", ".py", ".toml", ".tsv", ".cmake", ".dat", ".in", ".md")
NOT_SOURCE_FOLDERS = {"build", "out"}  # made by a build or a run: what is in them is not cited source
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
CODE_SPAN = re.compile(r"`([^`]+)`")
# A placeholder: a capital word the docs write for a name of the reader's choice (`lab_NAME.cpp`,
# `mutants/EXERCISE/`), or any <word>. It matches any text, as '*' does.
PLACEHOLDER = re.compile(r"<[^>/]+>|(?<![A-Za-z0-9])(BUG_NAME|NAME|FILE|DIR|EXERCISE|SYSTEM|OUT|PREFIX|LANG)(?![A-Za-z0-9])")
# Names the docs give to files a student writes or numlab writes, never files of the repository.
USER_FILES = {"solution.py", "solution.cpp", "f.toml", "model.toml", "TASK.md", "sitecustomize.py"}


def top_level_folders(root):
    return sorted(name for name in os.listdir(root)
                  if os.path.isdir(os.path.join(root, name)) and name not in NOT_SOURCE_FOLDERS
                  and (not name.startswith(".") or name == ".ci"))


def prose_lines(text):
    """The lines of a Markdown text outside fenced code blocks, with their line numbers."""
    fenced = False
    for number, line in enumerate(text.splitlines(), start=1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def as_pattern(path):
    """A cited path as a glob: '...' is any folders, a placeholder any text within one folder."""
    return "/".join("**" if part == "..." else PLACEHOLDER.sub("*", part) for part in path.split("/"))


def exists(base, path):
    """PATH under BASE, as a glob; a path without an extension may name a file's stem
    (`labs/parsing/argument_parsing`: its .hpp and .cpp)."""
    pattern = os.path.join(base, as_pattern(path.rstrip("/")))
    if glob.glob(pattern, recursive=True):
        return True
    return "." not in os.path.basename(path) and bool(glob.glob(pattern + ".*", recursive=True))


def file_names(root, folders):
    names = set()
    for folder in folders:
        for _, _, files in os.walk(os.path.join(root, folder)):
            names.update(files)
    for name in os.listdir(root):
        if os.path.isfile(os.path.join(root, name)):
            names.add(name)
    return names


def cited_paths(md_file, root, folders):
    """(line, path, base folder or None for 'a file of this name somewhere') for each citation."""
    with open(md_file, encoding="utf-8") as f:
        text = f.read()
    here = os.path.dirname(os.path.abspath(md_file))
    prefixes = tuple(folder + "/" for folder in folders)
    for number, line in prose_lines(text):
        for target in LINK.findall(line):
            target = target.split("#", 1)[0]
            if target and not re.match(r"^[a-z][a-z0-9+.-]*:", target):
                yield number, target, here
        for span in CODE_SPAN.findall(line):
            for word in span.split():
                word = word.strip(",;:()'\"")
                if word.startswith(prefixes):
                    yield number, word, root
                elif "/" not in word and word.endswith(SOURCE_EXTENSIONS) and not word.startswith("."):
                    if word not in USER_FILES:
                        yield number, word, None


def missing_paths(root, md_files):
    folders = top_level_folders(root)
    names = file_names(root, folders)
    missing = []
    for md_file in md_files:
        for number, path, base in cited_paths(md_file, root, folders):
            found = bool(fnmatch.filter(names, as_pattern(path))) if base is None else exists(base, path)
            if not found:
                missing.append((os.path.relpath(md_file, root), number, path))
    return missing


def report(missing):
    for md_file, number, path in missing:
        print(f"{md_file}:{number}: cites {path}, which does not exist")


def main(argv):
    if len(argv) == 3 and argv[0] == "--self-test":
        root, fixture = argv[1], argv[2]
        missing = missing_paths(root, [fixture])
        reported = sorted({path for _, _, path in missing})
        with open(fixture, encoding="utf-8") as f:
            text = f.read()
        listed = re.search(r"<!-- expected missing:(.*?)-->", text, re.S)
        expected = sorted(set(listed.group(1).split())) if listed else []
        if reported != expected or not expected:
            print("self-test failed: reported missing", reported, "expected", expected)
            return 1
        print(f"self-test: the {len(expected)} missing paths of {os.path.basename(fixture)} reported, nothing else")
        return 0
    if not argv:
        print(__doc__)
        return 2
    root = argv[0]
    md_files = argv[1:] or [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    missing = missing_paths(root, md_files)
    report(missing)
    if missing:
        print(f"{len(missing)} cited paths do not exist: fix the citation or the file")
        return 1
    print(f"every path cited in {len(md_files)} files exists")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
