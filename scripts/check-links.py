#!/usr/bin/env python3
"""Fails when a relative link or image in the project's Markdown does not resolve.

Checks README.md and every Markdown file under docs/ (and bench/results/README.md): each
relative link, image and reference definition must name a file or folder that exists, and a
`#anchor` must name a heading of the target page (or of the page itself) by GitHub's rule:
the heading's text, lower case, punctuation dropped, spaces turned to '-', and "-1", "-2", ...
added to repeats. External links (http, https, mailto) are not fetched: the check runs offline
and must not fail because a site is down. Links inside code (fenced blocks, `spans`) are not
links and are skipped.

The pages are rewritten by hand often and their anchors come from headings that change, so a
broken link is easy to make and invisible until a reader clicks it: ctest's Docs.LinksResolve
runs this. Prints FILE:LINE: PROBLEM for each broken link and exits 1 if there is any.

Usage: scripts/check-links.py [ROOT]   (ROOT: the tree to check; default the repository)
"""
import pathlib
import re
import sys
import urllib.parse

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.S)
# [text](target "title") and ![alt](target); the text may hold one level of brackets and wrap.
INLINE = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\(\s*(<[^>\n]*>|[^()\s]+)"
                    r"(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
DEFINITION = re.compile(r"^ {0,3}\[[^\]\n]+\]:\s*(<[^>\n]*>|\S+)", re.M)
HTML_TARGET = re.compile(r"<(?:img|a)\b[^>]*?\b(?:src|href)\s*=\s*[\"']([^\"']+)[\"']", re.I)
HTML_ANCHOR = re.compile(r"<[^>]*\b(?:id|name)\s*=\s*[\"']([^\"']+)[\"']", re.I)
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)(?:[ \t]+#+)?[ \t]*$")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


def without_code(text: str, spans: bool = True) -> str:
    """The text with fenced code blocks, and code spans unless `spans` is False, blanked
    (lengths and lines kept)."""
    lines, fence = [], None
    for line in text.split("\n"):
        match = FENCE.match(line)
        if fence is None and match:
            fence = match.group(1)[0] * len(match.group(1))
            lines.append("")
        elif fence is not None:
            if line.strip().startswith(fence) and not line.strip().strip(fence[0]):
                fence = None
            lines.append("")
        else:
            lines.append(line)
    blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))
    return CODE_SPAN.sub(blank, "\n".join(lines)) if spans else "\n".join(lines)


def heading_text(raw: str) -> str:
    """A heading's text as GitHub renders it: code, links and emphasis reduced to their words."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", raw)  # links and images: their text
    text = re.sub(r"<[^>]+>", "", text)                     # HTML tags
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"(?<!\w)_+|_+(?!\w)", "", text)          # _emphasis_, not snake_case
    return text.strip()


def slug(text: str) -> str:
    """GitHub's anchor of a heading (github-slugger): lower case, anything but letters, digits,
    '_', '-' and spaces dropped, each space a '-'."""
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def anchors_of(path: pathlib.Path, cache: dict) -> set:
    if path not in cache:
        found, seen = set(), {}
        text = path.read_text(encoding="utf-8")
        for line in without_code(text, spans=False).split("\n"):
            match = HEADING.match(line)
            if match:
                base = slug(heading_text(match.group(2)))
                count = seen.get(base, 0)
                seen[base] = count + 1
                found.add(base if count == 0 else "%s-%d" % (base, count))
        # Explicit anchors: <a name="x"></a>, <span id="x">, in the raw text.
        found.update(HTML_ANCHOR.findall(text))
        cache[path] = found
    return cache[path]


def targets(text: str):
    """(line, target, is_image) for every link in the Markdown `text`."""
    plain = without_code(text)
    line_of = lambda offset: plain.count("\n", 0, offset) + 1
    for match in INLINE.finditer(plain):
        yield line_of(match.start()), match.group(3).strip("<>"), bool(match.group(1))
    for match in DEFINITION.finditer(plain):
        yield line_of(match.start()), match.group(1).strip("<>"), False
    for match in HTML_TARGET.finditer(plain):
        yield line_of(match.start()), match.group(1), match.group(0)[1:4].lower() == "img"


def check(root: pathlib.Path, page: pathlib.Path, cache: dict) -> list:
    problems = []
    shown = page.relative_to(root)
    for line, target, image in targets(page.read_text(encoding="utf-8")):
        if SCHEME.match(target) or target.startswith("//"):
            continue  # external: not fetched
        path_part, _, anchor = target.partition("#")
        path_part = urllib.parse.unquote(path_part)
        destination = (page.parent / path_part).resolve() if path_part else page
        what = "image" if image else "link"
        if not destination.exists():
            problems.append("%s:%d: %s %s: no file %s" % (shown, line, what, target, path_part))
            continue
        if anchor and destination.suffix.lower() == ".md" and destination.is_file():
            if urllib.parse.unquote(anchor) not in anchors_of(destination, cache):
                where = "this page" if destination == page else path_part
                problems.append("%s:%d: %s %s: no heading with anchor #%s in %s"
                                % (shown, line, what, target, anchor, where))
    return problems


def main() -> int:
    root = (pathlib.Path(sys.argv[1]) if len(sys.argv) > 1
            else pathlib.Path(__file__).resolve().parent.parent).resolve()
    pages = [root / "README.md"] if (root / "README.md").exists() else []
    pages += sorted((root / "docs").rglob("*.md")) if (root / "docs").is_dir() else []
    pages += [p for p in [root / "bench" / "results" / "README.md"] if p.exists()]
    cache, problems = {}, []
    for page in pages:
        problems += check(root, page, cache)
    for problem in problems:
        print(problem)
    if problems:
        print("%d broken link%s in %d page%s" % (len(problems), "" if len(problems) == 1 else "s",
                                                 len(pages), "" if len(pages) == 1 else "s"))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
