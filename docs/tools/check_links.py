# SPDX-License-Identifier: GPL-3.0-or-later
"""Every link of the built site leads somewhere: each relative href and src names a file of the
site, and each #fragment an id or name on that page; no page shows Doxygen commands left from
markdown it could not parse. Links out of the site (http, mailto) are
counted, not followed (CI has no network). Usage: python3 check_links.py SITE_FOLDER"""
import html.parser
import pathlib
import sys
import urllib.parse


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.anchors = [], set()

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for key in ("id", "name"):
            if attrs.get(key):
                self.anchors.add(attrs[key])
        for key in ("href", "src"):
            if attrs.get(key) is not None:
                self.links.append((tag, attrs[key]))


def main(site):
    site = pathlib.Path(site).resolve()
    pages = {}
    for path in site.rglob("*.html"):
        page = Page()
        page.feed(path.read_text(encoding="utf-8", errors="replace"))
        pages[path] = page
    broken, outside = [], 0
    for path in pages:
        # Markdown Doxygen could not parse is left on the page as its own commands.
        text = path.read_text(encoding="utf-8", errors="replace")
        for command in ("@ref ", "@subsection ", "@section ", "@code{", "@image "):
            if command in text:
                broken.append(f"{path.relative_to(site)}: '{command.strip()}' left unrendered")
    for path, page in pages.items():
        for tag, link in page.links:
            parts = urllib.parse.urlsplit(link)
            if parts.scheme or link.startswith("//"):
                outside += 1
                continue
            target = (path.parent / urllib.parse.unquote(parts.path)).resolve() if parts.path else path
            if not target.exists() or site not in (target, *target.parents):
                broken.append(f"{path.relative_to(site)}: <{tag}> {link} (no such file)")
                continue
            if parts.fragment and target.suffix == ".html":
                anchors = pages[target].anchors if target in pages else set()
                if parts.fragment not in anchors:
                    broken.append(f"{path.relative_to(site)}: {link} (no anchor '{parts.fragment}')")
    for line in broken:
        print("broken link: " + line, file=sys.stderr)
    print(f"{len(pages)} pages, {sum(len(p.links) for p in pages.values())} links: "
          f"{len(broken)} broken, {outside} out of the site (not followed)")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
