"""testrig in Python: the virtual 1983 gear rig (F. Basmaji, The City University, London).

The same engine as the `testrig` command line, on numpy arrays:

- ``simulate(rpm, load_nm, ...)``: the plant alone at a steady point; every true signal
  as an array (units in the names), the impacts and the summary (the physics judge's
  motion with its numbers).
- ``analyse(signal, rate_hz, fmax_hz, ...)``: the Fourier analyser (with its ADC and an
  optional anti-alias filter) on any array, with the ground truth of which lines are
  aliases.

Errors are ``TestrigError`` with the command line's message, the argument named.
"""

from ._testrig import TestrigError, __version__, analyse, simulate

__all__ = ["TestrigError", "__version__", "analyse", "simulate"]
