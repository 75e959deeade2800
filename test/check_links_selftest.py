#!/usr/bin/env python3
"""Proves that check_links.py can fail: on a tiny fake repository (a temporary folder, not a git
checkout) with one good and one broken link in README.md, a good and a broken anchor in
doc/x.md, and a header whose comment names a missing doc/missing.md, it must exit 1 and report
exactly the three broken references; once they are fixed, it must exit 0.
Usage: check_links_selftest.py   (standard library only)

The paths below are the fake repository's, not this one's (check_links: skip this file).
"""

import os
import subprocess
import sys
import tempfile

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_links.py")


def write(root, name, text):
    path = os.path.join(root, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run(root):
    result = subprocess.run([sys.executable, CHECKER, root], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, universal_newlines=True)
    return result.returncode, result.stdout.splitlines()


def main():
    failures = []

    def expect(condition, what):
        if not condition:
            failures.append(what)

    with tempfile.TemporaryDirectory() as root:
        write(root, "README.md",
              "# Fake\n\nSee [the guide](doc/x.md) and [the missing page](doc/gone.md).\n\n"
              "```sh\ncat doc/not_a_link.md  # in a code block: not checked\n```\n")
        write(root, "doc/x.md",
              "# X\n\n## The first section\n\nText.\n\n## Second: with `code`, punctuation!\n\n"
              "Back to [the first](#the-first-section), on to [the second](#second-with-code-punctuation)"
              " and [nowhere](#no-such-section).\n")
        write(root, "include/a.h",
              "// The design: doc/x.md, \"The first section\"; the rest: doc/missing.md.\n"
              "int a();\n")

        code, out = run(root)
        broken = [line for line in out if not line.startswith("check_links:")]
        expected = ["README.md:3: doc/gone.md",
                    "doc/x.md:9: #no-such-section",
                    "include/a.h:1: doc/missing.md"]
        expect(code == 1, "exit status %d on the broken tree, expected 1" % code)
        expect(sorted(broken) == sorted(expected),
               "reported %r, expected exactly %r" % (broken, expected))

        write(root, "doc/gone.md", "# Gone\n")
        write(root, "doc/missing.md", "# Missing\n")
        write(root, "doc/x.md",
              "# X\n\n## The first section\n\nText.\n\n## Second: with `code`, punctuation!\n\n"
              "Back to [the first](#the-first-section), on to [the second](#second-with-code-punctuation)"
              " and [the README](../README.md#fake).\n")
        code, out = run(root)
        expect(code == 0, "exit status %d on the fixed tree, expected 0; output: %r" % (code, out))
        expect(len(out) == 1 and out[0].startswith("check_links:"),
               "on the fixed tree, expected one summary line, got %r" % out)

    for f in failures:
        print("FAIL: " + f)
    if failures:
        return 1
    print("check_links_selftest: check_links.py reports exactly the 3 broken references, "
          "and passes once they are fixed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
