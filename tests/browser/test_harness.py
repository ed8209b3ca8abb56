"""The browser harness tests itself on a small fixture page, so a browser test that passes means something.

Usage: test_harness.py OUT_DIR. Checks that keys, a click and a range input reach the page; that an
uncaught exception and a console.error are reported (a page that throws fails); that with scripts
off the page shows only its static content; that a screenshot is a PNG; that a wait with nothing
coming times out; and that no chromium process outlives close() or a timeout.
"""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from browser import Browser, BrowserError  # noqa: E402

FIXTURE = pathlib.Path(__file__).resolve().parent / "fixtures" / "harness.html"


def expect_error(action, words):
    """Runs `action`, which must raise a BrowserError whose text holds `words`."""
    try:
        action()
    except BrowserError as error:
        assert words in str(error), f"expected '{words}' in: {error}"
        return
    raise AssertionError(f"no error raised (expected '{words}')")


def main(out_dir):
    out = pathlib.Path(out_dir)
    with Browser(out) as browser:
        # 1. Keys, a click and a range input reach the page.
        page = browser.open(FIXTURE)
        assert page.text("#count") == "0"
        page.press("ArrowRight")
        page.press("ArrowRight")
        page.press("ArrowLeft")
        assert page.text("#count") == "1", page.text("#count")
        page.click("#more")
        assert page.text("#count") == "11", page.text("#count")
        page.set_range("#slider", 7)
        assert page.text("#shown") == "7"
        assert page.exists("#scripted")
        page.check_no_errors()
        shot = page.screenshot("harness.png")
        assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 1000

        # 2. An uncaught exception and a console error are reported.
        page.click("#throw")
        expect_error(page.check_no_errors, "thrown on purpose")
        page.errors.clear()
        page.click("#complain")
        expect_error(page.check_no_errors, "complained on purpose")
        expect_error(lambda: page.eval("undefinedName + 1"), "undefinedName")

        # 3. Scripts off: the static text, nothing the script adds, no key handling.
        quiet = browser.open(FIXTURE, scripts=False)
        assert quiet.exists("#static") and not quiet.exists("#scripted")
        quiet.press("ArrowRight")
        assert quiet.text("#count") == "0"
        quiet.check_no_errors()

        # 4. A wait for something that never comes times out, and the browser is gone after it.
        browser.timeout = 1.0
        expect_error(lambda: browser.wait_event("Page.neverSent"), "timeout waiting for Page.neverSent")
        assert browser.processes_left() == [], browser.processes_left()
        profile = browser.profile

    # 5. After close: no process left, the profile removed.
    assert not pathlib.Path(profile).exists()
    with Browser(out) as browser:
        browser.open(FIXTURE).check_no_errors()
        group = browser.process.pid
        browser_ref = browser
    assert browser_ref.process is None
    assert not any(pathlib.Path(f"/proc/{pid}").exists() for pid in [group]), "the browser outlived close()"
    print("harness: keys, click, range, errors, scripts off, screenshot, timeout and clean-up all work")


if __name__ == "__main__":
    main(sys.argv[1])
