"""What the book build's Python steps share: the book's Markdown pages, read once, and
writing an output file so that it is never half-written under its final name."""
import glob
import os
import re


def pages(source_dir):
    """[(page id, title, text)] of book/*.md that begin with `# Title {#id}`, sorted by file."""
    out = []
    for md in sorted(glob.glob(os.path.join(source_dir, "book", "*.md"))):
        with open(md, encoding="utf-8") as f:
            text = f.read()
        head = re.match(r"#\s+(.*?)\s*\{#([\w-]+)\}", text)
        if head:
            out.append((head.group(2), head.group(1), text))
    return out


def write_text(path, text):
    """Write TEXT to PATH through a temporary file beside it, renamed when complete."""
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def chapter_labels(source_dir):
    """{page id: label} for the chapters and appendices, in the order of the table of contents
    on the first page (book/index.md, its `\\subpage` list): chapter-* pages are numbered 1, 2,
    ..., appendix-* pages lettered A, B, ...; the other pages (report, tables) have none."""
    with open(os.path.join(source_dir, "book", "index.md"), encoding="utf-8") as f:
        order = re.findall(r"\\subpage\s+([\w-]+)", f.read())
    labels, chapters, appendices = {}, 0, 0
    for page in order:
        if page.startswith("chapter-"):
            chapters += 1
            labels[page] = str(chapters)
        elif page.startswith("appendix-"):
            labels[page] = chr(ord("A") + appendices)
            appendices += 1
    return labels
