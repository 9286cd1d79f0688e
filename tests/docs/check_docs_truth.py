#!/usr/bin/env python3
"""Checks that README.md and docs/*.md say what the code does, in four mechanical ways:

(a) Header paths exist. Every `quat/...hpp` (with `include/` or `single_include/` before it or
    not; `{a,b}` lists expanded) named in README.md or docs/*.md, code blocks included, is a file
    under include/ (or single_include/ when written so); and every bare header name in the first
    and third column of README's table "API at a glance" (`vec3.hpp`, `paths/squad.hpp`,
    `paths/detail/segments.hpp`: relative to include/quat/) exists too. The first column must name
    the headers' current paths, not the forwarding headers of the old paths.
(b) The API table names what its headers declare. The table is the Markdown table under README's
    heading "## API at a glance": rows `| header(s) | contents | brings in |`, the first cell one
    or more code spans naming headers relative to include/quat/, optionally followed by "(opt-in)".
    In the contents cell, every code span is read: each identifier written as a call, `name(` or
    `name<...>(`, is a function that must appear as `name(` in the row's headers or in the headers
    they include from their own family (a family is a folder of include/quat/ with its detail/;
    the top-level headers and detail/ are the core), and a code span that is one bare identifier
    (`dot`, `quatf`, `matrix3<T>`) must appear as a word there. Code spans qualified by another
    library (`Eigen::`, `glm::`, `ceres::`, `std::`, `fmt::`) and operators are not quat's and are
    skipped; so is a span right after "scipy's ", which names scipy's API. docs/api.md has no API
    table of its own (it says so, and this script checks that it still has none).
(c) The opt-in list is the one tools/amalgamate.py computes (opt_in_headers, the headers generated
    beside single_include/quat/quat.hpp). README.md and docs/integration.md each mark their list
    with <!-- opt-in-list --> ... <!-- /opt-in-list -->; the header names between the markers
    (outside double quotes, prefixes `single_include/quat/`, `include/quat/`, `quat/` dropped,
    quat.hpp itself left out) must be that set exactly. In README's API table, the rows marked
    "(opt-in)" must be exactly the rows whose headers are in that set.
(d) README.md has at most 300 lines.

Usage: check_docs_truth.py <source dir>. Exits 1 and names each failure with its file and line.
"""
import pathlib
import re
import sys

MAX_README_LINES = 300
HEADER_PATH = re.compile(r"((?:single_)?include/)?quat/([\w./{},-]*\.hpp)")
CODE_SPAN = re.compile(r"`([^`]+)`")
BRACES = re.compile(r"\{([^{}]*)\}")
CALL = re.compile(r"(?<![\w./])([A-Za-z_]\w*)\s*(?:<[^<>()]*>)?\(")
BARE = re.compile(r"^([A-Za-z_]\w*)(?:<[^<>()]*>)?$")
FOREIGN = re.compile(r"\b(?:Eigen|glm|ceres|std|fmt)::")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def expand(text):
    """`interop/{glm,eigen}.hpp` -> [`interop/glm.hpp`, `interop/eigen.hpp`]."""
    m = BRACES.search(text)
    if not m:
        return [text]
    return [x for part in m.group(1).split(",")
            for x in expand(text[:m.start()] + part.strip() + text[m.end():])]


def family(rel):
    """The family of a header relative to include/quat: its folder, detail/ folded into it."""
    parts = rel.split("/")[:-1]
    if parts and parts[-1] == "detail":
        parts = parts[:-1]
    return "/".join(parts)


class Checker:
    def __init__(self, source):
        self.source = source
        self.quat = source / "include" / "quat"
        self.failures = []
        sys.path.insert(0, str(source / "tools"))
        import amalgamate  # noqa: E402 (the one source of the opt-in list)
        self.amalgamate = amalgamate
        _, held = amalgamate.generate()
        self.opt_in = set(amalgamate.opt_in_headers(held))

    def fail(self, path, line, message):
        self.failures.append(f"{path.relative_to(self.source).as_posix()}:{line}: {message}")

    # ---- the headers --------------------------------------------------------------------------
    def includes(self, rel):
        """The quat headers rel includes, relative to include/quat."""
        path = self.quat / rel
        found = []
        for spelling in INCLUDE.findall(path.read_text(encoding="utf-8")):
            for candidate in (path.parent / spelling, self.source / "include" / spelling):
                candidate = candidate.resolve()
                if candidate.is_file() and self.quat.resolve() in candidate.parents:
                    found.append(candidate.relative_to(self.quat.resolve()).as_posix())
                    break
        return found

    def family_closure(self, rels):
        """rels and the headers they include from their own family, transitively."""
        seen, stack = set(), list(rels)
        while stack:
            rel = stack.pop()
            if rel in seen:
                continue
            seen.add(rel)
            stack += [inc for inc in self.includes(rel)
                      if inc.endswith(".hpp") and family(inc) == family(rel)]
        return seen

    def is_forwarder(self, rel):
        """An old include path: nothing but one include of the header's new path."""
        path = self.quat / rel
        return (self.amalgamate.only_includes(path) and len(self.includes(rel)) == 1
                and "This header moved" in path.read_text(encoding="utf-8"))

    # ---- (a) ----------------------------------------------------------------------------------
    def check_paths(self, path):
        for n, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
            for m in HEADER_PATH.finditer(line):
                root = "single_include" if m.group(1) == "single_include/" else "include"
                for rel in expand(m.group(2)):
                    if not (self.source / root / "quat" / rel).is_file():
                        self.fail(path, n, f"{root}/quat/{rel} does not exist")

    # ---- the API table -------------------------------------------------------------------------
    def api_table(self, path):
        """(line, header cell, contents cell, brings-in cell) of each row of README's API table."""
        rows, inside = [], False
        for n, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
            if line.startswith("## "):
                inside = line.strip() == "## API at a glance"
                continue
            if inside and line.startswith("| `"):
                cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
                if len(cells) != 3:
                    self.fail(path, n, f"API table row with {len(cells)} cells, not 3")
                    continue
                rows.append((n, *cells))
        if not rows:
            self.fail(path, 1, "no API table under '## API at a glance'")
        return rows

    def check_api_table(self, path):
        for n, header_cell, contents, brings in self.api_table(path):
            headers = [h for span in CODE_SPAN.findall(header_cell) for h in expand(span)]
            # (a) the headers it names, and the headers in the third column, exist.
            for rel in headers + [h for span in CODE_SPAN.findall(brings) for h in expand(span)
                                  if h.endswith(".hpp") and not h.startswith("<")]:
                if not (self.quat / rel).is_file():
                    self.fail(path, n, f"include/quat/{rel} does not exist")
            headers = [h for h in headers if (self.quat / h).is_file()]
            for rel in headers:
                if self.is_forwarder(rel):
                    self.fail(path, n, f"{rel} is an old path forwarding elsewhere: name the new one")
            # (c) the opt-in mark.
            marked = "(opt-in)" in header_cell
            for rel in headers:
                if marked != (rel in self.opt_in):
                    self.fail(path, n, f"{rel} is {'' if rel in self.opt_in else 'not '}opt-in "
                                       f"(tools/amalgamate.py) but the row "
                                       f"{'is not' if not marked else 'is'} marked (opt-in)")
            # (b) the names in the contents.
            text = "\n".join((self.quat / h).read_text(encoding="utf-8")
                             for h in sorted(self.family_closure(headers)))
            for m in CODE_SPAN.finditer(contents):
                span = m.group(1)
                if FOREIGN.search(span) or contents[:m.start()].endswith("scipy's "):
                    continue
                for name in CALL.findall(span):
                    if name == "operator":
                        continue
                    if not re.search(r"\b" + re.escape(name) + r"\s*\(", text):
                        self.fail(path, n, f"{name}( is not declared in {', '.join(headers)} "
                                           f"or the headers it includes from its family")
                bare = BARE.match(span.strip())
                if bare and not re.search(r"\b" + re.escape(bare.group(1)) + r"\b", text):
                    self.fail(path, n, f"{bare.group(1)} is not found in {', '.join(headers)} "
                                       f"or the headers it includes from its family")

    # ---- (c) ----------------------------------------------------------------------------------
    def check_opt_in_list(self, path):
        text = path.read_text(encoding="utf-8")
        regions = re.findall(r"<!-- opt-in-list -->(.*?)<!-- /opt-in-list -->", text, re.S)
        if len(regions) != 1:
            self.fail(path, 1, f"{len(regions)} regions <!-- opt-in-list --> ... "
                               f"<!-- /opt-in-list -->, not 1")
            return
        line = text[:text.index("<!-- opt-in-list -->")].count("\n") + 1
        region = re.sub(r'"[^"\n]*"', "", regions[0])
        named = set()
        for token in re.findall(r"[\w./{},-]+\.hpp", region):
            for rel in expand(token):
                rel = re.sub(r"^(?:single_include/quat/|include/quat/|quat/)", "", rel)
                if rel != "quat.hpp":
                    named.add(rel)
        if named != self.opt_in:
            missing = sorted(self.opt_in - named)
            extra = sorted(named - self.opt_in)
            self.fail(path, line, "the opt-in list differs from tools/amalgamate.py's: "
                                  f"missing {missing}, not opt-in {extra}")

    # ---- (d) ----------------------------------------------------------------------------------
    def check_readme_length(self, path):
        lines = path.read_text(encoding="utf-8").count("\n")
        if lines > MAX_README_LINES:
            self.fail(path, lines, f"README.md has {lines} lines, more than {MAX_README_LINES}")

    def run(self):
        readme = self.source / "README.md"
        docs = sorted((self.source / "docs").glob("*.md"))
        for path in [readme] + docs:
            self.check_paths(path)
        self.check_api_table(readme)
        api = self.source / "docs" / "api.md"
        if re.search(r"^## API at a glance", api.read_text(encoding="utf-8"), re.M):
            self.fail(api, 1, "docs/api.md has an API table: teach this script its format")
        self.check_opt_in_list(readme)
        self.check_opt_in_list(self.source / "docs" / "integration.md")
        self.check_readme_length(readme)
        for failure in self.failures:
            print(failure, file=sys.stderr)
        print(f"docs truth: {len(self.failures)} failure(s); opt-in headers "
              f"(tools/amalgamate.py): {', '.join(sorted(self.opt_in))}")
        return 1 if self.failures else 0


if __name__ == "__main__":
    sys.exit(Checker(pathlib.Path(sys.argv[1]).resolve()).run())
