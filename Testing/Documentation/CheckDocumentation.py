"""The documentation's shape: the README short (at most 150 lines) and linking every page of
Documentation/ (pages in its folders linked from those pages), and every relative link and picture in the README and the pages resolving to a
file of the checkout (an anchor's page must exist; the anchor itself is not checked).
Usage: CheckDocumentation.py SOURCE_DIR"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1])
failures = []
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def links(path):
    """The relative targets of the Markdown links and pictures in `path`, outside code."""
    fence = False
    found = []
    with open(path, encoding="utf-8") as text:
        for line in text:
            if line.startswith("```"):
                fence = not fence
                continue
            if not fence:
                found += [t for t in LINK.findall(line) if not re.match(r"^[a-z]+:", t)]
    return found


readme = os.path.join(root, "README.md")
lines = sum(1 for _ in open(readme, encoding="utf-8"))
if lines > 150:
    failures.append(f"README.md has {lines} lines (at most 150)")
documentation = os.path.join(root, "Documentation")
pages = sorted(p for p in os.listdir(documentation) if p.endswith(".md"))
linked = {os.path.normpath(os.path.join(root, t.split("#")[0])) for t in links(readme)}
for page in pages:
    if os.path.join(documentation, page) not in linked:
        failures.append(f"Documentation/{page} is not linked from README.md")
# Pages in folders of Documentation/ (the measured tables) are reached through the pages.
nested = sorted(os.path.join(folder, name) for folder, _, names in os.walk(documentation)
                if folder != documentation for name in names if name.endswith(".md"))
reached = set(linked)
for page in pages:
    path = os.path.join(documentation, page)
    reached |= {os.path.normpath(os.path.join(documentation, t.split("#")[0])) for t in links(path)}
for path in nested:
    if path not in reached:
        failures.append(f"{os.path.relpath(path, root)} is not linked from README.md or a page it links")
for path in [readme] + [os.path.join(documentation, p) for p in pages] + nested:
    for target in links(path):
        file = target.split("#")[0]
        if file and not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), file))):
            failures.append(f"{os.path.relpath(path, root)}: the link {target} leads nowhere")
print(f"README.md: {lines} lines; {len(pages)} pages and {len(nested)} in folders, each linked: {not any('not linked' in f for f in failures)}")
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
