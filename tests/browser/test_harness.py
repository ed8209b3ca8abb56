"""The browser harness tests itself on a small fixture page, so a browser test that passes means something.

Usage: test_harness.py OUT_DIR. Checks that keys, a click and a range input reach the page; that an
uncaught exception and a console.error are reported (a page that throws fails); that with scripts
off the page shows only its static content; that a screenshot is a PNG; that a wait with nothing
coming times out; that a browser that never answers is started twice and then fails with its
stderr, and one that exits at once is named; and that no chromium process outlives close(), a
timeout or a failed start.
"""

import os
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

    # 6. A browser that never answers: two starts, then one error with its stderr, and nothing left running.
    silent = out / "silent-chromium"
    seconds = f"599.{os.getpid()}"  # this run's own: tests running beside it have theirs
    silent.write_text(f"#!/bin/sh\necho 'silent chromium: started, will not answer' >&2\nexec sleep {seconds}\n")
    silent.chmod(0o755)
    expect_error(lambda: Browser(out / "silent", chromium=str(silent), startup_timeout=1.0),
                 "did not start in 2 tries of 1 s: timeout waiting for Target.setDiscoverTargets's answer; "
                 "its stderr ends: silent chromium: started, will not answer | silent chromium")
    assert not sleeping_fakes(seconds), "the silent browser outlived its failed start"

    # 7. A browser that exits at once: the pipe closes, named as such.
    expect_error(lambda: Browser(out / "gone", chromium="/bin/false", startup_timeout=5.0, starts=1),
                 "chromium closed the pipe waiting for Target.setDiscoverTargets's answer")
    print("harness: keys, click, range, errors, scripts off, screenshot, timeout, failed starts and clean-up all work")


def sleeping_fakes(seconds):
    """Pids of the silent fake browser's `sleep SECONDS` still alive (zombies excluded)."""
    alive = []
    for entry in pathlib.Path("/proc").iterdir():
        try:
            if entry.name.isdigit() and (entry / "cmdline").read_bytes() == f"sleep\0{seconds}\0".encode():
                stat = (entry / "stat").read_text()
                if stat[stat.rindex(")") + 2] != "Z":
                    alive.append(int(entry.name))
        except OSError:
            continue
    return alive


if __name__ == "__main__":
    main(sys.argv[1])
