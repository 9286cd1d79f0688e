#!/usr/bin/env python3
"""Checks every relative link of README.md and docs/*.md: the file or directory it names exists,
and a #fragment names a heading of the Markdown file it points to (GitHub's anchors).

Usage: check_links.py <source dir>
Links inside code blocks and code spans are not links. Absolute URLs (http:, https:, mailto:) are
not fetched. Exits 1 and names each broken link with its file and line.
"""
import pathlib
import re
import sys

FENCE = re.compile(r"^\s*(```+|~~~+)")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s*\[[^\]]+\]:\s*(\S+)")
HTML = re.compile(r"<(?:a|img)\s[^>]*?(?:href|src)=\"([^\"]+)\"")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def prose_lines(path, blank_code_spans=True):
    """(line number, text) of each line outside code blocks, code spans blanked unless asked not to."""
    fence = None
    for n, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
        m = FENCE.match(line)
        if fence is None and m:
            fence = m.group(1)[0] * 3
            continue
        if fence is not None:
            if line.strip().startswith(fence):
                fence = None
            continue
        yield n, re.sub(r"`+[^`]*`+", "``", line) if blank_code_spans else line


def anchors(path):
    """GitHub's anchors of a Markdown file's headings: lower case, punctuation dropped, spaces to -."""
    seen, result = {}, set()
    for _, line in prose_lines(path, blank_code_spans=False):
        m = HEADING.match(line)
        if not m:
            continue
        text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", m.group(2))
        slug = re.sub(r"[^\w\- ]", "", text.lower().replace("`", "")).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        result.add(slug if count == 0 else f"{slug}-{count}")
    return result



def main():
    source = pathlib.Path(sys.argv[1]).resolve()
    files = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    broken, checked = [], 0
    for path in files:
        rel = path.relative_to(source).as_posix()
        for n, line in prose_lines(path):
            targets = LINK.findall(line) + REFERENCE.findall(line) + HTML.findall(line)
            for target in targets:
                if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                    continue
                checked += 1
                name, _, fragment = target.partition("#")
                resolved = (path.parent / name).resolve() if name else path
                if not resolved.exists():
                    broken.append(f"{rel}:{n}: {target}: no such file or directory")
                    continue
                if fragment and resolved.suffix == ".md" and fragment not in anchors(resolved):
                    broken.append(f"{rel}:{n}: {target}: no heading with that anchor in "
                                  f"{resolved.relative_to(source).as_posix()}")
    for b in broken:
        print(b)
    print(f"{checked} relative links in {len(files)} files, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
