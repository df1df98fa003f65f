#!/usr/bin/env python3
"""The front panel in a real browser (Debian's chromium, headless, driven by playwright).

Starts `testrig panel`, opens the page, moves the speed to 1300 rev/min and the load to
2.712 N m with the page's own controls, sees the tacho DVM follow, starts an average and
reads the half-order line with the marker; then the panel of a rig file's scenario (the
two-stage reduction): its name shown, the load box unbounded (its motor has no torque
limit), the speed moved with the page's controls and followed by the DVM, the impacts
counted; then the planetary bench's scenario: the analyser on its ring sensor, its
strongest line the planet-pass frequency; keeps screenshots. Run by .ci/run:

    python3 tests/browser/panel_browser.py --binary target/release/testrig --shots target/panel-screenshots
"""

import argparse
import re
import subprocess
import sys
import shutil
import tempfile
import time
from pathlib import Path

from playwright.sync_api import sync_playwright

CHROMIUM = "/usr/bin/chromium"


def start_panel(binary, out, extra):
    panel = subprocess.Popen(
        [binary, "panel", "--listen", "127.0.0.1:0", "--pace", "10", "--out", out] + extra,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = panel.stdout.readline()
    match = re.search(r"http://[0-9.:]+/", line)
    if not match:
        panel.kill()
        sys.exit(f"the panel did not start: {line!r} {panel.stderr.read()}")
    return panel, match.group(0)


def dvm_rpm(page):
    """The tacho DVM's reading on `page` (rev/min; 0 before the first)."""
    return float(re.sub(r"[^0-9.]", "", page.inner_text("#dvm-rpm")) or 0)


def wait_until(what, test, limit_s=120):
    start = time.time()
    while not test():
        if time.time() - start > limit_s:
            sys.exit(f"FAILED: {what} within {limit_s} s")
        time.sleep(0.1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="target/release/testrig")
    parser.add_argument("--shots", default="target/panel-screenshots")
    args = parser.parse_args()
    shots = Path(args.shots)
    shots.mkdir(parents=True, exist_ok=True)
    out = on_panel(args.binary, ["--set", "analyser.averages=4"],
                   lambda browser, page, url: thesis_rig(browser, page, url, shots))
    if not (Path(out) / "session.toml").exists():
        sys.exit(f"FAILED: no session.toml in {out}")
    shutil.rmtree(out, ignore_errors=True)
    scenario = Path(__file__).resolve().parents[2] / "scenarios" / "two-stage-run.toml"
    out = on_panel(args.binary, [str(scenario)],
                   lambda browser, page, url: two_stage_rig(page, shots))
    shutil.rmtree(out, ignore_errors=True)
    scenario = Path(__file__).resolve().parents[2] / "scenarios" / "planetary-run.toml"
    out = on_panel(args.binary, [str(scenario)],
                   lambda browser, page, url: planetary_rig(page, shots))
    shutil.rmtree(out, ignore_errors=True)
    print(f"browser test passed; screenshots in {shots}")


def on_panel(binary, extra, check):
    """Starts `testrig panel` with `extra` arguments, runs `check(browser, page, url)` on
    its page in chromium, quits from the page and sees the panel exit cleanly; returns
    its folder. A failure keeps the folder, and says where."""
    out = tempfile.mkdtemp(prefix="testrig-browser-")
    panel, url = start_panel(binary, out, extra)
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True,
                                        args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            page.goto(url)
            check(browser, page, url)
            page.click("#quit")
            browser.close()
        code = panel.wait(timeout=60)
        if code != 0:
            sys.exit(f"FAILED: the panel exited with {code}: {panel.stderr.read()}")
        return out
    except SystemExit:
        print(f"the panel's files are kept in {out}", file=sys.stderr)
        raise
    finally:
        if panel.poll() is None:
            panel.kill()


def thesis_rig(browser, page, url, shots):
    """The bundled scenario: the 1983 rig moved to its half-order point."""
    rpm = lambda: dvm_rpm(page)
    wait_until("a first DVM reading", lambda: rpm() > 0)
    before = rpm()
    page.screenshot(path=str(shots / "1-opening.png"))
    # The chain's signals are volts, and the analyser's and scope's scales say so.
    wait_until("the scope's and analyser's scales",
               lambda: page.evaluate("() => state.trace !== null && state.spectrum !== null"))
    labels = [page.inner_text(f"#{k}-label") for k in ("range", "vdiv", "trigger")]
    if labels != ["ADC ± V", "V/div", "trigger V"]:
        sys.exit(f"FAILED: the chain's scales read {labels}, not volts")
    # An empty speed box refuses the command in the page; the rig keeps its speed.
    set_before = page.evaluate("() => state.speed_set_rpm")
    page.fill("#speed", "")
    page.click("#set-speed")
    said = page.inner_text("#error")
    if "give a number" not in said:
        sys.exit(f"FAILED: an empty speed box was not refused: {said!r}")
    time.sleep(0.5)
    if page.evaluate("() => state.speed_set_rpm") != set_before:
        sys.exit("FAILED: an empty speed box changed the set speed")
    limit = page.get_attribute("#speed", "max")
    if float(limit) != page.evaluate("() => info.max_speed_rpm"):
        sys.exit(f"FAILED: the speed box's limit {limit} is not the rig's")
    # The controls echo what the rig applies: a refused gain returns to the applied one.
    page.fill("#gain", "1e300")
    page.click("#set-gain")
    wait_until("the refused gain replaced by the applied one",
               lambda: float(page.input_value("#gain"))
               == page.evaluate("() => state.chain.amplifier_gain"))
    page.fill("#speed", "1300")
    page.click("#set-speed")
    page.fill("#load", "2.712")
    page.click("#set-load")
    wait_until("the tacho DVM at 1300 rev/min", lambda: abs(rpm() - 1300) <= 13)
    print(f"DVM: {before:.0f} -> {rpm():.0f} rev/min")
    # The rig settles into its period-2 motion within some 20 s of its start.
    wait_until("20 s simulated", lambda: page.evaluate("() => state.simulated_s") > 20)
    page.click("#start-average")
    # The page's own state: first the new average under way (the panel's own first
    # average, already at 1300 rev/min, must not be taken for it), then complete.
    started = "() => state.spectrum && !state.spectrum.complete"
    wait_until("the new average under way", lambda: page.evaluate(started))
    done = "() => state.spectrum && state.spectrum.complete && state.spectrum.averages === 4" \
           " && state.spectrum.running_hz > 21"
    wait_until("an average of 4 at 1300 rev/min", lambda: page.evaluate(done))
    page.click("#marker-half")
    readout = page.inner_text("#marker-readout")
    print(f"marker: {readout}")
    page.screenshot(path=str(shots / "2-half-order.png"))
    order = float(re.search(r"order ([0-9.]+)", readout).group(1))
    level = float(re.search(r"(-?[0-9.]+) dB", readout).group(1))
    if not (abs(order - 0.5) <= 0.02 and "not an alias" in readout and level > -20):
        sys.exit(f"FAILED: the marker does not read a half-order line: {readout}")
    # A second page sees the same rig.
    other = browser.new_page()
    other.goto(url)
    wait_until("the second page's DVM", lambda: abs(dvm_rpm(other) - 1300) <= 13)
    other.close()


def two_stage_rig(page, shots):
    """`scenarios/two-stage-run.toml`, a rig file's rig: its name shown, the load box
    unbounded (its motor has no torque limit), impacts counted, the speed followed."""
    wait_until("the scenario's name", lambda: page.inner_text("#scenario") == "two-stage-run")
    if page.get_attribute("#load", "max") not in (None, ""):
        sys.exit("FAILED: a load limit on a motor without one")
    rpm = lambda: dvm_rpm(page)
    wait_until("the tacho DVM at 1500 rev/min", lambda: abs(rpm() - 1500) <= 15)
    wait_until("impacts under the reversing load",
               lambda: page.evaluate("() => state.impacts") > 100)
    page.fill("#speed", "1000")
    page.click("#set-speed")
    wait_until("the tacho DVM at 1000 rev/min", lambda: abs(rpm() - 1000) <= 10)
    print(f"two-stage rig: DVM {rpm():.0f} rev/min, {page.evaluate('() => state.impacts')} impacts")
    page.screenshot(path=str(shots / "3-two-stage.png"))


def planetary_rig(page, shots):
    """`scenarios/planetary-run.toml`: the analyser reads the ring sensor (`ring_n`, the
    AC-coupled, low-passed `sensor_epi_n`); once the schedule has brought the motor to
    1000 rev/min (from 8 s), three planets pass it at 3 × 200/60 = 10 Hz, its strongest
    line."""
    wait_until("the scenario's name", lambda: page.inner_text("#scenario") == "planetary-run")
    # `state` is null until the panel's first message: the scenario's name may come first.
    wait_until("9 s simulated",
               lambda: page.evaluate("() => state !== null && state.simulated_s > 9"))
    wait_until("the tacho DVM at 1000 rev/min", lambda: abs(dvm_rpm(page) - 1000) <= 10)
    # Eight averages of 1024-point blocks at 2 kHz (2 × Fmax) take 4.1 s simulated:
    # complete and 4.3 s on from the click, the average is the one the click started (at
    # pace 10 it may run its course between two looks).
    clicked_s = page.evaluate("() => state.simulated_s")
    page.click("#start-average")
    done = "() => state.spectrum && state.spectrum.complete && state.spectrum.averages === 8" \
           f" && state.simulated_s > {clicked_s + 4.3}"
    wait_until("an average of 8 after the click", lambda: page.evaluate(done))
    spectrum = page.evaluate("() => state.spectrum")
    if spectrum["signal"] != "ring_n":
        sys.exit(f"FAILED: the analyser reads {spectrum['signal']!r}, not the ring sensor")
    power = spectrum["power_v2"]
    top = max(range(len(power)), key=lambda i: power[i])
    hz = spectrum["frequency_hz"][top]
    bin_hz = spectrum["frequency_hz"][1] - spectrum["frequency_hz"][0]
    print(f"planetary bench: the ring sensor's strongest line at {hz:.2f} Hz")
    if abs(hz - 10.0) > bin_hz:
        sys.exit(f"FAILED: the ring sensor's strongest line at {hz} Hz, not the planet pass")
    # The sensor reads newtons, straight into the analyser and the scope: their scales
    # say so, not volts.
    wait_until("the scope's trace", lambda: page.evaluate("() => state.trace !== null"))
    labels = [page.inner_text(f"#{k}-label") for k in ("range", "vdiv", "trigger")]
    if spectrum["unit"] != "N" or labels != ["ADC ± N", "N/div", "trigger N"]:
        sys.exit(f"FAILED: the ring sensor's scales in {spectrum['unit']!r}, {labels}, not N")
    page.screenshot(path=str(shots / "4-planetary.png"))


if __name__ == "__main__":
    main()
