"""The tool's web page inlines three.js safely (viewer_page.h), run by Debian's /usr/bin/python3:

  check_viewer_page.py PAGE_PROBE WORK

writes into WORK a three.js directory of scripts that hold, in strings, a template, regular
expressions and comments, every sequence that ends a <script> element early or changes how an
HTML parser reads on ("</script", "<!--", "<script", in any case), has page_probe inline them, and
exits 1 unless: the page's script elements are the five the page has (three.js's three, the
model, the page's own), each read up to its first "</script" as an HTML parser reads it; none
holds such a sequence; and each of three.js's scripts is the file's text but for each such
sequence's '<' written as "\\x3C", which means '<' in JavaScript's strings, templates and regular
expressions.
"""

import pathlib
import re
import subprocess
import sys

probe, work = sys.argv[1], pathlib.Path(sys.argv[2])
SCRIPTS = ["three.min.js", "examples/js/loaders/GLTFLoader.js", "examples/js/controls/OrbitControls.js"]
CODE = [
    'var THREE = {a: "</script>", b: "</SCRIPT >", c: \'<!-- not a comment\', d: `<Script src=x>`};\n',
    "// a comment that says </sCrIpT> and <!-- and <script\nvar loader = /<\\/?script/i.test('<script>');\n",
    "/* <!--<script>--> */ var controls = ['a<b', 'x </scrip', '<!-'];\n",
]
DANGEROUS = re.compile(r"<(!--|script|/script)", re.IGNORECASE)

for name, code in zip(SCRIPTS, CODE):
    path = work / "three" / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(code)
page = work / "page.html"
subprocess.run([probe, str(work / "three"), str(page)], check=True)
html = page.read_text()

# The script elements as an HTML parser splits them: each ends at the first "</script".
elements = re.findall(r"<script[^>]*>(.*?)</script", html, re.IGNORECASE | re.DOTALL)
assert len(elements) == 5, f"{len(elements)} script elements, not 5"
for k, content in enumerate(elements):
    assert not DANGEROUS.search(content), f"script element {k} holds {DANGEROUS.search(content).group(0)!r}"
for k, code in enumerate(CODE):
    inlined = elements[k].strip("\n")
    assert inlined.replace("\\x3C", "<") == code.strip("\n"), f"script {SCRIPTS[k]} is not the file's text:\n{inlined}"
    assert inlined.count("\\x3C") == len(DANGEROUS.findall(code)), f"{SCRIPTS[k]}: not only the sequences escaped"
assert "<title>a &lt;title> &amp; more</title>" in html, "the title is not escaped"
print(f"{page}: five script elements, three.js's inlined with every '<' of {sum(len(DANGEROUS.findall(c)) for c in CODE)} "
      "sequences as \\x3C")
