"""Ship pitch with the reactive stabilizer (Gaisha, theory/vessel.md §2) and its effect on the tow point.

:func:`solve_pitch` solves a pitch block for several stabilizer modes by the Fourier steady
state (:mod:`.fourier`) and by periodic shooting (:mod:`.periodic`); the control laws are in
:mod:`.laws` (the optimal shape in :mod:`.optimal`), the ship in :mod:`.system`, and the
steady pitch as a motion of the tow point in :mod:`.motion`.
"""
from kanat.vessel.pitch.laws import Feedback, FourierSeries, Off, Rectangular, Shaped, Sinusoidal
from kanat.vessel.pitch.solve import (MODES, PAPER_MODES, PitchResponse, PitchResult, solve_mode, solve_pitch,
                                      stabilizer_law, summary_table)
from kanat.vessel.pitch.system import PitchSystem, ResonanceError

__all__ = ["MODES", "PAPER_MODES", "Feedback", "FourierSeries", "Off", "PitchResponse", "PitchResult",
           "PitchSystem", "Rectangular", "ResonanceError", "Shaped", "Sinusoidal", "solve_mode", "solve_pitch",
           "stabilizer_law", "summary_table"]
