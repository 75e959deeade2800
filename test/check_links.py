#!/usr/bin/env python3
"""Checks that every link of the documentation and every repository path the sources name exists.

Usage: check_links.py [repository root]   (default: the parent of this script's folder)

(a) Every Markdown file (*.md, doc/performance-log.md included): each relative link target,
    `[text](path)`, `![alt](path)`, `[label]: path`, `<img src="path">` and `<a href="path">`,
    must exist (a file or a folder, relative to the Markdown file; a leading / is the repository
    root). A `#anchor`, into the same file or into another Markdown file, must match one of that
    file's headings under GitHub's slug rules (lower case, punctuation other than - and _
    removed, spaces to hyphens, -1, -2 ... on repeats). Links inside code blocks and code spans
    are not links; URLs with a scheme (https:, mailto: ...) are not checked. Outside code
    blocks, the repository paths its text names are checked too, as in (b).

(b) Every source file (*.h, *.cpp, *.py, *.pyi, *.js, *.sh, *.cmake, CMakeLists.txt): each token
    that names a repository path, in its comments, docstrings and strings alike, must exist:
    a token starting with one of the repository's top-level entries (doc/, include/, test/,
    tools/, python/, blender/, examples/, benchmark/, fuzz/, cmake/, .ci/, README.md), relative
    to the root or to the source file's own folder, and a bare `NAME.md`, which names a file of
    doc/ (or of the root, as README.md). A program may be named by its source without the
    suffix (test/uv_bits for test/uv_bits.cpp). Skipped: tokens holding `<`, `*`, `$`, `{`, `%`
    or `...` (patterns, variables, elisions), placeholders in capitals (FILE.md), the target of
    a shell redirection (a file a command writes: > table.md), #include <...> lines and
    three.js's own examples/js/ paths; build outputs (build/...) start with no top-level entry
    and are not checked. A source file whose text holds the marker "check_links: skip this
    file" (the self-test, whose paths are its fake repository's) is not searched for paths.

The files are those of `git ls-files` (tracked, and untracked files git does not ignore); where
the root is not a git checkout, the files of its tree (no .git, no build* folders).
Prints each broken reference as `file:line: target` and exits 1 if any, else prints a one-line
summary and exits 0. Standard library only.
"""

import os
import re
import subprocess
import sys
import urllib.parse

TOP_LEVEL = ("doc", "include", "test", "tools", "python", "blender", "examples", "benchmark",
             "fuzz", "cmake", ".ci")
SOURCE_SUFFIXES = (".h", ".cpp", ".py", ".pyi", ".js", ".sh", ".cmake")
SKIP_CHARS = ("<", "*", "$", "{", "%", "...")


def list_files(root):
    """Files of the repository, relative to root, with forward slashes."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others",
                              "--exclude-standard"], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, check=True).stdout
        # Is root the top of that checkout (not a folder inside another repository)?
        top = subprocess.run(["git", "-C", root, "rev-parse", "--show-toplevel"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             check=True).stdout.decode().strip()
        if os.path.realpath(top) != os.path.realpath(root):
            raise OSError("not the top of a checkout")
        names = sorted(set(n for n in out.decode("utf-8", "replace").split("\0") if n))
        return [n for n in names if os.path.isfile(os.path.join(root, n))]
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for folder, dirs, names in os.walk(root):
        rel = os.path.relpath(folder, root)
        dirs[:] = sorted(d for d in dirs
                         if d != ".git" and not (rel == "." and d.startswith("build")))
        for n in sorted(names):
            files.append(os.path.normpath(os.path.join(rel, n)).replace(os.sep, "/"))
    return files


def read_text(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


# ---------------------------------------------------------------------------------------------
# Markdown

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>\n]*>|[^()\s]+(?:\([^()\s]*\))?)"
                         r"(?:\s+(?:\"[^\"]*\"|'[^']*'|\([^)]*\)))?\s*\)")
REFERENCE_DEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
HTML_ATTR = re.compile(r"<(?:img|a|source)\b[^>]*?\b(?:src|href)\s*=\s*(\"[^\"]*\"|'[^']*')",
                       re.IGNORECASE)
ATX_HEADING = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$")
SETEXT_UNDERLINE = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
HTML_ID = re.compile(r"<[^>]*\b(?:id|name)\s*=\s*[\"']([^\"']+)[\"']", re.IGNORECASE)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:|^//")


def markdown_lines(text, blank_code_spans=True):
    """(line number, line) of the lines outside fenced code blocks, code spans blanked."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if fence is not None:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) \
                    and not line.strip().strip(fence[0]):
                fence = None
            continue
        if m:
            fence = m.group(1)
            continue
        yield number, CODE_SPAN.sub(lambda s: " " * len(s.group(0)), line) if blank_code_spans else line


def heading_text(raw):
    """The text GitHub renders for a heading's Markdown."""
    text = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", raw)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"\[([^\]]*)\]\[[^\]]*\]", r"\1", text)
    text = re.sub(r"<[^>]+>", "", text)
    return text.replace("`", "")


def github_slug(text):
    text = heading_text(text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


_anchor_cache = {}


def anchors_of(path):
    """The anchors GitHub makes for a Markdown file: its headings' slugs and explicit ids."""
    if path in _anchor_cache:
        return _anchor_cache[path]
    text = read_text(path)
    seen = {}
    anchors = set()
    previous = None
    fence = None
    for line in text.split("\n"):
        m = FENCE.match(line)
        if fence is not None:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) \
                    and not line.strip().strip(fence[0]):
                fence = None
            previous = None
            continue
        if m:
            fence = m.group(1)
            previous = None
            continue
        heading = None
        h = ATX_HEADING.match(line)
        if h:
            heading = h.group(2) or ""
        elif previous and SETEXT_UNDERLINE.match(line) and not previous.startswith((" " * 4, "|")) \
                and not ATX_HEADING.match(previous) and not previous.lstrip().startswith(("-", "*", ">")):
            heading = previous.strip()
        if heading is not None:
            slug = github_slug(heading)
            if slug in seen:
                seen[slug] += 1
                slug = "%s-%d" % (slug, seen[slug])
            else:
                seen[slug] = 0
            anchors.add(slug)
        for explicit in HTML_ID.findall(line):
            anchors.add(explicit.lower())
        previous = line if line.strip() else None
    _anchor_cache[path] = anchors
    return anchors


def check_target(root, markdown_file, target):
    """None if target (a relative reference, maybe with #anchor) exists, else why not."""
    path, _, anchor = target.partition("#")
    path = urllib.parse.unquote(path)
    anchor = urllib.parse.unquote(anchor)
    if not path:  # #anchor: into the file itself
        resolved = markdown_file
    elif path.startswith("/"):
        resolved = os.path.normpath(os.path.join(root, path.lstrip("/")))
    else:
        resolved = os.path.normpath(os.path.join(os.path.dirname(markdown_file), path))
    if not os.path.exists(resolved):
        return "missing"
    if anchor and resolved.endswith(".md") and os.path.isfile(resolved):
        if anchor.lower() not in anchors_of(resolved):
            return "no such heading"
    return None


def markdown_targets(text):
    for number, line in markdown_lines(text):
        targets = [m.group(1) for m in INLINE_LINK.finditer(line)]
        m = REFERENCE_DEF.match(line)
        if m:
            targets.append(m.group(1))
        targets += [m.group(1)[1:-1] for m in HTML_ATTR.finditer(line)]
        for target in targets:
            if target.startswith("<") and target.endswith(">"):
                target = target[1:-1]
            target = target.strip()
            if not target or SCHEME.match(target):
                continue
            yield number, target


# ---------------------------------------------------------------------------------------------
# Sources

PATH_TOKEN = re.compile(
    r"(?<![\w./\\$}{@-])"
    r"((?:(?:" + "|".join(re.escape(t) for t in TOP_LEVEL) + r")/|README\.md\b)[^\s\"'`(),;:\[\]=]*"
    r"|[\w+-][\w.+-]*\.md\b[^\s\"'`(),;:\[\]=]*)")


SYSTEM_INCLUDE = re.compile(r"^\s*#\s*include\s*<")
REDIRECT = re.compile(r"(?:^|\s)\d?>>?\s*$")
PLACEHOLDER = re.compile(r"^[A-Z][A-Z0-9_]*\.md$")
# Paths of other packages that start like one of ours: three.js's scripts, relative to its folder.
EXTERNAL = ("examples/js/",)
# A source file holding this marker names the files of another tree: its paths are not checked.
SKIP_FILE = "check_links: " + "skip this file"


def source_paths(text):
    for number, line in enumerate(text.split("\n"), 1):
        if SYSTEM_INCLUDE.match(line):  # a system include: another package's header
            continue
        for m in PATH_TOKEN.finditer(line):
            token = m.group(1)
            start, end = m.start(1), m.end(1)
            # A token running on into a pattern or a variable: `doc/figures/<mesh>.png`.
            if end < len(line) and line[end] in "<$":
                continue
            if REDIRECT.search(line[:start]):  # `... > table.md`: a file the command writes
                continue
            token = token.rstrip(".,:;!?)'\"\\")
            if start > 0 and line[start - 1] == "<":  # <tools/texture_mesh/test/test_meshes.py>
                token = token.rstrip(">")
            if not token or any(c in token for c in SKIP_CHARS) or token.startswith(EXTERNAL):
                continue
            if PLACEHOLDER.match(token) and token != "README.md":  # usage: FILE.md
                continue
            yield number, token


def check_source_token(root, folder, token):
    path, _, anchor = token.partition("#")
    if path.startswith(tuple(t + "/" for t in TOP_LEVEL)) or path == "README.md":
        candidates = [os.path.join(root, path), os.path.join(folder, path)]
    else:  # a bare NAME.md: a file of doc/ (or of the root)
        candidates = [os.path.join(root, "doc", path), os.path.join(root, path),
                      os.path.join(folder, path)]
    for c in candidates:
        c = os.path.normpath(c)
        if os.path.exists(c) or any(os.path.isfile(c + s) for s in (".cpp", ".py")):
            if anchor and c.endswith(".md") and os.path.isfile(c) \
                    and anchor.lower() not in anchors_of(c):
                return "no such heading"
            return None
    return "missing"


def is_source(name):
    base = name.rsplit("/", 1)[-1]
    return base == "CMakeLists.txt" or base.endswith(SOURCE_SUFFIXES)


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1] in ("-h", "--help")):
        print("usage: check_links.py [repository root]")
        return 2
    root = os.path.abspath(argv[1] if len(argv) == 2 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
    if not os.path.isdir(root):
        print("check_links: no such folder: %s" % root)
        return 2
    files = list_files(root)
    broken = []
    counts = {"md": 0, "links": 0, "sources": 0, "paths": 0}
    for name in files:
        full = os.path.join(root, name)
        folder = os.path.dirname(full)
        if name.endswith(".md"):
            counts["md"] += 1
            text = read_text(full)
            reported = set()
            for number, target in markdown_targets(text):
                counts["links"] += 1
                if check_target(root, full, target):
                    broken.append("%s:%d: %s" % (name, number, target))
                    reported.add((number, target))
            # Repository paths its prose names, as in the sources (code blocks excluded).
            for number, line in markdown_lines(text, blank_code_spans=False):
                for _, token in source_paths(line):
                    counts["paths"] += 1
                    if (number, token) not in reported and check_source_token(root, folder, token):
                        broken.append("%s:%d: %s" % (name, number, token))
                        reported.add((number, token))
        elif is_source(name):
            counts["sources"] += 1
            text = read_text(full)
            if SKIP_FILE in text:  # its paths are another tree's (the self-test's fake repository)
                continue
            for number, token in source_paths(text):
                counts["paths"] += 1
                if check_source_token(root, folder, token):
                    broken.append("%s:%d: %s" % (name, number, token))
    for line in broken:
        print(line)
    if broken:
        print("check_links: %d broken reference%s" % (len(broken), "" if len(broken) == 1 else "s"))
        return 1
    print("check_links: %d links and %d named paths in %d Markdown and %d source files, all exist"
          % (counts["links"], counts["paths"], counts["md"], counts["sources"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
