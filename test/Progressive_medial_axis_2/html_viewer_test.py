#!/usr/bin/env python3
"""The progressive viewer (--html) in a real browser.

    html_viewer_test.py TOOL SHAPE WORKDIR

Writes the viewer page of SHAPE with 10 frames, loads it in Debian's
chromium in headless mode at the first and at the last frame (#frame=K in
the address sets the slider), takes a screenshot of each, and checks that
both pictures show a drawing (not blank) and that they differ.  Exits with
77 (CTest: skipped) when chromium or python3-pil is absent.
"""

import os
import shutil
import subprocess
import sys


def skip(why):
    print("skipped: " + why)
    sys.exit(77)


def main():
    tool, shape, work = sys.argv[1:4]
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        skip("chromium not found (apt-get install chromium)")
    try:
        from PIL import Image, ImageChops
    except ImportError:
        skip("python3-pil not found (apt-get install python3-pil)")
    os.makedirs(work, exist_ok=True)
    page = os.path.join(work, "viewer.html")
    subprocess.run([tool, "--html", page, "--frames", "10", shape], check=True)
    with open(page) as f:
        text = f.read()
    # self-contained: nothing is loaded from the network
    for needle in ("http://", "https://"):
        for line in text.splitlines():
            if needle in line and "xmlns" not in line:
                sys.exit("the page refers to the network: " + line.strip()[:200])
    shots = []
    for frame in (0, 9):
        png = os.path.join(work, "frame%d.png" % frame)
        if os.path.exists(png):
            os.remove(png)
        subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                        "--window-size=900,700", "--virtual-time-budget=5000", "--screenshot=" + png,
                        "file://" + os.path.abspath(page) + "#frame=%d" % frame],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
        full = Image.open(png).convert("RGB")
        image = full.crop((0, 50, full.width, full.height))   # the picture, below the bar
        # a drawing: enough pixels that are neither the background nor white,
        # in several colours (the shape's fill, its outline, the axis)
        colours = image.getcolors(maxcolors=1 << 20) or []
        drawn = sum(n for n, c in colours if c not in ((250, 250, 250), (255, 255, 255)))
        print("frame %d: %d colours, %d drawn pixels of %d" % (frame, len(colours), drawn, image.width * image.height))
        if len(colours) < 4 or drawn < 0.005 * image.width * image.height:
            sys.exit("frame %d: the screenshot is blank" % frame)
        shots.append(image)
    diff = ImageChops.difference(shots[0], shots[1])
    changed = sum(1 for p in diff.getdata() if p != (0, 0, 0))
    print("pixels that differ between the first and the last frame: %d" % changed)
    if changed < 0.001 * diff.width * diff.height:
        sys.exit("the first and the last frame look the same")
    print("ok")


if __name__ == "__main__":
    main()
