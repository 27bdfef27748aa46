"""The tow vessel: pitch dynamics with the reactive stabilizer (seed 003, SPEC §6.2).

:func:`~kanat.vessel.pitch.solve_pitch` solves a pitch block for several stabilizer modes
by the Fourier steady state and by periodic shooting; :func:`~kanat.vessel.pitch.run_pitch_case`
is the ``kanat pitch`` verb's body.
"""
from kanat.vessel.pitch import (
    MODES,
    PAPER_MODES,
    PitchResponse,
    PitchResult,
    run_pitch_case,
    solve_mode,
    solve_pitch,
    stabilizer_law,
    summary_table,
)
from kanat.vessel.pitch_laws import (
    Feedback,
    FourierSeries,
    Off,
    Rectangular,
    Shaped,
    Sinusoidal,
)
from kanat.vessel.pitch_system import RESONANCE_RTOL, PitchSystem, ResonanceError

__all__ = [
    "MODES", "PAPER_MODES", "RESONANCE_RTOL", "Feedback", "FourierSeries", "Off", "PitchResponse",
    "PitchResult", "PitchSystem", "Rectangular", "ResonanceError", "Shaped", "Sinusoidal",
    "run_pitch_case", "solve_mode", "solve_pitch", "stabilizer_law", "summary_table",
]
