#!/usr/bin/env python3
"""Drive a rehearsal on a running `testrig panel` from a script (docs/api.md).

Sets the speed and the brake load, waits until the tacho DVM has settled on the new
speed, starts an average, waits for it on the state stream (WebSocket), fetches the
spectrum into numpy and reports the half-order line: its frequency, its height above the
lines around it, and whether the ground truth calls it an alias.

    testrig panel &                      # serves http://127.0.0.1:8080/
    python3 examples/panel_client.py --speed 1300 --load 2.712

Needs requests, websocket-client and numpy (pip install requests websocket-client numpy).
"""

import argparse
import json
import sys
import time

import numpy as np
import requests
import websocket


class Panel:
    """The panel's API at `url`."""

    def __init__(self, url):
        self.url = url.rstrip("/")

    def command(self, cmd, **fields):
        reply = requests.post(f"{self.url}/api/command", json={"cmd": cmd, **fields}, timeout=30).json()
        if not reply["ok"]:
            raise RuntimeError(f"{cmd}: {reply['error']}")
        return reply

    def state(self):
        return requests.get(f"{self.url}/api/state", timeout=30).json()

    def stream(self):
        """Yields the state as the panel streams it (ten times a second)."""
        ws = websocket.create_connection(self.url.replace("http", "ws", 1) + "/api/stream", timeout=30)
        try:
            while True:
                yield json.loads(ws.recv())
        finally:
            ws.close()


def wait_for_speed(panel, rpm, tolerance=0.01, hold_s=2.0, limit_s=600):
    """Waits until the DVM (1 s gate) has read within `tolerance` of `rpm` for `hold_s`
    of virtual time."""
    start, since = time.time(), None
    for state in panel.stream():
        reading = state["dvm_rpm"]
        if abs(reading - rpm) <= tolerance * rpm:
            since = state["simulated_s"] if since is None else since
            if state["simulated_s"] - since >= hold_s:
                return state
        else:
            since = None
        if time.time() - start > limit_s:
            raise TimeoutError(f"the DVM reads {reading:.0f} rev/min, not {rpm}")


def average(panel, averages, limit_s=600):
    """Starts an average of `averages` spectra and returns the display when complete."""
    panel.command("set_analyser", averages=averages)
    panel.command("start_average")
    start = time.time()
    for state in panel.stream():
        s = state["spectrum"]
        if s and s["complete"] and s["averages"] == averages:
            return s
        if time.time() - start > limit_s:
            raise TimeoutError("the average did not complete")


def half_order(spectrum, around=8):
    """The strongest line within one line of half the running speed, and its height (dB)
    above the median of the `around` lines either side of it."""
    f = np.asarray(spectrum["frequency_hz"])
    p = np.asarray(spectrum["power_v2"])
    target = 0.5 * spectrum["running_hz"]
    near = np.flatnonzero(np.abs(f - target) <= 1.5 * (f[1] - f[0]))
    k = near[np.argmax(p[near])]
    lo, hi = max(0, k - around), min(len(p), k + around + 1)
    floor = np.median(np.delete(p[lo:hi], np.arange(max(0, k - 1 - lo), min(hi, k + 2) - lo)))
    return {
        "half_order_hz": float(f[k]),
        "expected_hz": target,
        "level_db": float(10 * np.log10(p[k])),
        "above_floor_db": float(10 * np.log10(p[k] / floor)),
        "alias_of_hz": spectrum["alias_of_hz"][k],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--url", default="http://127.0.0.1:8080")
    parser.add_argument("--speed", type=float, default=1300.0, help="rev/min")
    parser.add_argument("--load", type=float, default=2.712, help="N m")
    parser.add_argument("--averages", type=int, default=4)
    parser.add_argument("--quit", action="store_true", help="end the session afterwards")
    parser.add_argument("--limit-s", type=float, default=600, help="longest wait for each step (s)")
    args = parser.parse_args()
    panel = Panel(args.url)
    panel.command("set_speed", rpm=args.speed)
    panel.command("set_load", nm=args.load)
    settled = wait_for_speed(panel, args.speed, limit_s=args.limit_s)
    print(f"settled: DVM {settled['dvm_rpm']:.0f} rev/min at t = {settled['simulated_s']:.1f} s", file=sys.stderr)
    spectrum = average(panel, args.averages, limit_s=args.limit_s)
    result = half_order(spectrum)
    result["averages"] = spectrum["averages"]
    print(json.dumps(result))
    if args.quit:
        panel.command("quit")


if __name__ == "__main__":
    main()
