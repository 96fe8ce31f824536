#!/usr/bin/python3
"""Every internal link, anchor and image of a built HTML site resolves: read each page as the
browser would (html.parser), and for every relative href/src of <a>, <img>, <link> and <script>
check that the file exists and, for a link with a #fragment into an HTML page, that the page has
an element with that id. External links (a scheme such as https: or mailto:) are not followed:
the check runs offline.

Usage: python3 -m tools.docs.check_site SITE_DIR   (exit 0 clean, 1 with one line per fault)
"""
import argparse
import os
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit

# Which attribute of which element names another file.
REF_ATTRS = {"a": "href", "img": "src", "link": "href", "script": "src"}


class Page(HTMLParser):
    """The ids a page defines and the references it makes, each as (tag, value, line)."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids, self.refs = set(), []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name") if tag == "a" else ("id",):
            if a.get(key):
                self.ids.add(a[key])
        attr = REF_ATTRS.get(tag)
        if attr and a.get(attr) is not None:
            self.refs.append((tag, a[attr], self.getpos()[0]))

    handle_startendtag = handle_starttag


def read(path):
    p = Page()
    with open(path, encoding="utf-8") as f:
        p.feed(f.read())
    return p


def internal(ref):
    """The (path, fragment) of a reference to this site, None for an external one."""
    u = urlsplit(ref)
    if u.scheme or u.netloc or ref.startswith("data:"):
        return None
    return unquote(u.path), unquote(u.fragment)


def check_page(site, rel, pages):
    """Faults of one page: (rel, line, message). pages caches parsed pages by absolute path."""
    path = os.path.join(site, rel)
    faults = []
    for tag, ref, line in pages[path].refs:
        target = internal(ref)
        if target is None:
            continue
        file, frag = target
        dest = os.path.normpath(os.path.join(os.path.dirname(path), file)) if file else path
        if file.endswith("/") or os.path.isdir(dest):
            dest = os.path.join(dest, "index.html")
        if not os.path.isfile(dest):
            faults.append((rel, line, f"<{tag}> {ref}: no file {os.path.relpath(dest, site)}"))
            continue
        if frag and tag == "a" and dest.endswith(".html"):
            if dest not in pages:
                pages[dest] = read(dest)
            if frag not in pages[dest].ids:
                faults.append((rel, line, f"<a> {ref}: {os.path.relpath(dest, site)} has no id '{frag}'"))
    return faults


def check_site(site):
    pages, faults = {}, []
    rels = sorted(os.path.relpath(os.path.join(d, f), site)
                  for d, _, fs in os.walk(site) for f in fs if f.endswith(".html"))
    if not rels:
        return [(site, 0, "no HTML page")]
    for rel in rels:
        path = os.path.join(site, rel)
        if path not in pages:
            pages[path] = read(path)
        faults += check_page(site, rel, pages)
    return faults


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("site")
    a = ap.parse_args(argv)
    if not os.path.isdir(a.site):
        print(f"check_site: site: no directory {a.site}", file=sys.stderr)
        return 2
    faults = check_site(a.site)
    for rel, line, msg in faults:
        print(f"{rel}:{line}: {msg}")
    print(f"check_site: {len(faults)} broken link(s) or missing image(s) in {a.site}"
          if faults else f"check_site: every internal link, anchor and image of {a.site} resolves")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
