#!/usr/bin/python3
"""Open HTML pages in headless Chromium as a reader would and fail on what the reader would meet:
a console error or an uncaught exception, a resource that failed to load, an image that did not
render (naturalWidth 0), or a link into the site whose file or #anchor does not exist. Keeps a
screenshot of each page.

For each PAGE: a fresh headless Chromium (tools/docs/cdp.py) loads it from the disk, the DevTools
protocol reports console messages (Runtime, Log) and failed loads (Network), and the page itself
is asked for its links (as the browser resolved them), its images (complete, naturalWidth) and
its ids. A link to a file: URL must name an existing file, and its #fragment an element of that
page. Links to other schemes (https:, mailto:) are not followed: the check runs offline.

  --screenshot FILE  a PNG of the viewport (1280x900) once the page has loaded
  --show SELECTOR    scroll the first element matching the CSS selector to the top first (e.g.
                     `table`: the screenshot then shows the page's first table)
  --site DIR         then every other HTML page under DIR too, in the same browser

Usage: python3 -m tools.docs.check_browser PAGE [--screenshot FILE] [--show SELECTOR] [--site DIR]
Exit 0 clean, 1 faults (one line each), 2 bad input or no Chromium.
"""
import argparse
import json
import os
import sys
from urllib.parse import unquote, urlsplit

from tools.docs.cdp import BrowserError, Chromium, find_chromium
from tools.docs.check_site import read

# What the page itself reports once loaded: links as resolved, images as rendered, ids.
INSPECT = """(() => ({
  links: Array.from(document.querySelectorAll('a[href]'), a => a.href),
  images: Array.from(document.images, i => ({src: (i.currentSrc || i.src).slice(0, 120),
                                            ok: i.complete && i.naturalWidth > 0})),
  ids: Array.from(document.querySelectorAll('[id], a[name]'), e => e.id || e.name),
  title: document.title
}))()"""
SCROLL = "(() => { const e = document.querySelector(%s); if (!e) return false; e.scrollIntoView(); window.scrollBy(0, -48); return true; })()"


def console_faults(events):
    """Console errors, uncaught exceptions and failed loads among the DevTools events."""
    urls, faults = {}, []
    for e in events:
        m, p = e["method"], e.get("params", {})
        if m == "Network.requestWillBeSent":
            urls[p["requestId"]] = p["request"]["url"]
        elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", []))
            faults.append(f"console {p['type']}: {text}")
        elif m == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            faults.append(f"uncaught exception: {d.get('exception', {}).get('description') or d.get('text')}")
        elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            entry = p["entry"]
            faults.append(f"console error ({entry.get('source')}): {entry.get('text')} {entry.get('url', '')}".rstrip())
        elif m == "Network.loadingFailed" and not p.get("canceled"):
            faults.append(f"failed to load {urls.get(p['requestId'], p['requestId'])[:120]}: {p.get('errorText')}")
    return faults


def link_faults(page_path, links, page_ids):
    """Links to files that do not exist, or to ids their page lacks."""
    faults, cache = [], {}
    here = os.path.realpath(page_path)
    for href in links:
        u = urlsplit(href)
        if u.scheme != "file":
            continue
        path, frag = os.path.realpath(unquote(u.path)), unquote(u.fragment)
        if os.path.isdir(path):
            path = os.path.join(path, "index.html")
        if not os.path.isfile(path):
            faults.append(f"broken link {href}: no such file")
        elif frag and path.endswith(".html"):
            if path == here:
                ids = page_ids
            else:
                if path not in cache:
                    cache[path] = read(path).ids
                ids = cache[path]
            if frag not in ids:
                faults.append(f"broken link {href}: no element with id '{frag}'")
    return faults


def inspect(b, page, screenshot=None, show=None):
    """(faults, facts) of one page in the open browser b; facts: title, links, images."""
    b.events.clear()
    b.open("file://" + os.path.realpath(page))
    seen = b.evaluate(INSPECT)
    if show is not None and not b.evaluate(SCROLL % json.dumps(show)):
        raise BrowserError(f"--show: no element matches {show!r} on {page}")
    if screenshot:
        b.settle(0.3)
        b.screenshot(screenshot)
    faults = console_faults(b.events)
    faults += [f"image not rendered: {i['src']}" for i in seen["images"] if not i["ok"]]
    faults += link_faults(page, seen["links"], set(seen["ids"]))
    return faults, {"title": seen["title"], "links": len(seen["links"]), "images": len(seen["images"]),
                    "screenshot": screenshot}


def check(page, chromium, screenshot=None, show=None):
    """(faults, facts) of one page in a fresh browser."""
    with Chromium(chromium) as b:
        return inspect(b, page, screenshot, show)


def site_pages(site, first):
    """Every HTML page under site except first, in order."""
    pages = sorted(os.path.join(d, f) for d, _, fs in os.walk(site) for f in fs if f.endswith(".html"))
    return [p for p in pages if os.path.realpath(p) != os.path.realpath(first)]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("page")
    ap.add_argument("--screenshot")
    ap.add_argument("--show")
    ap.add_argument("--site", help="also check every other HTML page under this directory")
    ap.add_argument("--chromium", default=None, help="the browser (default: chromium on PATH)")
    a = ap.parse_args(argv)
    chromium = a.chromium or find_chromium()
    if not os.path.isfile(a.page):
        print(f"check_browser: page: no file {a.page}", file=sys.stderr)
        return 2
    if not chromium:
        print("check_browser: no Chromium on PATH (Debian: apt-get install chromium; tools/ensure_deps.sh)",
              file=sys.stderr)
        return 2
    if a.site and not os.path.isdir(a.site):
        print(f"check_browser: site: no directory {a.site}", file=sys.stderr)
        return 2
    if a.screenshot:
        os.makedirs(os.path.dirname(os.path.abspath(a.screenshot)), exist_ok=True)
    bad = 0
    try:
        with Chromium(chromium) as b:
            for i, page in enumerate([a.page] + (site_pages(a.site, a.page) if a.site else [])):
                faults, facts = inspect(b, page, *((a.screenshot, a.show) if i == 0 else (None, None)))
                for f in faults:
                    print(f"{page}: {f}")
                shot = f"; screenshot {facts['screenshot']}" if facts["screenshot"] else ""
                print(f"check_browser: {page} ('{facts['title']}'): {facts['links']} links, "
                      f"{facts['images']} images, {len(faults)} fault(s){shot}")
                bad += bool(faults)
    except BrowserError as e:
        print(f"check_browser: {a.page}: {e}", file=sys.stderr)
        return 2
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
