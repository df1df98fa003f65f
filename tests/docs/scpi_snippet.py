"""docs/scpi.md's pyvisa lines, run as written against the README's panel command
(`testrig panel --scpi 127.0.0.1:5025`, at its default pace 1): the spectrum arrives, and
the next answer is the answer to the next query, not one left over from a timed-out one
(run by the Rust test `the_scpi_pages_pyvisa_lines_run_as_written`, tests/doc_snippets.rs).

    python3 tests/docs/scpi_snippet.py target/release/testrig OUT_DIR
"""

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        sys.exit(1)


def snippet():
    """The first ```python block after "In pyvisa:" in docs/scpi.md."""
    text = (ROOT / "docs" / "scpi.md").read_text()
    after = text.split("In pyvisa:", 1)[1]
    return re.search(r"```python\n(.*?)```", after, re.S).group(1)


def main():
    testrig, out = sys.argv[1], Path(sys.argv[2])
    panel = subprocess.Popen([testrig, "panel", "--scpi", "127.0.0.1:5025",
                              "--out", out / "panel", "--replace"],
                             stdout=subprocess.PIPE, text=True)
    try:
        for _ in range(2):   # the page's address, then the SCPI line
            print(panel.stdout.readline().strip())
        names = {}
        exec(compile(snippet(), "docs/scpi.md", "exec"), names)
        power = names["power"]
        check(len(power) > 100 and min(power) >= 0,
              f"the snippet's spectrum: {len(power)} lines")
        rig = names["rig"]
        rig.write("FORM ASC")
        check(rig.query("RIG:SPE?") == "1.3E3", "the next query gets its own answer")
        check(rig.query("SYST:ERR?").startswith("0,"), "no error queued")
        rig.close()
    finally:
        panel.terminate()
        panel.wait(timeout=60)


if __name__ == "__main__":
    main()
