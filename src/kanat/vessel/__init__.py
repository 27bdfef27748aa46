"""The tow vessel: manoeuvres (:mod:`~kanat.vessel.track`) and pitch with the reactive stabilizer
(seed 003, SPEC §6.2).

:func:`~kanat.vessel.pitch.solve_pitch` solves a pitch block for several stabilizer modes by
the Fourier steady state and by periodic shooting; :func:`~kanat.vessel.pitch.run_pitch_case`
is the ``kanat pitch`` verb's body. The pitch names below are imported on first use (PEP 562),
so that code needing only the track does not load the pitch solvers and their optimizers.
"""
from importlib import import_module

_EXPORTS = {
    "kanat.vessel.pitch": ("MODES", "PAPER_MODES", "PitchResponse", "PitchResult", "run_pitch_case", "solve_mode",
                           "solve_pitch", "stabilizer_law", "summary_table"),
    "kanat.vessel.pitch_laws": ("Feedback", "FourierSeries", "Off", "Rectangular", "Shaped", "Sinusoidal"),
    "kanat.vessel.pitch_system": ("RESONANCE_RTOL", "PitchSystem", "ResonanceError"),
}
_WHERE = {name: module for module, names in _EXPORTS.items() for name in names}

__all__ = sorted(_WHERE)


def __getattr__(name):
    if name in _WHERE:
        return getattr(import_module(_WHERE[name]), name)
    raise AttributeError(f"module 'kanat.vessel' has no attribute {name!r}")
